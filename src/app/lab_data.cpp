// SPDX-License-Identifier: MIT
#include "app/lab_data.hpp"

#include <algorithm>
#include <cmath>

#include "app/render_pipeline.hpp"
#include "compose/frame_source.hpp"
#include "report/csv_table.hpp"

namespace collide::app {
namespace {

// About, from above: a number in its shortest form with its tab, as the CSV's estimate.
constexpr double kBytesPerField = 20.0;

double toNanosecond(double t_s) {
  return std::round(t_s * 1e9) / 1e9;
}

}  // namespace

std::vector<report::TrackerRow> trackerRows(const scene::SceneDesc& scene,
                                            const physics::Timeline& timeline, int fps) {
  const std::vector<double> shown = compose::frameSimulatedTimes(
      scene, timeline, fps, [fps](double duration_s) { return frameCount(duration_s, fps); });
  std::vector<report::TrackerRow> rows;
  rows.reserve(shown.size());
  for (std::size_t k = 0; k < shown.size(); ++k) {
    rows.push_back({toNanosecond(static_cast<double>(k) / fps), toNanosecond(shown[k])});
  }
  return rows;
}

output::PlannedOutput trackerOutput(const std::string& option, const std::string& path,
                                    const scene::SceneDesc& scene, int fps) {
  const double rows =
      std::ceil(fps * scene.duration_s * std::max(1.0, scene.view.slow_motion_factor)) + 1.0;
  const double columns = 1.0 + 2.0 * static_cast<double>(scene.bodies.size());
  output::PlannedOutput planned{option, path};
  planned.estimated_bytes = rows * columns * kBytesPerField;
  planned.estimate_basis = std::to_string(static_cast<long long>(rows)) + " rows of " +
                           std::to_string(static_cast<long long>(columns)) + " columns";
  planned.smaller_with = "a shorter --duration or a lower --fps";
  return planned;
}

output::PlannedOutput vernierOutput(const std::string& option, const std::string& path,
                                    const scene::SceneDesc& scene, double step_s) {
  const report::CsvSize size =
      report::estimateCsvSize(scene.dimensions, scene.bodies.size(), scene.duration_s, step_s);
  output::PlannedOutput planned{option, path};
  planned.estimated_bytes = size.bytes;
  planned.estimate_basis =
      std::to_string(size.rows) + " rows of " + std::to_string(size.columns) + " columns";
  planned.smaller_with = "a shorter --duration or a larger --dt";
  return planned;
}

}  // namespace collide::app
