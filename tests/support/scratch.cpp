#include "scratch.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace collide::test {

namespace fs = std::filesystem;

fs::path makeUniqueTempDir(const std::string& prefix) {
  std::string pattern = (fs::temp_directory_path() / (prefix + "XXXXXX")).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (mkdtemp(buffer.data()) == nullptr) {
    throw std::system_error(errno, std::generic_category(), "mkdtemp " + pattern);
  }
  return fs::path(buffer.data());
}

ScratchDir::ScratchDir(const std::string& prefix) : path_(makeUniqueTempDir(prefix)) {}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  // Tests may leave read-only folders behind (unwritable-output cases): make them removable.
  for (auto it = fs::recursive_directory_iterator(path_, ignored);
       it != fs::recursive_directory_iterator(); it.increment(ignored)) {
    if (it->is_directory(ignored))
      fs::permissions(it->path(), fs::perms::owner_all, fs::perm_options::add, ignored);
  }
  fs::remove_all(path_, ignored);
}

std::vector<std::string> ScratchDir::entries() const {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(path_)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string ScratchDir::shellFile(const std::string& name) const {
  return shellQuoted(file(name));
}

int runShellBounded(const std::string& command, std::chrono::seconds limit) {
  // coreutils timeout signals the whole process group it leads, so pipelines die with it.
  const std::string bounded = "timeout --kill-after=10 " + std::to_string(limit.count()) +
                              " /bin/sh -c " + shellQuoted(command);
  const int status = std::system(bounded.c_str());  // check-tests: bounded by timeout(1)
  if (status == -1 || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

ShellRun runShellCaptured(const fs::path& directory, const std::string& command,
                          std::chrono::seconds limit) {
  const fs::path out = directory / "captured_stdout.txt", err = directory / "captured_stderr.txt";
  ShellRun run{
      runShellBounded(
          command + " >" + shellQuoted(out.string()) + " 2>" + shellQuoted(err.string()), limit),
      readFileBytes(out), readFileBytes(err)};
  std::error_code ignored;
  fs::remove(out, ignored);
  fs::remove(err, ignored);
  return run;
}

std::string readFileBytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

std::optional<fs::path> makeFullDevice(const fs::path& directory, const std::string& name,
                                       std::string& why_not) {
  const fs::path node = directory / name;
  if (mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
    why_not = "cannot make a device node (mknod c 1 7) in " + directory.string() + ": " +
              std::strerror(errno);
    return std::nullopt;
  }
  // A nodev mount refuses to open it; check that it really reports a full disk.
  const int fd = open(node.c_str(), O_WRONLY);
  if (fd < 0) {
    why_not =
        "cannot open the device node " + node.string() + " (nodev mount?): " + std::strerror(errno);
    fs::remove(node);
    return std::nullopt;
  }
  const char byte = 0;
  const ssize_t written = write(fd, &byte, 1);
  const int write_errno = errno;
  close(fd);
  if (written != -1 || write_errno != ENOSPC) {
    why_not = "the device node " + node.string() + " does not report a full disk";
    fs::remove(node);
    return std::nullopt;
  }
  return node;
}

}  // namespace collide::test
