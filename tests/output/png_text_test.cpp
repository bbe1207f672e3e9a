// PNG text chunks: what the file says about itself, read back with libpng.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <map>

#include "output/png_sinks.hpp"
#include "output/png_writer.hpp"
#include "output/test_support.hpp"

namespace collide::output {
namespace {

struct TextChunk {
  std::string text;
  bool international = false;  // iTXt rather than tEXt
};

std::map<std::string, TextChunk> readText(const std::filesystem::path& path) {
  std::map<std::string, TextChunk> chunks;
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    ADD_FAILURE() << "cannot open " << path;
    return chunks;
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    ADD_FAILURE() << "libpng failed on " << path;
  } else {
    png_init_io(png, file);
    png_read_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
    png_textp text = nullptr;
    const int count = png_get_text(png, info, &text, nullptr);
    for (int i = 0; i < count; ++i) {
      chunks[text[i].key] = {
          std::string(text[i].text,
                      text[i].text_length != 0 ? text[i].text_length : text[i].itxt_length),
          text[i].compression >= PNG_ITXT_COMPRESSION_NONE};
    }
  }
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(file);
  return chunks;
}

TEST(PngTextTest, StillCarriesTitleSoftwareAndUtf8Description) {
  test::ScratchDirectory dir;
  PngStillSink sink(dir / "still.png", {{"Title", "Two carts"},
                                        {"Software", "collide 0.1.0"},
                                        {"Description", "A 2 kg cart moving at 3 m/s → right"}});
  const core::Image frame = test::makeFrame(16, 16, 0);
  sink.begin({16, 16, 1});
  sink.write(frame.view());
  sink.finish();
  const auto chunks = readText(dir / "still.png");
  ASSERT_EQ(chunks.size(), 3u);
  EXPECT_EQ(chunks.at("Title").text, "Two carts");
  EXPECT_FALSE(chunks.at("Title").international);
  EXPECT_EQ(chunks.at("Software").text, "collide 0.1.0");
  EXPECT_EQ(chunks.at("Description").text, "A 2 kg cart moving at 3 m/s → right");
  EXPECT_TRUE(chunks.at("Description").international);
  EXPECT_EQ(test::maxChannelDifference(test::readPng(dir / "still.png"), frame), 0);
}

TEST(PngTextTest, EveryFrameOfASequenceCarriesTheText) {
  test::ScratchDirectory dir;
  PngSequenceSink sink(dir / "frames", {{"Comment", "scene worked-example"}});
  sink.begin({8, 8, 10});
  for (int i = 0; i < 2; ++i) sink.write(test::makeFrame(8, 8, i).view());
  sink.finish();
  for (const char* name : {"frame_00000.png", "frame_00001.png"}) {
    const auto chunks = readText(dir / "frames" / name);
    ASSERT_EQ(chunks.count("Comment"), 1u) << name;
    EXPECT_EQ(chunks.at("Comment").text, "scene worked-example");
  }
}

}  // namespace
}  // namespace collide::output
