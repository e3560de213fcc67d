// Part (b) of scene generation: frame values → the text of frames/frame_NNNN.pov. Pure.
// Encodings follow docs/povray-notes.md: near drops are bare spheres in one union sharing
// RT_DropMaterial (never merge), far drops are quads in one mesh2 with shared uv_vectors into
// the streak atlas, bolts are emissive cylinders. No free text is ever written.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "povgen/frame_values.h"
#include "povgen/streak_atlas.h"

namespace raintrace::povgen {

/// Receives text in order, piece by piece (a file, a hash, a string).
using TextSink = std::function<void(std::string_view)>;

/// Streams the frame scene to sink in pieces of at most a few MB, so a million-drop frame
/// never sits in memory whole. Same bytes as frame_text(). With threads > 1 the sink may be
/// called from a writer thread, but always one call at a time and in text order.
void write_frame_text(const FrameValues& values, const TextSink& sink,
                      const StreakAtlasLayout& atlas = {}, int threads = 1);

/// The frame scene: declares RT_Flash and RT_FlashPosition, includes scene.inc (camera,
/// lights, environment, materials), then the rain. `threads` > 1 writes chunks of drops in
/// parallel; the text is byte-identical for every thread count. Throws std::invalid_argument
/// if a value is not finite.
std::string frame_text(const FrameValues& values, const StreakAtlasLayout& atlas = {},
                       int threads = 1);

/// The rain mask scene of a frame: re-uses the frame file with RT_Mask set, so scene.inc
/// swaps in plain white emissive materials on black and leaves the environment out.
/// frame_path is the frame file relative to the output folder (frame_file_name()).
std::string mask_text(const std::string& frame_path);

/// Digits in frame file names: 4, or more for animations past 9999 frames.
int frame_digits(int frame_count);
/// "frame_0001.pov" for ("frame", 1, 4, ".pov"); prefix is "frame" or "mask".
std::string frame_file_name(const std::string& prefix, int number, int digits,
                            const std::string& extension);

}  // namespace raintrace::povgen
