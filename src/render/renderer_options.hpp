// SPDX-License-Identifier: MIT
#pragma once
// How a Renderer draws: the font, the smallest text, the language's fonts and whether a frame
// repaints only what changed. Its own header so that the rasterizers behind the Renderer
// (render/gl/frame_rasterizer.hpp) need not include the Renderer itself.
#include <string>

#include "render/text/script_fonts.hpp"

namespace collide::render {

struct RendererOptions {
  std::string font_path;  // TrueType/OpenType file for all text; empty: defaultFontPath()
  double text_floor_px =
      0.0;  // printed figures: smallest text em (frame::printTextFloorPx); 0: none
  // The fonts and direction of the language text is in (font_path first). Empty: those of the
  // active language (text/language.hpp), resolved where the Renderer is made (the GL module
  // keeps its own copy of the active language).
  TextFonts text_fonts;
  // Each frame after the first draws only where it differs from the one before, which the
  // framebuffer still holds (render/draw/repaint_regions.hpp): the same pixels for less work. Off:
  // every frame drawn whole (tests compare the two).
  bool repaint_changes_only = true;
};

}  // namespace collide::render
