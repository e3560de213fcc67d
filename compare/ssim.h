// Structural similarity (SSIM) of two images' luminance, after Wang, Bovik, Sheikh & Simoncelli,
// "Image quality assessment: from error visibility to structural similarity", IEEE TIP 13(4),
// 2004.
#pragma once

#include <vector>

#include "compare/image.h"

namespace raintrace::compare {

/// Luminance of each pixel: Rec. 709 weights 0.2126 R + 0.7152 G + 0.0722 B on the first three
/// channels (alpha ignored here; the error metrics cover it); channel 0 for 1- or 2-channel
/// (grey, grey+alpha) images. Row-major, width × height values.
std::vector<float> luminance(const Image& image);

/// Mean SSIM of the luminance of a and b (same width and height, else std::invalid_argument).
/// Local statistics use an 11×11 Gaussian window, σ = 1.5, normalised to sum 1; the stabilising
/// constants are C1 = (0.01 L)² and C2 = (0.03 L)² with dynamic range L = 1 (values normalised to
/// [0, 1]), as in the paper:
///   SSIM(x, y) = (2 μa μb + C1)(2 σab + C2) / ((μa² + μb² + C1)(σa² + σb² + C2)).
/// The mean is over the window centres where the whole window lies inside the image (the
/// paper's 'valid' filtering: (w − 10) × (h − 10) positions). Images narrower or lower than 11
/// pixels use every pixel as a centre, with the window cut at the border and renormalised.
/// Identical images give exactly 1; the result lies in [−1, 1].
double ssim(const Image& a, const Image& b);

}  // namespace raintrace::compare
