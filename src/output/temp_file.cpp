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
    default:
      return "";
  }
}

}  // namespace collide::output
