// `raintrace compare A B`: compares two images or two folders of frames (A the reference, B the
// candidate) with idiff's threshold rules, prints a table, optionally writes JSON, an HTML
// report and difference images; exit 0 all pass (warnings included), 1 any fail or missing
// frame, 2 unusable input (main turns the thrown error into the message and code 2).
#include <fmt/core.h>
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "compare/compare_run.h"
#include "compare/report_html.h"
#include "compare/report_json.h"
#include "compare/report_table.h"
#include "film/display_transform.h"

namespace raintrace::cli {

namespace {

struct CompareArgs {
  std::string a, b, json, html, diff;
  compare::Thresholds thresholds;
  int threads = 2;
  bool hdr = false;
  bool linear = false;
  double exposure_ev = 0.0;
  std::string view = "filmic";
  std::string look = "medium-high-contrast";
};

constexpr const char* kCompareFooter = R"(
Thresholds follow OpenImageIO's idiff (ImageBufAlgo::compare). Values are per channel of each
pixel, normalised to [0, 1] (8-bit: 1/255 = 0.0039); alpha is compared like any channel. A value
fails when |A-B| > --fail and |A-B| > --fail-relative * (|A|+|B|)/2; a pixel fails when any
channel fails. An image FAILS when more than --fail-percent % of its pixels fail or any error
exceeds --hard-fail; else it WARNS by the same rule with the --warn options; else it PASSes.
Defaults as idiff: --fail 1e-6 --warn 1e-6, percentages 0, relative 0, hard limits infinite.
Metrics: mean/max absolute error, RMSE, PSNR = 20 log10(1/RMSE), SSIM of Rec.709 luminance
(Wang et al. 2004: 11x11 Gaussian window sigma 1.5, C1=(0.01)^2, C2=(0.03)^2, L=1).
NaN or Inf against any other value is an infinite error: it fails and warns whatever the
thresholds, mean error, RMSE, PSNR and SSIM read nan or inf (null in --json), and the pixels
are counted ("N pixel(s) hold NaN or Inf"); NaN against NaN, or the same Inf, counts as equal.
Folders are matched by file name without extension (frame_0001.png meets frame_0001.exr); a
frame on one side only counts as a failure. A folder holding both an EXR and a PNG of a frame
(a render's images/) gives its PNG, or with --hdr its EXR.
HDR input (OpenEXR, HDR: scene-linear light) is developed before it is compared, so values,
thresholds and metrics stay those of the picture a viewer sees (1/255 = one 8-bit step):
against a PNG raintrace developed, exactly as that PNG's description says ("is this PNG its EXR
developed?": within half a step of rounding); otherwise with the curve alone (--exposure-ev,
--view, --look; no spikes, softness, bloom, noise, grain or vignetting). --linear
compares scene-linear values as stored instead: thresholds are then in linear units
(--fail-relative suits them), and PSNR and SSIM, which assume a peak of 1, are not
computed ("-"; null in --json).
Exit codes: 0 all pass or warn, 1 any fail or missing frame, 2 unusable input.
Example: the default example rendered at the size and frames of its reference stills, compared
with them by the thresholds tests/reference/thresholds.json gives it:
  raintrace render examples/default.toml -o out/check --width 160 --height 90 --frames 1-2
  raintrace compare tests/reference/default out/check/images --fail 0.1 --fail-percent 0.5)";

int run_compare(const CompareArgs& args) {
  compare::CompareOptions options;
  options.thresholds = args.thresholds;
  options.threads = args.threads;
  options.prefer_hdr = args.hdr;
  options.hdr.linear = args.linear;
  options.hdr.curve.exposure_ev = args.exposure_ev;
  options.hdr.curve.view = *film::parse_view(args.view);  // CLI checked the names
  options.hdr.curve.look = *film::parse_look(args.look);
  options.diff_dir = args.diff;
  if (!args.html.empty()) options.assets_dir = compare::html_assets_dir(args.html);
  const compare::CompareReport report = compare::compare_paths(args.a, args.b, options);

  fmt::print("{}", compare::format_table(report));
  std::fflush(stdout);
  if (!args.json.empty()) compare::write_json(args.json, report);
  if (!args.html.empty()) compare::write_html(args.html, report);

  for (const auto& frame : report.frames) {
    if (frame.status == compare::FrameStatus::error) throw std::runtime_error(frame.error);
  }
  return report.any_failed() ? exit_code::failed : exit_code::ok;
}

}  // namespace

Command register_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  auto* sub = app.add_subcommand(
      "compare", "Compare two images or two folders of frames (A reference, B candidate)");
  sub->footer(kCompareFooter);
  sub->add_option("A", args->a, "Reference image or folder")->required();
  sub->add_option("B", args->b, "Candidate image or folder")->required();
  auto& t = args->thresholds;
  sub->add_option("--fail", t.fail, "Per-channel absolute failure threshold (default 1e-6)")
      ->check(not_negative());
  sub->add_option("--warn", t.warn, "Per-channel absolute warning threshold (default 1e-6)")
      ->check(not_negative());
  sub->add_option("--fail-percent", t.fail_percent,
                  "Percentage of pixels allowed to fail (default 0)")
      ->check(number_in(0.0, 100.0));
  sub->add_option("--warn-percent", t.warn_percent,
                  "Percentage of pixels allowed to warn (default 0)")
      ->check(number_in(0.0, 100.0));
  sub->add_option("--fail-relative", t.fail_relative,
                  "Also require |A-B| > this * (|A|+|B|)/2 to fail (default 0: off)")
      ->check(not_negative());
  sub->add_option("--warn-relative", t.warn_relative,
                  "Also require |A-B| > this * (|A|+|B|)/2 to warn (default 0: off)")
      ->check(not_negative());
  sub->add_option("--hard-fail", t.hard_fail, "Fail if any one error exceeds this (default inf)")
      ->check(not_negative());
  sub->add_option("--hard-warn", t.hard_warn, "Warn if any one error exceeds this (default inf)")
      ->check(not_negative());
  sub->add_option("--json", args->json, "Write every number as JSON to FILE");
  sub->add_option("--html", args->html,
                  "Write an HTML report to FILE (images in <FILE stem>_files/ beside it)");
  sub->add_option("--diff", args->diff, "Write a heat-map difference PNG per frame into DIR");
  sub->add_option("--threads", args->threads, "Frames compared at once (default 2)")
      ->check(whole_number_in(1, 256));
  sub->add_flag("--hdr", args->hdr,
                "Folders: compare a frame's EXR, not its PNG, where a folder holds both");
  sub->add_flag("--linear", args->linear,
                "Compare HDR values as stored (scene-linear) instead of developing them");
  sub->add_option("--exposure-ev", args->exposure_ev,
                  "Exposure HDR input is developed with, in stops (default 0)")
      ->check(number_in(-16.0, 16.0));
  const std::vector<std::string> views(std::begin(film::kViewNames), std::end(film::kViewNames));
  const std::vector<std::string> looks(std::begin(film::kLookNames), std::end(film::kLookNames));
  sub->add_option("--view", args->view, "View HDR input is developed with (default filmic)")
      ->check(CLI::IsMember(views));
  sub->add_option("--look", args->look,
                  "Filmic look HDR input is developed with (default medium-high-contrast)")
      ->check(CLI::IsMember(looks));
  return {sub, [args] { return run_compare(*args); }};
}

}  // namespace raintrace::cli
