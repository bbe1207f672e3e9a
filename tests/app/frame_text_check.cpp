#include "frame_text_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <numbers>
#include <regex>

namespace collide::test {
namespace {

// Building blocks of the grammars (UTF-8 spelled out: std::regex works on bytes, so multi-byte
// characters appear only as literal sequences, never inside brackets).
const std::string kSign = "(\\+|\u2212)?";  // "+" or a true minus sign; a hyphen never reads
const std::string kNumber = kSign + "([0-9]+(?:\\.[0-9]+)?)";  // 2 groups
const std::string kUnsigned = "([0-9]+(?:\\.[0-9]+)?)";        // 1 group
const std::string kSubscript =
    "((?:\u2080|\u2081|\u2082|\u2083|\u2084|\u2085|\u2086|\u2087|"
    "\u2088|\u2089)+)";                  // 1 group
const std::string kPrime = "(\u2032)?";  // 1 group
const std::string kMomentumUnit = " kg\u00b7m/s";
const std::string kEnergyUnit = "(\u00b5J|mJ|J|kJ|MJ)";  // 1 group: one SI prefix per picture

double energyUnit(const std::string& unit) {
  if (unit == "\u00b5J") return 1e-6;
  if (unit == "mJ") return 1e-3;
  if (unit == "kJ") return 1e3;
  if (unit == "MJ") return 1e6;
  return 1.0;
}

// A number as shown: its sign character, magnitude and number of decimals.
struct Shown {
  int sign = 0;  // +1 for "+", -1 for "−", 0 for none
  double magnitude = 0.0;
  int decimals = 0;
  double value() const { return sign < 0 ? -magnitude : magnitude; }
};

Shown shown(const std::string& sign, const std::string& digits) {
  Shown s;
  s.sign = sign.empty() ? 0 : sign == "+" ? 1 : -1;
  s.magnitude = std::stod(digits);
  const std::size_t dot = digits.find('.');
  s.decimals = dot == std::string::npos ? 0 : static_cast<int>(digits.size() - dot - 1);
  return s;
}

int subscriptValue(const std::string& text) {
  // Each subscript digit is three bytes, E2 82 80 + d.
  int value = 0;
  for (std::size_t i = 0; i + 2 < text.size(); i += 3) {
    value = 10 * value + (static_cast<unsigned char>(text[i + 2]) - 0x80);
  }
  return value;
}

// The subscript digits of n (n >= 0), e.g. 12 -> "₁₂".
std::string subscriptOf(int n) {
  std::string digits = std::to_string(n), out;
  for (char d : digits) out += std::string{'\xE2', '\x82', static_cast<char>(0x80 + (d - '0'))};
  return out;
}

enum class SignRule {
  kPlusForPositive,  // 1D velocities and momenta: "+2.00", "−1.00", "0.00"
  kMinusOnly,        // everything else: "2.00", "−78"
};

class Checker {
 public:
  explicit Checker(const FrameTruth& truth) : truth_(truth) {}
  int compared() const { return compared_; }

  // A shown number against the expected value: within half a unit of its last digit, with the
  // sign the rule asks for (none on a value shown as zero).
  void number(const Shown& s, double expected, SignRule rule, const std::string& where) {
    ++compared_;
    const double half_unit = 0.5 * std::pow(10.0, -s.decimals);
    EXPECT_LE(std::abs(s.value() - expected), half_unit * (1.0 + 1e-9) + 1e-12)
        << where << ": shows " << s.value() << " with " << s.decimals
        << " decimals; the physics says " << expected;
    if (s.magnitude == 0.0) {
      EXPECT_EQ(s.sign, 0) << where << ": a zero carries no sign";
    } else if (expected < 0.0) {
      EXPECT_EQ(s.sign, -1) << where << ": negative (" << expected << ") needs a minus sign";
    } else {
      EXPECT_EQ(s.sign, rule == SignRule::kPlusForPositive ? 1 : 0)
          << where << ": positive (" << expected << ") "
          << (rule == SignRule::kPlusForPositive ? "needs a plus sign" : "carries no sign");
    }
  }

  // A part of the energy bar: the parts are rounded together so they add up to the total as
  // shown (largest remainder), so each is within one unit of its last digit, not half a unit.
  void part(const Shown& s, double expected, const std::string& where) {
    ++compared_;
    EXPECT_LT(std::abs(s.value() - expected), std::pow(10.0, -s.decimals) * (1.0 + 1e-9))
        << where << ": shows " << s.value() << " with " << s.decimals
        << " decimals; the physics says " << expected;
  }

  // An angle in degrees, compared on the circle.
  void angle(const Shown& s, double expected_deg, const std::string& where) {
    ++compared_;
    double difference = std::fmod(s.value() - expected_deg + 540.0, 360.0) - 180.0;
    EXPECT_LE(std::abs(difference), 0.5 * std::pow(10.0, -s.decimals) + 1e-9)
        << where << ": shows " << s.value() << "°; the physics says " << expected_deg << "°";
    EXPECT_NE(s.sign, 1) << where << ": angles carry no plus sign";
  }

  // "v₁′ = +0.25 m/s" (1D) or "v₁′ = 0.75 m/s, 60°" (2D): the body, prime, value and unit.
  void velocity(const std::smatch& m, std::size_t first, const std::string& where) {
    const int index = subscriptValue(m[first]);
    ASSERT_GE(index, 1) << where;
    ASSERT_LE(static_cast<std::size_t>(index), panel_->bodies.size()) << where;
    const BodyTruth& body = panel_->bodies[index - 1];
    EXPECT_EQ(m[first + 1].matched, body.collided)
        << where << ": v" << index << (body.collided ? " has collided: primed" : " not yet");
    if (truth_.dimensions == 1) {
      number(shown(m[first + 2], m[first + 3]), body.velocity_mps.x(), SignRule::kPlusForPositive,
             where);
      EXPECT_FALSE(m[first + 5].matched) << where << ": 1D velocities have no direction";
      return;
    }
    number(shown(m[first + 2], m[first + 3]), body.velocity_mps.norm(), SignRule::kMinusOnly,
           where + " (speed)");
    const bool moving = body.velocity_mps.norm() > 5e-3;  // shown as more than 0.00 m/s
    ASSERT_EQ(m[first + 5].matched, moving) << where << ": a direction iff moving";
    if (moving) {
      const double degrees =
          std::atan2(body.velocity_mps.y(), body.velocity_mps.x()) * 180.0 / std::numbers::pi;
      angle(shown(m[first + 4], m[first + 5]), degrees, where + " (direction)");
    }
  }

  // "+1.00 kg·m/s" (1D) or "(0.36, −1.77) kg·m/s" (2D) at groups [first, first + 4).
  void momentum(const std::smatch& m, std::size_t first, const core::Vec2& expected,
                const std::string& where) {
    if (truth_.dimensions == 1) {
      number(shown(m[first], m[first + 1]), expected.x(), SignRule::kPlusForPositive, where);
      return;
    }
    number(shown(m[first], m[first + 1]), expected.x(), SignRule::kMinusOnly, where + " x");
    number(shown(m[first + 2], m[first + 3]), expected.y(), SignRule::kMinusOnly, where + " y");
  }

  std::string momentumPattern() const {
    if (truth_.dimensions == 1) return kNumber + "()()" + kMomentumUnit;
    return "\\(" + kNumber + ", " + kNumber + "\\)" + kMomentumUnit;
  }

  void checkFrame(const frame::FrameModel& frame) {
    EXPECT_EQ(frame.title, truth_.title);
    std::smatch m;
    const std::regex time_pattern("t = " + kNumber + " s");
    ASSERT_TRUE(std::regex_match(frame.time_readout, m, time_pattern)) << frame.time_readout;
    number(shown(m[1], m[2]), truth_.t_s, SignRule::kMinusOnly, "time readout");
    // No slow motion in these scenes: nothing under the time.
    EXPECT_EQ(frame.subtitle, "");
    ASSERT_EQ(frame.panels.size(), truth_.panels.size());
    for (std::size_t i = 0; i < frame.panels.size(); ++i) {
      panel_ = &truth_.panels[i];
      SCOPED_TRACE("panel " + std::to_string(i));
      checkPanel(frame.panels[i]);
    }
    EXPECT_TRUE(frame.charts.empty()) << "charts are checked by their own tests";
  }

 private:
  core::Vec2 momentumNow() const {
    core::Vec2 p(0.0, 0.0);
    for (const BodyTruth& body : panel_->bodies) p += body.mass_kg * body.velocity_mps;
    return p;
  }

  void checkPanel(const frame::PanelModel& panel) {
    EXPECT_EQ(panel.heading, panel_->heading);
    checkInfo(panel.info);
    ASSERT_EQ(panel.bodies.size(), panel_->bodies.size());
    for (std::size_t b = 0; b < panel.bodies.size(); ++b) checkBody(panel, b);
    EXPECT_TRUE(panel.ghosts.empty());
    checkEnergyBar(panel.energy_bar);
    checkMomentumDiagram(panel);
    checkCaption(panel.caption);
  }

  // "collisions: 1   Σp: start +1.00 kg·m/s, now +1.00 kg·m/s", or "… Σp = +2.00 kg·m/s".
  void checkInfo(const std::string& info) {
    std::smatch m;
    const std::regex both("collisions: ([0-9]+)   \u03a3p: start " + momentumPattern() + ", now " +
                          momentumPattern());
    const std::regex one("collisions: ([0-9]+)   \u03a3p = " + momentumPattern());
    if (std::regex_match(info, m, both)) {
      momentum(m, 2, panel_->momentum_start_Ns, "info Σp at the start");
      momentum(m, 6, momentumNow(), "info Σp now");
    } else if (std::regex_match(info, m, one)) {
      // One figure stands for both: it must be right at the start and now.
      momentum(m, 2, panel_->momentum_start_Ns, "info Σp (start)");
      momentum(m, 2, momentumNow(), "info Σp (now)");
    } else {
      ADD_FAILURE() << "info line reads as neither form: " << info;
      return;
    }
    ++compared_;
    EXPECT_EQ(std::stoi(m[1]), panel_->collisions) << info;
  }

  void checkBody(const frame::PanelModel& panel, std::size_t b) {
    const frame::BodyModel& body = panel.bodies[b];
    const std::string where = "body " + std::to_string(b + 1);
    const BodyTruth& truth = panel_->bodies[b];
    EXPECT_NEAR((body.velocity_mps - truth.velocity_mps).norm(), 0.0, 1e-9) << where << " arrow";
    if (body.moves_with >= 0) {
      // Riding on another body as one (stuck at e = 0): that body's labels speak for both.
      ASSERT_LT(static_cast<std::size_t>(body.moves_with), panel.bodies.size());
      EXPECT_EQ(panel.bodies[body.moves_with].moves_with, -1) << where;
      EXPECT_NEAR((truth.velocity_mps - panel_->bodies[body.moves_with].velocity_mps).norm(), 0.0,
                  1e-9)
          << where << " moves with body " << body.moves_with + 1;
      EXPECT_TRUE(body.label.empty() && body.velocity_label.empty()) << where;
      return;
    }
    // A body others ride on is named with them, in body order: "m₁ + m₂ = 1.01 kg",
    // "v₁′ = v₂′ = +1.98 m/s"; each name is read off and the rest checked as one body's label.
    // A text that gave way to the panel's legend is read there (a wrapped one from its lines).
    const auto stated = [&](const std::string& by_body, bool mass) {
      if (!by_body.empty()) return by_body;
      std::string listed;
      for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
        if (entry.body != static_cast<int>(b) || entry.mass != mass) continue;
        listed += (listed.empty() ? "" : " ") + entry.text;
      }
      return listed;
    };
    std::string label = stated(body.label, true),
                velocity_label = stated(body.velocity_label, false);
    double mass_kg = 0.0;
    for (std::size_t k = 0; k < panel.bodies.size(); ++k) {
      if (k != b && panel.bodies[k].moves_with != static_cast<int>(b)) continue;
      mass_kg += panel_->bodies[k].mass_kg;
      if (k == b) continue;
      const std::string mass_name = "m" + subscriptOf(static_cast<int>(k) + 1);
      const std::string velocity_name =
          "v" + subscriptOf(static_cast<int>(k) + 1) + (panel_->bodies[k].collided ? "\u2032" : "");
      if (k < b) {
        EXPECT_EQ(label.rfind(mass_name + " + ", 0), 0u) << where << ": " << body.label;
        EXPECT_EQ(velocity_label.rfind(velocity_name + " = ", 0), 0u)
            << where << ": " << body.velocity_label;
        label.erase(0, std::min(label.size(), mass_name.size() + 3));
        velocity_label.erase(0, std::min(velocity_label.size(), velocity_name.size() + 3));
      } else {
        const std::size_t at = label.find(" + " + mass_name);
        EXPECT_NE(at, std::string::npos) << where << ": " << body.label;
        if (at != std::string::npos) label.erase(at, mass_name.size() + 3);
        const std::size_t v_at = velocity_label.find(" = " + velocity_name + " = ");
        EXPECT_NE(v_at, std::string::npos) << where << ": " << body.velocity_label;
        if (v_at != std::string::npos) velocity_label.erase(v_at, velocity_name.size() + 3);
      }
    }
    std::smatch m;
    const std::regex mass("m" + kSubscript + " = " + kNumber + " kg");
    if (std::regex_match(label, m, mass)) {
      EXPECT_EQ(subscriptValue(m[1]), static_cast<int>(b + 1)) << body.label;
      number(shown(m[2], m[3]), mass_kg, SignRule::kMinusOnly, where + " mass label");
    } else {
      ADD_FAILURE() << where << " label unread: " << body.label;
    }
    const std::regex velocity_pattern(velocityPattern());
    if (std::regex_match(velocity_label, m, velocity_pattern)) {
      EXPECT_EQ(subscriptValue(m[1]), static_cast<int>(b + 1)) << body.velocity_label;
      velocity(m, 1, where + " velocity label \"" + body.velocity_label + "\"");
    } else {
      ADD_FAILURE() << where << " velocity label unread: " << body.velocity_label;
    }
    EXPECT_TRUE(body.tag.empty() || body.tag == std::to_string(b + 1)) << body.tag;
  }

  // Groups: index, prime, sign, magnitude, and in 2D an optional direction (sign, magnitude).
  std::string velocityPattern() const {
    return "v" + kSubscript + kPrime + " = " + kNumber + " m/s(?:, " + kNumber + "\u00b0)?";
  }

  void checkEnergyBar(const frame::EnergyBar& bar) {
    EXPECT_EQ(bar.title.find_first_of("0123456789"), std::string::npos) << bar.title;
    const std::regex kinetic("KE" + kSubscript + " " + kUnsigned + " " + kEnergyUnit);
    const std::regex potential("PE " + kUnsigned + " " + kEnergyUnit);
    const std::regex lost("lost " + kUnsigned + " " + kEnergyUnit);
    std::vector<bool> seen(panel_->bodies.size(), false);
    bool seen_potential = false, seen_lost = false;
    // A segment of zero width has no legend entry ("lost 0 J" would point at nothing).
    const double zero_J = 1e-9 * bar.full_scale_J;
    for (const frame::EnergySegment& segment : bar.segments) {
      std::smatch m;
      double expected = 0.0;
      if (segment.label.empty()) {
        EXPECT_LE(segment.energy_J, zero_J) << "a segment with width but no legend entry";
        continue;
      }
      if (std::regex_match(segment.label, m, kinetic)) {
        const int index = subscriptValue(m[1]);
        ASSERT_GE(index, 1) << segment.label;
        ASSERT_LE(static_cast<std::size_t>(index), seen.size()) << segment.label;
        seen[index - 1] = true;
        const BodyTruth& body = panel_->bodies[index - 1];
        expected = 0.5 * body.mass_kg * body.velocity_mps.squaredNorm();
        part(shown("", m[2]), expected / energyUnit(m[3]), segment.label);
      } else if (std::regex_match(segment.label, m, potential)) {
        ASSERT_TRUE(panel_->potential_J.has_value()) << "no gravity, yet " << segment.label;
        seen_potential = true;
        expected = *panel_->potential_J;
        part(shown("", m[1]), expected / energyUnit(m[2]), segment.label);
      } else if (std::regex_match(segment.label, m, lost)) {
        seen_lost = true;
        expected = panel_->lost_J;
        part(shown("", m[1]), expected / energyUnit(m[2]), segment.label);
      } else {
        ADD_FAILURE() << "energy bar label unread: " << segment.label;
        continue;
      }
      // The segment's length is the same energy.
      EXPECT_NEAR(segment.energy_J, expected, 1e-9 * (1.0 + panel_->energy_start_J))
          << segment.label;
    }
    for (std::size_t b = 0; b < seen.size(); ++b) {
      const BodyTruth& body = panel_->bodies[b];
      const double kinetic_J = 0.5 * body.mass_kg * body.velocity_mps.squaredNorm();
      EXPECT_TRUE(seen[b] || kinetic_J <= zero_J) << "no KE of body " << b + 1;
    }
    if (panel_->potential_J.has_value()) {
      EXPECT_TRUE(seen_potential || *panel_->potential_J <= zero_J) << "no potential energy";
    } else {
      EXPECT_FALSE(seen_potential) << "potential energy segment without gravity";
    }
    EXPECT_TRUE(seen_lost || panel_->lost_J <= zero_J) << "no energy lost segment";
  }

  void checkMomentumDiagram(const frame::PanelModel& panel) {
    ASSERT_EQ(panel.momentum.has_value(), panel_->momentum_diagram);
    if (!panel.momentum) return;
    EXPECT_EQ(panel.momentum->sum_label, "\u03a3p");
    ASSERT_EQ(panel.momentum->arrows.size(), panel_->bodies.size());
    for (std::size_t b = 0; b < panel_->bodies.size(); ++b) {
      const frame::MomentumArrow& arrow = panel.momentum->arrows[b];
      static const char* const kLabels[] = {"p₁", "p₂", "p₃", "p₄", "p₅"};
      ASSERT_LT(b, std::size(kLabels));
      EXPECT_EQ(arrow.label, kLabels[b]);
      const BodyTruth& body = panel_->bodies[b];
      EXPECT_NEAR((arrow.momentum_Ns - body.mass_kg * body.velocity_mps).norm(), 0.0, 1e-9)
          << arrow.label;
    }
  }

  // "t = 2.500 s: energy lost 1.69 J of 2.50 J (67.5%); v₁′ = −0.25 m/s, v₂′ = +1.25 m/s", or
  // with nothing lost (yet) "t = 0.000 s: no energy lost (total 2.50 J); v₁ = ...".
  void checkCaption(const std::string& caption) {
    std::smatch m;
    const std::regex none("t = " + kNumber + " s: no energy lost \\(total " + kUnsigned + " " +
                          kEnergyUnit + "\\); (.*)");
    if (std::regex_match(caption, m, none)) {
      number(shown(m[1], m[2]), truth_.t_s, SignRule::kMinusOnly, "caption time");
      // Nothing lost to the three figures of the energy at the start.
      EXPECT_LE(std::abs(panel_->lost_J), 5e-4 * panel_->energy_start_J)
          << "caption says no energy lost: " << caption;
      number(shown("", m[3]), panel_->energy_start_J / energyUnit(m[4]), SignRule::kMinusOnly,
             "caption energy at the start");
      checkCaptionVelocities(m[5]);
      return;
    }
    const std::regex form("t = " + kNumber + " s: energy lost " + kUnsigned + " " + kEnergyUnit +
                          " of " + kUnsigned + " " + kEnergyUnit + " \\(" + kUnsigned +
                          "%\\); (.*)");
    if (!std::regex_match(caption, m, form)) {
      ADD_FAILURE() << "caption unread: " << caption;
      return;
    }
    number(shown(m[1], m[2]), truth_.t_s, SignRule::kMinusOnly, "caption time");
    number(shown("", m[3]), panel_->lost_J / energyUnit(m[4]), SignRule::kMinusOnly,
           "caption energy lost");
    number(shown("", m[5]), panel_->energy_start_J / energyUnit(m[6]), SignRule::kMinusOnly,
           "caption energy at the start");
    number(shown("", m[7]), 100.0 * panel_->lost_J / panel_->energy_start_J, SignRule::kMinusOnly,
           "caption energy lost (%)");
    // An exact zero is said in words, never "0 J of 2.50 J (0%)".
    EXPECT_GT(std::abs(panel_->lost_J), 0.0) << "caption: " << caption;
    checkCaptionVelocities(m[8]);
  }

  // The velocities, one per body in order, separated by ", " and nothing else.
  void checkCaptionVelocities(const std::string& list) {
    const std::regex velocity_pattern(velocityPattern());
    std::size_t at = 0, count = 0;
    for (auto it = std::sregex_iterator(list.begin(), list.end(), velocity_pattern);
         it != std::sregex_iterator(); ++it) {
      const std::smatch& v = *it;
      EXPECT_EQ(static_cast<std::size_t>(v.position(0)), at) << "caption: " << list;
      EXPECT_EQ(subscriptValue(v[1]), static_cast<int>(count + 1)) << "caption: " << list;
      if (subscriptValue(v[1]) >= 1 &&
          static_cast<std::size_t>(subscriptValue(v[1])) <= panel_->bodies.size()) {
        velocity(v, 1, "caption \"" + v.str() + "\"");
      }
      at = v.position(0) + v.length(0) + 2;  // past ", "
      ++count;
    }
    EXPECT_EQ(count, panel_->bodies.size()) << "caption: " << list;
    EXPECT_EQ(at, list.size() + 2) << "caption has more than the velocities: " << list;
  }

  const FrameTruth& truth_;
  const PanelTruth* panel_ = nullptr;
  int compared_ = 0;
};

}  // namespace

int checkFrameText(const frame::FrameModel& frame, const FrameTruth& truth) {
  Checker checker(truth);
  checker.checkFrame(frame);
  return checker.compared();
}

}  // namespace collide::test
