#version 330 core
// Glyph quads from the atlas. Positions in pixels (origin top-left, y down, as shape.vert);
// texture coordinates in atlas texels, so the fragment shader can fetch texels exactly.
layout(location = 0) in vec2 a_position_px;
layout(location = 1) in vec2 a_texel;
layout(location = 2) in vec4 a_color;  // straight alpha

uniform vec2 u_frame_size_px;

out vec2 v_texel;
flat out vec4 v_color;

void main() {
  vec2 ndc = vec2(2.0 * a_position_px.x / u_frame_size_px.x - 1.0,
                  1.0 - 2.0 * a_position_px.y / u_frame_size_px.y);
  gl_Position = vec4(ndc, 0.0, 1.0);
  v_texel = a_texel;
  v_color = a_color;
}
