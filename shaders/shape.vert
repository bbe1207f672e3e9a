#version 330 core
// Flat-coloured 2D shapes. Positions arrive in pixels with the origin at the frame's top-left
// corner and y pointing down (see src/render/layout.hpp).
layout(location = 0) in vec2 a_position_px;
layout(location = 1) in vec4 a_color;  // straight alpha

uniform vec2 u_frame_size_px;

flat out vec4 v_color;

void main() {
  vec2 ndc = vec2(2.0 * a_position_px.x / u_frame_size_px.x - 1.0,
                  1.0 - 2.0 * a_position_px.y / u_frame_size_px.y);
  gl_Position = vec4(ndc, 0.0, 1.0);
  v_color = a_color;
}
