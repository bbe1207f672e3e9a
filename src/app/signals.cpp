#include "app/signals.hpp"

#include <signal.h>

namespace collide::app {
namespace {

// How many StopSignals are alive. Only the main thread creates and destroys them; the handler
// never touches this.
int g_depth = 0;

struct sigaction g_previous_int {};
struct sigaction g_previous_term {};

// Async-signal-safe: one lock-free atomic store.
extern "C" void onStopSignal(int signal_number) {
  core::requestStop(signal_number);
}

}  // namespace

StopSignals::StopSignals() {
  if (g_depth++ > 0) return;
  core::clearStopRequest();
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the next signal of the same kind gets the default action (terminate).
  // SA_RESTART: file writes interrupted by the signal resume instead of failing with EINTR.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

StopSignals::~StopSignals() {
  if (--g_depth > 0) return;
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  // A signal that came after the last check point found the work complete; it must not stop a
  // later run in this process (the in-process tests run many).
  core::clearStopRequest();
}

int StopSignals::received() {
  return core::stopRequested();
}

void StopSignals::throwIfReceived(const std::string& what_is_removed) {
  const int signal_number = received();
  if (signal_number == 0) return;
  throw InterruptedError(signal_number, "removed the partly written " + what_is_removed);
}

}  // namespace collide::app
