#pragma once
// Private to src/output: one video file written by libavformat, with a video stream, optionally an
// audio stream and a subtitle stream, through an OutputFile (a regular file safely: temporary
// name, renamed at finish; a device, FIFO or stdout as a stream). Follows FFmpeg's
// doc/examples/mux.c. The MP4, WebM and GIF sinks are thin layers over it.
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/image.hpp"
#include "output/av_resources.hpp"
#include "output/frame_sink.hpp"
#include "output/media_extras.hpp"
#include "output/output_file.hpp"

namespace collide::output::av {

using Options = std::vector<std::pair<std::string, std::string>>;

struct VideoSetup {
  std::string container;   // libavformat muxer name: "mp4", "webm", "gif"
  std::string encoder;     // libavcodec encoder name: "libx264", "libvpx-vp9", "gif"
  std::string codec_name;  // for people, in errors: "H.264", "VP9", "GIF"
  AVPixelFormat pixel_format = AV_PIX_FMT_YUV420P;
  bool bt709 =
      true;  // tag the stream BT.709 limited range, centred chroma (how convertRgba converts)
  Options encoder_options;  // private options of the encoder, e.g. {"crf", "20"}
  Options muxer_options;    // e.g. {"movflags", "+faststart"}
  // Instead of muxer_options when the output is a stream that cannot be sought back into (a FIFO,
  // a device, stdout); empty: muxer_options serve both. MP4 switches to fragments.
  Options streamed_muxer_options;
  std::string audio_encoder;            // for MediaExtras::audio: "aac", "libopus"
  int audio_bit_rate = 96000;           // bits per second
  std::string subtitle_encoder;         // for MediaExtras::subtitles: "mov_text", "webvtt"
  bool bibliographic_language = false;  // tag streams with ISO 639-2/B (Matroska), else /T
};

class Writer {
 public:
  // Opens the encoders and writes the header to a temporary file beside `target`. Throws
  // OutputError naming `target`.
  Writer(std::filesystem::path target, const FrameFormat& format, const VideoSetup& setup,
         const MediaExtras& extras);
  ~Writer();  // removes the temporary file unless finish() renamed it
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // The frame to fill for the next picture, already writable (the encoder may still hold the
  // previous one).
  AVFrame& nextFrame();
  // Encodes nextFrame() as picture number framesWritten() and any sound up to its end.
  void encodeFrame();
  // The same for a picture in a frame of the caller's (from newVideoFrame()).
  void encodeFrame(AVFrame& picture);
  // A frame of the video's size and pixel format for encodeFrame(AVFrame&); safe to call from
  // another thread while this writer encodes.
  FramePtr newVideoFrame() const;
  // Drains the encoders, writes the trailer and renames the file to the target.
  void finish();

  int framesWritten() const { return frames_written_; }
  const std::filesystem::path& target() const { return target_; }
  [[noreturn]] void fail(const std::string& what, int av_error) const;

 private:
  struct Audio;
  void addAudio(const VideoSetup& setup, const AudioTrack& track, const std::string& language);
  void addSubtitles(const VideoSetup& setup, const MediaExtras& extras);
  void writeSubtitlesUntil(double until_s);
  void encodeAudioUntil(long long end_sample, bool flush);
  void drain(AVCodecContext& codec, AVStream& stream, bool one_frame_packets);

  std::filesystem::path target_;
  // Removes the temporary file when the writer dies unfinished, also when its constructor throws.
  // Declared before muxer_, so destroyed after it: the file is closed first.
  OutputFile file_;
  FrameFormat format_;
  OutputFormatPtr muxer_;
  AVStream* video_stream_ = nullptr;  // owned by muxer_
  CodecContextPtr video_codec_;
  AVPixelFormat pixel_format_;
  FramePtr frame_;  // nextFrame()'s, made on first use
  PacketPtr packet_;
  std::unique_ptr<Audio> audio_;
  AVStream* subtitle_stream_ = nullptr;
  CodecContextPtr subtitle_codec_;
  std::vector<TimedText> subtitles_;
  std::size_t next_subtitle_ = 0;  // first cue not yet written
  int frames_written_ = 0;
};

// Makes `frame` writable (the encoder may still hold its buffer) and fills it from `image`, an
// RGBA8 view top-down or bottom-up: Y'CbCr 4:2:0 (yuv420p; yuva420p also takes the alpha) by
// rgbaToYuv420Bt709, BT.709 matrix, limited range, chroma centred in each 2x2 block. Throws
// OutputError naming `target` when memory runs out. With `rects`, converts only those
// (rgbaToYuv420Bt709's rectangle form): the frame's other samples keep what they held (a buffer
// made writable is copied with them).
void convertRgba(const core::ImageView& image, AVFrame& frame, const std::filesystem::path& target,
                 const std::vector<core::ImageRect>* rects = nullptr);

}  // namespace collide::output::av
