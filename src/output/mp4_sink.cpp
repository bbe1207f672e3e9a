#include "output/mp4_sink.hpp"

extern "C" {
#include <libavutil/opt.h>
}

#include <algorithm>
#include <limits>

#include "output/av_resources.hpp"
#include "output/temp_file.hpp"

namespace collide::output {

// Everything libav: muxer, encoder, one reusable frame and packet, one RGBA→YUV converter.
// Follows FFmpeg's doc/examples/mux.c. Time stamps count frames: codec time base 1/fps.
struct Mp4Sink::Encoder {
  std::filesystem::path target;     // what the user asked for (named in errors)
  std::filesystem::path temporary;  // what libav writes; renamed to target at finish()
  av::OutputFormatPtr muxer;
  AVStream* stream = nullptr;  // owned by muxer
  av::CodecContextPtr codec;
  av::FramePtr frame;  // YUV420P, reused for every input frame
  av::PacketPtr packet;
  av::SwsPtr converter;
  bool header_written = false;

  ~Encoder() {
    // Close the file before deleting it; a finished encoder has already renamed it away.
    muxer.reset();
    removeQuietly(temporary);
  }

  void check(int result, const char* what) const {
    if (result < 0) throw OutputError(av::errorMessage(what, target, result));
  }

  // Sends one frame (nullptr: end of stream) and writes every packet the encoder has ready.
  void encode(const AVFrame* input) {
    check(avcodec_send_frame(codec.get(), input), "cannot encode video");
    for (;;) {
      const int result = avcodec_receive_packet(codec.get(), packet.get());
      if (result == AVERROR(EAGAIN) || result == AVERROR_EOF) return;
      check(result, "cannot encode video");
      // libx264 in FFmpeg 5.1 leaves the duration at 0; the MP4 muxer would then give the last
      // frame no time and the file would be one frame short. Each packet lasts one frame.
      if (packet->duration == 0) packet->duration = 1;
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      // Takes over the packet's data and leaves `packet` blank for the next round.
      check(av_interleaved_write_frame(muxer.get(), packet.get()), "cannot write video");
    }
  }
};

Mp4Sink::Mp4Sink(std::filesystem::path path, Mp4Options options)
    : path_(std::move(path)), options_(std::move(options)) {}

Mp4Sink::~Mp4Sink() = default;  // ~Encoder deletes the temporary file unless finish() renamed it

void Mp4Sink::begin(const FrameFormat& format) {
  COLLIDE_ASSERT(encoder_ == nullptr && !finished_, "begin() called twice");
  COLLIDE_ASSERT(format.width_px > 0 && format.height_px > 0 && format.fps > 0,
                 "empty frame format");
  if (format.width_px % 2 != 0 || format.height_px % 2 != 0) {
    throw OutputError("cannot write video '" + path_.string() + "': H.264 needs an even width " +
                      "and height, got " + std::to_string(format.width_px) + "x" +
                      std::to_string(format.height_px));
  }
  // Checked here rather than left to x264, which would also print its own complaint to stderr.
  if (std::find(kX264Presets.begin(), kX264Presets.end(), options_.preset) == kX264Presets.end()) {
    std::string allowed;
    for (const auto preset : kX264Presets)
      allowed += (allowed.empty() ? "" : ", ") + std::string(preset);
    throw OutputError("cannot write video '" + path_.string() + "': unknown x264 preset '" +
                      options_.preset + "' (allowed: " + allowed + ")");
  }
  if (options_.crf < 0 || options_.crf > kMaxCrf) {
    throw OutputError("cannot write video '" + path_.string() + "': crf " +
                      std::to_string(options_.crf) + " is outside 0.." + std::to_string(kMaxCrf));
  }
  failed_ = true;  // until begin() completes
  format_ = format;
  auto encoder = std::make_unique<Encoder>();
  Encoder& e = *encoder;
  e.target = path_;
  e.temporary = temporaryPathFor(path_);

  const AVCodec* h264 = avcodec_find_encoder_by_name("libx264");
  if (h264 == nullptr) throw OutputError("H.264 encoder libx264 not available");

  // The format is named, not guessed from the (temporary) file name.
  AVFormatContext* muxer = nullptr;
  e.check(avformat_alloc_output_context2(&muxer, nullptr, "mp4", e.temporary.c_str()),
          "cannot set up MP4 muxer for");
  e.muxer.reset(muxer);
  e.stream = avformat_new_stream(muxer, nullptr);
  if (e.stream == nullptr) e.check(AVERROR(ENOMEM), "cannot add video stream to");

  e.codec.reset(avcodec_alloc_context3(h264));
  if (e.codec == nullptr) e.check(AVERROR(ENOMEM), "cannot set up H.264 encoder for");
  AVCodecContext& c = *e.codec;
  c.width = format.width_px;
  c.height = format.height_px;
  c.pix_fmt = AV_PIX_FMT_YUV420P;
  c.time_base = AVRational{1, format.fps};  // one tick per frame
  c.framerate = AVRational{format.fps, 1};
  // Rendered RGB is converted with BT.709 matrices into limited range; say so in the stream so
  // players convert back with the same matrices.
  c.color_range = AVCOL_RANGE_MPEG;
  c.colorspace = AVCOL_SPC_BT709;
  c.color_primaries = AVCOL_PRI_BT709;
  c.color_trc = AVCOL_TRC_BT709;
  e.stream->time_base = c.time_base;
  // MP4 keeps SPS/PPS once in the avcC box, not in every keyframe.
  if (muxer->oformat->flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  av_opt_set(c.priv_data, "preset", options_.preset.c_str(), 0);
  av_opt_set_double(c.priv_data, "crf", options_.crf, 0);
  {
    const int result = avcodec_open2(&c, h264, nullptr);
    if (result < 0) {
      throw OutputError(av::errorMessage("cannot open H.264 encoder (preset '" + options_.preset +
                                             "', crf " + std::to_string(options_.crf) + ") for",
                                         path_, result));
    }
  }
  e.check(avcodec_parameters_from_context(e.stream->codecpar, &c),
          "cannot set up video stream for");

  for (const auto& [key, value] : options_.metadata) {
    av_dict_set(&muxer->metadata, key.c_str(), value.c_str(), 0);
  }

  e.check(avio_open(&muxer->pb, e.temporary.c_str(), AVIO_FLAG_WRITE), "cannot create video");
  {
    // +faststart: after the last frame the muxer moves the index (moov) before the frame data
    // (mdat), so playback can start before the whole file has arrived.
    AVDictionary* muxer_options = nullptr;
    av_dict_set(&muxer_options, "movflags", "+faststart", 0);
    const int result = avformat_write_header(muxer, &muxer_options);
    av_dict_free(&muxer_options);
    e.check(result, "cannot write video header to");
  }
  e.header_written = true;

  e.frame.reset(av_frame_alloc());
  e.packet.reset(av_packet_alloc());
  if (e.frame == nullptr || e.packet == nullptr) e.check(AVERROR(ENOMEM), "cannot encode video");
  e.frame->format = c.pix_fmt;
  e.frame->width = c.width;
  e.frame->height = c.height;
  e.check(av_frame_get_buffer(e.frame.get(), 0), "cannot allocate frame for");

  e.converter.reset(sws_getContext(c.width, c.height, AV_PIX_FMT_RGBA, c.width, c.height,
                                   AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr));
  if (e.converter == nullptr) e.check(AVERROR(ENOMEM), "cannot set up colour conversion for");
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  // Source RGB is full range (1), destination YUV limited range (0); brightness 0, contrast and
  // saturation 1.0 in 16.16 fixed point.
  sws_setColorspaceDetails(e.converter.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);

  encoder_ = std::move(encoder);
  failed_ = false;
}

void Mp4Sink::write(const core::ImageView& frame) {
  COLLIDE_ASSERT(encoder_ != nullptr && !finished_, "write() outside begin()/finish()");
  COLLIDE_ASSERT(frame.width == format_.width_px && frame.height == format_.height_px,
                 "frame size differs from the format given to begin()");
  COLLIDE_ASSERT(frame.row_stride <= std::numeric_limits<int>::max() &&
                     frame.row_stride >= std::numeric_limits<int>::min(),
                 "row stride out of int range");
  if (failed_) throw OutputError("cannot write video '" + path_.string() + "' after an error");
  failed_ = true;  // until this frame is through
  Encoder& e = *encoder_;
  // The encoder may still hold a reference to the previous frame's buffers.
  e.check(av_frame_make_writable(e.frame.get()), "cannot encode video");
  // A bottom-up view has a negative stride: sws_scale walks it upwards, flipping for free.
  const std::uint8_t* source_planes[4] = {frame.top_row, nullptr, nullptr, nullptr};
  const int source_strides[4] = {static_cast<int>(frame.row_stride), 0, 0, 0};
  sws_scale(e.converter.get(), source_planes, source_strides, 0, frame.height, e.frame->data,
            e.frame->linesize);
  e.frame->pts = frames_written_;
  e.encode(e.frame.get());
  ++frames_written_;
  failed_ = false;
}

void Mp4Sink::finish() {
  COLLIDE_ASSERT(encoder_ != nullptr && !finished_, "finish() outside begin()");
  if (failed_) throw OutputError("cannot finish video '" + path_.string() + "' after an error");
  if (frames_written_ == 0) {
    throw OutputError("cannot write video '" + path_.string() + "': no frames were rendered");
  }
  failed_ = true;
  Encoder& e = *encoder_;
  e.encode(nullptr);  // flush: the encoder holds back frames for lookahead and B-frames
  e.check(av_write_trailer(e.muxer.get()), "cannot finish video");
  e.check(avio_closep(&e.muxer->pb), "cannot finish video");
  renameOrThrow(e.temporary, e.target);
  e.temporary.clear();  // nothing left for ~Encoder to delete
  finished_ = true;
  failed_ = false;
  encoder_.reset();  // free the codec now rather than when the sink dies
}

}  // namespace collide::output
