#pragma once
// Private: gives back LLVM's pages once llvmpipe has compiled what a video needs. llvmpipe
// compiles each shader variant with LLVM on first use, in the first frame or two; after that a
// frame runs only the compiled code. A fifth or so of a 1080p60 render's peak resident memory
// was libLLVM's code and read-only data, touched while compiling and left mapped
// (bench/results.md).
// They are clean file pages: dropping them from this process (MADV_DONTNEED) loses nothing, the
// page cache keeps the file, and a later compile faults back in only what it runs.
#include <cstddef>

namespace collide::render {

// Drops this process's resident pages of libLLVM's read-only segments (not its relocated data,
// and nothing where the loader wrote into its code), so nothing but clean file contents is
// dropped. Returns the bytes of the ranges given back, resident or not (0 without libLLVM).
std::size_t releaseCompilerPages();

// Decides when: called after every frame, it releases once the file-backed resident memory has
// grown by a compile's worth since the last release (the first frame compiles every shader; a
// later one, a variant seen for the first time). The first frame itself never pays for it, so a
// still costs nothing more.
class CompilerPageKeeper {
 public:
  void afterFrame();

 private:
  long frames_ = 0;
  long file_pages_at_release_ = -1;  // resident file-backed pages after the last release
};

}  // namespace collide::render
