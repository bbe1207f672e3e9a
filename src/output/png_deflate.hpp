#pragma once
// The compressed image data (the zlib stream that a PNG's IDAT chunks carry) of an RGBA8 image,
// made in parallel: one large still's deflate is about a tenth of its CPU and runs after
// everything else, with the other cores idle. The rows are cut into parts, one per thread; each
// part is deflated on its own, primed with the 32 KiB of rows before it (as if it had seen them:
// matches reach back into the part before, so the file hardly grows), and ends on a byte boundary
// (a sync flush), so the parts join into one valid stream. The checksum is each part's Adler-32,
// combined. The same level and filter as png_writer.cpp's single stream: no row filter (type 0).
#include <cstdint>
#include <string>

#include "core/image.hpp"

namespace collide::output {

// The zlib stream of `image`'s rows, each preceded by its filter byte 0, at zlib `level`, in
// `parts` pieces deflated on as many threads (the calling one among them; 1: no thread). Returns
// an empty string if zlib fails (out of memory).
std::string deflateImageRows(const core::ImageView& image, int level, int parts);

}  // namespace collide::output
