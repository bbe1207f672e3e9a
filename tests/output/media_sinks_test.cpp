// MP4 with sound and captions, WebM (with and without alpha), GIF: each written file is read back
// through libavformat/libavcodec and checked for codec, size, pixel format, frames, duration,
// sound, captions, palette and alpha.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "output/gif_sink.hpp"
#include "output/media_probe.hpp"
#include "output/mp4_sink.hpp"
#include "output/test_support.hpp"
#include "output/webm_sink.hpp"

namespace collide::output {
namespace {

using test::ScratchDirectory;

constexpr int kRate = 48000;

// A 10 ms 1 kHz burst at each time, on silence: easy to find again after lossy coding.
AudioTrack bursts(const std::vector<double>& times_s, double length_s) {
  AudioTrack track;
  track.samples.assign(static_cast<std::size_t>(std::llround(length_s * kRate)), 0.0f);
  for (const double t : times_s) {
    const auto first = static_cast<std::size_t>(std::ceil(t * kRate));
    for (std::size_t n = first; n < first + kRate / 100 && n < track.samples.size(); ++n) {
      track.samples[n] =
          static_cast<float>(0.7 * std::sin(2 * M_PI * 1000.0 * (n / double(kRate) - t)) + 0.1);
    }
  }
  return track;
}

// Times where the decoded sound first exceeds half the bursts' level after 50 ms of quiet.
std::vector<double> onsets(const std::vector<float>& samples, int rate) {
  std::vector<double> found;
  long long last_loud = -rate;
  for (std::size_t n = 0; n < samples.size(); ++n) {
    if (std::fabs(samples[n]) > 0.35f) {
      if (static_cast<long long>(n) - last_loud > rate / 20) found.push_back(double(n) / rate);
      last_loud = static_cast<long long>(n);
    }
  }
  return found;
}

template <typename Sink>
void writeFrames(Sink& sink, const FrameFormat& format, int count) {
  sink.begin(format);
  std::vector<std::uint8_t> storage;
  for (int i = 0; i < count; ++i) {
    const core::Image frame = test::makeFrame(format.width_px, format.height_px, i);
    sink.write(i % 2 == 0 ? frame.view() : test::bottomUpView(frame, storage));
  }
  sink.finish();
}

TEST(MediaSinksTest, Mp4CarriesAacSoundAndMovTextCaptions) {
  ScratchDirectory dir;
  MediaExtras extras;
  extras.audio = bursts({0.5, 1.25}, 2.0);
  extras.subtitles = {{0.0, 0.5, "Start"}, {0.5, 1.25, "First hit\nline two"}, {1.25, 2.0, "End"}};
  extras.metadata = {{"title", "Bursts"}};
  Mp4Sink sink(dir / "sound.mp4", {}, extras);
  writeFrames(sink, {160, 90, 24}, 48);  // 2 s
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"sound.mp4"});

  const test::MediaFacts facts = test::probeMedia(dir / "sound.mp4");
  EXPECT_EQ(facts.video_frames, 48);
  EXPECT_EQ(facts.metadata.count("title") ? facts.metadata.at("title") : "", "Bursts");
  const test::StreamFacts* audio = test::findStream(facts, "audio");
  ASSERT_NE(audio, nullptr);
  EXPECT_EQ(audio->codec, "aac");
  EXPECT_EQ(audio->sample_rate_hz, kRate);
  // The muxer's edit list hides the encoder's priming samples: the sound starts at 0 and lasts
  // as long as the pictures, to within one AAC frame.
  EXPECT_NEAR(static_cast<double>(facts.audio.size()) / kRate, 2.0, 1024.0 / kRate);
  const std::vector<double> found = onsets(facts.audio, kRate);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0], 0.5, 0.002);
  EXPECT_NEAR(found[1], 1.25, 0.002);

  const test::StreamFacts* text = test::findStream(facts, "subtitle");
  ASSERT_NE(text, nullptr);
  EXPECT_EQ(text->codec, "mov_text");
  EXPECT_EQ(text->metadata.count("language") ? text->metadata.at("language") : "", "eng");
  ASSERT_EQ(facts.cues.size(), 3u);
  EXPECT_NEAR(facts.cues[1].start_s, 0.5, 1e-3);
  EXPECT_NEAR(facts.cues[1].end_s, 1.25, 1e-3);
  EXPECT_NE(facts.cues[1].text.find("First hit\\Nline two"), std::string::npos)
      << facts.cues[1].text;
}

TEST(MediaSinksTest, WebmIsVp9WithExactFramesAndDuration) {
  ScratchDirectory dir;
  MediaExtras extras;
  extras.metadata = {{"title", "Gradient"}};
  WebmSink sink(dir / "clip.webm", {}, extras);
  writeFrames(sink, {160, 90, 30}, 30);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.webm"});
  const test::MediaFacts facts = test::probeMedia(dir / "clip.webm", {15});
  EXPECT_EQ(facts.container, "matroska,webm");
  ASSERT_EQ(facts.streams.size(), 1u);
  EXPECT_EQ(facts.streams[0].codec, "vp9");
  EXPECT_EQ(facts.streams[0].format, "yuv420p");
  EXPECT_EQ(facts.streams[0].width, 160);
  EXPECT_EQ(facts.streams[0].height, 90);
  EXPECT_EQ(facts.video_frames, 30);
  EXPECT_NEAR(facts.duration_s, 1.0, 1e-3);
  EXPECT_EQ(facts.metadata.count("title") ? facts.metadata.at("title") : "", "Gradient");
  ASSERT_EQ(facts.kept.size(), 1u);
  EXPECT_LE(test::maxChannelDifference(facts.kept[0], test::makeFrame(160, 90, 15)), 40);
}

TEST(MediaSinksTest, WebmKeepsAlphaUnderTransparency) {
  ScratchDirectory dir;
  WebmOptions options;
  options.alpha = true;
  WebmSink sink(dir / "alpha.webm", options);
  const FrameFormat format{64, 48, 25};
  sink.begin(format);
  for (int i = 0; i < 10; ++i) {
    core::Image frame = test::makeFrame(64, 48, i);
    for (int y = 0; y < 48; ++y) {
      for (int x = 0; x < 32; ++x) frame.pixel(x, y)[3] = 0;  // left half transparent
    }
    sink.write(frame.view());
  }
  sink.finish();
  const test::MediaFacts facts = test::probeMedia(dir / "alpha.webm", {5}, "libvpx-vp9");
  ASSERT_EQ(facts.streams.size(), 1u);
  EXPECT_EQ(facts.streams[0].metadata.count("alpha_mode")
                ? facts.streams[0].metadata.at("alpha_mode")
                : "",
            "1");
  EXPECT_EQ(facts.video_frames, 10);
  EXPECT_EQ(facts.decoded_format, "yuva420p");
  ASSERT_EQ(facts.kept.size(), 1u);
  EXPECT_LE(facts.kept[0].pixel(8, 24)[3], 10);
  EXPECT_GE(facts.kept[0].pixel(56, 24)[3], 245);
}

TEST(MediaSinksTest, WebmCarriesOpusSoundAndWebVttCaptions) {
  ScratchDirectory dir;
  MediaExtras extras;
  extras.audio = bursts({0.4}, 1.0);
  extras.subtitles = {{0.0, 0.4, "Start"}, {0.4, 1.0, "Hit"}};
  WebmSink sink(dir / "sound.webm", {}, extras);
  writeFrames(sink, {64, 48, 25}, 25);
  const test::MediaFacts facts = test::probeMedia(dir / "sound.webm");
  const test::StreamFacts* audio = test::findStream(facts, "audio");
  ASSERT_NE(audio, nullptr);
  EXPECT_EQ(audio->codec, "opus");
  const std::vector<double> found = onsets(facts.audio, facts.audio_rate_hz);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0], 0.4, 0.002);
  const test::StreamFacts* text = test::findStream(facts, "subtitle");
  ASSERT_NE(text, nullptr);
  EXPECT_EQ(text->codec, "webvtt");
  ASSERT_EQ(facts.cues.size(), 2u);
  // Opus starts 6.5 ms early (its encoder delay), so the muxer shifts every stream by that much to
  // keep timestamps non-negative: captions stay in step with the pictures.
  const test::StreamFacts* video = test::findStream(facts, "video");
  ASSERT_NE(video, nullptr);
  EXPECT_LT(video->start_s, 0.01);
  EXPECT_NEAR(facts.cues[1].start_s - video->start_s, 0.4, 1e-3);
}

// Flat colours and a moving square in a fourth colour: 4 colours in all.
core::Image flatFrame(int width, int height, int index, bool hole) {
  core::Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      const bool square = x >= index * 2 && x < index * 2 + 8 && y >= 20 && y < 28;
      static constexpr std::uint8_t kSquare[] = {220, 60, 40};
      static constexpr std::uint8_t kTop[] = {250, 248, 240};
      static constexpr std::uint8_t kBottomLeft[] = {31, 119, 180};
      static constexpr std::uint8_t kBottomRight[] = {128, 128, 128};
      const std::uint8_t* c = square           ? kSquare
                              : y < height / 2 ? kTop
                              : x < width / 2  ? kBottomLeft
                                               : kBottomRight;
      p[0] = c[0];
      p[1] = c[1];
      p[2] = c[2];
      p[3] = hole && x < 4 ? 0 : 255;
    }
  }
  return image;
}

TEST(MediaSinksTest, GifHasAGeneratedGlobalPaletteAndExactColours) {
  ScratchDirectory dir;
  GifSink sink(dir / "anim.gif");
  const FrameFormat format{64, 48, 25};
  sink.begin(format);
  for (int i = 0; i < 20; ++i) sink.write(flatFrame(64, 48, i, false).view());
  sink.finish();
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"anim.gif"});

  // Header: "GIF89a", width, height, then flags with the global colour table bit (0x80).
  std::ifstream file(dir / "anim.gif", std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), {});
  ASSERT_GT(bytes.size(), 13u);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 6), "GIF89a");
  EXPECT_EQ(bytes[6] | bytes[7] << 8, 64);
  EXPECT_EQ(bytes[8] | bytes[9] << 8, 48);
  ASSERT_TRUE(bytes[10] & 0x80) << "no global colour table";
  const int table_size = 2 << (bytes[10] & 0x07);
  std::vector<std::array<int, 3>> table;
  for (int i = 0; i < table_size; ++i) {
    table.push_back({bytes[13 + 3 * i], bytes[14 + 3 * i], bytes[15 + 3 * i]});
  }
  for (const std::array<int, 3> colour :
       {std::array<int, 3>{220, 60, 40}, {250, 248, 240}, {31, 119, 180}, {128, 128, 128}}) {
    EXPECT_NE(std::find(table.begin(), table.end(), colour), table.end())
        << colour[0] << "," << colour[1] << "," << colour[2];
  }

  const test::MediaFacts facts = test::probeMedia(dir / "anim.gif", {0, 13});
  ASSERT_EQ(facts.streams.size(), 1u);
  EXPECT_EQ(facts.streams[0].codec, "gif");
  EXPECT_EQ(facts.video_frames, 20);
  EXPECT_NEAR(facts.duration_s, 0.8, 0.011);  // 20 frames of 4 hundredths
  ASSERT_EQ(facts.kept.size(), 2u);
  EXPECT_EQ(test::maxChannelDifference(facts.kept[1], flatFrame(64, 48, 13, false)), 0);
}

TEST(MediaSinksTest, GifMakesLowAlphaTransparent) {
  ScratchDirectory dir;
  GifOptions options;
  options.transparency = true;
  GifSink sink(dir / "hole.gif", options);
  sink.begin({64, 48, 25});
  for (int i = 0; i < 3; ++i) sink.write(flatFrame(64, 48, i, true).view());
  sink.finish();
  const test::MediaFacts facts = test::probeMedia(dir / "hole.gif", {2});
  ASSERT_EQ(facts.kept.size(), 1u);
  EXPECT_EQ(facts.kept[0].pixel(1, 40)[3], 0);
  EXPECT_EQ(facts.kept[0].pixel(40, 40)[3], 255);
}

TEST(MediaSinksTest, GifDestroyedBeforeFinishLeavesNothing) {
  ScratchDirectory dir;
  {
    GifSink sink(dir / "gone.gif");
    sink.begin({32, 32, 25});
    sink.write(flatFrame(32, 32, 0, false).view());
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(MediaSinksTest, PaletteIsExactForFewColoursAndCloseForMany) {
  ColorHistogram few;
  std::vector<std::uint16_t> keys(3);
  const std::uint8_t row[] = {10, 20, 30, 255, 11, 20, 30, 255, 200, 100, 0, 255};
  few.addRow(row, 3, false, keys.data());
  const Palette exact = buildPalette(few, 256);
  // 10,20,30 and 11,20,30 share a bin: its mean, 10.5 -> 11 (rounded), is the colour.
  ASSERT_EQ(exact.colors.size(), 2u);
  EXPECT_EQ(exact.colors[exact.index_of_key[keys[2]]], (std::array<std::uint8_t, 3>{200, 100, 0}));

  ColorHistogram many;
  std::vector<std::uint8_t> gradient(256 * 4);
  std::vector<std::uint16_t> many_keys(256);
  for (int x = 0; x < 256; ++x) {
    gradient[4 * x] = static_cast<std::uint8_t>(x);
    gradient[4 * x + 1] = static_cast<std::uint8_t>(255 - x);
    gradient[4 * x + 2] = 128;
    gradient[4 * x + 3] = 255;
  }
  many.addRow(gradient.data(), 256, false, many_keys.data());
  const Palette reduced = buildPalette(many, 16);
  EXPECT_EQ(reduced.colors.size(), 16u);
  for (int x = 0; x < 256; ++x) {
    const auto& c = reduced.colors[reduced.index_of_key[many_keys[x]]];
    EXPECT_LE(std::abs(c[0] - x), 12) << x;
  }
}

}  // namespace
}  // namespace collide::output
