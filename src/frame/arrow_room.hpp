// SPDX-License-Identifier: MIT
#pragma once
// Room for a 2D body's velocity arrow (issue 37: no arrow runs through a wall, a cushion or
// another body): how far it may reach from the body's centre, and the arrow drawn in that room
// (frame::bodyArrowShape's 2D arrows).
#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::frame {

// A moving body's arrow shows at least this many full head lengths (a head and a shaft behind
// it, so its direction reads at a glance); its head at least this share of the full head, and
// at most this share of the arrow.
inline constexpr double kArrowMinHeads = 1.0;
inline constexpr double kArrowHeadMinShare = 0.5;
inline constexpr double kArrowHeadOfLength = 0.35;
// The gap of an off-scale arrow's break, a share of its head's width (frame::arrowBreak).
inline constexpr double kArrowBreakOfHeadWidth = 0.6;
// An arrow drawn beside its body stands near it: its tail at most a gap and this many of its
// heads' widths off the body's outline (touching is half a head's width), so it reads as that
// body's and no label fits between them.
inline constexpr double kArrowBesideReachHeads = 0.75;

// Half the size of the box `body` is drawn in, pixels: its shape turned by its angle, and half
// its outline.
core::Vec2 drawnHalfBoxPx(const BodyModel& body, const FrameLayout& layout,
                          const WorldToPixel& to_px);

// 2D: how far an arrow from `body`'s centre along its motion reaches before the face of a wall
// or the box (drawnHalfBoxPx) of another body it would run into, less a gap, pixels (infinity
// where nothing is in its way); a body whose box holds the centre (the body itself, one it
// overlaps or is stuck to) is no obstacle.
double arrowRoomPx(const BodyModel& body, const PanelModel& panel, const FrameLayout& layout,
                   const WorldToPixel& to_px);

// The unit vector, pixels, that ArrowShape::beside_px counts along for an arrow pointing along
// `direction` (pixels, unit): across it, towards the top of the picture (to the left where the
// arrow points straight up or down).
core::Vec2 arrowBesideDirection(const core::Vec2& direction);

// How far from `body`'s centre a line along `direction` (pixels, y down, unit) leaves the body,
// pixels: a disk's radius, the side of a box (turned by its angle) that the line crosses.
double edgeAlongPx(const BodyModel& body, const core::Vec2& direction, const WorldToPixel& to_px);

// 2D: `shape` (drawn from the body's centre, its first hidden_px under the body) in the room
// straight on (room_px, arrowRoomPx; arrowInRoom); where that leaves no arrow at all, beside
// `body` instead (ArrowShape::beside_px), whole and to its scale, near it (its tail within a gap
// and kArrowBesideReachHeads head widths of the body's outline), where there, above first, then
// below, nothing is in its way (no wall, no other body within half its head's width and a gap of
// its line) and it stays in the panel's view. A ball swinging into a row of others
// (newtons-cradle) shows its velocity up to the strike, over the row. Else no arrow (its value in
// its readout). A body marked BodyModel::arrow_beside_first (compose plans it over time) has its
// arrow beside it wherever a place beside holds it, before it is drawn straight on or with a
// break.
ArrowShape arrowBesideOrInRoom(const ArrowShape& shape, double room_px, double hidden_px,
                               const BodyModel& body, const PanelModel& panel,
                               const FrameLayout& layout, const WorldToPixel& to_px);

// 2D: the arrow of `body` whose drawn minimum from the centre, `mark` (under scale: a head beyond
// its first hidden_px, which are under the body), would say "below scale". Where its true length
// reads (a head length or more: arrowShape from its tail is not under scale), it is drawn that
// long, on its scale: from the body's edge where its motion leaves the body
// (ArrowShape::tail_ahead_px), where nothing is in its way there and it stays in the panel's view;
// else beside the body (arrowBesideOrInRoom's places; first where BodyModel::arrow_beside_first);
// else not at all, its value in its readout.
// Too short to read: the mark, where the room straight on holds it (arrowInRoom).
ArrowShape arrowReadingOrMark(const ArrowShape& mark, double room_px, double hidden_px,
                              const BodyModel& body, const PanelModel& panel,
                              const FrameLayout& layout, const WorldToPixel& to_px);

// `shape`, a 2D arrow whose first hidden_px are under its body, where it is longer than room_px:
// drawn that long, off the scale (a break in its shaft just past the body, its value in its
// readout) where the room holds hidden_px, the break and a head; else no arrow (zero length), its
// value in its readout. Never drawn through what stops it.
ArrowShape arrowInRoom(const ArrowShape& shape, double room_px, double hidden_px,
                       const FrameLayout& layout);

}  // namespace collide::frame
