#include "render/vector/vector_painter.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <memory>
#include <utility>

#include "core/error.hpp"
#include "frame/layout.hpp"
#include "render/draw/frame_drawing.hpp"
#include "render/errors.hpp"
#include "render/gl_context.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/text_metrics.hpp"
#include "render/vector/pdf_language.hpp"
#include "render/vector/vector_canvas.hpp"
#include "render/vector/vector_text.hpp"

namespace collide::render {
namespace {

constexpr double kPointsPerInch = 72.0;

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
};

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void check(cairo_status_t status, const char* doing) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw RenderError(std::string("vector figure: ") + doing + ": " +
                      cairo_status_to_string(status));
  }
}

// An SVG's root element with xml:lang, so screen readers and search read its text in the frame's
// language (a PDF's /Lang: declarePdfLanguage).
std::string declareLanguage(std::string document, const std::string& lang) {
  const std::size_t root = document.find("<svg");
  if (document.rfind("<?xml", 0) != 0 || root == std::string::npos || lang.empty()) return document;
  document.insert(root + 4, " xml:lang=\"" + lang + "\"");
  return document;
}

}  // namespace

double vectorPageWidthPt(const VectorFigureOptions& options) {
  return options.width_px * kPointsPerInch / options.px_per_inch;
}

double vectorPageHeightPt(const VectorFigureOptions& options) {
  return options.height_px * kPointsPerInch / options.px_per_inch;
}

std::string paintVectorFigure(const frame::FrameModel& frame, const VectorFigureOptions& options) {
  COLLIDE_ASSERT(options.width_px > 0 && options.height_px > 0 && options.px_per_inch > 0.0,
                 "paintVectorFigure: size and resolution must be positive (validate input)");
  // Text is measured exactly as the GL painter measures it, so both lay the frame out alike.
  const std::string font_path = options.font_path.empty() ? defaultFontPath() : options.font_path;
  const TextFonts text_fonts =
      options.text_fonts.files.empty() ? textFontsFor(font_path) : options.text_fonts;
  FontSet fonts(text_fonts);
  GlyphAtlas atlas(fonts);
  TextPainter painter(atlas);
  const bool svg = options.format == VectorFormat::kSvg;
  VectorText text(text_fonts,
                  svg ? std::optional<double>(kPointsPerInch / options.px_per_inch) : std::nullopt);

  std::string bytes;
  const double width_pt = vectorPageWidthPt(options), height_pt = vectorPageHeightPt(options);
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface(
      svg ? cairo_svg_surface_create_for_stream(appendBytes, &bytes, width_pt, height_pt)
          : cairo_pdf_surface_create_for_stream(appendBytes, &bytes, width_pt, height_pt));
  check(cairo_surface_status(surface.get()), "creating the page");
  if (options.format == VectorFormat::kPdf) {
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, options.title.c_str());
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_SUBJECT,
                                   options.subject.c_str());
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "collide");
  }
  {
    std::unique_ptr<cairo_t, ContextDeleter> cr(cairo_create(surface.get()));
    cairo_scale(cr.get(), kPointsPerInch / options.px_per_inch,
                kPointsPerInch / options.px_per_inch);
    const frame::Rgba& bg = frame.style.background;
    if (bg.a > 0.0f) {
      cairo_set_source_rgba(cr.get(), bg.r, bg.g, bg.b, bg.a);
      cairo_paint(cr.get());
    }
    const frame::FrameLayout layout = frame::layoutFrame(
        frame, options.width_px, options.height_px, options.text_floor_px,
        [&painter](std::string_view line, double size) { return painter.width(line, size); });
    VectorCanvas canvas(painter, cr.get(), text, options.width_px, options.height_px);
    drawFrame(frame, layout, canvas);
    check(cairo_status(cr.get()), "drawing");
  }
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()), "writing");
  if (!svg) return declarePdfLanguage(std::move(bytes), frame.lang);
  return declareLanguage(text.finishSvg(bytes), frame.lang);
}

}  // namespace collide::render
