// Ctrl-C and SIGTERM while a command works on an output folder: the handler only sets a flag,
// and everything long-running (the simulation's substeps, the export's frames, POV-Ray's
// processes, the Slurm job) watches it and stops within a fraction of a second, keeping what is
// finished. Shared by `raintrace export` and `raintrace render`.
#pragma once

#include <atomic>
#include <csignal>

namespace raintrace::cli {

/// Set by the handler; what long-running work watches.
std::atomic<bool>& stop_requested();
/// The signal that set it (SIGINT or SIGTERM); 0 before any.
int stop_signal();

/// Installs the SIGINT/SIGTERM handlers for its lifetime and restores the previous ones after.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

 private:
  struct sigaction m_old_int {};
  struct sigaction m_old_term {};
};

/// "SIGINT" or "SIGTERM", for messages.
const char* stop_signal_name();
/// The exit code of a run stopped by a signal: 128 + its number (130 for SIGINT).
int interrupted_exit_code();

}  // namespace raintrace::cli
