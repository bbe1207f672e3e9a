// SPDX-License-Identifier: MIT
#include "working/steps.hpp"

#include <utility>

#include "text/number_format.hpp"
#include "text/translate.hpp"

namespace collide::working {

using text::Math;

namespace {

std::string headingOf(StepKind kind) {
  // TRANSLATORS: the headings of the steps of a working (the solution of a collision written
  // out, as on a teacher's board).
  switch (kind) {
    case StepKind::kGiven:
      return text::trc("working step", "Given");
    case StepKind::kLaw:
      return text::trc("working step", "The laws");
    case StepKind::kSolved:
      return text::trc("working step", "Solved");
    case StepKind::kSubstituted:
      return text::trc("working step", "With the numbers");
    case StepKind::kResult:
      return text::trc("working step", "Result");
  }
  return "";
}

}  // namespace

Step step(StepKind kind) {
  return Step{kind, headingOf(kind), {}};
}

Step& stepOf(Working& working, StepKind kind) {
  for (Step& existing : working.steps) {
    if (existing.kind == kind) return existing;
  }
  // Steps keep their order (given, laws, solved, numbers, result) whatever adds them first.
  auto place = working.steps.begin();
  while (place != working.steps.end() && place->kind < kind) ++place;
  return *working.steps.insert(place, step(kind));
}

Math product(std::vector<Math> factors) {
  Math math = text::row({});
  for (Math& factor : factors) {
    if (!math.parts.empty()) math.parts.push_back(text::op(text::multiplicationSign()));
    math.parts.push_back(text::grouped(std::move(factor)));
  }
  return math;
}

Math juxtaposed(std::vector<Math> factors) {
  Math math = text::row({});
  for (Math& factor : factors) math.parts.push_back(text::grouped(std::move(factor)));
  return math;
}

Math sum(Math left, Math right) {
  return text::row({std::move(left), text::op("+"), text::grouped(std::move(right))});
}

Math difference(Math left, Math right) {
  return text::row({std::move(left), text::op("−"), text::grouped(std::move(right))});
}

}  // namespace collide::working
