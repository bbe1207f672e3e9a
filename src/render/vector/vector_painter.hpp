#pragma once
// Vector figures (SVG, PDF) of a FrameModel for print and slides. They are laid out by the same
// code as the GL renderer's frames (frame_drawing.hpp) and painted with Cairo: exact shapes
// (circles as arcs), the GL output's colours, and text as text in the frame's font: subset and
// embedded in a PDF, <text> elements naming the font's family in an SVG (a viewer needs the font,
// DejaVu Sans, installed to show it alike; every glyph is placed, so another font keeps the
// layout). Either can be selected, searched and read aloud. Cairo stays private: this header
// includes none of it.
#include <string>

#include "frame/frame_model.hpp"
#include "render/text/script_fonts.hpp"

namespace collide::render {

enum class VectorFormat { kSvg, kPdf };

struct VectorFigureOptions {
  VectorFormat format = VectorFormat::kPdf;
  int width_px = 1280;  // the frame is laid out at this size, as the GL renderer would (> 0)
  int height_px = 720;
  // How large a layout pixel is on the page: 96 (CSS pixels) for a figure of screen size, the
  // printing resolution for a figure of physical size. The page is width_px / px_per_inch wide.
  double px_per_inch = 96.0;
  double text_floor_px = 0.0;  // printed figures: frame::printTextFloorPx(px_per_inch); 0: none
  std::string font_path;       // TrueType/OpenType file for all text; empty: defaultFontPath()
  // The fonts and direction of the language text is in (font_path first). Empty: those of the
  // active language (text/language.hpp), resolved where the figure is asked for (the vector
  // module keeps its own copy of the active language, as the GL module does).
  TextFonts text_fonts;
  std::string title;    // PDF document information
  std::string subject;  // PDF document information, e.g. the figure's alt text
};

// The page size in points (1/72 inch).
double vectorPageWidthPt(const VectorFigureOptions& options);
double vectorPageHeightPt(const VectorFigureOptions& options);

// The figure as the bytes of an SVG document or a one-page PDF. Throws FontError if the font
// cannot be loaded, RenderError if Cairo fails.
std::string paintVectorFigure(const frame::FrameModel& frame, const VectorFigureOptions& options);

}  // namespace collide::render
