#include "output/process_end.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <utility>

#include "output/temp_file.hpp"

namespace collide::output {
namespace {

std::atomic<bool> program_process{false};
std::atomic<bool> one_picture{false};
// Never destroyed: the process ends with it alive (std::_Exit below).
std::atomic<std::shared_ptr<void>*> kept{nullptr};

}  // namespace

void declareProgramProcess() {
  program_process = true;
}

void declareOnePictureProcess() {
  one_picture = true;
}

bool drawsOnePicture() {
  return one_picture;
}

bool keepsForProcessEnd() {
  // A leak checker must see the teardown: what it checks is then what the program frees.
  return !kLeaksCheckedAtExit && program_process && one_picture;
}

void keepForProcessEnd(std::shared_ptr<void> drawer) {
  if (!keepsForProcessEnd() || kept.load() != nullptr) return;  // `drawer` goes now
  kept = new std::shared_ptr<void>(std::move(drawer));
}

int finishStandardOutput(int exit_code, std::ostream& err) {
  errno = 0;
  std::cout.flush();  // through stdio: a failure here sets errno and stdout's error flag
  int error_number = errno;
  if (std::fflush(stdout) != 0 && error_number == 0) error_number = errno;
  if (std::ferror(stdout) == 0 && !std::cout.bad()) return exit_code;
  if (exit_code != 0) return exit_code;  // the failure that ended the run was reported
  // A write that failed earlier left no errno behind: a closed descriptor still says so.
  if (error_number == 0 && ::write(STDOUT_FILENO, "", 0) < 0) error_number = errno;
  err << "collide: cannot write to stdout: "
      << std::strerror(error_number != 0 ? error_number : EIO) << output::ioAdvice(error_number)
      << "\n";
  return 1;
}

void endIfKept(int exit_code) {
  if (kept.load() == nullptr) return;
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  std::_Exit(exit_code);
}

}  // namespace collide::output
