#include "output/yuv420.hpp"

#include <cstring>

#include "core/error.hpp"

namespace collide::output {
namespace {

// BT.709 luma weights of R' and B' (G' has the rest).
constexpr double kKr = 0.2126;
constexpr double kKb = 0.0722;
constexpr double kKg = 1.0 - kKr - kKb;
// Limited range: Y' spans 219 levels from 16, Cb and Cr 224 levels around 128, for R'G'B' 0..255.
constexpr double kLumaScale = 219.0 / 255.0;
constexpr double kChromaScale = 224.0 / 255.0;

// Fixed point: weights times 2^16. Luma sums one pixel; chroma sums four (the 2x2 block), so its
// shift is two bits more. Every sum stays below 2^31: 1020 x 0.44 x 2^16 plus the offset.
constexpr int kBits = 16;
constexpr int kChromaBits = kBits + 2;

constexpr std::int32_t fixed(double weight) {
  return static_cast<std::int32_t>(weight * (1 << kBits) + (weight < 0 ? -0.5 : 0.5));
}

constexpr std::int32_t kYr = fixed(kLumaScale * kKr);
constexpr std::int32_t kYg = fixed(kLumaScale * kKg);
constexpr std::int32_t kYb = fixed(kLumaScale * kKb);
// Cb = (B' - Y') / (2 (1 - Kb)), Cr = (R' - Y') / (2 (1 - Kr)), each scaled to 224 levels.
constexpr double kCbDivisor = 2.0 * (1.0 - kKb);
constexpr double kCrDivisor = 2.0 * (1.0 - kKr);
constexpr std::int32_t kCbR = fixed(-kChromaScale * kKr / kCbDivisor);
constexpr std::int32_t kCbG = fixed(-kChromaScale * kKg / kCbDivisor);
constexpr std::int32_t kCbB = fixed(kChromaScale * (1.0 - kKb) / kCbDivisor);
constexpr std::int32_t kCrR = fixed(kChromaScale * (1.0 - kKr) / kCrDivisor);
constexpr std::int32_t kCrG = fixed(-kChromaScale * kKg / kCrDivisor);
constexpr std::int32_t kCrB = fixed(-kChromaScale * kKb / kCrDivisor);
// The offsets (16 and 128) with the rounding half folded in.
constexpr std::int32_t kLumaOffset = (16 << kBits) + (1 << (kBits - 1));
constexpr std::int32_t kChromaOffset = (128 << kChromaBits) + (1 << (kChromaBits - 1));

// One row of luma. Each pixel is read as one 32-bit word and its channels are masked out: in this
// form GCC and Clang vectorise the loops (-O3), where byte-wise loads of interleaved channels
// became shuffles.
inline __attribute__((always_inline)) std::uint32_t loadPixel(const std::uint8_t* p) {
  std::uint32_t word;
  std::memcpy(&word, p, sizeof word);
  return word;
}

std::int32_t red(std::uint32_t pixel) {
  return static_cast<std::int32_t>(pixel & 0xff);
}
std::int32_t green(std::uint32_t pixel) {
  return static_cast<std::int32_t>((pixel >> 8) & 0xff);
}
std::int32_t blue(std::uint32_t pixel) {
  return static_cast<std::int32_t>((pixel >> 16) & 0xff);
}

inline __attribute__((always_inline)) void lumaRow(const std::uint8_t* __restrict rgba,
                                                   std::uint8_t* __restrict luma, int width) {
  for (int x = 0; x < width; ++x) {
    const std::uint32_t p = loadPixel(rgba + 4 * x);
    luma[x] = static_cast<std::uint8_t>(
        (kYr * red(p) + kYg * green(p) + kYb * blue(p) + kLumaOffset) >> kBits);
  }
}

// One row of Cb and Cr from two rows of pixels: each sample from the sums of a 2x2 block.
inline __attribute__((always_inline)) void chromaRow(const std::uint8_t* __restrict upper,
                                                     const std::uint8_t* __restrict lower,
                                                     std::uint8_t* __restrict cb,
                                                     std::uint8_t* __restrict cr, int half_width) {
  for (int x = 0; x < half_width; ++x) {
    const std::uint32_t a = loadPixel(upper + 8 * x);
    const std::uint32_t b = loadPixel(upper + 8 * x + 4);
    const std::uint32_t c = loadPixel(lower + 8 * x);
    const std::uint32_t d = loadPixel(lower + 8 * x + 4);
    const std::int32_t r = red(a) + red(b) + red(c) + red(d);
    const std::int32_t g = green(a) + green(b) + green(c) + green(d);
    const std::int32_t bl = blue(a) + blue(b) + blue(c) + blue(d);
    cb[x] =
        static_cast<std::uint8_t>((kCbR * r + kCbG * g + kCbB * bl + kChromaOffset) >> kChromaBits);
    cr[x] =
        static_cast<std::uint8_t>((kCrR * r + kCrG * g + kCrB * bl + kChromaOffset) >> kChromaBits);
  }
}

inline __attribute__((always_inline)) void alphaRow(const std::uint8_t* __restrict rgba,
                                                    std::uint8_t* __restrict alpha, int width) {
  for (int x = 0; x < width; ++x) alpha[x] = rgba[4 * x + 3];
}

// The pixels [x0, x1) × [y0, y1) (all even), compiled four times where the compiler can pick one at
// load time (x86-64): for AVX-512 (x86-64-v4, sixteen pixels a step), AVX2 (eight), SSE4.1 (four,
// with a 32-bit multiply) and plain x86-64 (whose SSE2 has no 32-bit multiply, so this is several
// times slower; bench/results.md, "Figures behind the code"). Integer arithmetic: every variant
// gives the same bytes.
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("arch=x86-64-v4", "avx2", "arch=x86-64-v2", "default")))
#endif
void convertRect(const core::ImageView& rgba, const Yuv420Planes& out, int x0, int y0, int x1,
                 int y1) {
  const int width = x1 - x0;
  for (int y = y0; y < y1; y += 2) {
    const std::uint8_t* upper = rgba.row(y) + 4 * x0;
    const std::uint8_t* lower = rgba.row(y + 1) + 4 * x0;
    lumaRow(upper, out.luma + out.luma_stride * y + x0, width);
    lumaRow(lower, out.luma + out.luma_stride * (y + 1) + x0, width);
    chromaRow(upper, lower, out.cb + out.cb_stride * (y / 2) + x0 / 2,
              out.cr + out.cr_stride * (y / 2) + x0 / 2, width / 2);
    if (out.alpha != nullptr) {
      alphaRow(upper, out.alpha + out.alpha_stride * y + x0, width);
      alphaRow(lower, out.alpha + out.alpha_stride * (y + 1) + x0, width);
    }
  }
}

}  // namespace

void rgbaToYuv420Bt709(const core::ImageView& rgba, const Yuv420Planes& out) {
  COLLIDE_ASSERT(rgba.width % 2 == 0 && rgba.height % 2 == 0, "4:2:0 needs an even size");
  convertRect(rgba, out, 0, 0, rgba.width, rgba.height);
}

void rgbaToYuv420Bt709(const core::ImageView& rgba, const Yuv420Planes& out,
                       const std::vector<core::ImageRect>& rects) {
  COLLIDE_ASSERT(rgba.width % 2 == 0 && rgba.height % 2 == 0, "4:2:0 needs an even size");
  for (const core::ImageRect& r : rects) {
    COLLIDE_ASSERT(0 <= r.x0 && r.x0 <= r.x1 && r.x1 <= rgba.width && 0 <= r.y0 && r.y0 <= r.y1 &&
                       r.y1 <= rgba.height,
                   "rgbaToYuv420Bt709: rectangles inside the image");
    // A chroma sample comes from a 2x2 block: the rectangle widens to whole blocks. (Where two
    // widened rectangles share a block, it is converted twice, to the same values.)
    const int x0 = r.x0 - r.x0 % 2, y0 = r.y0 - r.y0 % 2;
    const int x1 = r.x1 + r.x1 % 2, y1 = r.y1 + r.y1 % 2;
    if (x0 < x1 && y0 < y1) convertRect(rgba, out, x0, y0, x1, y1);
  }
}

}  // namespace collide::output
