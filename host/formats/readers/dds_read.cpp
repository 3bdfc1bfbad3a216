// DDS reading, from Microsoft's DDS reference: the magic "DDS ", DDS_HEADER (dwSize 124, the
// dimensions at bytes 12, 16 and 24 of the file, the pixel format at 76 with dwSize 32 and the FourCC
// "DX10"), DDS_HEADER_DXT10 at 128 (dxgiFormat, resourceDimension, miscFlag, arraySize) and the texels
// from byte 148, x fastest, then y, then z. The top mip level is read. DDS has no metadata.
#include <map>

#include "formats/readers/reader_internal.h"

namespace brdfbake {
namespace readers {

namespace {

// DXGI_FORMAT values (dxgiformat.h) of the uncompressed UNORM / FLOAT formats.
const std::map<uint32_t, TexelLayout>& dxgiFormats() {
  static const std::map<uint32_t, TexelLayout> kFormats = {
      {2, {4, Precision::Float32}},  {6, {3, Precision::Float32}},  {16, {2, Precision::Float32}},
      {41, {1, Precision::Float32}}, {10, {4, Precision::Float16}}, {34, {2, Precision::Float16}},
      {54, {1, Precision::Float16}}, {11, {4, Precision::Unorm16}}, {35, {2, Precision::Unorm16}},
      {56, {1, Precision::Unorm16}}, {28, {4, Precision::Unorm8}},  {49, {2, Precision::Unorm8}},
      {61, {1, Precision::Unorm8}}};
  return kFormats;
}

}  // namespace

void readDds(const std::string& bytes, bool pixels, TableFile& t) {
  const Fields f{bytes, t.path, "DDS"};
  auto refuse = [&](const std::string& what) { bad(t.path, "DDS", what); };
  if (f.u32(4, "DDS_HEADER.dwSize") != 124) refuse("DDS_HEADER.dwSize is not 124");
  const uint32_t flags = f.u32(8, "dwFlags"), height = f.u32(12, "dwHeight"), width = f.u32(16, "dwWidth");
  const uint32_t depthField = f.u32(24, "dwDepth");
  if (f.u32(76, "DDS_PIXELFORMAT.dwSize") != 32) refuse("DDS_PIXELFORMAT.dwSize is not 32");
  const uint32_t pfFlags = f.u32(80, "DDS_PIXELFORMAT.dwFlags");
  f.need(88, "DDS_PIXELFORMAT.dwFourCC");
  if (!(pfFlags & 0x4) || bytes.compare(84, 4, "DX10") != 0)
    refuse(
        "has no DX10 header (DDS_PIXELFORMAT FourCC 'DX10'): brdfbake reads DX10 files, whose DXGI_FORMAT names "
        "the texels");
  const uint32_t dxgi = f.u32(128, "DDS_HEADER_DXT10.dxgiFormat"), dimension = f.u32(132, "resourceDimension");
  const uint32_t miscFlag = f.u32(136, "miscFlag"), arraySize = f.u32(140, "arraySize");
  f.need(148, "DDS_HEADER_DXT10");
  TexelLayout layout{};
  if (!findLayout(dxgiFormats(), dxgi, &layout))
    refuse("DXGI_FORMAT " + std::to_string(dxgi) +
           " is not one brdfbake reads: R/RG/RGBA 8- or 16-bit UNORM, 16- or "
           "32-bit FLOAT, RGB 32-bit FLOAT (2, 6, 10, 11, 16, 28, 34, 35, 41, 49, 54, 56, 61)");
  if (dimension < 2 || dimension > 4)
    refuse("resourceDimension " + std::to_string(dimension) + ": brdfbake reads 2, 3 or 4 (TEXTURE1D, 2D, 3D)");
  if (miscFlag & 0x4)
    refuse("miscFlag says a cube map (DDS_RESOURCE_MISC_TEXTURECUBE): brdfbake reads 2D and 3D textures");
  if (arraySize != 1) refuse("arraySize " + std::to_string(arraySize) + ": brdfbake reads 1 (not an array)");
  const bool volume = dimension == 4;
  const uint32_t depth = volume ? depthField : 1;
  const uint32_t h = dimension == 2 ? 1 : height;
  if (width < 1 || width > (1u << 16)) refuse("dwWidth " + std::to_string(width) + " is outside [1, 65536]");
  if (h < 1 || h > (1u << 16)) refuse("dwHeight " + std::to_string(h) + " is outside [1, 65536]");
  if (depth < 1 || depth > (1u << 16))
    refuse("dwDepth " + std::to_string(depth) + " of a TEXTURE3D is outside [1, 65536]");
  (void)flags;  // DDSD_* flags are advisory; the DX10 header's dimension decides

  const uint64_t texels = static_cast<uint64_t>(width) * h * depth;
  const uint64_t size = texels * layout.components * static_cast<uint64_t>(bytesPerChannel(layout.precision));
  f.need(148 + size, "the texels (" + std::to_string(width) + "x" + std::to_string(h) +
                         (volume ? "x" + std::to_string(depth) : std::string()) + ")");
  t.precision = layout.precision;
  t.storage = "DXGI_FORMAT_" + componentsName(layout.components, layout.precision, false) +
              (volume           ? ", TEXTURE3D"
               : dimension == 2 ? ", TEXTURE1D"
                                : ", TEXTURE2D");
  t.depth = static_cast<int>(depth);
  t.table.width = static_cast<int>(width);
  t.table.height = static_cast<int>(h);
  setChannels(t, layout.components);
  if (pixels) decodeTexels(bytes, 148, texels, layout.components, layout.precision, t);
}

}  // namespace readers
}  // namespace brdfbake
