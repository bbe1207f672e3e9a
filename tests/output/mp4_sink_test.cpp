#include "output/mp4_sink.hpp"

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>

#include "output/encode_thread.hpp"
#include "output/test_support.hpp"

namespace collide::output {
namespace {

using test::ScratchDirectory;

// What a test learns from reading a video back with libavformat/libavcodec.
struct VideoFacts {
  std::string codec;         // e.g. "h264"
  std::string pixel_format;  // e.g. "yuv420p"
  AVChromaLocation chroma_location = AVCHROMA_LOC_UNSPECIFIED;
  int width = 0;
  int height = 0;
  std::int64_t container_frames = 0;  // nb_frames from the MP4 index
  int decoded_frames = 0;
  double stream_seconds = 0;  // stream duration × time base
  double format_seconds = 0;  // container duration
  std::map<std::string, std::string> metadata;
  core::Image sample;  // decoded frame number `sample_index`, converted back to RGBA
};

VideoFacts readVideo(const std::filesystem::path& path, int sample_index) {
  VideoFacts facts;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
    ADD_FAILURE() << "cannot open " << path;
    return facts;
  }
  avformat_find_stream_info(format, nullptr);
  const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  EXPECT_GE(index, 0);
  if (index < 0) {
    avformat_close_input(&format);
    return facts;
  }
  const AVStream* stream = format->streams[index];
  const AVCodecParameters* par = stream->codecpar;
  facts.codec = avcodec_get_name(par->codec_id);
  const char* pix = av_get_pix_fmt_name(static_cast<AVPixelFormat>(par->format));
  facts.pixel_format = pix != nullptr ? pix : "?";
  facts.width = par->width;
  facts.chroma_location = par->chroma_location;
  facts.height = par->height;
  facts.container_frames = stream->nb_frames;
  facts.stream_seconds = static_cast<double>(stream->duration) * av_q2d(stream->time_base);
  facts.format_seconds = static_cast<double>(format->duration) / AV_TIME_BASE;
  const AVDictionaryEntry* tag = nullptr;
  while ((tag = av_dict_get(format->metadata, "", tag, AV_DICT_IGNORE_SUFFIX)) != nullptr) {
    facts.metadata[tag->key] = tag->value;
  }

  const AVCodec* decoder = avcodec_find_decoder(par->codec_id);
  AVCodecContext* codec = avcodec_alloc_context3(decoder);
  avcodec_parameters_to_context(codec, par);
  codec->thread_count = 1;
  EXPECT_EQ(avcodec_open2(codec, decoder, nullptr), 0);
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  auto take_frames = [&] {
    while (avcodec_receive_frame(codec, frame) == 0) {
      if (facts.decoded_frames == sample_index) {
        // Back to RGBA with the matrices the sink used (BT.709, limited range).
        facts.sample = core::Image(frame->width, frame->height);
        SwsContext* sws = sws_getContext(
            frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
            frame->height, AV_PIX_FMT_RGBA, SWS_BICUBIC, nullptr, nullptr, nullptr);
        const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(sws, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
        std::uint8_t* dst[4] = {facts.sample.data(), nullptr, nullptr, nullptr};
        const int dst_stride[4] = {4 * frame->width, 0, 0, 0};
        sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, dst_stride);
        sws_freeContext(sws);
      }
      ++facts.decoded_frames;
      av_frame_unref(frame);
    }
  };
  while (av_read_frame(format, packet) == 0) {
    if (packet->stream_index == index) {
      avcodec_send_packet(codec, packet);
      take_frames();
    }
    av_packet_unref(packet);
  }
  avcodec_send_packet(codec, nullptr);
  take_frames();
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&codec);
  avformat_close_input(&format);
  return facts;
}

// Four-character types of the top-level MP4 boxes, in file order.
std::vector<std::string> topLevelBoxes(const std::filesystem::path& path) {
  std::vector<std::string> boxes;
  std::ifstream file(path, std::ios::binary);
  const auto file_size = static_cast<std::uint64_t>(std::filesystem::file_size(path));
  std::uint64_t offset = 0;
  while (offset + 8 <= file_size) {
    unsigned char header[16];
    file.seekg(static_cast<std::streamoff>(offset));
    file.read(reinterpret_cast<char*>(header), 8);
    std::uint64_t size = (std::uint64_t{header[0]} << 24) | (std::uint64_t{header[1]} << 16) |
                         (std::uint64_t{header[2]} << 8) | header[3];
    boxes.emplace_back(reinterpret_cast<char*>(header + 4), 4);
    if (size == 1) {  // 64-bit size follows the type
      file.read(reinterpret_cast<char*>(header + 8), 8);
      size = 0;
      for (int i = 8; i < 16; ++i) size = (size << 8) | header[i];
    } else if (size == 0) {  // box runs to the end of the file
      size = file_size - offset;
    }
    if (size < 8) break;
    offset += size;
  }
  return boxes;
}

int indexOf(const std::vector<std::string>& list, const std::string& item) {
  const auto it = std::find(list.begin(), list.end(), item);
  return it == list.end() ? -1 : static_cast<int>(it - list.begin());
}

double meanAbsoluteError(const core::Image& a, const core::Image& b) {
  double sum = 0;
  std::size_t count = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      for (int c = 0; c < 3; ++c) {  // RGB; the video has no alpha
        sum += std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]);
        ++count;
      }
    }
  }
  return sum / static_cast<double>(count);
}

// Writes `frame_count` synthetic frames, every other one through a bottom-up view.
void writeVideo(Mp4Sink& sink, const FrameFormat& format, int frame_count) {
  sink.begin(format);
  std::vector<std::uint8_t> storage;
  for (int i = 0; i < frame_count; ++i) {
    const core::Image frame = test::makeFrame(format.width_px, format.height_px, i);
    sink.write(i % 2 == 0 ? frame.view() : test::bottomUpView(frame, storage));
  }
}

TEST(Mp4SinkTest, WritesEveryFrameWithExactDurationAndFastStart) {
  ScratchDirectory dir;
  const FrameFormat format{320, 180, 30};
  const int frames = 120;  // 4.0 s at 30 fps
  Mp4Options options;
  MediaExtras extras;
  extras.metadata = {{"title", "Two carts"}, {"comment", "e = 0.8"}};
  Mp4Sink sink(dir / "video.mp4", options, extras);
  writeVideo(sink, format, frames);
  EXPECT_FALSE(std::filesystem::exists(dir / "video.mp4"));  // still under its temporary name
  sink.finish();
  EXPECT_EQ(sink.framesWritten(), frames);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"video.mp4"});

  const int sample = 61;  // odd: written through a bottom-up view
  const VideoFacts facts = readVideo(dir / "video.mp4", sample);
  EXPECT_EQ(facts.codec, "h264");
  EXPECT_EQ(facts.pixel_format, "yuv420p");
  EXPECT_EQ(facts.width, 320);
  EXPECT_EQ(facts.height, 180);
  EXPECT_EQ(facts.container_frames, frames);
  EXPECT_EQ(facts.decoded_frames, frames);
  EXPECT_NEAR(facts.stream_seconds, 4.0, 1e-3);
  EXPECT_NEAR(facts.format_seconds, 4.0, 1e-3);
  EXPECT_EQ(facts.metadata.count("title") ? facts.metadata.at("title") : "", "Two carts");
  EXPECT_EQ(facts.metadata.count("comment") ? facts.metadata.at("comment") : "", "e = 0.8");

  const auto boxes = topLevelBoxes(dir / "video.mp4");
  const int moov = indexOf(boxes, "moov");
  const int mdat = indexOf(boxes, "mdat");
  ASSERT_GE(moov, 0);
  ASSERT_GE(mdat, 0);
  EXPECT_LT(moov, mdat) << "moov must come before mdat (+faststart)";

  // Lossy (4:2:0 chroma, crf 20), but the picture must be the source picture, upright.
  ASSERT_EQ(facts.sample.width(), 320);
  const core::Image source = test::makeFrame(320, 180, sample);
  const double error = meanAbsoluteError(source, facts.sample);
  EXPECT_LT(error, 3.0) << "mean absolute error per channel, levels of 255";
  // Upside down would put the moving square's rows far from the source's.
  core::Image upside_down(320, 180);
  for (int y = 0; y < 180; ++y) {
    std::memcpy(upside_down.pixel(0, y), source.pixel(0, 179 - y), 320 * 4);
  }
  EXPECT_GT(meanAbsoluteError(upside_down, facts.sample), 2 * error + 1.0);
}

TEST(Mp4SinkTest, FramesStagedThroughTheEncodeThreadAreTheSourcePictures) {
  // The render path: the drawing thread converts each frame into one of the encoder's Y'CbCr
  // frames (stage), the encode thread only encodes it (writeStaged).
  ScratchDirectory dir;
  const FrameFormat format{320, 180, 30};
  const int frames = 30;
  Mp4Sink sink(dir / "staged.mp4");
  sink.begin(format);
  ASSERT_NE(sink.newStagedFrame(), nullptr);
  {
    EncodeThread encoder(sink, format.width_px, format.height_px, 1, 3);
    std::vector<std::uint8_t> storage;
    for (int i = 0; i < frames; ++i) {
      const core::Image frame = test::makeFrame(format.width_px, format.height_px, i);
      encoder.submit(i % 2 == 0 ? frame.view() : test::bottomUpView(frame, storage));
    }
    encoder.finish();
  }
  EXPECT_EQ(sink.framesWritten(), frames);
  for (const int sample : {0, 17}) {  // top-down and bottom-up
    const VideoFacts facts = readVideo(dir / "staged.mp4", sample);
    EXPECT_EQ(facts.decoded_frames, frames);
    // Each chroma sample is a 2x2 mean, centred in its block, and the stream says so.
    EXPECT_EQ(facts.chroma_location, AVCHROMA_LOC_CENTER);
    ASSERT_EQ(facts.sample.width(), 320);
    EXPECT_LT(meanAbsoluteError(test::makeFrame(320, 180, sample), facts.sample), 3.0)
        << "frame " << sample;
  }
}

TEST(Mp4SinkTest, OddSizeIsAnOutputError) {
  ScratchDirectory dir;
  Mp4Sink sink(dir / "odd.mp4");
  EXPECT_THROW(sink.begin(FrameFormat{321, 180, 30}), OutputError);
  Mp4Sink sink2(dir / "odd2.mp4");
  EXPECT_THROW(sink2.begin(FrameFormat{320, 181, 30}), OutputError);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Mp4SinkTest, DestroyedWithoutFinishLeavesNoFile) {
  ScratchDirectory dir;
  {
    Mp4Sink sink(dir / "video.mp4");
    writeVideo(sink, FrameFormat{64, 36, 30}, 10);
    EXPECT_EQ(dir.entries().size(), 1u);  // the temporary file exists while writing
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Mp4SinkTest, FinishWithoutFramesIsAnOutputError) {
  ScratchDirectory dir;
  {
    Mp4Sink sink(dir / "video.mp4");
    sink.begin(FrameFormat{64, 36, 30});
    EXPECT_THROW(sink.finish(), OutputError);
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Mp4SinkTest, MissingDirectoryIsAnOutputErrorNamingThePath) {
  ScratchDirectory dir;
  const auto target = dir / "missing" / "video.mp4";
  Mp4Sink sink(target);
  try {
    sink.begin(FrameFormat{64, 36, 30});
    FAIL() << "expected OutputError";
  } catch (const OutputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(target.string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Mp4SinkTest, UnknownPresetOrCrfOutOfRangeIsAnOutputError) {
  ScratchDirectory dir;
  Mp4Options options;
  options.preset = "warp-speed";
  Mp4Sink sink(dir / "video.mp4", options);
  try {
    sink.begin(FrameFormat{64, 36, 30});
    FAIL() << "expected OutputError";
  } catch (const OutputError& error) {
    EXPECT_NE(std::string(error.what()).find("warp-speed"), std::string::npos) << error.what();
  }
  options.preset = "medium";
  options.crf = 52;
  Mp4Sink sink2(dir / "video.mp4", options);
  EXPECT_THROW(sink2.begin(FrameFormat{64, 36, 30}), OutputError);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Mp4SinkTest, ShortVideoAtOtherFrameRateHasExactDuration) {
  ScratchDirectory dir;
  Mp4Sink sink(dir / "short.mp4");
  writeVideo(sink, FrameFormat{64, 36, 24}, 6);  // 0.25 s
  sink.finish();
  const VideoFacts facts = readVideo(dir / "short.mp4", 0);
  EXPECT_EQ(facts.decoded_frames, 6);
  EXPECT_EQ(facts.container_frames, 6);
  EXPECT_NEAR(facts.stream_seconds, 0.25, 1e-3);
}

}  // namespace
}  // namespace collide::output
