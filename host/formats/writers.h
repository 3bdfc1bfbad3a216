// The table writers besides OpenEXR (exr/table_file.h): KTX2, DDS, 16-bit PNG and a C/C++ header
// with a JavaScript module. Each writes a temporary (the output set renames it with the others,
// formats/output_set.h), syncs it, and is deterministic: the same table gives the same bytes.
// Values are validated as they are packed (formats/storage.h, packTexels); an Error leaves no file.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "formats/storage.h"

namespace brdfbake {

// KTX 2.0 (Khronos), written from the specification (ktx2_writer.cpp): one mip level,
// supercompression none, a 2D texture (src.depth == 1) or a 3D one (pixelDepth = depth, slices
// z-major, streamed block by block), vkFormat R*_SFLOAT / R*_UNORM with outChannels components,
// a basic Data Format Descriptor, and key/value data: KTXorientation ("rd" / "rdi"), KTXwriter
// and every attribute of `meta` as NUL-terminated text, sorted by key.
void writeKtx2Temporary(const std::string& tmp, const std::string& path, const TableImage& meta, const SliceSource& src,
                        int outChannels, Precision p);
// The VkFormat for `channels` (1..4) components of precision p (R8_UNORM 9 ... R32G32B32A32_SFLOAT 109).
uint32_t ktx2VkFormat(int channels, Precision p);

// DDS with the DX10 header (dds_writer.cpp): DXGI_FORMAT R32/R16 float, R16/R8 unorm with 1, 2 or
// 4 components (DXGI has no 3-component 16- or 8-bit format; outChannels 3 is for float32 only),
// TEXTURE2D or TEXTURE3D (DDSD_DEPTH, DDSCAPS2_VOLUME), one mip level. DDS has no place for
// metadata: the brdf.* attributes are not in the file.
void writeDdsTemporary(const std::string& tmp, const std::string& path, const SliceSource& src, int outChannels,
                       Precision p);
uint32_t ddsDxgiFormat(int channels, Precision p);  // 0 when DXGI has none

// 16-bit PNG (png_writer.cpp, libpng): 2D only, RGB (3 channels) or RGBA (4), each value stored
// as round((v - offset) / scale * 65535): value = png / 65535 * scale + offset. `meta`'s
// attributes go into tEXt chunks (one per attribute), brdf.mapping among them.
void writePng16Temporary(const std::string& tmp, const std::string& path, const TableImage& img, double scale,
                         double offset);
// An 8-bit sRGB picture of linear RGB planes (png_writer.cpp): clamped to [0, 1], sRGB-encoded, an
// sRGB chunk and one tEXt chunk per (key, text).
void writePng8SrgbTemporary(const std::string& tmp, const std::string& path, int width, int height,
                            const std::vector<std::vector<float>>& rgb,
                            const std::vector<std::pair<std::string, std::string>>& text);

// A C/C++ header (header_writer.cpp) or an ECMAScript module (js == true) holding the table as
// literals: float32 as float literals with 9 significant digits (exact), float16 as the half
// bit patterns (uint16), unorm16 / unorm8 as the integer codes; dimensions, channel layout and
// every attribute as constants. `name` is the identifier stem (letters, digits, underscores).
void writeHeaderTemporary(const std::string& tmp, const std::string& path, const TableImage& meta,
                          const SliceSource& src, Precision p, const std::string& name, bool js);
// An identifier stem from a file stem: non-alphanumerics become '_', a leading digit gets '_'.
std::string headerIdentifier(const std::string& stem);

}  // namespace brdfbake
