#pragma once
// PNG encoding of one RGBA8 image with libpng, tuned for speed (animations write many frames).
// Rows are handed to libpng by pointer, so a bottom-up view is written upright without a copy.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/image.hpp"

namespace collide::output {

// Text chunks that say what the image is, e.g. {"Title", ...}, {"Software", "collide 0.1.0"},
// {"Description", ...}, {"Comment", ...} (the PNG specification's keywords). ASCII text goes into
// tEXt chunks, anything else into uncompressed UTF-8 iTXt chunks. Keywords are 1-79 Latin-1
// characters.
using PngText = std::vector<std::pair<std::string, std::string>>;

// Writes `image` as an 8-bit RGBA PNG at `path` through an OutputFile: a regular file safely (the
// bytes go to a temporary file in the same directory, renamed to `path` only when complete; on any
// failure an existing file there is kept), a device or FIFO in place, "-" to stdout. OutputError
// names the path and the reason. `dots_per_inch` > 0 records the printing resolution in a pHYs
// chunk (pixels per metre, as the PNG specification has it), so word processors and LaTeX place
// the image at its physical size; 0 writes none.
// `deflate_threads` > 1 compresses a large image in as many parts at once (png_deflate.hpp): the
// same pixels, a file a few bytes larger; 1 (videos' frames, batch, which keep to their cores)
// compresses on the calling thread alone.
void writePng(const std::filesystem::path& path, const core::ImageView& image,
              const PngText& text = {}, double dots_per_inch = 0.0, int deflate_threads = 1);

// Writes the PNG straight to `path` ("-": standard output) with no temporary file and no clean-up
// on failure; the building block of the safe writers. Throws OutputError naming `shown_path` (the
// path the user asked for, when `path` is a temporary name; empty means `path`) and the reason.
void writePngDirect(const std::filesystem::path& path, const core::ImageView& image,
                    const std::filesystem::path& shown_path = {}, const PngText& text = {},
                    double dots_per_inch = 0.0, int deflate_threads = 1);

}  // namespace collide::output
