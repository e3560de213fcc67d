// Slurm backend: plan file, batch script, submission, following with squeue, result merging.
#include "render/slurm_render.h"

#include <fmt/core.h>
#include <chrono>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "povgen/manifest.h"
#include "render/environment_plate.h"
#include "render/frame_plan.h"
#include "render/process.h"

namespace raintrace::render {
namespace {

using nlohmann::json;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in{path, std::ios::binary};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_atomically(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  const auto temp = path.parent_path() / ("." + path.filename().string() + ".tmp");
  {
    std::ofstream out{temp, std::ios::binary | std::ios::trunc};
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write " + temp.string());
  }
  std::filesystem::rename(temp, path);
}

std::filesystem::path results_dir(const std::filesystem::path& out) {
  return out / "slurm" / "results";
}

std::string result_name(Pass pass, int frame) {
  return fmt::format("{}_{:04d}.json", pass == Pass::image ? "image" : "mask", frame);
}

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

// A result file as written by a task, applied to the manifest and the summary.
struct Merger {
  const std::filesystem::path& out;
  povgen::Manifest& manifest;
  RenderSummary& summary;
  const SlurmRenderSettings* settings = nullptr;

  // Returns the number of result files consumed.
  int merge_all() {
    std::error_code ec;
    if (!std::filesystem::is_directory(results_dir(out), ec)) return 0;
    int consumed = 0;
    bool manifest_changed = false;
    for (const auto& entry : std::filesystem::directory_iterator(results_dir(out))) {
      const auto name = entry.path().filename().string();
      if (name.empty() || name[0] == '.' || entry.path().extension() != ".json") continue;
      json r;
      try {
        r = json::parse(read_text(entry.path()));
      } catch (const json::exception&) {
        continue;  // renamed into place atomically, so this is not ours: leave it
      }
      const int frame = r.value("frame", 0);
      const Pass pass = r.value("pass", "image") == "mask" ? Pass::mask : Pass::image;
      const bool ok = r.value("status", "") == "rendered";
      for (auto& f : manifest.frames) {
        if (f.number != frame || pass != Pass::image) continue;
        // A result made from other inputs than the manifest now names is stale: ignore it.
        if (r.value("hash", "") != f.input_hash) break;
        f.status = ok ? "rendered" : "failed";
        f.rendered_hash = ok ? f.input_hash : std::string{};
        f.render_seconds = r.value("seconds", 0.0);
        f.error = r.value("error", "");
        manifest_changed = true;
      }
      if (ok) {
        ++summary.progress.done;
      } else {
        FrameFailure failure;
        failure.frame = frame;
        failure.pass = pass;
        failure.command = r.value("command", "");
        failure.exit_code = r.value("exit_code", 0);
        failure.log = r.value("log", "");
        failure.error_lines = r.value("error_lines", std::vector<std::string>{});
        ++summary.progress.failed;
        summary.failures.push_back(failure);
        if (settings != nullptr && settings->on_failed) settings->on_failed(failure);
      }
      std::filesystem::remove(entry.path());
      ++consumed;
    }
    if (manifest_changed) povgen::write_manifest(out / "manifest.json", manifest);
    return consumed;
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

RenderSummary render_slurm(const std::filesystem::path& out_dir_in,
                           const SlurmRenderSettings& settings) {
  const auto out_dir = std::filesystem::absolute(out_dir_in).lexically_normal();
  if (!find_program("sbatch") || !find_program("squeue")) {
    throw std::runtime_error(
        "Slurm not found (sbatch/squeue): install slurm-client or use --backend local");
  }
  const auto manifest_path = out_dir / "manifest.json";
  povgen::Manifest manifest = povgen::read_manifest(manifest_path);
  RenderSummary summary;
  // Results of an earlier, interrupted submission count before planning.
  Merger{out_dir, manifest, summary}.merge_all();
  summary = {};
  clean_temp_images(out_dir);
  const int digits = frame_digits(manifest);

  const auto frames = frames_needing_render(manifest, out_dir, settings.force, settings.only);
  std::vector<int> masks;
  if (settings.mask) {
    for (const auto& f : manifest.frames) {
      if (settings.only && (f.number < settings.only->first || f.number > settings.only->last)) {
        continue;
      }
      if (settings.force || std::binary_search(frames.begin(), frames.end(), f.number) ||
          !std::filesystem::exists(out_dir / final_image_name(Pass::mask, f.number, digits))) {
        masks.push_back(f.number);
      }
    }
  }
  auto& progress = summary.progress;
  progress.total = static_cast<int>(frames.size() + masks.size());
  progress.skipped = static_cast<int>(manifest.frames.size() - frames.size());
  if (progress.total == 0) return summary;
  {
    // Array tasks may start POV-Ray as soon as the job is submitted, so the plate is finished
    // here first; the folder is shared, so the nodes see it.
    EnvironmentPlate plate{out_dir, manifest.width, manifest.height, settings.stop};
    plate.wait();
    if (plate.interrupted()) {
      summary.interrupted = true;
      return summary;
    }
    if (!plate.problem().empty() && settings.on_status) {
      settings.on_status(environment_plate_notice(plate));
    }
  }

  int tasks = settings.tasks > 0 ? settings.tasks : std::clamp((progress.total + 7) / 8, 1, 64);
  const auto image_shares = share_frames(frames, tasks);
  const auto mask_shares = share_frames(masks, tasks);
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
  write_atomically(out_dir / "slurm" / "plan.json", json{{"tasks", plan_tasks}}.dump(1) + "\n");
  const auto script = out_dir / "slurm" / "render.sbatch";
  write_atomically(script, sbatch_script(out_dir, settings.raintrace_exe, tasks));
  prepare_povray_home(out_dir);

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
  if (settings.on_status) {
    settings.on_status(fmt::format("submitted Slurm job {} ({} array tasks); logs in {}/logs/",
                                   job_id, tasks, out_dir.string()));
  }

  const auto start = std::chrono::steady_clock::now();
  auto report = [&] {
    progress.elapsed_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int finished = progress.done + progress.failed;
    progress.eta_seconds =
        finished > 0 ? progress.elapsed_seconds / finished * (progress.total - finished) : -1.0;
    if (settings.on_progress) settings.on_progress(progress);
  };
  Merger merger{out_dir, manifest, summary, &settings};
  for (;;) {
    if (settings.stop != nullptr && settings.stop->load()) {
      ProcessSpec cancel;
      cancel.argv = {"scancel", job_id};
      run_capture(cancel);
      while (job_active(job_id)) std::this_thread::sleep_for(std::chrono::milliseconds(200));
      merger.merge_all();
      summary.interrupted = true;
      report();
      return summary;
    }
    const bool active = job_active(job_id);
    merger.merge_all();
    report();
    if (!active) break;
    std::this_thread::sleep_for(std::chrono::duration<double>(settings.poll_seconds));
  }

  // Frames no result file speaks for: their task died (node failure, time limit, no POV-Ray).
  const auto plan = json::parse(read_text(out_dir / "slurm" / "plan.json"));
  for (int t = 0; t < tasks; ++t) {
    for (const auto pass : {Pass::image, Pass::mask}) {
      const auto& spans =
          plan["tasks"][static_cast<std::size_t>(t)][pass == Pass::image ? "images" : "masks"];
      for (const auto& span : spans_from_json(spans)) {
        for (int f = span.first; f <= span.last; ++f) {
          if (std::filesystem::exists(out_dir / final_image_name(pass, f, digits))) {
            bool recorded = false;
            for (const auto& e : manifest.frames) {
              recorded |= pass == Pass::mask || (e.number == f && e.status == "rendered" &&
                                                 e.rendered_hash == e.input_hash);
            }
            if (recorded) continue;
          }
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
          ++progress.failed;
          summary.failures.push_back(failure);
          if (settings.on_failed) settings.on_failed(failure);
        }
      }
    }
  }
  report();
  return summary;
}

int run_slurm_task(const std::filesystem::path& out_dir_in, int task_index,
                   const std::atomic<bool>* stop) {
  const auto out_dir = std::filesystem::absolute(out_dir_in).lexically_normal();
  require_povray();
  const auto plan = json::parse(read_text(out_dir / "slurm" / "plan.json"));
  const auto& tasks = plan.at("tasks");
  if (task_index < 0 || task_index >= static_cast<int>(tasks.size())) {
    throw std::runtime_error(fmt::format("Slurm task {} is not in {}/slurm/plan.json (0..{})",
                                         task_index, out_dir.string(), tasks.size() - 1));
  }
  // Read-only here: only the submitting raintrace writes the manifest.
  const auto manifest = povgen::read_manifest(out_dir / "manifest.json");
  std::map<int, std::string> hash_of;
  for (const auto& f : manifest.frames) hash_of[f.number] = f.input_hash;

  std::deque<RenderJob> jobs;
  const auto& mine = tasks.at(static_cast<std::size_t>(task_index));
  for (const auto& s : spans_from_json(mine.at("images"))) jobs.push_back({Pass::image, s});
  for (const auto& s : spans_from_json(mine.at("masks"))) jobs.push_back({Pass::mask, s});

  RunnerSettings runner;
  runner.jobs = 1;  // Slurm gave this task its share of the node; POV-Ray traces multi-threaded
  runner.width = manifest.width;
  runner.height = manifest.height;
  runner.digits = frame_digits(manifest);
  runner.stop = stop;
  bool all_ok = true;
  RunnerCallbacks callbacks;
  callbacks.on_rendered = [&](Pass pass, int frame, double seconds) {
    write_atomically(results_dir(out_dir) / result_name(pass, frame),
                     json{{"frame", frame},
                          {"pass", pass == Pass::image ? "image" : "mask"},
                          {"status", "rendered"},
                          {"hash", hash_of[frame]},
                          {"seconds", seconds}}
                         .dump());
  };
  callbacks.on_failed = [&](const FrameFailure& failure) {
    all_ok = false;
    write_atomically(results_dir(out_dir) / result_name(failure.pass, failure.frame),
                     json{{"frame", failure.frame},
                          {"pass", failure.pass == Pass::image ? "image" : "mask"},
                          {"status", "failed"},
                          {"hash", hash_of[failure.frame]},
                          {"command", failure.command},
                          {"exit_code", failure.exit_code},
                          {"log", failure.log},
                          {"error_lines", failure.error_lines},
                          {"error", failure.summary()}}
                         .dump());
  };
  const bool finished = run_povray_jobs(out_dir, std::move(jobs), runner, callbacks);
  return finished && all_ok ? 0 : 1;
}

}  // namespace raintrace::render
