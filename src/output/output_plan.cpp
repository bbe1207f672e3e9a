// SPDX-License-Identifier: MIT
#include "output/output_plan.hpp"

#include <sys/stat.h>
#include <sys/statvfs.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include "core/bounded_read.hpp"
#include "core/error.hpp"
#include "output/output_file.hpp"
#include "output/output_target.hpp"

namespace collide::output {
namespace fs = std::filesystem;
namespace {

// What an output is, compared with the other outputs and the inputs.
struct Placed {
  const PlannedOutput* output = nullptr;
  fs::path file;           // the file written (links resolved), or the frames directory
  bool shareable = false;  // stdout, a device, a FIFO, a socket: written in place, may repeat
  std::string identity;    // "dev:inode" of an existing file, else its normalized path
  bool exists = false;
  unsigned long long device = 0, inode = 0;
  fs::path directory;  // where its bytes land, for the free space
};

std::string quoted(const std::string& path) {
  return "'" + path + "'";
}

// "frame_" digits ".png": a name a frames directory's sink writes (png_sinks.hpp).
bool isFrameName(const std::string& name) {
  constexpr std::size_t kPrefix = 6, kSuffix = 4;  // "frame_", ".png"
  return name.size() > kPrefix + kSuffix && name.compare(0, kPrefix, "frame_") == 0 &&
         name.compare(name.size() - kSuffix, kSuffix, ".png") == 0 &&
         name.find_first_not_of("0123456789", kPrefix) == name.size() - kSuffix;
}

// The frames directory checked as render's framesTarget does: its parent exists, and it is a
// directory if anything is there; and every frame name already in it is one a frame may replace
// (not a directory, a block device or a link loop), as the sink would find only once drawing.
void checkFramesDirectory(const PlannedOutput& output) {
  requireParentDirectory(output.option, output.path);
  struct stat info {};
  if (::stat(output.path.c_str(), &info) != 0) return;
  if (!S_ISDIR(info.st_mode)) {
    throw core::InputError(output.option + ": " + quoted(output.path) +
                           ": exists and is not a directory; allowed: a directory for PNG frames");
  }
  std::error_code error;
  for (fs::directory_iterator it(output.path, error), end; !error && it != end;
       it.increment(error)) {
    if (isFrameName(it->path().filename().string())) {
      checkOutputPath(output.option, it->path().string());
    }
  }
}

Placed place(const PlannedOutput& output) {
  Placed placed;
  placed.output = &output;
  if (output.frames_directory) {
    checkFramesDirectory(output);
    placed.file = output.path;
  } else {
    checkOutputPath(output.option, output.path);
    const OutputPlace where = placeOutput(output.path);
    placed.shareable = where.route != OutputRoute::kReplace;
    placed.file = where.path;
  }
  placed.directory = output.frames_directory ? placed.file : placed.file.parent_path();
  if (placed.directory.empty()) placed.directory = ".";
  struct stat info {};
  if (::stat(placed.file.c_str(), &info) == 0) {
    placed.exists = true;
    placed.device = info.st_dev;
    placed.inode = info.st_ino;
    placed.identity = std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
    if (output.frames_directory) placed.directory = placed.file;
  } else {
    std::error_code error;
    const fs::path absolute = fs::absolute(placed.file, error);
    fs::path normal = fs::weakly_canonical(absolute, error);
    if (error) normal = absolute.lexically_normal();
    placed.identity = normal.string();
    if (output.frames_directory) placed.directory = placed.file.parent_path();
    if (placed.directory.empty()) placed.directory = ".";
  }
  return placed;
}

void refuseTwice(const Placed& earlier, const Placed& later) {
  throw core::InputError(later.output->option + ": " + quoted(later.output->path) +
                         ": the same file as " + earlier.output->option + " " +
                         quoted(earlier.output->path) +
                         "; allowed: a different file for each output");
}

void refuseInput(const Placed& output, const core::InputFile& input) {
  throw core::InputError(output.output->option + ": " + quoted(output.output->path) + ": is " +
                         quoted(input.path) +
                         ", which this run reads; allowed: an output path that names no input "
                         "(scene file, font)");
}

void refuseSize(const PlannedOutput& output, const std::string& why) {
  const std::string smaller =
      output.smaller_with.empty() ? "a smaller output" : output.smaller_with;
  throw core::InputError(output.option + ": " + quoted(output.path) + ": would be " +
                         aboutBytes(output.estimated_bytes) +
                         (output.estimate_basis.empty() ? "" : " (" + output.estimate_basis + ")") +
                         ", " + why + "; allowed: " + smaller + ", or --force to write it anyway");
}

// Bytes that an unprivileged writer may still add to the file system holding `directory`; none
// where it cannot be told.
std::optional<double> freeBytes(const fs::path& directory, unsigned long long& device) {
  struct statvfs info {};
  struct stat where {};
  // A file system without blocks (/proc, /sys) says nothing of its room.
  if (::statvfs(directory.c_str(), &info) != 0 || ::stat(directory.c_str(), &where) != 0 ||
      info.f_blocks == 0) {
    return std::nullopt;
  }
  device = where.st_dev;
  return static_cast<double>(info.f_bavail) * static_cast<double>(info.f_frsize);
}

// The size rules: each output at most kMaxOutputBytes, and those on one file system at most its
// free space (an output that replaces a file frees that file's size).
void checkSizes(const std::vector<Placed>& placed) {
  std::map<unsigned long long, double> wanted;  // bytes per file system
  std::map<unsigned long long, double> free;
  std::map<unsigned long long, const Placed*> largest;
  for (const Placed& p : placed) {
    const PlannedOutput& output = *p.output;
    if (output.estimated_bytes > kMaxOutputBytes) {
      refuseSize(output, "more than the " + aboutBytes(kMaxOutputBytes).substr(6) +
                             " collide writes without --force");
    }
    if (p.shareable || output.estimated_bytes <= 0.0) continue;
    unsigned long long device = 0;
    const std::optional<double> available = freeBytes(p.directory, device);
    if (!available) continue;
    free[device] = *available;
    wanted[device] += output.estimated_bytes;
    if (largest[device] == nullptr ||
        output.estimated_bytes > largest[device]->output->estimated_bytes) {
      largest[device] = &p;
    }
  }
  for (const auto& [device, bytes] : wanted) {
    if (bytes > free[device]) {
      refuseSize(*largest[device]->output,
                 "and its file system has " + aboutBytes(free[device]).substr(6) + " free");
    }
  }
}

}  // namespace

OutputPlan::OutputPlan(const std::vector<PlannedOutput>& outputs, bool force) {
  std::vector<Placed> placed;
  placed.reserve(outputs.size());
  for (const PlannedOutput& output : outputs) placed.push_back(place(output));
  std::map<std::string, const Placed*> seen;
  const std::vector<core::InputFile> inputs = core::inputFiles();
  for (const Placed& p : placed) {
    if (p.shareable) continue;
    const auto [at, fresh] = seen.emplace(p.identity, &p);
    if (!fresh) refuseTwice(*at->second, p);
    for (const core::InputFile& input : inputs) {
      if (p.exists && input.device == p.device && input.inode == p.inode) refuseInput(p, input);
    }
  }
  if (!force) checkSizes(placed);
  std::map<std::string, bool> watching;
  for (const Placed& p : placed) {
    if (p.shareable || !watching.emplace(p.directory.string(), true).second) continue;
    watched_.emplace_back(p.directory);
  }
}

std::string aboutBytes(double bytes) {
  static const char* const kUnits[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int unit = 0;
  while (bytes >= 999.5 && unit < 6) {
    bytes /= 1000.0;
    ++unit;
  }
  char text[48];
  if (unit == 0) {
    std::snprintf(text, sizeof text, "about %.0f bytes", bytes);
  } else {
    std::snprintf(text, sizeof text, bytes < 9.95 ? "about %.1f %s" : "about %.0f %s", bytes,
                  kUnits[unit]);
  }
  return text;
}

}  // namespace collide::output
