#include "render/renderer.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "render/backend.hpp"
#include "render/canvas.hpp"
#include "render/font.hpp"
#include "render/frame_drawing.hpp"
#include "render/framebuffers.hpp"
#include "render/gl.hpp"
#include "render/gl_check.hpp"
#include "render/glyph_atlas.hpp"
#include "render/layout.hpp"
#include "render/shader_program.hpp"
#include "render/shaders.hpp"
#include "render/text.hpp"

#ifndef COLLIDE_DEFAULT_FONT
#define COLLIDE_DEFAULT_FONT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#endif

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
  void release() {
    glDeleteBuffers(1, &buffer);
    glDeleteVertexArrays(1, &array);
  }
  template <typename V>
  void upload(const std::vector<V>& vertices) const {
    glBindVertexArray(array);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(V)),
                 vertices.data(), GL_STREAM_DRAW);
  }
};

}  // namespace

namespace {
std::mutex font_mutex;
std::string chosen_font;  // guarded by font_mutex; empty: the built-in default
}  // namespace

std::string defaultFontPath() {
  const std::lock_guard<std::mutex> lock(font_mutex);
  return chosen_font.empty() ? std::string(COLLIDE_DEFAULT_FONT) : chosen_font;
}

void setDefaultFontPath(const std::string& path) {
  const std::lock_guard<std::mutex> lock(font_mutex);
  chosen_font = path;
}

void checkFont(const std::string& path) {
  Font font(path);
  static_cast<void>(font.rasterize(U'0', 12));
}

struct Renderer::Impl {
  // Declared first so it is destroyed last: every GL object below dies while it is alive.
  std::unique_ptr<GlContext> context;
  int width_px;
  int height_px;
  std::string renderer_name;
  Font font;
  GlyphAtlas atlas{font};
  TextPainter painter{atlas};
  Canvas canvas{painter};
  std::unique_ptr<ShaderProgram> shape_program, text_program;
  int shape_frame_size = -1, text_frame_size = -1, text_atlas = -1;
  VertexStream shapes{sizeof(Vertex), {{2, offsetof(Vertex, x_px)}, {4, offsetof(Vertex, r)}}};
  VertexStream text{sizeof(TextVertex),
                    {{2, offsetof(TextVertex, x_px)},
                     {2, offsetof(TextVertex, u_texel)},
                     {4, offsetof(TextVertex, r)}}};
  unsigned atlas_texture = 0;
  std::uint64_t atlas_revision = 0;  // revision uploaded to atlas_texture
  int atlas_height = 0;              // texels allocated in atlas_texture
  std::unique_ptr<Framebuffers> framebuffers;
  std::vector<std::uint8_t> readback;  // reused; bottom row first

  static std::unique_ptr<GlContext> current(std::unique_ptr<GlContext> ctx) {
    ctx->makeCurrent();  // before any member below touches GL
    return ctx;
  }

  Impl(std::unique_ptr<GlContext> ctx, int w, int h, const RendererOptions& options)
      : context(current(std::move(ctx))),
        width_px(w),
        height_px(h),
        font(options.font_path.empty() ? defaultFontPath() : options.font_path) {
    renderer_name = glString(GL_RENDERER);
    shape_program =
        std::make_unique<ShaderProgram>(shaders::shape_vert, shaders::shape_frag, "shape");
    shape_frame_size = shape_program->uniformLocation("u_frame_size_px");
    text_program = std::make_unique<ShaderProgram>(shaders::text_vert, shaders::text_frag, "text");
    text_frame_size = text_program->uniformLocation("u_frame_size_px");
    text_atlas = text_program->uniformLocation("u_atlas");
    glGenTextures(1, &atlas_texture);
    glBindTexture(GL_TEXTURE_2D, atlas_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    checkGl("setting up vertex buffers and the glyph atlas");
    framebuffers = std::make_unique<Framebuffers>(w, h);
  }

  ~Impl() {
    // GL objects belong to this context; if it cannot be made current they die with it anyway.
    try {
      context->makeCurrent();
    } catch (const RenderError&) {
      // Deleting now would hit whichever context is current; leak the handles instead (they die
      // with the context).
      static_cast<void>(framebuffers.release());
      static_cast<void>(shape_program.release());
      static_cast<void>(text_program.release());
      return;
    }
    framebuffers.reset();
    shape_program.reset();
    text_program.reset();
    shapes.release();
    text.release();
    glDeleteTextures(1, &atlas_texture);
  }

  void uploadAtlas() {
    if (atlas.revision() == atlas_revision) return;
    glBindTexture(GL_TEXTURE_2D, atlas_texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (atlas.height() != atlas_height) {
      glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.width(), atlas.height(), 0, GL_RED,
                   GL_UNSIGNED_BYTE, atlas.texels().data());
      atlas_height = atlas.height();
    } else {
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, atlas.width(), atlas.height(), GL_RED,
                      GL_UNSIGNED_BYTE, atlas.texels().data());
    }
    atlas_revision = atlas.revision();
  }

  void scissor(const std::optional<PixelRect>& clip) {
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

  core::ImageView render(const FrameModel& frame) {
    context->makeCurrent();
    const FrameLayout layout = computeFrameLayout(width_px, height_px, shapeOf(frame));
    drawFrame(frame, layout, canvas);

    framebuffers->bindForDrawing();
    const Rgba& bg = frame.style.background;
    glDisable(GL_SCISSOR_TEST);
    glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);  // premultiplied, as drawn colours
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"

    shapes.upload(canvas.shapeVertices());
    text.upload(canvas.textVertices());
    uploadAtlas();
    const float size[2] = {static_cast<float>(width_px), static_cast<float>(height_px)};
    glUseProgram(shape_program->id());
    glUniform2fv(shape_frame_size, 1, size);
    glUseProgram(text_program->id());
    glUniform2fv(text_frame_size, 1, size);
    glUniform1i(text_atlas, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, atlas_texture);

    for (const DrawBatch& batch : canvas.batches()) {
      scissor(batch.clip);
      if (batch.shape_count > 0) {
        glUseProgram(shape_program->id());
        glBindVertexArray(shapes.array);
        glDrawArrays(GL_TRIANGLES, static_cast<GLint>(batch.shape_first),
                     static_cast<GLsizei>(batch.shape_count));
      }
      if (batch.text_count > 0) {
        glUseProgram(text_program->id());
        glBindVertexArray(text.array);
        glDrawArrays(GL_TRIANGLES, static_cast<GLint>(batch.text_first),
                     static_cast<GLsizei>(batch.text_count));
      }
    }
    glDisable(GL_SCISSOR_TEST);
    checkGl("drawing a frame");

    framebuffers->resolveAndRead(readback);
    if (bg.a < 1.0f) unpremultiply(readback);

    const std::ptrdiff_t row_bytes = static_cast<std::ptrdiff_t>(width_px) * 4;
    return core::ImageView{readback.data() + row_bytes * (height_px - 1), width_px, height_px,
                           -row_bytes};
  }
};

Renderer::Renderer(int width_px, int height_px, const RendererOptions& options)
    : Renderer(createContext(defaultBackend()), width_px, height_px, options) {}

Renderer::Renderer(std::unique_ptr<GlContext> context, int width_px, int height_px,
                   const RendererOptions& options) {
  COLLIDE_ASSERT(context != nullptr, "no GL context given");
  COLLIDE_ASSERT(width_px > 0 && height_px > 0, "frame size must be positive (validate input)");
  impl_ = std::make_unique<Impl>(std::move(context), width_px, height_px, options);
}

Renderer::~Renderer() = default;

core::ImageView Renderer::render(const FrameModel& frame) {
  return impl_->render(frame);
}

int Renderer::width_px() const {
  return impl_->width_px;
}
int Renderer::height_px() const {
  return impl_->height_px;
}
std::string Renderer::glRendererName() const {
  return impl_->renderer_name;
}

}  // namespace collide::render
