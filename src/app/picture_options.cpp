#include "app/picture_options.hpp"

#include "core/typed_text.hpp"
#include "output/output_file.hpp"
#include "report/physics_warnings.hpp"

namespace collide::app {

void PictureOptions::addTo(CLI::App& command, const std::string& output_help,
                           const std::function<void(CLI::App&)>& main_options) {
  // --help lists them in this order: what to draw, where to, how big, then the changes.
  scene.addSceneArgument(command);
  command.add_option("-o,--output", output, output_help)->required();
  size.addTo(command);
  if (main_options) main_options(command);
  scene.addChanges(command);
  style.addTo(command);  // --theme --font --chart --panels
  backend.addTo(command);
}

scene::SceneDesc PictureOptions::loadScene() const {
  backend.apply();
  scene::SceneDesc loaded = scene.load();
  style.applyTo(loaded);
  return loaded;
}

PictureRequest pictureRequest(const PictureOptions& options, const PrintOptions& print,
                              const BundleOptions& bundle, const CLI::App& command) {
  PictureRequest request{options.loadScene(), options.size.parse(),
                         output::stillTarget(options.output), std::nullopt, bundle};
  request.print = print.resolve(request.size, command);
  return request;
}

std::ostream& reportStream(const output::OutputTarget& target, CommandStreams& streams) {
  return target.path == output::kStdoutName ? streams.err : streams.out;
}

std::string shownPath(const output::OutputTarget& target) {
  // Escaped: a path is shown on a terminal.
  return target.path == output::kStdoutName ? "stdout" : core::echoTyped(target.path, 1000);
}

void reportSideFilesAndWarnings(const std::vector<std::string>& side_files,
                                const std::vector<std::string>& warnings, CommandStreams& streams) {
  for (const std::string& file : side_files) {
    streams.out << "wrote " << core::echoTyped(file, 1000) << "\n";
  }
  report::printWarnings(warnings, streams.err);
}

}  // namespace collide::app
