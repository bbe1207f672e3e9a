#include "app/print_options.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>

#include "core/error.hpp"
#include "core/typed_text.hpp"

namespace collide::app {
namespace {

constexpr double kCmPerInch = 2.54;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void checkDpi(const std::string& option, const std::string& typed, double dpi) {
  if (!std::isfinite(dpi) || dpi <= 0.0 || dpi > kMaxPrintDpi) {
    throw core::InputError(option + ": '" + core::echoTyped(typed) +
                           "': resolution out of range; allowed: more than 0 and at most " +
                           number(kMaxPrintDpi) + " dpi");
  }
}

void checkWidth(const std::string& option, const std::string& typed, double width_cm) {
  if (!std::isfinite(width_cm) || width_cm <= 0.0) {
    throw core::InputError(option + ": '" + core::echoTyped(typed) +
                           "': allowed: a width greater than 0 (and small enough to print: " +
                           std::to_string(kMaxFrameSize.width_px) + " px at the resolution)");
  }
}

// A number the pattern below has matched; digits past a double's range read as infinity (which
// the checks refuse) instead of std::stod's out_of_range.
double matchedNumber(const std::string& text) {
  return std::strtod(text.c_str(), nullptr);
}

// Longer than any size typed by hand: refused before the pattern is tried on it.
constexpr std::size_t kMaxPrintText = 64;

}  // namespace

void PrintOptions::addTo(CLI::App& command) {
  print_option_ = command.add_option(
      "--print", print,
      "Physical size for print, WIDTH@DPI, e.g. 8cm@300 or 3.5in@600 (cm, mm or in; DPI "
      "optional, default 300): text stays 8.5 pt or larger");
  width_option_ = command.add_option("--width-cm", width_cm,
                                     "Physical width of the figure, cm (height: --size's aspect, "
                                     "else 3:2)");
  dpi_option_ = command.add_option(
      "--dpi", dpi, "Printing resolution, dots per inch, up to 2400 (PNG pHYs; default 300)");
}

std::optional<frame::PrintSize> PrintOptions::resolve(const FrameSize& given,
                                                      const CLI::App& command) const {
  const bool size_given = command.get_option("--size")->count() > 0;
  const bool has_print = print_option_ != nullptr && print_option_->count() > 0;
  const bool has_width = width_option_ != nullptr && width_option_->count() > 0;
  const bool has_dpi = dpi_option_ != nullptr && dpi_option_->count() > 0;
  if (!has_print && !has_width && !has_dpi) return std::nullopt;
  if (has_print && (has_width || has_dpi)) {
    throw core::InputError("--print: '" + core::echoTyped(print) +
                           "': give either --print or --width-cm/--dpi, not both");
  }

  std::optional<double> width;
  double dots = kDefaultPrintDpi;
  std::string option = "--print", typed = print;
  if (has_print) {
    static const std::regex form(
        R"(^\s*([-+]?[0-9]*\.?[0-9]+)\s*(cm|mm|in)\s*(?:@\s*([-+]?[0-9]*\.?[0-9]+)\s*(?:dpi)?)?\s*$)");
    std::smatch match;
    if (print.size() > kMaxPrintText || !std::regex_match(print, match, form)) {
      throw core::InputError("--print: '" + core::echoTyped(print) +
                             "': allowed: WIDTH@DPI with the width in cm, mm or in, e.g. 8cm@300 "
                             "or 3.5in (300 dpi)");
    }
    const double value = matchedNumber(match[1]);
    const std::string unit = match[2];
    width = unit == "cm" ? value : unit == "mm" ? value / 10.0 : value * kCmPerInch;
    if (match[3].matched) dots = matchedNumber(match[3]);
    checkWidth(option, typed, *width);
  } else {
    if (has_width) {
      option = "--width-cm", typed = core::echoTyped(width_option_->results().back());
      checkWidth(option, typed, width_cm);
      width = width_cm;
    }
    if (has_dpi) {
      dots = dpi;
      const std::string typed_dpi = core::echoTyped(dpi_option_->results().back());
      if (!has_width) option = "--dpi", typed = typed_dpi;
      checkDpi("--dpi", typed_dpi, dpi);
    }
  }
  checkDpi(option, typed, dots);

  const FrameSize size = size_given || !width ? given : kPrintDefaultAspect;
  frame::PrintSize out;
  out.dots_per_inch = dots;
  if (width) {
    const double width_px = *width / kCmPerInch * dots;
    const double height_px = width_px * size.height_px / size.width_px;
    if (width_px > kMaxFrameSize.width_px || height_px > kMaxFrameSize.height_px ||
        width_px < kMinFrameSize.width_px || height_px < kMinFrameSize.height_px) {
      throw core::InputError(
          option + ": '" + core::echoTyped(typed) + "': " + number(std::round(width_px)) + "x" +
          number(std::round(height_px)) +
          " px (width in inches × dpi, --size's aspect); allowed: " +
          std::to_string(kMinFrameSize.width_px) + "x" + std::to_string(kMinFrameSize.height_px) +
          " to " + std::to_string(kMaxFrameSize.width_px) + "x" +
          std::to_string(kMaxFrameSize.height_px) + " px");
    }
    out.width_px = static_cast<int>(std::lround(width_px));
    out.height_px = static_cast<int>(std::lround(height_px));
    out.width_cm = *width;
    out.height_cm = *width * size.height_px / size.width_px;
    out.px_per_inch = out.width_px / (*width / kCmPerInch);
  } else {
    // --dpi alone: --size's pixels, printed at that resolution.
    out.width_px = size.width_px;
    out.height_px = size.height_px;
    out.px_per_inch = dots;
    out.width_cm = size.width_px / dots * kCmPerInch;
    out.height_cm = size.height_px / dots * kCmPerInch;
  }
  return out;
}

}  // namespace collide::app
