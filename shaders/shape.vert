#version 330 core
// One quad per analytic shape (src/render/mesh.hpp). Positions arrive in pixels with the origin at
// the frame's top-left corner and y pointing down (see src/render/layout.hpp); the shape's
// parameters pass unchanged to shape.frag, which computes the coverage (the painter picks the
// program for the shape's kind, so the kind itself is not passed on).
layout(location = 0) in vec2 a_position_px;
layout(location = 1) in vec4 a_color;  // straight alpha
layout(location = 2) in float a_kind;  // read by the painter, not here
layout(location = 3) in vec4 a_p0;
layout(location = 4) in vec4 a_p1;
layout(location = 5) in vec4 a_p2;

uniform vec2 u_frame_size_px;

flat out vec4 v_color;
flat out vec4 v_p0;
flat out vec4 v_p1;
flat out vec4 v_p2;

void main() {
  vec2 ndc = vec2(2.0 * a_position_px.x / u_frame_size_px.x - 1.0,
                  1.0 - 2.0 * a_position_px.y / u_frame_size_px.y);
  gl_Position = vec4(ndc, 0.0, 1.0);
  v_color = a_color;
  v_p0 = a_p0;
  v_p1 = a_p1;
  v_p2 = a_p2;
}
