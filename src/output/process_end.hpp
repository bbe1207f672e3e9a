#pragma once
// How the program ends after a one-picture command (still, strobe, chart). Tearing down the GL
// renderer (the OSMesa context, llvmpipe's compiled shaders, LLVM's modules and execution
// engines) and then running every library's exit handlers cost a 720p still about a tenth of
// its CPU, for memory the kernel takes back at once when the process ends anyway. So, where the
// process is the program and its one picture is written, the renderer is kept and the process
// ends without destructors or exit handlers (compilers skip freeing at exit for the same reason).
// A test calling runCli() in its own long-lived process, and batch, which draws many pictures in
// one process, never declare either and tear everything down as before.
#include <memory>
#include <ostream>

namespace collide::output {

// Whether a leak checker watches this build's exit: AddressSanitizer (g++ says so with
// __SANITIZE_ADDRESS__, clang with __has_feature) or LeakSanitizer alone.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kLeaksCheckedAtExit = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
inline constexpr bool kLeaksCheckedAtExit = true;
#else
inline constexpr bool kLeaksCheckedAtExit = false;
#endif
#else
inline constexpr bool kLeaksCheckedAtExit = false;
#endif

// main() alone, before runCli(): this process is the program and ends when runCli() returns.
void declareProgramProcess();

// The still, strobe and chart commands: the picture drawn next is the process's only one.
void declareOnePictureProcess();

// Whether declareOnePictureProcess() was called: the process draws one picture, and its PNG may be
// compressed on every core (batch keeps to its core budget and never declares it).
bool drawsOnePicture();

// Whether keepForProcessEnd() keeps: both declarations made, and no leak checker (the sanitizer
// build's LeakSanitizer) watching the exit, which must see the teardown.
bool keepsForProcessEnd();

// Called once the picture is written, with what drew it (the Renderer). Keeps `drawer` alive to
// the end of the process where keepsForProcessEnd(); destroys it here otherwise.
void keepForProcessEnd(std::shared_ptr<void> drawer);

// main(), with runCli()'s exit code: flushes standard output and returns 1 after one line on
// `err` when anything written there was lost (a full disk or device, a closed stdout, a reader
// gone while SIGPIPE is ignored) and the run would otherwise have succeeded; else `exit_code`.
int finishStandardOutput(int exit_code, std::ostream& err);

// main(), with runCli()'s exit code: where something was kept, flushes the standard streams and
// ends the process at once (std::_Exit: no destructors, no exit handlers); returns otherwise.
// Every output file is complete and renamed into place before runCli() returns.
void endIfKept(int exit_code);

}  // namespace collide::output
