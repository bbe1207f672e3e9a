#pragma once
// How large a line of text is drawn, without GL: for laying out text outside the painter (compose
// places labels with it). Widths are exactly those the painters draw (same fonts, same shaping,
// same sizes, same sub- and superscript handling).
#include <memory>
#include <string>
#include <string_view>

#include "text/text_measure.hpp"

namespace collide::render {

// The font used when RendererOptions gives none: the one set by setDefaultFontPath() (the CLI's
// --font), else DejaVu Sans from Debian's fonts-dejavu-core.
std::string defaultFontPath();
// Sets it for every renderer and TextMetrics created afterwards; empty restores the built-in one.
void setDefaultFontPath(const std::string& path);

// fontconfig prints the errors and warnings of its configuration files on stderr as it loads
// them, on its first use in the process (a language's script font, script_fonts.hpp). They are
// caught then, and passed on to stderr only while `shown` (true until told otherwise; the CLI
// says false under -q).
void showFontconfigMessages(bool shown);

// Throws FontError (render/errors.hpp) unless `path` loads as a scalable font (lets the CLI check
// --font early).
void checkFont(const std::string& path);

class TextMetrics final : public text::TextMeasure {
 public:
  // Text in `language_tag` (empty: the active language, text/language.hpp) with `font_path` as
  // the default font and the language's script font. Throws FontError (render/errors.hpp) if
  // a font cannot be loaded, core::InputError naming the Debian package if the language's font
  // is not installed.
  explicit TextMetrics(const std::string& font_path = defaultFontPath(),
                       std::string_view language_tag = {});
  ~TextMetrics() override;
  TextMetrics(const TextMetrics&) = delete;
  TextMetrics& operator=(const TextMetrics&) = delete;

  double width(std::string_view text, double size_px) override;
  double ascender(double size_px) override;
  double descender(double size_px) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace collide::render
