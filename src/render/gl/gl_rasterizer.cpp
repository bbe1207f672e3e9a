#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/image.hpp"
#include "core/stale_rects.hpp"
#include "render/backend.hpp"
#include "render/draw/canvas.hpp"
#include "render/draw/frame_drawing.hpp"
#include "render/draw/repaint_regions.hpp"
#include "render/gl/canvas_painter.hpp"
#include "render/gl/compiler_pages.hpp"
#include "render/gl/frame_rasterizer.hpp"
#include "render/gl/framebuffers.hpp"
#include "render/gl/gl.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/text.hpp"

namespace collide::render {
namespace {

// Readback holds premultiplied colour; a translucent background needs straight alpha back.
void unpremultiply(std::vector<std::uint8_t>& pixels) {
  for (std::size_t i = 0; i + 3 < pixels.size(); i += 4) {
    const unsigned a = pixels[i + 3];
    if (a == 0 || a == 255) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      const unsigned straight = (pixels[i + c] * 255u + a / 2) / a;
      pixels[i + c] = static_cast<std::uint8_t>(straight > 255u ? 255u : straight);
    }
  }
}

std::string glString(GLenum name) {
  const auto* text = reinterpret_cast<const char*>(glGetString(name));
  return text != nullptr ? text : "";
}

// A frame's changes are drawn in at most this many clipped passes: each pass sets up every
// primitive again (llvmpipe culls those outside it), so a few larger regions beat many small.
constexpr std::size_t kMaxRegions = 4;

// Everything one GL context needs to draw frames of one size.
class GlRasterizer final : public FrameRasterizer {
 public:
  // Declared first so it is destroyed last: every GL object below dies while it is alive.
  std::unique_ptr<GlContext> context;
  int width_px;
  int height_px;
  double text_floor_px;
  std::string renderer_name;
  FontSet fonts;
  GlyphAtlas atlas{fonts};
  TextPainter painter{atlas};
  MeshCanvas canvas{painter};
  std::unique_ptr<CanvasPainter> canvas_painter;
  std::unique_ptr<Framebuffers> framebuffers;
  // Frames are read back into these in turn (bottom row first), so a frame stays whole while the
  // next one is drawn and read: the video path converts it on another thread meanwhile. A still
  // draws one frame and touches only the first.
  std::vector<std::uint8_t> readbacks[2];
  long frames_drawn = 0;
  CompilerPageKeeper compiler_pages;
  // The frame the framebuffer holds, to draw only what the next one changes (repaint_regions.hpp);
  // none: it holds something else, the next frame is drawn whole.
  bool repaint_changes_only;
  std::optional<CanvasRecord> framebuffer_holds;
  frame::Rgba held_background;
  std::vector<frame::PixelRect> regions;
  // The rectangles (top row 0) each readback buffer must read again: those drawn since it was
  // last read. Its other pixels still hold what the framebuffer holds.
  core::StaleRects stale[2];
  // The rectangles the last frame drew (top row 0), valid where changed_rects_known.
  std::vector<core::ImageRect> changed_rects;
  bool changed_rects_known = false;

  std::string glRendererName() const override { return renderer_name; }

  const std::vector<core::ImageRect>* changedRects() const override {
    return changed_rects_known ? &changed_rects : nullptr;
  }

  // Notes the regions drawn (none: the whole frame) as changedRects() gives them, and as stale in
  // both readback buffers.
  void noteChanged(const std::vector<frame::PixelRect>* drawn) {
    changed_rects.clear();
    changed_rects_known = drawn != nullptr;
    if (drawn != nullptr) {
      // changedRegions() gives whole pixels inside the frame.
      for (const frame::PixelRect& r : *drawn) {
        changed_rects.push_back({static_cast<int>(r.x0), static_cast<int>(r.y0),
                                 static_cast<int>(r.x1), static_cast<int>(r.y1)});
      }
      core::joinOverlapping(changed_rects);
    }
    for (core::StaleRects& buffer : stale) buffer.note(changedRects());
  }

  static std::unique_ptr<GlContext> current(std::unique_ptr<GlContext> ctx) {
    ctx->makeCurrent();  // before any member below touches GL
    return ctx;
  }

  GlRasterizer(std::unique_ptr<GlContext> ctx, int w, int h, const RendererOptions& options)
      : context(current(std::move(ctx))),
        width_px(w),
        height_px(h),
        text_floor_px(options.text_floor_px),
        fonts(options.text_fonts),
        repaint_changes_only(options.repaint_changes_only) {
    renderer_name = glString(GL_RENDERER);
    canvas_painter = std::make_unique<CanvasPainter>(atlas);
    framebuffers = std::make_unique<Framebuffers>(w, h);
  }

  ~GlRasterizer() override {
    // GL objects belong to this context; if it cannot be made current they die with it anyway.
    try {
      context->makeCurrent();
    } catch (const RenderError&) {
      // Deleting now would hit whichever context is current; leak the handles instead (they die
      // with the context).
      static_cast<void>(framebuffers.release());
      static_cast<void>(canvas_painter.release());
      return;
    }
    framebuffers.reset();
    canvas_painter.reset();
  }

  // Draws one shape of every kind, clipped and not, and a line of text into the framebuffer (the
  // frame is already read back; the next one clears it), so llvmpipe compiles each shader variant
  // now rather than when it first appears: a worked example's first contact, seconds in, compiled
  // one and touched LLVM's pages again at the time the encoder held the most memory.
  void compileEveryShader() {
    MeshCanvas warm{painter};
    const frame::Rgba grey{0.5f, 0.5f, 0.5f, 0.75f};
    for (const std::optional<frame::PixelRect>& clip :
         {std::optional<frame::PixelRect>(),
          std::optional<frame::PixelRect>(frame::PixelRect{0.0, 0.0, 32.0, 32.0})}) {
      warm.beginBatch(clip);
      ShapeSink& shapes = warm.shapes();
      shapes.addTriangle({1.0, 1.0}, {9.0, 1.0}, {1.0, 9.0}, grey);
      shapes.addRect({2.0, 2.0, 12.0, 8.0}, grey);
      shapes.addRectFrame({2.0, 2.0, 12.0, 8.0}, 1.5, grey);
      shapes.addDisk({8.0, 8.0}, 4.0, grey);
      shapes.addRing({8.0, 8.0}, 5.0, 3.0, grey);
      shapes.addSector({8.0, 8.0}, 5.0, 0.0, 1.0, grey);
      shapes.addArrow({2.0, 12.0}, {1.0, 0.0}, 20.0, 2.0, 5.0, 5.0, grey);
      shapes.addLine({1.0, 20.0}, {20.0, 24.0}, 1.5, grey);
      shapes.addPolyline({{1.0, 26.0}, {10.0, 28.0}, {20.0, 26.0}}, 1.5, grey, 3.0);
      shapes.addPolyline({{1.0, 30.0}, {10.0, 31.0}, {20.0, 30.0}}, 1.5,
                         std::vector<frame::Rgba>{grey, grey});
      warm.text("0.5 m/s", {2.0, 30.0}, 12.0, grey);
    }
    warm.finish();
    framebuffers->bindForDrawing();
    canvas_painter->paint(warm, width_px, height_px, frame::Rgba{1.0f, 1.0f, 1.0f, 1.0f});
    // And once in a region, as a frame drawn where it changed is: its background box.
    const std::vector<frame::PixelRect> region{frame::PixelRect{0.0, 0.0, 32.0, 32.0}};
    canvas_painter->paint(warm, width_px, height_px, frame::Rgba{1.0f, 1.0f, 1.0f, 1.0f}, &region);
    glFinish();
    framebuffer_holds.reset();
  }

  // Draws the canvas: only where it differs from the frame the framebuffer holds, if it holds one
  // drawn over the same background, else whole. New glyphs need no whole frame: they go into
  // texels no quad of an earlier glyph reads (a glyph stays where it was placed, with a texel of
  // padding that stays empty; growing appends rows: glyph_atlas.cpp), so an unchanged quad draws
  // the same pixels.
  // Returns the regions drawn, or none for the whole frame.
  const std::vector<frame::PixelRect>* paint(const frame::Rgba& background) {
    const bool same_ground = framebuffer_holds && held_background.r == background.r &&
                             held_background.g == background.g &&
                             held_background.b == background.b && held_background.a == background.a;
    const std::vector<frame::PixelRect>* drawn = nullptr;
    if (same_ground) {
      regions = changedRegions(*framebuffer_holds, canvas, width_px, height_px, kMaxRegions);
      if (!regions.empty()) {
        canvas_painter->paint(canvas, width_px, height_px, background, &regions);
      }
      drawn = &regions;
    } else {
      canvas_painter->paint(canvas, width_px, height_px, background);
    }
    if (repaint_changes_only) {
      if (!framebuffer_holds) framebuffer_holds.emplace();
      framebuffer_holds->keep(canvas);
      held_background = background;
    }
    return drawn;
  }

  // Reads the frame into `readback`: only the rectangles drawn since that buffer was last read,
  // unless it must be read whole (its first use, a whole frame drawn, or a translucent background,
  // whose pixels are converted in place after reading).
  void readInto(int buffer, bool translucent) {
    // Two frames' regions, mostly overlapping, joined: each pixel read once.
    const std::vector<core::ImageRect>* rects = stale[buffer].take();
    std::vector<std::uint8_t>& readback = readbacks[buffer];
    if (rects == nullptr || translucent) {
      framebuffers->read(readback);
      if (translucent) unpremultiply(readback);
    } else {
      for (const core::ImageRect& r : *rects) {
        // GL counts rows from the bottom.
        framebuffers->readRect(readback, r.x0, height_px - r.y1, r.x1 - r.x0, r.y1 - r.y0);
      }
    }
    // Converted in place: read whole again next time.
    if (translucent) stale[buffer].markWhole();
  }

  core::ImageView render(const frame::FrameModel& frame) override {
    context->makeCurrent();
    const frame::FrameLayout layout = frame::layoutFrame(
        frame, width_px, height_px, text_floor_px,
        [this](std::string_view text, double size) { return canvas.painter().width(text, size); });
    drawFrame(frame, layout, canvas);

    framebuffers->bindForDrawing();
    const std::vector<frame::PixelRect>* drawn = paint(frame.style.background);
    const int buffer = static_cast<int>(frames_drawn % 2);
    noteChanged(drawn);
    readInto(buffer, frame.style.background.a < 1.0f);
    std::vector<std::uint8_t>& readback = readbacks[buffer];
    // A second frame means a video: every shader it can need is compiled now, and LLVM's pages
    // go, before the encoder's lookahead has filled (a still draws one frame and pays nothing).
    if (++frames_drawn == 2) compileEveryShader();
    compiler_pages.afterFrame();

    const std::ptrdiff_t row_bytes = static_cast<std::ptrdiff_t>(width_px) * 4;
    return core::ImageView{readback.data() + row_bytes * (height_px - 1), width_px, height_px,
                           -row_bytes};
  }
};

}  // namespace

std::unique_ptr<FrameRasterizer> makeGlRasterizer(std::unique_ptr<GlContext> context, int width_px,
                                                  int height_px, const RendererOptions& options) {
  COLLIDE_ASSERT(context != nullptr, "no GL context given");
  COLLIDE_ASSERT(width_px > 0 && height_px > 0, "frame size must be positive (validate input)");
  COLLIDE_ASSERT(!options.font_path.empty() && !options.text_fonts.files.empty(),
                 "the caller resolves the default font and the language's fonts");
  return std::make_unique<GlRasterizer>(std::move(context), width_px, height_px, options);
}

}  // namespace collide::render
