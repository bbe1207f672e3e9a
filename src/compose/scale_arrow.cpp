#include "compose/scale_arrow.hpp"

#include <cmath>

#include "text/number_format.hpp"

namespace collide::compose {
namespace {

// The round speed after `speed_mps` in 1, 2, 5, 10, 20, ...
double nextRoundSpeed(double speed_mps) {
  const double decade = std::pow(10.0, std::floor(std::log10(speed_mps) + 1e-9));
  for (double step : {1.0, 2.0, 5.0, 10.0}) {
    if (step * decade > speed_mps * (1.0 + 1e-9)) return step * decade;
  }
  return 10.0 * decade;
}

}  // namespace

double roundValueBelow(double most) {
  if (!(most > 0.0)) return 0.0;
  const double decade = std::pow(10.0, std::floor(std::log10(most)));
  for (double step : {5.0, 2.0, 1.0}) {
    if (step * decade <= most * (1.0 + 1e-9)) return step * decade;
  }
  return decade;
}

std::string scaleArrowLabel(double speed_mps) {
  return text::formatPlain(speed_mps) + " m/s";
}

void fitScaleArrows(frame::FrameModel& frame, const frame::FrameLayout& layout) {
  // A scale arrow grows to the visible minimum of a body's arrow, but never past this share of
  // its panel's scene width (a small grid cell's heading line has room for little more).
  constexpr double kMostOfScene = 0.12;
  constexpr int kMostSteps = 12;  // four decades: far beyond any arrow scale a plan picks
  for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
    frame::PanelModel& panel = frame.panels[p];
    if (!(panel.scale_arrow_mps > 0.0) || !(panel.arrow_m_per_mps > 0.0)) continue;
    const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels[p], layout);
    // The shortest arrow render draws for a body: how long a speed must be drawn to read.
    const double least_px = frame::arrowShape(1e-12, panel, layout, to_px).length_px;
    const double most_px = kMostOfScene * layout.panels[p].scene.width();
    double speed = panel.scale_arrow_mps;
    for (int step = 0; step < kMostSteps; ++step) {
      if (frame::scaleArrowShape(speed, panel, layout, to_px).length_px >= least_px) break;
      const double next = nextRoundSpeed(speed);
      if (frame::scaleArrowShape(next, panel, layout, to_px).length_px > most_px) break;
      speed = next;
    }
    if (speed != panel.scale_arrow_mps) {
      panel.scale_arrow_mps = speed;
      panel.scale_arrow_label = scaleArrowLabel(speed);
    }
  }
}

}  // namespace collide::compose
