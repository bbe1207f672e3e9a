#include "render/compiler_pages.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace collide::render {
namespace {

// A compile touches several MiB of LLVM; x264 and the frame buffers grow anonymous memory only.
constexpr long kFileGrowthBytes = 4L << 20;

struct Mapping {
  std::uintptr_t start = 0, end = 0;
  bool candidate = false;  // libLLVM, not writable
  long anonymous_kib = -1;
  long resident_kib = 0;
};

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
  std::ifstream smaps("/proc/self/smaps");
  if (!smaps) return 0;
  std::vector<Mapping> mappings;
  for (std::string line; std::getline(smaps, line);) {
    const std::size_t dash = line.find('-');
    const std::size_t space = line.find(' ');
    if (dash != std::string::npos && space != std::string::npos && dash < space &&
        line.find(':') > space) {
      // A mapping's header: "start-end perms offset dev inode [path]".
      std::istringstream header(line);
      std::string range, perms, offset, device, inode, path;
      header >> range >> perms >> offset >> device >> inode >> path;
      Mapping mapping;
      mapping.start = std::stoull(range.substr(0, dash), nullptr, 16);
      mapping.end = std::stoull(range.substr(dash + 1), nullptr, 16);
      mapping.candidate =
          perms.size() >= 2 && perms[1] != 'w' && path.find("/libLLVM") != std::string::npos;
      mappings.push_back(mapping);
    } else if (!mappings.empty() && line.starts_with("Rss:")) {
      mappings.back().resident_kib = std::stol(line.substr(4));
    } else if (!mappings.empty() && line.starts_with("Anonymous:")) {
      mappings.back().anonymous_kib = std::stol(line.substr(10));
    }
  }
  std::size_t released = 0;
  for (const Mapping& m : mappings) {
    // A private page (a relocation written into read-only-after-relocation data) would be lost:
    // such a mapping is left alone.
    if (!m.candidate || m.anonymous_kib != 0 || m.resident_kib == 0) continue;
    if (madvise(reinterpret_cast<void*>(m.start), m.end - m.start, MADV_DONTNEED) == 0) {
      released += static_cast<std::size_t>(m.resident_kib) * 1024;
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
