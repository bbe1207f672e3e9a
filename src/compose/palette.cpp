#include "compose/palette.hpp"

#include "core/error.hpp"

namespace collide::compose {
namespace {

frame::Rgba rgb(int r, int g, int b, float a = 1.0f) {
  return {static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f,
          static_cast<float>(b) / 255.0f, a};
}

// Okabe–Ito: blue, orange, bluish green, vermillion, reddish purple, sky blue, yellow.
std::vector<frame::Rgba> okabeIto() {
  return {rgb(0, 114, 178),   rgb(230, 159, 0),  rgb(0, 158, 115), rgb(213, 94, 0),
          rgb(204, 121, 167), rgb(86, 180, 233), rgb(240, 228, 66)};
}

Theme light() {
  Theme t;
  t.name = "light";
  t.bodies = okabeIto();
  t.lost = rgb(153, 153, 153);
  t.potential = rgb(86, 180, 233);
  t.spring = rgb(204, 121, 167);
  t.total = rgb(25, 25, 25);
  t.released = rgb(120, 60, 10);  // brown: dark where orange is light
  t.surface = rgb(90, 90, 90);
  t.equipartition = rgb(0, 158, 115);
  t.air = rgb(150, 0, 240);
  return t;  // FrameStyle defaults are the light theme
}

Theme dark() {
  Theme t;
  t.name = "dark";
  t.style.background = rgb(24, 26, 30);
  t.style.text = rgb(235, 235, 235);
  t.style.muted_text = rgb(170, 170, 170);
  t.style.track = rgb(170, 170, 170);
  t.style.arrow = rgb(240, 240, 240);
  t.style.bar_frame = rgb(90, 90, 95);
  t.style.flash = rgb(255, 220, 80);
  t.style.inset_background = rgb(40, 43, 48, 0.92f);
  t.style.outline_shade = 1.35f;  // lighter edges read better on a dark ground
  // Okabe–Ito blue is too dark on this background: the sky blue takes its place.
  t.bodies = {rgb(86, 180, 233),  rgb(230, 159, 0), rgb(0, 158, 115), rgb(213, 94, 0),
              rgb(204, 121, 167), rgb(0, 114, 178), rgb(240, 228, 66)};
  t.lost = rgb(120, 120, 125);
  t.potential = rgb(0, 114, 178);
  t.spring = rgb(204, 121, 167);
  t.total = rgb(235, 235, 235);
  t.released = rgb(150, 80, 20);
  t.surface = rgb(190, 190, 195);
  t.equipartition = rgb(0, 158, 115);
  t.air = rgb(150, 0, 240);
  return t;
}

// Black on white, thick lines, saturated fills with black outlines (WCAG contrast > 7:1 for text).
Theme highContrast() {
  Theme t;
  t.name = "high-contrast";
  t.style.background = rgb(255, 255, 255);
  t.style.text = rgb(0, 0, 0);
  t.style.muted_text = rgb(0, 0, 0);
  t.style.track = rgb(0, 0, 0);
  t.style.arrow = rgb(0, 0, 0);
  t.style.bar_frame = rgb(0, 0, 0);
  t.style.flash = rgb(230, 0, 0);
  t.style.inset_background = rgb(255, 255, 255);
  t.style.outline_shade = 0.0f;  // black outlines
  t.style.line_scale = 1.6;
  t.bodies = {rgb(0, 90, 181),   rgb(220, 50, 32), rgb(0, 130, 60), rgb(255, 194, 10),
              rgb(120, 40, 140), rgb(0, 170, 200), rgb(110, 70, 20)};
  t.lost = rgb(90, 90, 90);
  t.potential = rgb(0, 170, 200);
  t.spring = rgb(170, 60, 150);
  t.total = rgb(0, 0, 0);
  t.released = rgb(0, 200, 140);  // mint: light beside the dark blue, red and gray
  t.surface = rgb(170, 170, 170);
  t.equipartition = rgb(0, 110, 50);  // darker than the released mint
  t.air = rgb(135, 0, 255);
  return t;
}

}  // namespace

const std::vector<std::string>& themeNames() {
  static const std::vector<std::string> names = {"light", "dark", "high-contrast"};
  return names;
}

const Theme& themeNamed(const std::string& name, const std::string& what) {
  static const std::vector<Theme> themes = {light(), dark(), highContrast()};
  for (const Theme& theme : themes) {
    if (theme.name == name) return theme;
  }
  throw core::InputError(what + ": '" + name + "': allowed: light, dark, high-contrast");
}

frame::Rgba bodyColor(const Theme& theme, std::size_t index, const scene::BodyDesc& body) {
  if (body.color) return rgb(body.color->r, body.color->g, body.color->b);
  return theme.bodies[index % theme.bodies.size()];
}

}  // namespace collide::compose
