// SPDX-License-Identifier: MIT
// The energy bar where energy comes in: its length is the largest total the scene reaches (the
// start's energy and all that is released), the parts add up to the start's and what was released
// by then, and the released strip has its own colour, told apart from the blue, orange and gray
// beside it with each kind of colour blindness in every theme.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>

#include "app/animation.hpp"
#include "compose/palette.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace released_bar_test {

const frame::EnergySegment* stripOf(const frame::EnergyBar& bar) {
  for (const frame::EnergySegment& segment : bar.segments) {
    if (segment.strip) return &segment;
  }
  return nullptr;
}

TEST(ReleasedBarTest, BarStandsForTheLargestTotalAndThePartsAddUpToStartPlusReleased) {
  // spring-carts: nothing moves at the start; Q = 3 J at t = 0.5 s. recoil: Q = 802 J at 0.25 s.
  for (const auto& [preset, q_J, release_s] :
       {std::tuple{"spring-carts", 3.0, 0.5}, std::tuple{"recoil", 802.0, 0.25}}) {
    SCOPED_TRACE(preset);
    const app::Animation animation = app::animate(scene::loadPreset(preset), {640, 360});
    for (double t : {0.0, release_s + 0.1, animation.frames.simulatedDuration_s()}) {
      const frame::FrameModel frame = animation.frames.frameAtSimulated(t);
      const frame::EnergyBar& bar = frame.panels.front().energy_bar;
      EXPECT_NEAR(bar.full_scale_J, q_J, 1e-9 * q_J);
      const frame::EnergySegment* strip = stripOf(bar);
      ASSERT_NE(strip, nullptr) << "t = " << t;
      const double released = t < release_s ? 0.0 : q_J;
      EXPECT_NEAR(strip->energy_J, released, 1e-9 * q_J) << "t = " << t;
      EXPECT_EQ(strip->from_J, 0.0);
      EXPECT_EQ(strip->label.empty(), released == 0.0) << strip->label;
      double parts = 0.0;
      for (const frame::EnergySegment& segment : bar.segments) {
        if (!segment.strip) parts += segment.energy_J;
      }
      EXPECT_NEAR(parts, released, 1e-9 * q_J) << "t = " << t;
    }
  }
}

// Machado, Oliveira and Fernandes (IEEE TVCG 2009): the full-severity simulation matrices of
// protanopia, deuteranopia and tritanopia in linear RGB; and normal vision.
using Matrix = std::array<std::array<double, 3>, 3>;
const std::array<Matrix, 4> kVisions = {{
    {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
    {{{0.152286, 1.052583, -0.204868},
      {0.114503, 0.786281, 0.099216},
      {-0.003882, -0.048116, 1.051998}}},
    {{{0.367322, 0.860646, -0.227968},
      {0.280085, 0.672501, 0.047413},
      {-0.011820, 0.042940, 0.968881}}},
    {{{1.255528, -0.076749, -0.178779},
      {-0.078411, 0.930809, 0.147602},
      {0.004733, 0.691367, 0.303900}}},
}};

double linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// CIELAB (D65) of an sRGB colour as seen with `vision`.
std::array<double, 3> labSeen(const frame::Rgba& color, const Matrix& vision) {
  const double in[3] = {linear(color.r), linear(color.g), linear(color.b)};
  double rgb[3];
  for (int i = 0; i < 3; ++i) {
    rgb[i] =
        std::clamp(vision[i][0] * in[0] + vision[i][1] * in[1] + vision[i][2] * in[2], 0.0, 1.0);
  }
  const double x = (0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2]) / 0.95047;
  const double y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
  const double z = (0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2]) / 1.08883;
  const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
  return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

TEST(ReleasedBarTest, ReleasedColourIsToldApartFromBlueOrangeAndGrayInEveryVision) {
  // A colour difference of 25 (CIE76) reads as a different colour at a glance; the bar's own
  // neighbours (KE of body 1 and 2, lost) must all be that far from it in every theme.
  constexpr double kApart = 25.0;
  for (const std::string& name : compose::themeNames()) {
    const compose::Theme& theme = compose::themeNamed(name);
    for (const Matrix& vision : kVisions) {
      const std::array<double, 3> released = labSeen(theme.released, vision);
      for (const frame::Rgba& other : {theme.bodies[0], theme.bodies[1], theme.lost}) {
        const std::array<double, 3> seen = labSeen(other, vision);
        const double apart =
            std::hypot(released[0] - seen[0], released[1] - seen[1], released[2] - seen[2]);
        EXPECT_GT(apart, kApart) << name;
      }
    }
  }
}

}  // namespace released_bar_test
}  // namespace collide
