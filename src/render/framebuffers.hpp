#pragma once
// Private: the renderer's own RGBA8 targets: a 4× multisampled framebuffer to draw into and a
// single-sample one it is resolved into for read-back. Needs a current context throughout.
#include <cstdint>
#include <vector>

namespace collide::render {

class Framebuffers {
 public:
  static constexpr int kSamples = 4;  // llvmpipe offers 1 or 4

  // Throws RenderError if the size exceeds the context's limits or a framebuffer is incomplete.
  Framebuffers(int width_px, int height_px);
  ~Framebuffers();
  Framebuffers(const Framebuffers&) = delete;
  Framebuffers& operator=(const Framebuffers&) = delete;

  // Binds the multisampled framebuffer for drawing and sets the viewport to the whole frame.
  void bindForDrawing() const;
  // Resolves the samples and reads the frame into `pixels` (resized to w·h·4), bottom row first.
  void resolveAndRead(std::vector<std::uint8_t>& pixels) const;

 private:
  int width_px_;
  int height_px_;
  unsigned multisample_fbo_ = 0, multisample_color_ = 0;
  unsigned resolve_fbo_ = 0, resolve_color_ = 0;
};

}  // namespace collide::render
