// SPDX-License-Identifier: MIT
#pragma once
// Every file a run will write (the output and its side files: alt text, captions, LaTeX, a batch's
// manifest), checked together before any work starts, so that a run never fails late after
// replacing some of them:
//   - each path is one an output may be written at (its directory exists; not a directory, a
//     block device or a link loop: output_target.hpp's checkOutputPath);
//   - no two outputs are the same file (names, links and hard links compared by identity);
//   - no output is a file the run reads (a scene file, a font: core::inputFiles());
//   - no output is estimated larger than kMaxOutputBytes, nor all of them on one file system
//     larger than its free space, unless forced (--force).
// The plan also watches the directories the files go to (temp_file.hpp), so that a signal that
// ends the run removes the temporary files there, whichever module wrote them.
#include <string>
#include <utility>
#include <vector>

#include "output/temp_file.hpp"

namespace collide::output {

// Larger than this, an output needs --force: 10 GB, well past any lesson's video or table.
inline constexpr double kMaxOutputBytes = 10e9;

struct PlannedOutput {
  PlannedOutput(std::string option_name, std::string output_path, bool frames = false)
      : option(std::move(option_name)), path(std::move(output_path)), frames_directory(frames) {}

  std::string option;  // what named it, for messages: "-o", "--json", "--captions", "manifest"
  std::string path;    // as given ("-": stdout)
  bool frames_directory = false;  // a directory of PNG frames, not a file
  double estimated_bytes = 0.0;   // 0: not estimated
  std::string estimate_basis;     // how: "7200001 rows of 8003 columns"
  std::string smaller_with;       // how to ask for less: "a shorter --duration or a larger --dt"
};

class OutputPlan {
 public:
  OutputPlan() = default;
  // Throws core::InputError (exit 2) naming the option and the path of the first output that
  // breaks a rule above. `force`: the size rules give way.
  explicit OutputPlan(const std::vector<PlannedOutput>& outputs, bool force = false);

 private:
  std::vector<WatchedDirectory> watched_;
};

// "about 1.0 TB", "about 350 MB", "about 12 kB": a size for a message, in SI units.
std::string aboutBytes(double bytes);

}  // namespace collide::output
