// 16-bit PNG through libpng (PNG specification, ISO/IEC 15948): IHDR with bit depth 16, colour
// type RGB or RGBA, no interlace; samples big-endian (libpng's own order for 16-bit rows); one tEXt
// chunk per attribute; no tIME or other varying chunk, fixed zlib level: the same bytes each time.
#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>

#include "common/errors.h"
#include "formats/writers.h"

namespace brdfbake {

namespace {

struct PngSink {
  TempFileWriter* out;
  std::string error;  // the first Error's message, raised again after libpng returns
  ExitCode code = kExitIoErr;
};

extern "C" void pngWrite(png_structp png, png_bytep data, png_size_t n) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  try {
    sink->out->write(data, n);
  } catch (const Error& e) {
    sink->error = e.what();
    sink->code = e.code();
    png_error(png, "write failed");
  }
}
extern "C" void pngFlush(png_structp) {}
extern "C" void pngFail(png_structp png, png_const_charp msg) {
  auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
  if (sink->error.empty()) sink->error = std::string("libpng: ") + msg;
  png_longjmp(png, 1);
}
extern "C" void pngWarn(png_structp, png_const_charp) {}

// The libpng calls, apart: setjmp/longjmp here skip no C++ object's destructor.
bool encode(png_structp png, png_infop info, PngSink* sink, int width, int height, int channels, png_textp chunks,
            int numChunks, png_bytepp rows, int bitDepth = 16) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, sink, pngWrite, pngFlush);
  png_set_compression_level(png, 9);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bitDepth,
               channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_text(png, info, chunks, numChunks);
  if (bitDepth == 8) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);  // a picture, not data
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

// Encodes `rows` (bitDepth 16: big-endian samples; 8: an sRGB picture) with one tEXt chunk per
// (key, text) into the temporary for `path`.
void writeRows(const std::string& tmp, const std::string& path, int width, int height, int channels, int bitDepth,
               std::vector<std::vector<png_byte>>& rows, const std::vector<std::pair<std::string, std::string>>& text) {
  std::vector<png_text> chunks(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    chunks[i].compression = PNG_TEXT_COMPRESSION_NONE;
    chunks[i].key = const_cast<char*>(text[i].first.c_str());
    chunks[i].text = const_cast<char*>(text[i].second.c_str());
    chunks[i].text_length = text[i].second.size();
  }
  std::vector<png_bytep> rowPointers;
  for (auto& r : rows) rowPointers.push_back(r.data());
  TempFileWriter out(tmp, path);
  PngSink sink{&out, {}};
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, pngFail, pngWarn);
  if (!png) throw Error(kExitIoErr, "cannot write " + path + ": libpng could not start");
  png_infop info = png_create_info_struct(png);
  const bool ok = info && encode(png, info, &sink, width, height, channels, chunks.data(),
                                 static_cast<int>(chunks.size()), rowPointers.data(), bitDepth);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw Error(sink.code, "cannot write " + path + ": " + (sink.error.empty() ? "libpng failed" : sink.error));
  out.finish();
}

}  // namespace

void writePng16Temporary(const std::string& tmp, const std::string& path, const TableImage& img, double scale,
                         double offset) {
  const int channels = static_cast<int>(img.channels.size());
  if (channels != 3 && channels != 4)
    throw Error(kExitSoftware, "internal: PNG of " + std::to_string(channels) + " channels (RGB or RGBA only)");
  validateTableImage(path, img, TableFormatRules{});
  const size_t w = static_cast<size_t>(img.width);
  // rows first (every value checked), so libpng sees only what it can store
  std::vector<std::vector<png_byte>> rows(static_cast<size_t>(img.height), std::vector<png_byte>(w * channels * 2));
  for (int y = 0; y < img.height; ++y)
    for (size_t x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) {
        const double v = img.planes[c][y * w + x];
        const double q = std::nearbyint((v - offset) / scale * 65535.0);
        if (!(q >= 0 && q <= 65535)) throw Error(kExitSoftware, "internal: " + path + " value outside its PNG mapping");
        const unsigned code = static_cast<unsigned>(q);
        rows[y][(x * channels + c) * 2] = static_cast<png_byte>(code >> 8);
        rows[y][(x * channels + c) * 2 + 1] = static_cast<png_byte>(code & 0xFF);
      }
  std::vector<std::pair<std::string, std::string>> text = attributesAsText(img);
  for (const auto& [k, v] : text)
    if (k.size() > 79)
      throw Error(kExitDataErr,
                  "cannot write " + path + ": attribute name '" + k + "' is longer than PNG's 79-byte keyword");

  writeRows(tmp, path, img.width, img.height, channels, 16, rows, text);
}

// An 8-bit sRGB picture: each linear value clamped to [0, 1] and encoded with the sRGB transfer
// function (IEC 61966-2-1), rounded; an sRGB chunk; tEXt chunks from `text`.
void writePng8SrgbTemporary(const std::string& tmp, const std::string& path, int width, int height,
                            const std::vector<std::vector<float>>& rgb,
                            const std::vector<std::pair<std::string, std::string>>& text) {
  const size_t w = static_cast<size_t>(width);
  std::vector<std::vector<png_byte>> rows(static_cast<size_t>(height), std::vector<png_byte>(w * 3));
  for (int y = 0; y < height; ++y)
    for (size_t x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        double v = std::clamp(static_cast<double>(rgb[c][y * w + x]), 0.0, 1.0);
        if (!(v == v)) v = 0;
        const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
        rows[y][x * 3 + c] = static_cast<png_byte>(std::lround(s * 255));
      }
  writeRows(tmp, path, width, height, 3, 8, rows, text);
}

}  // namespace brdfbake
