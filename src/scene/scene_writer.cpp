// SceneDesc -> TOML scene file. The same text builds every preset (scene_loader.cpp reads it back)
// and `collide presets show` prints it, so what a teacher copies is exactly what runs.
#include <cstdio>
#include <sstream>

#include "scene/scene_io.hpp"
#include "scene/toml_reader.hpp"
#include "text/translate.hpp"

namespace collide::scene {
#ifndef COLLIDE_SCENE_SCHEMA
#define COLLIDE_SCENE_SCHEMA "/usr/share/doc/collide/docs/scene.schema.json"
#endif
namespace {

// Where `cmake --install` puts docs/scene.schema.json.
constexpr const char* kSceneSchemaPath = COLLIDE_SCENE_SCHEMA;

using detail::numberText;

std::string quote(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// A position-like value: a number in 1D, [x, y] in 2D.
std::string vectorText(const core::Vec2& v, int dimensions) {
  if (dimensions == 1) return numberText(v.x());
  std::string text = "[";
  text += numberText(v.x());
  text += ", ";
  text += numberText(v.y());
  return text + "]";
}

// "key = value" padded so that the comments line up.
void line(std::ostream& out, const std::string& key, const std::string& value,
          const std::string& comment = "") {
  std::string text = key + " = " + value;
  if (!comment.empty()) {
    if (text.size() < 32) text.resize(32, ' ');
    text += "  # " + comment;
  }
  out << text << "\n";
}

std::string boolText(bool value) {
  return value ? "true" : "false";
}

void writeBodies(std::ostream& out, const SceneDesc& scene) {
  for (const BodyDesc& body : scene.bodies) {
    const bool disk = body.shape == "disk";
    out << "\n[[body]]\n";
    line(out, "name", quote(body.name));
    line(out, "shape", quote(body.shape));
    line(out, "mass", numberText(body.mass_kg), "kg");
    line(out, disk ? "radius" : "width", numberText(body.size_m), "m");
    if (body.pivot_m && body.string_length_m) {
      line(out, "pivot", vectorText(*body.pivot_m, 2), "m, the string hangs here");
      line(out, "length", numberText(*body.string_length_m), "m, the string");
      line(out, "angle", numberText(body.string_angle_deg),
           "degrees from straight down, counter-clockwise");
    } else {
      line(out, "position", vectorText(body.position_m, scene.dimensions), "m, centre");
      if (body.pivot_m) {
        line(out, "pivot", vectorText(*body.pivot_m, 2), "m, the string hangs here");
      }
    }
    line(out, "velocity", vectorText(body.velocity_mps, scene.dimensions), "m/s");
    if (body.friction != 0.0) line(out, "friction", numberText(body.friction), "kinetic mu");
    if (body.static_friction) {
      line(out, "static_friction", numberText(*body.static_friction), "static mu");
    }
    if (body.rolling_friction != 0.0) {
      line(out, "rolling_mu", numberText(body.rolling_friction), "rolling resistance mu");
    }
    if (!body.spin.empty()) line(out, "spin", quote(body.spin), "how the cue strikes it");
    if (body.drag_linear_kgps != 0.0) {
      line(out, "drag_linear", numberText(body.drag_linear_kgps), "kg/s, F = -k v");
    }
    if (body.drag_quadratic_kgpm != 0.0) {
      line(out, "drag_quadratic", numberText(body.drag_quadratic_kgpm), "kg/m, F = -c |v| v");
    }
    if (body.color) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "#%02x%02x%02x", body.color->r & 0xff, body.color->g & 0xff,
                    body.color->b & 0xff);
      line(out, "color", quote(hex));
    }
  }
}

void writeWalls(std::ostream& out, const SceneDesc& scene) {
  for (const WallDesc& wall : scene.walls) {
    out << "\n[[wall]]\n";
    line(out, "name", quote(wall.name));
    line(out, "position", vectorText(wall.position_m, scene.dimensions), "m, a point on the wall");
    if (scene.dimensions == 1) {
      line(out, "normal", wall.normal.x() >= 0.0 ? "1" : "-1",
           wall.normal.x() >= 0.0 ? "free side to the right" : "free side to the left");
    } else {
      line(out, "normal", vectorText(wall.normal, 2), "points into the free side");
    }
    if (wall.restitution) line(out, "restitution", numberText(*wall.restitution));
  }
  if (scene.box) {
    out << "\n[box]\n";
    line(out, "min", vectorText(scene.box->min_m, scene.dimensions), "m");
    line(out, "max", vectorText(scene.box->max_m, scene.dimensions), "m");
    if (scene.box->restitution) line(out, "restitution", numberText(*scene.box->restitution));
  }
}

void writePhysicsOptions(std::ostream& out, const SceneDesc& scene) {
  for (const PairDesc& pair : scene.pairs) {
    out << "\n[[pair]]\n";
    std::string bodies = "[";
    bodies += quote(scene.bodies[pair.body_a].name);
    bodies += ", ";
    bodies += quote(scene.bodies[pair.body_b].name);
    line(out, "bodies", bodies + "]");
    line(out, "restitution", numberText(pair.restitution));
  }
  for (const ReleaseDesc& release : scene.releases) {
    out << "\n[[release]]\n";
    std::string bodies = "[";
    bodies += quote(scene.bodies[release.body_a].name);
    bodies += ", ";
    bodies += quote(scene.bodies[release.body_b].name);
    line(out, "bodies", bodies + "]", "touching at t = 0");
    line(out, "time", numberText(release.time_s), "s");
    if (release.energy_J) line(out, "energy", numberText(*release.energy_J), "J, released");
    if (release.speed_mps) line(out, "speed", numberText(*release.speed_mps), "m/s, apart");
  }
  const RestitutionLawDesc& law = scene.restitution_law;
  if (law != RestitutionLawDesc{}) {
    out << "\n[restitution_law]\n";
    switch (law.kind) {
      case RestitutionLawKind::kConstant:
        line(out, "kind", quote("constant"));
        break;
      case RestitutionLawKind::kSpeedThreshold:
        line(out, "kind", quote("speed-threshold"));
        line(out, "threshold_speed", numberText(law.threshold_speed_mps), "m/s");
        line(out, "exponent", numberText(law.exponent));
        break;
      case RestitutionLawKind::kTable: {
        line(out, "kind", quote("table"));
        std::string points = "[";
        for (std::size_t i = 0; i < law.table.size(); ++i) {
          points += i > 0 ? ", [" : "[";
          points += numberText(law.table[i].first);
          points += ", ";
          points += numberText(law.table[i].second);
          points += "]";
        }
        line(out, "table", points + "]", "[speed m/s, e]");
        break;
      }
    }
  }
  const ContactDesc& contact = scene.contact;
  const ContactDesc defaults;
  if (contact != defaults) {
    out << "\n[contact]\n";
    if (contact.model != defaults.model) {
      line(out, "model",
           quote(contact.model == ContactModelKind::kSpringDamper ? "spring-damper" : "impulse"));
    }
    if (contact.duration_s != defaults.duration_s) {
      line(out, "duration", numberText(contact.duration_s), "s, one soft contact");
    }
    if (contact.inelastic != defaults.inelastic) {
      line(out, "inelastic", quote(contact.inelastic == InelasticMode::kStick ? "stick" : "slip"));
    }
    if (contact.collapse_time_s != defaults.collapse_time_s) {
      line(out, "collapse_time", numberText(contact.collapse_time_s), "s");
    }
  }
}

void writeView(std::ostream& out, const ViewDesc& view) {
  const ViewDesc d;
  if (view == d) return;
  out << "\n[view]\n";
  if (view.theme != d.theme) line(out, "theme", quote(view.theme));
  if (!view.panel_values.empty()) {
    std::string values;
    for (std::size_t i = 0; i < view.panel_values.size(); ++i) {
      if (i > 0) values += ", ";
      values += numberText(view.panel_values[i]);
    }
    line(out, "panels",
         "{ parameter = " + quote(view.panel_parameter) + ", values = [" + values + "] }");
  }
  if (view.chart != d.chart || view.chart_quantity != d.chart_quantity) {
    line(out, "chart", view.chart ? quote(view.chart_quantity) : quote("none"));
  }
  if (view.momentum_diagram != d.momentum_diagram) {
    line(out, "momentum_diagram", boolText(view.momentum_diagram));
  }
  if (view.arc_trail != d.arc_trail) line(out, "arc_trail", boolText(view.arc_trail));
  if (view.calibration != d.calibration) line(out, "calibration", boolText(view.calibration));
  if (view.working != d.working) line(out, "working", boolText(view.working));
  if (view.center_of_mass != d.center_of_mass) {
    line(out, "center_of_mass", boolText(view.center_of_mass));
  }
  if (view.trail_s != d.trail_s) line(out, "trail", numberText(view.trail_s), "s");
  if (view.center_of_momentum_frame != d.center_of_momentum_frame) {
    line(out, "center_of_momentum_frame", boolText(view.center_of_momentum_frame));
  }
  if (view.slow_motion_factor != d.slow_motion_factor) {
    line(out, "slow_motion", numberText(view.slow_motion_factor), "times slower near collisions");
  }
  if (view.strobe_rate_hz != d.strobe_rate_hz) {
    line(out, "strobe_rate", numberText(view.strobe_rate_hz), "images per second");
  }
  if (view.best_still_s) {
    line(out, "best_still", numberText(*view.best_still_s), "s: the still shown for the strobe");
  }
}

}  // namespace

std::string sceneToToml(const SceneDesc& scene) {
  std::ostringstream out;
  line(out, "name", quote(scene.name));
  line(out, "title", quote(scene.title_template.empty() ? scene.title : scene.title_template));
  if (!scene.lang.empty()) line(out, "lang", quote(scene.lang), "language of the pictures' words");
  line(out, "dimensions", std::to_string(scene.dimensions), "1: a line, 2: a plane");
  line(out, "duration", numberText(scene.duration_s), "s");
  line(out, "gravity", vectorText(scene.gravity_mps2, scene.dimensions), "m/s^2");
  line(out, "restitution", numberText(scene.restitution), "default e for every pair");
  if (scene.rolling) line(out, "rolling", "true", "balls on a cloth: they slide, then roll");
  if (scene.super_elastic) {
    line(out, "super_elastic", "true", "e above 1: impacts release stored energy");
  }
  if (scene.string_restitution != 0.0) {
    line(out, "string_restitution", numberText(scene.string_restitution),
         "e of a string snapping taut");
  }
  if (scene.surface_gravity_mps2 != SceneDesc{}.surface_gravity_mps2) {
    line(out, "surface_gravity", numberText(scene.surface_gravity_mps2),
         "m/s^2, presses the bodies onto the surface");
  }
  if (scene.internal_dof != 0) {
    line(out, "internal", std::to_string(scene.internal_dof), "internal degrees of freedom");
  }
  writeBodies(out, scene);
  writeWalls(out, scene);
  writePhysicsOptions(out, scene);
  writeView(out, scene.view);
  return out.str();
}

std::string presetToml(const std::string& name, const std::string& lang) {
  const PresetInfo* info = findPreset(name);
  if (info == nullptr) throwUnknownPreset(name);
  SceneDesc scene = makePreset(name, {});
  scene.lang = lang;
  std::ostringstream out;
  // Taplo (Even Better TOML) reads the schema named on the first line: keys, units and limits
  // are completed and checked as the file is edited.
  out << "#:schema " << kSceneSchemaPath << "\n";
  out << "# " << info->name << ": " << text::tr(info->summary) << "\n";
  out << "# Copy this file, edit it and run: collide render FILE.toml -o out.mp4\n";
  out << "# Every key is described in docs/scene-format.md.\n";
  if (info->parameters.empty()) {
    out << "\n" << sceneToToml(scene);
    return out.str();
  }
  out << "#\n# The scene is built from its parameters; change them here or with --set "
         "NAME=VALUE.\n";
  out << "preset = " << quote(name) << "\n";
  if (!lang.empty()) line(out, "lang", quote(lang), "language of the pictures' words");
  for (const PresetParameter& p : info->parameters) {
    const auto text = [&](double v) {
      return p.integer ? std::to_string(static_cast<long long>(v)) : numberText(v);
    };
    line(out, p.name, text(p.default_value),
         text::tr(p.description) + ", " + text(p.min) + " to " + text(p.max));
  }
  out << "\n# What these parameters generate. Any key set in this file replaces the generated\n"
         "# one ([[body]], [[wall]] and [[pair]] lists as a whole; [view], [contact], [box] and\n"
         "# [restitution_law] key by key).\n#\n";
  std::istringstream generated(sceneToToml(scene));
  for (std::string text; std::getline(generated, text);) {
    out << (text.empty() ? "#" : "# ") << text << "\n";
  }
  return out.str();
}

}  // namespace collide::scene
