#pragma once
// The one way an input file is read (scene files, fonts): whole into memory, but never more than a
// limit, counted on what is read and not on the size the file reports (a pipe reports none,
// /dev/zero reports 0 and never ends). Pipes and process substitution (collide check <(...)) are
// read like files up to the limit; character devices, directories and block devices are refused
// before anything is read from them.
#include <cstddef>
#include <string>
#include <vector>

namespace collide::core {

enum class ReadOutcome {
  kRead,             // `bytes` holds the whole input
  kTooLarge,         // more than the limit: reading stopped there
  kCannotOpen,       // `error_number` says why (ENOENT, EACCES, ...)
  kReadFailed,       // `error_number` says why
  kDirectory,        // refused
  kCharacterDevice,  // refused: /dev/zero, /dev/urandom, a terminal
  kBlockDevice,      // refused
};

struct BoundedRead {
  ReadOutcome outcome = ReadOutcome::kRead;
  std::string bytes;
  int error_number = 0;
};

// Reads `path` whole when it holds at most `limit_bytes` bytes.
BoundedRead readBounded(const std::string& path, std::size_t limit_bytes);

// For messages: "is a directory", "is a character device", "more than N bytes",
// "cannot read: <strerror>" (not opened or a read failed); empty for kRead.
std::string describeRefusal(const BoundedRead& read, std::size_t limit_bytes);

// A regular file this process has read as an input (a scene file, a font), by identity: no output
// of the run may replace it (output/output_plan.hpp), whatever name or link reaches it.
struct InputFile {
  std::string path;  // as it was read, for messages
  unsigned long long device = 0, inode = 0;
};

// Records `path` as an input when it is a regular file (readBounded records what it reads).
void noteInputFile(const std::string& path);
// Every input recorded since the last forgetInputFiles(), in order.
std::vector<InputFile> inputFiles();
// A new run begins (app::runCli): no input recorded yet.
void forgetInputFiles();

}  // namespace collide::core
