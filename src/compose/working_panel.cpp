// SPDX-License-Identifier: MIT
#include "compose/working_panel.hpp"

#include "working/working.hpp"

namespace collide::compose {

std::optional<frame::WorkingModel> workingPanel(const physics::Timeline& timeline) {
  if (working::impactCount(timeline) == 0) return std::nullopt;
  const working::Working working = working::workingFor(timeline, 0);
  frame::WorkingModel model;
  model.title = working.title;
  for (const working::Step& step : working.steps) {
    // The laws solved in symbols come again with the numbers in them: the panel keeps only that.
    if (step.kind == working::StepKind::kSolved) continue;
    model.lines.push_back({step.heading, {}});
    for (const working::Equation& equation : step.equations) {
      model.lines.push_back({"", equation.sides});
    }
  }
  return model;
}

int workingLinesShown(const frame::WorkingModel& working, double impact_s, double t_s) {
  int steps_shown = 1;  // the given values
  if (t_s >= impact_s) steps_shown += 1 + static_cast<int>((t_s - impact_s) / kWorkingStepDelay_s);
  int steps = 0;
  for (std::size_t k = 0; k < working.lines.size(); ++k) {
    if (working.lines[k].sides.empty() && ++steps > steps_shown) return static_cast<int>(k);
  }
  return static_cast<int>(working.lines.size());
}

}  // namespace collide::compose
