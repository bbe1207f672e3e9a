#include "core/bounded_read.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>

namespace collide::core {
namespace {

// Refuses what is no file of text or data to read: judged before opening (opening some devices
// does something: a tape rewinds, a terminal becomes controlling) and again on the opened file.
ReadOutcome refusalFor(mode_t mode) {
  if (S_ISDIR(mode)) return ReadOutcome::kDirectory;
  if (S_ISCHR(mode)) return ReadOutcome::kCharacterDevice;
  if (S_ISBLK(mode)) return ReadOutcome::kBlockDevice;
  return ReadOutcome::kRead;
}

// Closes the descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::mutex g_inputs_mutex;
std::vector<InputFile> g_inputs;

void noteInput(const std::string& path, const struct stat& info) {
  if (!S_ISREG(info.st_mode)) return;
  const std::lock_guard<std::mutex> lock(g_inputs_mutex);
  for (const InputFile& input : g_inputs) {
    if (input.device == info.st_dev && input.inode == info.st_ino) return;
  }
  g_inputs.push_back({path, info.st_dev, info.st_ino});
}

}  // namespace

void noteInputFile(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) noteInput(path, info);
}

std::vector<InputFile> inputFiles() {
  const std::lock_guard<std::mutex> lock(g_inputs_mutex);
  return g_inputs;
}

void forgetInputFiles() {
  const std::lock_guard<std::mutex> lock(g_inputs_mutex);
  g_inputs.clear();
}

BoundedRead readBounded(const std::string& path, std::size_t limit_bytes) {
  BoundedRead result;
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) {
    result.outcome = refusalFor(info.st_mode);
    if (result.outcome != ReadOutcome::kRead) return result;
  }
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY)};
  if (file.fd < 0) {
    result.outcome = ReadOutcome::kCannotOpen;
    result.error_number = errno;
    return result;
  }
  if (::fstat(file.fd, &info) == 0) {
    result.outcome = refusalFor(info.st_mode);
    if (result.outcome != ReadOutcome::kRead) return result;
    noteInput(path, info);
  }
  char chunk[65536];
  for (;;) {
    const ssize_t got = ::read(file.fd, chunk, sizeof chunk);
    if (got == 0) return result;
    if (got < 0) {
      if (errno == EINTR) continue;
      result.outcome = ReadOutcome::kReadFailed;
      result.error_number = errno;
      result.bytes.clear();
      return result;
    }
    if (result.bytes.size() + static_cast<std::size_t>(got) > limit_bytes) {
      result.outcome = ReadOutcome::kTooLarge;
      result.bytes.clear();
      result.bytes.shrink_to_fit();
      return result;
    }
    result.bytes.append(chunk, static_cast<std::size_t>(got));
  }
}

std::string describeRefusal(const BoundedRead& read, std::size_t limit_bytes) {
  switch (read.outcome) {
    case ReadOutcome::kRead:
      return "";
    case ReadOutcome::kTooLarge:
      return "more than " + std::to_string(limit_bytes) + " bytes";
    case ReadOutcome::kCannotOpen:
      return std::string("cannot read: ") + std::strerror(read.error_number);
    case ReadOutcome::kReadFailed:
      return std::string("cannot read: ") + std::strerror(read.error_number);
    case ReadOutcome::kDirectory:
      return "is a directory";
    case ReadOutcome::kCharacterDevice:
      return "is a character device, not a file";
    case ReadOutcome::kBlockDevice:
      return "is a block device, not a file";
  }
  return "cannot be read";
}

}  // namespace collide::core
