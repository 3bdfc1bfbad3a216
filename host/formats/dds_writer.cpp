// DDS writer with the DX10 extended header, from Microsoft's "Programming Guide for DDS" and the
// DDS_HEADER / DDS_PIXELFORMAT / DDS_HEADER_DXT10 reference pages (Direct3D 10 and later).
//
//   0    "DDS "                 magic 0x20534444
//   4    DDS_HEADER             124 bytes: dwSize 124, dwFlags, dwHeight, dwWidth, dwPitchOrLinearSize,
//                               dwDepth, dwMipMapCount, dwReserved1[11], ddspf (32 bytes: dwSize 32,
//                               DDPF_FOURCC, 'DX10', masks 0), dwCaps, dwCaps2, dwCaps3, dwCaps4, dwReserved2
//   128  DDS_HEADER_DXT10       dxgiFormat, resourceDimension, miscFlag, arraySize, miscFlags2
//   148  texels                 x fastest, then y (rows of dwPitchOrLinearSize bytes), then z
#include "common/errors.h"
#include "formats/writers.h"

namespace brdfbake {

uint32_t ddsDxgiFormat(int channels, Precision p) {
  // DXGI_FORMAT values (dxgiformat.h); 0 (UNKNOWN) where DXGI has no such format
  static const uint32_t kFloat32[4] = {41, 16, 6, 2};   // R32_FLOAT, R32G32_FLOAT, R32G32B32_FLOAT, R32G32B32A32_FLOAT
  static const uint32_t kFloat16[4] = {54, 34, 0, 10};  // R16_FLOAT, R16G16_FLOAT, -, R16G16B16A16_FLOAT
  static const uint32_t kUnorm16[4] = {56, 35, 0, 11};  // R16_UNORM, R16G16_UNORM, -, R16G16B16A16_UNORM
  static const uint32_t kUnorm8[4] = {61, 49, 0, 28};   // R8_UNORM, R8G8_UNORM, -, R8G8B8A8_UNORM
  if (channels < 1 || channels > 4) return 0;
  switch (p) {
    case Precision::Float32:
      return kFloat32[channels - 1];
    case Precision::Float16:
      return kFloat16[channels - 1];
    case Precision::Unorm16:
      return kUnorm16[channels - 1];
    case Precision::Unorm8:
      return kUnorm8[channels - 1];
  }
  return 0;
}

void writeDdsTemporary(const std::string& tmp, const std::string& path, const SliceSource& src, int outChannels,
                       Precision p) {
  const uint32_t dxgi = ddsDxgiFormat(outChannels, p);
  if (dxgi == 0)
    throw Error(kExitUsage, "cannot write " + path + ": DXGI has no " + std::to_string(outChannels) + "-channel " +
                                precisionName(p) + " format");
  const bool volume = src.depth > 1;
  const uint32_t texelBytes = static_cast<uint32_t>(bytesPerChannel(p) * outChannels);
  constexpr uint32_t DDSD_CAPS = 0x1, DDSD_HEIGHT = 0x2, DDSD_WIDTH = 0x4, DDSD_PITCH = 0x8, DDSD_PIXELFORMAT = 0x1000,
                     DDSD_MIPMAPCOUNT = 0x20000, DDSD_DEPTH = 0x800000;
  constexpr uint32_t DDPF_FOURCC = 0x4, DDSCAPS_COMPLEX = 0x8, DDSCAPS_TEXTURE = 0x1000, DDSCAPS2_VOLUME = 0x200000;
  constexpr uint32_t kDimTexture2D = 3, kDimTexture3D = 4;  // D3D10_RESOURCE_DIMENSION

  std::string h = "DDS ";
  putU32(h, 124);  // dwSize
  putU32(h, DDSD_CAPS | DDSD_HEIGHT | DDSD_WIDTH | DDSD_PITCH | DDSD_PIXELFORMAT | DDSD_MIPMAPCOUNT |
                (volume ? DDSD_DEPTH : 0u));
  putU32(h, static_cast<uint32_t>(src.height));
  putU32(h, static_cast<uint32_t>(src.width));
  putU32(h, static_cast<uint32_t>(src.width) * texelBytes);   // dwPitchOrLinearSize: bytes per row
  putU32(h, volume ? static_cast<uint32_t>(src.depth) : 0u);  // dwDepth
  putU32(h, 1);                                               // dwMipMapCount
  for (int k = 0; k < 11; ++k) putU32(h, 0);                  // dwReserved1
  putU32(h, 32);                                              // ddspf.dwSize
  putU32(h, DDPF_FOURCC);                                     // ddspf.dwFlags
  h += "DX10";                                                // ddspf.dwFourCC
  for (int k = 0; k < 5; ++k) putU32(h, 0);                   // dwRGBBitCount and the four masks
  putU32(h, DDSCAPS_TEXTURE | (volume ? DDSCAPS_COMPLEX : 0u));
  putU32(h, volume ? DDSCAPS2_VOLUME : 0u);
  putU32(h, 0);  // dwCaps3
  putU32(h, 0);  // dwCaps4
  putU32(h, 0);  // dwReserved2
  putU32(h, dxgi);
  putU32(h, volume ? kDimTexture3D : kDimTexture2D);
  putU32(h, 0);  // miscFlag
  putU32(h, 1);  // arraySize: 1 (a 3D texture cannot be an array)
  putU32(h, 0);  // miscFlags2: DDS_ALPHA_MODE_UNKNOWN

  TempFileWriter out(tmp, path);
  out.write(h);
  writeSlices(out, src, path, outChannels, p);
  out.finish();
}

}  // namespace brdfbake
