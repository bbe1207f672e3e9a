#pragma once
// A palette generated for a whole GIF animation: a histogram of every frame's colours, reduced by
// median cut. Scenes drawn with a few flat colours and antialiased edges come out exact when they
// have fewer colours than the palette holds.
#include <array>
#include <cstdint>
#include <vector>

#include "core/image.hpp"

namespace collide::output {

// Colours are counted in 32768 bins of 5 bits per channel, each with the exact sum of the colours
// that fell into it, so a bin's mean is the true colour when only one colour uses it.
class ColorHistogram {
 public:
  static constexpr int kBins = 1 << 15;
  static constexpr std::uint16_t kTransparent = 0x8000;  // key of a pixel with alpha < 128

  ColorHistogram();
  static std::uint16_t keyOf(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return static_cast<std::uint16_t>((r >> 3) << 10 | (g >> 3) << 5 | (b >> 3));
  }
  // Counts one row of RGBA pixels and writes each pixel's key to `keys` (width entries). With
  // `transparency`, pixels with alpha below 128 get kTransparent and are not counted.
  void addRow(const std::uint8_t* rgba, int width, bool transparency, std::uint16_t* keys);

  std::uint64_t count(int bin) const { return count_[static_cast<std::size_t>(bin)]; }
  // Mean colour of a non-empty bin, per channel 0..255.
  std::array<double, 3> mean(int bin) const;

 private:
  std::vector<std::uint64_t> count_;
  std::vector<std::array<std::uint64_t, 3>> sum_;
};

struct Palette {
  std::vector<std::array<std::uint8_t, 3>> colors;  // at most the requested number
  std::vector<std::uint8_t> index_of_key;  // ColorHistogram::kBins entries: key -> colour index
};

// Median cut: the box of bins with the most pixels times the longest side is split at its
// weighted median until there are `max_colors` boxes; each colour is its box's weighted mean;
// each bin maps to the nearest colour. 1 <= max_colors <= 256.
Palette buildPalette(const ColorHistogram& histogram, int max_colors);

}  // namespace collide::output
