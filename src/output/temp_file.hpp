#pragma once
// Safe writing: a file is written under a hidden temporary name in the directory of its target and
// renamed over the target only once it is complete, so the target never holds a partial file.
// rename(2) within one directory (one file system) is atomic.
#include <filesystem>
#include <string>

namespace collide::output {

// "<dir>/.<stem>.tmp-<pid>-<n><ext>" beside `target`. The extension is kept so tools that pick a
// format from the name still see it; <n> counts per process so two sinks never share a name.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

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
