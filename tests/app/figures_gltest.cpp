// Figures for print (issue 20) through the real binary: SVG and PDF stills rasterised and compared
// with the GL still, the PDF's text, the SVG's bodies and energy bar, physical page sizes, the PNG
// resolution chunk, the LaTeX/Markdown bundle, batch formats, and bad input refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>

#include "frame/layout.hpp"
#include "png_io.hpp"
#include "scratch.hpp"
#include "svg_positions.hpp"
#include "svg_shapes.hpp"

namespace collide {
namespace {

constexpr double kMmPerPt = 25.4 / 72.0;

class FiguresGLTest : public ::testing::Test {
 protected:
  test::ScratchDir dir{"collide-figures-"};

  // Runs collide with `args`; stdout and stderr go to files in the scratch directory.
  int collide(const std::string& args) {
    return test::runShellBounded(test::shellQuoted(COLLIDE_BINARY) + " " + args + " >" +
                                 dir.shellFile("out.txt") + " 2>" + dir.shellFile("err.txt"));
  }
  int tool(const std::string& command) {
    return test::runShellBounded(command + " >" + dir.shellFile("tool.txt") + " 2>&1");
  }
  std::string still(const std::string& name, const std::string& extra = "",
                    const std::string& size = "640x360") {
    const std::string path = dir.file(name);
    EXPECT_EQ(collide("still worked-example --at 2.5 --size " + size + " -o " +
                      test::shellQuoted(path) + " " + extra),
              0)
        << test::readFileBytes(dir.file("err.txt"));
    return path;
  }
};

// Share of pixels where some channel differs by more than 16/255.
double differingShare(const core::Image& a, const core::Image& b) {
  EXPECT_EQ(a.width(), b.width());
  EXPECT_EQ(a.height(), b.height());
  if (a.width() != b.width() || a.height() != b.height()) return 1.0;
  long differing = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      for (int c = 0; c < 3; ++c) {
        if (std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])) > 16) {
          ++differing;
          break;
        }
      }
    }
  }
  return double(differing) / (double(a.width()) * a.height());
}

TEST_F(FiguresGLTest, SvgAndPdfLookLikeTheGlStill) {
  // The default size and Full HD, as for slides. The GL painter's text is hinted (glyphs snapped
  // to whole pixels up and down), vector text is not: at 640x360 a hinted edge is 2% of all
  // pixels, from 1280x720 up under 1%. A page of W × H CSS pixels at 96 dpi is the GL still's
  // size. The PDF is rasterised by poppler's Cairo renderer, the SVG by librsvg. A line's string
  // carries one x per character, which librsvg 2.54 does not read (it lays the string out itself
  // from the first, within a pixel of the layout): it is given each character on its own, as a
  // viewer that reads the lists draws them. As it stands, the share is printed.
  for (const std::string size : {"1280x720", "1920x1080"}) {
    SCOPED_TRACE(size);
    const core::Image gl = test::readPng(still("fig.png", "", size));
    const std::string pdf = still("fig.pdf", "", size), svg = still("fig.svg", "", size);
    // The title is one string in the file, as a search finds it.
    EXPECT_NE(test::readFileBytes(svg).find(">Inelastic collision, e = 0.5</tspan>"),
              std::string::npos);
    ASSERT_EQ(tool("pdftocairo -r 96 -png -singlefile " + test::shellQuoted(pdf) + " " +
                   dir.shellFile("pdf")),
              0);
    const std::string placed = test::withEachCharacterPlaced(test::readFileBytes(svg));
    ASSERT_FALSE(placed.empty());
    std::ofstream(dir.file("placed.svg"), std::ios::binary) << placed;
    ASSERT_EQ(
        tool("rsvg-convert -o " + dir.shellFile("svg.png") + " " + dir.shellFile("placed.svg")), 0);
    ASSERT_EQ(tool("rsvg-convert -o " + dir.shellFile("raw.png") + " " + test::shellQuoted(svg)),
              0);
    const double pdf_share = differingShare(gl, test::readPng(dir.file("pdf.png")));
    const double svg_share = differingShare(gl, test::readPng(dir.file("svg.png")));
    const double raw_share = differingShare(gl, test::readPng(dir.file("raw.png")));
    EXPECT_LE(pdf_share, 0.01);
    EXPECT_LE(svg_share, 0.01);
    std::printf("%s: pixels beyond 16/255: PDF %.3f%%, SVG %.3f%% (librsvg's own layout %.3f%%)\n",
                size.c_str(), 100 * pdf_share, 100 * svg_share, 100 * raw_share);
  }
}

// Text with every space removed: pdftotext may part a subscript from its letter ("m ₂").
std::string squeezed(std::string text) {
  text.erase(std::remove_if(text.begin(), text.end(), [](char c) { return std::isspace(c); }),
             text.end());
  return text;
}

TEST_F(FiguresGLTest, PdfKeepsTheTitleAndLabelsAsText) {
  const std::string pdf = still("fig.pdf");
  ASSERT_EQ(tool("pdftotext " + test::shellQuoted(pdf) + " " + dir.shellFile("fig.txt")), 0);
  const std::string text = squeezed(test::readFileBytes(dir.file("fig.txt")));
  // 1 kg at +2 m/s meets 1 kg at −1 m/s, e = 0.5: v₁′ = (m₁ − e·m₂)v₁ + (1 + e)m₂v₂)/(m₁ + m₂)
  // = (0.5·2 − 1.5)/2 = −0.25 m/s and v₂′ = (1.5·2 − 0.5)/2 = +1.25 m/s.
  for (const std::string label :
       {"Inelastic collision, e = 0.5", "t = 2.500 s", "m₁ = 1.00 kg", "m₂ = 1.00 kg",
        "v₁′ = −0.250 m/s", "v₂′ = +1.25 m/s", "lost 1.69 J"}) {
    EXPECT_NE(text.find(squeezed(label)), std::string::npos) << label;
  }
  ASSERT_EQ(tool("pdffonts " + test::shellQuoted(pdf)), 0);
  EXPECT_NE(test::readFileBytes(dir.file("tool.txt")).find("DejaVuSans"), std::string::npos);
}

TEST_F(FiguresGLTest, SvgKeepsTheTitleAndLabelsAsSelectableText) {
  const std::optional<test::SvgDocument> svg = test::readSvg(test::readFileBytes(still("fig.svg")));
  ASSERT_TRUE(svg.has_value());
  EXPECT_EQ(svg->glyph_outlines, 0);  // every glyph is in a <text>, none drawn as a shape
  // Each line is one <text> element holding exactly its characters (the values are derived in
  // PdfKeepsTheTitleAndLabelsAsText above).
  for (const std::string label : {"Inelastic collision, e = 0.5", "t = 2.500 s", "m₁ = 1.00 kg",
                                  "m₂ = 1.00 kg", "v₁′ = −0.250 m/s", "v₂′ = +1.25 m/s"}) {
    const auto match = std::find_if(svg->texts.begin(), svg->texts.end(),
                                    [&](const test::SvgText& t) { return t.content == label; });
    ASSERT_NE(match, svg->texts.end()) << label;
    EXPECT_NE(match->font_family.find("DejaVu Sans"), std::string::npos) << match->font_family;
  }
  const auto lost = std::find_if(svg->texts.begin(), svg->texts.end(), [](const test::SvgText& t) {
    return t.content.find("lost 1.69 J") != std::string::npos;
  });
  EXPECT_NE(lost, svg->texts.end());
  // The strobe and the chart carry their text alike.
  for (const std::string& kind : {std::string("strobe"), std::string("chart")}) {
    const std::string path = dir.file(kind + ".svg");
    ASSERT_EQ(collide(kind + " worked-example -o " + test::shellQuoted(path)), 0)
        << test::readFileBytes(dir.file("err.txt"));
    const std::optional<test::SvgDocument> figure = test::readSvg(test::readFileBytes(path));
    ASSERT_TRUE(figure.has_value());
    EXPECT_EQ(figure->glyph_outlines, 0) << kind;
    EXPECT_TRUE(std::any_of(figure->texts.begin(), figure->texts.end(), [](const test::SvgText& t) {
      return t.content == "Inelastic collision, e = 0.5";
    })) << kind;
  }
}

TEST_F(FiguresGLTest, SvgHasOneElementPerBodyAndTheBarInProportion) {
  const std::optional<test::SvgDocument> svg = test::readSvg(test::readFileBytes(still("fig.svg")));
  ASSERT_TRUE(svg.has_value());
  // Bodies are the only shapes both filled and outlined.
  int bodies = 0;
  for (const test::SvgShape& shape : svg->shapes) bodies += shape.fill && shape.stroke ? 1 : 0;
  EXPECT_EQ(bodies, 2);

  // The bar's inside, in points (the layout's pixels at 96 per inch), from the shared layout of
  // a one-panel frame.
  const double pt_per_px = 0.75;
  const frame::PixelRect inner =
      frame::computeFrameLayout(640, 360, frame::FrameShape{1, 1, 0, 1.0, 0.0}).panel().bar_inner;
  std::vector<test::SvgShape> segments;
  for (const test::SvgShape& shape : svg->shapes) {
    if (shape.fill && !shape.stroke && shape.y0 >= inner.y0 * pt_per_px - 1e-3 &&
        shape.y1 <= inner.y1 * pt_per_px + 1e-3 && shape.x0 >= inner.x0 * pt_per_px - 1e-3) {
      segments.push_back(shape);
    }
  }
  ASSERT_EQ(segments.size(), 3u);
  std::sort(segments.begin(), segments.end(),
            [](const auto& a, const auto& b) { return a.x0 < b.x0; });
  // After the collision: KE₁ = ½·1·0.25² = 0.03125 J, KE₂ = ½·1·1.25² = 0.78125 J, lost
  // ½·μ·(1 − e²)·u² = ½·0.5·0.75·3² = 1.6875 J, of the 2.5 J at the start (the bar's full width).
  const double full_J = 0.5 * 1 * 2 * 2 + 0.5 * 1 * 1 * 1;
  const double energies_J[3] = {0.5 * 0.25 * 0.25, 0.5 * 1.25 * 1.25, 0.5 * 0.5 * 0.75 * 9.0};
  for (int i = 0; i < 3; ++i) {
    const double expected = inner.width() * pt_per_px * energies_J[i] / full_J;
    EXPECT_NEAR(segments[i].x1 - segments[i].x0, expected, 0.005 * expected) << "segment " << i;
  }
}

TEST_F(FiguresGLTest, PrintSizeSetsThePageAndThePngResolution) {
  // 8 cm wide at 300 dpi, 3:2 when --size is not given.
  const std::string pdf = dir.file("print.pdf"), svg = dir.file("print.svg");
  const std::string png = dir.file("print.png");
  for (const std::string& path : {pdf, svg, png}) {
    ASSERT_EQ(
        collide("still worked-example --at 2.5 --print 8cm@300 -o " + test::shellQuoted(path)), 0)
        << test::readFileBytes(dir.file("err.txt"));
  }
  ASSERT_EQ(tool("pdfinfo " + test::shellQuoted(pdf)), 0);
  std::smatch match;
  const std::string info = test::readFileBytes(dir.file("tool.txt"));
  ASSERT_TRUE(
      std::regex_search(info, match, std::regex(R"(Page size:\s+([0-9.]+) x ([0-9.]+) pts)")));
  EXPECT_NEAR(std::stod(match[1]) * kMmPerPt, 80.0, 0.1);
  EXPECT_NEAR(std::stod(match[2]) * kMmPerPt, 80.0 * 2.0 / 3.0, 0.1);

  const std::optional<test::SvgDocument> doc = test::readSvg(test::readFileBytes(svg));
  ASSERT_TRUE(doc.has_value());
  ASSERT_EQ(doc->width.substr(doc->width.size() - 2), "pt");
  EXPECT_NEAR(std::stod(doc->width) * kMmPerPt, 80.0, 0.1);
  EXPECT_NEAR(std::stod(doc->height) * kMmPerPt, 80.0 * 2.0 / 3.0, 0.1);

  // 8 cm at 300 dpi = 944.9 px; 300 dpi = 11811 px/m.
  const core::Image image = test::readPng(png);
  EXPECT_EQ(image.width(), 945);
  EXPECT_EQ(image.height(), 630);
  EXPECT_EQ(test::readPngPixelsPerMetre(png), (std::pair<unsigned, unsigned>{11811, 11811}));
}

TEST_F(FiguresGLTest, LatexAndMarkdownBundlesNameThePictureCaptionAndAltText) {
  const std::string pdf = still("lesson.pdf", "--print 8cm --latex --markdown");
  const std::string tex = test::readFileBytes(dir.file("lesson.tex"));
  const std::string alt = test::readFileBytes(dir.file("lesson.alt.txt"));
  ASSERT_FALSE(alt.empty());
  EXPECT_NE(tex.find("\\includegraphics[width=8cm]{lesson.pdf}"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\caption{Inelastic collision, e = 0.5, at t = 2.500 s.}"), std::string::npos)
      << tex;
  EXPECT_NE(tex.find("\\label{fig:lesson}"), std::string::npos);
  EXPECT_NE(tex.find("% Alt text: " + alt.substr(0, alt.size() - 1)), std::string::npos);
  const std::string md = test::readFileBytes(dir.file("lesson.md"));
  EXPECT_EQ(md.rfind("![" + alt.substr(0, 40), 0), 0u) << md;
  EXPECT_NE(md.find("](lesson.pdf \"Inelastic collision, e = 0.5, at t = 2.500 s.\")"),
            std::string::npos)
      << md;
}

TEST_F(FiguresGLTest, StrobeChartAndBatchWriteVectorFigures) {
  ASSERT_EQ(collide("strobe worked-example -o " + dir.shellFile("strobe.svg")), 0);
  ASSERT_TRUE(test::readSvg(test::readFileBytes(dir.file("strobe.svg"))).has_value());
  ASSERT_EQ(collide("chart worked-example -o " + dir.shellFile("chart.pdf")), 0);
  EXPECT_EQ(test::readFileBytes(dir.file("chart.pdf")).rfind("%PDF-", 0), 0u);
  ASSERT_EQ(collide("batch worked-example --formats svg,pdf -o " + dir.shellFile("batch/")), 0)
      << test::readFileBytes(dir.file("err.txt"));
  EXPECT_TRUE(test::readSvg(test::readFileBytes(dir.file("batch/worked-example.svg"))).has_value());
  EXPECT_EQ(test::readFileBytes(dir.file("batch/worked-example.pdf")).rfind("%PDF-", 0), 0u);
}

TEST_F(FiguresGLTest, BadPrintInputIsRefusedInOneLineAndWritesNothing) {
  const std::string target = dir.file("bad.pdf");
  for (const std::string& args :
       {"still worked-example --at 1 --print -8cm@300 -o " + test::shellQuoted(target),
        "still worked-example --at 1 --width-cm -3 -o " + test::shellQuoted(target),
        "still worked-example --at 1 --print 8cm@0 -o " + test::shellQuoted(target),
        "still worked-example --at 1 --dpi 0 -o " + test::shellQuoted(target),
        "still worked-example --at 1 --dpi 2401 -o " + test::shellQuoted(target),
        "strobe worked-example --print 8cm@2401 -o " + test::shellQuoted(target),
        "still worked-example --at 1 --print 8furlongs -o " + test::shellQuoted(target),
        "render worked-example -o " + test::shellQuoted(target)}) {
    EXPECT_EQ(collide(args), 2) << args;
    const std::string err = test::readFileBytes(dir.file("err.txt"));
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << args << ": " << err;
    EXPECT_FALSE(std::filesystem::exists(target)) << args;
  }
  std::size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    const std::string name = entry.path().filename().string();
    entries += name == "out.txt" || name == "err.txt" ? 0 : 1;
  }
  EXPECT_EQ(entries, 0u);
}

// pi-blocks after the first hit: the big block moves at 1 m/s in a picture scaled for the small
// one's 100 m/s, so its arrow is shorter than a head. It is drawn as a smaller arrow of the same
// shape (at most as much wider than long as a full head: 0.04 / 0.035 of the frame height), never
// a full-width head squeezed into a sliver that reads as an empty leader line.
TEST_F(FiguresGLTest, ArrowsShorterThanTheirHeadKeepTheirShape) {
  const std::string path = dir.file("pi.svg");
  ASSERT_EQ(collide("still pi-blocks --at 1.4 --size 640x360 -o " + test::shellQuoted(path)), 0)
      << test::readFileBytes(dir.file("err.txt"));
  const std::optional<test::SvgDocument> svg = test::readSvg(test::readFileBytes(path));
  ASSERT_TRUE(svg.has_value());
  // Arrows are the only filled, unstroked shapes in the arrow grey (0.12).
  int arrows = 0;
  for (const test::SvgShape& shape : svg->shapes) {
    if (!shape.fill || shape.stroke || std::abs(shape.fill->r - 0.12) > 0.01 ||
        std::abs(shape.fill->g - 0.12) > 0.01) {
      continue;
    }
    const double along = shape.x1 - shape.x0, across = shape.y1 - shape.y0;
    EXPECT_LE(across, 1.2 * along + 0.5) << along << " x " << across;
    ++arrows;
  }
  EXPECT_EQ(arrows, 3);  // both blocks move; and the scale arrow at the caption line's end
}

}  // namespace
}  // namespace collide
