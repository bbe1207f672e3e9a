#include "png_io.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
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

std::pair<unsigned, unsigned> readPngPixelsPerMetre(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw std::runtime_error("cannot open PNG " + path);
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(file);
    throw std::runtime_error("cannot read PNG " + path);
  }
  png_init_io(png, file);
  png_read_info(png, info);
  png_uint_32 x = 0, y = 0;
  int unit = PNG_RESOLUTION_UNKNOWN;
  const bool has = png_get_pHYs(png, info, &x, &y, &unit) != 0 && unit == PNG_RESOLUTION_METER;
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(file);
  return has ? std::pair<unsigned, unsigned>{x, y} : std::pair<unsigned, unsigned>{0, 0};
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
