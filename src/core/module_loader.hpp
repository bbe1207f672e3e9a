#pragma once
// Opening one of the program's own modules (collide-video.so, collide-gl.so, collide-vector.so) on
// demand: the heavy libraries they link (libav*, libOSMesa with LLVM, Cairo) are mapped only by the
// commands that use them.
#include <string>
#include <vector>

namespace collide::core {

// Looks for `module_file` beside the shared object holding this code when that is not the program
// (the Python extension), beside the program, in ../lib/collide (an install prefix), then at
// `built_in_paths` (the install directory and the build tree, compiled in), opens the first found
// with RTLD_NOW | RTLD_GLOBAL (global, so that an LD_PRELOAD wrapper's RTLD_NEXT sees the
// libraries it links, as for a linked library) and returns the address of `symbol`. The module
// is never closed: objects it made may live until the process ends. On failure returns nullptr
// and sets `error` to one sentence naming the module and where it looked or why it failed.
void* loadModuleSymbol(const std::string& module_file, const char* symbol,
                       const std::vector<std::string>& built_in_paths, std::string& error);

}  // namespace collide::core
