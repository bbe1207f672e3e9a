#include "core/module_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

namespace collide::core {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> candidatesFor(const std::string& module_file,
                                    const std::vector<std::string>& built_in_paths) {
  std::vector<fs::path> candidates;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    candidates.push_back(program.parent_path() / module_file);
    candidates.push_back(program.parent_path() / ".." / "lib" / "collide" / module_file);
  }
  for (const std::string& path : built_in_paths) candidates.emplace_back(path);
  return candidates;
}

}  // namespace

void* loadModuleSymbol(const std::string& module_file, const char* symbol,
                       const std::vector<std::string>& built_in_paths, std::string& error) {
  std::string tried;
  for (const fs::path& candidate : candidatesFor(module_file, built_in_paths)) {
    std::error_code exists_error;
    if (!fs::exists(candidate, exists_error)) {
      tried += (tried.empty() ? "" : ", ") + candidate.string();
      continue;
    }
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle == nullptr) {
      error = "cannot load the module '" + candidate.string() + "': " + dlerror();
      return nullptr;
    }
    void* address = dlsym(handle, symbol);
    if (address == nullptr) {
      error = "the module '" + candidate.string() + "' has no " + symbol;
      return nullptr;
    }
    return address;
  }
  error = "the module " + module_file + " is not installed (looked for " + tried + ")";
  return nullptr;
}

}  // namespace collide::core
