#include "output/png_writer.hpp"

#include <fcntl.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "output/frame_sink.hpp"
#include "output/output_file.hpp"
#include "output/png_deflate.hpp"
#include "output/temp_file.hpp"

namespace collide::output {
namespace {

// zlib level 2 without row filters. collide's pictures are flat shapes with anti-aliased edges:
// a filter turns each edge into a run of small differences that compress worse than the pixels
// themselves. Against the "sub" filter and against zlib's default level 6 this is faster and no
// larger than "sub", a little larger than level 6 (bench/results.md, "Figures behind the code").
// Animations write thousands of frames, so speed wins; recompress afterwards if size matters.
constexpr int kZlibLevel = 2;
constexpr int kPngFilters = PNG_FILTER_NONE;
// A part deflated on a thread of its own holds at least this much of the image: thread start and
// the priming of each part's window cost about what deflating 30 KiB does.
constexpr std::size_t kBytesPerDeflatePart = std::size_t{256} << 10;

// Shared between the libpng callbacks and the caller. Plain data only: libpng reports errors by
// longjmp, which must not skip destructors, so nothing with a destructor lives in encodeRows().
struct EncodeState {
  std::FILE* file = nullptr;
  int write_errno = 0;         // errno of the failed fwrite/fflush; 0 if libpng itself failed
  char png_message[256] = {};  // libpng's own error text
};

void writeData(png_structp png, png_bytep data, png_size_t length) {
  auto* state = static_cast<EncodeState*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, length, state->file) != length) {
    state->write_errno = errno != 0 ? errno : EIO;
    png_error(png, "write failed");
  }
}

void flushData(png_structp png) {
  auto* state = static_cast<EncodeState*>(png_get_io_ptr(png));
  if (std::fflush(state->file) != 0) {
    state->write_errno = errno != 0 ? errno : EIO;
    png_error(png, "flush failed");
  }
}

void onError(png_structp png, png_const_charp message) {
  auto* state = static_cast<EncodeState*>(png_get_error_ptr(png));
  std::snprintf(state->png_message, sizeof state->png_message, "%s", message);
  png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}  // warnings do not concern a writer of RGBA8

bool isAscii(const std::string& text) {
  for (const char c : text) {
    if (static_cast<unsigned char>(c) >= 0x80) return false;
  }
  return true;
}

// Returns true on success. `rows` holds one pointer per image row, top row first; `chunks` are
// ready png_text entries (their strings live in the caller). `deflated`, where not null, is the
// rows' zlib stream already made (png_deflate.hpp), written as the image data instead of `rows`.
bool encodeRows(EncodeState* state, int width, int height, png_bytepp rows, png_textp chunks,
                int chunk_count, png_uint_32 pixels_per_metre, const std::string* deflated) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, state, onError, onWarning);
  if (png == nullptr) {
    std::snprintf(state->png_message, sizeof state->png_message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, state, writeData, flushData);
  png_set_compression_level(png, kZlibLevel);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, kPngFilters);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
               PNG_FILTER_TYPE_BASE);
  if (chunk_count > 0) png_set_text(png, info, chunks, chunk_count);
  if (pixels_per_metre > 0) {
    png_set_pHYs(png, info, pixels_per_metre, pixels_per_metre, PNG_RESOLUTION_METER);
  }
  if (deflated != nullptr) {
    // The header and text chunks, then the data in one IDAT chunk, and the end.
    png_write_info(png, info);
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"),
                    reinterpret_cast<png_const_bytep>(deflated->data()), deflated->size());
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
  } else {
    png_set_rows(png, info, rows);
    png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  }
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void writePngDirect(const std::filesystem::path& file_path, const core::ImageView& image,
                    const std::filesystem::path& shown_path, const PngText& text,
                    double dots_per_inch, int deflate_threads) {
  const std::filesystem::path& path = shown_path.empty() ? file_path : shown_path;
  COLLIDE_ASSERT(image.top_row != nullptr && image.width > 0 && image.height > 0, "empty image");
  COLLIDE_ASSERT(dots_per_inch >= 0.0 && dots_per_inch < 1e6, "writePngDirect: bad resolution");
  const auto pixels_per_metre = static_cast<png_uint_32>(std::lround(dots_per_inch / 0.0254));
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) {
    // libpng only reads the rows; its API is not const-correct.
    rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(image.row(y));
  }

  // Built before encodeRows: libpng's longjmp must not skip these destructors.
  std::vector<std::string> keys, values;
  std::vector<png_text> chunks(text.size());
  keys.reserve(text.size());
  values.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    COLLIDE_ASSERT(!text[i].first.empty() && text[i].first.size() <= 79, "bad PNG keyword");
    keys.push_back(text[i].first);
    values.push_back(text[i].second);
    chunks[i].compression =
        isAscii(values[i]) ? PNG_TEXT_COMPRESSION_NONE : PNG_ITXT_COMPRESSION_NONE;
    chunks[i].key = keys[i].data();
    chunks[i].text = values[i].data();
    chunks[i].text_length = values[i].size();
  }

  // Deflated in parts before the file is opened (nothing of libpng's involved yet).
  const std::size_t image_bytes =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
  const int parts = static_cast<int>(std::min<std::size_t>(
      static_cast<std::size_t>(std::max(deflate_threads, 1)), image_bytes / kBytesPerDeflatePart));
  std::string deflated;
  if (parts > 1) deflated = deflateImageRows(image, kZlibLevel, parts);

  EncodeState state;
  // "-": standard output, through a duplicate of its descriptor so closing ours leaves it open.
  if (file_path == kStdoutName) {
    const int descriptor = ::dup(STDOUT_FILENO);
    state.file = descriptor >= 0 ? ::fdopen(descriptor, "wb") : nullptr;
    if (state.file == nullptr && descriptor >= 0) {
      // fdopen says EINVAL for a descriptor not open for writing: a closed stdout
      // (output/stop_signals.hpp)
      if (errno == EINVAL && (::fcntl(descriptor, F_GETFL) & O_ACCMODE) == O_RDONLY) errno = EBADF;
      ::close(descriptor);
    }
  } else {
    state.file = std::fopen(file_path.c_str(), "wb");
  }
  if (state.file == nullptr) {
    const int open_errno = errno;
    throw OutputError(ioErrorMessage("cannot create PNG", path, open_errno));
  }

  errno = 0;
  // An empty stream (zlib out of memory in a part): the rows the usual way, which reports it.
  const bool encoded = encodeRows(&state, image.width, image.height, rows.data(), chunks.data(),
                                  static_cast<int>(chunks.size()), pixels_per_metre,
                                  deflated.empty() ? nullptr : &deflated);
  // fclose flushes the last buffered bytes: a full disk may only show up here.
  const int close_result = std::fclose(state.file);
  const int close_errno = errno;
  if (!encoded) {
    if (state.write_errno != 0) {
      throw OutputError(ioErrorMessage("cannot write PNG", path, state.write_errno));
    }
    throw OutputError("cannot write PNG '" + path.string() + "': libpng: " + state.png_message);
  }
  if (close_result != 0) throw OutputError(ioErrorMessage("cannot write PNG", path, close_errno));
}

void writePng(const std::filesystem::path& path, const core::ImageView& image, const PngText& text,
              double dots_per_inch, int deflate_threads) {
  OutputFile file(path);
  writePngDirect(file.writePath(), image, path, text, dots_per_inch, deflate_threads);
  file.commit();
}

}  // namespace collide::output
