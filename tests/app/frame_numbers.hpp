// SPDX-License-Identifier: MIT
#pragma once
// What the frame-numbers tests share (frame_numbers_test.cpp, frame_figures_test.cpp,
// frame_legibility_test.cpp): every preset animated once at 1280x720, the instants they sample,
// and the numbers read back from its labels.
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"

namespace collide::frame_numbers {

inline constexpr int kInstants = 20;
inline const std::string kMinus = "\u2212";

// A displayed number back to a double: true minus sign, thousands commas ("12,500").
double parseShown(std::string text);

// The number at the end of an energy label "KE₁ 12.3 mJ", its unit and its decimals.
bool labelValue(const std::string& label, double& value, std::string& unit, int& decimals);

double unitValue(const std::string& unit);

struct Picture {
  std::string preset;
  scene::SceneDesc scene;
  app::Animation animation;
};

// Every preset with its animation, made once for the test binary.
std::vector<Picture>& everyPreset();

// The k-th of kInstants instants spread evenly over the scene's duration.
double instant(const scene::SceneDesc& scene, int k);

// Significant figures of a shown number with `decimals` decimals: "7.22" -> 3, "0.680" -> 3.
int figuresOf(double value, int decimals);

// The signed number and its decimals in a velocity label "v₁′ = +0.170 m/s" (1D) or the speed in
// "v₁ = 4.26 m/s, −82°" (2D).
bool velocityValue(const std::string& label, double& value, int& decimals);

}  // namespace collide::frame_numbers
