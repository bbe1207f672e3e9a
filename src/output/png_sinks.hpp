#pragma once
// PNG sinks: a single still image, or a numbered sequence of frames in a directory.
#include <filesystem>
#include <memory>
#include <vector>

#include "output/frame_sink.hpp"
#include "output/png_writer.hpp"

namespace collide::output {

class OutputFile;

// Writes exactly one frame to `path` through an OutputFile ("-": stdout). For a regular file the
// frame goes to a temporary file at write() and is renamed to `path` at finish(); destroyed before
// finish(), it leaves nothing behind.
// Throws OutputError: a second write(), finish() without a frame, or any I/O failure.
class PngStillSink : public FrameSink {
 public:
  // `text` goes into the PNG's text chunks (see PngText); dots_per_inch > 0 into a pHYs chunk;
  // `deflate_threads`: see writePng().
  explicit PngStillSink(std::filesystem::path path, PngText text = {}, double dots_per_inch = 0.0,
                        int deflate_threads = 1);
  ~PngStillSink() override;

  void begin(const FrameFormat& format) override;
  void write(const core::ImageView& frame) override;
  void finish() override;

 private:
  std::filesystem::path path_;
  PngText text_;
  double dots_per_inch_;
  int deflate_threads_;
  FrameFormat format_;
  bool begun_ = false;
  bool finished_ = false;
  int frames_written_ = 0;
  std::unique_ptr<OutputFile> file_;  // null until write()
};

// Writes frame_00000.png, frame_00001.png, ... into `directory`, which begin() creates if it does
// not exist (its parent must). Each frame goes through an OutputFile, by the rules of every
// output: a new name or a regular file is written under a hidden temporary name and finish()
// renames them all to their frame names, so frames of an earlier run in the same directory stay
// intact until the whole new sequence is complete; a frame name that is a link is followed (its
// file replaced, the link stays a link); a character device or FIFO there is written straight
// through, never replaced. begin() refuses (core::InputError) a frame name that is a directory,
// a block device or a link loop before any frame is drawn. Destroyed before finish() (an error,
// a signal), it removes every temporary frame and the directory if it created it. Once the new
// sequence is in place, finish() removes the frames of an earlier, longer run beyond it (files
// and links named as this sink names frames, never a device or FIFO), so the directory holds one
// run's frames and `ffmpeg -i frame_%05d.png` or a count of the files sees that run alone.
class PngSequenceSink : public FrameSink {
 public:
  // `text` goes into every frame's text chunks (see PngText).
  explicit PngSequenceSink(std::filesystem::path directory, PngText text = {});
  ~PngSequenceSink() override;

  void begin(const FrameFormat& format) override;
  void write(const core::ImageView& frame) override;
  void finish() override;

  // "frame_00042.png" for index 42; five digits, more when the index needs them.
  static std::string frameFileName(int index);
  int framesWritten() const { return static_cast<int>(staged_.size()); }

 private:
  void removeStaged() noexcept;
  void removeLaterFrames() const;

  std::filesystem::path directory_;
  PngText text_;
  FrameFormat format_;
  bool begun_ = false;
  bool finished_ = false;
  bool created_directory_ = false;
  // Complete frames in order, those to be renamed still under temporary names.
  std::vector<std::unique_ptr<OutputFile>> staged_;
};

}  // namespace collide::output
