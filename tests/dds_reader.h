// A DDS (DX10 header) reader for the tests, written from Microsoft's DDS reference (DDS_HEADER,
// DDS_PIXELFORMAT, DDS_HEADER_DXT10) apart from the writer. OpenImageIO 2.4 (Debian 12) refuses
// every DX10 file with uncompressed texels ("Unsupported compression type") and Pillow 9.4 reads
// only R8G8B8A8_UNORM of them, so the float and 16-bit forms, and 3D textures, are checked here.
#pragma once
#include <Imath/half.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace ddscheck {

struct Texture {
  uint32_t dxgi = 0, width = 0, height = 0, depth = 0, dimension = 0;
  int components = 0, bits = 0;
  bool isFloat = false;
  std::vector<double> texels;  // [((z * h + y) * w + x) * components + c]
  std::vector<std::string> problems;
};

inline uint32_t u32(const std::string& b, size_t at) {
  uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
  return v;
}

inline Texture read(const std::string& path) {
  struct Info {
    int components, bits;
    bool isFloat;
  };
  // DXGI_FORMAT values (dxgiformat.h) of the uncompressed formats the baker may write
  static const std::map<uint32_t, Info> kFormats = {
      {2, {4, 32, true}},  {6, {3, 32, true}},  {16, {2, 32, true}},  {41, {1, 32, true}},  {10, {4, 16, true}},
      {34, {2, 16, true}}, {54, {1, 16, true}}, {11, {4, 16, false}}, {35, {2, 16, false}}, {56, {1, 16, false}},
      {28, {4, 8, false}}, {49, {2, 8, false}}, {61, {1, 8, false}}};
  Texture t;
  std::ifstream in(path, std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto bad = [&](const std::string& what) { t.problems.push_back(what); };
  if (b.size() < 148) {
    bad("shorter than magic + DDS_HEADER + DDS_HEADER_DXT10");
    return t;
  }
  if (b.compare(0, 4, "DDS ") != 0) bad("magic is not 'DDS '");
  const uint32_t size = u32(b, 4), flags = u32(b, 8);
  t.height = u32(b, 12);
  t.width = u32(b, 16);
  const uint32_t pitch = u32(b, 20);
  t.depth = u32(b, 24);
  const uint32_t mips = u32(b, 28);
  if (size != 124) bad("dwSize is not 124");
  const uint32_t required = 0x1 | 0x2 | 0x4 | 0x1000;  // DDSD_CAPS | HEIGHT | WIDTH | PIXELFORMAT
  if ((flags & required) != required) bad("dwFlags lacks DDSD_CAPS, DDSD_HEIGHT, DDSD_WIDTH or DDSD_PIXELFORMAT");
  if (mips > 1) bad("more than one mip level");
  if (u32(b, 76) != 32) bad("ddspf.dwSize is not 32");
  if ((u32(b, 80) & 0x4) == 0) bad("ddspf.dwFlags lacks DDPF_FOURCC");
  if (b.compare(84, 4, "DX10") != 0) bad("ddspf.dwFourCC is not 'DX10'");
  const uint32_t caps = u32(b, 108), caps2 = u32(b, 112);
  if ((caps & 0x1000) == 0) bad("dwCaps lacks DDSCAPS_TEXTURE");
  t.dxgi = u32(b, 128);
  t.dimension = u32(b, 132);
  const uint32_t arraySize = u32(b, 140);
  auto it = kFormats.find(t.dxgi);
  if (it == kFormats.end()) {
    bad("dxgiFormat " + std::to_string(t.dxgi) + " is not an uncompressed float/unorm format");
    return t;
  }
  t.components = it->second.components;
  t.bits = it->second.bits;
  t.isFloat = it->second.isFloat;
  const bool volume = t.dimension == 4;
  if (t.dimension != 3 && t.dimension != 4) bad("resourceDimension is neither TEXTURE2D (3) nor TEXTURE3D (4)");
  if (volume != ((flags & 0x800000) != 0)) bad("DDSD_DEPTH does not match the resource dimension");
  if (volume != ((caps2 & 0x200000) != 0)) bad("DDSCAPS2_VOLUME does not match the resource dimension");
  if (volume && (caps & 0x8) == 0) bad("a volume texture without DDSCAPS_COMPLEX");
  if (arraySize != 1) bad("arraySize is not 1");
  const uint64_t texelBytes = static_cast<uint64_t>(t.components) * t.bits / 8;
  if ((flags & 0x8) && pitch != t.width * texelBytes) bad("dwPitchOrLinearSize is not the row's bytes");
  const uint64_t count = static_cast<uint64_t>(t.width) * t.height * (volume ? t.depth : 1);
  if (b.size() != 148 + count * texelBytes) bad("the data is not exactly width * height * depth texels");
  if (b.size() < 148 + count * texelBytes) return t;
  const int bytes = t.bits / 8;
  t.texels.resize(count * t.components);
  for (uint64_t i = 0; i < t.texels.size(); ++i) {
    const size_t at = 148 + i * bytes;
    uint32_t raw = 0;
    for (int k = bytes - 1; k >= 0; --k) raw = (raw << 8) | static_cast<unsigned char>(b[at + k]);
    if (!t.isFloat)
      t.texels[i] = raw / (t.bits == 16 ? 65535.0 : 255.0);
    else if (t.bits == 16)
      t.texels[i] = static_cast<float>(Imath::half(Imath::half::FromBits, static_cast<uint16_t>(raw)));
    else {
      float f;
      std::memcpy(&f, &raw, 4);
      t.texels[i] = f;
    }
  }
  return t;
}

}  // namespace ddscheck
