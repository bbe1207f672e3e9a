#pragma once
// Tier-3 errors (docs/architecture.md, "Errors, in three tiers"): input and I/O failures.
// Modules throw subclasses; only `main` catches them and turns them into an exit code.
#include <stdexcept>
#include <string>

namespace collide::core {

// Process exit codes, shared by every command.
enum class ExitCode : int { kSuccess = 0, kRuntimeFailure = 1, kBadInput = 2 };

// Base of every error the tool reports to the user. The message is one line, complete on its own.
class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

// Bad usage or bad input: the user can fix it by changing what they typed. Exit 2.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(ExitCode::kBadInput, message) {}
};

// The input was fine but something failed at run time (GL context, codec, disk). Exit 1.
class RuntimeError : public Error {
 public:
  explicit RuntimeError(const std::string& message) : Error(ExitCode::kRuntimeFailure, message) {}
};

// Aborts with "function: message" for programmer mistakes (tier 1); never for user input.
[[noreturn]] void assertionFailed(const char* function, const std::string& message);

}  // namespace collide::core

#define COLLIDE_ASSERT(condition, message)                                 \
  do {                                                                     \
    if (!(condition)) ::collide::core::assertionFailed(__func__, message); \
  } while (false)
