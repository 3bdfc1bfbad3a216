// KTX 2.0 reading, from the KTX File Format Specification 2.0: the identifier, the header (nine
// uint32), the index (DFD and key/value offsets and lengths, supercompression global data), the level
// index (byteOffset, byteLength, uncompressedByteLength per level) and the key/value entries
// (uint32 length, key NUL value, padded to 4). What the baker does not write is refused with the
// field's name and the values it accepts: block-compressed or packed formats, arrays, cube maps,
// supercompression. Level 0 is the one read.
#include <map>

#include "formats/readers/reader_internal.h"

namespace brdfbake {
namespace readers {

namespace {

// VkFormat enumerant values (Vulkan registry) of the uncompressed UNORM / SFLOAT formats.
const std::map<uint32_t, TexelLayout>& vkFormats() {
  static const std::map<uint32_t, TexelLayout> kFormats = {
      {9, {1, Precision::Unorm8}},    {16, {2, Precision::Unorm8}},   {23, {3, Precision::Unorm8}},
      {37, {4, Precision::Unorm8}},   {70, {1, Precision::Unorm16}},  {77, {2, Precision::Unorm16}},
      {84, {3, Precision::Unorm16}},  {91, {4, Precision::Unorm16}},  {76, {1, Precision::Float16}},
      {83, {2, Precision::Float16}},  {90, {3, Precision::Float16}},  {97, {4, Precision::Float16}},
      {100, {1, Precision::Float32}}, {103, {2, Precision::Float32}}, {106, {3, Precision::Float32}},
      {109, {4, Precision::Float32}}};
  return kFormats;
}

}  // namespace

void readKtx2(const std::string& bytes, bool pixels, TableFile& t) {
  const Fields f{bytes, t.path, "KTX2"};
  auto refuse = [&](const std::string& what) { bad(t.path, "KTX2", what); };
  f.need(80, "the header and index");
  const uint32_t vk = f.u32(12, "vkFormat"), typeSize = f.u32(16, "typeSize");
  const uint32_t width = f.u32(20, "pixelWidth"), height = f.u32(24, "pixelHeight"), depth = f.u32(28, "pixelDepth");
  const uint32_t layers = f.u32(32, "layerCount"), faces = f.u32(36, "faceCount");  // levelCount: level 0 is read
  const uint32_t scheme = f.u32(44, "supercompressionScheme");
  TexelLayout layout{};
  if (!findLayout(vkFormats(), vk, &layout))
    refuse("vkFormat " + std::to_string(vk) +
           " is not one brdfbake reads: R/RG/RGB/RGBA 8- or 16-bit UNORM, 16- or "
           "32-bit SFLOAT (VkFormat 9, 16, 23, 37, 70, 77, 84, 91, 76, 83, 90, 97, 100, 103, 106, 109)");
  const uint32_t component = static_cast<uint32_t>(bytesPerChannel(layout.precision));
  if (typeSize != component)
    refuse("typeSize " + std::to_string(typeSize) + " is not the size of a component of vkFormat " +
           std::to_string(vk) + " (" + std::to_string(component) + ")");
  if (width < 1 || width > (1u << 16)) refuse("pixelWidth " + std::to_string(width) + " is outside [1, 65536]");
  if (height > (1u << 16)) refuse("pixelHeight " + std::to_string(height) + " is outside [0, 65536]");
  if (depth > (1u << 16)) refuse("pixelDepth " + std::to_string(depth) + " is outside [0, 65536]");
  if (depth > 0 && height == 0)
    refuse("pixelDepth " + std::to_string(depth) + " with pixelHeight 0 (a 3D texture needs both)");
  if (layers > 1) refuse("layerCount " + std::to_string(layers) + ": an array texture (brdfbake reads 0 or 1)");
  if (faces != 1) refuse("faceCount " + std::to_string(faces) + ": brdfbake reads 1 (not a cube map)");
  if (scheme != 0) refuse("supercompressionScheme " + std::to_string(scheme) + ": brdfbake reads 0 (none)");

  // key/value data: the brdf.* metadata
  const uint32_t kvdOffset = f.u32(56, "kvdByteOffset"), kvdLength = f.u32(60, "kvdByteLength");
  const uint64_t kvdEnd = static_cast<uint64_t>(kvdOffset) + kvdLength;
  f.need(kvdEnd, "the key/value data");
  for (uint64_t at = kvdOffset; at < kvdEnd;) {
    const uint32_t len = f.u32(at, "a key/value entry's length");
    if (at + 4 + len > kvdEnd) refuse("key/value entry at byte " + std::to_string(at) + " runs past kvdByteLength");
    const std::string entry = bytes.substr(at + 4, len);
    const size_t nul = entry.find('\0');
    if (nul == std::string::npos || nul == 0)
      refuse("key/value entry at byte " + std::to_string(at) + " has no NUL-terminated key");
    std::string value = entry.substr(nul + 1);
    if (!value.empty() && value.back() == '\0') value.pop_back();
    t.text.emplace_back(entry.substr(0, nul), value);
    at += 4 + (static_cast<uint64_t>(len) + 3) / 4 * 4;
  }

  // level 0: the texels, x fastest, then y, then z
  const uint64_t levelOffset = f.u64(80, "level 0 byteOffset"), levelLength = f.u64(88, "level 0 byteLength");
  const uint64_t texels = static_cast<uint64_t>(width) * (height ? height : 1) * (depth ? depth : 1);
  const uint64_t expected = texels * component * static_cast<uint64_t>(layout.components);
  if (levelLength != expected)
    refuse("level 0 byteLength " + std::to_string(levelLength) + " is not width * height * depth * texel size (" +
           std::to_string(expected) + ")");
  f.need(levelOffset > bytes.size() ? levelOffset : levelOffset + levelLength, "level 0");

  t.precision = layout.precision;
  t.storage = "VK_FORMAT_" + componentsName(layout.components, layout.precision, true);
  t.depth = depth ? static_cast<int>(depth) : 1;
  t.table.width = static_cast<int>(width);
  t.table.height = height ? static_cast<int>(height) : 1;
  setChannels(t, layout.components);
  if (pixels) decodeTexels(bytes, levelOffset, texels, layout.components, layout.precision, t);
}

}  // namespace readers
}  // namespace brdfbake
