// SPDX-License-Identifier: MIT
// collide layout --json, in-process (no GL: the layout is recorded, not painted): the items a
// frame draws, their stable ids, the arrows' facts, a still equal to the video's frame, and
// the opacity of a text fading in or out (written only below 1).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/layout_json.hpp"
#include "cli_runner.hpp"
#include "report/json_writer.hpp"

namespace collide {
namespace {

using nlohmann::json;
using test::run;

json layoutOf(const std::vector<std::string>& args) {
  const test::CliResult r = run(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return json::parse(r.out);
}

const json* itemNamed(const json& frame, const std::string& id) {
  for (const json& item : frame.at("items")) {
    if (item.at("id") == id) return &item;
  }
  return nullptr;
}

// The worked example: 1 kg at +2 m/s meets 1 kg at -1 m/s, e = 0.5. Momentum 1 kg·m/s and the
// separation speed e · 3 m/s give v1' = (1 - 1.5) / 2 = -0.25 m/s, v2' = (1 + 1.5) / 2 = +1.25.
TEST(LayoutCliTest, AStillListsWhatItDrawsWithTheArrowsToScale) {
  const json layout = layoutOf({"layout", "worked-example", "--at", "2.5", "--json", "-"});
  EXPECT_EQ(layout.at("size"), json::array({1280, 720}));
  EXPECT_EQ(layout.at("events").size(), 1u);
  ASSERT_EQ(layout.at("frames").size(), 1u);
  const json& frame = layout.at("frames")[0];
  EXPECT_EQ(frame.at("t"), 2.5);
  std::set<std::string> ids;
  for (const json& item : frame.at("items")) {
    EXPECT_TRUE(ids.insert(item.at("id")).second) << "two items named " << item.at("id");
    // Nothing fades in this still: every item is solid, which the file says by saying nothing.
    EXPECT_FALSE(item.contains("opacity")) << item.at("id");
    const json& box = item.at("box");
    EXPECT_LE(box[0].get<double>(), box[2].get<double>()) << item.at("id");
    EXPECT_LE(box[1].get<double>(), box[3].get<double>()) << item.at("id");
  }
  for (const char* id :
       {"title", "time", "body.1", "body.2", "mass.1", "mass.2", "arrow.1", "arrow.2", "caption"}) {
    EXPECT_NE(itemNamed(frame, id), nullptr) << id;
  }
  const double expected_mps[] = {0.25, 1.25};
  for (int body = 1; body <= 2; ++body) {
    const json* arrow = itemNamed(frame, "arrow." + std::to_string(body));
    ASSERT_NE(arrow, nullptr);
    EXPECT_EQ(arrow->at("kind"), "arrow");
    EXPECT_EQ(arrow->at("body"), body);
    EXPECT_NEAR(arrow->at("value").get<double>(), expected_mps[body - 1], 1e-9);
    const double dx = arrow->at("to")[0].get<double>() - arrow->at("from")[0].get<double>();
    // After the impact body 1 moves left, body 2 right.
    EXPECT_EQ(dx > 0.0, body == 2);
    if (arrow->at("drawn") == "on_scale") {
      EXPECT_NEAR(std::abs(dx), arrow->at("value").get<double>() * arrow->at("scale").get<double>(),
                  2.0);
    }
  }
  const json* readout = itemNamed(frame, "velocity.2");
  ASSERT_NE(readout, nullptr);
  EXPECT_EQ(readout->at("body"), 2);
  EXPECT_NE(readout->at("text").get<std::string>().find("+1.25 m/s"), std::string::npos);
}

TEST(LayoutCliTest, AVideosFramesKeepTheirIdsAndAStillIsTheVideosFrame) {
  const json video =
      layoutOf({"layout", "worked-example", "--fps", "10", "--size", "640x360", "--json", "-"});
  EXPECT_EQ(video.at("size"), json::array({640, 360}));
  EXPECT_EQ(video.at("fps"), 10);
  const json& frames = video.at("frames");
  ASSERT_EQ(frames.size(), 40u);  // 4 s at 10 per second
  for (std::size_t k = 0; k < frames.size(); ++k) {
    EXPECT_EQ(frames[k].at("frame"), static_cast<int>(k));
    EXPECT_NEAR(frames[k].at("t").get<double>(), k / 10.0, 1e-12);
    for (const char* id : {"title", "body.1", "body.2"}) {
      EXPECT_NE(itemNamed(frames[k], id), nullptr) << id << " in frame " << k;
    }
  }
  const json still =
      layoutOf({"layout", "worked-example", "--at", "1.5", "--size", "640x360", "--json", "-"});
  EXPECT_EQ(still.at("frames")[0].at("items"), frames[15].at("items"));
}

json itemJson(const frame::DrawnItem& item) {
  std::ostringstream out;
  report::JsonWriter writer(out);
  app::writeDrawnItem(writer, item);
  return json::parse(out.str());
}

TEST(LayoutJsonTest, AFadingTextSaysItsOpacityAndASolidOneNothing) {
  frame::DrawnItem item;
  item.id = "mass.1";
  item.kind = "label";
  item.lines = {"m₁ = 1.00 kg"};
  item.box = {10.0, 20.0, 110.0, 40.0};
  EXPECT_FALSE(itemJson(item).contains("opacity"));
  // An opacity a painter was handed as a float (frame::PlacedText::opacity), to the thousandth.
  item.opacity = double(0.3f);
  EXPECT_EQ(itemJson(item).at("opacity").get<double>(), 0.3);
  item.opacity = 0.25;
  EXPECT_EQ(itemJson(item).at("opacity").get<double>(), 0.25);
  // Under half a thousandth from solid is solid.
  item.opacity = 0.9996;
  EXPECT_FALSE(itemJson(item).contains("opacity"));
}

}  // namespace
}  // namespace collide
