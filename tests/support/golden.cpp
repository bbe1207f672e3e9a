#include "golden.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "png_io.hpp"

namespace collide::test {
namespace {

namespace fs = std::filesystem;

constexpr int kDiffAmplification = 16;

bool updateRequested() {
  const char* value = std::getenv("GOLDEN_UPDATE");
  return value != nullptr && std::string(value) == "1";
}

fs::path rendererFile() {
  return fs::path(goldenSourceDir()) / "RENDERER.txt";
}

std::string recordedRenderer() {
  std::ifstream in(rendererFile());
  std::string line;
  std::getline(in, line);
  return line;
}

void recordRenderer(const std::string& renderer) {
  if (renderer.empty()) return;
  std::ofstream(rendererFile()) << renderer << '\n';
}

// Writes actual (and expected + difference when given) next to each other for inspection.
std::string writeFailureImages(const std::string& golden_name, const core::ImageView& actual,
                               const core::ImageView* expected) {
  const fs::path base = fs::path(goldenFailureDir()) / golden_name;
  const std::string stem = (base.parent_path() / base.stem()).string();
  writePng(stem + ".actual.png", actual);
  if (expected != nullptr) {
    writePng(stem + ".expected.png", *expected);
    writePng(stem + ".diff.png", amplifiedDifference(actual, *expected).view());
  }
  return stem + ".actual.png";
}

}  // namespace

std::string goldenSourceDir() {
  return COLLIDE_GOLDEN_SOURCE_DIR;
}
std::string goldenFailureDir() {
  return COLLIDE_GOLDEN_FAILURE_DIR;
}

ImageDifference compareImages(const core::ImageView& actual, const core::ImageView& expected,
                              int channel_tolerance) {
  ImageDifference result;
  result.same_size = actual.width == expected.width && actual.height == expected.height;
  if (!result.same_size) return result;
  double sum_squares = 0.0;
  for (int y = 0; y < actual.height; ++y) {
    const std::uint8_t* a = actual.row(y);
    const std::uint8_t* e = expected.row(y);
    for (int x = 0; x < actual.width; ++x) {
      int pixel_max = 0;
      for (int c = 0; c < 4; ++c) {
        const int d = std::abs(int{a[4 * x + c]} - int{e[4 * x + c]});
        pixel_max = std::max(pixel_max, d);
        sum_squares += double(d) * d;
      }
      result.max_channel_diff = std::max(result.max_channel_diff, pixel_max);
      if (pixel_max > channel_tolerance) ++result.pixels_beyond;
    }
  }
  const double channels = 4.0 * actual.width * actual.height;
  result.rms = channels > 0 ? std::sqrt(sum_squares / channels) : 0.0;
  return result;
}

core::Image amplifiedDifference(const core::ImageView& actual, const core::ImageView& expected) {
  core::Image diff(actual.width, actual.height);
  for (int y = 0; y < actual.height; ++y) {
    for (int x = 0; x < actual.width; ++x) {
      const std::uint8_t* a = actual.pixel(x, y);
      const std::uint8_t* e = expected.pixel(x, y);
      std::uint8_t* d = diff.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        // Alpha differences show up in all colour channels, so nothing goes unseen.
        const int channel = std::max(std::abs(a[c] - e[c]), std::abs(a[3] - e[3]));
        d[c] = static_cast<std::uint8_t>(std::min(255, channel * kDiffAmplification));
      }
      d[3] = 255;
    }
  }
  return diff;
}

namespace {

struct PixelBox {
  int min_x = 0, min_y = 0, max_x = -1, max_y = -1;
  void add(int x, int y) {
    if (max_x < min_x) {
      min_x = max_x = x;
      min_y = max_y = y;
      return;
    }
    min_x = std::min(min_x, x), max_x = std::max(max_x, x);
    min_y = std::min(min_y, y), max_y = std::max(max_y, y);
  }
};

bool covers(const GoldenAllowance& a, int x, int y) {
  return x >= a.x && x < a.x + a.width && y >= a.y && y < a.y + a.height;
}

int pixelDifference(const std::uint8_t* a, const std::uint8_t* e) {
  int largest = 0;
  for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int{a[c]} - int{e[c]}));
  return largest;
}

}  // namespace

::testing::AssertionResult judgeImages(const core::ImageView& actual,
                                       const core::ImageView& expected,
                                       const GoldenOptions& options) {
  const ImageDifference diff = compareImages(actual, expected, options.channel_tolerance);
  if (!diff.same_size) {
    return ::testing::AssertionFailure()
           << "size " << actual.width << "x" << actual.height << " but expected " << expected.width
           << "x" << expected.height;
  }
  // Pixels past the gross tolerance, outside every allowance and inside each one.
  long gross_outside = 0;
  PixelBox gross_box;
  std::vector<long> gross_inside(options.allowances.size(), 0);
  for (int y = 0; y < actual.height; ++y) {
    for (int x = 0; x < actual.width; ++x) {
      if (pixelDifference(actual.pixel(x, y), expected.pixel(x, y)) <= options.gross_tolerance) {
        continue;
      }
      bool allowed = false;
      for (std::size_t i = 0; i < options.allowances.size() && !allowed; ++i) {
        if (covers(options.allowances[i], x, y)) ++gross_inside[i], allowed = true;
      }
      if (!allowed) ++gross_outside, gross_box.add(x, y);
    }
  }

  std::ostringstream problems;
  if (diff.pixels_beyond > options.max_pixels_beyond) {
    problems << diff.pixels_beyond << " px differ by more than " << options.channel_tolerance
             << "/255 (cap " << options.max_pixels_beyond << "); ";
  }
  if (gross_outside > 0) {
    problems << gross_outside << " px differ by more than " << options.gross_tolerance
             << "/255 (none allowed) within x " << gross_box.min_x << ".." << gross_box.max_x
             << ", y " << gross_box.min_y << ".." << gross_box.max_y << " (top left origin); ";
  }
  for (std::size_t i = 0; i < options.allowances.size(); ++i) {
    const GoldenAllowance& a = options.allowances[i];
    if (gross_inside[i] > a.max_pixels) {
      problems << gross_inside[i] << " px differ by more than " << options.gross_tolerance
               << "/255 inside the allowance for " << a.why << " (cap " << a.max_pixels << "); ";
    }
  }
  const std::string summary = problems.str();
  if (summary.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << summary << "RMS " << diff.rms << "/255, max " << diff.max_channel_diff << "/255";
}

::testing::AssertionResult compareWithGolden(const core::ImageView& actual,
                                             const std::string& golden_name,
                                             const GoldenOptions& options) {
  const fs::path golden_path = fs::path(goldenSourceDir()) / golden_name;
  if (updateRequested()) {
    writePng(golden_path.string(), actual);
    recordRenderer(options.renderer);
    std::printf("[golden] %s: rewritten (GOLDEN_UPDATE=1); look at it before committing\n",
                golden_name.c_str());
    return ::testing::AssertionSuccess();
  }
  if (!fs::exists(golden_path)) {
    const std::string candidate = writeFailureImages(golden_name, actual, nullptr);
    return ::testing::AssertionFailure()
           << "no golden image " << golden_path.string() << "; candidate written to " << candidate
           << " (GOLDEN_UPDATE=1 writes it into the source tree)";
  }

  const core::Image expected = readPng(golden_path.string());
  const core::ImageView expected_view = expected.view();
  if (actual.width != expected.width() || actual.height != expected.height()) {
    const std::string written = writeFailureImages(golden_name, actual, nullptr);
    return ::testing::AssertionFailure()
           << golden_name << ": size " << actual.width << "x" << actual.height << " but golden is "
           << expected.width() << "x" << expected.height() << "; actual written to " << written;
  }
  const ImageDifference diff = compareImages(actual, expected_view, options.channel_tolerance);
  const long total = static_cast<long>(actual.width) * actual.height;
  std::printf("[golden] %s: %ld of %ld px beyond %d/255 (cap %ld), RMS %.3f/255, max %d/255\n",
              golden_name.c_str(), diff.pixels_beyond, total, options.channel_tolerance,
              options.max_pixels_beyond, diff.rms, diff.max_channel_diff);
  const ::testing::AssertionResult verdict = judgeImages(actual, expected_view, options);
  if (verdict) return verdict;

  const std::string written = writeFailureImages(golden_name, actual, &expected_view);
  std::ostringstream message;
  message << golden_name << ": " << verdict.message() << "; actual, expected and diff written "
          << "beside " << written;
  const std::string recorded = recordedRenderer();
  if (!options.renderer.empty() && !recorded.empty() && recorded != options.renderer) {
    message << "; goldens were made with \"" << recorded << "\", this run used \""
            << options.renderer << "\"";
  }
  return ::testing::AssertionFailure() << message.str();
}

}  // namespace collide::test
