// Generated lookup code: for each baked table, GLSL or HLSL functions that take the physical
// quantities (mu, r; the angles of a 3D table) and return the table's quantities, with the grid
// convention, axis ranges, atlas layout and channel meaning built in, so a shader cannot get the
// mapping wrong. Two paths per table: the hardware bilinear filter (texture()), and an exact one
// (four texelFetch and the lerps in float) for GPUs whose filter weights have 8 fractional bits.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "formats/readers/table_reader.h"  // tableHeaderFromText, for callers that read files themselves
#include "formats/table_image.h"

namespace brdfbake {

enum class ShaderLang { Glsl, Hlsl };

// The identifier a table's functions start with, from its file name: "splitsum_ggx_smith-correlated.exr"
// -> "brdf_splitsum_ggx_smith_correlated".
std::string shaderPrefix(const std::string& path);

// The functions for one table (its header attributes describe it; its pixels are not needed).
// Throws Error(kExitDataErr) naming the file when the header lacks what the code needs.
std::string shaderForTable(const std::string& path, const TableImage& header, ShaderLang lang);

// `brdfbake shader --lang L FILE...`: every file's functions (EXR, KTX2, PNG, the header format; a DDS
// with the metadata of the file beside it: formats/readers/table_reader.h tableMetadata), then what a
// kind among them writes once (the LTC's polygon integral, tables/kind_info.h ShaderCode), plus the glue to
// shaders/multiscatter.glsl (lookupE, lookupEavg, lookupAB) when the albedo, albedo-avg and
// split-sum tables of one pair are among the files.
std::string shaderForFiles(const std::vector<std::string>& paths, ShaderLang lang);

}  // namespace brdfbake
