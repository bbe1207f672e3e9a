// SPDX-License-Identifier: MIT
// A tiny but nonzero mass, speed or energy on a picture and in its alt text reads as itself, in
// powers of ten below a femto-unit (text/number_format.hpp), never "0": the worked example with
// one cart of 1e-300 kg, and with one cart moving at 1e-300 m/s.
#include <gtest/gtest.h>

#include <string>

#include "app/animation.hpp"
#include "report/alt_text.hpp"
#include "scene/scene_io.hpp"

namespace collide {
namespace {

const std::string kTimesTenToTheMinus300 =
    "1.00 \u00d7 10\u207b\u00b3\u2070\u2070";  // 1.00 × 10⁻³⁰⁰

app::Animation workedExample(const std::vector<std::string>& sets) {
  std::vector<scene::Override> changes;
  for (const std::string& set : sets) changes.push_back(scene::parseSetExpression(set));
  return app::animate(scene::loadScene("worked-example", changes), {640, 360});
}

TEST(TinyNumbersTest, ATinyMassReadsAsItselfNotZero) {
  const app::Animation animation = workedExample({"body.1.mass=1e-300"});
  const frame::FrameModel frame = animation.frames.frameAtSimulated(1.0);
  ASSERT_EQ(frame.panels.size(), 1u);
  EXPECT_EQ(frame.panels[0].bodies[0].label, "m₁ = " + kTimesTenToTheMinus300 + " kg");
  EXPECT_EQ(frame.panels[0].bodies[1].label, "m₂ = 1.00 kg");
  // The alt text too.
  const std::string alt = report::describeStill(animation.frames.timeline(), "", 1.0);
  EXPECT_NE(alt.find("(" + kTimesTenToTheMinus300 + " kg)"), std::string::npos) << alt;
  EXPECT_EQ(alt.find("(0 kg)"), std::string::npos) << alt;
}

TEST(TinyNumbersTest, ATinySpeedAndItsMomentumReadAsThemselves) {
  // Cart 1 (1 kg) at 1e-300 m/s, cart 2 at rest: v₁ = +1e-300 m/s and Σp = +1e-300 kg·m/s.
  // Their squares are below what a double holds: a scale taken from |v|² would be 0.
  const frame::FrameModel frame =
      workedExample({"body.1.velocity=1e-300", "body.2.velocity=0"}).frames.frameAtSimulated(1.0);
  ASSERT_EQ(frame.panels.size(), 1u);
  EXPECT_EQ(frame.panels[0].bodies[0].velocity_label, "v₁ = +" + kTimesTenToTheMinus300 + " m/s");
  const std::string& info = frame.panels[0].info;
  EXPECT_NE(info.find("+" + kTimesTenToTheMinus300 + " kg·m/s"), std::string::npos) << info;
}

}  // namespace
}  // namespace collide
