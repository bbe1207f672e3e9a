#pragma once
// SIGINT (Ctrl-C) and SIGTERM during a render: instead of dying with a half-written file, the
// pipeline notices between frames, unwinds (every sink removes what it wrote) and exits with the
// shell's convention for a signal, 128 + its number (130 for SIGINT, 143 for SIGTERM).
#include <string>

#include "core/error.hpp"

namespace collide::app {

// Thrown when a stop signal arrived; carries exit code 128 + signal number.
class InterruptedError : public core::Error {
 public:
  InterruptedError(int signal_number, const std::string& message);
  int signalNumber() const { return signal_number_; }

 private:
  int signal_number_;
};

// While alive, SIGINT and SIGTERM set a flag instead of ending the process; the previous handlers
// come back on destruction. A second signal of the same kind ends the process at once (the
// handler resets itself), for a user who really wants out. Not nestable.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal that arrived (SIGINT, SIGTERM), or 0.
  static int received();
  // Throws InterruptedError naming `what_is_removed` if a signal arrived.
  static void throwIfReceived(const std::string& what_is_removed);
};

}  // namespace collide::app
