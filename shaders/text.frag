#version 330 core
// Glyph quads sit on whole pixels, so each pixel centre maps to one texel centre: texelFetch
// copies the rasterized coverage exactly (no filtering, same pixels on every run). Writes
// premultiplied alpha, as shape.frag.
flat in vec4 v_color;
flat in vec4 v_p0;  // xy: the glyph's atlas texel minus its pixel
flat in vec4 v_p1;
flat in vec4 v_p2;

uniform vec2 u_frame_size_px;
uniform sampler2D u_atlas;  // coverage in the red channel

out vec4 o_color;

void main() {
  // Every input is read, as in shape.frag, so text and shapes share one triangle set-up. Pixel
  // and texel coordinates are far below 1e30: the test never discards.
  vec4 all_inputs = v_color + v_p0 + v_p1 + v_p2;
  if (all_inputs.x + all_inputs.y + all_inputs.z + all_inputs.w < -1.0e30) discard;
  // Pixel centre in layout coordinates (y down from the top edge), as shape.frag.
  vec2 p = vec2(gl_FragCoord.x, u_frame_size_px.y - gl_FragCoord.y);
  float coverage = texelFetch(u_atlas, ivec2(floor(p + v_p0.xy)), 0).r;
  float alpha = v_color.a * coverage;
  o_color = vec4(v_color.rgb * alpha, alpha);
}
