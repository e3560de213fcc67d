// Cluster backend: the folder's plan (output::FolderState::plan) rendered as one Slurm job
// array. Each array task runs `raintrace render --slurm-task OUT` on a node, which renders its
// share of frames with the same runner as the local backend (verify, then rename) and drops one
// small result file per picture in OUT/slurm/results/. Only the submitting raintrace changes
// the folder's state: it holds the folder's lock for the whole job and merges result files as
// they appear, so tasks never race on the manifest and a re-run after an interruption picks up
// results that landed meanwhile. Tasks take no lock: they render in parallel under the
// submitter's, and check (before each span) that the folder is still held by the run whose id
// is in their plan, so a task outliving a killed submitter never writes into a folder that
// another run has taken since. OUT must be on a filesystem every node sees at the same path,
// and so must the raintrace binary.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/backend.h"

namespace raintrace::render {

struct SlurmRenderSettings : BackendSettings {
  int tasks = 0;                        ///< array size; 0 = one task per ~8 frames, at most 64
  std::string partition;                ///< sbatch --partition; empty = the cluster's default
  std::filesystem::path raintrace_exe;  ///< absolute path the nodes run for each task
  double poll_seconds = 1.0;            ///< how often squeue and the results folder are checked
  std::function<void(const std::string&)> on_status;  ///< "submitted job 12 (4 tasks)", …
};

/// One task's share: spans of images and of masks.
struct SlurmTaskPlan {
  std::vector<FrameSpan> images;
  std::vector<FrameSpan> masks;
};

/// Splits frames into `tasks` contiguous, nearly equal shares (fewer when there are fewer frames).
std::vector<std::vector<int>> share_frames(const std::vector<int>& frames, int tasks);

/// The batch script: `#SBATCH --array=0-(tasks-1)`, logs in OUT/logs/slurm_%A_%a.out, runs
/// `raintrace_exe render --slurm-task OUT`.
std::string sbatch_script(const std::filesystem::path& out_dir,
                          const std::filesystem::path& raintrace_exe, int tasks);

/// Submits, follows and merges; throws std::runtime_error when sbatch is missing or refuses.
/// When something is to be rendered, the environment plate (environment_plate.h) is brought up to
/// date on this machine first; a failure is reported through on_status and frames render the
/// full environment.
RenderSummary render_slurm(output::FolderState& folder, const SlurmRenderSettings& settings);

/// The worker inside one array task (SLURM_ARRAY_TASK_ID selects its share). Returns 0 when all
/// its frames rendered, 1 otherwise; throws when the plan or manifest is unusable, or when the
/// folder is no longer held by the run that submitted the task.
int run_slurm_task(const std::filesystem::path& out_dir, int task_index,
                   const std::atomic<bool>* stop = nullptr);

}  // namespace raintrace::render
