#pragma once
// A one-picture process (a still, a strobe, a chart) spends most of its kernel time on page
// faults: llvmpipe's framebuffer and texture storage, LLVM's compile of the shaders and the
// readback each take megabytes of fresh memory, which the kernel hands out one 4 KiB page, one
// fault at a time (thousands of faults for a 720p still). Backing the heap with transparent huge
// pages serves the same memory in 2 MiB pieces: far fewer faults and less CPU for a still
// (bench/results.md has the figures). Not for videos: x264's frames in huge pages cost memory,
// and the video sink turns them off (output/encoded_video_sink.cpp).
#include <cstddef>

namespace collide::core {

// Makes the next `bytes` of the main heap eligible for transparent huge pages (madvise
// MADV_HUGEPAGE): allocations up to that size come from the heap rather than from mappings of
// their own (mallopt M_MMAP_THRESHOLD), the heap grows by `bytes` at once and is never trimmed
// below it. Only hints: where the kernel has huge pages off ("never") nothing changes but where
// large blocks come from. Idempotent in effect; call it once, before the big allocations.
void preferHugePagesForHeap(std::size_t bytes);

}  // namespace collide::core
