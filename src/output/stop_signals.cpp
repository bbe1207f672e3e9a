#include "output/stop_signals.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

#include "output/process_end.hpp"
#include "output/temp_file.hpp"

namespace collide::output {
namespace {

// How many StopSignals are alive. Only the main thread creates and destroys them; the handlers
// never touch this.
int g_depth = 0;
// Set once by leaveToHost(), before any StopSignals lives; read by every one.
std::atomic<bool> g_left_to_host{false};
// The watchdog's delay, read by the stop handler.
volatile sig_atomic_t g_grace_seconds = kStopGraceSeconds;

// The stop signals and the watchdog's, with the actions they had before the outermost StopSignals.
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGALRM};
struct sigaction g_previous[sizeof kStopSignals / sizeof kStopSignals[0]];
bool g_installed[sizeof kStopSignals / sizeof kStopSignals[0]];

// Signals whose default action ends the process and that a handler can see. SIGINT, SIGTERM and
// SIGHUP are StopSignals' while outputs are open, and keep their default action otherwise (nothing
// to remove then). Crashes are left to the sanitizers where they watch (their reports need their
// own handlers).
constexpr int kEndingSignals[] = {SIGQUIT,   SIGUSR1, SIGUSR2,   SIGPIPE, SIGALRM, SIGXCPU,
                                  SIGVTALRM, SIGPROF, SIGSTKFLT, SIGIO,   SIGPWR};
constexpr int kCrashSignals[] = {SIGILL, SIGTRAP, SIGABRT, SIGBUS, SIGFPE, SIGSEGV, SIGSYS};

void writeError(const char* text) {
  const std::size_t length = std::strlen(text);
  (void)!::write(STDERR_FILENO, text, length);
}

// Removes the temporary files, then lets `signal_number` end the process as it would have
// (async-signal-safe). Delivered when the handler returns: it is blocked while its handler runs.
void endAsSignal(int signal_number) {
  output::removeOwnTemporaryFiles();
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

extern "C" void onEndingSignal(int signal_number) {
  endAsSignal(signal_number);
}

// The first stop signal asks the run to stop and starts the watchdog; a second ends it now.
extern "C" void onStopSignal(int signal_number) {
  if (core::stopRequested() != 0) {
    endAsSignal(signal_number);
    return;
  }
  core::requestStop(signal_number);
  ::alarm(static_cast<unsigned>(g_grace_seconds));
}

extern "C" void onWatchdog(int signal_number) {
  const int stop = core::stopRequested();
  if (stop == 0) {  // an alarm from outside, not the watchdog's
    endAsSignal(signal_number);
    return;
  }
  output::removeOwnTemporaryFiles();
  writeError("collide: stopped by ");
  writeError(stop == SIGINT ? "SIGINT" : stop == SIGTERM ? "SIGTERM" : "SIGHUP");
  writeError(
      "; the run did not reach a point to stop at (a read or write was blocked), so it ended "
      "at once and removed its temporary files\n");
  ::_exit(128 + stop);
}

// A closed standard descriptor gets /dev/null opened the other way round: reading fd 0 and writing
// fds 1 and 2 then fail with EBADF, as they did while closed.
void holdClosedStandardDescriptors() {
  for (const int fd : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO}) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int opened = ::open("/dev/null", fd == STDIN_FILENO ? O_WRONLY : O_RDONLY);
    if (opened >= 0 && opened != fd) {
      ::dup2(opened, fd);
      ::close(opened);
    }
  }
}

// A signal whose action is the default one (nohup's ignored SIGHUP stays ignored) removes the
// temporary files before it ends the process.
void handleIfDefault(int signal_number) {
  struct sigaction old {};
  if (::sigaction(signal_number, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) return;
  struct sigaction action {};
  action.sa_handler = onEndingSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(signal_number, &action, nullptr);
}

}  // namespace

void prepareProcess() {
  holdClosedStandardDescriptors();
  // A stop is never lost, also for a job a script started in the background (its shell ignores
  // SIGINT there). Outside StopSignals they keep their default action: no output is open then.
  for (const int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    if (::sigaction(signal_number, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) {
      ::signal(signal_number, SIG_DFL);
    }
  }
  for (const int signal_number : kEndingSignals) handleIfDefault(signal_number);
  for (int signal_number = SIGRTMIN; signal_number <= SIGRTMAX; ++signal_number) {
    handleIfDefault(signal_number);
  }
  if (!kLeaksCheckedAtExit) {
    for (const int signal_number : kCrashSignals) handleIfDefault(signal_number);
  }
}

void StopSignals::leaveToHost() {
  g_left_to_host.store(true);
}

StopSignals::StopSignals(unsigned grace_seconds) {
  if (g_left_to_host.load()) return;
  if (g_depth++ > 0) return;
  core::clearStopRequest();
  g_grace_seconds = static_cast<sig_atomic_t>(grace_seconds);
  for (std::size_t k = 0; k < sizeof kStopSignals / sizeof kStopSignals[0]; ++k) {
    const int signal_number = kStopSignals[k];
    g_installed[k] = false;
    if (::sigaction(signal_number, nullptr, &g_previous[k]) != 0) continue;
    // nohup's SIGHUP stays ignored: the user asked for the run to outlive the terminal.
    if (signal_number == SIGHUP && g_previous[k].sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = signal_number == SIGALRM ? onWatchdog : onStopSignal;
    sigemptyset(&action.sa_mask);
    for (const int blocked : kStopSignals) sigaddset(&action.sa_mask, blocked);
    // SA_RESTART: file writes interrupted by the signal resume instead of failing with EINTR;
    // one that cannot resume is the watchdog's.
    action.sa_flags = SA_RESTART;
    g_installed[k] = ::sigaction(signal_number, &action, nullptr) == 0;
  }
}

StopSignals::~StopSignals() {
  if (g_left_to_host.load()) return;
  if (--g_depth > 0) return;
  ::alarm(0);
  for (std::size_t k = 0; k < sizeof kStopSignals / sizeof kStopSignals[0]; ++k) {
    if (g_installed[k]) ::sigaction(kStopSignals[k], &g_previous[k], nullptr);
  }
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

}  // namespace collide::output
