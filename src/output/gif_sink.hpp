#pragma once
// Animated GIF (for slides), encoded by libavcodec's GIF encoder with one palette generated from
// the colours of every frame. GIF frame delays count hundredths of a second, so 25 or 50 fps play
// evenly; other rates alternate delays.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "output/frame_sink.hpp"
#include "output/gif_palette.hpp"

namespace collide::output {

struct GifOptions {
  int max_colors = 256;       // palette size, 2..256 (one is kept for transparency)
  bool transparency = false;  // pixels with alpha < 128 become transparent
  bool loop = true;           // play forever, as slides expect; false: play once
};

// Frames are counted into a colour histogram and spooled (2 bytes a pixel) to an anonymous file
// beside `path`, which disappears however the process ends; finish() builds the palette, encodes
// every frame and renames the GIF into place. Destroyed before finish(), it leaves nothing.
// Throws OutputError: max_colors out of range, finish() without frames, any codec or I/O failure.
class GifSink : public FrameSink {
 public:
  explicit GifSink(std::filesystem::path path, GifOptions options = {});
  ~GifSink() override;
  GifSink(const GifSink&) = delete;
  GifSink& operator=(const GifSink&) = delete;

  void begin(const FrameFormat& format) override;
  void write(const core::ImageView& frame) override;
  void finish() override;

 private:
  struct SpoolCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };

  std::filesystem::path path_;
  GifOptions options_;
  FrameFormat format_;
  std::unique_ptr<std::FILE, SpoolCloser> spool_;
  std::unique_ptr<ColorHistogram> histogram_;
  std::vector<std::uint16_t> keys_;  // one row of colour keys
  int frames_written_ = 0;
  bool begun_ = false;
  bool finished_ = false;
};

}  // namespace collide::output
