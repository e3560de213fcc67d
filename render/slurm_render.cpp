// Slurm backend: plan file, batch script, submission, following with squeue, result merging.
#include "render/slurm_render.h"

#include <fmt/core.h>
#include <chrono>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "output/folder_lock.h"
#include "output/image_check.h"
#include "povgen/output_folder.h"
#include "render/develop_queue.h"
#include "render/environment_plate.h"
#include "render/process.h"
#include "render/slurm_flight.h"
#include "render/spans.h"
#include "render/text_file.h"

namespace raintrace::render {
namespace {

using nlohmann::json;
using output::FolderState;

std::filesystem::path results_dir(const std::filesystem::path& out) {
  return out / "slurm" / "results";
}

std::string result_name(Pass pass, int frame) {
  return fmt::format("{}_{:04d}.json", output::pass_prefix(pass), frame);
}

// A task's develop result for a frame, written after its render result.
std::string develop_result_name(int frame) { return fmt::format("develop_{:04d}.json", frame); }
constexpr const char* kDevelopPrefix = "develop_";

json spans_to_json(const std::vector<FrameSpan>& spans) {
  json a = json::array();
  for (const auto& s : spans) a.push_back({s.first, s.last});
  return a;
}

std::vector<FrameSpan> spans_from_json(const json& a) {
  std::vector<FrameSpan> spans;
  for (const auto& s : a) spans.push_back({s.at(0).get<int>(), s.at(1).get<int>()});
  return spans;
}

std::string shell_single_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string{"'\\''"} : std::string(1, c);
  return out + "'";
}

// Result files as written by tasks, turned into the same events the local runner reports, so the
// folder's transitions and the progress are recorded by the same callbacks. A frame's develop
// result counts only when the task developed it with this run's develop hash from the EXR now
// recorded; otherwise (or when the task could not develop) `develop_here` gets the frame and
// this machine develops it.
struct Merger {
  FolderState& folder;
  const RunnerCallbacks& callbacks;
  ProgressReporter* reporter = nullptr;   // null: results of an earlier run, not counted
  std::function<void(int)> develop_here;  // null: leave undeveloped frames to the sweep

  // Returns the number of result files consumed: render results first, so a frame's develop
  // result (written after it) finds its EXR recorded.
  int merge_all() {
    const auto& out = folder.dir();
    std::error_code ec;
    if (!std::filesystem::is_directory(results_dir(out), ec)) return 0;
    std::vector<std::filesystem::path> renders;
    std::vector<std::filesystem::path> develops;
    for (const auto& entry : std::filesystem::directory_iterator(results_dir(out))) {
      const auto name = entry.path().filename().string();
      if (name.empty() || name[0] == '.' || entry.path().extension() != ".json") continue;
      (name.rfind(kDevelopPrefix, 0) == 0 ? develops : renders).push_back(entry.path());
    }
    int consumed = 0;
    for (const auto& path : renders) consumed += merge_render(path);
    for (const auto& path : develops) consumed += merge_develop(path);
    return consumed;
  }

  int merge_develop(const std::filesystem::path& path) {
    json r;
    try {
      r = json::parse(read_text(path));
    } catch (const json::exception&) {
      return 0;  // renamed into place atomically, so this is not ours: leave it
    }
    std::filesystem::remove(path);
    const int frame = r.value("frame", 0);
    const auto* f = folder.find(frame);
    if (f == nullptr || r.value("hash", "") != f->input_hash ||
        folder.decide(Pass::image, frame, false) != output::RenderReason::up_to_date) {
      return 1;  // stale: the frame was exported or rendered again since
    }
    const auto& id = folder.manifest().identity;
    if (r.value("status", "") == "developed" &&
        r.value("develop_hash", "") == folder.develop_hash() &&
        r.value("source_hash", "") == f->image.file_hash &&
        output::image_is_complete(folder.dir() / developed_image_name(frame, folder.digits()),
                                  id.width, id.height)) {
      folder.developed(frame, r.value("seconds", 0.0));
      if (reporter != nullptr) {
        ++reporter->progress().done;
        reporter->report();
      }
    } else if (develop_here) {
      develop_here(frame);
    }
    return 1;
  }

  int merge_render(const std::filesystem::path& path) {
    const auto& out = folder.dir();
    const auto& identity = folder.manifest().identity;
    {
      json r;
      try {
        r = json::parse(read_text(path));
      } catch (const json::exception&) {
        return 0;  // renamed into place atomically, so this is not ours: leave it
      }
      const int frame = r.value("frame", 0);
      const Pass pass = r.value("pass", "frame") == "mask" ? Pass::mask : Pass::image;
      const auto* f = folder.find(frame);
      std::filesystem::remove(path);
      // A result made from other inputs than the manifest now names is stale: ignore it.
      if (f == nullptr || r.value("hash", "") != f->input_hash) return 1;
      if (r.value("status", "") == "rendered") {
        // Verified by the task before it was renamed into place; checked again here, since
        // the result may be from a run long gone.
        if (output::image_is_complete(out / final_image_name(pass, frame, folder.digits()),
                                      identity.width, identity.height)) {
          callbacks.on_rendered(pass, frame, r.value("seconds", 0.0));
          return 1;
        }
      }
      FrameFailure failure;
      failure.frame = frame;
      failure.pass = pass;
      failure.command = r.value("command", "");
      failure.exit_code = r.value("exit_code", 0);
      failure.log = r.value("log", "");
      failure.error_lines = r.value("error_lines", std::vector<std::string>{});
      if (failure.error_lines.empty()) failure.error_lines = {"the rendered image is not complete"};
      callbacks.on_failed(failure);
    }
    return 1;
  }
};

// True while the job has tasks pending or running. squeue forgets finished jobs, so an empty
// answer (or "Invalid job id") means done.
bool job_active(const std::string& job_id) {
  ProcessSpec spec;
  spec.argv = {"squeue", "-h", "-j", job_id, "-o", "%T"};
  const auto r = run_capture(spec);
  if (r.exit_code != 0) return false;
  return r.out.find_first_not_of(" \n") != std::string::npos;
}

}  // namespace

std::vector<std::vector<int>> share_frames(const std::vector<int>& frames, int tasks) {
  std::vector<std::vector<int>> shares;
  const int n = static_cast<int>(frames.size());
  tasks = std::clamp(tasks, 1, std::max(n, 1));
  for (int t = 0; t < tasks && n > 0; ++t) {
    // Task t takes frames [t·n/tasks, (t+1)·n/tasks): sizes differ by at most one.
    const auto begin = frames.begin() + t * n / tasks;
    const auto end = frames.begin() + (t + 1) * n / tasks;
    shares.emplace_back(begin, end);
  }
  return shares;
}

std::string sbatch_script(const std::filesystem::path& out_dir,
                          const std::filesystem::path& raintrace_exe, int tasks) {
  const std::string out = std::filesystem::absolute(out_dir).lexically_normal().string();
  return fmt::format(
      "#!/bin/bash\n"
      "# Written by raintrace: renders {0} with one array task per share of frames.\n"
      "#SBATCH --job-name=raintrace-render\n"
      "#SBATCH --array=0-{1}\n"
      "#SBATCH --output={2}/logs/slurm_%A_%a.out\n"
      "#SBATCH --chdir={2}\n"
      "exec {3} render --slurm-task {4}\n",
      out, tasks - 1, out, shell_single_quote(raintrace_exe.string()), shell_single_quote(out));
}

RenderSummary render_slurm(FolderState& folder, const SlurmRenderSettings& settings) {
  // Absolute: sbatch runs inside the folder, where a relative path (-o out/x) means nothing.
  const auto out_dir = std::filesystem::absolute(folder.dir()).lexically_normal();
  if (!find_program("sbatch") || !find_program("squeue")) {
    throw std::runtime_error(
        "Slurm not found (sbatch/squeue): install slurm-client or use --backend local");
  }
  // This machine develops what the nodes could not (and frames whose EXR is all they lack).
  const auto display = prepare_develop(folder);
  RenderSummary summary;
  ProgressReporter reporter{settings.on_progress};
  auto& progress = reporter.progress();
  DevelopQueue developer{out_dir, develop_target(folder.manifest()), *display, settings.stop};
  // Nodes develop their own frames: a rendered frame waits for its task's develop result.
  RunnerCallbacks callbacks =
      folder_callbacks(folder, reporter, summary, settings.on_failed, nullptr);
  auto status = [&](const std::string& text) {
    if (settings.on_status) settings.on_status(text);
  };
  {
    // Results of an earlier, interrupted submission count before planning.
    RenderSummary earlier;
    ProgressReporter quiet{nullptr};
    const RunnerCallbacks record = folder_callbacks(folder, quiet, earlier, nullptr, nullptr);
    Merger{folder, record, nullptr, nullptr}.merge_all();
  }
  clean_temp_images(out_dir);
  const output::RenderPlan plan = folder.plan({settings.force, settings.only});
  if (settings.on_plan) settings.on_plan(plan);
  progress.total = static_cast<int>(plan.images.size() + plan.masks.size() + plan.develops.size());
  progress.skipped = plan.up_to_date;
  for (const int frame : plan.develops) developer.submit(frame, true);
  auto finish = [&] {
    // Frames whose EXR is current and whose PNG is not (a node without blender-data, a task
    // that died between render and develop): developed here.
    for (const auto& f : folder.manifest().frames) {
      if (plan.develops.end() != std::find(plan.develops.begin(), plan.develops.end(), f.number))
        continue;
      if (output::needs_develop(folder.decide_develop(f.number))) developer.submit(f.number);
    }
    finish_developing(developer, folder, reporter, summary, settings.on_failed);
    if (settings.stop != nullptr && settings.stop->load()) summary.interrupted = true;
    reporter.report();
    summary.progress = progress;
    return summary;
  };
  if (plan.images.empty() && plan.masks.empty()) return finish();
  const auto& identity = folder.manifest().identity;
  {
    // Array tasks may start POV-Ray as soon as the job is submitted, so the plate is finished
    // here first; the folder is shared, so the nodes see it.
    EnvironmentPlate plate{out_dir, identity.width, identity.height, settings.stop};
    plate.wait();
    if (plate.interrupted()) {
      summary.interrupted = true;
      return finish();
    }
    if (!plate.problem().empty()) status(environment_plate_notice(plate));
  }

  int tasks = settings.tasks > 0 ? settings.tasks : std::clamp((progress.total + 7) / 8, 1, 64);
  const auto image_shares = share_frames(plan.images, tasks);
  const auto mask_shares = share_frames(plan.masks, tasks);
  tasks = static_cast<int>(std::max(image_shares.size(), mask_shares.size()));
  json plan_tasks = json::array();
  for (int t = 0; t < tasks; ++t) {
    const auto spans_of = [&](const std::vector<std::vector<int>>& shares) {
      return t < static_cast<int>(shares.size())
                 ? split_into_spans(shares[static_cast<std::size_t>(t)], 1, 16)
                 : std::vector<FrameSpan>{};
    };
    plan_tasks.push_back({{"images", spans_to_json(spans_of(image_shares))},
                          {"masks", spans_to_json(spans_of(mask_shares))}});
  }
  std::filesystem::create_directories(out_dir / "logs");
  std::filesystem::remove_all(results_dir(out_dir));
  std::filesystem::create_directories(results_dir(out_dir));
  // The run id proves to each task that it works for the run holding the folder's lock.
  povgen::write_file_atomic(out_dir / "slurm" / "plan.json",
                            json{{"run_id", folder.holder().run_id},
                                 {"develop_hash", folder.develop_hash()},
                                 {"tasks", plan_tasks}}
                                    .dump(1) +
                                "\n");
  const auto script = out_dir / "slurm" / "render.sbatch";
  povgen::write_file_atomic(script, sbatch_script(out_dir, settings.raintrace_exe, tasks));
  prepare_povray_home(out_dir);
  for (const int f : plan.images) folder.rendering(Pass::image, {f, f});
  for (const int f : plan.masks) folder.rendering(Pass::mask, {f, f});
  folder.save();

  ProcessSpec submit;
  submit.argv = {"sbatch", "--parsable"};
  if (!settings.partition.empty()) submit.argv.push_back("--partition=" + settings.partition);
  submit.argv.push_back(script.string());
  submit.working_dir = out_dir;
  submit.log_path = out_dir / "logs" / "sbatch.log";
  const auto submitted = run_capture(submit);
  std::string job_id = submitted.out.substr(0, submitted.out.find_first_of(";\n"));
  if (submitted.exit_code != 0 || job_id.empty()) {
    throw std::runtime_error(fmt::format("sbatch failed (exit code {}): {}", submitted.exit_code,
                                         read_text(submit.log_path)));
  }
  status(fmt::format("submitted Slurm job {} ({} array tasks); logs in {}/logs/", job_id, tasks,
                     out_dir.string()));

  Merger merger{folder, callbacks, &reporter, [&developer](int f) { developer.submit(f); }};
  // The ETA follows the tasks' pace, as a local render's follows its processes' (slurm_flight.h).
  reporter.follow_pace();
  FlightFollower flights;
  for (;;) {
    if (settings.stop != nullptr && settings.stop->load()) {
      ProcessSpec cancel;
      cancel.argv = {"scancel", job_id};
      run_capture(cancel);
      while (job_active(job_id)) std::this_thread::sleep_for(std::chrono::milliseconds(200));
      merger.merge_all();
      summary.interrupted = true;
      return finish();
    }
    const bool active = job_active(job_id);
    merger.merge_all();
    flights.follow(results_dir(out_dir), folder.holder().run_id, reporter);
    record_developed(folder, reporter, summary, developer.take(), settings.on_failed);
    reporter.report();
    if (!active) break;
    std::this_thread::sleep_for(std::chrono::duration<double>(settings.poll_seconds));
  }

  // Pictures no result file spoke for: their task died (node failure, time limit, no POV-Ray).
  for (int t = 0; t < tasks; ++t) {
    for (const auto pass : {Pass::image, Pass::mask}) {
      const auto& spans =
          plan_tasks[static_cast<std::size_t>(t)][pass == Pass::image ? "images" : "masks"];
      for (const auto& span : spans_from_json(spans)) {
        for (int f = span.first; f <= span.last; ++f) {
          if (folder.decide(pass, f, false) == output::RenderReason::up_to_date) continue;
          bool already = false;
          for (const auto& failure : summary.failures) {
            already |= failure.frame == f && failure.pass == pass;
          }
          if (already) continue;
          FrameFailure failure;
          failure.frame = f;
          failure.pass = pass;
          failure.command = "sbatch " + script.string();
          failure.exit_code = -1;
          failure.log = fmt::format("logs/slurm_{}_{}.out", job_id, t);
          failure.error_lines = {fmt::format(
              "Slurm task {} ended without a result for this frame (see {})", t, failure.log)};
          callbacks.on_failed(failure);
        }
      }
    }
  }
  return finish();
}

int run_slurm_task(const std::filesystem::path& out_dir_in, int task_index,
                   const std::atomic<bool>* stop) {
  const auto out_dir = std::filesystem::absolute(out_dir_in).lexically_normal();
  require_povray();
  const auto plan = json::parse(read_text(out_dir / "slurm" / "plan.json"));
  const std::string run_id = plan.value("run_id", "");
  output::require_lock_held_by(out_dir, run_id);
  const auto& tasks = plan.at("tasks");
  if (task_index < 0 || task_index >= static_cast<int>(tasks.size())) {
    throw std::runtime_error(fmt::format("Slurm task {} is not in {}/slurm/plan.json (0..{})",
                                         task_index, out_dir.string(), tasks.size() - 1));
  }
  // Read-only here: only the submitting raintrace changes the folder's state.
  const auto manifest = output::read_manifest(out_dir / output::kManifest);
  std::map<int, std::string> hash_of;
  for (const auto& f : manifest.frames) hash_of[f.number] = f.input_hash;

  std::deque<RenderJob> jobs;
  const auto& mine = tasks.at(static_cast<std::size_t>(task_index));
  for (const auto& s : spans_from_json(mine.at("images"))) jobs.push_back({Pass::image, s});
  for (const auto& s : spans_from_json(mine.at("masks"))) jobs.push_back({Pass::mask, s});

  RunnerSettings runner;
  runner.jobs = 1;  // Slurm gave this task its share of the node; POV-Ray traces multi-threaded
  runner.width = manifest.identity.width;
  runner.height = manifest.identity.height;
  runner.digits = output::frame_digits(manifest);
  runner.stop = stop;
  bool all_ok = true;
  auto write_result = [&](Pass pass, int frame, json result) {
    result["frame"] = frame;
    result["pass"] = output::pass_prefix(pass);
    result["hash"] = hash_of[frame];
    result["run_id"] = run_id;
    povgen::write_file_atomic(results_dir(out_dir) / result_name(pass, frame), result.dump());
  };
  // Each task develops its own frames, on a thread beside its POV-Ray, when this node's
  // blender-data develops them exactly as the submitting machine would (same develop hash);
  // otherwise the submitting machine develops them after the job.
  const DevelopTarget target = develop_target(manifest);
  std::unique_ptr<film::DisplayTransform> display;
  std::string cannot_develop;
  try {
    display = std::make_unique<film::DisplayTransform>();
    const std::string here =
        output::develop_hash(manifest.develop, manifest.identity.seed,
                             display->response(target.settings.view, target.settings.look));
    if (here != plan.value("develop_hash", "")) {
      cannot_develop =
          "this node's blender-data or OpenColorIO develops other pictures than the "
          "submitting machine's";
    }
  } catch (const std::runtime_error& e) {
    cannot_develop = e.what();
  }
  std::unique_ptr<DevelopQueue> developer;
  if (cannot_develop.empty()) {
    developer = std::make_unique<DevelopQueue>(out_dir, target, *display, stop);
  }
  auto write_develop_result = [&](const DevelopResult& d) {
    json result{{"frame", d.frame},
                {"hash", hash_of[d.frame]},
                {"run_id", run_id},
                {"status", d.error.empty() ? "developed" : "failed"},
                {"seconds", d.seconds},
                {"error", d.error},
                {"develop_hash", plan.value("develop_hash", "")}};
    const auto exr =
        output::file_facts(out_dir / final_image_name(Pass::image, d.frame, target.digits));
    result["source_hash"] = exr ? exr->hash : "";
    povgen::write_file_atomic(results_dir(out_dir) / develop_result_name(d.frame), result.dump());
  };
  int developed = 0;
  auto write_develop_results = [&] {
    if (developer == nullptr) return;
    for (const DevelopResult& d : developer->take()) {
      developed += d.error.empty() ? 1 : 0;
      write_develop_result(d);
    }
  };
  // What this task's POV-Ray has in flight, for the submitting raintrace's ETA (slurm_flight.h).
  // Not written is not fatal: the ETA is a guide, and the frames' results say what went wrong.
  TaskFlight flight;
  auto publish = [&] {
    try {
      publish_flight(results_dir(out_dir), task_index, run_id, flight);
    } catch (const std::system_error&) {
    }
  };
  RunnerCallbacks callbacks;
  callbacks.on_started = [&](const RenderJob& job) {
    output::require_lock_held_by(out_dir, run_id);
    flight = {job.pass, job.span, job.span.first, -1.0};
    publish();
  };
  callbacks.on_traced_share = [&](Pass pass, int frame, double share) {
    flight.pass = pass;
    flight.frame = frame;
    flight.share = share;
    publish();
  };
  callbacks.on_rendered = [&](Pass pass, int frame, double seconds) {
    write_result(pass, frame, {{"status", "rendered"}, {"seconds", seconds}});
    if (pass == flight.pass && frame == flight.frame && frame < flight.span.last) {
      flight.frame = frame + 1;
      flight.share = -1.0;
      publish();
    }
    if (pass != Pass::image) return;
    if (developer != nullptr) {
      developer->submit(frame);
    } else {
      write_develop_result({frame, false, 0.0, cannot_develop});
    }
  };
  callbacks.on_tick = write_develop_results;
  callbacks.on_failed = [&](const FrameFailure& failure) {
    all_ok = false;
    write_result(failure.pass, failure.frame,
                 {{"status", "failed"},
                  {"command", failure.command},
                  {"exit_code", failure.exit_code},
                  {"log", failure.log},
                  {"error_lines", failure.error_lines},
                  {"error", failure.summary()}});
  };
  const bool finished = run_povray_jobs(out_dir, std::move(jobs), runner, callbacks);
  retire_flight(results_dir(out_dir), task_index);
  while (developer != nullptr && !developer->idle()) {
    write_develop_results();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  write_develop_results();
  // In the task's Slurm log (logs/slurm_JOB_TASK.out), for whoever wonders where frames went.
  std::fprintf(stderr, "raintrace Slurm task %d: %d frames developed here%s%s\n", task_index,
               developed,
               cannot_develop.empty() ? "" : "; not developed here: ", cannot_develop.c_str());
  return finished && all_ok ? 0 : 1;
}

}  // namespace raintrace::render
