#pragma once
// RGBA8 frames to the planar Y'CbCr 4:2:0 that the MP4 and WebM encoders take: BT.709 matrix,
// full-range R'G'B' in, limited ("video") range out (Y' 16..235, Cb and Cr 16..240), each chroma
// sample the mean of its 2x2 pixels (so it sits at the centre of them: the stream says so).
// A fixed-point loop written so the compiler vectorises it, in place of swscale's slower generic
// path (bench/results.md).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/image.hpp"

namespace collide::output {

struct Yuv420Planes {
  std::uint8_t* luma = nullptr;  // width x height samples
  std::ptrdiff_t luma_stride = 0;
  std::uint8_t* cb = nullptr;  // width/2 x height/2 samples
  std::ptrdiff_t cb_stride = 0;
  std::uint8_t* cr = nullptr;
  std::ptrdiff_t cr_stride = 0;
  std::uint8_t* alpha = nullptr;  // optional: width x height, the frame's alpha copied
  std::ptrdiff_t alpha_stride = 0;
};

// Converts `rgba` (top-down or bottom-up view; the planes come out top row first). Its width and
// height must be even. Each output sample is within about half a level of the exact BT.709 value.
void rgbaToYuv420Bt709(const core::ImageView& rgba, const Yuv420Planes& out);
// The same for the pixels in `rects` only, each widened to whole 2x2 blocks (a chroma sample's
// four pixels); the planes' other samples are left as they are. A frame that differs from the one
// converted into `out` before only in those rectangles comes out as if converted whole.
void rgbaToYuv420Bt709(const core::ImageView& rgba, const Yuv420Planes& out,
                       const std::vector<core::ImageRect>& rects);

}  // namespace collide::output
