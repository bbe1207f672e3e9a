#pragma once
// Safe writing: a file is written under a hidden temporary name in the directory of its target and
// renamed over the target only once it is complete, so the target never holds a partial file.
// rename(2) within one directory (one file system) is atomic.
//
// Every temporary name carries the process id (".<stem>.tmp-<pid>-<n><ext>"), and the directories
// that hold them are kept open and listed here (WatchedDirectory), so a temporary file can be found
// and removed whatever ends the process: a signal's handler (removeOwnTemporaryFiles), or the
// batch parent when one of its workers was killed (removeTemporaryFilesOf). A directory kept open
// is followed when it is moved: the file is renamed into place, or removed, where it now is.
#include <sys/types.h>

#include <filesystem>
#include <string>

namespace collide::output {

// "<dir>/.<stem>.tmp-<pid>-<n><ext>" beside `target`. The extension is kept so tools that pick a
// format from the name still see it; <n> counts per process so two sinks never share a name.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Whether `name` (a file name, no directory) is a temporary name made by process `pid`.
bool isTemporaryNameOf(const std::string& name, pid_t pid);

// A directory held open (a descriptor shared by every handle on the same directory) and listed
// for removeOwnTemporaryFiles while any handle lives. fd() is -1 when it could not be opened.
class WatchedDirectory {
 public:
  WatchedDirectory() = default;
  explicit WatchedDirectory(const std::filesystem::path& directory);
  ~WatchedDirectory();
  WatchedDirectory(WatchedDirectory&& other) noexcept;
  WatchedDirectory& operator=(WatchedDirectory&& other) noexcept;
  WatchedDirectory(const WatchedDirectory&) = delete;
  WatchedDirectory& operator=(const WatchedDirectory&) = delete;

  int fd() const { return fd_; }

 private:
  void release() noexcept;
  int fd_ = -1;
  int slot_ = -1;  // its place in the list; -1: not listed (the list was full), fd_ is its own
};

// Removes this process's temporary files from every watched directory. Async-signal-safe (only
// system calls, no allocation): for the handlers of signals that end the process.
void removeOwnTemporaryFiles() noexcept;

// Removes the temporary files of process `pid` (a worker that was killed) from `directory`;
// returns how many. Never throws.
int removeTemporaryFilesOf(const std::filesystem::path& directory, pid_t pid) noexcept;

// Renames `from` to `to`, replacing `to`. Throws OutputError naming `to` and strerror(errno).
void renameOrThrow(const std::filesystem::path& from, const std::filesystem::path& to);

// Removes a file if it exists; never throws (used on error paths and in destructors).
void removeQuietly(const std::filesystem::path& path) noexcept;

// "<what> '<path>': <strerror(error_number)>[; <advice>]", the one-line form of every I/O error of
// this module.
std::string ioErrorMessage(const std::string& what, const std::filesystem::path& path,
                           int error_number);

// What the user can do about a failed write, for the errno values a user can act on (a full disk,
// a quota, the file-size limit, a directory without write permission, a read-only file system):
// "; free space on that disk or write to another directory". Empty for any other value.
std::string ioAdvice(int error_number);

}  // namespace collide::output
