// SPDX-License-Identifier: MIT
// Arrows' forms planned over a stretch between two events (issue 37, compose/arrow_forms.hpp):
// a form that would last a frame or two between two others is replaced by one its neighbours
// have, and one that stands longer is kept. The plan is checked on made-up stretches, and on
// newtons-cradle 640x360, whose ball 5, swinging out to its turn at about 0.7 s, was drawn
// beside it, then from its edge for two frames, then as a below-scale mark: read frame by frame
// as `collide layout` writes it, from 0.6 s to 0.75 s, well under a second.
#include "compose/arrow_forms.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "arrow_form_checks.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

using compose::ArrowForm;
using compose::ArrowFormChoice;
using compose::ArrowFormPlan;
using Ask = ArrowFormPlan::Ask;

// `count` samples whose own form is `own` and beside first `beside`.
void append(std::vector<ArrowFormChoice>& forms, std::size_t count, ArrowForm own,
            ArrowForm beside) {
  forms.insert(forms.end(), count, ArrowFormChoice{own, beside});
}

// The forms drawn where the plan's asks are taken.
std::vector<ArrowForm> drawnForms(const std::vector<ArrowFormChoice>& forms,
                                  const std::vector<Ask>& asks) {
  std::vector<ArrowForm> drawn;
  for (std::size_t k = 0; k < forms.size(); ++k) {
    if (asks[k] == Ask::kBesideFirst) {
      drawn.push_back(forms[k].beside_first);
    } else {
      drawn.push_back(asks[k] == Ask::kHidden ? ArrowForm::kNone : forms[k].own);
    }
  }
  return drawn;
}

int changes(const std::vector<ArrowForm>& drawn) {
  int count = 0;
  for (std::size_t k = 1; k < drawn.size(); ++k) count += drawn[k] != drawn[k - 1] ? 1 : 0;
  return count;
}

TEST(ArrowFormsTest, TwoFramesFromTheEdgeBetweenBesideAndAMarkGoBeside) {
  // A ball slowing to its turn: beside it, from its edge for two samples, then a mark; beside
  // first holds it beside while its arrow reads.
  std::vector<ArrowFormChoice> forms;
  append(forms, 6, ArrowForm::kBeside, ArrowForm::kBeside);
  append(forms, 2, ArrowForm::kEdge, ArrowForm::kBeside);
  append(forms, 6, ArrowForm::kMark, ArrowForm::kMark);
  const std::vector<Ask> asks = ArrowFormPlan::plan(forms);
  const std::vector<ArrowForm> drawn = drawnForms(forms, asks);
  EXPECT_EQ(changes(drawn), 1);
  for (std::size_t k = 0; k < forms.size(); ++k) {
    EXPECT_EQ(asks[k], k == 6 || k == 7 ? Ask::kBesideFirst : Ask::kOwn) << "sample " << k;
  }
}

TEST(ArrowFormsTest, AMarkForOneFrameBetweenNoneIsHidden) {
  // A ball creeping through the rack: its mark finds room straight on for one sample.
  std::vector<ArrowFormChoice> forms;
  forms.insert(forms.end(), 5, ArrowFormChoice{ArrowForm::kNone, ArrowForm::kNone, true});
  append(forms, 1, ArrowForm::kMark, ArrowForm::kMark);
  forms.insert(forms.end(), 5, ArrowFormChoice{ArrowForm::kNone, ArrowForm::kNone, true});
  const std::vector<Ask> asks = ArrowFormPlan::plan(forms);
  EXPECT_EQ(changes(drawnForms(forms, asks)), 0);
  EXPECT_EQ(asks[5], Ask::kHidden);
}

TEST(ArrowFormsTest, AnArrowFromRestIsNotHidden) {
  // Released from rest: none at its first sample (no speed, not crowded), a mark for two
  // samples, then from its edge: the mark is its velocity's first sight, and is kept.
  std::vector<ArrowFormChoice> forms;
  append(forms, 1, ArrowForm::kNone, ArrowForm::kNone);
  append(forms, 2, ArrowForm::kMark, ArrowForm::kMark);
  append(forms, 8, ArrowForm::kEdge, ArrowForm::kBeside);
  const std::vector<ArrowForm> drawn = drawnForms(forms, ArrowFormPlan::plan(forms));
  EXPECT_EQ(drawn[1], ArrowForm::kMark);
  EXPECT_EQ(drawn[2], ArrowForm::kMark);
}

TEST(ArrowFormsTest, ABreakThatStandsIsKeptAndOneOfTwoFramesGoesBeside) {
  // Straight on, then with a break, then beside: a break of two samples goes beside at once; a
  // break of more samples than a replaced form may have reads, and is kept.
  for (const std::size_t breaks : {std::size_t{2}, std::size_t{8}}) {
    std::vector<ArrowFormChoice> forms;
    append(forms, 6, ArrowForm::kStraight, ArrowForm::kBeside);
    append(forms, breaks, ArrowForm::kBreak, ArrowForm::kBeside);
    append(forms, 6, ArrowForm::kBeside, ArrowForm::kBeside);
    const std::vector<ArrowForm> drawn = drawnForms(forms, ArrowFormPlan::plan(forms));
    EXPECT_EQ(changes(drawn), breaks == 2 ? 1 : 2) << breaks << " breaks";
    EXPECT_EQ(drawn[6], breaks == 2 ? ArrowForm::kBeside : ArrowForm::kBreak) << breaks;
    EXPECT_EQ(drawn[0], ArrowForm::kStraight);
  }
}

TEST(ArrowFormsTest, AFormTheStretchBeginsWithIsKept) {
  // Released from rest: a mark for two samples from the stretch's start, then from the edge; no
  // change comes before the mark, so it does not flicker.
  std::vector<ArrowFormChoice> forms;
  append(forms, 2, ArrowForm::kMark, ArrowForm::kMark);
  append(forms, 8, ArrowForm::kEdge, ArrowForm::kBeside);
  const std::vector<Ask> asks = ArrowFormPlan::plan(forms);
  for (std::size_t k = 0; k < forms.size(); ++k) EXPECT_EQ(asks[k], Ask::kOwn) << "sample " << k;
}

TEST(ArrowFormsTest, NewtonsCradleBall5KeepsItsFormToItsTurn) {
  constexpr int kWidthPx = 640, kHeightPx = 360, kFps = 60;
  const app::Animation animation =
      app::animate(scene::loadPreset("newtons-cradle"), {kWidthPx, kHeightPx});
  constexpr int kFirst = 36, kLast = 45;  // 0.6 s to 0.75 s
  for (const physics::CollisionEvent& event : animation.frames.panelTimeline(0).collisions()) {
    ASSERT_FALSE(event.time_s > static_cast<double>(kFirst) / kFps &&
                 event.time_s < static_cast<double>(kLast) / kFps)
        << "no event between the frames, one at " << event.time_s << " s";
  }
  test::ArrowFormWatch watch;
  int beside = 0;
  for (int k = kFirst; k <= kLast; ++k) {
    const double t_s = static_cast<double>(k) / kFps;
    const frame::FrameModel model = animation.frames.frameAtSimulated(t_s);
    const test::ArrowFormsAt forms =
        test::arrowFormsAt(model, render::drawnItems(model, kWidthPx, kHeightPx));
    beside += forms.at({0, 4}).form == "beside" ? 1 : 0;
    watch.add(t_s, forms, false);
  }
  EXPECT_GT(beside, 0) << "ball 5's arrow beside it as it swings out";
  for (const std::string& flicker : watch.finish()) ADD_FAILURE() << flicker;
}

// One body's arrow watched over frames of `forms` and `speeds_mps`, no event between them.
std::vector<std::string> watched(const std::vector<std::string>& forms,
                                 const std::vector<double>& speeds_mps) {
  test::ArrowFormWatch watch;
  for (std::size_t k = 0; k < forms.size(); ++k) {
    watch.add(static_cast<double>(k) / 60.0, {{{0, 0}, {forms[k], speeds_mps[k]}}}, false);
  }
  return watch.finish();
}

TEST(ArrowFormWatchTest, AFormOfTwoFramesBetweenTwoOthersFlickers) {
  // Slowing all along: beside, from the edge for two frames, a mark: its speed does not turn in
  // the two frames, so the form flickers.
  const std::vector<std::string> found =
      watched({"beside", "beside", "beside", "from the edge", "from the edge", "below scale",
               "below scale", "below scale"},
              {1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].find("from the edge for 2 frame(s)"), std::string::npos) << found[0];
}

TEST(ArrowFormWatchTest, AVelocityThroughZeroDoesNotFlicker) {
  // A glider turning on its spring: on its scale, a mark, none at rest, a mark, on its scale,
  // its speed least in the middle; and the same forms at a speed that does not dip do flicker.
  const std::vector<std::string> forms = {"on scale",    "on scale", "on scale",
                                          "below scale", "none",     "below scale",
                                          "on scale",    "on scale", "on scale"};
  EXPECT_TRUE(watched(forms, {0.5, 0.4, 0.3, 0.1, 0.0, 0.1, 0.3, 0.4, 0.5}).empty());
  EXPECT_EQ(watched(forms, {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5}).size(), 3u);
}

}  // namespace
}  // namespace collide
