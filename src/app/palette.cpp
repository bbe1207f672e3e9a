#include "app/palette.hpp"

#include <array>

namespace collide::app {
namespace {

render::Rgba fromBytes(int r, int g, int b) {
  return {static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f,
          static_cast<float>(b) / 255.0f, 1.0f};
}

}  // namespace

render::Rgba bodyColor(std::size_t index, const scene::BodyDesc& body) {
  if (body.color) return fromBytes(body.color->r, body.color->g, body.color->b);
  // Okabe–Ito: blue, orange, bluish green, vermillion, reddish purple, sky blue, yellow.
  static const std::array<scene::Rgb, 7> kPalette = {{{0, 114, 178},
                                                      {230, 159, 0},
                                                      {0, 158, 115},
                                                      {213, 94, 0},
                                                      {204, 121, 167},
                                                      {86, 180, 233},
                                                      {240, 228, 66}}};
  const scene::Rgb& c = kPalette[index % kPalette.size()];
  return fromBytes(c.r, c.g, c.b);
}

render::Rgba lostEnergyColor() {
  return fromBytes(153, 153, 153);
}

}  // namespace collide::app
