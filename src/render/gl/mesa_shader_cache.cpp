// SPDX-License-Identifier: MIT
#include "render/gl/mesa_shader_cache.hpp"

#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace collide::render {
namespace {

const char* variable(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && value[0] != '\0' ? value : nullptr;
}

// The folder Mesa (22.3) makes its shader cache's folder in: $MESA_SHADER_CACHE_DIR (its older
// name $MESA_GLSL_CACHE_DIR), else $XDG_CACHE_HOME, else .cache in the account's home folder
// (from the password database, not $HOME). Empty when there is no home to find.
std::string cacheParent() {
  for (const char* name : {"MESA_SHADER_CACHE_DIR", "MESA_GLSL_CACHE_DIR", "XDG_CACHE_HOME"}) {
    if (const char* value = variable(name)) return value;
  }
  const passwd* account = getpwuid(getuid());
  if (account == nullptr || account->pw_dir == nullptr) return {};
  return std::string(account->pw_dir) + "/.cache";
}

bool writableFolder(const std::string& path) {
  struct stat info {};
  return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode) &&
         access(path.c_str(), W_OK | X_OK) == 0;
}

// "/a/b/" -> "/a", "b" -> ".".
std::string folderAbove(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Mesa makes `parent` if missing (one level: mkdir, not mkdir -p), then its own folder in it.
bool mesaCanMakeItsFolderIn(const std::string& parent) {
  if (parent.empty()) return false;
  struct stat info {};
  if (stat(parent.c_str(), &info) == 0) return writableFolder(parent);
  return writableFolder(folderAbove(parent));
}

void switchOff() {
  if (variable("MESA_SHADER_CACHE_DISABLE") != nullptr) return;  // someone chose
  if (!mesaCanMakeItsFolderIn(cacheParent())) setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
}

}  // namespace

void switchOffAnUnusableShaderCache() {
  // A function-local static, not std::call_once: that would take thread-local storage, and so
  // the dynamic loader itself as a dependency of the GL module.
  static const bool done = (switchOff(), true);
  static_cast<void>(done);
}

}  // namespace collide::render
