#pragma once
// Private: the renderer's own RGBA8 target, one sample per pixel (shapes compute their own edge
// coverage, shaders/shape.frag). Needs a current context throughout.
#include <cstdint>
#include <vector>

namespace collide::render {

class Framebuffers {
 public:
  // Throws RenderError if the size exceeds the context's limits or the framebuffer is incomplete.
  Framebuffers(int width_px, int height_px);
  ~Framebuffers();
  Framebuffers(const Framebuffers&) = delete;
  Framebuffers& operator=(const Framebuffers&) = delete;

  // Binds the framebuffer for drawing and sets the viewport to the whole frame.
  void bindForDrawing() const;
  // Reads the frame into `pixels` (resized to w·h·4), bottom row first.
  void read(std::vector<std::uint8_t>& pixels) const;
  // Reads only the rectangle of `width` x `height` pixels from column x, row first_row (rows
  // counted from the bottom) into its place in `pixels`, which already holds a whole frame.
  void readRect(std::vector<std::uint8_t>& pixels, int x, int first_row, int width,
                int height) const;

 private:
  int width_px_;
  int height_px_;
  unsigned fbo_ = 0, color_ = 0;
};

}  // namespace collide::render
