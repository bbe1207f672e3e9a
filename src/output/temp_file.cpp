#include "output/temp_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <vector>

#include "output/frame_sink.hpp"

namespace collide::output {
namespace {

// Directories watched at once. An output and its side files share one; a batch worker writes into
// one folder. A directory beyond the list is still used, only not swept by a signal's handler.
constexpr int kWatchSlots = 64;

struct WatchSlot {
  std::atomic<int> fd{-1};  // read by signal handlers: set only once the slot is complete
  dev_t device = 0;
  ino_t inode = 0;
  int handles = 0;
};

WatchSlot g_watched[kWatchSlots];
std::mutex g_watched_mutex;  // guards every field but the handlers' reads of fd

// ".tmp-<pid>-" into `out` (at least 32 bytes), without allocating; returns its length.
std::size_t pidMarker(pid_t pid, char* out) {
  char digits[24];
  std::size_t count = 0;
  auto value = static_cast<unsigned long>(pid);
  do {
    digits[count++] = static_cast<char>('0' + value % 10);
    value /= 10;
  } while (value != 0 && count < sizeof digits);
  std::size_t length = 0;
  for (const char c : {'.', 't', 'm', 'p', '-'}) out[length++] = c;
  while (count > 0) out[length++] = digits[--count];
  out[length++] = '-';
  out[length] = '\0';
  return length;
}

// Whether `name` starts with '.' and holds `marker` (plain loops: called from signal handlers).
bool hasMarker(const char* name, const char* marker, std::size_t marker_length) {
  if (name[0] != '.') return false;
  for (const char* at = name + 1; *at != '\0'; ++at) {
    std::size_t k = 0;
    while (k < marker_length && at[k] == marker[k]) ++k;
    if (k == marker_length) return true;
  }
  return false;
}

// One sweep of the directory open at `fd` with getdents64 (no allocation, async-signal-safe);
// returns how many files it removed.
int removeMarkedOnce(int fd, const char* marker, std::size_t marker_length) noexcept {
  if (::lseek(fd, 0, SEEK_SET) < 0) return 0;
  alignas(8) char buffer[4096];
  int removed = 0;
  for (;;) {
    const long got = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
    if (got <= 0) return removed;
    for (long at = 0; at < got;) {
      // struct linux_dirent64: u64 inode, s64 offset, u16 record length, u8 type, name.
      unsigned short record_length = 0;
      std::memcpy(&record_length, buffer + at + 16, sizeof record_length);
      const char* name = buffer + at + 19;
      if (hasMarker(name, marker, marker_length) && ::unlinkat(fd, name, 0) == 0) ++removed;
      if (record_length == 0) return removed;
      at += record_length;
    }
  }
}

void removeMarked(int fd, pid_t pid) noexcept {
  char marker[32];
  const std::size_t length = pidMarker(pid, marker);
  // Removing entries while listing may make the listing skip some: sweep until none is left.
  for (int sweep = 0; sweep < 8 && removeMarkedOnce(fd, marker, length) > 0; ++sweep) {
  }
}

}  // namespace

std::filesystem::path temporaryPathFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  const unsigned n = counter.fetch_add(1);
  // Built with append, not operator+ chains: GCC 12 warns falsely (-Wrestrict) on "." + string.
  std::string name = ".";
  name.append(target.stem().string());
  name.append(".tmp-");
  name.append(std::to_string(::getpid()));
  name.append("-");
  name.append(std::to_string(n));
  name.append(target.extension().string());
  return target.parent_path() / name;
}

bool isTemporaryNameOf(const std::string& name, pid_t pid) {
  char marker[32];
  const std::size_t length = pidMarker(pid, marker);
  return hasMarker(name.c_str(), marker, length);
}

WatchedDirectory::WatchedDirectory(const std::filesystem::path& directory) {
  const std::string where = directory.empty() ? "." : directory.string();
  // Read access lets a handler list it; without it the directory still serves renameat/unlinkat.
  int fd = ::open(where.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fd = ::open(where.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    ::close(fd);
    return;
  }
  const std::lock_guard<std::mutex> lock(g_watched_mutex);
  int free_slot = -1;
  for (int k = 0; k < kWatchSlots; ++k) {
    WatchSlot& slot = g_watched[k];
    if (slot.handles > 0 && slot.device == info.st_dev && slot.inode == info.st_ino) {
      ++slot.handles;
      ::close(fd);
      fd_ = slot.fd.load();
      slot_ = k;
      return;
    }
    if (slot.handles == 0 && free_slot < 0) free_slot = k;
  }
  fd_ = fd;
  if (free_slot < 0) return;  // not listed; this handle owns its descriptor
  WatchSlot& slot = g_watched[free_slot];
  slot.device = info.st_dev;
  slot.inode = info.st_ino;
  slot.handles = 1;
  slot.fd.store(fd);
  slot_ = free_slot;
}

WatchedDirectory::~WatchedDirectory() {
  release();
}

WatchedDirectory::WatchedDirectory(WatchedDirectory&& other) noexcept
    : fd_(other.fd_), slot_(other.slot_) {
  other.fd_ = -1;
  other.slot_ = -1;
}

WatchedDirectory& WatchedDirectory::operator=(WatchedDirectory&& other) noexcept {
  if (this != &other) {
    release();
    fd_ = other.fd_;
    slot_ = other.slot_;
    other.fd_ = -1;
    other.slot_ = -1;
  }
  return *this;
}

void WatchedDirectory::release() noexcept {
  if (fd_ < 0) return;
  if (slot_ < 0) {
    ::close(fd_);
  } else {
    const std::lock_guard<std::mutex> lock(g_watched_mutex);
    WatchSlot& slot = g_watched[slot_];
    if (--slot.handles == 0) {
      slot.fd.store(-1);
      ::close(fd_);
    }
  }
  fd_ = -1;
  slot_ = -1;
}

void removeOwnTemporaryFiles() noexcept {
  const pid_t pid = ::getpid();
  for (WatchSlot& slot : g_watched) {
    const int fd = slot.fd.load();
    if (fd >= 0) removeMarked(fd, pid);
  }
}

int removeTemporaryFilesOf(const std::filesystem::path& directory, pid_t pid) noexcept {
  int removed = 0;
  try {
    std::vector<std::filesystem::path> found;
    std::error_code error;
    for (std::filesystem::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
      if (isTemporaryNameOf(it->path().filename().string(), pid)) found.push_back(it->path());
    }
    for (const std::filesystem::path& path : found) {
      if (std::filesystem::remove(path, error)) ++removed;
    }
  } catch (const std::exception&) {
    // Out of memory listing a directory: what is left stays.
  }
  return removed;
}

void renameOrThrow(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) {
    const int error_number = errno;
    // Names the target only: the temporary name means nothing to the user.
    throw OutputError("cannot put '" + to.string() + "' in place: " + std::strerror(error_number) +
                      ioAdvice(error_number));
  }
}

void removeQuietly(const std::filesystem::path& path) noexcept {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

std::string ioErrorMessage(const std::string& what, const std::filesystem::path& path,
                           int error_number) {
  return what + " '" + path.string() + "': " + std::strerror(error_number) + ioAdvice(error_number);
}

std::string ioAdvice(int error_number) {
  switch (error_number) {
    case ENOSPC:
    case EDQUOT:
      return "; free space on that disk (or raise the quota) or write to another directory";
    case EFBIG:
      return "; the file outgrew the file-size limit (ulimit -f): raise the limit or write a "
             "smaller output";
    case EACCES:
    case EPERM:
      return "; choose a directory you may write to";
    case EROFS:
      return "; that file system is read-only: write to another directory";
    case EIO:
      return "; the disk reported an I/O error: check it or write to another directory";
    case EPIPE:
      return "; the program reading the output ended before it was complete";
    case EBADF:
      return "; the output was closed or not open for writing";
    default:
      return "";
  }
}

}  // namespace collide::output
