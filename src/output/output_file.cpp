#include "output/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"
#include "output/frame_sink.hpp"
#include "output/temp_file.hpp"

namespace collide::output {
namespace fs = std::filesystem;
namespace {

// The kernel's own limit on links followed in one lookup (MAXSYMLINKS).
constexpr int kMaxLinkHops = 40;

OutputPlace refused(const fs::path& path, const char* what) {
  return {OutputRoute::kRefused, path, what};
}

// A link whose chain ends at a name with nothing there: that name, where the new file goes.
OutputPlace placeThroughDanglingLink(const fs::path& link) {
  fs::path at = link;
  for (int hop = 0; hop < kMaxLinkHops; ++hop) {
    std::error_code error;
    const fs::path next = fs::read_symlink(at, error);
    if (error) return refused(link, "a link that cannot be read");
    at = next.is_absolute() ? next : at.parent_path() / next;
    struct stat info {};
    if (::lstat(at.c_str(), &info) != 0) {
      const fs::path parent = at.parent_path().empty() ? fs::path(".") : at.parent_path();
      if (!fs::is_directory(parent, error)) return refused(link, "a link into a missing directory");
      return {OutputRoute::kReplace, at.lexically_normal(), ""};
    }
    if (!S_ISLNK(info.st_mode)) break;  // appeared meanwhile: let the caller look again
  }
  return refused(link, "a link loop");
}

OutputPlace placeByType(const fs::path& path, mode_t mode, bool through_link) {
  if (S_ISREG(mode)) {
    if (!through_link) return {OutputRoute::kReplace, path, ""};
    // Replace the file the link points to, in its own directory, so the link stays a link.
    std::error_code error;
    const fs::path resolved = fs::canonical(path, error);
    if (error) return refused(path, "a link that cannot be followed");
    return {OutputRoute::kReplace, resolved, ""};
  }
  if (S_ISCHR(mode)) return {OutputRoute::kInPlace, path, "a character device"};
  if (S_ISFIFO(mode)) return {OutputRoute::kInPlace, path, "a FIFO"};
  if (S_ISSOCK(mode)) return {OutputRoute::kInPlace, path, "a socket"};
  if (S_ISDIR(mode)) return refused(path, "a directory");
  if (S_ISBLK(mode)) return refused(path, "a block device");
  return refused(path, "not a file");
}

// `name` in the directory open at `fd`, as a path that reaches it through the descriptor (Linux's
// /proc/self/fd), so every writer (stdio, libav, libpng) follows the directory if it is moved;
// `fallback` where /proc is not mounted or the directory could not be opened.
fs::path throughDirectory(int fd, const std::string& name, const fs::path& fallback) {
  if (fd < 0) return fallback;
  const fs::path directory = "/proc/self/fd/" + std::to_string(fd);
  struct stat info {};
  if (::stat(directory.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) return fallback;
  return directory / name;
}

// Gives the new file at `temporary` the permissions of the file `replaced` it is about to replace
// (and its owner, where allowed: root may give any, a user only a group of theirs). Best effort:
// a file system without owners or modes keeps what it gives.
void keepModeAndOwner(int fd, const std::string& temporary, const std::string& replaced) {
  struct stat old {};
  if (::fstatat(fd, replaced.c_str(), &old, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(old.st_mode)) {
    return;
  }
  const uid_t owner = ::geteuid() == 0 ? old.st_uid : static_cast<uid_t>(-1);
  if (owner != static_cast<uid_t>(-1) || old.st_gid != ::getegid()) {
    // Done before the mode: changing the owner clears the set-user-ID and set-group-ID bits.
    (void)::fchownat(fd, temporary.c_str(), owner, old.st_gid, AT_SYMLINK_NOFOLLOW);
  }
  (void)::fchmodat(fd, temporary.c_str(), old.st_mode & 07777, 0);
}

}  // namespace

OutputPlace placeOutput(const fs::path& path) {
  if (path == kStdoutName) return {OutputRoute::kStdout, path, "standard output"};
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0) {
    // Nothing there (or a parent that cannot be searched, which opening the file will report).
    return {OutputRoute::kReplace, path, ""};
  }
  if (!S_ISLNK(info.st_mode)) return placeByType(path, info.st_mode, false);
  if (::stat(path.c_str(), &info) != 0) {
    if (errno == ENOENT) return placeThroughDanglingLink(path);
    if (errno == ELOOP) return refused(path, "a link loop");
    return refused(path, "a link that cannot be followed");
  }
  return placeByType(path, info.st_mode, true);
}

OutputFile::OutputFile(fs::path target) : target_(std::move(target)) {
  OutputPlace place = placeOutput(target_);
  route_ = place.route;
  switch (route_) {
    case OutputRoute::kRefused:
      throw core::InputError("'" + target_.string() + "': is " + place.what +
                             "; allowed: a file, a link to one, a character device, a FIFO or "
                             "- for stdout");
    case OutputRoute::kReplace: {
      replaced_ = std::move(place.path);
      const fs::path temporary = temporaryPathFor(replaced_);
      temporary_name_ = temporary.filename().string();
      directory_ = WatchedDirectory(replaced_.parent_path());
      write_path_ = throughDirectory(directory_.fd(), temporary_name_, temporary);
      break;
    }
    case OutputRoute::kInPlace:
    case OutputRoute::kStdout:
      write_path_ = target_;
      break;
  }
}

OutputFile::~OutputFile() {
  if (route_ != OutputRoute::kReplace || committed_) return;
  if (directory_.fd() >= 0) {
    ::unlinkat(directory_.fd(), temporary_name_.c_str(), 0);
  } else {
    removeQuietly(write_path_);
  }
}

void OutputFile::commit() {
  if (route_ == OutputRoute::kReplace && !committed_) {
    const int fd = directory_.fd();
    if (fd < 0) {
      renameOrThrow(write_path_, replaced_);
    } else {
      const std::string name = replaced_.filename().string();
      keepModeAndOwner(fd, temporary_name_, name);
      if (::renameat(fd, temporary_name_.c_str(), fd, name.c_str()) != 0) {
        const int error_number = errno;
        // Names the target only: the temporary name means nothing to the user.
        throw OutputError("cannot put '" + replaced_.string() +
                          "' in place: " + std::strerror(error_number) + ioAdvice(error_number));
      }
    }
  }
  committed_ = true;
}

}  // namespace collide::output
