#include "output/png_deflate.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

#include "output/test_support.hpp"

namespace collide::output {
namespace {

// The bytes a PNG's data carries for `image` with no row filter: each row after a 0 byte.
std::vector<std::uint8_t> filteredRows(const core::ImageView& image) {
  std::vector<std::uint8_t> bytes;
  for (int y = 0; y < image.height; ++y) {
    bytes.push_back(0);
    bytes.insert(bytes.end(), image.row(y), image.row(y) + image.width * 4);
  }
  return bytes;
}

// zlib's own inflate, which also checks the header and the Adler-32 at the end.
std::vector<std::uint8_t> inflated(const std::string& stream, std::size_t expected_size) {
  std::vector<std::uint8_t> out(expected_size + 1);  // one more: a longer result shows
  uLongf size = static_cast<uLongf>(out.size());
  const int result = uncompress(out.data(), &size, reinterpret_cast<const Bytef*>(stream.data()),
                                static_cast<uLong>(stream.size()));
  EXPECT_EQ(result, Z_OK);
  out.resize(size);
  return out;
}

// Every count of parts, one row each included, joins into one stream of exactly the image's rows.
TEST(PngDeflateTest, PartsJoinIntoOneStreamOfTheRows) {
  const core::Image source = test::makeFrame(301, 97, 4);
  const std::vector<std::uint8_t> rows = filteredRows(source.view());
  for (int parts : {1, 2, 3, 5, 97, 200}) {
    const std::string stream = deflateImageRows(source.view(), 2, parts);
    ASSERT_FALSE(stream.empty()) << parts;
    EXPECT_EQ(inflated(stream, rows.size()), rows) << parts << " parts";
  }
}

TEST(PngDeflateTest, BottomUpViewIsDeflatedUpright) {
  const core::Image source = test::makeFrame(64, 90, 1);
  std::vector<std::uint8_t> storage;
  const core::ImageView flipped = test::bottomUpView(source, storage);
  ASSERT_LT(flipped.row_stride, 0);
  const std::vector<std::uint8_t> rows = filteredRows(source.view());
  EXPECT_EQ(inflated(deflateImageRows(flipped, 2, 3), rows.size()), rows);
}

// Each part starts with the 32 KiB before it as its window, so matches still reach back across
// a cut: rows repeating the row above compress as well cut as whole (within the few bytes of the
// flush that ends each part and a code table each).
TEST(PngDeflateTest, PartsSeeTheRowsBeforeThem) {
  core::Image source(512, 200);
  for (int y = 0; y < source.height(); ++y) {
    for (int x = 0; x < source.width(); ++x) {
      std::uint8_t* p = source.pixel(x, y);
      // One row of noise-like bytes (a multiplicative hash), repeated down the image.
      const std::uint32_t h = static_cast<std::uint32_t>(x) * 2654435761u;
      p[0] = static_cast<std::uint8_t>(h >> 24);
      p[1] = static_cast<std::uint8_t>(h >> 16);
      p[2] = static_cast<std::uint8_t>(h >> 8);
      p[3] = 255;
    }
  }
  const std::size_t whole = deflateImageRows(source.view(), 2, 1).size();
  const std::size_t cut = deflateImageRows(source.view(), 2, 4).size();
  // Unprimed, each of the 3 later parts would store its first row's 2048 noise bytes again.
  EXPECT_LT(cut, whole + 3 * 256);
}

}  // namespace
}  // namespace collide::output
