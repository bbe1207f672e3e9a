// SPDX-License-Identifier: MIT
#pragma once
// The engine's long work called from Python: on a thread of its own while the caller waits with
// the GIL released (other Python threads run, and render at the same time), Ctrl-C or a
// notebook's interrupt passed on as a stop request, and one language of words at a time.
#include <functional>
#include <memory>

#include "text/language.hpp"

namespace collide::python {

// Runs `work` on a worker thread and waits for it with the GIL released. On the interpreter's main
// thread the caller checks the interpreter's signals every few hundredths of a second; a
// KeyboardInterrupt becomes a stop request (core::requestStop), which ends the work at its next
// check point (between frames, between collisions), every temporary file removed, and is then
// raised. An exception `work` threw is rethrown here, with the GIL held. Call with the GIL held.
// `poll`, if given, is called with the GIL held at each check and once when the work has ended
// (a progress bar's update).
void runReleased(const std::function<void()>& work, const std::function<void()>& poll = {});

// Keeps `language` the active one (text::setActiveLanguage, which is process-wide) while it lives:
// waits while work in another language holds it, so that two threads drawing in one language run
// at once and two in different languages take turns.
class LanguageHold {
 public:
  explicit LanguageHold(const text::Language& language);
  ~LanguageHold();
  LanguageHold(const LanguageHold&) = delete;
  LanguageHold& operator=(const LanguageHold&) = delete;
};

}  // namespace collide::python
