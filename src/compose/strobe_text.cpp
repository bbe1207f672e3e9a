#include "compose/strobe_text.hpp"

#include <algorithm>
#include <cmath>

#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::compose {

std::string strobeSpanText(double duration_s, const text::QuantityFormat& time) {
  const double value = duration_s / time.unit_value;
  int decimals = 0;
  while (decimals < std::max(0, time.decimals)) {
    const double scale = std::pow(10.0, decimals);
    if (std::abs(std::round(value * scale) - value * scale) <= 1e-6) break;
    ++decimals;
  }
  text::QuantityFormat end = time;
  end.decimals = std::min(decimals, std::max(0, time.decimals));
  // The start is t = 0 exactly: "0", whatever decimals the end needs ("t = 0–0.517 s").
  text::QuantityFormat start = end;
  start.unit.clear();
  start.decimals = 0;
  // TRANSLATORS: a stroboscopic picture's time span, "t = 0–12.5 s": a range with an en dash,
  // closed up. It stands in the header beside the picture's title, so keep it as short as the
  // language allows (" to " in words left a long title 4 px short of one line at 1280x720).
  return text::fill(text::tr("{symbol} = {start}–{end}"),
                    {{"symbol", text::symbol(text::Symbol::kTime)},
                     {"start", text::formatReading(0.0, start)},
                     {"end", text::formatReading(duration_s, end)}});
}

StrobeRelease strobeRelease(const physics::Timeline& timeline, double span_s,
                            const text::QuantityFormat& time) {
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    if (event.time_s > span_s) break;
    if (!event.release) continue;
    const std::vector<physics::BodyDef>& bodies = timeline.world().bodies;
    const std::string& a = bodies[std::size_t(event.body_a)].name;
    const std::string& b = bodies[std::size_t(event.body_b)].name;
    const std::string at =
        text::equation(text::symbol(text::Symbol::kTime), text::formatReading(event.time_s, time));
    if (event.velocity_a_before_mps.isZero(0.0) && event.velocity_b_before_mps.isZero(0.0)) {
      // TRANSLATORS: a clause of a stroboscopic picture's caption where stored energy (a
      // spring, a shot) pushes two bodies apart: {a} and {b} are their names, {time} is
      // "t = 0.500 s". Keep it short: the caption has two lines.
      return {text::fill(text::tr("{a} and {b} start together at rest, pushed apart at {time}"),
                         {{"a", a}, {"b", b}, {"time", at}}),
              true};
    }
    // TRANSLATORS: as "{a} and {b} start together at rest, pushed apart at {time}", for bodies
    // that were moving together.
    return {text::fill(text::tr("{a} and {b} are pushed apart at {time}"),
                       {{"a", a}, {"b", b}, {"time", at}}),
            false};
  }
  return {};
}

std::string strobeCaption(double rate_hz, int images, bool overlaps_left_out, bool marked_gas,
                          int impact_images, const StrobeRelease& release, int release_images) {
  const std::string count = text::formatScaled(images, 0);
  const double whole = std::round(rate_hz);
  std::string caption;
  if (whole >= 1.0 && std::abs(rate_hz - whole) <= 1e-9 * rate_hz) {
    caption = text::fill(
        // TRANSLATORS: a stroboscopic picture's caption; {rate} is a whole number of images per
        // second such as "25" (the plural goes by it), {count} the number of flashes.
        text::trn("Stroboscopic image: {rate} image per second ({count} in all), earlier images "
                  "fainter",
                  "Stroboscopic image: {rate} images per second ({count} in all), earlier images "
                  "fainter",
                  static_cast<unsigned long>(whole)),
        {{"rate", text::formatPlain(whole)}, {"count", count}});
  } else {
    caption = text::fill(
        // TRANSLATORS: a stroboscopic picture's caption when the rate is not a whole number;
        // {interval} is the time between images with its unit, e.g. "0.4 s".
        text::tr("Stroboscopic image: one image every {interval} ({count} in all), earlier "
                 "images fainter"),
        {{"interval", text::formatPlain(1.0 / rate_hz) + " s"}, {"count", count}});
  }
  if (marked_gas) {
    // TRANSLATORS: a clause after the caption of a gas's stroboscopic picture: only a few
    // molecules, drawn in colour, are shown at every flash with the path each one took.
    caption += text::clauseSeparator() + text::tr("marked molecules with their paths");
    // TRANSLATORS: the clause after "marked molecules with their paths": the other molecules of
    // the gas are drawn only once, pale, where they are at the end.
    caption +=
        text::clauseSeparator() + text::tr("the rest of the gas drawn once, faint, at the end");
  }
  if (!release.text.empty()) caption += text::clauseSeparator() + release.text;
  if (release_images > 0 && !release.from_rest) {
    caption += text::clauseSeparator() +
               text::fill(
                   // TRANSLATORS: a clause after a stroboscopic picture's caption: the bodies
                   // pushed apart by stored energy are drawn at the instant of the push.
                   text::trn("{count} more image at the instant of the push",
                             "{count} more images at the instants of the pushes",
                             static_cast<unsigned long>(release_images)),
                   {{"count", text::formatScaled(release_images, 0)}});
  }
  if (impact_images > 0) {
    caption += text::clauseSeparator() +
               text::fill(
                   // TRANSLATORS: a clause after a stroboscopic picture's caption: besides the
                   // regular flashes, the colliding bodies are drawn at the instant they meet.
                   text::trn("{count} more image at the instant of a collision",
                             "{count} more images at the instants of collisions",
                             static_cast<unsigned long>(impact_images)),
                   {{"count", text::formatScaled(impact_images, 0)}});
  }
  if (!overlaps_left_out) return caption;
  // TRANSLATORS: a clause after a stroboscopic picture's caption when some images of a body that
  // slows down were not drawn because they would overlap its other images.
  return caption + text::clauseSeparator() + text::tr("images that would overlap left out");
}

}  // namespace collide::compose
