#include <malloc.h>

#include <csignal>
#include <exception>
#include <iostream>

#include "app/cli.hpp"
#include "core/typed_text.hpp"
#include "output/process_end.hpp"
#include "output/stop_signals.hpp"

int main(int argc, char** argv) {
  // A file that outgrows the file-size limit (ulimit -f, RLIMIT_FSIZE) raises SIGXFSZ, whose
  // default action kills the process mid-write and leaves the temporary file behind. Ignored, the
  // write fails with EFBIG instead, which every writer reports and cleans up like a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  // Closed standard descriptors held; any signal that ends the process removes its temporary
  // files first (output/stop_signals.hpp).
  collide::output::prepareProcess();
  // llvmpipe allocates its vertex buffers (over 1 MiB) for each draw and frees them after; at the
  // top of the heap glibc hands such a block back to the kernel at once (trim threshold 128 KiB),
  // and the next draw faults it in again, zero-filled. A 720p60 video drawn in clipped passes
  // (render/draw/repaint_regions.hpp) faulted several times as many pages without it; keeping up
  // to 4 MiB of free heap top stops that at a negligible cost in peak memory (the figures are in
  // bench/results.md).
  mallopt(M_TRIM_THRESHOLD, 4 << 20);
  collide::output::declareProgramProcess();  // not a test calling runCli (output/process_end.hpp)
  try {
    const int exit_code = collide::output::finishStandardOutput(
        collide::app::runCli(argc, argv, std::cout, std::cerr), std::cerr);
    collide::output::endIfKept(exit_code);  // a one-picture command ends here
    return exit_code;
  } catch (const std::exception& e) {
    // Anything not mapped to a typed error is still a runtime failure with a message, never a
    // crash.
    std::cerr << "collide: internal error: " << collide::core::echoTyped(e.what(), 1000) << "\n";
    return 1;
  }
}
