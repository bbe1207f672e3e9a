#pragma once
// Which kind of output a path (or --format) asks for, decided by the app alone (sinks never
// choose), and the sink that writes it.
#include <memory>
#include <optional>
#include <string>

#include "output/frame_sink.hpp"
#include "output/media_extras.hpp"
#include "output/png_writer.hpp"

namespace collide::output {

enum class OutputKind {
  kMp4,        // "*.mp4": H.264 video (AAC sound, mov_text captions)
  kWebm,       // "*.webm": VP9 video (alpha, Opus sound, WebVTT captions)
  kGif,        // "*.gif": animated GIF with a generated palette
  kPngFrames,  // an existing directory or a path ending in '/': frame_00000.png, ...
  kPngStill,   // "*.png": one image
  kSvgFigure,  // "*.svg": one picture as a vector figure (not a FrameSink: app/figure_writer.hpp)
  kPdfFigure,  // "*.pdf": one picture as a one-page vector PDF
};

struct OutputTarget {
  OutputKind kind;
  std::string path;  // "-": standard output
  // Written as a stream, not a replaced file: "-", a character device, a FIFO or a socket. Such a
  // target has no name to put side files beside (captions, alt text).
  bool streamed = false;
};

// "MP4", "WebM", "GIF", "PNG frames", "PNG", "SVG", "PDF": for messages.
std::string kindName(OutputKind kind);

// Classifies `path` for `collide render`. `format` (--format: mp4, webm, gif, frames; empty: from
// the path) chooses where the path has no extension and must agree with one it has; "-" (stdout)
// needs --format, a device or FIFO without one gets MP4. Throws core::InputError for an unknown
// extension or format, a missing parent directory, a path that is not writable as that kind (see
// checkOutputPath), or binary output to a terminal.
OutputTarget videoTarget(const std::string& path, const std::string& format = "");

// Checks `path` for `collide still`, `strobe` and `chart`: a .png, .svg or .pdf path, a device or
// FIFO (PNG), or "-" (PNG on stdout, not a terminal); as checkOutputPath.
OutputTarget stillTarget(const std::string& path);

// Throws core::InputError, naming `option`, unless `path` is "-", or its directory exists and
// output::placeOutput would write it (not a directory, block device or link loop).
void checkOutputPath(const std::string& option, const std::string& path);

// Throws core::InputError, naming `option`, when the directory that would hold `path` is missing.
void requireParentDirectory(const std::string& option, const std::string& path);

// How the chosen sink encodes: what the user asked on the command line, already checked.
struct SinkSettings {
  std::optional<int> quality;       // crf for MP4 (0-51) and WebM (0-63); none: the default
  std::string preset = "veryfast";  // x264 preset; WebM maps it to a libvpx speed
  bool transparent = false;         // keep alpha: WebM (yuva420p), GIF, PNG
  output::MediaExtras extras;       // MP4/WebM: tags, sound, captions
  output::PngText png_text;         // PNG: text chunks
  double png_dpi = 0.0;             // PNG still: printing resolution for its pHYs chunk; 0: none
  int png_threads = 1;              // PNG still: threads deflating it (output/png_writer.hpp)
  int encoder_threads = 0;          // MP4: x264 threads; 0: 1.5 per core
};

// The sink that writes `target` (not a vector figure: those are painted, not streamed).
std::unique_ptr<output::FrameSink> makeSink(const OutputTarget& target, SinkSettings settings = {});

// libvpx speed (cpu-used, 0 best .. 8 fastest) for an x264 preset name, so --preset means the same
// trade on both codecs: ultrafast..veryfast 8..6, faster 5, fast 4, medium 3, slow 2, slower 1,
// veryslow and placebo 0.
int vp9SpeedForPreset(const std::string& preset);

// A file beside `path` with its extension replaced: ("out/lesson.mp4", ".vtt") -> "out/lesson.vtt".
std::string besidePath(const std::string& path, const std::string& extension);

}  // namespace collide::output
