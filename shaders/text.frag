#version 330 core
// Glyph quads sit on whole pixels, so each pixel centre maps to one texel centre: texelFetch
// copies the rasterized coverage exactly (no filtering, same pixels on every run). Writes
// premultiplied alpha, as shape.frag.
uniform sampler2D u_atlas;  // coverage in the red channel

in vec2 v_texel;
flat in vec4 v_color;

out vec4 o_color;

void main() {
  float coverage = texelFetch(u_atlas, ivec2(floor(v_texel)), 0).r;
  float alpha = v_color.a * coverage;
  o_color = vec4(v_color.rgb * alpha, alpha);
}
