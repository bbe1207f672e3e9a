#pragma once
// One picture (a still, a strobe, a chart) to its file, by the target's kind: PNG through the GL
// renderer, SVG or PDF through the vector painter of the same frame; at screen size or at a
// physical size for print. Written under a temporary name and renamed: a failure or a stop signal
// leaves nothing at the target.
#include <optional>
#include <string>

#include "app/print_options.hpp"
#include "app/render_settings.hpp"
#include "compose/frame_source.hpp"
#include "frame/frame_model.hpp"
#include "frame/print_layout.hpp"
#include "output/output_target.hpp"
#include "output/png_writer.hpp"

namespace collide::app {

struct FigureSettings {
  FrameSize size;                         // --size
  std::optional<frame::PrintSize> print;  // --print, --width-cm, --dpi
  std::string title;                      // a PDF's title
  std::string description;                // a PDF's subject: the alt text
  output::PngText png_text;               // a PNG's text chunks
};

// The size the frame is laid out at: the print size's pixels, else --size.
FrameSize figureFrameSize(const FigureSettings& settings);
// The size and text floor a picture of `kind` is laid out at (a printed vector figure's layout
// is frame::vectorPrintFrame's): what compose places labels for.
compose::PictureSize figurePictureSize(const FigureSettings& settings, output::OutputKind kind);

// Writes `frame` to target (kPngStill, kSvgFigure or kPdfFigure). Throws OutputError, RenderError,
// InterruptedError (a stop signal before the rename).
void writeFigure(const output::OutputTarget& target, const frame::FrameModel& frame,
                 const FigureSettings& settings);

}  // namespace collide::app
