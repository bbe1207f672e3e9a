// SPDX-License-Identifier: MIT
#include "host_work.hpp"

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <exception>
#include <future>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include "core/stop_request.hpp"

namespace py = pybind11;

namespace collide::python {
namespace {

// How often the waiting main thread looks for a KeyboardInterrupt: soon enough to feel at once.
constexpr auto kSignalPoll = std::chrono::milliseconds(30);

// Work in flight. A stop request is forgotten when the first starts and when the last ends, so
// that a Ctrl-C stops every run going at the time and no later one.
std::mutex g_work_mutex;
int g_work_running = 0;

void startWork() {
  const std::lock_guard<std::mutex> lock(g_work_mutex);
  if (g_work_running++ == 0) core::clearStopRequest();
}

void endWork() {
  const std::lock_guard<std::mutex> lock(g_work_mutex);
  if (--g_work_running == 0) core::clearStopRequest();
}

// The active language and how many holds share it.
std::mutex g_language_mutex;
std::condition_variable g_language_free;
const text::Language* g_held_language = nullptr;
int g_language_holds = 0;

// Waits for `done` without the GIL. A pending KeyboardInterrupt (or any exception a Python signal
// handler raised; the interpreter runs them on its main thread only, elsewhere the check finds
// none) is taken, turned into a stop request and returned once the work has ended.
std::optional<py::error_already_set> waitForWork(std::future<void>& done,
                                                 const std::function<void()>& poll) {
  std::optional<py::error_already_set> interrupt;
  for (;;) {
    {
      const py::gil_scoped_release released;
      if (interrupt) {
        done.wait();
        return interrupt;
      }
      if (done.wait_for(kSignalPoll) == std::future_status::ready) return interrupt;
    }
    if (poll) poll();
    if (PyErr_CheckSignals() != 0) {
      interrupt.emplace();  // takes the pending exception
      core::requestStop(SIGINT);
    }
  }
}

}  // namespace

void runReleased(const std::function<void()>& work, const std::function<void()>& poll) {
  std::packaged_task<void()> task([&work] {
    startWork();
    try {
      work();
    } catch (...) {
      endWork();
      throw;
    }
    endWork();
  });
  std::future<void> done = task.get_future();
  std::thread worker(std::move(task));
  std::optional<py::error_already_set> interrupt;
  try {
    interrupt = waitForWork(done, poll);
  } catch (...) {
    const py::gil_scoped_release released;
    worker.join();
    throw;
  }
  {
    const py::gil_scoped_release released;
    worker.join();
  }
  if (interrupt) throw *interrupt;
  done.get();  // rethrows what the work threw
  if (poll) poll();
}

LanguageHold::LanguageHold(const text::Language& language) {
  std::unique_lock<std::mutex> lock(g_language_mutex);
  g_language_free.wait(lock, [&] { return g_language_holds == 0 || g_held_language == &language; });
  if (g_language_holds++ == 0) {
    g_held_language = &language;
    text::setActiveLanguage(language);
  }
}

LanguageHold::~LanguageHold() {
  {
    const std::lock_guard<std::mutex> lock(g_language_mutex);
    --g_language_holds;
  }
  g_language_free.notify_all();
}

}  // namespace collide::python
