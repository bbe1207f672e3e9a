#version 330 core
// One colour everywhere, the background of a repaint pass, drawn unblended. No input, no discard
// and full coverage: llvmpipe draws such a shader as opaque, writing whole tiles without reading
// them, almost as cheaply as it clears a whole frame.
uniform vec4 u_color;  // premultiplied, as the painter's clear colour

out vec4 o_color;

void main() {
  o_color = u_color;
}
