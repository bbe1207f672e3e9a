#include "render/renderer.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/backend.hpp"
#include "render/frame_mesh.hpp"
#include "render/framebuffers.hpp"
#include "render/gl.hpp"
#include "render/gl_check.hpp"
#include "render/layout.hpp"
#include "render/mesh.hpp"
#include "render/shader_program.hpp"
#include "render/shaders.hpp"

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

}  // namespace

struct Renderer::Impl {
  // Declared first so it is destroyed last: every GL object below dies while it is alive.
  std::unique_ptr<GlContext> context;
  int width_px;
  int height_px;
  FrameLayout layout;
  std::string renderer_name;
  std::unique_ptr<ShaderProgram> program;
  int frame_size_uniform = -1;
  unsigned vertex_array = 0;
  unsigned vertex_buffer = 0;
  std::unique_ptr<Framebuffers> framebuffers;
  MeshBuilder mesh;                    // reused: no allocation per frame once warmed up
  std::vector<std::uint8_t> readback;  // reused; bottom row first

  Impl(std::unique_ptr<GlContext> ctx, int w, int h)
      : context(std::move(ctx)), width_px(w), height_px(h), layout(computeFrameLayout(w, h)) {
    context->makeCurrent();
    renderer_name = glString(GL_RENDERER);
    program = std::make_unique<ShaderProgram>(shaders::shape_vert, shaders::shape_frag, "shape");
    frame_size_uniform = program->uniformLocation("u_frame_size_px");

    glGenVertexArrays(1, &vertex_array);
    glGenBuffers(1, &vertex_buffer);
    glBindVertexArray(vertex_array);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, x_px)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, r)));
    checkGl("setting up the vertex buffer");

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
      static_cast<void>(program.release());
      return;
    }
    framebuffers.reset();
    program.reset();
    glDeleteBuffers(1, &vertex_buffer);
    glDeleteVertexArrays(1, &vertex_array);
  }

  core::ImageView render(const FrameModel& frame) {
    context->makeCurrent();
    const FrameMeshRanges ranges = buildFrameMesh(frame, layout, mesh);

    framebuffers->bindForDrawing();
    const Rgba& bg = frame.background;
    glDisable(GL_SCISSOR_TEST);
    glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);  // premultiplied, as drawn colours
    glClear(GL_COLOR_BUFFER_BIT);

    glUseProgram(program->id());
    glUniform2f(frame_size_uniform, static_cast<float>(width_px), static_cast<float>(height_px));
    glBindVertexArray(vertex_array);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
    const auto& vertices = mesh.vertices();
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                 vertices.data(), GL_STREAM_DRAW);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"

    // GL scissor rows count from the bottom.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, height_px - layout.world_clip_y1_px, width_px, layout.world_clip_y1_px);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(ranges.world_vertices));
    glDisable(GL_SCISSOR_TEST);
    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(ranges.world_vertices),
                 static_cast<GLsizei>(ranges.total_vertices - ranges.world_vertices));
    checkGl("drawing a frame");

    framebuffers->resolveAndRead(readback);
    if (bg.a < 1.0f) unpremultiply(readback);

    const std::ptrdiff_t row_bytes = static_cast<std::ptrdiff_t>(width_px) * 4;
    return core::ImageView{readback.data() + row_bytes * (height_px - 1), width_px, height_px,
                           -row_bytes};
  }
};

Renderer::Renderer(int width_px, int height_px)
    : Renderer(createContext(defaultBackend()), width_px, height_px) {}

Renderer::Renderer(std::unique_ptr<GlContext> context, int width_px, int height_px) {
  COLLIDE_ASSERT(context != nullptr, "no GL context given");
  COLLIDE_ASSERT(width_px > 0 && height_px > 0, "frame size must be positive (validate input)");
  impl_ = std::make_unique<Impl>(std::move(context), width_px, height_px);
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
