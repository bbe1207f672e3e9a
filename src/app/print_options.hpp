#pragma once
// The physical size of a figure for print: --print WIDTH@DPI (e.g. 8cm@300), or --width-cm and
// --dpi. The frame is laid out at that many pixels, with text no smaller than print legibility
// asks (frame::kPrintTextFloor_pt); a PNG records the resolution in its pHYs chunk, an SVG or PDF
// gets a page of exactly that width.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "app/render_settings.hpp"
#include "frame/print_layout.hpp"

namespace collide::app {

inline constexpr double kDefaultPrintDpi = 300.0;  // when only a width is given
inline constexpr double kMaxPrintDpi = 2400.0;
// A printed figure's shape when --size is not given: 3:2 leaves room for legible labels at 8 cm
// wide, where 16:9 squeezes the scene between them.
inline constexpr FrameSize kPrintDefaultAspect{1500, 1000};

struct PrintOptions {
  std::string print;      // "WIDTH@DPI": WIDTH a number with cm, mm or in; "@DPI" optional
  double width_cm = 0.0;  // --width-cm
  double dpi = 0.0;       // --dpi

  void addTo(CLI::App& command);
  // The figure's physical size for a picture of `size` (whose aspect ratio it keeps; where
  // `command` was given no --size, kPrintDefaultAspect's), or none when no option was given.
  // Throws core::InputError naming the option, the value and what is allowed.
  std::optional<frame::PrintSize> resolve(const FrameSize& size, const CLI::App& command) const;

 private:
  CLI::Option* print_option_ = nullptr;
  CLI::Option* width_option_ = nullptr;
  CLI::Option* dpi_option_ = nullptr;
};

}  // namespace collide::app
