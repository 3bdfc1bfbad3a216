// What the per-format readers (ktx2_read.cpp, dds_read.cpp, png_read.cpp, header_read.cpp) share;
// not part of the interface, which is table_reader.h.
#pragma once
#include <map>
#include <cstdint>
#include <string>

#include "formats/readers/table_reader.h"

namespace brdfbake {
namespace readers {

// The file's bytes (all of them, or the first `limit`). Error(kExitNoInput) when it is missing,
// unreadable or a directory.
std::string fileBytes(const std::string& path, size_t limit = SIZE_MAX);

// Error(kExitDataErr, "cannot read PATH: FORMAT WHAT").
[[noreturn]] void bad(const std::string& path, const std::string& format, const std::string& what);

// Little-endian fields of a binary file, each read checked against its end: a field past the end
// throws bad(path, format, "is truncated: <what> would end at byte N, the file has M bytes").
struct Fields {
  const std::string& bytes;
  const std::string& path;
  const char* format;
  void need(uint64_t end, const std::string& what) const;
  uint32_t u32(uint64_t at, const char* what) const;
  uint64_t u64(uint64_t at, const char* what) const;
};

// A texel format code's channel count and precision (DXGI_FORMAT, VkFormat).
struct TexelLayout {
  int components;
  Precision precision;
};
// The layout of `code` in `formats`; false when the code is not one of them.
inline bool findLayout(const std::map<uint32_t, TexelLayout>& formats, uint32_t code, TexelLayout* out) {
  auto it = formats.find(code);
  if (it == formats.end()) return false;
  *out = it->second;
  return true;
}

// One stored channel value as a number: float32 / float16 bit patterns, unorm codes over their maximum.
double decodeStored(uint32_t bits, Precision p);
// Reads `count` texels of `components` channels of precision p starting at byte `at` into the planes of
// `t.table` (planes[c][i]); the bytes must be there (Fields::need first).
void decodeTexels(const std::string& bytes, uint64_t at, uint64_t count, int components, Precision p, TableFile& t);
// channels R, G, B, A (the first n).
void setChannels(TableFile& t, int n);
// "R16G16B16A16" + "_SFLOAT" / "_FLOAT" / "_UNORM" for n channels of precision p.
std::string componentsName(int n, Precision p, bool vulkan);

void readKtx2(const std::string& bytes, bool pixels, TableFile& t);
void readDds(const std::string& bytes, bool pixels, TableFile& t);
void readPng(const std::string& bytes, bool pixels, TableFile& t);
// The header format: a C header (js == false) or an ECMAScript module.
void readHeader(const std::string& text, bool js, bool pixels, TableFile& t);

}  // namespace readers
}  // namespace brdfbake
