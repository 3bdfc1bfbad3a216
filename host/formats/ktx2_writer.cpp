// KTX 2.0 writer, from the Khronos KTX File Format Specification 2.0 and the Khronos Data Format
// Specification 1.3 (basic descriptor block). No libktx: it is not a Debian package.
//
// File layout (offsets for one mip level):
//   0   identifier            AB 4B 54 58 20 32 30 BB 0D 0A 1A 0A  ("«KTX 20»\r\n\x1A\n")
//   12  header                vkFormat, typeSize, pixelWidth, pixelHeight, pixelDepth, layerCount,
//                             faceCount, levelCount, supercompressionScheme   (9 x uint32)
//   48  index                 dfdByteOffset, dfdByteLength, kvdByteOffset, kvdByteLength (uint32),
//                             sgdByteOffset, sgdByteLength (uint64)
//   80  level index           byteOffset, byteLength, uncompressedByteLength (uint64) for level 0
//   104 DFD                   dfdTotalSize, then the basic descriptor block
//       key/value data        keyAndValueByteLength, key NUL value, padding to 4; sorted by key
//       padding               to lcm(texel size, 4)
//       level 0               texels, x fastest, then y, then z; little-endian
#include <numeric>

#include "common/errors.h"
#include "formats/writers.h"
#include "version.h"

namespace brdfbake {

uint32_t ktx2VkFormat(int channels, Precision p) {
  // VkFormat values (Vulkan 1.0 core): the UNORM / SFLOAT entries of each component width
  static const uint32_t kUnorm8[4] = {9, 16, 23, 37};        // R8_UNORM .. R8G8B8A8_UNORM
  static const uint32_t kUnorm16[4] = {70, 77, 84, 91};      // R16_UNORM .. R16G16B16A16_UNORM
  static const uint32_t kFloat16[4] = {76, 83, 90, 97};      // R16_SFLOAT .. R16G16B16A16_SFLOAT
  static const uint32_t kFloat32[4] = {100, 103, 106, 109};  // R32_SFLOAT .. R32G32B32A32_SFLOAT
  if (channels < 1 || channels > 4)
    throw Error(kExitSoftware, "internal: KTX2 with " + std::to_string(channels) + " channels");
  switch (p) {
    case Precision::Unorm8:
      return kUnorm8[channels - 1];
    case Precision::Unorm16:
      return kUnorm16[channels - 1];
    case Precision::Float16:
      return kFloat16[channels - 1];
    case Precision::Float32:
      return kFloat32[channels - 1];
  }
  return 0;
}

namespace {

// The Data Format Descriptor of an RGBA-ordered format: one sample per channel.
std::string dataFormatDescriptor(int channels, Precision p) {
  const uint32_t bytes = static_cast<uint32_t>(bytesPerChannel(p));
  const uint32_t blockSize = 24 + 16 * static_cast<uint32_t>(channels);
  std::string d;
  putU32(d, 4 + blockSize);          // dfdTotalSize
  putU32(d, 0);                      // vendorId 0 (Khronos, 17 bits) | descriptorType 0 (basic) << 17
  putU32(d, 2 | (blockSize << 16));  // versionNumber 2 (KDF 1.3) | descriptorBlockSize << 16
  putU8(d, 1);                       // colorModel KHR_DF_MODEL_RGBSDA
  putU8(d, 1);                       // colorPrimaries KHR_DF_PRIMARIES_BT709 (as vk2dfd for colour formats)
  putU8(d, 1);                       // transferFunction KHR_DF_TRANSFER_LINEAR (data, not sRGB)
  putU8(d, 0);                       // flags KHR_DF_FLAG_ALPHA_STRAIGHT
  putU32(d, 0);                      // texelBlockDimension0..3 = 0: a 1x1x1x1 block
  putU8(d, bytes * static_cast<uint32_t>(channels));    // bytesPlane0: the texel's bytes
  for (int k = 0; k < 7; ++k) putU8(d, 0);              // bytesPlane1..7
  static const uint32_t kChannelId[4] = {0, 1, 2, 15};  // R, G, B, A (KHR_DF_CHANNEL_RGBSDA_*)
  for (int c = 0; c < channels; ++c) {
    const bool isFloat = !isUnorm(p);
    const uint32_t qualifiers = isFloat ? 0x80u | 0x40u : 0u;  // KHR_DF_SAMPLE_DATATYPE_FLOAT | _SIGNED
    const uint32_t channelType = kChannelId[c] | qualifiers;
    putU32(d, (static_cast<uint32_t>(c) * bytes * 8) | ((bytes * 8 - 1) << 16) | (channelType << 24));
    putU32(d, 0);  // samplePosition0..3
    if (isFloat) {
      putU32(d, 0xBF800000u);  // sampleLower: -1.0f
      putU32(d, 0x3F800000u);  // sampleUpper: 1.0f
    } else {
      putU32(d, 0);
      putU32(d, p == Precision::Unorm16 ? 0xFFFFu : 0xFFu);
    }
  }
  return d;
}

std::string keyValueData(const TableImage& meta, bool volume) {
  std::vector<std::pair<std::string, std::string>> kv = attributesAsText(meta);
  kv.emplace_back("KTXorientation", volume ? "rdi" : "rd");  // x right, y down (row 0 first), z in
  kv.emplace_back("KTXwriter", std::string("brdfbake ") + BRDFBAKE_VERSION + " (git " + BRDFBAKE_GIT_REV + ")");
  std::sort(kv.begin(), kv.end());  // by key, byte order (the specification's codepoint order for UTF-8)
  std::string out;
  for (const auto& [k, v] : kv) {
    if (k.empty() || k.find('\0') != std::string::npos || v.find('\0') != std::string::npos)
      throw Error(kExitDataErr, "cannot write KTX2 key/value data: key '" + k + "' holds a NUL");
    const uint32_t len = static_cast<uint32_t>(k.size() + 1 + v.size() + 1);
    putU32(out, len);
    out += k;
    out.push_back('\0');
    out += v;
    out.push_back('\0');
    while (out.size() % 4) out.push_back('\0');  // valuePadding
  }
  return out;
}

}  // namespace

void writeKtx2Temporary(const std::string& tmp, const std::string& path, const TableImage& meta, const SliceSource& src,
                        int outChannels, Precision p) {
  const bool volume = src.depth > 1;
  const uint32_t vkFormat = ktx2VkFormat(outChannels, p);
  const uint64_t texelBytes = static_cast<uint64_t>(bytesPerChannel(p)) * outChannels;
  const uint64_t sliceTexels = static_cast<uint64_t>(src.width) * src.height;
  const uint64_t levelBytes = texelBytes * sliceTexels * static_cast<uint64_t>(src.depth);
  const std::string dfd = dataFormatDescriptor(outChannels, p);
  const std::string kvd = keyValueData(meta, volume);

  const uint64_t dfdOffset = 104, kvdOffset = dfdOffset + dfd.size();
  const uint64_t align = std::lcm<uint64_t>(texelBytes, 4);
  const uint64_t levelOffset = (kvdOffset + kvd.size() + align - 1) / align * align;

  std::string head = std::string("\xAB\x4B\x54\x58\x20\x32\x30\xBB\x0D\x0A\x1A\x0A", 12);
  putU32(head, vkFormat);
  putU32(head, static_cast<uint32_t>(bytesPerChannel(p)));  // typeSize: the component's bytes
  putU32(head, static_cast<uint32_t>(src.width));
  putU32(head, static_cast<uint32_t>(src.height));
  putU32(head, volume ? static_cast<uint32_t>(src.depth) : 0u);  // pixelDepth: 0 for 2D
  putU32(head, 0);                                               // layerCount: not an array
  putU32(head, 1);                                               // faceCount
  putU32(head, 1);                                               // levelCount: level 0 only
  putU32(head, 0);                                               // supercompressionScheme: none
  putU32(head, static_cast<uint32_t>(dfdOffset));
  putU32(head, static_cast<uint32_t>(dfd.size()));
  putU32(head, kvd.empty() ? 0u : static_cast<uint32_t>(kvdOffset));
  putU32(head, static_cast<uint32_t>(kvd.size()));
  putU64(head, 0);  // sgdByteOffset
  putU64(head, 0);  // sgdByteLength
  putU64(head, levelOffset);
  putU64(head, levelBytes);
  putU64(head, levelBytes);  // uncompressedByteLength: no supercompression
  head += dfd;
  head += kvd;
  head.resize(levelOffset, '\0');

  TempFileWriter out(tmp, path);
  out.write(head);
  writeSlices(out, src, path, outChannels, p);
  out.finish();
}

}  // namespace brdfbake
