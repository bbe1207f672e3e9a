// collide chart SCENE -o OUT.png [--chart energy|momentum|force]: a chart against time, alone.
#include "app/command.hpp"
#include "app/physics_warnings.hpp"
#include "app/picture_pipeline.hpp"
#include "app/scene_options.hpp"
#include "app/style_options.hpp"

namespace collide::app {
namespace {

class ChartCommand : public Command {
 public:
  explicit ChartCommand(CLI::App& root)
      : app_(*root.add_subcommand(
            "chart", "Plot energy (or momentum, or contact force) against time to a PNG")) {
    scene_.addTo(app_);
    app_.add_option("-o,--output", output_, "Output path, *.png")->required();
    size_.addTo(app_);
    style_.addTo(app_);
    app_.footer(
        "The chart plots each body's kinetic energy, the total, potential energy (with gravity)\n"
        "and the energy lost; --chart momentum plots momenta, --chart force the soft-contact "
        "force.\nExamples:\n"
        "  collide chart worked-example -o energy.png\n"
        "  collide chart soft-contact -o force.png --chart force");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    PictureRequest request{scene_.load(), size_.parse(), stillTarget(output_)};
    style_.applyTo(request.scene);
    if (style_.chart.empty() && !request.scene.view.chart) {
      request.scene.view.chart_quantity = "energy";
    }
    printWarnings(renderChart(request).warnings, streams.err);
    streams.out << "wrote " << request.target.path << " (" << request.scene.view.chart_quantity
                << " against time)\n";
    return 0;
  }

 private:
  CLI::App& app_;
  SceneOptions scene_;
  SizeOption size_;
  StyleOptions style_;
  std::string output_;
};

}  // namespace

std::unique_ptr<Command> makeChartCommand(CLI::App& root) {
  return std::make_unique<ChartCommand>(root);
}

}  // namespace collide::app
