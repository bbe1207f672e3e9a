#include "render/vector/vector_painter.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <cctype>
#include <map>
#include <memory>
#include <string_view>
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

// Where the next id or reference to an id `prefix`N (N: digits) begins at or after `from`, at
// its prefix: written by Cairo as id="surface1", xlink:href="#surface1" or url(#surface1), inside
// a tag. Text never matches: it holds no '<' or '>' of its own (escaped).
std::size_t findNumberedId(const std::string& document, std::string_view prefix, std::size_t from) {
  for (std::size_t at = from; (at = document.find(prefix, at)) != std::string::npos; ++at) {
    if (at == 0 || (document[at - 1] != '"' && document[at - 1] != '#')) continue;
    const std::size_t bracket = document.find_last_of("<>", at);
    if (bracket == std::string::npos || document[bracket] != '<') continue;
    std::size_t end = at + prefix.size();
    while (end < document.size() && std::isdigit(static_cast<unsigned char>(document[end]))) ++end;
    if (end > at + prefix.size() && end < document.size() &&
        (document[end] == '"' || document[end] == ')')) {
      return at;
    }
  }
  return std::string::npos;
}

// Cairo numbers an SVG's surfaces (and images, which figures have none of) with counters of the
// whole process, so a figure drawn after others had other ids (surface16 for surface1). The ids
// `prefix`N are renumbered from 1 in order of first appearance: the bytes depend on the document
// alone.
std::string numberIdsInOrder(const std::string& document, std::string_view prefix) {
  std::map<std::string, std::string> renamed;
  std::string out;
  std::size_t copied = 0;
  for (std::size_t at; (at = findNumberedId(document, prefix, copied)) != std::string::npos;) {
    std::size_t end = at + prefix.size();
    while (std::isdigit(static_cast<unsigned char>(document[end]))) ++end;
    const std::string old_number = document.substr(at + prefix.size(), end - at - prefix.size());
    const auto [entry, added] = renamed.try_emplace(old_number, "");
    if (added) entry->second = std::to_string(renamed.size());
    out.append(document, copied, at + prefix.size() - copied);
    out += entry->second;
    copied = end;
  }
  out.append(document, copied, std::string::npos);
  return out;
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
  return declareLanguage(numberIdsInOrder(text.finishSvg(bytes), "surface"), frame.lang);
}

}  // namespace collide::render
