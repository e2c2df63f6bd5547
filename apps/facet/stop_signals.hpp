// Stopping a frame sequence cleanly: while a StopSignals lives, the first Ctrl-C (SIGINT) or
// SIGTERM (what Slurm and Kubernetes send before they kill) is only recorded, so the sequence
// can finish the frame it is on and stop with every written file whole; a second one ends the
// program at once, as it would have without.
#pragma once

#include <csignal>

namespace facet::cli {

class StopSignals {
 public:
  StopSignals();   // installs the handlers
  ~StopSignals();  // puts the previous ones back
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal received (SIGINT or SIGTERM), or 0.
  int received() const;

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

}  // namespace facet::cli
