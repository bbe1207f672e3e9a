// SPDX-License-Identifier: MIT
// The working beside a picture (issue 41) in what goes with it, through the real binary: a still's
// and a strobe picture's --latex and --markdown bundles carry it as math (align*, $…$) after the
// figure, their captions and alt text read it out in words ("v 1 prime equals minus 0.250 metres
// per second"), in the picture's language; `batch --formats working` writes STEM.working.tex and
// STEM.working.md. The numbers expected are the worked example's, solved here from momentum
// conservation and the definition of e, and the ballistic pendulum's rise speed from energy
// conservation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "scratch.hpp"

namespace collide {
namespace {

// x to three significant figures, as the readouts show it (no sign).
std::string threeFigures(double x) {
  const int decimals = std::max(0, 2 - int(std::floor(std::log10(std::abs(x)))));
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(x));
  return text;
}

// The worked example: m1 = m2 = 1 kg, v1 = +2 m/s, v2 = -1 m/s, e = 0.5.
struct WorkedExample {
  double m1 = 1.0, m2 = 1.0, v1 = 2.0, v2 = -1.0, e = 0.5;
  double v1After() const { return ((m1 - e * m2) * v1 + (1 + e) * m2 * v2) / (m1 + m2); }
  double v2After() const { return ((m2 - e * m1) * v2 + (1 + e) * m1 * v1) / (m1 + m2); }
  double energyLost() const {
    const double mu = m1 * m2 / (m1 + m2), u = v1 - v2;
    return 0.5 * mu * (1 - e * e) * u * u;
  }
};

class WorkingBundleGLTest : public ::testing::Test {
 protected:
  test::ScratchDir dir{"collide-working-bundle-"};

  int collide(const std::string& args) {
    return test::runShellBounded(test::shellQuoted(COLLIDE_BINARY) + " " + args + " >" +
                                 dir.shellFile("out.txt") + " 2>" + dir.shellFile("err.txt"));
  }
  std::string err() { return test::readFileBytes(dir.file("err.txt")); }
  void still(const std::string& name, const std::string& extra) {
    ASSERT_EQ(collide("still worked-example --at 2.5 --size 320x180 -o " + dir.shellFile(name) +
                      " --latex --markdown " + extra),
              0)
        << err();
  }
};

TEST_F(WorkingBundleGLTest, BundlesCarryTheWorkingAsMathAndAsWords) {
  const WorkedExample w;
  still("w.png", "--working");
  const std::string v1 = threeFigures(w.v1After()), v2 = threeFigures(w.v2After());
  ASSERT_LT(w.v1After(), 0.0);
  ASSERT_GT(w.v2After(), 0.0);
  const std::string tex = test::readFileBytes(dir.file("w.tex"));
  const std::size_t figure_end = tex.find("\\end{figure}");
  ASSERT_NE(figure_end, std::string::npos) << tex;
  EXPECT_NE(tex.find("\\begin{align*}", figure_end), std::string::npos) << tex;
  EXPECT_NE(tex.find("&= -" + v1 + "\\,\\mathrm{m/s}", figure_end), std::string::npos) << tex;
  EXPECT_NE(tex.find("amsmath"), std::string::npos) << tex;
  const std::string md = test::readFileBytes(dir.file("w.md"));
  EXPECT_NE(md.find("= -" + v1 + "\\,\\mathrm{m/s}$"), std::string::npos) << md;
  EXPECT_NE(md.find("= +" + v2 + "\\,\\mathrm{m/s}$"), std::string::npos) << md;

  const std::string v1_words = "v 1 prime equals minus " + v1 + " metres per second";
  const std::string v2_words = "v 2 prime equals plus " + v2 + " metres per second";
  const std::string lost_words = "equals " + threeFigures(w.energyLost()) + " joules";
  const std::string alt = test::readFileBytes(dir.file("w.alt.txt"));
  for (const std::string& words : {v1_words, v2_words, lost_words}) {
    EXPECT_NE(alt.find(words), std::string::npos) << words << "\n" << alt;
  }
  // The caption reads the result out too.
  const std::size_t caption = tex.find("\\caption{");
  ASSERT_NE(caption, std::string::npos);
  EXPECT_NE(tex.substr(caption, tex.find('\n', caption) - caption).find(v1_words),
            std::string::npos)
      << tex;
  // What is read out has words where the picture has symbols.
  const std::string spoken = alt.substr(alt.find("Impact 1 of 1: cart"));
  for (const char* symbol : {"′", "−", "₁", "½", "²", "√", "m/s"}) {
    EXPECT_EQ(spoken.find(symbol), std::string::npos) << symbol << "\n" << spoken;
  }
}

// A strobe picture's bundle carries the working as a still's does (one code path,
// app/working_texts.hpp): the math after the figure, the result in the caption, every step in the
// alt text.
TEST_F(WorkingBundleGLTest, StrobeBundlesCarryTheWorkingToo) {
  const WorkedExample w;
  ASSERT_EQ(collide("strobe worked-example --size 320x180 -o " + dir.shellFile("s.png") +
                    " --latex --markdown --working"),
            0)
      << err();
  const std::string v1 = threeFigures(w.v1After()), v2 = threeFigures(w.v2After());
  const std::string tex = test::readFileBytes(dir.file("s.tex"));
  const std::size_t figure_end = tex.find("\\end{figure}");
  ASSERT_NE(figure_end, std::string::npos) << tex;
  EXPECT_NE(tex.find("\\begin{align*}", figure_end), std::string::npos) << tex;
  EXPECT_NE(tex.find("&= -" + v1 + "\\,\\mathrm{m/s}", figure_end), std::string::npos) << tex;
  const std::size_t caption = tex.find("\\caption{");
  ASSERT_NE(caption, std::string::npos) << tex;
  EXPECT_NE(tex.substr(caption, tex.find('\n', caption) - caption)
                .find("v 1 prime equals minus " + v1 + " metres per second"),
            std::string::npos)
      << tex;
  const std::string md = test::readFileBytes(dir.file("s.md"));
  EXPECT_NE(md.find("= +" + v2 + "\\,\\mathrm{m/s}$"), std::string::npos) << md;
  // The image line's alt text: what the picture shows, then the working in words.
  const std::string alt = md.substr(0, md.find("]("));
  EXPECT_NE(alt.find("Stroboscopic image of worked-example"), std::string::npos) << md;
  EXPECT_NE(alt.find("equals " + threeFigures(w.energyLost()) + " joules"), std::string::npos)
      << md;
}

TEST_F(WorkingBundleGLTest, TheWordsComeFromTheCatalogue) {
  const WorkedExample w;
  still("de.png", "--working --lang de");
  std::string v1 = threeFigures(w.v1After());
  v1.replace(v1.find('.'), 1, ",");  // German decimals
  const std::string alt = test::readFileBytes(dir.file("de.alt.txt"));
  EXPECT_NE(alt.find("v 1 Strich gleich minus " + v1 + " Meter pro Sekunde"), std::string::npos)
      << alt;
}

TEST_F(WorkingBundleGLTest, WithoutWorkingTheBundleHasNone) {
  still("plain.png", "");
  EXPECT_EQ(test::readFileBytes(dir.file("plain.tex")).find("align*"), std::string::npos);
  EXPECT_EQ(test::readFileBytes(dir.file("plain.md")).find('$'), std::string::npos);
  EXPECT_EQ(test::readFileBytes(dir.file("plain.alt.txt")).find("prime"), std::string::npos);
}

TEST_F(WorkingBundleGLTest, BatchWritesTheWorkingAsLatexAndMarkdown) {
  ASSERT_EQ(collide("batch worked-example ballistic-pendulum --formats working -o " +
                    dir.shellFile("batch/")),
            0)
      << err();
  const WorkedExample w;
  const std::string tex = test::readFileBytes(dir.file("batch/worked-example.working.tex"));
  EXPECT_NE(tex.find("\\begin{align*}"), std::string::npos) << tex;
  EXPECT_NE(tex.find("= -" + threeFigures(w.v1After()) + "\\,\\mathrm{m/s}"), std::string::npos)
      << tex;
  // The pendulum's rise h = 0.200 m: (m1 + m2) g h = ½ (m1 + m2) v'², so v' = √(2gh).
  const double rise_speed = std::sqrt(2.0 * 9.81 * 0.2);
  const std::string md = test::readFileBytes(dir.file("batch/ballistic-pendulum.working.md"));
  EXPECT_NE(md.find(threeFigures(rise_speed) + "\\,\\mathrm{m/s}$"), std::string::npos) << md;
  const std::string manifest = test::readFileBytes(dir.file("batch/manifest.json"));
  for (const char* file : {"worked-example.working.tex", "worked-example.working.md",
                           "ballistic-pendulum.working.tex", "ballistic-pendulum.working.md"}) {
    EXPECT_NE(manifest.find(file), std::string::npos) << file << "\n" << manifest;
  }
}

}  // namespace
}  // namespace collide
