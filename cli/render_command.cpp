// `raintrace render SCENE.toml -o OUT`: simulate + export (output/export.h) and ray-trace every
// frame with POV-Ray, then make the MP4, GIF and contact sheet. Locally the two overlap: the
// exporter runs on its own thread and POV-Ray starts on each range of frames as soon as the
// range is exported. Slurm exports everything first, then submits one job array. Re-running
// resumes: finished frames whose inputs and images are unchanged are never redone. What is up
// to date, and whether this run may use OUT at all, is output::FolderState's decision.
//
// Options (each with an example in --help):
//   --frames A-B   --jobs N   --width W --height H   --quality preview|final   --mask   --force
//   --backend local|slurm   --partition P   --tasks K   --no-movie   --seed N
// Hidden: --slurm-task OUT, the worker each Slurm array task runs.
#include <fmt/core.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "cli/command.h"
#include "cli/exit_codes.h"
#include "cli/folder_run.h"
#include "cli/options.h"
#include "cli/scene.h"
#include "cli/stop_signals.h"
#include "output/export.h"
#include "output/folder_state.h"
#include "render/assemble.h"
#include "render/frame_feed.h"
#include "render/local_render.h"
#include "render/progress_format.h"
#include "render/slurm_render.h"
#include "render/spans.h"

namespace raintrace::cli {
namespace {

struct RenderArgs {
  std::string scene;
  std::string out;
  std::string frames;
  int jobs = 0;
  int width = 0;
  int height = 0;
  std::string quality;
  bool mask = false;
  bool force = false;
  std::string backend = "local";
  std::string partition;
  int tasks = 0;
  bool no_movie = false;
  std::string slurm_task;
  LimitArgs limits;
  std::optional<std::uint64_t> seed;  ///< none: the scene file's seed
};

constexpr const char* kRenderFooter = R"(
Examples:
  raintrace render examples/default.toml -o out/default            # everything, resumable
  raintrace render examples/default.toml -o out/default --frames 1-24   # a range (or 7)
  raintrace render examples/default.toml -o out/default --jobs 3   # POV-Ray processes in flight
  raintrace render examples/default.toml -o out/small --width 320 --height 240
  raintrace render examples/default.toml -o out/final --quality final   # antialiased
  raintrace render examples/default.toml -o out/masks --mask       # also images/mask_NNNN.png
  raintrace render examples/default.toml -o out/default --force    # re-render every frame
  raintrace render out/default                                     # an already exported folder
  raintrace render examples/default.toml -o out/seed7 --seed 7   # other rain, same scene
  raintrace render examples/default.toml -o out/cluster --backend slurm --tasks 4

Locally, POV-Ray starts on each range of frames as soon as it is exported, while later
frames are still simulated (Slurm exports everything first, then submits).
Re-running the same command renders only frames that are missing or whose inputs changed;
Ctrl-C stops the export and POV-Ray, keeps finished frames, and the next run resumes.
Output: OUT/images/frame_NNNN.png, OUT/animation.mp4 and .gif (needs ffmpeg),
OUT/contact_sheet.png, OUT/manifest.json (per-frame status, image size and content hash,
seconds: docs/output-folder.md), OUT/raintrace.lock, OUT/logs/.
Slurm: OUT and the raintrace binary must be on a filesystem every node mounts at the same path;
the nodes need POV-Ray. Each array task runs `raintrace render --slurm-task OUT`. No cluster?
scripts/slurm-localhost.sh starts a one-node one (README: Rendering on a Slurm cluster).
OUT must be new, empty, or a folder raintrace made from the same scene and settings (seed,
size, quality, masks): another scene's folder is refused unless --force, which deletes its
frames and images first. A second run on the same folder stops at once and says who holds it.
The memory and simulation work a scene asks for are estimated before anything starts; past
--max-memory or --max-drop-steps the run stops, naming the scene keys to change.
Images are checked against the size and content hash recorded when they were made: a missing,
truncated or changed image is rendered again, and the movie and contact sheet show only
checked frames.
Exit codes: 0 all frames rendered, 1 some frames failed, 2 unusable input, output folder or
missing POV-Ray, 3 system error (disk full, permission denied: the message says which),
4 output folder in use by another raintrace, 130/143 interrupted (SIGINT/SIGTERM).)";

// Prints progress to stderr: a bar redrawn in place on a terminal, plain lines otherwise.
class ProgressPrinter {
 public:
  ProgressPrinter() : m_tty(::isatty(STDERR_FILENO) == 1) {}

  void update(const render::RenderProgress& p) {
    if (p.export_total > 0 && p.exported == p.export_total && !m_export_reported) {
      m_export_reported = true;
      break_line();
      fmt::print(stderr, "export: all {} frames written after {:.1f} s\n", p.export_total,
                 p.elapsed_seconds);
    }
    const int finished = p.done + p.failed;
    if (m_tty) {
      const double now = p.elapsed_seconds;
      if (finished == m_last_finished && now - m_last_draw < 0.1) return;
      fmt::print(stderr, "\r{}\x1b[K", render::format_progress_bar(p));
      m_drawn = true;
      m_last_draw = now;
    } else {
      // A line per finished frame, or every 10 s while a slow frame is tracing.
      if (finished == m_last_finished && p.elapsed_seconds - m_last_draw < 10.0) return;
      if (finished == m_last_finished && p.total == 0) return;
      fmt::print(stderr, "{}\n", render::format_progress_line(p));
      m_last_draw = p.elapsed_seconds;
    }
    m_last_finished = finished;
    std::fflush(stderr);
  }

  /// Ends the bar's line so the next message starts on its own line.
  void break_line() {
    if (m_tty && m_drawn) fmt::print(stderr, "\n");
    m_drawn = false;
  }

 private:
  bool m_tty;
  bool m_drawn = false;
  bool m_export_reported = false;
  int m_last_finished = -1;
  double m_last_draw = -1e9;
};

// Runs the export on its own thread and hands each frame to the renderer through `feed`. The
// stop flag ends it between substeps; an export error sets the flag too (so POV-Ray stops) and is
// rethrown by finish(). The destructor stops and joins, so no path leaves the thread running.
// The folder is the export's until its shared files are written, then the renderer's alone.
class ExportThread {
 public:
  ExportThread(output::FolderState& folder, const output::SceneToExport& scene,
               output::FrameSpan range, render::FrameFeed& feed, std::atomic<bool>& stop)
      : m_stop{stop} {
    auto shared_files = m_shared_files.get_future();
    m_thread = std::thread([this, &folder, &scene, range, &feed] {
      bool announced = false;
      try {
        output::ExportHooks hooks;
        hooks.stop = &m_stop;
        hooks.on_shared_files = [&] {
          announced = true;
          m_shared_files.set_value();
        };
        hooks.on_frame = [&](output::ExportedFrame frame) { feed.publish(std::move(frame)); };
        output::export_frames(folder, scene, range, hooks);
      } catch (...) {
        m_error = std::current_exception();
        m_stop.store(true);
        if (!announced) m_shared_files.set_exception(m_error);
      }
      feed.close();
    });
    try {
      shared_files.get();  // manifest.json and scene.ini exist: the renderer may start
    } catch (...) {
      m_thread.join();
      throw;
    }
  }
  ~ExportThread() {
    if (m_thread.joinable()) {
      m_stop.store(true);
      m_thread.join();
    }
  }
  ExportThread(const ExportThread&) = delete;
  ExportThread& operator=(const ExportThread&) = delete;

  /// Waits for the export to end; rethrows its error, if any.
  void finish() {
    if (m_thread.joinable()) m_thread.join();
    if (m_error) std::rethrow_exception(m_error);
  }

 private:
  std::atomic<bool>& m_stop;
  std::promise<void> m_shared_files;
  std::exception_ptr m_error;
  std::thread m_thread;
};

void print_failure(const render::FrameFailure& f, const std::filesystem::path& out) {
  if (f.in_develop) {
    fmt::print(stderr, "raintrace: frame {}: developing its EXR failed: {}\n", f.frame,
               f.summary());
    return;
  }
  fmt::print(stderr, "raintrace: {} {} failed: POV-Ray exited with code {}\n",
             f.pass == render::Pass::image ? "frame" : "mask of frame", f.frame, f.exit_code);
  fmt::print(stderr, "  command: {}\n", f.command);
  for (const auto& line : f.error_lines) fmt::print(stderr, "  {}\n", line);
  fmt::print(stderr, "  log: {}\n", (out / f.log).string());
}

int run_worker(const RenderArgs& args) {
  const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
  if (id == nullptr) throw std::runtime_error("--slurm-task runs inside a Slurm array task only");
  StopSignals signals;
  return render::run_slurm_task(args.slurm_task, std::stoi(id), &stop_requested());
}

// The folder this run renders, claimed for a scene file (export first) or opened as exported.
struct RenderInput {
  std::optional<output::FolderState> folder;
  std::optional<output::SceneToExport> scene;  ///< set: export `range` first
  output::FrameSpan range;
  std::optional<render::FrameSpan> only;
};

RenderInput prepare(const RenderArgs& args, int povray_processes) {
  RenderInput in;
  const std::filesystem::path input{args.scene};
  if (std::filesystem::is_directory(input)) {
    // An exported folder: rendered as it is.
    if (!args.out.empty() &&
        std::filesystem::absolute(args.out) != std::filesystem::absolute(input)) {
      throw std::invalid_argument(
          "rendering an exported folder: leave out -o (or give the same folder)");
    }
    if (args.width != 0 || args.height != 0 || !args.quality.empty() || args.seed) {
      throw std::invalid_argument(
          "--width/--height/--quality/--seed change the scene: give the scene file, not the "
          "folder");
    }
    in.folder.emplace(output::FolderState::open(input, this_command()));
    if (const auto edits = hand_edit_note(*in.folder, false); !edits.empty()) {
      fmt::print(stderr, "render: {}\n", edits);
    }
    const auto& manifest = in.folder->manifest();
    if (args.mask && !manifest.identity.masks) {
      throw std::invalid_argument(
          "this folder was exported without masks: render the scene file with --mask");
    }
    if (!args.frames.empty()) {
      const int frames = std::max(manifest.frame_count, static_cast<int>(manifest.frames.size()));
      const auto r = parse_frame_range(args.frames, frames);
      in.only = render::FrameSpan{r.first, r.last};
    }
    return in;
  }
  if (args.out.empty()) throw std::invalid_argument("-o OUT is required with a scene file");
  Scene scene = load_scene_file(input);
  if (args.seed) scene.sim.seed = *args.seed;
  if (args.width != 0 || args.height != 0) {
    set_image_size(scene, args.width != 0 ? args.width : scene.look.width,
                   args.height != 0 ? args.height : scene.look.height);
  }
  if (!args.quality.empty()) {
    scene.look.quality =
        args.quality == "final" ? povgen::Quality::final : povgen::Quality::preview;
  }
  if (args.mask) scene.look.mask = true;
  const FrameRange range = parse_frame_range(args.frames, scene.frames);
  in.range = {range.first, range.last};
  in.only = in.range;
  in.scene = scene_to_export(scene);
  check_run_budget(*in.scene, in.range, povray_processes, args.limits);
  output::ClaimNote note;
  in.folder.emplace(claim_folder(args.out, scene, *in.scene, args.force, &note));
  if (!note.text.empty()) fmt::print(stderr, "render: {}\n", note.text);
  if (const auto edits = hand_edit_note(*in.folder, true); !edits.empty()) {
    fmt::print(stderr, "render: {}\n", edits);
  }
  return in;
}

int run_render(const RenderArgs& args) {
  if (!args.slurm_task.empty()) return run_worker(args);
  if (args.backend != "local" && args.backend != "slurm") {
    throw std::invalid_argument("--backend must be local or slurm, not '" + args.backend + "'");
  }
  if (args.backend == "local") render::require_povray();
  StopSignals signals;
  // Slurm: each node runs one POV-Ray per task; this machine only simulates.
  const int jobs = args.jobs > 0 ? args.jobs : render::default_jobs();
  RenderInput in = prepare(args, args.backend == "local" ? jobs : 1);
  output::FolderState& folder = *in.folder;
  const std::filesystem::path out = folder.dir();

  ProgressPrinter printer;
  render::RenderSummary summary;
  auto on_failed = [&](const render::FrameFailure& f) {
    printer.break_line();
    print_failure(f, out);
  };
  auto on_progress = [&](const render::RenderProgress& p) { printer.update(p); };
  auto on_notice = [&](const std::string& s) {
    printer.break_line();
    fmt::print(stderr, "render: {}\n", s);
  };
  auto on_plan = [&](const output::RenderPlan& plan) {
    fmt::print(stderr, "render: {}\n", plan.summary());
  };
  if (in.scene) {
    fmt::print(stderr, "export: simulating and writing frames {}-{} to {}{}\n", in.range.first,
               in.range.last, out.string(),
               args.backend == "local" ? " (POV-Ray starts as they are written)" : "");
  }
  render::BackendSettings common;
  common.force = args.force;
  common.only = in.only;
  common.stop = &stop_requested();
  common.on_progress = on_progress;
  common.on_failed = on_failed;
  common.on_plan = on_plan;
  if (args.backend == "local") {
    render::LocalRenderSettings settings;
    static_cast<render::BackendSettings&>(settings) = common;
    settings.jobs = jobs;
    settings.on_notice = on_notice;
    if (in.scene) {
      render::FrameFeed feed{in.range.count()};
      ExportThread exporter{folder, *in.scene, in.range, feed, stop_requested()};
      settings.incoming = &feed;
      summary = render::render_local(folder, settings);
      printer.break_line();
      exporter.finish();
    } else {
      summary = render::render_local(folder, settings);
    }
  } else {
    if (in.scene) {
      // The cluster gets a complete folder.
      output::ExportHooks hooks;
      hooks.stop = &stop_requested();
      if (!output::export_frames(folder, *in.scene, in.range, hooks)) summary.interrupted = true;
    }
    if (!summary.interrupted) {
      render::SlurmRenderSettings settings;
      static_cast<render::BackendSettings&>(settings) = common;
      settings.tasks = args.tasks;
      settings.partition = args.partition;
      settings.raintrace_exe = std::filesystem::read_symlink("/proc/self/exe");
      settings.on_status = on_notice;
      summary = render::render_slurm(folder, settings);
    }
  }
  printer.break_line();
  const auto& p = summary.progress;
  if (summary.interrupted) {
    fmt::print(stderr,
               "raintrace: interrupted by {}: {} frames finished and kept; run the same command "
               "again to resume\n",
               stop_signal_name(), p.done);
    return interrupted_exit_code();
  }
  const std::string developed =
      p.developed_only > 0 ? fmt::format("{} developed only, ", p.developed_only) : "";
  fmt::print(stderr, "render: {} frames rendered, {}{} up to date, {} failed in {:.1f} s\n",
             p.done - p.developed_only, developed, p.skipped, p.failed, p.elapsed_seconds);

  // The animation's outputs, from the frames whose images are verified now.
  render::AssemblyOptions options;
  options.movie = !args.no_movie;
  const auto made = render::assemble(folder, options);
  fmt::print("images: {}/images/ ({} frames)\n", out.string(), made.frames.size());
  for (const auto& warning : made.warnings) fmt::print(stderr, "raintrace: warning: {}\n", warning);
  if (!made.contact_sheet.empty()) fmt::print("contact sheet: {}\n", made.contact_sheet.string());
  if (!made.mp4.empty()) fmt::print("video: {}\n", made.mp4.string());
  if (!made.gif.empty()) fmt::print("gif: {}\n", made.gif.string());
  std::fflush(stdout);
  return summary.failures.empty() ? exit_code::ok : exit_code::failed;
}

}  // namespace

Command register_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  auto* sub = app.add_subcommand(
      "render", "Simulate, export and ray-trace a scene with POV-Ray (local or Slurm)");
  sub->footer(kRenderFooter);
  sub->add_option("scene", args->scene, "Scene file (.toml), or an exported output folder");
  sub->add_option("-o,--output", args->out, "Output folder (created; reused to resume)");
  sub->add_option("--frames", args->frames, "Frame range A-B or one frame N (default: all)");
  sub->add_option("--jobs", args->jobs,
                  "POV-Ray processes in flight (default: cores/2 + 3, i.e. 4 on 2 cores)")
      ->check(whole_number_in(1, 256));
  // The same ranges as the scene file's [output] width and height.
  const sim::Range size =
      sim::find_param<povgen::ExportParams>(povgen::kExportParams, "output", "width")->range;
  sub->add_option("--width", args->width, "Image width in pixels (overrides the scene)")
      ->check(whole_number_in(static_cast<int>(size.min), static_cast<int>(size.max)));
  sub->add_option("--height", args->height, "Image height in pixels (overrides the scene)")
      ->check(whole_number_in(static_cast<int>(size.min), static_cast<int>(size.max)));
  sub->add_option("--quality", args->quality,
                  "preview (no antialiasing, cheaper environment effects: RT_Preview=1) or "
                  "final (adaptive antialiasing, full effects)")
      ->check(one_of({"preview", "final"}));
  sub->add_flag("--mask", args->mask, "Also render rain masks (images/mask_NNNN.png)");
  sub->add_flag("--force", args->force,
                "Render every frame again; and replace a folder made from another scene or with "
                "other settings (its frames and images are deleted), or write into a non-empty "
                "folder raintrace did not make");
  sub->add_option("--backend", args->backend, "local (default) or slurm (one job array)")
      ->check(one_of({"local", "slurm"}));
  sub->add_option("--partition", args->partition, "Slurm partition (default: the cluster's)");
  sub->add_option("--tasks", args->tasks, "Slurm array tasks (default: one per ~8 frames)")
      ->check(whole_number_in(1, 10000));
  sub->add_flag("--no-movie", args->no_movie, "Skip the MP4 and GIF");
  add_seed_option(*sub, args->seed);
  add_limit_options(*sub, args->limits);
  sub->add_option("--slurm-task", args->slurm_task, "Worker mode inside a Slurm array task")
      ->group("");
  return {
      sub, [args]() -> int {
        if (args->scene.empty() && args->slurm_task.empty()) {
          throw std::invalid_argument("render: give a scene file (see raintrace render --help)");
        }
        return run_render(*args);
      }};
}

}  // namespace raintrace::cli
