#include "output/png_sinks.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>

#include "output/output_file.hpp"
#include "output/png_writer.hpp"
#include "output/temp_file.hpp"

namespace collide::output {
namespace {

void checkFrame(const FrameFormat& format, const core::ImageView& frame) {
  COLLIDE_ASSERT(frame.width == format.width_px && frame.height == format.height_px,
                 "frame size differs from the format given to begin()");
}

// "frame_" digits ".png": a name this sink may write.
bool isFrameFileName(const std::string& name) {
  constexpr std::size_t kPrefix = 6, kSuffix = 4;  // "frame_", ".png"
  if (name.size() <= kPrefix + kSuffix || name.compare(0, kPrefix, "frame_") != 0 ||
      name.compare(name.size() - kSuffix, kSuffix, ".png") != 0) {
    return false;
  }
  for (std::size_t i = kPrefix; i < name.size() - kSuffix; ++i) {
    if (name[i] < '0' || name[i] > '9') return false;
  }
  return true;
}

}  // namespace

// ---- PngStillSink ----------------------------------------------------------------------------

PngStillSink::PngStillSink(std::filesystem::path path, PngText text, double dots_per_inch,
                           int deflate_threads)
    : path_(std::move(path)),
      text_(std::move(text)),
      dots_per_inch_(dots_per_inch),
      deflate_threads_(deflate_threads) {}

// The OutputFile removes its temporary file unless finish() committed it.
PngStillSink::~PngStillSink() = default;

void PngStillSink::begin(const FrameFormat& format) {
  COLLIDE_ASSERT(!begun_, "begin() called twice");
  COLLIDE_ASSERT(format.width_px > 0 && format.height_px > 0, "empty frame format");
  format_ = format;
  begun_ = true;
}

void PngStillSink::write(const core::ImageView& frame) {
  COLLIDE_ASSERT(begun_ && !finished_, "write() outside begin()/finish()");
  checkFrame(format_, frame);
  if (frames_written_ > 0) {
    throw OutputError("PNG still '" + path_.string() + "' takes exactly one frame, got a second");
  }
  file_ = std::make_unique<OutputFile>(path_);
  try {
    writePngDirect(file_->writePath(), frame, path_, text_, dots_per_inch_, deflate_threads_);
  } catch (...) {
    file_.reset();
    throw;
  }
  ++frames_written_;
}

void PngStillSink::finish() {
  COLLIDE_ASSERT(begun_ && !finished_, "finish() outside begin()");
  if (frames_written_ == 0) {
    throw OutputError("PNG still '" + path_.string() + "' got no frame to write");
  }
  file_->commit();
  finished_ = true;
}

// ---- PngSequenceSink -------------------------------------------------------------------------

PngSequenceSink::PngSequenceSink(std::filesystem::path directory, PngText text)
    : directory_(std::move(directory)), text_(std::move(text)) {}

PngSequenceSink::~PngSequenceSink() {
  if (!finished_) removeStaged();
}

std::string PngSequenceSink::frameFileName(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return name;
}

void PngSequenceSink::begin(const FrameFormat& format) {
  COLLIDE_ASSERT(!begun_, "begin() called twice");
  COLLIDE_ASSERT(format.width_px > 0 && format.height_px > 0, "empty frame format");
  // mkdir, not create_directories: a mistyped parent should fail loudly, not grow a tree.
  if (::mkdir(directory_.c_str(), 0777) == 0) {
    created_directory_ = true;
  } else {
    const int mkdir_errno = errno;
    std::error_code ec;
    if (mkdir_errno != EEXIST || !std::filesystem::is_directory(directory_, ec)) {
      throw OutputError(ioErrorMessage("cannot create frame directory", directory_,
                                       mkdir_errno == EEXIST ? ENOTDIR : mkdir_errno));
    }
  }
  if (!created_directory_) {
    // An earlier run's frame name that no output may replace (a directory, a block device, a link
    // loop) is refused now, before any frame is drawn: OutputFile throws for it, and for any
    // other name only works out where its bytes would go.
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(directory_, ec)) {
      if (isFrameFileName(entry.path().filename().string())) OutputFile probe(entry.path());
    }
  }
  format_ = format;
  begun_ = true;
}

void PngSequenceSink::write(const core::ImageView& frame) {
  COLLIDE_ASSERT(begun_ && !finished_, "write() outside begin()/finish()");
  checkFrame(format_, frame);
  const std::filesystem::path target = directory_ / frameFileName(framesWritten());
  auto file = std::make_unique<OutputFile>(target);
  writePngDirect(file->writePath(), frame, target, text_);  // on failure `file` removes its bytes
  staged_.push_back(std::move(file));
}

void PngSequenceSink::finish() {
  COLLIDE_ASSERT(begun_ && !finished_, "finish() outside begin()");
  // Renames within one directory (or, for a frame name that links elsewhere, within its file's):
  // they do not fail for want of space, so the earlier run's frames are replaced only once every
  // new frame is complete.
  for (const std::unique_ptr<OutputFile>& file : staged_) file->commit();
  finished_ = true;
}

void PngSequenceSink::removeStaged() noexcept {
  staged_.clear();  // each OutputFile not committed removes its temporary file
  if (created_directory_) {
    std::error_code ignored;
    std::filesystem::remove(directory_, ignored);  // only succeeds if it is empty
  }
}

}  // namespace collide::output
