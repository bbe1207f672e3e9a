#include "app/figure_writer.hpp"

#include <algorithm>
#include <thread>

#include "core/heap_pages.hpp"
#include "frame/print_layout.hpp"
#include "output/frame_sink.hpp"
#include "output/process_end.hpp"
#include "output/stop_signals.hpp"
#include "output/text_output.hpp"
#include "render/renderer.hpp"
#include "render/vector/vector_painter.hpp"

namespace collide::app {
namespace {

void writePng(const output::OutputTarget& target, const frame::FrameModel& frame,
              const FigureSettings& settings) {
  const FrameSize size = figureFrameSize(settings);
  render::RendererOptions options;
  output::SinkSettings sink_settings;
  sink_settings.png_text = settings.png_text;
  // The process's one picture has the machine to itself: its PNG is deflated on every core, at
  // most four (each part costs a little size and set-up).
  if (output::drawsOnePicture()) {
    sink_settings.png_threads =
        static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 4u));
  }
  if (settings.print) {
    options.text_floor_px = frame::rasterPrintFrame(*settings.print).text_floor_px;
    sink_settings.png_dpi = settings.print->dots_per_inch;
  }
  // One picture: its fresh memory (LLVM's compile, llvmpipe's buffers, the readback) in huge
  // pages rather than thousands of 4 KiB faults. 32 MiB and two frames' worth held every large
  // block of a 720p and a 1080p still (core/heap_pages.hpp).
  const std::size_t frame_bytes = std::size_t(size.width_px) * std::size_t(size.height_px) * 4;
  core::preferHugePagesForHeap((std::size_t{32} << 20) + 2 * frame_bytes);
  auto renderer = std::make_unique<render::Renderer>(size.width_px, size.height_px, options);
  std::unique_ptr<output::FrameSink> sink = output::makeSink(target, std::move(sink_settings));
  sink->begin({size.width_px, size.height_px, 1});
  sink->write(renderer->render(frame));
  // Drawing and encoding a large picture take a while: a signal meanwhile keeps the earlier file.
  output::StopSignals::throwIfReceived(output::kindName(target.kind) + " '" + target.path + "'");
  sink->finish();
  output::keepForProcessEnd(std::move(renderer));  // the program's one picture: no teardown
}

void writeVector(const output::OutputTarget& target, const frame::FrameModel& frame,
                 const FigureSettings& settings) {
  render::VectorFigureOptions options;
  options.format = target.kind == output::OutputKind::kSvgFigure ? render::VectorFormat::kSvg
                                                                 : render::VectorFormat::kPdf;
  const FrameSize size = figureFrameSize(settings);
  options.width_px = size.width_px;
  options.height_px = size.height_px;
  if (settings.print) {
    const frame::PrintFrame page = frame::vectorPrintFrame(*settings.print);
    options.width_px = page.width_px;
    options.height_px = page.height_px;
    options.px_per_inch = page.px_per_inch;
    options.text_floor_px = page.text_floor_px;
  }
  options.title = settings.title;
  options.subject = settings.description;
  const std::string bytes = render::paintVectorFigure(frame, options);

  output::writeDocumentOutput(target.path, bytes, output::kindName(target.kind));
}

}  // namespace

FrameSize figureFrameSize(const FigureSettings& settings) {
  if (!settings.print) return settings.size;
  return {settings.print->width_px, settings.print->height_px};
}

compose::PictureSize figurePictureSize(const FigureSettings& settings, output::OutputKind kind) {
  if (!settings.print) return {settings.size.width_px, settings.size.height_px};
  const bool vector =
      kind == output::OutputKind::kSvgFigure || kind == output::OutputKind::kPdfFigure;
  const frame::PrintFrame frame =
      vector ? frame::vectorPrintFrame(*settings.print) : frame::rasterPrintFrame(*settings.print);
  return {frame.width_px, frame.height_px, frame.text_floor_px};
}

void writeFigure(const output::OutputTarget& target, const frame::FrameModel& frame,
                 const FigureSettings& settings) {
  switch (target.kind) {
    case output::OutputKind::kSvgFigure:
    case output::OutputKind::kPdfFigure:
      writeVector(target, frame, settings);
      return;
    default:
      writePng(target, frame, settings);
      return;
  }
}

}  // namespace collide::app
