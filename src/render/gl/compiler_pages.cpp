#include "render/gl/compiler_pages.hpp"

#include <link.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

namespace collide::render {
namespace {

// A compile touches several MiB of LLVM; x264 and the frame buffers grow anonymous memory only.
constexpr long kFileGrowthBytes = 4L << 20;

// libLLVM's read-only segments (an object found by dl_iterate_phdr).
struct Segments {
  std::vector<std::pair<std::uintptr_t, std::uintptr_t>> ranges;  // [start, end), page-aligned
};

// Whether the object asks the loader to write into its code (text relocations): its read-only
// pages would then hold copied ones.
bool writesItsText(const dl_phdr_info& info) {
  for (int i = 0; i < info.dlpi_phnum; ++i) {
    const ElfW(Phdr)& header = info.dlpi_phdr[i];
    if (header.p_type != PT_DYNAMIC) continue;
    const auto* entry = reinterpret_cast<const ElfW(Dyn)*>(info.dlpi_addr + header.p_vaddr);
    for (; entry->d_tag != DT_NULL; ++entry) {
      if (entry->d_tag == DT_TEXTREL) return true;
      if (entry->d_tag == DT_FLAGS && (entry->d_un.d_val & DF_TEXTREL) != 0) return true;
    }
  }
  return false;
}

int findCompiler(dl_phdr_info* info, std::size_t, void* data) {
  if (info->dlpi_name == nullptr || std::strstr(info->dlpi_name, "/libLLVM") == nullptr) return 0;
  if (writesItsText(*info)) return 0;
  auto& segments = *static_cast<Segments*>(data);
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& header = info->dlpi_phdr[i];
    // Writable segments hold relocated data, also the part made read-only after relocating
    // (PT_GNU_RELRO lies inside the writable one): copied pages, never given back.
    if (header.p_type != PT_LOAD || (header.p_flags & PF_W) != 0) continue;
    // Whole pages inside the segment only: a page it shares with another is left alone.
    const std::uintptr_t start = info->dlpi_addr + header.p_vaddr;
    const std::uintptr_t first = (start + page - 1) & ~(page - 1);
    const std::uintptr_t end = (start + header.p_memsz) & ~(page - 1);
    if (first < end) segments.ranges.emplace_back(first, end);
  }
  return 0;
}

// Resident file-backed (plus shared memory) pages of this process: /proc/self/statm's third field.
long residentFilePages() {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  if (statm == nullptr) return -1;
  long size = 0, resident = 0, shared = -1;
  if (std::fscanf(statm, "%ld %ld %ld", &size, &resident, &shared) != 3) shared = -1;
  std::fclose(statm);
  return shared;
}

}  // namespace

std::size_t releaseCompilerPages() {
  // The segments from the loader's own list, not from /proc/self/smaps: reading that walks every
  // page table of the process (about 1 % of a batch's CPU, once per video).
  Segments segments;
  dl_iterate_phdr(findCompiler, &segments);
  std::size_t released = 0;
  for (const auto& [start, end] : segments.ranges) {
    if (madvise(reinterpret_cast<void*>(start), end - start, MADV_DONTNEED) == 0) {
      released += end - start;
    }
  }
  return released;
}

void CompilerPageKeeper::afterFrame() {
  ++frames_;
  const long file_pages = residentFilePages();
  if (file_pages < 0) return;
  if (frames_ == 1) {
    // The first frame compiled every shader it drew; a still ends here, so wait for a second.
    file_pages_at_release_ = 0;
    return;
  }
  const long page_bytes = sysconf(_SC_PAGESIZE);
  if ((file_pages - file_pages_at_release_) * page_bytes < kFileGrowthBytes) return;
  releaseCompilerPages();
  file_pages_at_release_ = residentFilePages();
}

}  // namespace collide::render
