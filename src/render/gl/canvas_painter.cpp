#include "render/gl/canvas_painter.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "render/gl/gl.hpp"
#include "render/gl/gl_check.hpp"
#include "render/gl/shader_program.hpp"
#include "render/gl/shaders.hpp"
#include "render/text/glyph_atlas.hpp"

namespace collide::render {
namespace {

// A vertex array reading `stride`-byte vertices of float attributes with these component counts
// and byte offsets, from its own buffer.
struct VertexStream {
  unsigned array = 0, buffer = 0;

  VertexStream(std::size_t stride, std::initializer_list<std::pair<int, std::size_t>> attributes) {
    glGenVertexArrays(1, &array);
    glGenBuffers(1, &buffer);
    glBindVertexArray(array);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    GLuint index = 0;
    for (const auto& [components, offset] : attributes) {
      glEnableVertexAttribArray(index);
      glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride),
                            reinterpret_cast<const void*>(offset));
      ++index;
    }
  }
  ~VertexStream() {
    glDeleteBuffers(1, &buffer);
    glDeleteVertexArrays(1, &array);
  }
  VertexStream(const VertexStream&) = delete;
  VertexStream& operator=(const VertexStream&) = delete;

  template <typename V>
  void upload(const std::vector<V>& vertices) const {
    glBindVertexArray(array);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(V)),
                 vertices.data(), GL_STREAM_DRAW);
  }
};

// Which compiled shape program draws a primitive: its kind, and for boxes and disks whether they
// have a hole (a frame, a ring), so that no program computes what its primitives never need. The
// numbers are SHAPE_VARIANT in shaders/shape.frag.
constexpr int kBoxFrameVariant = 7, kRingVariant = 8, kShapeVariants = 9;

int shapeVariant(const Vertex& vertex) {
  const auto kind = static_cast<ShapeKind>(std::lround(vertex.kind));
  if (kind == ShapeKind::kBox && vertex.p1[2] > 0.0f) return kBoxFrameVariant;
  if (kind == ShapeKind::kDisk && vertex.p0[3] > 0.0f) return kRingVariant;
  return static_cast<int>(kind);
}

// One shape program, compiled the first time a frame needs it.
struct ShapeProgram {
  ShaderProgram program;
  int frame_size;

  explicit ShapeProgram(int variant)
      : program(shaders::shape_vert, shaders::shape_frag, "shape",
                "#define SHAPE_VARIANT " + std::to_string(variant) + "\n"),
        frame_size(program.uniformLocation("u_frame_size_px")) {}
};

}  // namespace

// The program that fills a region's pass with the background, and its box.
struct FillProgram {
  ShaderProgram program{shaders::fill_vert, shaders::fill_frag, "fill"};
  int frame_size = program.uniformLocation("u_frame_size_px");
  int color = program.uniformLocation("u_color");
  VertexStream box{2 * sizeof(float), {{2, 0}}};
  int box_width_px = 0, box_height_px = 0;  // the frame `box` was uploaded for
};

struct CanvasPainter::Gl {
  std::unique_ptr<ShapeProgram> shape_programs[kShapeVariants];
  ShaderProgram text_program{shaders::text_vert, shaders::text_frag, "text"};
  int text_frame_size = text_program.uniformLocation("u_frame_size_px");
  int text_atlas = text_program.uniformLocation("u_atlas");
  VertexStream shapes{sizeof(Vertex),
                      {{2, offsetof(Vertex, x_px)},
                       {4, offsetof(Vertex, r)},
                       {1, offsetof(Vertex, kind)},
                       {4, offsetof(Vertex, p0)},
                       {4, offsetof(Vertex, p1)},
                       {4, offsetof(Vertex, p2)}}};
  VertexStream text{sizeof(TextVertex),
                    {{2, offsetof(TextVertex, x_px)},
                     {2, offsetof(TextVertex, u_texel)},
                     {4, offsetof(TextVertex, r)}}};
  // A region's pass starts by filling it with the background: one box over the whole frame (the
  // scissor keeps it inside the region) with a program that only writes a colour. A scissored
  // glClear did the same through llvmpipe's quad of its own, saving and restoring the GL state
  // around it, and cost more CPU than the shapes drawn in a frame's passes; shape.frag's box
  // writes the same pixels but, with its discard, is never opaque to llvmpipe, and cost more still.
  // Made for the first region drawn: a still, drawn whole, never needs it (a program to compile
  // and link, about 1 % of a 720p still's CPU).
  std::unique_ptr<FillProgram> fill;
  unsigned atlas_texture = 0;

  Gl() {
    glGenTextures(1, &atlas_texture);
    glBindTexture(GL_TEXTURE_2D, atlas_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    checkGl("setting up vertex buffers and the glyph atlas");
  }
  ~Gl() { glDeleteTextures(1, &atlas_texture); }

  // Binds the program of `variant` for a frame of `size` pixels.
  void useShapeProgram(int variant, const float (&size)[2]) {
    COLLIDE_ASSERT(variant > 0 && variant < kShapeVariants, "unknown shape kind");
    std::unique_ptr<ShapeProgram>& slot = shape_programs[variant];
    if (!slot) slot = std::make_unique<ShapeProgram>(variant);
    glUseProgram(slot->program.id());
    glUniform2fv(slot->frame_size, 1, size);
  }
};

CanvasPainter::CanvasPainter(const GlyphAtlas& atlas)
    : gl_(std::make_unique<Gl>()), atlas_(atlas) {}

CanvasPainter::~CanvasPainter() = default;

namespace {

void scissor(const std::optional<frame::PixelRect>& clip, int width_px, int height_px) {
  if (!clip) {
    glDisable(GL_SCISSOR_TEST);
    return;
  }
  // Whole pixels covering the rectangle; GL scissor rows count from the bottom.
  const int x0 = std::max(0, static_cast<int>(std::floor(clip->x0)));
  const int x1 = std::min(width_px, static_cast<int>(std::ceil(clip->x1)));
  const int y0 = std::max(0, static_cast<int>(std::floor(clip->y0)));
  const int y1 = std::min(height_px, static_cast<int>(std::ceil(clip->y1)));
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0, height_px - std::max(y0, y1), std::max(0, x1 - x0), std::max(0, y1 - y0));
}

}  // namespace

namespace {

// Whether the quad of six vertices from `quad` may cover a pixel centre inside `clip`: its box
// meets the clip's whole pixels, with a pixel more on each side for the rounding between pixel and
// window coordinates. A quad that does not is left out of a clipped pass: llvmpipe would transform
// and set it up only to find it outside the scissor.
template <typename V>
bool reaches(const V* quad, const frame::PixelRect& clip) {
  float x0 = quad[0].x_px, x1 = x0, y0 = quad[0].y_px, y1 = y0;
  for (int v = 1; v < kVerticesPerShape; ++v) {
    x0 = std::min(x0, quad[v].x_px);
    x1 = std::max(x1, quad[v].x_px);
    y0 = std::min(y0, quad[v].y_px);
    y1 = std::max(y1, quad[v].y_px);
  }
  return x1 >= std::floor(clip.x0) - 1.0 && x0 <= std::ceil(clip.x1) + 1.0 &&
         y1 >= std::floor(clip.y0) - 1.0 && y0 <= std::ceil(clip.y1) + 1.0;
}

// Calls draw(first, end) for each run of consecutive quads in [first, end) that reach `clip`
// (all of them without a clip) and that `same_run` puts together, in order.
template <typename V, typename SameRun, typename Draw>
void drawRuns(const std::vector<V>& vertices, std::size_t first, std::size_t end,
              const std::optional<frame::PixelRect>& clip, SameRun same_run, Draw draw) {
  const auto visible = [&](std::size_t at) { return !clip || reaches(&vertices[at], *clip); };
  while (first < end) {
    if (!visible(first)) {
      first += kVerticesPerShape;
      continue;
    }
    std::size_t last = first + kVerticesPerShape;
    while (last < end && same_run(vertices[first], vertices[last]) && visible(last)) {
      last += kVerticesPerShape;
    }
    draw(first, last);
    first = last;
  }
}

std::optional<frame::PixelRect> intersect(const std::optional<frame::PixelRect>& a,
                                          const frame::PixelRect& b) {
  if (!a) return b;
  return frame::PixelRect{std::max(a->x0, b.x0), std::max(a->y0, b.y0), std::min(a->x1, b.x1),
                          std::min(a->y1, b.y1)};
}

}  // namespace

void CanvasPainter::paint(const MeshCanvas& canvas, int width_px, int height_px,
                          const frame::Rgba& background,
                          const std::vector<frame::PixelRect>* regions) {
  const frame::Rgba& bg = background;
  glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);  // premultiplied, as drawn colours
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);                // premultiplied "over"

  gl_->shapes.upload(canvas.shapeVertices());
  gl_->text.upload(canvas.textVertices());
  glBindTexture(GL_TEXTURE_2D, gl_->atlas_texture);
  if (atlas_.revision() != atlas_revision_) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (atlas_.height() != atlas_height_) {
      glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas_.width(), atlas_.height(), 0, GL_RED,
                   GL_UNSIGNED_BYTE, atlas_.texels().data());
      atlas_height_ = atlas_.height();
    } else {
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, atlas_.width(), atlas_.height(), GL_RED,
                      GL_UNSIGNED_BYTE, atlas_.texels().data());
    }
    atlas_revision_ = atlas_.revision();
  }
  const float size[2] = {static_cast<float>(width_px), static_cast<float>(height_px)};
  glUseProgram(gl_->text_program.id());
  glUniform2fv(gl_->text_frame_size, 1, size);
  glUniform1i(gl_->text_atlas, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, gl_->atlas_texture);

  if (regions == nullptr) {
    drawPass(canvas, width_px, height_px, std::nullopt);
  } else {
    if (!gl_->fill) gl_->fill = std::make_unique<FillProgram>();
    FillProgram& fill = *gl_->fill;
    if (fill.box_width_px != width_px || fill.box_height_px != height_px) {
      // Two triangles reaching a pixel beyond the frame: every pixel centre is inside one.
      const float x0 = -1.0f, y0 = -1.0f;
      const float x1 = static_cast<float>(width_px) + 1.0f;
      const float y1 = static_cast<float>(height_px) + 1.0f;
      fill.box.upload(std::vector<float>{x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
      fill.box_width_px = width_px;
      fill.box_height_px = height_px;
    }
    glUseProgram(fill.program.id());
    glUniform2fv(fill.frame_size, 1, size);
    // The clear colour of a whole frame, so a pass's background pixels are the same bytes.
    const float premultiplied[4] = {bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a};
    glUniform4fv(fill.color, 1, premultiplied);
    for (const frame::PixelRect& region : *regions) drawPass(canvas, width_px, height_px, region);
  }
  glDisable(GL_SCISSOR_TEST);
  checkGl("drawing a frame");
}

void CanvasPainter::drawPass(const MeshCanvas& canvas, int width_px, int height_px,
                             const std::optional<frame::PixelRect>& region) {
  const float size[2] = {static_cast<float>(width_px), static_cast<float>(height_px)};
  scissor(region, width_px, height_px);
  glDisable(GL_BLEND);  // the background is written as it is, also a transparent one
  if (region) {
    glUseProgram(gl_->fill->program.id());
    glBindVertexArray(gl_->fill->box.array);
    glDrawArrays(GL_TRIANGLES, 0, 6);
  } else {
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glEnable(GL_BLEND);
  for (const DrawBatch& batch : canvas.batches()) {
    const std::optional<frame::PixelRect> clip =
        region ? intersect(batch.clip, *region) : batch.clip;
    if (clip && (clip->x1 <= clip->x0 || clip->y1 <= clip->y0)) continue;
    scissor(clip, width_px, height_px);
    // The batch's shapes in order, each run of one variant drawn with its program.
    if (batch.shape_count > 0) glBindVertexArray(gl_->shapes.array);
    drawRuns(
        canvas.shapeVertices(), batch.shape_first, batch.shape_first + batch.shape_count, clip,
        [](const Vertex& a, const Vertex& b) { return shapeVariant(a) == shapeVariant(b); },
        [&](std::size_t first, std::size_t last) {
          gl_->useShapeProgram(shapeVariant(canvas.shapeVertices()[first]), size);
          glDrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(last - first));
        });
    if (batch.text_count > 0) {
      glUseProgram(gl_->text_program.id());
      glBindVertexArray(gl_->text.array);
      drawRuns(
          canvas.textVertices(), batch.text_first, batch.text_first + batch.text_count, clip,
          [](const TextVertex&, const TextVertex&) { return true; },
          [&](std::size_t first, std::size_t last) {
            glDrawArrays(GL_TRIANGLES, static_cast<GLint>(first),
                         static_cast<GLsizei>(last - first));
          });
    }
  }
}

}  // namespace collide::render
