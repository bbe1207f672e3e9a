#pragma once
// What every command that draws a scene (render, still, strobe, chart) takes: SCENE with
// --duration, --set and the shortcuts; -o OUT; --size; --backend; --theme --font --chart --panels.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "app/backend_option.hpp"
#include "app/command.hpp"
#include "app/picture_pipeline.hpp"
#include "app/scene_options.hpp"
#include "app/style_options.hpp"
#include "output/output_target.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

// What -o may be for a command that writes one figure (still, strobe, chart).
inline constexpr const char* kFigureOutputHelp =
    "Output path: *.png, or *.svg / *.pdf (vector figures), a device or FIFO, or - for stdout";

struct PictureOptions {
  SceneOptions scene;
  StyleOptions style;
  SizeOption size;
  BackendOption backend;
  std::string output;

  // Registers them on `command`; -o is required and `output_help` says what it may be.
  // `main_options` registers the command's own main options (--fps, --at, --rate), listed right
  // after SCENE, -o and --size in --help.
  void addTo(CLI::App& command, const std::string& output_help,
             const std::function<void(CLI::App&)>& main_options = {});
  // Makes --backend the renderers' backend, loads and validates the scene with its overrides and
  // applies the style options. Throws core::InputError naming the option.
  scene::SceneDesc loadScene() const;
};

// What a one-figure command (strobe, chart) asks for: the scene its options load, the size, the
// target -o names, the --print size (as resolved for the --size `command` was given) and the
// bundle options, in that order.
PictureRequest pictureRequest(const PictureOptions& options, const PrintOptions& print,
                              const BundleOptions& bundle, const CLI::App& command);

// Where the "wrote OUT" line goes: stdout, or stderr when the picture itself fills stdout.
std::ostream& reportStream(const output::OutputTarget& target, CommandStreams& streams);
// The target as the report names it: its path, or "stdout" for "-".
std::string shownPath(const output::OutputTarget& target);

// After the "wrote OUT" line: the files written beside it (stdout) and the physics warnings
// (stderr, "warning: ...").
void reportSideFilesAndWarnings(const std::vector<std::string>& side_files,
                                const std::vector<std::string>& warnings, CommandStreams& streams);

}  // namespace collide::app
