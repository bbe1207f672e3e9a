#include "output/gif_sink.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "output/av_writer.hpp"
#include "output/temp_file.hpp"

namespace collide::output {
namespace {

// An unnamed file in `directory` (O_TMPFILE): nothing to clean up after a crash or a kill. Falls
// back to tmpfile(3) where the file system does not support it.
std::FILE* openSpool(const std::filesystem::path& directory) {
  const std::string where = directory.empty() ? "." : directory.string();
  const int fd = ::open(where.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) {
    std::FILE* file = ::fdopen(fd, "w+b");
    if (file != nullptr) return file;
    ::close(fd);
  }
  return std::tmpfile();
}

}  // namespace

GifSink::GifSink(std::filesystem::path path, GifOptions options)
    : path_(std::move(path)), options_(options) {}

GifSink::~GifSink() = default;  // the spool vanishes when closed; the GIF is only written at finish

void GifSink::begin(const FrameFormat& format) {
  COLLIDE_ASSERT(!begun_, "begin() called twice");
  COLLIDE_ASSERT(format.width_px > 0 && format.height_px > 0 && format.fps > 0,
                 "empty frame format");
  if (options_.max_colors < 2 || options_.max_colors > 256) {
    throw OutputError("cannot write GIF '" + path_.string() +
                      "': " + std::to_string(options_.max_colors) + " colours is outside 2..256");
  }
  if (format.width_px > 65535 || format.height_px > 65535) {
    throw OutputError("cannot write GIF '" + path_.string() + "': larger than 65535 pixels");
  }
  spool_.reset(openSpool(path_.parent_path()));
  if (spool_ == nullptr) {
    throw OutputError(ioErrorMessage("cannot create a spool file for GIF", path_, errno));
  }
  histogram_ = std::make_unique<ColorHistogram>();
  keys_.resize(static_cast<std::size_t>(format.width_px));
  format_ = format;
  begun_ = true;
}

void GifSink::write(const core::ImageView& frame) {
  COLLIDE_ASSERT(begun_ && !finished_, "write() outside begin()/finish()");
  COLLIDE_ASSERT(frame.width == format_.width_px && frame.height == format_.height_px,
                 "frame size differs from the format given to begin()");
  for (int y = 0; y < frame.height; ++y) {
    histogram_->addRow(frame.row(y), frame.width, options_.transparency, keys_.data());
    if (std::fwrite(keys_.data(), sizeof keys_[0], keys_.size(), spool_.get()) != keys_.size()) {
      throw OutputError(ioErrorMessage("cannot spool GIF frames for", path_, errno));
    }
  }
  ++frames_written_;
}

void GifSink::finish() {
  COLLIDE_ASSERT(begun_ && !finished_, "finish() outside begin()");
  if (frames_written_ == 0) {
    throw OutputError("cannot write GIF '" + path_.string() + "': no frames were rendered");
  }
  if (std::fflush(spool_.get()) != 0 || std::fseek(spool_.get(), 0, SEEK_SET) != 0) {
    throw OutputError(ioErrorMessage("cannot spool GIF frames for", path_, errno));
  }
  const Palette palette =
      buildPalette(*histogram_, options_.max_colors - (options_.transparency ? 1 : 0));
  histogram_.reset();
  // PAL8 palettes are native-endian 0xAARRGGBB; the transparent entry (alpha 0) comes last and
  // the GIF encoder makes it the transparent index.
  std::uint32_t argb[256] = {};
  for (std::size_t i = 0; i < palette.colors.size(); ++i) {
    const auto& c = palette.colors[i];
    argb[i] = 0xFF000000u | std::uint32_t{c[0]} << 16 | std::uint32_t{c[1]} << 8 | c[2];
  }
  const auto transparent_index = static_cast<std::uint8_t>(palette.colors.size());
  if (options_.transparency) argb[transparent_index] = 0x00000000u;

  av::VideoSetup setup;
  setup.container = "gif";
  setup.encoder = "gif";
  setup.codec_name = "GIF";
  setup.pixel_format = AV_PIX_FMT_PAL8;
  setup.bt709 = false;
  setup.muxer_options = {{"loop", options_.loop ? "0" : "-1"}};  // 0: forever, -1: once
  av::Writer writer(path_, format_, setup, MediaExtras{});
  for (int k = 0; k < frames_written_; ++k) {
    AVFrame& frame = writer.nextFrame();
    for (int y = 0; y < format_.height_px; ++y) {
      if (std::fread(keys_.data(), sizeof keys_[0], keys_.size(), spool_.get()) != keys_.size()) {
        throw OutputError(
            ioErrorMessage("cannot read back GIF frames for", path_, errno != 0 ? errno : EIO));
      }
      std::uint8_t* row = frame.data[0] + static_cast<std::ptrdiff_t>(y) * frame.linesize[0];
      for (int x = 0; x < format_.width_px; ++x) {
        const std::uint16_t key = keys_[static_cast<std::size_t>(x)];
        row[x] =
            key == ColorHistogram::kTransparent ? transparent_index : palette.index_of_key[key];
      }
    }
    std::memcpy(frame.data[1], argb, sizeof argb);
    writer.encodeFrame();
  }
  writer.finish();
  spool_.reset();
  finished_ = true;
}

}  // namespace collide::output
