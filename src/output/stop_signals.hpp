#pragma once
// SIGINT (Ctrl-C), SIGTERM and SIGHUP (a closed terminal or SSH session) while a command writes
// files: instead of dying with a temporary file left behind, the run notices at its next check
// point (between frames, between collisions written, between CSV rows, in the physics run),
// unwinds (every temporary file is removed, an earlier file at the target stays as it was) and
// exits with the shell's convention for a signal, 128 + its number (130 for SIGINT, 143 for
// SIGTERM, 129 for SIGHUP), after one line saying what became of the output.
//
// A run that cannot reach a check point (a write blocked on a FIFO or a stalled pipe, a read of a
// FIFO given as a font) still ends: a stop signal also starts a watchdog, and a run still going
// kStopGraceSeconds later removes its temporary files and exits at once with the same code. Any
// other signal that ends a process (SIGQUIT, SIGPIPE, SIGALRM, SIGXCPU, SIGUSR1, a crash, ...)
// first removes the process's temporary files (output/temp_file.hpp), then ends it as it would
// have.
#include <string>

#include "core/stop_request.hpp"

namespace collide::output {

// Thrown when a stop signal arrived; carries exit code 128 + signal number.
using InterruptedError = core::StopRequested;

// Seconds a stopped run has to end by itself before the watchdog ends it.
inline constexpr unsigned kStopGraceSeconds = 2;

// main() only, first thing: every other signal that would end the process and is not ignored
// removes this process's temporary files first; SIGINT and SIGTERM ignored by a parent shell
// (a script's background job) get their default action back, so a stop is never lost.
// Standard input, output and error that were closed are held by /dev/null opened the wrong way, so
// that reading or writing them fails (EBADF) instead of reaching a file opened later, which would
// otherwise get their numbers.
void prepareProcess();

// While at least one is alive, SIGINT, SIGTERM and SIGHUP (unless ignored when the program
// started) record a stop request (core/stop_request.hpp) instead of ending the process. Nestable:
// the first installs the handlers and clears any old request, the last puts the previous handlers
// back, the ones between change nothing, so a command may hold one for its whole run and the
// pipelines it calls hold their own. A second stop signal ends the process at once (its temporary
// files removed), for a user who really wants out. Create and destroy them on one thread (the
// main one). `grace_seconds`: the watchdog's (see above), set by the outermost.
class StopSignals {
 public:
  explicit StopSignals(unsigned grace_seconds = kStopGraceSeconds);
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // For a host that handles stop signals itself and passes them on with core::requestStop (the
  // Python module: the interpreter owns SIGINT, and several threads may render at once): from
  // then on StopSignals install no handler, start no watchdog and clear no request, on any thread;
  // the host clears requests. Call before any StopSignals is alive.
  static void leaveToHost();

  // The signal that arrived (SIGINT, SIGTERM, SIGHUP), or 0.
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

}  // namespace collide::output
