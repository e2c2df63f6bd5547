// Recording the first stop signal (see stop_signals.hpp).
#include "stop_signals.hpp"

namespace facet::cli {
namespace {

volatile std::sig_atomic_t g_received = 0;
volatile std::sig_atomic_t g_caught_int = 0, g_caught_term = 0;  // handlers installed for

// Only async-signal-safe calls (POSIX.1-2017 2.4.3 lists signal()): the default actions go back
// so that a second signal of either kind ends the program.
void record(int signal) {
  g_received = signal;
  if (g_caught_int) std::signal(SIGINT, SIG_DFL);
  if (g_caught_term) std::signal(SIGTERM, SIG_DFL);
}

// Installs `record` for `signal` unless it is ignored (as a shell ignores SIGINT for a command
// it starts in the background), keeping the previous action.
bool catch_signal(int signal, struct sigaction& previous) {
  sigaction(signal, nullptr, &previous);
  if (previous.sa_handler == SIG_IGN) return false;
  struct sigaction action {};
  action.sa_handler = record;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(signal, &action, nullptr);
  return true;
}

}  // namespace

StopSignals::StopSignals() {
  g_received = 0;
  g_caught_int = catch_signal(SIGINT, previous_int_);
  g_caught_term = catch_signal(SIGTERM, previous_term_);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
  g_caught_int = 0;
  g_caught_term = 0;
}

int StopSignals::received() const { return g_received; }

}  // namespace facet::cli
