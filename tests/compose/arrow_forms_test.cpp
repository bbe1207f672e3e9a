// SPDX-License-Identifier: MIT
// Arrows' forms planned over a stretch between two events (issue 37, compose/arrow_forms.hpp):
// a form that would last a frame or two between two others is replaced by one its neighbours
// have, and one that stands longer is kept. The plan is checked on made-up stretches.
#include "compose/arrow_forms.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

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

}  // namespace
}  // namespace collide
