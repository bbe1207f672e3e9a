#include "output/temp_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "output/frame_sink.hpp"

namespace collide::output {

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

void renameOrThrow(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) {
    const int error_number = errno;
    throw OutputError("cannot rename '" + from.string() + "' to '" + to.string() +
                      "': " + std::strerror(error_number));
  }
}

void removeQuietly(const std::filesystem::path& path) noexcept {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

std::string ioErrorMessage(const std::string& what, const std::filesystem::path& path,
                           int error_number) {
  return what + " '" + path.string() + "': " + std::strerror(error_number);
}

TemporaryFile::TemporaryFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporaryPathFor(target_)) {}

TemporaryFile::~TemporaryFile() {
  if (!committed_) removeQuietly(temporary_);
}

void TemporaryFile::commit() {
  renameOrThrow(temporary_, target_);
  committed_ = true;
}

}  // namespace collide::output
