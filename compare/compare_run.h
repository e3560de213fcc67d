// Comparing two images or two folders of frames: reading, metrics, difference images and the
// PNG copies an HTML report shows, frame by frame on a pool of threads.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "compare/hdr_input.h"
#include "compare/metrics.h"

namespace raintrace::compare {

struct CompareOptions {
  Thresholds thresholds;
  /// Frames compared at once, >= 1. Default 2 (the machine's cores). OpenImageIO's own
  /// threads are set to 1 while the pool runs more than one frame, to avoid oversubscription.
  int threads = 2;
  /// Folder for one heat-map difference PNG per frame ("<frame stem>_diff.png"); empty = none.
  std::filesystem::path diff_dir;
  /// Folder for the PNGs an HTML report shows ("<nnnn>_reference.png", "_candidate.png",
  /// "_diff.png", nnnn the frame's index); empty = none.
  std::filesystem::path assets_dir;
  /// How scene-linear (HDR) images are compared (hdr_input.h).
  HdrOptions hdr;
  /// Folders holding a frame both as HDR (.exr, .hdr) and as a picture (.png, …) under one name:
  /// false compares the pictures, true the HDR files (`--hdr`).
  bool prefer_hdr = false;
};

enum class FrameStatus {
  compared,   ///< both sides read; metrics valid
  missing_a,  ///< only in the candidate folder: counts as a failure
  missing_b,  ///< only in the reference folder: counts as a failure
  error,      ///< unreadable or mismatched sizes: unusable input
};

struct FrameResult {
  std::string name;         ///< file name (folders) or the candidate's file name (images)
  std::filesystem::path a;  ///< reference file; empty when missing
  std::filesystem::path b;  ///< candidate file; empty when missing
  FrameStatus status = FrameStatus::compared;
  Metrics metrics;                   ///< valid when status == compared
  std::string error;                 ///< what went wrong when status == error
  std::filesystem::path diff_image;  ///< the --diff file written, if any
  /// File names inside assets_dir (empty when not written): reference, candidate, difference.
  std::string asset_reference, asset_candidate, asset_diff;
  /// How each side was developed before comparing (HdrInput::prepare); empty: as stored.
  std::string developed_a, developed_b;

  /// True for a failed comparison or a frame present on one side only.
  bool failed() const;
  /// "PASS", "WARN", "FAIL", "MISSING" (one side only) or "ERROR".
  std::string verdict_string() const;
};

struct CompareReport {
  std::filesystem::path a, b;  ///< as given
  bool folders = false;        ///< true when a and b are folders
  Thresholds thresholds;
  std::vector<FrameResult> frames;  ///< sorted by name: stable whatever the thread count

  bool any_failed() const;
  bool any_error() const;
};

/// Compares a (reference) with b (candidate): two image files, or two folders whose image
/// files (extensions OpenImageIO reads; hidden files skipped) are matched by name without the
/// extension, so a.png meets a.exr; where a folder holds both an HDR file and a picture of one
/// name, `prefer_hdr` picks which. Scene-linear input is compared as hdr_input.h says. Per-frame
/// problems (unreadable file, different sizes) are recorded in the frame, not thrown, so one
/// bad frame does not hide the others. Throws std::runtime_error when a path does not exist or
/// one is a folder and the other a file, std::invalid_argument for bad options.
CompareReport compare_paths(const std::filesystem::path& a, const std::filesystem::path& b,
                            const CompareOptions& options = {});

}  // namespace raintrace::compare
