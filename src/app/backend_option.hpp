#pragma once
// --backend osmesa|egl|gpu|auto on every rendering command.
#include <CLI/CLI.hpp>
#include <string>

namespace collide::app {

struct BackendOption {
  std::string name;  // empty: the default (OSMesa, or $COLLIDE_BACKEND)
  void addTo(CLI::App& command);
  // Makes the chosen backend the process-wide default for renderers. Throws core::InputError for
  // an unknown name.
  void apply() const;
};

}  // namespace collide::app
