// SPDX-License-Identifier: MIT
#pragma once
// The working beside a picture (--working, issue 41) in the words and the bundle that go with it:
// read out in the alt text (every step the panel shows) and the caption (the result), as math in
// NAME.tex and NAME.md. A still and a strobe picture both build their bundle here.
#include <optional>
#include <string>

#include "physics/timeline.hpp"
#include "report/figure_bundle.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

struct WorkingTexts {
  std::string spoken_steps;   // the title and every step, in words
  std::string spoken_result;  // the result step, in words
  std::string latex, markdown;
};

// The first impact's working when the scene shows it (ViewDesc::working); empty when it does not
// or the run has no impact.
WorkingTexts workingTexts(const scene::SceneDesc& scene, const physics::Timeline& timeline);

// `text` and then `sentence`, a space between; `text` alone when `sentence` is empty.
std::string withSentence(const std::string& text, const std::string& sentence);

// A picture's bundle: its caption with the result read out, its alt text (already carrying the
// steps, as the picture's Description does) and the working as math.
report::FigureBundle pictureBundle(const std::string& image_path, const std::string& caption,
                                   const std::string& alt_text, std::optional<double> width_cm,
                                   const WorkingTexts& working);

}  // namespace collide::app
