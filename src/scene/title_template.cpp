#include "scene/title_template.hpp"

#include "scene/override_apply.hpp"
#include "scene/scene_io.hpp"
#include "text/number_format.hpp"

namespace collide::scene::detail {
namespace {

// The scalar at a key path such as "body.2.mass" (1-based indices into arrays of tables).
const toml::node* find(const toml::table& root, const std::string& key) {
  const toml::node* node = &root;
  std::size_t start = 0;
  while (node != nullptr && start <= key.size()) {
    const std::size_t dot = std::min(key.find('.', start), key.size());
    const std::string part = key.substr(start, dot - start);
    start = dot + 1;
    if (const toml::table* table = node->as_table()) {
      node = table->get(part);
    } else if (const toml::array* array = node->as_array()) {
      const bool digits = !part.empty() && part.size() < 7 &&
                          part.find_first_not_of("0123456789") == std::string::npos;
      const std::size_t index = digits ? std::stoul(part) : 0;
      node = index >= 1 && index <= array->size() ? array->get(index - 1) : nullptr;
    } else {
      return nullptr;
    }
  }
  return node != nullptr && (node->is_number() || node->is_string() || node->is_boolean())
             ? node
             : nullptr;
}

std::string text(const toml::node& node) {
  // A typed value as typed, in the reader's way of writing numbers ("e = 0,5" in German).
  if (const auto* i = node.as_integer()) return text::typedNumber(std::to_string(i->get()));
  if (const auto* f = node.as_floating_point()) return text::typedNumber(plainNumber(f->get()));
  if (const auto* s = node.as_string()) return s->get();
  return node.as_boolean()->get() ? "true" : "false";
}

}  // namespace

std::string fillTitle(const std::string& title, const SceneDesc& scene, std::string& problem) {
  const std::string allowed =
      "; allowed: {KEY} with a scene key such as {restitution} or {body.2.mass}, and {{ or }} "
      "for a brace";
  // Every value, defaults included, as the writer spells them. The title itself is left out so
  // that it cannot refer to itself.
  SceneDesc plain = scene;
  plain.title = plain.title_template = "";
  const toml::table values = parseToml(sceneToToml(plain), "");
  std::string out;
  for (std::size_t i = 0; i < title.size(); ++i) {
    const char c = title[i];
    if ((c == '{' || c == '}') && i + 1 < title.size() && title[i + 1] == c) {
      out += c;
      ++i;
    } else if (c == '{') {
      const std::size_t close = title.find('}', i);
      if (close == std::string::npos) {
        problem = "'{' without '}'" + allowed;
        return "";
      }
      const std::string key = title.substr(i + 1, close - i - 1);
      const toml::node* value = find(values, key);
      if (value == nullptr || key == "title") {
        problem = "{" + key + "} names no value of this scene" + allowed;
        return "";
      }
      out += text(*value);
      i = close;
    } else if (c == '}') {
      problem = "'}' without '{'" + allowed;
      return "";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace collide::scene::detail
