#pragma once
// Where an output's bytes go, decided from what is at its path before anything is written. Only a
// regular file (or a new name) is ever replaced, and then safely: written under a temporary name
// beside it and renamed over it when complete. A symbolic link is followed: the file it points to
// is replaced and the link stays a link. A character device, FIFO or socket is written straight
// through and never replaced, as every Unix tool does (-o /dev/null, --json /dev/stdout). "-" is
// standard output. Anything else (a directory, a block device) is refused.
#include <filesystem>
#include <string>

#include "output/temp_file.hpp"

namespace collide::output {

// The name that means standard output on the command line.
inline constexpr const char* kStdoutName = "-";

enum class OutputRoute {
  kReplace,  // a regular file or a new name: a temporary file beside it, renamed over it
  kInPlace,  // a character device, FIFO or socket: opened and written where it is
  kStdout,   // "-": the process's standard output, file descriptor 1
  kRefused,  // a directory, a block device, a link loop: never written
};

struct OutputPlace {
  OutputRoute route = OutputRoute::kReplace;
  // kReplace: the file to replace, symbolic links resolved (it may not exist yet); kInPlace: the
  // path as given (opening follows links); kStdout and kRefused: the path as given.
  std::filesystem::path path;
  // What is there, for messages: "a directory", "a character device", "a FIFO", "a socket",
  // "a block device", "a link loop", "a link into a missing directory"; empty for kReplace.
  std::string what;
};

// Looks at `path` (never writes). A missing parent directory is not judged here.
OutputPlace placeOutput(const std::filesystem::path& path);

// One output file. Routes as placeOutput says: for kReplace the bytes go to a temporary file
// that commit() renames over the target, and that the destructor removes unless committed; for
// kInPlace and kStdout they go straight to the target and commit() does nothing (what was written
// there cannot be taken back). Throws core::InputError for a kRefused path.
//
// The target's directory is held open (WatchedDirectory): the temporary file is written, renamed
// and removed through it, so a directory moved meanwhile keeps the file (complete, under its
// name) or loses the temporary one, and a signal that ends the process removes it. A file replaced
// keeps the permissions of the one it replaces, and its owner where the process may give it
// (root).
class OutputFile {
 public:
  explicit OutputFile(std::filesystem::path target);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Where to open and write: the temporary file, the device or FIFO itself, or "-" for stdout
  // (the caller writes to file descriptor 1).
  const std::filesystem::path& writePath() const { return write_path_; }
  // The path as the user gave it, for messages (never the temporary name).
  const std::filesystem::path& target() const { return target_; }
  OutputRoute route() const { return route_; }
  // Whether the bytes go out as a stream that cannot be sought back into or reread (a FIFO,
  // a device, stdout): containers that rewrite their start at the end need a streaming layout.
  bool streamed() const { return route_ != OutputRoute::kReplace; }
  // Puts the complete file in place (the rename); afterwards the destructor leaves it alone.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path replaced_;  // kReplace: the resolved file the rename replaces
  std::filesystem::path write_path_;
  WatchedDirectory directory_;  // kReplace: the directory of replaced_
  std::string temporary_name_;  // kReplace: the temporary file's name in it
  OutputRoute route_;
  bool committed_ = false;
};

}  // namespace collide::output
