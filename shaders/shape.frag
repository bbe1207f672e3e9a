#version 330 core
// Writes premultiplied alpha: blending (ONE, ONE_MINUS_SRC_ALPHA) and the MSAA resolve then average
// correctly; the renderer converts back to straight alpha only for a translucent background.
flat in vec4 v_color;

out vec4 o_color;

void main() { o_color = vec4(v_color.rgb * v_color.a, v_color.a); }
