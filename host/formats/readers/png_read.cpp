// 16-bit PNG reading through libpng (PNG specification, ISO/IEC 15948): IHDR bit depth 16, colour type
// RGB or RGBA, the samples (big-endian), and the tEXt / zTXt / iTXt chunks before and after the image
// data, where the baker keeps its metadata and the value mapping brdf.mapping.scale / .offset
// (value = png / 65535 * scale + offset; the identity without them). libpng checks the chunks' CRCs
// and the zlib stream; a truncated file fails at the image data or the end chunk.
#include <png.h>

#include <csetjmp>
#include <cstdlib>
#include <cstring>

#include "formats/readers/reader_internal.h"

namespace brdfbake {
namespace readers {

namespace {

struct PngSource {
  const std::string* bytes;
  size_t at = 0;
  char message[200] = {0};  // libpng's first error
};

extern "C" void pngReadBytes(png_structp png, png_bytep out, png_size_t n) {
  auto* src = static_cast<PngSource*>(png_get_io_ptr(png));
  if (n > src->bytes->size() - src->at) png_error(png, "unexpected end of file (truncated)");
  std::memcpy(out, src->bytes->data() + src->at, n);
  src->at += n;
}
extern "C" void pngReadFail(png_structp png, png_const_charp msg) {
  auto* src = static_cast<PngSource*>(png_get_error_ptr(png));
  if (!src->message[0]) std::snprintf(src->message, sizeof src->message, "%s", msg);
  png_longjmp(png, 1);
}
extern "C" void pngReadWarn(png_structp, png_const_charp) {}

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int depth = 0, colour = 0, interlace = 0;
};

// The libpng calls, apart: setjmp/longjmp here skip no C++ object's destructor. `rows` (width *
// channels * 2 bytes each) is filled when not null; `text` gets the text chunks (key, value) through
// the callback. Returns false with src->message set on a libpng error.
bool decode(png_structp png, png_infop info, png_infop endInfo, PngSource* src, PngHeader* h,
            std::vector<unsigned char>* pixels, void (*addText)(void*, const char*, const char*, size_t),
            void* textSink) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, src, pngReadBytes);
  png_read_info(png, info);
  png_get_IHDR(png, info, &h->width, &h->height, &h->depth, &h->colour, &h->interlace, nullptr, nullptr);
  const bool ok = h->depth == 16 && (h->colour == PNG_COLOR_TYPE_RGB || h->colour == PNG_COLOR_TYPE_RGB_ALPHA) &&
                  h->interlace == PNG_INTERLACE_NONE && h->width >= 1 && h->width <= 65536 && h->height >= 1 &&
                  h->height <= 65536;
  if (!ok) return true;  // the caller names what is wrong
  const size_t stride = static_cast<size_t>(h->width) * (h->colour == PNG_COLOR_TYPE_RGB ? 3 : 4) * 2;
  // the rows the header declares must fit deflate's 1032:1 of the file's bytes (with room), before
  // a byte is allocated for them (a 237-byte file claiming 16384^2 had 2.1 GB allocated)
  if ((stride + 1) * h->height > src->bytes->size() * 1100 + 65536) {
    std::snprintf(src->message, sizeof src->message,
                  "IHDR declares %u x %u, %zu bytes of rows, more than the file's %zu bytes can hold (damaged header?)",
                  static_cast<unsigned>(h->width), static_cast<unsigned>(h->height), (stride + 1) * h->height,
                  src->bytes->size());
    return false;
  }
  pixels->resize(stride * h->height);
  for (png_uint_32 y = 0; y < h->height; ++y) png_read_row(png, pixels->data() + stride * y, nullptr);
  png_read_end(png, endInfo);
  for (png_infop i : {info, endInfo}) {
    png_textp chunks = nullptr;
    const int n = png_get_text(png, i, &chunks, nullptr);
    for (int k = 0; k < n; ++k)
      addText(textSink, chunks[k].key, chunks[k].text, chunks[k].text ? std::strlen(chunks[k].text) : 0);
  }
  return true;
}

void addText(void* sink, const char* key, const char* value, size_t n) {
  static_cast<TableFile*>(sink)->text.emplace_back(key, std::string(value ? value : "", n));
}

bool numberText(const TableFile& t, const std::string& key, double* v) {
  for (const auto& [k, text] : t.text) {
    if (k != key) continue;
    char* end = nullptr;
    *v = std::strtod(text.c_str(), &end);
    return end != text.c_str() && *end == '\0';
  }
  return false;
}

}  // namespace

void readPng(const std::string& bytes, bool pixels, TableFile& t) {
  PngSource src{&bytes};
  PngHeader h;
  std::vector<unsigned char> samples;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &src, pngReadFail, pngReadWarn);
  if (!png) bad(t.path, "PNG", "could not be read: libpng could not start");
  png_infop info = png_create_info_struct(png), endInfo = png_create_info_struct(png);
  png_set_user_limits(png, 65536, 65536);
  // a chunk whose CRC fails is an error, ancillary ones included: libpng's default drops a damaged
  // text chunk with a warning, and a dropped brdf.mapping.scale read as 1 (tests/readers_test.cpp)
  png_set_crc_action(png, PNG_CRC_ERROR_QUIT, PNG_CRC_ERROR_QUIT);
  const bool ok = info && endInfo && decode(png, info, endInfo, &src, &h, &samples, addText, &t);
  png_destroy_read_struct(&png, &info, &endInfo);
  if (!ok)
    bad(t.path, "PNG", std::string("is damaged or truncated: ") + (src.message[0] ? src.message : "libpng failed"));
  if (h.depth != 16 || (h.colour != PNG_COLOR_TYPE_RGB && h.colour != PNG_COLOR_TYPE_RGB_ALPHA))
    bad(t.path, "PNG",
        "has bit depth " + std::to_string(h.depth) + " and colour type " + std::to_string(h.colour) +
            ": brdfbake reads 16-bit RGB (colour type 2) or RGBA (6), as it writes them");
  if (h.interlace != PNG_INTERLACE_NONE) bad(t.path, "PNG", "is interlaced: brdfbake reads non-interlaced files");

  const int n = h.colour == PNG_COLOR_TYPE_RGB ? 3 : 4;
  double scale = 1, offset = 0;
  const bool hasScale = numberText(t, "brdf.mapping.scale", &scale),
             hasOffset = numberText(t, "brdf.mapping.offset", &offset);
  if (!hasScale) scale = 1;
  if (!hasOffset) offset = 0;
  t.precision = Precision::Unorm16;
  t.storage = std::string("16-bit ") + (n == 3 ? "RGB" : "RGBA");
  t.table.width = static_cast<int>(h.width);
  t.table.height = static_cast<int>(h.height);
  setChannels(t, n);
  if (!pixels) return;
  const size_t count = static_cast<size_t>(h.width) * h.height;
  t.table.planes.assign(static_cast<size_t>(n), std::vector<float>(count));
  for (size_t i = 0; i < count; ++i)
    for (int c = 0; c < n; ++c) {
      const unsigned code = static_cast<unsigned>(samples[(i * n + c) * 2]) << 8 | samples[(i * n + c) * 2 + 1];
      t.table.planes[c][i] = static_cast<float>(code / 65535.0 * scale + offset);
    }
}

}  // namespace readers
}  // namespace brdfbake
