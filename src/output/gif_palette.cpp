#include "output/gif_palette.hpp"

#include <algorithm>
#include <numeric>

#include "core/error.hpp"

namespace collide::output {
namespace {

struct Box {
  std::vector<int> bins;  // non-empty histogram bins in this box
  std::uint64_t pixels = 0;
  int longest_axis = 0;       // 0 r, 1 g, 2 b
  double longest_side = 0.0;  // extent of the bins' means along that axis, 0..255
};

void measure(Box& box, const ColorHistogram& histogram) {
  std::array<double, 3> low{255, 255, 255}, high{0, 0, 0};
  box.pixels = 0;
  for (const int bin : box.bins) {
    box.pixels += histogram.count(bin);
    const std::array<double, 3> m = histogram.mean(bin);
    for (int c = 0; c < 3; ++c) {
      low[c] = std::min(low[c], m[c]);
      high[c] = std::max(high[c], m[c]);
    }
  }
  box.longest_axis = 0;
  for (int c = 1; c < 3; ++c) {
    if (high[c] - low[c] > high[box.longest_axis] - low[box.longest_axis]) box.longest_axis = c;
  }
  box.longest_side = high[box.longest_axis] - low[box.longest_axis];
}

}  // namespace

ColorHistogram::ColorHistogram() : count_(kBins, 0), sum_(kBins, {0, 0, 0}) {}

void ColorHistogram::addRow(const std::uint8_t* rgba, int width, bool transparency,
                            std::uint16_t* keys) {
  for (int x = 0; x < width; ++x, rgba += 4) {
    if (transparency && rgba[3] < 128) {
      keys[x] = kTransparent;
      continue;
    }
    const std::uint16_t key = keyOf(rgba[0], rgba[1], rgba[2]);
    keys[x] = key;
    ++count_[key];
    auto& sum = sum_[key];
    sum[0] += rgba[0];
    sum[1] += rgba[1];
    sum[2] += rgba[2];
  }
}

std::array<double, 3> ColorHistogram::mean(int bin) const {
  const auto i = static_cast<std::size_t>(bin);
  const double n = static_cast<double>(count_[i]);
  return {sum_[i][0] / n, sum_[i][1] / n, sum_[i][2] / n};
}

Palette buildPalette(const ColorHistogram& histogram, int max_colors) {
  COLLIDE_ASSERT(max_colors >= 1 && max_colors <= 256, "a GIF palette holds 1 to 256 colours");
  Box all;
  for (int bin = 0; bin < ColorHistogram::kBins; ++bin) {
    if (histogram.count(bin) > 0) all.bins.push_back(bin);
  }
  Palette palette;
  palette.index_of_key.assign(ColorHistogram::kBins, 0);
  if (all.bins.empty()) {  // every pixel transparent: one colour, never shown
    palette.colors.push_back({0, 0, 0});
    return palette;
  }
  measure(all, histogram);
  std::vector<Box> boxes{std::move(all)};
  while (static_cast<int>(boxes.size()) < max_colors) {
    // The box whose split helps most: many pixels over a long extent.
    auto widest = std::max_element(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) {
      const auto score = [](const Box& x) {
        return x.bins.size() > 1 ? static_cast<double>(x.pixels) * x.longest_side : -1.0;
      };
      return score(a) < score(b);
    });
    if (widest->bins.size() < 2) break;  // every box is one bin: all colours are exact
    Box& box = *widest;
    const int axis = box.longest_axis;
    std::sort(box.bins.begin(), box.bins.end(), [&](int a, int b) {
      return histogram.mean(a)[static_cast<std::size_t>(axis)] <
             histogram.mean(b)[static_cast<std::size_t>(axis)];
    });
    // Weighted median, keeping at least one bin on each side.
    std::uint64_t running = 0;
    std::size_t cut = 1;
    for (; cut < box.bins.size() - 1; ++cut) {
      running += histogram.count(box.bins[cut - 1]);
      if (2 * running >= box.pixels) break;
    }
    Box upper;
    upper.bins.assign(box.bins.begin() + static_cast<std::ptrdiff_t>(cut), box.bins.end());
    box.bins.resize(cut);
    measure(box, histogram);
    measure(upper, histogram);
    boxes.push_back(std::move(upper));
  }

  std::vector<std::array<double, 3>> means;
  for (const Box& box : boxes) {
    std::array<double, 3> sum{0, 0, 0};
    for (const int bin : box.bins) {
      const std::array<double, 3> m = histogram.mean(bin);
      for (int c = 0; c < 3; ++c) sum[c] += m[c] * static_cast<double>(histogram.count(bin));
    }
    std::array<std::uint8_t, 3> color{};
    for (int c = 0; c < 3; ++c) {
      sum[c] /= static_cast<double>(box.pixels);
      color[c] = static_cast<std::uint8_t>(std::clamp(sum[c] + 0.5, 0.0, 255.0));
    }
    means.push_back(sum);
    palette.colors.push_back(color);
  }
  // Nearest colour for every bin in use (bins not in use are never looked up).
  for (const Box& box : boxes) {
    for (const int bin : box.bins) {
      const std::array<double, 3> m = histogram.mean(bin);
      double best = 1e300;
      for (std::size_t i = 0; i < means.size(); ++i) {
        const double d = (m[0] - means[i][0]) * (m[0] - means[i][0]) +
                         (m[1] - means[i][1]) * (m[1] - means[i][1]) +
                         (m[2] - means[i][2]) * (m[2] - means[i][2]);
        if (d < best) {
          best = d;
          palette.index_of_key[static_cast<std::size_t>(bin)] = static_cast<std::uint8_t>(i);
        }
      }
    }
  }
  return palette;
}

}  // namespace collide::output
