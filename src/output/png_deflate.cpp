#include "output/png_deflate.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace collide::output {
namespace {

constexpr std::size_t kWindowBytes = 32768;  // deflate's window: how far back a match reaches
// Rows go to zlib in batches of about this many bytes (with their filter bytes).
constexpr std::size_t kBatchBytes = 65536;

struct Part {
  int first_row = 0, end_row = 0;
  bool last = false;
  std::string out;
  uLong adler = 1;   // Adler-32 of this part's bytes alone (1: of none)
  uLong length = 0;  // of those bytes
  bool ok = false;
};

// Appends row `y` with its filter byte to `bytes`.
void appendRow(const core::ImageView& image, int y, std::vector<Bytef>& bytes) {
  const std::uint8_t* row = image.row(y);
  bytes.push_back(0);  // filter type 0: none
  bytes.insert(bytes.end(), row, row + static_cast<std::size_t>(image.width) * 4);
}

// Sends what `z` holds as input on with `flush`, growing `out` as needed.
bool drain(z_stream& z, std::string& out, int flush) {
  for (;;) {
    if (z.avail_out == 0) {
      const std::size_t used = out.size();
      out.resize(used + std::max<std::size_t>(used / 2, 16384));
      z.next_out = reinterpret_cast<Bytef*>(out.data() + used);
      z.avail_out = static_cast<uInt>(out.size() - used);
    }
    const int result = deflate(&z, flush);
    if (result == Z_STREAM_ERROR) return false;
    if (flush == Z_FINISH ? result == Z_STREAM_END : (z.avail_in == 0 && z.avail_out > 0)) {
      return true;
    }
  }
}

void deflatePart(const core::ImageView& image, int level, Part& part) {
  z_stream z{};
  // Raw deflate (negative window bits): the zlib header and checksum are written once, around
  // the joined parts.
  if (deflateInit2(&z, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return;
  std::vector<Bytef> batch;
  batch.reserve(kBatchBytes + static_cast<std::size_t>(image.width) * 4 + 1);
  bool ok = true;
  if (part.first_row > 0) {
    // The bytes of the rows just before, as the window of one whole stream would hold them.
    const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 4 + 1;
    const int rows_before =
        std::min(part.first_row, static_cast<int>((kWindowBytes + row_bytes - 1) / row_bytes));
    for (int y = part.first_row - rows_before; y < part.first_row; ++y) appendRow(image, y, batch);
    const std::size_t keep = std::min(batch.size(), kWindowBytes);
    ok = deflateSetDictionary(&z, batch.data() + batch.size() - keep, static_cast<uInt>(keep)) ==
         Z_OK;
    batch.clear();
  }
  part.out.resize(16384);
  z.next_out = reinterpret_cast<Bytef*>(part.out.data());
  z.avail_out = static_cast<uInt>(part.out.size());
  for (int y = part.first_row; ok && y < part.end_row; ++y) {
    appendRow(image, y, batch);
    const bool end = y + 1 == part.end_row;
    if (batch.size() < kBatchBytes && !end) continue;
    part.adler = adler32(part.adler, batch.data(), static_cast<uInt>(batch.size()));
    part.length += batch.size();
    z.next_in = batch.data();
    z.avail_in = static_cast<uInt>(batch.size());
    // The last part ends the stream; the others end on a byte boundary for the next to follow.
    ok = drain(z, part.out, end ? (part.last ? Z_FINISH : Z_SYNC_FLUSH) : Z_NO_FLUSH);
    batch.clear();
  }
  part.out.resize(z.total_out);
  part.ok = ok;
  deflateEnd(&z);
}

}  // namespace

std::string deflateImageRows(const core::ImageView& image, int level, int parts) {
  parts = std::clamp(parts, 1, std::max(1, image.height));
  std::vector<Part> pieces(static_cast<std::size_t>(parts));
  for (int i = 0; i < parts; ++i) {
    Part& part = pieces[static_cast<std::size_t>(i)];
    part.first_row = static_cast<int>(static_cast<long>(image.height) * i / parts);
    part.end_row = static_cast<int>(static_cast<long>(image.height) * (i + 1) / parts);
    part.last = i + 1 == parts;
  }
  std::vector<std::thread> threads;
  for (std::size_t i = 1; i < pieces.size(); ++i) {
    try {
      threads.emplace_back(deflatePart, std::cref(image), level, std::ref(pieces[i]));
    } catch (const std::exception&) {
      deflatePart(image, level, pieces[i]);  // no thread to be had: here, in turn
    }
  }
  deflatePart(image, level, pieces[0]);
  for (std::thread& thread : threads) thread.join();

  // zlib's header (RFC 1950): deflate with a 32 KiB window, the level class zlib itself writes,
  // and the check bits that make the two bytes a multiple of 31.
  const unsigned level_class = level < 2 ? 0 : level < 6 ? 1 : level == 6 ? 2 : 3;
  const unsigned header = (0x78u << 8) | (level_class << 6);
  std::string stream;
  std::size_t size = 6;
  for (const Part& part : pieces) size += part.out.size();
  stream.reserve(size);
  stream.push_back(static_cast<char>(header >> 8));
  stream.push_back(static_cast<char>((header | (31 - header % 31)) & 0xff));
  uLong adler = 1;
  for (const Part& part : pieces) {
    if (!part.ok) return {};
    stream += part.out;
    adler = adler32_combine(adler, part.adler, static_cast<z_off_t>(part.length));
  }
  for (int shift = 24; shift >= 0; shift -= 8) stream.push_back(static_cast<char>(adler >> shift));
  return stream;
}

}  // namespace collide::output
