// collide chart SCENE -o OUT.png [--chart energy|momentum|force]: a chart against time, alone.
#include "app/command.hpp"
#include "app/picture_options.hpp"
#include "app/picture_pipeline.hpp"
#include "app/print_options.hpp"
#include "output/process_end.hpp"

namespace collide::app {
namespace {

class ChartCommand : public Command {
 public:
  explicit ChartCommand(CLI::App& root)
      : app_(*root.add_subcommand("chart",
                                  "Plot energy (or momentum, or contact force) against time, or a "
                                  "speed histogram: PNG, SVG or PDF")) {
    options_.addTo(app_, kFigureOutputHelp);
    print_.addTo(app_);
    bundle_.addTo(app_);
    app_.footer(
        "The chart plots each body's kinetic energy, the total, potential energy (with gravity)\n"
        "and the energy lost; --chart momentum plots momenta, --chart force the soft-contact "
        "force.\nExamples:\n"
        "  collide chart worked-example -o energy.png\n"
        "  collide chart soft-contact -o force.png --chart force");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    PictureRequest request = pictureRequest(options_, print_, bundle_, app_);
    if (options_.style.chart.empty() && !request.scene.view.chart) {
      request.scene.view.chart_quantity = "energy";
    }
    output::declareOnePictureProcess();  // no teardown after it (output/process_end.hpp)
    const PictureSummary summary = renderChart(request);
    reportStream(request.target, streams)
        << "wrote " << shownPath(request.target) << " ("
        << (request.scene.view.chart_quantity == "speed"
                ? std::string("speed histogram at the end")
                : request.scene.view.chart_quantity + " against time")
        << ")\n";
    reportSideFilesAndWarnings(summary.side_files, summary.warnings, streams);
    return 0;
  }

 private:
  CLI::App& app_;
  PictureOptions options_;
  PrintOptions print_;
  BundleOptions bundle_;
};

}  // namespace

std::unique_ptr<Command> makeChartCommand(CLI::App& root) {
  return std::make_unique<ChartCommand>(root);
}

}  // namespace collide::app
