// Signal handling for the commands that write output folders.
#include "cli/stop_signals.h"

namespace raintrace::cli {
namespace {

// A lock-free atomic store is async-signal-safe.
std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};

extern "C" void on_stop_signal(int sig) {
  g_signal.store(sig);
  g_stop.store(true);
}

}  // namespace

std::atomic<bool>& stop_requested() { return g_stop; }
int stop_signal() { return g_signal.load(); }

StopSignals::StopSignals() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &m_old_int);
  sigaction(SIGTERM, &sa, &m_old_term);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &m_old_int, nullptr);
  sigaction(SIGTERM, &m_old_term, nullptr);
}

const char* stop_signal_name() { return stop_signal() == SIGTERM ? "SIGTERM" : "SIGINT"; }

int interrupted_exit_code() { return 128 + (stop_signal() != 0 ? stop_signal() : SIGINT); }

}  // namespace raintrace::cli
