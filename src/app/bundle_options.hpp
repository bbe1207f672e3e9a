#pragma once
// --latex and --markdown: what a teacher pastes into lecture notes beside a picture, written beside
// it (report/figure_bundle.hpp makes the text).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "report/figure_bundle.hpp"

namespace collide::app {

struct BundleOptions {
  bool latex = false;     // --latex: NAME.tex beside the picture
  bool markdown = false;  // --markdown: NAME.md beside the picture

  void addTo(CLI::App& command);
  // Writes the bundles asked for beside bundle.image_path; returns the paths written.
  std::vector<std::string> write(const report::FigureBundle& bundle) const;
};

}  // namespace collide::app
