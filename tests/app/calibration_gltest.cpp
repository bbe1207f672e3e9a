// SPDX-License-Identifier: MIT
// render --calibration: the stick Tracker is calibrated on is as long in the picture as it says,
// at the picture's scale, and it and the origin cross stay put for the whole video.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "png_io.hpp"
#include "scratch.hpp"

namespace collide::calibration_test {
namespace {

using test::CliResult;
using test::run;

// The item with this id in a layout frame.
const nlohmann::json* itemWithId(const nlohmann::json& frame, const std::string& id) {
  for (const nlohmann::json& item : frame.at("items")) {
    if (item.at("id") == id) return &item;
  }
  return nullptr;
}

// The centres of the runs of dark pixels (the stick's colour on the light theme) along row y
// from x0 to x1.
std::vector<double> darkRunCentres(const core::Image& image, int y, int x0, int x1) {
  std::vector<double> centres;
  int start = -1;
  for (int x = x0; x <= x1 + 1; ++x) {
    const bool dark = x <= x1 && image.pixel(x, y)[0] < 128 && image.pixel(x, y)[1] < 128 &&
                      image.pixel(x, y)[2] < 128;
    if (dark && start < 0) start = x;
    if (!dark && start >= 0) {
      centres.push_back(0.5 * (start + x - 1));
      start = -1;
    }
  }
  return centres;
}

// The worked example at t = 1 s: the stick's ends, drawn in a still, are its stated length times
// the layout's scale apart; its label states that length; the origin cross is at its zero end.
TEST(CalibrationGLTest, StickIsItsStatedLengthAtTheLayoutsScale) {
  const test::ScratchDir dir("collide_calibration_");
  const CliResult layout =
      run({"layout", "worked-example", "--at", "1", "--calibration", "--json", "-"});
  ASSERT_EQ(layout.exit_code, 0) << layout.err;
  const nlohmann::json frame = nlohmann::json::parse(layout.out).at("frames").at(0);
  const nlohmann::json* stick = itemWithId(frame, "calibration");
  ASSERT_NE(stick, nullptr) << layout.out;
  const nlohmann::json& s = stick->at("stick");
  const double length_m = s.at("length_m").get<double>();
  const double px_per_m = s.at("px_per_m").get<double>();
  const double from_x = s.at("from")[0].get<double>(), to_x = s.at("to")[0].get<double>();
  const double y = s.at("from")[1].get<double>();
  // A round length: 1, 2 or 5 times a power of ten.
  const double mantissa = length_m / std::pow(10.0, std::floor(std::log10(length_m) + 1e-9));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
              std::abs(mantissa - 5) < 1e-9)
      << length_m;
  // Its label is the length in metres, as the ruler writes numbers ("1 m").
  ASSERT_EQ(stick->at("lines").get<int>(), 1);
  const std::string label = stick->at("text").get<std::string>();
  ASSERT_EQ(label.substr(label.size() - 2), " m") << label;
  EXPECT_DOUBLE_EQ(std::stod(label.substr(0, label.size() - 2)), length_m) << label;

  // The picture itself: the end caps reach above the ruler's line, where nothing else is drawn.
  ASSERT_EQ(
      run({"still", "worked-example", "--at", "1", "--calibration", "-o", dir.file("still.png")})
          .exit_code,
      0);
  const core::Image image = test::readPng(dir.file("still.png"));
  const int row = static_cast<int>(std::lround(y)) - 3;
  const std::vector<double> caps =
      darkRunCentres(image, row, static_cast<int>(from_x) - 20, static_cast<int>(to_x) + 20);
  ASSERT_EQ(caps.size(), 2u) << "row " << row;
  EXPECT_NEAR(caps[1] - caps[0], length_m * px_per_m, 1.0);

  // The worked example's origin is on the ruler's 0, where the stick starts.
  const nlohmann::json* origin = itemWithId(frame, "origin");
  ASSERT_NE(origin, nullptr);
  const nlohmann::json& box = origin->at("box");
  EXPECT_NEAR(0.5 * (box[0].get<double>() + box[2].get<double>()), from_x, 0.6);
}

// Every frame of a video draws the stick and the cross in the same place.
TEST(CalibrationGLTest, StickAndOriginStayPutForTheWholeVideo) {
  const CliResult layout = run({"layout", "ballistic-pendulum", "--fps", "4", "--size", "640x360",
                                "--calibration", "--json", "-"});
  ASSERT_EQ(layout.exit_code, 0) << layout.err;
  const nlohmann::json frames = nlohmann::json::parse(layout.out).at("frames");
  ASSERT_GT(frames.size(), 5u);
  const nlohmann::json* first_stick = itemWithId(frames[0], "calibration");
  const nlohmann::json* first_origin = itemWithId(frames[0], "origin");
  ASSERT_NE(first_stick, nullptr);
  ASSERT_NE(first_origin, nullptr);
  for (const nlohmann::json& frame : frames) {
    const nlohmann::json* stick = itemWithId(frame, "calibration");
    const nlohmann::json* origin = itemWithId(frame, "origin");
    ASSERT_NE(stick, nullptr) << frame.at("frame");
    ASSERT_NE(origin, nullptr) << frame.at("frame");
    EXPECT_EQ(stick->at("stick"), first_stick->at("stick")) << frame.at("frame");
    EXPECT_EQ(origin->at("box"), first_origin->at("box")) << frame.at("frame");
  }
  // Without --calibration, neither is drawn.
  const CliResult plain =
      run({"layout", "ballistic-pendulum", "--at", "1", "--size", "640x360", "--json", "-"});
  ASSERT_EQ(plain.exit_code, 0);
  const nlohmann::json plain_frame = nlohmann::json::parse(plain.out).at("frames").at(0);
  EXPECT_EQ(itemWithId(plain_frame, "calibration"), nullptr);
  EXPECT_EQ(itemWithId(plain_frame, "origin"), nullptr);
}

}  // namespace
}  // namespace collide::calibration_test
