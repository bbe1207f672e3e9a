#pragma once
// A request from outside to stop the run (SIGINT, SIGTERM, SIGHUP). The app's signal handler
// records it; long loops in any module (the physics run, the report writers) check it and stop by
// throwing StopRequested, without knowing about signals. Reading the request costs one relaxed
// atomic load, cheap enough to check once per collision.
#include <string>

#include "core/error.hpp"

namespace collide::core {

// Records that `signal_number` asked the run to stop. Async-signal-safe: one store to a lock-free
// atomic, so a signal handler may call it.
void requestStop(int signal_number) noexcept;

// The signal number that asked the run to stop, or 0 while none has.
int stopRequested() noexcept;

// Forgets a request, when stop handling starts or ends.
void clearStopRequest() noexcept;

// "SIGINT", "SIGTERM", "SIGHUP", or "signal N" for any other.
std::string signalName(int signal_number);

// The run stopped on request. Exit code 128 + the signal number, the shell's convention for a
// process ended by a signal (130 for SIGINT, 143 for SIGTERM). Message: "stopped by SIGINT" and,
// when given, "; " and what became of the output ("removed the partly written file 'a.json'").
class StopRequested : public Error {
 public:
  StopRequested(int signal_number, const std::string& consequence);
  int signalNumber() const { return signal_number_; }
  bool saysWhatBecameOfTheOutput() const { return has_consequence_; }

 private:
  int signal_number_;
  bool has_consequence_;
};

// Throws StopRequested (without a consequence; the caller that owns the output adds one) if a
// stop was requested.
void throwIfStopRequested();

}  // namespace collide::core
