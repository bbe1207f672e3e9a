#pragma once
// Test-only PNG reading and writing (libpng), RGBA8. The product's PNG sink lives in src/output;
// the golden library keeps its own so the two can be checked against each other.
#include <string>
#include <utility>

#include "core/image.hpp"

namespace collide::test {

// Reads any PNG as RGBA8, top row first. Throws std::runtime_error naming the file on failure.
core::Image readPng(const std::string& path);

// The resolution in the PNG's pHYs chunk, pixels per metre (x and y); {0, 0} when it has none or
// gives only an aspect ratio. Throws std::runtime_error naming the file if it cannot be read.
std::pair<unsigned, unsigned> readPngPixelsPerMetre(const std::string& path);

// Writes `image` (top-down or bottom-up view) as RGBA8 PNG, via a temporary name and a rename so
// no partial file is left at `path`. Creates missing parent directories. Throws std::runtime_error.
void writePng(const std::string& path, const core::ImageView& image);

}  // namespace collide::test
