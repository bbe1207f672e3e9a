#pragma once
// Helpers for the output tests: synthetic frames, a scratch directory, a PNG reader.
#include <filesystem>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "scratch.hpp"

namespace collide::output::test {

// A smooth diagonal gradient with a white square that moves one step per `frame_index`; every
// frame differs, and the content compresses like a rendered scene (flat areas, soft shading).
core::Image makeFrame(int width, int height, int frame_index);

// Copies `image` upside down into `storage` and returns a bottom-up view of it (negative stride,
// top_row pointing at the last row in memory) that shows the same picture as `image.view()`.
core::ImageView bottomUpView(const core::Image& image, std::vector<std::uint8_t>& storage);

// A fresh, empty directory for one test (collide::test::ScratchDir), named after the test.
class ScratchDirectory : public collide::test::ScratchDir {
 public:
  ScratchDirectory();
};

// Reads a PNG as RGBA8 (collide::test::readPng); fails the calling test (returns an empty image)
// if it can't.
core::Image readPng(const std::filesystem::path& path);

// Largest per-channel difference between two same-sized images, 0..255.
int maxChannelDifference(const core::Image& a, const core::Image& b);

}  // namespace collide::output::test
