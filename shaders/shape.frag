#version 330 core
// Analytic anti-aliasing with one sample per pixel: the fraction of this pixel's square that the
// shape covers, from the pixel centre's distance to the shape's edges. For a straight edge the
// fraction is exact (halfPlane); a corner multiplies the fractions of its two edges, and a curved
// edge uses its tangent at the nearest point. Kinds and parameters: src/render/mesh.hpp.
// Writes premultiplied alpha: blending is (ONE, ONE_MINUS_SRC_ALPHA); the renderer converts back
// to straight alpha only for a translucent background.
flat in vec4 v_color;
flat in vec4 v_p0;
flat in vec4 v_p1;
flat in vec4 v_p2;

uniform vec2 u_frame_size_px;

out vec4 o_color;

const float kPi = 3.14159265358979;

// Coverage of a unit pixel square by the half-plane whose edge has unit normal n (pointing inside)
// and lies `inside` pixels from the pixel centre (negative: the centre is outside). Projected on
// n the square spreads its area as a trapezoid of width a + b (a, b = the smaller and larger of
// |n.x|, |n.y|): its integral is quadratic over the first and last a, linear between.
float halfPlane(float inside, vec2 n) {
  vec2 m = abs(n);
  float a = min(m.x, m.y), b = max(m.x, m.y);
  float u = inside + 0.5 * (a + b);
  if (u <= 0.0) return 0.0;
  if (u >= a + b) return 1.0;
  if (a < 1e-4) return u / b;
  if (u < a) return u * u / (2.0 * a * b);
  if (u < b) return (u - 0.5 * a) / b;
  float rest = a + b - u;
  return 1.0 - rest * rest / (2.0 * a * b);
}

// The band |x| <= half across unit direction n, x the pixel centre's offset along n: the two
// parallel edges together (exact, even when both cross the pixel).
float band(float x, float half_width, vec2 n) {
  return max(0.0, halfPlane(half_width - x, n) + halfPlane(half_width + x, n) - 1.0);
}

// Coverage by the axis-aligned rectangle lo..hi (exact: its edges separate).
float aligned(vec2 p, vec2 lo, vec2 hi) {
  vec2 inside = clamp(min(p + 0.5, hi) - max(p - 0.5, lo), 0.0, 1.0);
  return inside.x * inside.y;
}

// A box of half extents `half_size` along unit u and v = perp(u), centred at the origin of q.
// Near a corner the product of the two bands can exceed the truth a little; the box never covers
// more than its bounding rectangle does, which keeps that from leaking into neighbouring pixels.
float box(vec2 q, vec2 u, vec2 half_size) {
  if (half_size.x <= 0.0 || half_size.y <= 0.0) return 0.0;
  vec2 v = vec2(-u.y, u.x);
  vec2 reach = abs(u) * half_size.x + abs(v) * half_size.y;
  return min(band(dot(q, u), half_size.x, u) * band(dot(q, v), half_size.y, v),
             aligned(q, -reach, reach));
}

// A disk of radius r centred at the origin of q; never more than its own area.
float disk(vec2 q, float r) {
  if (r <= 0.0) return 0.0;
  float d = length(q);
  vec2 n = d > 1e-6 ? q / d : vec2(1.0, 0.0);
  return min(halfPlane(r - d, n), kPi * r * r);
}

// The edge a–b of a triangle whose third corner is c, as a half-plane containing c.
float edge(vec2 p, vec2 a, vec2 b, vec2 c) {
  vec2 n = normalize(vec2(a.y - b.y, b.x - a.x));
  if (dot(c - a, n) < 0.0) n = -n;
  return halfPlane(dot(p - a, n), n);
}

float triangle(vec2 p, vec2 a, vec2 b, vec2 c) {
  return min(edge(p, a, b, c) * edge(p, b, c, a) * edge(p, c, a, b),
             aligned(p, min(a, min(b, c)), max(a, max(b, c))));
}

float arrow(vec2 p) {
  vec2 tail = v_p0.xy, u = v_p0.zw, v = vec2(-u.y, u.x);
  float length_px = v_p1.x, shaft_half = v_p1.y, head_length = v_p1.z, head_half = v_p1.w;
  float shaft_length = length_px - head_length;
  vec2 q = p - (tail + 0.5 * shaft_length * u);
  float shaft = shaft_length > 0.0 ? box(q, u, vec2(0.5 * shaft_length, shaft_half)) : 0.0;
  vec2 base = tail + shaft_length * u, tip = tail + length_px * u;
  float head = triangle(p, tip, base + head_half * v, base - head_half * v);
  // The shaft ends where the head begins: the two never overlap, so their coverages add.
  return min(1.0, shaft + head);
}

float sector(vec2 p) {
  vec2 q = p - v_p0.xy;
  // Inside: on the far side of the start ray (turning towards +y) and the near side of the end ray.
  vec2 n0 = vec2(-v_p1.y, v_p1.x), n1 = vec2(v_p1.w, -v_p1.z);
  return disk(q, v_p0.z) * halfPlane(dot(q, n0), n0) * halfPlane(dot(q, n1), n1);
}

// Distance from p to the segment a–b, the parameter of the nearest point clamped to [lo, hi]
// (lo < 0 or hi > 1 extend the segment into its line).
float segmentDistance(vec2 p, vec2 a, vec2 b, float lo, float hi, out vec2 nearest) {
  vec2 ab = b - a;
  float t = clamp(dot(p - a, ab) / dot(ab, ab), lo, hi);
  nearest = a + t * ab;
  return length(p - nearest);
}

float stroke(vec2 p) {
  vec2 a = v_p0.xy, b = v_p0.zw;
  float half_width = v_p2.x;
  bool has_prev = v_p2.y > 0.5, has_next = v_p2.z > 0.5;
  vec2 nearest, unused;
  float own = segmentDistance(p, a, b, 0.0, 1.0, nearest);
  // The segment nearest to the pixel draws it (the later one on a tie), so each pixel blends once.
  if (has_prev && segmentDistance(p, v_p1.xy, a, 0.0, 1.0, unused) < own) return -1.0;
  if (has_next && segmentDistance(p, b, v_p1.zw, 0.0, 1.0, unused) <= own) return -1.0;
  // Square ends: measure across the line there, and cut along it.
  float d = segmentDistance(p, a, b, has_prev ? 0.0 : -1e9, has_next ? 1.0 : 1e9, nearest);
  vec2 u = normalize(b - a);
  vec2 n = d > 1e-6 ? (p - nearest) / d : vec2(-u.y, u.x);
  float coverage = band(d, half_width, n);
  if (!has_prev) coverage *= halfPlane(dot(p - a, u), u);
  if (!has_next) coverage *= halfPlane(dot(b - p, u), -u);
  return coverage;
}

// One program per kind of primitive (and per box and disk, whether it has a hole): the painter
// defines SHAPE_VARIANT (the numbers of CanvasPainter's ShapeVariant) and draws each run of
// primitives of one variant with its program. llvmpipe runs both sides of every branch under a
// mask, so a program that chose the kind at run time paid for all six kinds on every pixel.
float coverage(vec2 p) {
#if SHAPE_VARIANT == 1
  return box(p - v_p0.xy, v_p0.zw, v_p1.xy);
#elif SHAPE_VARIANT == 2
  return disk(p - v_p0.xy, v_p0.z);
#elif SHAPE_VARIANT == 3
  return sector(p);
#elif SHAPE_VARIANT == 4
  return triangle(p, v_p0.xy, v_p0.zw, v_p1.xy);
#elif SHAPE_VARIANT == 5
  return arrow(p);
#elif SHAPE_VARIANT == 6
  return stroke(p);
#elif SHAPE_VARIANT == 7
  // A box frame: the box less the box shrunk by the inset.
  return max(0.0, box(p - v_p0.xy, v_p0.zw, v_p1.xy) -
                      box(p - v_p0.xy, v_p0.zw, v_p1.xy - vec2(v_p1.z)));
#elif SHAPE_VARIANT == 8
  // A ring: the disk less the inner disk.
  return max(0.0, disk(p - v_p0.xy, v_p0.z) - disk(p - v_p0.xy, v_p0.w));
#else
#error SHAPE_VARIANT must be defined
#endif
}

void main() {
  // Pixel centre in layout coordinates (y down from the top edge).
  vec2 p = vec2(gl_FragCoord.x, u_frame_size_px.y - gl_FragCoord.y);
  // Every program (text.frag too, with inputs of the same kinds) reads every component of every
  // input, so all of them share one triangle set-up function: llvmpipe compiles one per set of
  // inputs a fragment shader reads and, unlike the shaders, keeps none in its disk cache (a 720p
  // still compiled four, about 2 ms of CPU each).
  // p2.w is 0 in every primitive (mesh.hpp): the test never discards.
  vec4 all_inputs = v_color + v_p0 + v_p1 + v_p2;
  if (v_p2.w * (all_inputs.x + all_inputs.y + all_inputs.z + all_inputs.w) == 1.0) discard;
  float c = coverage(p);
  if (c <= 0.0) discard;
  float alpha = v_color.a * min(c, 1.0);
  o_color = vec4(v_color.rgb * alpha, alpha);
}
