#pragma once
// SIGINT (Ctrl-C) and SIGTERM while a command writes files: instead of dying with a temporary
// file left behind, the run notices at its next check point (between frames, between collisions
// written, between CSV rows, in the physics run), unwinds (every temporary file is removed, an
// earlier file at the target stays as it was) and exits with the shell's convention for a signal,
// 128 + its number (130 for SIGINT, 143 for SIGTERM), after one line saying what became of the
// output.
#include <string>

#include "core/stop_request.hpp"

namespace collide::app {

// Thrown when a stop signal arrived; carries exit code 128 + signal number.
using InterruptedError = core::StopRequested;

// While at least one is alive, SIGINT and SIGTERM record a stop request (core/stop_request.hpp)
// instead of ending the process. Nestable: the first installs the handler and clears any old
// request, the last puts the previous handlers back, the ones between change nothing, so a
// command may hold one for its whole run and the pipelines it calls hold their own. A second
// signal of the same kind ends the process at once (the handler resets itself), for a user who
// really wants out. Create and destroy them on one thread (the main one).
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal that arrived (SIGINT, SIGTERM), or 0.
  static int received();
  // Throws InterruptedError "stopped by SIGINT; removed the partly written <what_is_removed>" if
  // a signal arrived.
  static void throwIfReceived(const std::string& what_is_removed);
};

// Runs `work` (a simulation, before any output is opened); if a stop signal ends it, the
// InterruptedError says "nothing was written to <targets>" (e.g. "'still.png'").
template <class Work>
auto beforeWriting(const std::string& targets, Work&& work) -> decltype(work()) {
  try {
    return work();
  } catch (const InterruptedError& stop) {
    throw InterruptedError(stop.signalNumber(), "nothing was written to " + targets);
  }
}

}  // namespace collide::app
