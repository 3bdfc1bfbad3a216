// Request -> plan: the list of tables to bake, each with its size, grid, file name and the header
// attributes that do not depend on the baked values. Validation of combinations happens here, so
// nothing is computed or written for a request that cannot be honoured.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "cli/args.h"
#include "common/models.h"

namespace brdfbake {

struct TableJob {
  TableKind kind;
  int ndf;
  int gaf;           // GAF_NONE for kp, which depends on the NDF only
  int width, height; // x = mu (2D tables) or r (1D), y = r (2D) or 1
  bool nodeGrid;
  bool half;
  std::string path;  // output file
  FresnelChoice fresnel;  // albedo, albedo-avg: the model in B (one: F = 1); splitsum: schlick or f82-tint
  int diffuse = -1;       // albedo: a diffuse model's albedo (ndf, gaf unused); splitsum: burley in B
  int texture = -1;       // ashikhmin-shirley: Tex0, Tex1 or Tex2 (one file each)
  // the files written (path's extension replaced per format) and the precision of their channels;
  // half == (precision == float16), what the EXR file stores
  std::vector<FileFormat> formats = {FileFormat::Exr};
  Precision precision = Precision::Float32;
  TableLayout layout = {};  // splitsum: axis order, flips, channels (formats/layout.h)
  bool muSqrt = false;      // splitsum, albedo: x holds u = sqrt(mu), texel i at mu = u_i^2 (--mu-axis sqrt)
};

// A 3D table (--table brdf3d): one per NDF/GAF pair, baked and written slab by slab.
struct VolumeJob {
  Brdf3dSpec spec;
  std::string path;
  bool half = false;
  bool merl = false;      // MERL's binary layout instead of an EXR atlas
  int cols = 1, rows = 1; // the EXR atlas: slices left to right, then top to bottom
  std::vector<FileFormat> formats = {FileFormat::Exr};  // ktx2, dds: 3D textures; header; exr: the atlas
  Precision precision = Precision::Float32;
};

// A rough-dielectric table (--table dielectric: 3D over (mu, r, eta coordinate), an EXR atlas of
// eta slices; dielectric-avg: 2D over (r, eta coordinate)). bake/dielectric_bake.h.
struct DielectricJob {
  int ndf = 0, gaf = 0;
  bool avg = false;          // dielectric-avg
  int nx = 32, ny = 32, nz = 32;  // mu, r, eta (avg: nx = r, ny = eta, nz = 1)
  bool nodeGrid = false, half = false;
  double etaLo = 0.4, etaHi = 2.5;
  int cols = 1, rows = 1;    // the atlas (3D)
  std::string path;
};

struct Plan {
  std::string outDir;
  std::string device;
  std::vector<TableJob> jobs;
  std::vector<VolumeJob> volumes;
  // Extra string attributes of the file at a path (scenes: brdf.hash, brdf.scene).
  std::map<std::string, std::map<std::string, std::string>> extraStrings;
  std::vector<DielectricJob> dielectric;
  std::string merl;  // a measured material's MERL file, the jobs' material (bake/merl_bake.h); "" = none
};

// Throws Error(kExitUsage) for combinations that have no finite table (gaf none on a node grid,
// whose mu = 0 column is infinite).
Plan makePlan(const BakeRequest& req);
// The request's formats and precision on every job of `plan` (makePlan and makeMerlPlan call it).
void applyFormats(const BakeRequest& req, Plan& plan);

std::string fileName(const TableJob& job);
std::string fileName(const VolumeJob& job);
// The atlas grid for `depth` slices: an exact columns x rows split no wider than 4:1 when there is
// one (180 -> 15x12, 512 -> 32x16), else ceil(sqrt(depth)) columns and as many rows as needed.
std::pair<int, int> atlasGrid(int depth);

}  // namespace brdfbake
