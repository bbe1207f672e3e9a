#include "output/av_writer.hpp"

extern "C" {
#include <libavutil/channel_layout.h>
#include <libavutil/mathematics.h>
#include <libavutil/opt.h>
}

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "output/temp_file.hpp"
#include "output/yuv420.hpp"

namespace collide::output::av {
namespace {

// What libavcodec's own text decoders produce (avpriv_ass_get_subtitle_header_default): the text
// subtitle encoders (mov_text, webvtt) read their styles from it.
constexpr const char* kAssHeader =
    "[Script Info]\r\nScriptType: v4.00+\r\nPlayResX: 384\r\nPlayResY: 288\r\n"
    "ScaledBorderAndShadow: yes\r\n\r\n[V4+ Styles]\r\n"
    "Format: Name, Fontname, Fontsize, PrimaryColour, SecondaryColour, OutlineColour, "
    "BackColour, Bold, Italic, Underline, StrikeOut, ScaleX, ScaleY, Spacing, Angle, "
    "BorderStyle, Outline, Shadow, Alignment, MarginL, MarginR, MarginV, Encoding\r\n"
    "Style: Default,Arial,16,&Hffffff,&Hffffff,&H0,&H0,0,0,0,0,100,100,0,0,1,1,0,2,10,10,10,0"
    "\r\n\r\n[Events]\r\n"
    "Format: Layer, Start, End, Style, Name, MarginL, MarginR, MarginV, Effect, Text\r\n";

// Caption text as an ASS dialogue text field: line breaks become \N; braces (ASS override tags)
// and backslashes (ASS escapes) are replaced so the words come out as written.
std::string assText(const std::string& text) {
  std::string ass;
  for (const char c : text) {
    if (c == '\n') {
      ass += "\\N";
    } else if (c == '{') {
      ass += '(';
    } else if (c == '}') {
      ass += ')';
    } else if (c == '\\') {
      ass += '/';
    } else if (c != '\r') {
      ass += c;
    }
  }
  return ass;
}

// The first half of the advice for an encoder this libavcodec lacks; the caller adds the other
// way out. Debian's libavcodec59 has every encoder collide uses (libx264, libvpx-vp9, gif, aac,
// libopus, mov_text, webvtt); builds without the external libraries lack libx264, libvpx-vp9 and
// libopus.
std::string missingEncoderAdvice(const std::string& encoder) {
  return "install an FFmpeg libavcodec built with " + encoder + " (Debian: libavcodec59)";
}

void setOptions(void* object, const Options& options, const Writer& writer, const char* what) {
  for (const auto& [key, value] : options) {
    // Searches the codec context's own options ("b", "g") and the encoder's private ones.
    const int result = av_opt_set(object, key.c_str(), value.c_str(), AV_OPT_SEARCH_CHILDREN);
    if (result < 0)
      writer.fail(std::string(what) + " option " + key + "=" + value + " for", result);
  }
}

// The ISO 639-2 code the container wants for the streams' language.
const std::string& streamLanguage(const VideoSetup& setup, const MediaExtras& extras) {
  return setup.bibliographic_language ? extras.language_bibliographic : extras.language_terminology;
}

}  // namespace

struct Writer::Audio {
  CodecContextPtr codec;
  AVStream* stream = nullptr;  // owned by the muxer
  FramePtr frame;
  std::vector<float> samples;  // the whole track; mono
  long long next_sample = 0;   // first sample not yet sent to the encoder
  bool small_last_frame = false;
};

Writer::Writer(std::filesystem::path target, const FrameFormat& format, const VideoSetup& setup,
               const MediaExtras& extras)
    : target_(std::move(target)),
      file_(target_),
      format_(format),
      pixel_format_(setup.pixel_format) {
  // "file:" keeps a name with a colon from being taken for a protocol; stdout is FFmpeg's pipe.
  const std::string url = file_.route() == OutputRoute::kStdout
                              ? std::string("pipe:1")
                              : "file:" + file_.writePath().string();
  const AVCodec* encoder = avcodec_find_encoder_by_name(setup.encoder.c_str());
  if (encoder == nullptr) {
    throw OutputError("cannot write video '" + target_.string() + "': " + setup.codec_name +
                      " encoder " + setup.encoder + " is not available in this libavcodec; " +
                      missingEncoderAdvice(setup.encoder) +
                      " or choose another output: .mp4, .webm, .gif or a directory for PNG "
                      "frames");
  }
  // The format is named, not guessed from the (temporary) file name; the name is still given, as
  // +faststart reopens the file by it to move the index forward.
  AVFormatContext* muxer = nullptr;
  const int allocated =
      avformat_alloc_output_context2(&muxer, nullptr, setup.container.c_str(), url.c_str());
  if (allocated < 0) fail("cannot set up " + setup.container + " muxer for", allocated);
  muxer_.reset(muxer);
  video_stream_ = avformat_new_stream(muxer, nullptr);
  if (video_stream_ == nullptr) fail("cannot add video stream to", AVERROR(ENOMEM));

  video_codec_.reset(avcodec_alloc_context3(encoder));
  if (video_codec_ == nullptr) fail("cannot set up encoder for", AVERROR(ENOMEM));
  AVCodecContext& c = *video_codec_;
  c.width = format.width_px;
  c.height = format.height_px;
  c.pix_fmt = setup.pixel_format;
  c.time_base = AVRational{1, format.fps};  // one tick per frame
  c.framerate = AVRational{format.fps, 1};
  if (setup.bt709) {
    // RgbaConverter uses BT.709 matrices into limited range; say so, so players convert back the
    // same way.
    c.color_range = AVCOL_RANGE_MPEG;
    c.colorspace = AVCOL_SPC_BT709;
    c.color_primaries = AVCOL_PRI_BT709;
    c.color_trc = AVCOL_TRC_BT709;
    // Each chroma sample is the mean of a 2x2 block, so it sits at the block's centre (H.264's
    // default would be the left edge, MPEG-2 style).
    c.chroma_sample_location = AVCHROMA_LOC_CENTER;
  }
  video_stream_->time_base = c.time_base;
  // MP4 and WebM keep codec headers once in the track header, not in every keyframe.
  if (muxer->oformat->flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  setOptions(&c, setup.encoder_options, *this, "encoder");
  const int opened = avcodec_open2(&c, encoder, nullptr);
  if (opened < 0) fail("cannot open " + setup.codec_name + " encoder for", opened);
  const int copied = avcodec_parameters_from_context(video_stream_->codecpar, &c);
  if (copied < 0) fail("cannot set up video stream for", copied);

  for (const auto& [key, value] : extras.metadata) {
    av_dict_set(&muxer->metadata, key.c_str(), value.c_str(), 0);
  }
  if (extras.audio) addAudio(setup, *extras.audio, streamLanguage(setup, extras));
  if (!extras.subtitles.empty()) addSubtitles(setup, extras);

  const int created = avio_open(&muxer->pb, url.c_str(), AVIO_FLAG_WRITE);
  if (created < 0) fail("cannot create video", created);
  AVDictionary* muxer_options = nullptr;
  const Options& chosen_options = file_.streamed() && !setup.streamed_muxer_options.empty()
                                      ? setup.streamed_muxer_options
                                      : setup.muxer_options;
  for (const auto& [key, value] : chosen_options) {
    av_dict_set(&muxer_options, key.c_str(), value.c_str(), 0);
  }
  const int header = avformat_write_header(muxer, &muxer_options);
  av_dict_free(&muxer_options);
  if (header < 0) fail("cannot write video header to", header);

  packet_.reset(av_packet_alloc());
  if (packet_ == nullptr) fail("cannot encode video", AVERROR(ENOMEM));
}

FramePtr Writer::newVideoFrame() const {
  FramePtr frame(av_frame_alloc());
  if (frame == nullptr) fail("cannot encode video", AVERROR(ENOMEM));
  frame->format = pixel_format_;
  frame->width = format_.width_px;
  frame->height = format_.height_px;
  const int buffered = av_frame_get_buffer(frame.get(), 0);
  if (buffered < 0) fail("cannot allocate a frame for", buffered);
  return frame;
}

Writer::~Writer() = default;

void Writer::fail(const std::string& what, int av_error) const {
  throw OutputError(errorMessage(what, target_, av_error));
}

void Writer::addAudio(const VideoSetup& setup, const AudioTrack& track,
                      const std::string& language) {
  const AVCodec* encoder = avcodec_find_encoder_by_name(setup.audio_encoder.c_str());
  if (encoder == nullptr) {
    throw OutputError("cannot write video '" + target_.string() + "': audio encoder " +
                      setup.audio_encoder + " is not available in this libavcodec; " +
                      missingEncoderAdvice(setup.audio_encoder) + " or leave out --sound");
  }
  audio_ = std::make_unique<Audio>();
  Audio& a = *audio_;
  a.samples = track.samples;
  a.codec.reset(avcodec_alloc_context3(encoder));
  if (a.codec == nullptr) fail("cannot set up audio encoder for", AVERROR(ENOMEM));
  AVCodecContext& c = *a.codec;
  // Mono float samples: planar and packed are the same memory for one channel.
  c.sample_fmt = AV_SAMPLE_FMT_NONE;
  for (const AVSampleFormat* f = encoder->sample_fmts; f && *f != AV_SAMPLE_FMT_NONE; ++f) {
    if (*f == AV_SAMPLE_FMT_FLTP || *f == AV_SAMPLE_FMT_FLT) c.sample_fmt = *f;
  }
  if (c.sample_fmt == AV_SAMPLE_FMT_NONE) {
    throw OutputError("cannot write video '" + target_.string() + "': audio encoder " +
                      setup.audio_encoder + " takes no float samples");
  }
  c.sample_rate = track.sample_rate_hz;
  av_channel_layout_default(&c.ch_layout, 1);
  c.bit_rate = setup.audio_bit_rate;
  c.time_base = AVRational{1, track.sample_rate_hz};
  if (muxer_->oformat->flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  const int opened = avcodec_open2(&c, encoder, nullptr);
  if (opened < 0) fail("cannot open audio encoder " + setup.audio_encoder + " for", opened);
  a.stream = avformat_new_stream(muxer_.get(), nullptr);
  if (a.stream == nullptr) fail("cannot add audio stream to", AVERROR(ENOMEM));
  a.stream->time_base = c.time_base;
  const int copied = avcodec_parameters_from_context(a.stream->codecpar, &c);
  if (copied < 0) fail("cannot set up audio stream for", copied);
  av_dict_set(&a.stream->metadata, "language", language.c_str(), 0);

  a.small_last_frame = (encoder->capabilities & AV_CODEC_CAP_SMALL_LAST_FRAME) != 0;
  a.frame.reset(av_frame_alloc());
  if (a.frame == nullptr) fail("cannot set up audio for", AVERROR(ENOMEM));
  a.frame->format = c.sample_fmt;
  a.frame->sample_rate = c.sample_rate;
  a.frame->nb_samples = c.frame_size > 0 ? c.frame_size : 1024;
  av_channel_layout_copy(&a.frame->ch_layout, &c.ch_layout);
  const int buffered = av_frame_get_buffer(a.frame.get(), 0);
  if (buffered < 0) fail("cannot allocate audio frame for", buffered);
}

void Writer::addSubtitles(const VideoSetup& setup, const MediaExtras& extras) {
  const AVCodec* encoder = avcodec_find_encoder_by_name(setup.subtitle_encoder.c_str());
  if (encoder == nullptr) {
    throw OutputError("cannot write video '" + target_.string() + "': subtitle encoder " +
                      setup.subtitle_encoder + " is not available in this libavcodec; " +
                      missingEncoderAdvice(setup.subtitle_encoder) +
                      " or leave out --embed-captions");
  }
  subtitle_codec_.reset(avcodec_alloc_context3(encoder));
  if (subtitle_codec_ == nullptr) fail("cannot set up subtitles for", AVERROR(ENOMEM));
  AVCodecContext& c = *subtitle_codec_;
  c.time_base = AVRational{1, 1000};  // milliseconds, as caption files count
  const std::size_t header_size = std::strlen(kAssHeader);
  // The codec context owns and frees subtitle_header, so it comes from av_malloc.
  c.subtitle_header = static_cast<std::uint8_t*>(av_mallocz(header_size + 1));
  if (c.subtitle_header == nullptr) fail("cannot set up subtitles for", AVERROR(ENOMEM));
  std::memcpy(c.subtitle_header, kAssHeader, header_size);
  c.subtitle_header_size = static_cast<int>(header_size);
  if (muxer_->oformat->flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  const int opened = avcodec_open2(&c, encoder, nullptr);
  if (opened < 0) fail("cannot open subtitle encoder " + setup.subtitle_encoder + " for", opened);
  subtitle_stream_ = avformat_new_stream(muxer_.get(), nullptr);
  if (subtitle_stream_ == nullptr) fail("cannot add subtitle stream to", AVERROR(ENOMEM));
  subtitle_stream_->time_base = c.time_base;
  const int copied = avcodec_parameters_from_context(subtitle_stream_->codecpar, &c);
  if (copied < 0) fail("cannot set up subtitle stream for", copied);
  av_dict_set(&subtitle_stream_->metadata, "language", streamLanguage(setup, extras).c_str(), 0);
  av_dict_set(&subtitle_stream_->metadata, "title", extras.subtitle_title.c_str(), 0);
  subtitles_ = extras.subtitles;
}

AVFrame& Writer::nextFrame() {
  if (frame_ == nullptr) frame_ = newVideoFrame();
  const int writable = av_frame_make_writable(frame_.get());
  if (writable < 0) fail("cannot encode video", writable);
  return *frame_;
}

void Writer::drain(AVCodecContext& codec, AVStream& stream, bool one_frame_packets) {
  for (;;) {
    const int result = avcodec_receive_packet(&codec, packet_.get());
    if (result == AVERROR(EAGAIN) || result == AVERROR_EOF) return;
    if (result < 0) fail("cannot encode", result);
    // libx264 in FFmpeg 5.1 leaves the duration at 0; the MP4 muxer would then give the last frame
    // no time and the file would be one frame short. Each video packet lasts one frame.
    if (one_frame_packets && packet_->duration == 0) packet_->duration = 1;
    av_packet_rescale_ts(packet_.get(), codec.time_base, stream.time_base);
    packet_->stream_index = stream.index;
    // Takes over the packet's data and leaves it blank for the next round.
    const int written = av_interleaved_write_frame(muxer_.get(), packet_.get());
    if (written < 0) fail("cannot write", written);
  }
}

void Writer::encodeFrame() {
  COLLIDE_ASSERT(frame_ != nullptr, "encodeFrame() before nextFrame()");
  encodeFrame(*frame_);
}

void Writer::encodeFrame(AVFrame& picture) {
  picture.pts = frames_written_;
  const int sent = avcodec_send_frame(video_codec_.get(), &picture);
  if (sent < 0) fail("cannot encode video", sent);
  drain(*video_codec_, *video_stream_, true);
  ++frames_written_;
  // Sound and captions follow the pictures, so the muxer interleaves them in small steps.
  const double until_s = static_cast<double>(frames_written_) / format_.fps;
  writeSubtitlesUntil(until_s);
  if (audio_) encodeAudioUntil(std::llround(until_s * audio_->codec->sample_rate), false);
}

void Writer::encodeAudioUntil(long long end_sample, bool flush) {
  Audio& a = *audio_;
  AVCodecContext& c = *a.codec;
  const auto total = static_cast<long long>(a.samples.size());
  const long long limit = std::min(end_sample, total);
  const int frame_size = a.frame->nb_samples;
  while (a.next_sample < limit) {
    const long long available = limit - a.next_sample;
    // Whole frames only, until the track's end: a short frame is only allowed last.
    if (available < frame_size && limit < total) break;
    const int count = static_cast<int>(std::min<long long>(frame_size, available));
    const int writable = av_frame_make_writable(a.frame.get());
    if (writable < 0) fail("cannot encode audio", writable);
    auto* out = reinterpret_cast<float*>(a.frame->data[0]);
    std::copy_n(a.samples.begin() + a.next_sample, count, out);
    std::fill(out + count, out + frame_size, 0.0f);  // silence pads a short last frame
    a.frame->nb_samples = count < frame_size && a.small_last_frame ? count : frame_size;
    a.frame->pts = a.next_sample;
    const int sent = avcodec_send_frame(&c, a.frame.get());
    a.frame->nb_samples = frame_size;
    if (sent < 0) fail("cannot encode audio", sent);
    drain(c, *a.stream, false);
    a.next_sample += count;
  }
  if (flush) {
    const int sent = avcodec_send_frame(&c, nullptr);
    if (sent < 0) fail("cannot encode audio", sent);
    drain(c, *a.stream, false);
  }
}

void Writer::writeSubtitlesUntil(double until_s) {
  std::vector<std::uint8_t> buffer(1 << 16);
  while (next_subtitle_ < subtitles_.size() && subtitles_[next_subtitle_].start_s < until_s) {
    const TimedText& cue = subtitles_[next_subtitle_++];
    const long long start_ms = std::llround(cue.start_s * 1000.0);
    const long long end_ms = std::max(start_ms + 1, std::llround(cue.end_s * 1000.0));
    std::string dialogue = "0,0,Default,,0,0,0,," + assText(cue.text);
    AVSubtitleRect rect{};
    rect.type = SUBTITLE_ASS;
    rect.ass = dialogue.data();
    AVSubtitleRect* rects[1] = {&rect};
    AVSubtitle subtitle{};
    subtitle.format = 1;  // text
    subtitle.start_display_time = 0;
    subtitle.end_display_time = static_cast<std::uint32_t>(end_ms - start_ms);
    subtitle.num_rects = 1;
    subtitle.rects = rects;
    // AV_TIME_BASE_Q is a C compound literal (clang warns in C++): the same rational spelled out.
    subtitle.pts = av_rescale_q(start_ms, AVRational{1, 1000}, AVRational{1, AV_TIME_BASE});
    const int size = avcodec_encode_subtitle(subtitle_codec_.get(), buffer.data(),
                                             static_cast<int>(buffer.size()), &subtitle);
    if (size < 0) fail("cannot encode captions", size);
    const int allocated = av_new_packet(packet_.get(), size);
    if (allocated < 0) fail("cannot encode captions", allocated);
    std::memcpy(packet_->data, buffer.data(), static_cast<std::size_t>(size));
    packet_->pts = packet_->dts = start_ms;
    packet_->duration = end_ms - start_ms;
    av_packet_rescale_ts(packet_.get(), AVRational{1, 1000}, subtitle_stream_->time_base);
    packet_->stream_index = subtitle_stream_->index;
    const int written = av_interleaved_write_frame(muxer_.get(), packet_.get());
    if (written < 0) fail("cannot write captions to", written);
  }
}

void Writer::finish() {
  const int sent = avcodec_send_frame(video_codec_.get(), nullptr);  // end of stream: drain
  if (sent < 0) fail("cannot encode video", sent);
  drain(*video_codec_, *video_stream_, true);
  if (audio_) encodeAudioUntil(std::numeric_limits<long long>::max(), true);
  writeSubtitlesUntil(std::numeric_limits<double>::infinity());
  const int trailer = av_write_trailer(muxer_.get());
  if (trailer < 0) fail("cannot finish video", trailer);
  const int closed = avio_closep(&muxer_->pb);
  if (closed < 0) fail("cannot finish video", closed);
  file_.commit();
}

void convertRgba(const core::ImageView& image, AVFrame& frame, const std::filesystem::path& target,
                 const std::vector<core::ImageRect>* rects) {
  const bool alpha = frame.format == AV_PIX_FMT_YUVA420P;
  COLLIDE_ASSERT(alpha || frame.format == AV_PIX_FMT_YUV420P, "a 4:2:0 frame to convert into");
  COLLIDE_ASSERT(frame.width == image.width && frame.height == image.height,
                 "frame and image sizes differ");
  const int writable = av_frame_make_writable(&frame);
  if (writable < 0) throw OutputError(errorMessage("cannot encode video", target, writable));
  Yuv420Planes planes;
  planes.luma = frame.data[0];
  planes.luma_stride = frame.linesize[0];
  planes.cb = frame.data[1];
  planes.cb_stride = frame.linesize[1];
  planes.cr = frame.data[2];
  planes.cr_stride = frame.linesize[2];
  if (alpha) {
    planes.alpha = frame.data[3];
    planes.alpha_stride = frame.linesize[3];
  }
  if (rects == nullptr) {
    rgbaToYuv420Bt709(image, planes);
  } else {
    rgbaToYuv420Bt709(image, planes, *rects);
  }
}

}  // namespace collide::output::av
