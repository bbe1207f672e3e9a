#include "core/module_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <optional>
#include <system_error>

namespace collide::core {
namespace {

namespace fs = std::filesystem;

// The shared object this code was linked into, when it is not the program: the Python extension
// (python/), whose modules lie beside it in the installed package.
std::optional<fs::path> holdingLibrary(const fs::path& program) {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&loadModuleSymbol), &info) == 0 || info.dli_fname == nullptr) {
    return std::nullopt;
  }
  std::error_code error;
  const fs::path library = fs::canonical(info.dli_fname, error);
  if (error || library == program) return std::nullopt;
  return library;
}

std::vector<fs::path> candidatesFor(const std::string& module_file,
                                    const std::vector<std::string>& built_in_paths) {
  std::vector<fs::path> candidates;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  // First: a program of another project (python3) may have a collide of another version installed
  // beside it, whose modules would not match this code.
  if (const std::optional<fs::path> library = holdingLibrary(program)) {
    candidates.push_back(library->parent_path() / module_file);
  }
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
