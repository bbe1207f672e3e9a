#include "output/png_sinks.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <string>

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

// The index of a frame name this sink writes ("frame_00042.png": 42), or -1 for any other name
// ("frame_042.png" is not one of them: nothing here would have written it).
int frameIndexOf(const std::string& name) {
  if (!isFrameFileName(name)) return -1;
  const std::string digits = name.substr(6, name.size() - 10);
  if (digits.size() > 9) return -1;
  const int index = std::stoi(digits);
  return PngSequenceSink::frameFileName(index) == name ? index : -1;
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
    for (std::filesystem::directory_iterator it(directory_, ec), end; !ec && it != end;
         it.increment(ec)) {
      if (isFrameFileName(it->path().filename().string())) OutputFile probe(it->path());
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
  removeLaterFrames();
}

void PngSequenceSink::removeLaterFrames() const {
  std::vector<std::filesystem::path> later;
  std::error_code error;
  for (std::filesystem::directory_iterator it(directory_, error), end; !error && it != end;
       it.increment(error)) {
    const int index = frameIndexOf(it->path().filename().string());
    std::error_code status_error;
    const std::filesystem::file_status status = it->symlink_status(status_error);
    const bool file_or_link =
        std::filesystem::is_regular_file(status) || std::filesystem::is_symlink(status);
    if (index >= framesWritten() && file_or_link) later.push_back(it->path());
  }
  for (const std::filesystem::path& path : later) {
    std::error_code remove_error;
    if (!std::filesystem::remove(path, remove_error) && remove_error) {
      throw OutputError(ioErrorMessage("wrote the new frames but cannot remove the earlier frame",
                                       path, remove_error.value()));
    }
  }
}

void PngSequenceSink::removeStaged() noexcept {
  staged_.clear();  // each OutputFile not committed removes its temporary file
  if (created_directory_) {
    std::error_code ignored;
    std::filesystem::remove(directory_, ignored);  // only succeeds if it is empty
  }
}

}  // namespace collide::output
