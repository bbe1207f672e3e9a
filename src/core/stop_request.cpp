#include "core/stop_request.hpp"

#include <signal.h>

#include <atomic>

namespace collide::core {
namespace {

// A lock-free atomic is async-signal-safe to store from a handler (a mutex would not be).
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

std::string messageFor(int signal_number, const std::string& consequence) {
  std::string message = "stopped by " + signalName(signal_number);
  if (!consequence.empty()) message += "; " + consequence;
  return message;
}

}  // namespace

void requestStop(int signal_number) noexcept {
  g_stop_signal.store(signal_number, std::memory_order_relaxed);
}

int stopRequested() noexcept {
  return g_stop_signal.load(std::memory_order_relaxed);
}

void clearStopRequest() noexcept {
  g_stop_signal.store(0, std::memory_order_relaxed);
}

std::string signalName(int signal_number) {
  if (signal_number == SIGINT) return "SIGINT";
  if (signal_number == SIGTERM) return "SIGTERM";
  if (signal_number == SIGHUP) return "SIGHUP";
  return "signal " + std::to_string(signal_number);
}

StopRequested::StopRequested(int signal_number, const std::string& consequence)
    : Error(static_cast<ExitCode>(128 + signal_number), messageFor(signal_number, consequence)),
      signal_number_(signal_number),
      has_consequence_(!consequence.empty()) {}

void throwIfStopRequested() {
  const int signal_number = stopRequested();
  if (signal_number != 0) throw StopRequested(signal_number, "");
}

}  // namespace collide::core
