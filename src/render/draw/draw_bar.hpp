// SPDX-License-Identifier: MIT
#pragma once
// The energy bar of a panel (draw_bar.cpp): its frame, its parts and strips, and its legend
// entries with their leaders, drawn into the panel's bar place.
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "render/draw/canvas.hpp"

namespace collide::render {

// The bar of `where` (bar_outer, bar_inner) and its legend under it.
void drawBar(const frame::EnergyBar& bar, const frame::FrameStyle& style,
             const frame::PanelLayout& where, const frame::FrameLayout& layout, Canvas& canvas);

}  // namespace collide::render
