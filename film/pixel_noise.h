// Repeatable per-pixel noise for develop's grain and sensor noise: a pure function of (x, y,
// frame, seed), so the same seed and frame give byte-identical pictures on any machine and
// thread count, and consecutive frames differ.
#pragma once

#include <cstdint>

namespace raintrace::film {

/// Mean 0, variance 1, shared between neighbours as noise that spans about a pixel is: each
/// pixel's hash of (x, y, frame, seed) gives four uniform numbers, summed, centred and scaled
/// (Irwin–Hall), and the value is the pixel's and its eight neighbours' weighted (1, 4, 1) ⊗
/// (1, 4, 1) over their root sum of squares (18). Neighbours correlate 8/18 ≈ 0.44 across a side,
/// 1/18 two apart, not at all three apart; |value| < 6.93. Independent pixels read as a
/// renderer's sampling noise (a blind viewer: "looks like leftover path-tracer noise").
float clumped_noise(std::uint32_t x, std::uint32_t y, std::uint32_t frame, std::uint32_t seed);

/// A 64-bit seed or frame number folded into one 32-bit word for the hash (XOR of its halves:
/// values below 2^32 stay distinct).
std::uint32_t fold_to_32(std::uint64_t value);

}  // namespace raintrace::film
