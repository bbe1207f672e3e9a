#include "app/style_options.hpp"

#include <cmath>
#include <sstream>

#include "compose/palette.hpp"
#include "core/bounded_read.hpp"
#include "core/error.hpp"
#include "render/renderer.hpp"
#include "scene/scene_io.hpp"

namespace collide::app {
namespace {

constexpr const char* kPanelsAllowed =
    "allowed: KEY=V1,V2,... with 1 to 6 numbers, KEY a scene key such as restitution or "
    "body.2.mass";

void parsePanels(const std::string& text, scene::ViewDesc& view) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == text.size()) {
    throw core::InputError("--panels: '" + text + "': " + kPanelsAllowed);
  }
  std::vector<double> values;
  std::stringstream list(text.substr(equals + 1));
  std::string item;
  while (std::getline(list, item, ',')) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(value)) {
      throw core::InputError("--panels: '" + item + "': not a number; " + kPanelsAllowed);
    }
    values.push_back(value);
  }
  if (values.empty() || values.size() > static_cast<std::size_t>(scene::kMaxPanels)) {
    throw core::InputError("--panels: '" + text + "': " + kPanelsAllowed);
  }
  view.panel_parameter = text.substr(0, equals);
  view.panel_values = values;
}

}  // namespace

void StyleOptions::addTo(CLI::App& command) {
  command.add_option("--theme", theme, "Colours: light (default), dark or high-contrast");
  command.add_option("--font", font,
                     "TrueType/OpenType font file for all text (default: DejaVu Sans)");
  command.add_option("--chart", chart,
                     "Chart beside the animation: energy, momentum, force (soft contact), speed "
                     "(histogram) or none");
  command.add_flag("--working", working,
                   "The working of the first impact beside the scene: the laws with the scene's "
                   "numbers, typeset (as collide solve prints it). A video shows the given values "
                   "from the start and each further step in turn from the impact on, all of them "
                   "by its end; a still at --at T shows what the video's frame at T shows (before "
                   "the impact the given values only); a strobe picture shows the whole working");
  command.add_option("--panels", panels,
                     "Comparison panels, one per value: KEY=V1,V2,... e.g. restitution=1,0.5,0");
  command.add_flag("--calibration", calibration,
                   "A calibration stick of a round length on the ruler and a cross at the "
                   "origin, for measuring the video in Tracker");
}

void StyleOptions::applyTo(scene::SceneDesc& scene) const {
  if (!theme.empty()) scene.view.theme = compose::themeNamed(theme).name;
  if (!chart.empty()) {
    if (chart == "none") {
      scene.view.chart = false;
    } else if (chart == "energy" || chart == "momentum" || chart == "force" || chart == "speed") {
      scene.view.chart = true;
      scene.view.chart_quantity = chart;
    } else {
      throw core::InputError("--chart: '" + chart +
                             "': allowed: energy, momentum, force, speed or none");
    }
  }
  if (!panels.empty()) parsePanels(panels, scene.view);
  if (calibration) scene.view.calibration = true;
  if (working) scene.view.working = true;
  if (!font.empty()) {
    try {
      render::checkFont(font);
    } catch (const render::FontError& error) {
      throw core::InputError(error.what());
    }
    render::setDefaultFontPath(font);
    core::noteInputFile(font);  // an input: no output of the run may replace it
  }
}

}  // namespace collide::app
