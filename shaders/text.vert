#version 330 core
// Glyph quads from the atlas. Positions in pixels (origin top-left, y down, as shape.vert);
// texture coordinates in atlas texels. A glyph quad sits on whole pixels with one texel per pixel,
// so its texel is its pixel plus one offset per glyph: text.frag finds it from the pixel centre.
layout(location = 0) in vec2 a_position_px;
layout(location = 1) in vec2 a_texel;
layout(location = 2) in vec4 a_color;  // straight alpha

uniform vec2 u_frame_size_px;

// The shape programs' four flat inputs (shape.vert), so llvmpipe builds one triangle set-up
// function for text and shapes alike (see shape.frag). v_p1 and v_p2 carry nothing text.frag
// needs: it reads them for that reason alone.
flat out vec4 v_color;
flat out vec4 v_p0;  // xy: the glyph's atlas texel minus its pixel; zw: its pixel
flat out vec4 v_p1;
flat out vec4 v_p2;

void main() {
  vec2 ndc = vec2(2.0 * a_position_px.x / u_frame_size_px.x - 1.0,
                  1.0 - 2.0 * a_position_px.y / u_frame_size_px.y);
  gl_Position = vec4(ndc, 0.0, 1.0);
  v_color = a_color;
  // Every component a value of its own: Mesa's linker merges outputs that repeat one another
  // and drops constant ones, which would change the inputs text.frag reads.
  v_p0 = vec4(a_texel - a_position_px, a_position_px);
  v_p1 = vec4(a_texel, a_texel + a_position_px);
  v_p2 = a_color * u_frame_size_px.x;
}
