#include "app/bundle_options.hpp"

#include <iostream>

#include "output/output_target.hpp"
#include "output/text_output.hpp"

namespace collide::app {

void BundleOptions::addTo(CLI::App& command) {
  command.add_flag("--latex", latex,
                   "Also write NAME.tex: a LaTeX figure with the image, caption and alt text");
  command.add_flag("--markdown", markdown,
                   "Also write NAME.md: the Markdown image line with the alt text");
}

std::vector<std::string> BundleOptions::write(const report::FigureBundle& bundle) const {
  std::vector<std::string> written;
  if (latex) {
    const std::string path = output::besidePath(bundle.image_path, ".tex");
    output::writeTextOutput(path, std::cout,
                            [&](std::ostream& out) { out << report::latexFigure(bundle); });
    written.push_back(path);
  }
  if (markdown) {
    const std::string path = output::besidePath(bundle.image_path, ".md");
    output::writeTextOutput(path, std::cout,
                            [&](std::ostream& out) { out << report::markdownFigure(bundle); });
    written.push_back(path);
  }
  return written;
}

}  // namespace collide::app
