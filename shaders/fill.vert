#version 330 core
// The background box of a repaint pass (src/render/canvas_painter.cpp): corners in pixels, origin
// at the frame's top-left corner, y pointing down, as shape.vert.
layout(location = 0) in vec2 a_position_px;

uniform vec2 u_frame_size_px;

void main() {
  vec2 ndc = vec2(2.0 * a_position_px.x / u_frame_size_px.x - 1.0,
                  1.0 - 2.0 * a_position_px.y / u_frame_size_px.y);
  gl_Position = vec4(ndc, 0.0, 1.0);
}
