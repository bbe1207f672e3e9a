// SPDX-License-Identifier: MIT
#include "app/working_texts.hpp"

#include "working/working.hpp"
#include "working/writers.hpp"

namespace collide::app {

WorkingTexts workingTexts(const scene::SceneDesc& scene, const physics::Timeline& timeline) {
  if (!scene.view.working || working::impactCount(timeline) == 0) return {};
  using Kind = working::StepKind;
  const working::Working shown = working::workingFor(timeline, 0);
  return {
      shown.title + ". " +
          working::speakSteps(shown, {Kind::kGiven, Kind::kLaw, Kind::kSubstituted, Kind::kResult}),
      working::speakSteps(shown, {Kind::kResult}), working::writeLatex(shown),
      working::writeMarkdown(shown)};
}

std::string withSentence(const std::string& text, const std::string& sentence) {
  return sentence.empty() ? text : text + " " + sentence;
}

report::FigureBundle pictureBundle(const std::string& image_path, const std::string& caption,
                                   const std::string& alt_text, std::optional<double> width_cm,
                                   const WorkingTexts& working) {
  return {image_path,    withSentence(caption, working.spoken_result),
          alt_text,      width_cm,
          working.latex, working.markdown};
}

}  // namespace collide::app
