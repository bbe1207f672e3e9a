// The vector painter (SVG, PDF) against the shared layout: bodies as single elements, bar
// segments where layout.hpp says, the page as large as asked, text sizes that follow it.
#include "render/vector/vector_painter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "frame/layout.hpp"
#include "frame_models.hpp"
#include "render/gl_context.hpp"
#include "render/vector/pdf_language.hpp"
#include "svg_shapes.hpp"

namespace collide::render {
namespace {

constexpr double kPtPerInch = 72.0;
constexpr double kCmPerInch = 2.54;

VectorFigureOptions screenFigure(VectorFormat format) {
  VectorFigureOptions options;
  options.format = format;
  options.width_px = 640;
  options.height_px = 360;
  return options;
}

TEST(VectorPainterTest, SvgKeepsEachBodyAsOneFilledAndOutlinedElement) {
  const frame::FrameModel frame = testing::labelledBlocks();
  const std::optional<collide::test::SvgDocument> svg =
      collide::test::readSvg(paintVectorFigure(frame, screenFigure(VectorFormat::kSvg)));
  ASSERT_TRUE(svg.has_value());
  const double shade = frame.style.outline_shade;
  for (const frame::BodyModel& body : frame.panels[0].bodies) {
    int elements = 0;
    for (const collide::test::SvgShape& shape : svg->shapes) {
      if (shape.fill && shape.stroke &&
          collide::test::sameColor(*shape.fill, body.fill.r, body.fill.g, body.fill.b) &&
          collide::test::sameColor(*shape.stroke, shade * body.fill.r, shade * body.fill.g,
                                   shade * body.fill.b)) {
        ++elements;
      }
    }
    EXPECT_EQ(elements, 1) << "body with label " << body.label;
  }
}

TEST(VectorPainterTest, SvgBarSegmentsSpanTheirShareOfTheBar) {
  const frame::FrameModel frame = testing::labelledBlocks();
  const VectorFigureOptions options = screenFigure(VectorFormat::kSvg);
  const std::optional<collide::test::SvgDocument> svg =
      collide::test::readSvg(paintVectorFigure(frame, options));
  ASSERT_TRUE(svg.has_value());
  // Where the bar lies, in points (96 layout pixels per inch).
  const double pt_per_px = kPtPerInch / options.px_per_inch;
  const frame::PixelRect inner =
      frame::computeFrameLayout(options.width_px, options.height_px, frame::shapeOf(frame))
          .panel()
          .bar_inner;
  const frame::EnergyBar& bar = frame.panels[0].energy_bar;
  for (const frame::EnergySegment& segment : bar.segments) {
    std::vector<double> widths;
    for (const collide::test::SvgShape& shape : svg->shapes) {
      const bool in_bar = shape.y0 >= inner.y0 * pt_per_px - 1e-3 &&
                          shape.y1 <= inner.y1 * pt_per_px + 1e-3 &&
                          shape.x0 >= inner.x0 * pt_per_px - 1e-3;
      if (in_bar && shape.fill && !shape.stroke &&
          collide::test::sameColor(*shape.fill, segment.color.r, segment.color.g,
                                   segment.color.b)) {
        widths.push_back(shape.x1 - shape.x0);
      }
    }
    ASSERT_EQ(widths.size(), 1u) << segment.label;
    // The whole inner width stands for full_scale_J.
    const double expected = inner.width() * pt_per_px * segment.energy_J / bar.full_scale_J;
    EXPECT_NEAR(widths[0], expected, 0.005 * expected) << segment.label;
  }
}

TEST(VectorPainterTest, SvgWritesEachLineAsEscapedSelectableText) {
  // Characters that XML reserves, in the title and a label, come back as written.
  frame::FrameModel frame = testing::labelledBlocks();
  frame.title = "Ball <A> & \"B\" 'C'";
  frame.panels[0].bodies[0].label = "m₁ < m₂ & e = ½";
  const std::optional<collide::test::SvgDocument> svg =
      collide::test::readSvg(paintVectorFigure(frame, screenFigure(VectorFormat::kSvg)));
  ASSERT_TRUE(svg.has_value());
  EXPECT_EQ(svg->glyph_outlines, 0);  // no glyph is left drawn as a shape
  const auto text = [&](const std::string& content) -> const collide::test::SvgText* {
    for (const collide::test::SvgText& t : svg->texts) {
      if (t.content == content) return &t;
    }
    return nullptr;
  };
  for (const std::string& line : {frame.title, frame.panels[0].bodies[0].label,
                                  frame.panels[0].bodies[1].velocity_label, frame.time_readout}) {
    const collide::test::SvgText* found = text(line);
    ASSERT_NE(found, nullptr) << line;
    EXPECT_NE(found->font_family.find("'DejaVu Sans'"), std::string::npos) << found->font_family;
    // The style's text colour, 0.1 of full scale: 25.5 of 255, to the nearest 8-bit step.
    EXPECT_EQ(found->fill, "#1a1a1a") << line;
  }
  // The title starts at the header's left edge, its baseline inside the header, in points (96
  // layout pixels per inch): the glyph goes to the whole pixel the GL painter uses.
  const double pt_per_px = kPtPerInch / 96.0;
  const frame::PixelRect header = frame::computeFrameLayout(640, 360, frame::shapeOf(frame)).header;
  const collide::test::SvgText* title = text(frame.title);
  ASSERT_NE(title, nullptr);
  EXPECT_NEAR(title->x, header.x0 * pt_per_px, 0.5 * pt_per_px);
  EXPECT_GT(title->y, header.y0 * pt_per_px);
  EXPECT_LT(title->y, header.y1 * pt_per_px);
}

// The MediaBox of a one-page PDF, in points.
std::vector<double> mediaBox(const std::string& pdf) {
  std::smatch match;
  const std::regex box(R"(/MediaBox\s*\[\s*([-0-9.]+)\s+([-0-9.]+)\s+([-0-9.]+)\s+([-0-9.]+))");
  if (!std::regex_search(pdf, match, box)) return {};
  return {std::stod(match[1]), std::stod(match[2]), std::stod(match[3]), std::stod(match[4])};
}

TEST(VectorPainterTest, PdfPageHasThePhysicalSize) {
  // 8 cm wide at 300 dpi, 16:9: the frame is laid out on whole pixels, the page is exact.
  const double width_cm = 8.0, dpi = 300.0;
  VectorFigureOptions options;
  options.format = VectorFormat::kPdf;
  options.width_px = static_cast<int>(std::lround(width_cm / kCmPerInch * dpi));
  options.height_px = static_cast<int>(std::lround(options.width_px * 9.0 / 16.0));
  options.px_per_inch = options.width_px / (width_cm / kCmPerInch);
  options.text_floor_px = frame::printTextFloorPx(dpi);
  const std::string pdf = paintVectorFigure(testing::labelledBlocks(), options);
  ASSERT_EQ(pdf.rfind("%PDF-", 0), 0u);
  const std::vector<double> box = mediaBox(pdf);
  ASSERT_EQ(box.size(), 4u);
  const double mm_per_pt = 25.4 / kPtPerInch;
  EXPECT_NEAR((box[2] - box[0]) * mm_per_pt, 80.0, 0.1);
  EXPECT_NEAR((box[3] - box[1]) * mm_per_pt, 45.0, 0.1);
}

// The number after `key` in `text` from `from` on (0 when absent).
std::size_t pdfNumber(const std::string& text, const std::string& key, std::size_t from) {
  const std::size_t at = text.find(key, from);
  return at == std::string::npos ? 0 : std::stoul(text.substr(at + key.size()));
}

TEST(VectorPainterTest, PdfCatalogueDeclaresTheFramesLanguage) {
  frame::FrameModel frame = testing::labelledBlocks();
  frame.lang = "de";
  VectorFigureOptions options;
  options.format = VectorFormat::kPdf;
  const std::string pdf = paintVectorFigure(frame, options);
  ASSERT_TRUE(pdf.ends_with("%%EOF\n"));
  // Read as a PDF reader does: the last startxref gives the newest cross-reference section, its
  // trailer the catalogue's object number and the older section (/Prev); the section's entry the
  // catalogue's offset, where its newest revision is.
  const std::size_t xref_at = pdfNumber(pdf, "startxref", pdf.rfind("startxref"));
  ASSERT_EQ(pdf.compare(xref_at, 5, "xref\n"), 0);
  const std::size_t trailer = pdf.find("trailer", xref_at);
  const std::size_t root = pdfNumber(pdf, "/Root", trailer);
  const std::size_t previous = pdfNumber(pdf, "/Prev", trailer);
  ASSERT_GT(root, 0u);
  EXPECT_EQ(pdf.compare(previous, 5, "xref\n"), 0);
  const std::string subsection = "xref\n" + std::to_string(root) + " 1\n";
  ASSERT_EQ(pdf.compare(xref_at, subsection.size(), subsection), 0);
  const std::size_t catalogue_at = std::stoul(pdf.substr(xref_at + subsection.size(), 10));
  const std::string object = std::to_string(root) + " 0 obj";
  ASSERT_EQ(pdf.compare(catalogue_at, object.size(), object), 0);
  const std::string catalogue =
      pdf.substr(catalogue_at, pdf.find("endobj", catalogue_at) - catalogue_at);
  EXPECT_NE(catalogue.find("/Type /Catalog"), std::string::npos) << catalogue;
  EXPECT_NE(catalogue.find("/Pages"), std::string::npos) << catalogue;
  EXPECT_NE(catalogue.find("/Lang (de)"), std::string::npos) << catalogue;
  // Cairo's own revision is kept whole before the update.
  EXPECT_LT(previous, catalogue_at);
  EXPECT_EQ(pdf.compare(catalogue_at - 6, 6, "%%EOF\n"), 0);
}

TEST(VectorPainterTest, PdfLanguageRefusesAFileItCannotRead) {
  // No trailer to update: an error (the figure is then not written), never a broken file.
  EXPECT_THROW(declarePdfLanguage("%PDF-1.5\n1 0 obj\n<< >>\nendobj\n", "de"), RenderError);
  EXPECT_THROW(declarePdfLanguage("%PDF-1.5\nstartxref\n3\n%%EOF\n", "de"), RenderError);
  // No language: the file as it was.
  EXPECT_EQ(declarePdfLanguage("%PDF-1.5\n", ""), "%PDF-1.5\n");
}

TEST(VectorPainterTest, PrintedFigureTextStaysLegibleAtItsPhysicalSize) {
  // An 8 cm wide 16:9 figure at 300 dpi: sizes as fractions of the height alone would give
  // 0.041 · 531 px = 22 px = 5.2 pt labels; the floor keeps them at 8.5 pt (to a whole pixel).
  const double dpi = 300.0;
  const int width_px = 945, height_px = 531;
  const frame::FrameModel frame = testing::labelledBlocks();
  const frame::FrameLayout plain =
      frame::computeFrameLayout(width_px, height_px, frame::shapeOf(frame));
  const frame::FrameLayout printed = frame::computeFrameLayout(
      width_px, height_px, frame::shapeOf(frame, frame::printTextFloorPx(dpi)));
  const double pt_per_px = kPtPerInch / dpi;
  EXPECT_LT(plain.text_px * pt_per_px, 6.0);
  EXPECT_GE(printed.text_px * pt_per_px, 8.0);
  EXPECT_LE(printed.text_px * pt_per_px, 9.0);
  // Lines, gaps and the bar grow with the text.
  EXPECT_NEAR(printed.outline_px / plain.outline_px, printed.scale_px / height_px, 1e-9);
  EXPECT_GT(printed.panel().bar_outer.height(), plain.panel().bar_outer.height());
  // A figure large enough to need no floor keeps the screen layout.
  const frame::FrameLayout large =
      frame::computeFrameLayout(3000, 1688, frame::shapeOf(frame, frame::printTextFloorPx(dpi)));
  EXPECT_EQ(large.text_px, frame::computeFrameLayout(3000, 1688, frame::shapeOf(frame)).text_px);
}

TEST(VectorPainterTest, SvgPageIsTheFrameAtNinetySixPixelsPerInch) {
  const std::optional<collide::test::SvgDocument> svg = collide::test::readSvg(
      paintVectorFigure(testing::chartOnly(), screenFigure(VectorFormat::kSvg)));
  ASSERT_TRUE(svg.has_value());
  EXPECT_EQ(svg->width, "480pt");  // 640 px · 72/96
  EXPECT_EQ(svg->height, "270pt");
}

// Cairo numbers an SVG's surfaces with a counter of the whole process; the painter gives the ids
// the document's own numbering, so a figure's bytes do not depend on the figures drawn before it
// (a batch worker draws one job's still after another's).
TEST(VectorPainterTest, SvgBytesDoNotDependOnTheFiguresDrawnBefore) {
  const VectorFigureOptions options = screenFigure(VectorFormat::kSvg);
  const std::string first = paintVectorFigure(testing::labelledBlocks(), options);
  paintVectorFigure(testing::twoDimensional(), options);
  paintVectorFigure(testing::twoBlocks(), screenFigure(VectorFormat::kPdf));
  const std::string again = paintVectorFigure(testing::labelledBlocks(), options);
  EXPECT_TRUE(first == again) << "the same figure, other bytes:\n" << again.substr(0, 400);
  EXPECT_NE(again.find("<g id=\"surface1\">"), std::string::npos) << again.substr(0, 400);
}

}  // namespace
}  // namespace collide::render
