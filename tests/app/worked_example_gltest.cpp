// Frames of the default preset rendered in-process and compared with reviewed goldens, plus the
// energy bar's proportions measured in the pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "app/animation.hpp"
#include "frame/layout.hpp"
#include "golden.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"
#include "text/language.hpp"

namespace collide {
namespace {

core::Image renderWorkedExample(double t_s, int width_px, int height_px,
                                std::string* renderer_name = nullptr) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset("worked-example"), {width_px, height_px}).frames;
  render::Renderer renderer(width_px, height_px);
  if (renderer_name) *renderer_name = renderer.glRendererName();
  return core::Image::copyOf(renderer.render(source.frameAt(t_s)));
}

struct GoldenCase {
  const char* name;
  double t_s;
};

// Keeps ctest's test names readable (the default prints the struct's bytes).
void PrintTo(const GoldenCase& golden, std::ostream* out) {
  *out << golden.name;
}

class WorkedExampleGoldenGLTest : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(WorkedExampleGoldenGLTest, MatchesReviewedFrame) {
  test::GoldenOptions options;
  const core::Image frame = renderWorkedExample(GetParam().t_s, 480, 270, &options.renderer);
  EXPECT_TRUE(test::compareWithGolden(
      frame.view(), std::string("app/worked_example_") + GetParam().name + ".png", options));
}

// Start; approaching; the instant of contact (7/6 s); after, both moving apart.
INSTANTIATE_TEST_SUITE_P(Times, WorkedExampleGoldenGLTest,
                         ::testing::Values(GoldenCase{"t0_000", 0.0}, GoldenCase{"t0_800", 0.8},
                                           GoldenCase{"contact", 7.0 / 6.0},
                                           GoldenCase{"t2_500", 2.5}),
                         [](const auto& info) { return std::string(info.param.name); });

// After the collision, in German (Latin with umlauts, longer words), Arabic (joined letters, read
// from the right: title, headings, caption and legend from the right edge, the physics not
// mirrored), Hindi (Devanagari conjuncts and vowel signs) and Japanese (CJK, no spaces), at
// 640x360 so that every script is legible in the reviewed image.
class WorkedExampleLanguageGoldenGLTest : public ::testing::TestWithParam<std::string> {};

TEST_P(WorkedExampleLanguageGoldenGLTest, MatchesReviewedFrame) {
  const text::ScopedLanguage language(GetParam());
  test::GoldenOptions options;
  const core::Image frame = renderWorkedExample(2.5, 640, 360, &options.renderer);
  EXPECT_TRUE(
      test::compareWithGolden(frame.view(), "app/worked_example_" + GetParam() + ".png", options));
}

INSTANTIATE_TEST_SUITE_P(Languages, WorkedExampleLanguageGoldenGLTest,
                         ::testing::Values("de", "ar", "hi", "ja"));

// Which of the bar's colours a pixel shows, by nearest colour; 'x' for none of them.
char barColorAt(const core::Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  struct Named {
    char name;
    int r, g, b;
  };
  const Named colours[] = {{'b', 0, 114, 178}, {'o', 230, 159, 0}, {'g', 153, 153, 153}};
  for (const Named& c : colours) {
    if (std::abs(p[0] - c.r) <= 12 && std::abs(p[1] - c.g) <= 12 && std::abs(p[2] - c.b) <= 12)
      return c.name;
  }
  return 'x';
}

TEST(WorkedExampleBarGLTest, SegmentsMatchTheEnergiesWithinOnePixel) {
  // Energies after the impact, derived here: momentum m1 v1 + m2 v2 conserved and
  // v2' - v1' = e (v1 - v2).
  const scene::SceneDesc scene = scene::loadPreset("worked-example");
  const double m1 = scene.bodies[0].mass_kg, m2 = scene.bodies[1].mass_kg;
  const double v1 = scene.bodies[0].velocity_mps.x(), v2 = scene.bodies[1].velocity_mps.x();
  const double e = scene.restitution;
  const double v1_after = (m1 * v1 + m2 * v2 - m2 * e * (v1 - v2)) / (m1 + m2);
  const double v2_after = v1_after + e * (v1 - v2);
  const double total = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;
  const double ke1 = 0.5 * m1 * v1_after * v1_after, ke2 = 0.5 * m2 * v2_after * v2_after;
  const double lost = total - ke1 - ke2;

  const int width = 640, height = 360;
  const core::Image frame = renderWorkedExample(2.5, width, height);
  const frame::PixelRect inner = frame::computeFrameLayout(width, height).panel().bar_inner;
  const int row = static_cast<int>(0.5 * (inner.y0 + inner.y1));

  std::string runs;  // colour of each pixel across the bar's inside
  for (int x = static_cast<int>(inner.x0); x < static_cast<int>(inner.x1); ++x)
    runs += barColorAt(frame, x, row);
  auto count = [&](char c) { return static_cast<double>(std::count(runs.begin(), runs.end(), c)); };
  const double px_per_J = inner.width() / total;
  EXPECT_NEAR(count('b'), ke1 * px_per_J, 1.0) << runs;
  EXPECT_NEAR(count('o'), ke2 * px_per_J, 1.0) << runs;
  EXPECT_NEAR(count('g'), lost * px_per_J, 1.0) << runs;
  // Left to right: blue, then orange, then gray, with at most one blended pixel at each boundary.
  EXPECT_LT(runs.find_last_of('b'), runs.find_first_of('o'));
  EXPECT_LT(runs.find_last_of('o'), runs.find_first_of('g'));
  EXPECT_LE(count('x'), 2.0) << runs;
}

}  // namespace
}  // namespace collide
