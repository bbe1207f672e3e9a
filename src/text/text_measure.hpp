#pragma once
// How large a line of text will be drawn, as an interface: label placement (compose) measures
// text through it and so links no font library; render::TextMetrics (text_metrics.hpp) is the
// painters' own measure, with the same fonts, shaping and sizes they draw with.
#include <string_view>

namespace collide::text {

class TextMeasure {
 public:
  virtual ~TextMeasure() = default;

  // Advance width of the line at this em size, pixels.
  virtual double width(std::string_view text, double size_px) = 0;
  // Baseline to the top and to the bottom of the line, pixels (> 0 both).
  virtual double ascender(double size_px) = 0;
  virtual double descender(double size_px) = 0;
};

}  // namespace collide::text
