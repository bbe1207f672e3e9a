#pragma once
// Checks that a placed panel's texts stand clear: every text box lies inside the frame, at least
// the title's margin from each of its edges, covers no body, arrow, wall, string or contact flash,
// and is nearer its own body than any other (and near it, or tied to it by a leader); every leader
// line strikes through no other text, leader, arrow, wall, flash or body; and any two texts keep
// about a word space apart.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "frame/frame_model.hpp"
#include "painted_geometry.hpp"
#include "pixel_distances.hpp"
#include "scene_texts.hpp"

namespace collide::compose_test {

// Two lines of text read as two when there is about a word space between them across, or any
// room at all above or below (the line box holds the font's own leading): these many em.
inline constexpr double kLeastGapAcrossEm = 0.25;
inline constexpr double kLeastGapAlongEm = 0.05;

// Adds a gtest failure for every text of `panel` (gathered by gatherSceneTexts; `line_box_px` the
// height of its text's line) that covers or wanders, or whose leader crosses something.
// `margin_px`: how far the title stands from the frame's top left corner (FrameLayout::header).
void expectTextsClear(const frame::PanelModel& panel, const std::vector<SceneText>& texts,
                      const std::vector<PixelBody>& bodies, const std::vector<PaintedArrow>& arrows,
                      const std::vector<PaintedMark>& marks, int width_px, int height_px,
                      double margin_px, double line_box_px);

// Adds a gtest failure for every two boxes of a frame that overlap or stand nearer than the least
// gaps above, in em of `text_px`.
void expectTextsApart(const std::vector<Box>& boxes, double text_px);

// Checks every panel of `frame`, placed for a width_px x height_px picture (`text_floor_px`: a
// printed figure's, frame::printTextFloorPx; 0: none): it was placed for that size, its texts
// stand clear (expectTextsClear) and all the frame's texts apart (expectTextsApart).
// `margin_kept`: every text keeps the title's margin from the frame's edges (else it only stays
// inside the frame). `each_panel`, where given, checks more of each panel (its index and its
// arrows as painted).
using PanelCheck =
    std::function<void(const frame::PanelModel&, std::size_t, const std::vector<PaintedArrow>&)>;
void expectFrameClear(const frame::FrameModel& frame, int width_px, int height_px,
                      double text_floor_px, render::TextMetrics& metrics, bool margin_kept,
                      const PanelCheck& each_panel = {});

}  // namespace collide::compose_test
