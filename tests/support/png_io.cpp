#include "png_io.hpp"

#include <png.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace collide::test {

core::Image readPng(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    throw std::runtime_error("cannot read PNG " + path + ": " + png.message);
  }
  png.format = PNG_FORMAT_RGBA;
  core::Image image(static_cast<int>(png.width), static_cast<int>(png.height));
  if (!png_image_finish_read(&png, nullptr, image.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw std::runtime_error("cannot decode PNG " + path + ": " + message);
  }
  return image;
}

void writePng(const std::string& path, const core::ImageView& view) {
  const std::filesystem::path target(path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  // Top-down tight rows keep libpng's stride convention out of the picture.
  const core::Image image = core::Image::copyOf(view);
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width());
  png.height = static_cast<png_uint_32>(image.height());
  png.format = PNG_FORMAT_RGBA;
  const std::string temporary = path + ".partial";
  if (!png_image_write_to_file(&png, temporary.c_str(), 0, image.data(), 0, nullptr)) {
    std::filesystem::remove(temporary);
    throw std::runtime_error("cannot write PNG " + path + ": " + png.message);
  }
  std::filesystem::rename(temporary, target);
}

}  // namespace collide::test
