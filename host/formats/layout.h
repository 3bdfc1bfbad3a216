// Table layouts: how a split-sum table's texels are arranged for an engine that samples it with its
// own fixed expression. Axis order (mu along x, or r along x), which end of each axis is texel 0
// (flip), and which quantity each stored channel holds (A, B, A+B). Presets (--layout NAME) fix
// these plus the file format, precision and size the engine loads, each derived from the engine's
// own sampling code (cited per preset and in the README, "Layout presets"). The layout is recorded in
// the file (brdf.layout.*), and the generated shader code (shader/shader_gen.h) follows it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "formats/storage.h"
#include "formats/table_image.h"

namespace brdfbake {

struct TableLayout {
  bool rAlongX = false;               // --axes r,mu: x = r, y = mu (default mu,r)
  bool flipX = false, flipY = false;  // --flip-x / --flip-y: texel 0 holds the high end of that axis
  std::vector<std::string> channels;  // --channels: stored R, G[, B] from {A, B, A+B}; empty: as baked
  bool identity() const { return !rAlongX && !flipX && !flipY && channels.empty(); }
};

struct LayoutPreset {
  std::string name;
  TableLayout layout;
  FileFormat format;
  Precision precision;
  int size;
  std::string citation;  // the engine's sampling code it follows: repository, path, expression
  // How the engine addresses the texels: node grid (texel i holds i/(n-1), e.g. HDRP's
  // Remap01ToHalfTexelCoord) or texel centres; and whether its x coordinate is sqrt(mu). A --grid or
  // --mu-axis that contradicts them is refused (cli/layout_args.h): the engine's lookup would misread the file.
  bool nodeGrid = false;
  bool muSqrt = false;
};

const std::vector<LayoutPreset>& layoutPresets();
// The layout's name in file names and brdf.layout: the preset's, else one spelling the custom
// arrangement ("r-mu_flip-y_B-A"), else "" (the table as baked). Presets and custom layouts thus
// never share a file name with each other or with the plain table.
std::string layoutName(const std::optional<std::string>& preset, const TableLayout& layout);
// The preset named `name`; throws Error(kExitUsage) listing the presets when there is none.
const LayoutPreset& layoutPreset(const std::string& name);
// "A,B" -> {"A", "B"}; throws Error(kExitUsage) for a name other than A, B, A+B, a repeat, or
// fewer than 2 or more than 3 channels.
std::vector<std::string> parseLayoutChannels(const std::string& list);

// The split-sum table `img` (R = A, G = B, B = A + B, as computeTable makes it) in `layout`: texels
// transposed / flipped, channels recombined; brdf.axes, brdf.channels and brdf.layout.* updated.
// Throws Error(kExitUsage) for a non-identity layout of a table other than splitsum.
TableImage applyLayout(const TableImage& img, const TableLayout& layout);

}  // namespace brdfbake
