// `raintrace render SCENE.toml -o OUT`: simulate + export (cli/export_pipeline.h) and ray-trace
// every frame with POV-Ray, then make the MP4, GIF and contact sheet. Locally the two overlap:
// the exporter runs on its own thread and POV-Ray starts on each range of frames as soon as the
// range is exported. Slurm exports everything first, then submits one job array. Re-running
// resumes: finished frames whose inputs are unchanged are never redone.
//
// Options (each with an example in --help):
//   --frames A-B   --jobs N   --width W --height H   --quality preview|final   --mask   --force
//   --backend local|slurm   --partition P   --tasks K   --no-movie   --seed N
// Hidden: --slurm-task OUT, the worker each Slurm array task runs.
#include <fmt/core.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
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
#include "cli/export_pipeline.h"
#include "cli/options.h"
#include "cli/scene.h"
#include "povgen/frame_text.h"
#include "povgen/manifest.h"
#include "render/contact_sheet.h"
#include "render/frame_feed.h"
#include "render/frame_plan.h"
#include "render/local_render.h"
#include "render/movie.h"
#include "render/progress_format.h"
#include "render/slurm_render.h"

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
  std::optional<std::uint64_t> seed;  ///< none: the scene file's seed
};

constexpr const char* kFooter = R"(
Examples:
  raintrace render examples/default.toml -o out/default            # everything, resumable
  raintrace render examples/default.toml -o out/default --frames 1-24   # a range (or 7)
  raintrace render examples/default.toml -o out/default --jobs 3   # POV-Ray processes in flight
  raintrace render examples/default.toml -o out/small --width 320 --height 240
  raintrace render examples/default.toml -o out/final --quality final   # antialiased
  raintrace render examples/default.toml -o out/default --mask     # also images/mask_NNNN.png
  raintrace render examples/default.toml -o out/default --force    # re-render every frame
  raintrace render out/default                                     # an already exported folder
  raintrace render examples/default.toml -o out/seed7 --seed 7   # other rain, same scene
  raintrace render examples/default.toml -o out/cluster --backend slurm --tasks 4

Locally, POV-Ray starts on each range of frames as soon as it is exported, while later
frames are still simulated (Slurm exports everything first, then submits).
Re-running the same command renders only frames that are missing or whose inputs changed;
Ctrl-C stops the export and POV-Ray, keeps finished frames, and the next run resumes.
Output: OUT/images/frame_NNNN.png, OUT/animation.mp4 and .gif (needs ffmpeg),
OUT/contact_sheet.png, OUT/manifest.json (per-frame status and seconds), OUT/logs/.
Slurm: OUT and the raintrace binary must be on a filesystem every node mounts at the same path;
the nodes need POV-Ray. Each array task runs `raintrace render --slurm-task OUT`. No cluster?
scripts/slurm-localhost.sh starts a one-node one (README: Rendering on a Slurm cluster).
Exit codes: 0 all frames rendered, 1 some frames failed, 2 unusable input or missing POV-Ray,
130/143 interrupted (SIGINT/SIGTERM).)";

// Set from the signal handler; a lock-free atomic store is async-signal-safe.
std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};

extern "C" void on_stop_signal(int sig) {
  g_signal.store(sig);
  g_stop.store(true);
}

// Installs SIGINT/SIGTERM handlers for its lifetime, restoring the previous ones afterwards.
class StopSignals {
 public:
  StopSignals() {
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &m_old_int);
    sigaction(SIGTERM, &sa, &m_old_term);
  }
  ~StopSignals() {
    sigaction(SIGINT, &m_old_int, nullptr);
    sigaction(SIGTERM, &m_old_term, nullptr);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

 private:
  struct sigaction m_old_int {};
  struct sigaction m_old_term {};
};

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
// stop flag ends it between frames; an export error sets the flag too (so POV-Ray stops) and is
// rethrown by finish(). The destructor stops and joins, so no path leaves the thread running.
class ExportThread {
 public:
  ExportThread(const Scene& scene, const FrameRange& range, const std::filesystem::path& out,
               render::FrameFeed& feed, std::atomic<bool>& stop)
      : m_stop{stop} {
    auto shared_files = m_shared_files.get_future();
    m_thread = std::thread([this, &scene, range, out, &feed] {
      bool announced = false;
      try {
        ExportHooks hooks;
        hooks.stop = &m_stop;
        hooks.on_shared_files = [&] {
          announced = true;
          m_shared_files.set_value();
        };
        hooks.on_frame = [&](povgen::FrameEntry entry) { feed.publish(std::move(entry)); };
        export_scene(scene, range, out, hooks);
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
  return render::run_slurm_task(args.slurm_task, std::stoi(id), &g_stop);
}

int run_render(const RenderArgs& args) {
  if (!args.slurm_task.empty()) return run_worker(args);
  if (args.backend != "local" && args.backend != "slurm") {
    throw std::invalid_argument("--backend must be local or slurm, not '" + args.backend + "'");
  }
  if (args.backend == "local") render::require_povray();

  // SCENE.toml → export into OUT; an exported folder (manifest.json inside) → render it as is.
  std::filesystem::path out;
  std::optional<render::FrameSpan> only;
  std::optional<Scene> overlapped;  // local backend, scene file: exported while rendering
  FrameRange range;
  const std::filesystem::path input{args.scene};
  if (std::filesystem::is_directory(input) && std::filesystem::exists(input / "manifest.json")) {
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
    out = input;
    if (!args.frames.empty()) {
      const auto manifest = povgen::read_manifest(out / "manifest.json");
      const auto frames = parse_frame_range(args.frames, static_cast<int>(manifest.frames.size()));
      only = render::FrameSpan{frames.first, frames.last};
    }
  } else {
    if (args.out.empty()) throw std::invalid_argument("-o OUT is required with a scene file");
    out = args.out;
    Scene scene = load_scene_file(input);
    if (args.seed) scene.sim.seed = *args.seed;
    if (args.width != 0) scene.look.width = args.width;
    if (args.height != 0) scene.look.height = args.height;
    if (!args.quality.empty()) {
      scene.look.quality =
          args.quality == "final" ? povgen::Quality::final : povgen::Quality::preview;
    }
    if (args.mask) scene.look.mask = true;
    range = parse_frame_range(args.frames, scene.frames);
    only = render::FrameSpan{range.first, range.last};
    fmt::print(stderr, "export: simulating and writing frames {}-{} to {}{}\n", range.first,
               range.last, out.string(),
               args.backend == "local" ? " (POV-Ray starts as they are written)" : "");
    if (args.backend == "local") {
      overlapped = std::move(scene);
    } else {
      export_scene(scene, range, out);  // the cluster gets a complete folder
    }
  }

  ProgressPrinter printer;
  render::RenderSummary summary;
  {
    StopSignals signals;
    auto on_failed = [&](const render::FrameFailure& f) {
      printer.break_line();
      print_failure(f, out);
    };
    auto on_progress = [&](const render::RenderProgress& p) { printer.update(p); };
    if (args.backend == "local") {
      render::LocalRenderSettings settings;
      settings.jobs = args.jobs > 0 ? args.jobs : render::default_jobs();
      settings.force = args.force;
      settings.mask = args.mask;
      settings.only = only;
      settings.stop = &g_stop;
      settings.on_progress = on_progress;
      settings.on_failed = on_failed;
      settings.on_notice = [&](const std::string& s) {
        printer.break_line();
        fmt::print(stderr, "render: {}\n", s);
      };
      if (overlapped) {
        render::FrameFeed feed{range.last - range.first + 1,
                               povgen::frame_digits(overlapped->frames)};
        ExportThread exporter{*overlapped, range, out, feed, g_stop};
        settings.incoming = &feed;
        summary = render::render_local(out, settings);
        printer.break_line();
        exporter.finish();
      } else {
        summary = render::render_local(out, settings);
      }
    } else {
      render::SlurmRenderSettings settings;
      settings.tasks = args.tasks;
      settings.partition = args.partition;
      settings.raintrace_exe = std::filesystem::read_symlink("/proc/self/exe");
      settings.force = args.force;
      settings.mask = args.mask;
      settings.only = only;
      settings.stop = &g_stop;
      settings.on_progress = on_progress;
      settings.on_failed = on_failed;
      settings.on_status = [&](const std::string& s) {
        printer.break_line();
        fmt::print(stderr, "render: {}\n", s);
      };
      summary = render::render_slurm(out, settings);
    }
    printer.break_line();
  }
  const auto& p = summary.progress;
  if (summary.interrupted) {
    const int sig = g_signal.load();
    fmt::print(stderr,
               "raintrace: interrupted by {}: {} frames finished and kept; run the same command "
               "again to resume\n",
               sig == SIGTERM ? "SIGTERM" : "SIGINT", p.done);
    return 128 + (sig != 0 ? sig : SIGINT);
  }
  fmt::print(stderr, "render: {} frames rendered, {} up to date, {} failed in {:.1f} s\n", p.done,
             p.skipped, p.failed, p.elapsed_seconds);

  // Assemble what exists: every frame of the manifest that has a finished image.
  const auto manifest = povgen::read_manifest(out / "manifest.json");
  const int digits = render::frame_digits(manifest);
  std::vector<int> finished;
  for (const auto& f : manifest.frames) {
    if (f.status == "rendered" && std::filesystem::exists(out / f.image)) {
      finished.push_back(f.number);
    }
  }
  fmt::print("images: {}/images/ ({} frames)\n", out.string(), finished.size());
  if (!finished.empty()) {
    const auto sheet = render::make_contact_sheet(out, finished, 9, digits);
    if (!sheet.note.empty()) fmt::print(stderr, "raintrace: warning: {}\n", sheet.note);
    fmt::print("contact sheet: {}\n", sheet.path.string());
  }
  // A movie needs consecutive frames: made from the first frame on, only when none is missing.
  const bool consecutive = !finished.empty() && finished.back() - finished.front() + 1 ==
                                                    static_cast<int>(finished.size());
  if (!args.no_movie && finished.size() >= 2) {
    if (!consecutive) {
      fmt::print(stderr, "raintrace: warning: frames are missing: no MP4/GIF made\n");
    } else {
      const auto movies = render::make_movies(out, manifest.fps > 0 ? manifest.fps : 24.0,
                                              finished.front(), digits);
      if (!movies.warning.empty()) fmt::print(stderr, "raintrace: warning: {}\n", movies.warning);
      if (!movies.mp4.empty()) fmt::print("video: {}\n", movies.mp4.string());
      if (!movies.gif.empty()) fmt::print("gif: {}\n", movies.gif.string());
    }
  }
  std::fflush(stdout);
  return summary.failures.empty() ? exit_code::ok : exit_code::failed;
}

}  // namespace

Command register_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  auto* sub = app.add_subcommand(
      "render", "Simulate, export and ray-trace a scene with POV-Ray (local or Slurm)");
  sub->footer(kFooter);
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
  sub->add_flag("--force", args->force, "Re-render frames that are already up to date");
  sub->add_option("--backend", args->backend, "local (default) or slurm (one job array)")
      ->check(one_of({"local", "slurm"}));
  sub->add_option("--partition", args->partition, "Slurm partition (default: the cluster's)");
  sub->add_option("--tasks", args->tasks, "Slurm array tasks (default: one per ~8 frames)")
      ->check(whole_number_in(1, 10000));
  sub->add_flag("--no-movie", args->no_movie, "Skip the MP4 and GIF");
  add_seed_option(*sub, args->seed);
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
