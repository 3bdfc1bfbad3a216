// A KTX 2.0 reader for the tests, written from the specification apart from the writer
// (host/formats/ktx2_writer.cpp): it checks every field the KTX 2.0 specification and the Khronos
// Data Format Specification 1.3 constrain for an uncompressed, single-level texture, and decodes
// the texels. Each violated rule is recorded in `problems` (the tests expect none).
//
// Sources: KTX File Format Specification 2.0 (sections "File Structure", "Header", "Index",
// "Level Index", "Data Format Descriptor", "Key/Value Data", "Mip Level Array") and the Khronos
// Data Format Specification 1.3 ("Khronos Basic Data Format Descriptor Block").
#pragma once
#include <Imath/half.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace ktx2check {

struct Texture {
  uint32_t vkFormat = 0, typeSize = 0, width = 0, height = 0, depth = 0;
  int components = 0;
  bool isFloat = false;
  int bits = 0;
  std::map<std::string, std::string> kv;  // values without their trailing NUL
  std::vector<double> texels;             // decoded, [((z * h + y) * w + x) * components + c]
  std::vector<std::string> problems;
};

struct FormatInfo {
  int components, bits;
  bool isFloat;
};

// The Vulkan formats this project may write (VkFormat enumerant values from the Vulkan registry).
inline bool formatInfo(uint32_t vk, FormatInfo* out) {
  static const std::map<uint32_t, FormatInfo> kFormats = {
      {9, {1, 8, false}},   {16, {2, 8, false}},  {23, {3, 8, false}},  {37, {4, 8, false}},    // R8.._UNORM
      {70, {1, 16, false}}, {77, {2, 16, false}}, {84, {3, 16, false}}, {91, {4, 16, false}},   // R16.._UNORM
      {76, {1, 16, true}},  {83, {2, 16, true}},  {90, {3, 16, true}},  {97, {4, 16, true}},    // R16.._SFLOAT
      {100, {1, 32, true}}, {103, {2, 32, true}}, {106, {3, 32, true}}, {109, {4, 32, true}}};  // R32.._SFLOAT
  auto it = kFormats.find(vk);
  if (it == kFormats.end()) return false;
  *out = it->second;
  return true;
}

inline uint64_t le(const std::string& b, size_t at, int bytes) {
  uint64_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
  return v;
}

inline Texture read(const std::string& path) {
  Texture t;
  std::ifstream in(path, std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto bad = [&](const std::string& what) { t.problems.push_back(what); };
  if (b.size() < 104) {
    bad("file shorter than identifier + header + index + one level index entry");
    return t;
  }
  const unsigned char id[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  if (std::memcmp(b.data(), id, 12) != 0) bad("identifier is not «KTX 20»\\r\\n\\x1A\\n");
  auto u32 = [&](size_t at) { return static_cast<uint32_t>(le(b, at, 4)); };
  t.vkFormat = u32(12);
  t.typeSize = u32(16);
  t.width = u32(20);
  t.height = u32(24);
  t.depth = u32(28);
  const uint32_t layers = u32(32), faces = u32(36), levels = u32(40), scheme = u32(44);
  FormatInfo fi{};
  if (!formatInfo(t.vkFormat, &fi)) {
    bad("vkFormat " + std::to_string(t.vkFormat) + " is not an uncompressed R/RG/RGB/RGBA UNORM or SFLOAT format");
    return t;
  }
  t.components = fi.components;
  t.bits = fi.bits;
  t.isFloat = fi.isFloat;
  if (t.typeSize != static_cast<uint32_t>(fi.bits / 8)) bad("typeSize is not the component size");
  if (t.width == 0) bad("pixelWidth is 0");
  if (t.depth > 0 && t.height == 0) bad("a 3D texture with pixelHeight 0");
  if (layers != 0) bad("layerCount is not 0 (not an array)");
  if (faces != 1) bad("faceCount is not 1");
  if (levels != 1) bad("levelCount is not 1");
  if (scheme != 0) bad("supercompressionScheme is not 0 (none)");
  const uint32_t dfdOff = u32(48), dfdLen = u32(52), kvdOff = u32(56), kvdLen = u32(60);
  const uint64_t sgdOff = le(b, 64, 8), sgdLen = le(b, 72, 8);
  const uint64_t lvOff = le(b, 80, 8), lvLen = le(b, 88, 8), lvRaw = le(b, 96, 8);
  if (sgdOff != 0 || sgdLen != 0) bad("supercompression global data present without a scheme");
  if (dfdOff != 80 + 24 * levels) bad("dfdByteOffset does not follow the level index");
  if (dfdOff + static_cast<uint64_t>(dfdLen) > b.size() || dfdLen < 4 + 24) {
    bad("DFD outside the file");
    return t;
  }
  // Data Format Descriptor: dfdTotalSize, one basic block
  const int n = fi.components, bytes = fi.bits / 8;
  if (u32(dfdOff) != dfdLen) bad("dfdTotalSize differs from dfdByteLength");
  const size_t d = dfdOff + 4;
  const uint32_t w0 = u32(d), w1 = u32(d + 4);
  if ((w0 & 0x1FFFF) != 0) bad("DFD vendorId is not Khronos (0)");
  if ((w0 >> 17) != 0) bad("DFD descriptorType is not the basic block (0)");
  if ((w1 & 0xFFFF) != 2) bad("DFD versionNumber is not 2 (KDF 1.3)");
  if ((w1 >> 16) != static_cast<uint32_t>(24 + 16 * n)) bad("DFD descriptorBlockSize is not 24 + 16 samples");
  if (dfdLen != static_cast<uint32_t>(4 + 24 + 16 * n)) bad("dfdByteLength does not hold exactly one basic block");
  if (static_cast<unsigned char>(b[d + 8]) != 1) bad("DFD colorModel is not RGBSDA (1)");
  if (static_cast<unsigned char>(b[d + 9]) > 1) bad("DFD colorPrimaries is not BT709 or unspecified");
  if (static_cast<unsigned char>(b[d + 10]) != 1) bad("DFD transferFunction is not linear (1)");
  if (static_cast<unsigned char>(b[d + 11]) != 0) bad("DFD flags are not straight alpha (0)");
  if (u32(d + 12) != 0) bad("DFD texelBlockDimension is not 1x1x1x1 (all 0)");
  if (static_cast<unsigned char>(b[d + 16]) != n * bytes) bad("DFD bytesPlane0 is not the texel size");
  for (int k = 1; k < 8; ++k)
    if (b[d + 16 + k] != 0) bad("DFD bytesPlane" + std::to_string(k) + " is not 0");
  const unsigned kIds[4] = {0, 1, 2, 15};
  for (int s = 0; s < n; ++s) {
    const size_t o = d + 24 + 16 * s;
    const uint32_t word = u32(o);
    const std::string name = "DFD sample " + std::to_string(s);
    if ((word & 0xFFFF) != static_cast<uint32_t>(s * fi.bits)) bad(name + " bitOffset");
    if (((word >> 16) & 0xFF) != static_cast<uint32_t>(fi.bits - 1)) bad(name + " bitLength");
    const unsigned type = word >> 24;
    if ((type & 0xF) != kIds[s]) bad(name + " channel id is not " + "RGBA"[s]);
    const unsigned q = type & 0xF0;  // linear 0x10, exponent 0x20, signed 0x40, float 0x80
    if (q != (fi.isFloat ? 0xC0u : 0u))
      bad(name + " qualifiers do not say " + (fi.isFloat ? "float, signed" : "unsigned integer"));
    if (u32(o + 4) != 0) bad(name + " samplePosition is not 0");
    const uint32_t lower = u32(o + 8), upper = u32(o + 12);
    if (fi.isFloat ? (lower != 0xBF800000u || upper != 0x3F800000u)
                   : (lower != 0 || upper != (fi.bits == 16 ? 0xFFFFu : 0xFFu)))
      bad(name + " sampleLower/sampleUpper are not the format's range");
  }
  // key/value data: entries aligned to 4, sorted by key, keys NUL-terminated
  if (kvdLen > 0) {
    if (kvdOff != dfdOff + dfdLen) bad("kvdByteOffset does not follow the DFD");
    if (kvdOff % 4 != 0) bad("kvdByteOffset is not 4-aligned");
    size_t at = kvdOff;
    std::string last;
    while (at < kvdOff + static_cast<size_t>(kvdLen)) {
      const uint32_t len = u32(at);
      const std::string entry = b.substr(at + 4, len);
      const size_t nul = entry.find('\0');
      if (nul == std::string::npos || nul == 0) {
        bad("key/value entry without a NUL-terminated key");
        break;
      }
      const std::string key = entry.substr(0, nul);
      std::string value = entry.substr(nul + 1);
      if (!value.empty() && value.back() == '\0') value.pop_back();
      if (!last.empty() && !(last < key)) bad("key '" + key + "' out of order or repeated");
      last = key;
      t.kv[key] = value;
      const size_t padded = (len + 3) / 4 * 4;
      for (size_t k = len; k < padded; ++k)
        if (b[at + 4 + k] != 0) bad("valuePadding of '" + key + "' is not zero");
      at += 4 + padded;
    }
    if (at != kvdOff + static_cast<size_t>(kvdLen)) bad("kvdByteLength does not end on an entry");
  }
  const char* orient = t.depth > 0 ? "rdi" : "rd";
  if (t.kv.count("KTXorientation") && t.kv["KTXorientation"].size() != std::strlen(orient))
    bad("KTXorientation does not name each dimension");
  // level 0
  const uint64_t texelBytes = static_cast<uint64_t>(n) * bytes;
  const uint64_t count =
      static_cast<uint64_t>(t.width) * std::max<uint32_t>(1, t.height) * std::max<uint32_t>(1, t.depth);
  if (lvOff % std::lcm<uint64_t>(texelBytes, 4) != 0) bad("level 0 byteOffset is not aligned to lcm(texel size, 4)");
  if (lvOff < kvdOff + static_cast<uint64_t>(kvdLen) || lvOff < dfdOff + static_cast<uint64_t>(dfdLen))
    bad("level 0 overlaps the descriptors");
  if (lvLen != count * texelBytes) bad("level 0 byteLength is not width * height * depth * texel size");
  if (lvRaw != lvLen) bad("uncompressedByteLength differs from byteLength without supercompression");
  if (lvOff + lvLen != b.size()) bad("the file does not end with level 0");
  if (lvOff + lvLen > b.size()) return t;
  t.texels.resize(count * n);
  for (uint64_t i = 0; i < count * n; ++i) {
    const uint64_t raw = le(b, lvOff + i * bytes, bytes);
    if (!fi.isFloat)
      t.texels[i] = raw / (fi.bits == 16 ? 65535.0 : 255.0);
    else if (fi.bits == 16)
      t.texels[i] = static_cast<float>(Imath::half(Imath::half::FromBits, static_cast<uint16_t>(raw)));
    else {
      const uint32_t r32 = static_cast<uint32_t>(raw);
      float f;
      std::memcpy(&f, &r32, 4);
      t.texels[i] = f;
    }
  }
  return t;
}

}  // namespace ktx2check
