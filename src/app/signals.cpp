#include "app/signals.hpp"

#include <signal.h>

#include <atomic>
#include <cstring>

namespace collide::app {
namespace {

// Lock-free atomics are async-signal-safe to store from a handler.
std::atomic<int> g_received{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction g_previous_int {};
struct sigaction g_previous_term {};

extern "C" void onStopSignal(int signal_number) {
  g_received.store(signal_number);
}

}  // namespace

InterruptedError::InterruptedError(int signal_number, const std::string& message)
    : core::Error(static_cast<core::ExitCode>(128 + signal_number), message),
      signal_number_(signal_number) {}

StopSignals::StopSignals() {
  g_received.store(0);
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
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int StopSignals::received() {
  return g_received.load();
}

void StopSignals::throwIfReceived(const std::string& what_is_removed) {
  const int signal_number = received();
  if (signal_number == 0) return;
  const char* name = signal_number == SIGINT    ? "SIGINT"
                     : signal_number == SIGTERM ? "SIGTERM"
                                                : "a signal";
  throw InterruptedError(signal_number, std::string("stopped by ") + name +
                                            "; removed the partly "
                                            "written " +
                                            what_is_removed);
}

}  // namespace collide::app
