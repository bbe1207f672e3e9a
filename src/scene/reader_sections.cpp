// Reads the optional tables [restitution_law], [contact] and [view].
#include <cmath>

#include "scene/field_table.hpp"
#include "scene/reader_parts.hpp"
#include "scene/scene_io.hpp"

namespace collide::scene::detail {

void readRestitutionLaw(Fields& f, RestitutionLawDesc& out) {
  f.allowOnly(sectionKeys("restitution_law"));
  const std::string kind =
      f.choice("kind", {"constant", "speed-threshold", "table"}).value_or("constant");
  if (!f.has("kind")) f.missing("kind", "'constant', 'speed-threshold' or 'table'");
  out.kind = kind == "table"             ? RestitutionLawKind::kTable
             : kind == "speed-threshold" ? RestitutionLawKind::kSpeedThreshold
                                         : RestitutionLawKind::kConstant;
  // Keys that belong to another kind are mistakes the user should hear about.
  const auto only = [&](const std::string& key, RestitutionLawKind owner, const char* owner_name) {
    if (f.has(key) && out.kind != owner) {
      f.problem(f.node(key), key,
                std::string("only with kind = '") + owner_name +
                    "'; allowed: "
                    "remove it or change kind");
    }
  };
  only("threshold_speed", RestitutionLawKind::kSpeedThreshold, "speed-threshold");
  only("exponent", RestitutionLawKind::kSpeedThreshold, "speed-threshold");
  only("table", RestitutionLawKind::kTable, "table");

  if (out.kind == RestitutionLawKind::kSpeedThreshold) {
    out.threshold_speed_mps =
        f.number("threshold_speed", fieldRange("restitution_law", "threshold_speed"))
            .value_or(out.threshold_speed_mps);
    out.exponent =
        f.number("exponent", fieldRange("restitution_law", "exponent")).value_or(out.exponent);
  }
  if (out.kind != RestitutionLawKind::kTable) return;
  const std::string allowed =
      "allowed: [[speed, e], ...] with 1 to 100 points, speeds in m/s from 0 and increasing, e "
      "from 0 to 1";
  const toml::node* table = f.node("table");
  if (table == nullptr) {
    f.missing("table", allowed);
    return;
  }
  const toml::array* points = table->as_array();
  if (points == nullptr || points->empty() || points->size() > 100) {
    f.problem(table, "table", "not a list of points; " + allowed);
    return;
  }
  for (const toml::node& point : *points) {
    const toml::array* pair = point.as_array();
    std::optional<double> speed, e;
    if (pair != nullptr && pair->size() == 2) {
      speed = asNumber(*pair->get(0));
      e = asNumber(*pair->get(1));
    }
    const bool ok = speed && e && std::isfinite(*speed) && std::isfinite(*e) && *speed >= 0.0 &&
                    *speed <= kMaxSpeedMps && *e >= 0.0 && *e <= 1.0 &&
                    (out.table.empty() || *speed > out.table.back().first);
    if (!ok) {
      f.problem(table, "table", "point " + valueText(point) + " is not valid; " + allowed);
      out.table.clear();
      return;
    }
    out.table.emplace_back(*speed, *e);
  }
}

void readContact(Fields& f, ContactDesc& out) {
  f.allowOnly(sectionKeys("contact"));
  if (const auto model = f.choice("model", {"impulse", "spring-damper"})) {
    out.model =
        *model == "spring-damper" ? ContactModelKind::kSpringDamper : ContactModelKind::kImpulse;
  }
  out.duration_s = f.number("duration", fieldRange("contact", "duration")).value_or(out.duration_s);
  if (const auto mode = f.choice("inelastic", {"slip", "stick"})) {
    out.inelastic = *mode == "stick" ? InelasticMode::kStick : InelasticMode::kSlip;
  }
  out.collapse_time_s = f.number("collapse_time", fieldRange("contact", "collapse_time"))
                            .value_or(out.collapse_time_s);
}

void readView(Fields& f, ViewDesc& out) {
  f.allowOnly(sectionKeys("view"));
  out.theme = f.choice("theme", {"light", "dark", "high-contrast"}).value_or(out.theme);
  if (const toml::node* chart = f.node("chart")) {
    if (chart->is_boolean()) {
      out.chart = *f.flag("chart");
    } else if (const auto quantity =
                   f.choice("chart", {"none", "energy", "momentum", "force", "speed"})) {
      out.chart = *quantity != "none";
      if (out.chart) out.chart_quantity = *quantity;
    }
  }
  out.momentum_diagram = f.flag("momentum_diagram").value_or(out.momentum_diagram);
  out.center_of_mass = f.flag("center_of_mass").value_or(out.center_of_mass);
  out.arc_trail = f.flag("arc_trail").value_or(out.arc_trail);
  out.calibration = f.flag("calibration").value_or(out.calibration);
  out.working = f.flag("working").value_or(out.working);
  out.trail_s = f.number("trail", fieldRange("view", "trail")).value_or(out.trail_s);
  out.center_of_momentum_frame =
      f.flag("center_of_momentum_frame").value_or(out.center_of_momentum_frame);
  out.slow_motion_factor =
      f.number("slow_motion", fieldRange("view", "slow_motion")).value_or(out.slow_motion_factor);
  out.strobe_rate_hz =
      f.number("strobe_rate", fieldRange("view", "strobe_rate")).value_or(out.strobe_rate_hz);
  if (const auto best = f.number("best_still", fieldRange("view", "best_still"))) {
    out.best_still_s = *best;
  }

  const toml::node* panels = f.node("panels");
  if (panels == nullptr) return;
  const std::string allowed = "allowed: {parameter = \"KEY\", values = [a, b, ...]} with 1 to " +
                              std::to_string(kMaxPanels) +
                              " numbers, KEY a scene key such as "
                              "\"restitution\" or \"body.2.mass\"";
  const toml::table* table = panels->as_table();
  const toml::array* values = table != nullptr ? table->get_as<toml::array>("values") : nullptr;
  const auto* parameter = table != nullptr ? table->get_as<std::string>("parameter") : nullptr;
  if (values == nullptr || parameter == nullptr || table->size() != 2 || values->empty() ||
      values->size() > static_cast<std::size_t>(kMaxPanels) || parameter->get().empty()) {
    f.problem(panels, "panels", "not a panel list; " + allowed);
    return;
  }
  std::vector<double> numbers;
  for (const toml::node& value : *values) {
    const std::optional<double> number = asNumber(value);
    if (!number || !std::isfinite(*number)) {
      f.problem(panels, "panels",
                "value " + valueText(value) + " is not a finite number; " + allowed);
      return;
    }
    numbers.push_back(*number);
  }
  out.panel_parameter = parameter->get();
  out.panel_values = numbers;
}

}  // namespace collide::scene::detail
