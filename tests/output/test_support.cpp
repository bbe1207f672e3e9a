#include "output/test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "output/codec_log.hpp"
#include "png_io.hpp"

namespace collide::output::test {
namespace {
// Keep libx264's settings banner and statistics out of the test log; errors still show.
const bool kCodecLogQuieted = (setCodecLogLevel(CodecLogLevel::kErrors), true);
}  // namespace

core::Image makeFrame(int width, int height, int frame_index) {
  core::Image image(width, height);
  const int square = std::max(4, height / 6);                            // side, pixels
  const int square_x = (frame_index * 3) % std::max(1, width - square);  // moves 3 px per frame
  const int square_y = height / 3;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      const bool in_square =
          x >= square_x && x < square_x + square && y >= square_y && y < square_y + square;
      if (in_square) {
        p[0] = p[1] = p[2] = 240;
      } else {
        p[0] = static_cast<std::uint8_t>(40 + 160 * x / std::max(1, width - 1));
        p[1] = static_cast<std::uint8_t>(30 + 120 * y / std::max(1, height - 1));
        p[2] = static_cast<std::uint8_t>(90 + (frame_index * 2) % 60);
      }
      p[3] = 255;
    }
  }
  return image;
}

core::ImageView bottomUpView(const core::Image& image, std::vector<std::uint8_t>& storage) {
  const std::size_t row_bytes = static_cast<std::size_t>(image.width()) * 4;
  storage.resize(row_bytes * static_cast<std::size_t>(image.height()));
  // Memory row r holds picture row (height - 1 - r), as glReadPixels would leave it.
  for (int y = 0; y < image.height(); ++y) {
    std::memcpy(storage.data() + row_bytes * static_cast<std::size_t>(image.height() - 1 - y),
                image.pixel(0, y), row_bytes);
  }
  const std::uint8_t* top =
      storage.data() + row_bytes * static_cast<std::size_t>(image.height() - 1);
  return core::ImageView{top, image.width(), image.height(),
                         -static_cast<std::ptrdiff_t>(row_bytes)};
}

namespace {

// "collide-output-SUITE-TEST-": the directory says which test left it, should one be left.
std::string scratchPrefix() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string prefix = "collide-output-";
  if (info != nullptr) prefix += std::string(info->test_suite_name()) + "-" + info->name() + "-";
  return prefix;
}

}  // namespace

ScratchDirectory::ScratchDirectory() : ScratchDir(scratchPrefix()) {}

core::Image readPng(const std::filesystem::path& path) {
  try {
    return collide::test::readPng(path.string());
  } catch (const std::runtime_error& e) {
    ADD_FAILURE() << e.what();
    return {};
  }
}

int maxChannelDifference(const core::Image& a, const core::Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return 256;
  int worst = 0;
  const std::size_t n = static_cast<std::size_t>(a.width()) * a.height() * 4;
  for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(a.data()[i] - b.data()[i]));
  return worst;
}

}  // namespace collide::output::test
