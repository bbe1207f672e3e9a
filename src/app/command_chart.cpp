// collide chart SCENE -o OUT.png [--chart energy|momentum|force]: a chart against time, alone.
#include "app/command.hpp"
#include "app/picture_options.hpp"
#include "app/picture_pipeline.hpp"

namespace collide::app {
namespace {

class ChartCommand : public Command {
 public:
  explicit ChartCommand(CLI::App& root)
      : app_(*root.add_subcommand(
            "chart", "Plot energy (or momentum, or contact force) against time to a PNG")) {
    options_.addTo(app_, "Output path: *.png, a device or FIFO, or - for stdout");
    app_.footer(
        "The chart plots each body's kinetic energy, the total, potential energy (with gravity)\n"
        "and the energy lost; --chart momentum plots momenta, --chart force the soft-contact "
        "force.\nExamples:\n"
        "  collide chart worked-example -o energy.png\n"
        "  collide chart soft-contact -o force.png --chart force");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    PictureRequest request{options_.loadScene(), options_.size.parse(),
                           stillTarget(options_.output)};
    if (options_.style.chart.empty() && !request.scene.view.chart) {
      request.scene.view.chart_quantity = "energy";
    }
    const PictureSummary summary = renderChart(request);
    reportStream(request.target, streams)
        << "wrote " << shownPath(request.target) << " (" << request.scene.view.chart_quantity
        << " against time)\n";
    reportSideFilesAndWarnings({}, summary.warnings, streams);
    return 0;
  }

 private:
  CLI::App& app_;
  PictureOptions options_;
};

}  // namespace

std::unique_ptr<Command> makeChartCommand(CLI::App& root) {
  return std::make_unique<ChartCommand>(root);
}

}  // namespace collide::app
