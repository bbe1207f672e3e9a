// SPDX-License-Identifier: MIT
#include "compose/working_panel.hpp"

#include <algorithm>

#include "text/translate.hpp"
#include "working/working.hpp"

namespace collide::compose {

namespace {

bool sameMath(const text::Math& a, const text::Math& b) {
  if (a.kind != b.kind || a.text != b.text || a.close != b.close || a.primes != b.primes ||
      a.parts.size() != b.parts.size()) {
    return false;
  }
  for (std::size_t k = 0; k < a.parts.size(); ++k) {
    if (!sameMath(a.parts[k], b.parts[k])) return false;
  }
  return true;
}

// Whether a line of the numbers substituted already ends in `result` (v₁′ = … = −0.250 m/s).
bool resultShown(const working::Working& working, const working::Equation& result) {
  for (const working::Step& step : working.steps) {
    if (step.kind != working::StepKind::kSubstituted) continue;
    for (const working::Equation& line : step.equations) {
      if (line.sides.size() >= 2 && result.sides.size() >= 2 &&
          sameMath(line.sides.front(), result.sides.front()) &&
          sameMath(line.sides.back(), result.sides.back())) {
        return true;
      }
    }
  }
  return false;
}

frame::WorkingPart partOf(const working::Working& working, const working::Step& step,
                          const working::Equation& equation) {
  if (step.kind == working::StepKind::kGiven) return frame::WorkingPart::kGiven;
  if (step.kind == working::StepKind::kResult && resultShown(working, equation)) {
    return frame::WorkingPart::kRepeatedResult;
  }
  return frame::WorkingPart::kStep;
}

}  // namespace

std::optional<frame::WorkingModel> workingPanel(const physics::Timeline& timeline) {
  if (working::impactCount(timeline) == 0) return std::nullopt;
  const working::Working working = working::workingFor(timeline, 0);
  frame::WorkingModel model;
  model.title = working.title;
  // TRANSLATORS: in the working panel, where the given values were when there is no room for them
  // beside the scene; "collide solve" is the command's name.
  model.given_left_out = text::tr("(given values left out for room: see collide solve)");
  for (const working::Step& step : working.steps) {
    // The laws solved in symbols come again with the numbers in them: the panel keeps only that.
    if (step.kind == working::StepKind::kSolved) continue;
    const frame::WorkingPart heading_part = step.kind == working::StepKind::kGiven
                                                ? frame::WorkingPart::kGiven
                                                : frame::WorkingPart::kStep;
    model.lines.push_back({step.heading, {}, heading_part});
    for (const working::Equation& equation : step.equations) {
      model.lines.push_back({"", equation.sides, partOf(working, step, equation)});
    }
  }
  return model;
}

int workingLinesShown(const frame::WorkingModel& working, double impact_s, double end_s,
                      double t_s) {
  const auto headings = static_cast<int>(
      std::count_if(working.lines.begin(), working.lines.end(),
                    [](const frame::WorkingLine& line) { return line.sides.empty(); }));
  // The steps after the given values, the last a delay before the end at the latest.
  const int later_steps = std::max(1, headings - 1);
  const double delay_s =
      std::min(kWorkingStepDelay_s, std::max(0.0, end_s - impact_s) / later_steps);
  int steps_shown = 1;  // the given values
  if (t_s >= impact_s) {
    steps_shown += delay_s > 0.0 ? 1 + static_cast<int>((t_s - impact_s) / delay_s) : later_steps;
  }
  int steps = 0;
  for (std::size_t k = 0; k < working.lines.size(); ++k) {
    if (working.lines[k].sides.empty() && ++steps > steps_shown) return static_cast<int>(k);
  }
  return static_cast<int>(working.lines.size());
}

}  // namespace collide::compose
