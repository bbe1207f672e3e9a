#include <csignal>
#include <exception>
#include <iostream>

#include "app/cli.hpp"

int main(int argc, char** argv) {
  // A file that outgrows the file-size limit (ulimit -f, RLIMIT_FSIZE) raises SIGXFSZ, whose
  // default action kills the process mid-write and leaves the temporary file behind. Ignored, the
  // write fails with EFBIG instead, which every writer reports and cleans up like a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    return collide::app::runCli(argc, argv, std::cout, std::cerr);
  } catch (const std::exception& e) {
    // Anything not mapped to a typed error is still a runtime failure with a message, never a
    // crash.
    std::cerr << "collide: internal error: " << e.what() << "\n";
    return 1;
  }
}
