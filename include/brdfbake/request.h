// A bake request: which tables, for which models, at what size, in which formats. The library's
// input (brdfbake/brdfbake.h bake()); the command line (host/cli), scenes (host/scene) and the
// reports build one. The planner (plan/plan.h) validates it and turns it into jobs.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "brdfbake/observer.h"
#include "brdfbake/table_kind.h"
#include "common/brdf3d_grid.h"
#include "common/material.h"
#include "common/models.h"
#include "formats/layout.h"
#include "formats/storage.h"

namespace brdfbake {

struct BakeRequest {
  std::vector<int> ndfs;  // NDF_* ids; their product with gafs is baked
  std::vector<int> gafs;  // GAF_* ids
  std::vector<TableKind> tables;
  std::optional<int> size;  // texels per axis; default per table (defaultSize)
  std::string outDir = "out";
  std::optional<Precision> precision;       // --precision (--half: float16); unset: float32
  std::vector<FileFormat> formats;          // --format (merl apart: volume.merl); empty: exr
  TableLayout layout;                       // --layout preset / --axes, --flip-x, --flip-y, --channels
  std::optional<std::string> layoutPreset;  // --layout NAME: its format, precision and size unless given
  bool nodeGrid = false;                    // samples at i/(n-1) instead of texel centres (i+0.5)/n
  // --mu-axis sqrt: splitsum and albedo space their x texels in u = sqrt(mu) (texel i holds mu = u_i^2);
  // unset: linear, or the layout preset's (cli/layout_args.h validateMuAxis sets it)
  std::optional<bool> muSqrt;
  std::string device;                      // substring of the device (or platform) name; "" = first CPU
  std::string cacheDir;                    // PoCL kernel cache (POCL_CACHE_DIR); "" = PoCL's default
  bool noWait = false;                     // another bake writing into outDir: Error(kExitTempFail) instead of waiting
  std::shared_ptr<BakeObserver> observer;  // stages and progress as the bake runs (brdfbake/observer.h); optional
  // --fresnel and its parameters (validated); unset: no Fresnel chosen, and a table that takes one
  // holds F = 1 (fresnelOf)
  std::optional<FresnelChoice> fresnel;
  int diffuse = -1;             // --diffuse: DIFFUSE_* id, or -1
  std::string merl;             // --brdf merl:FILE: a measured material's MERL file, or ""
  std::string preset;           // --preset gltf: glTF's reference-shading tables (plan/plan.cpp), or ""
  std::optional<double> sigma;  // --sigma: oren-nayar's roughness (brdf3d; energy sweeps it when unset)
  // --table dielectric, dielectric-avg: the eta axis's range (--eta-range LO,HI)
  std::optional<std::pair<double, double>> etaRange;
  // --table brdf3d (the others ignore these; given without it, they are a usage error)
  struct Volume {
    Brdf3dParam param = Brdf3dParam::Angles;   // --param
    bool thetaHSqrt = false;                   // --theta-h sqrt
    bool timesCos = false;                     // --value f-cos
    double roughness = 0.5;                    // --roughness
    std::vector<double> rho;                   // --rho (diffuse albedo; default 1)
    std::optional<std::array<int, 3>> size;    // --size NX,NY,NZ (or N: N each)
    std::optional<std::pair<int, int>> atlas;  // --atlas CxR
    bool merl = false;                         // --format merl
  } volume;
};

// The request's Fresnel: the chosen one, or F = 1 (model one) when none is.
inline const FresnelChoice& fresnelOf(const BakeRequest& r) {
  static const FresnelChoice one;
  return r.fresnel ? *r.fresnel : one;
}

// Whether the request's tables store float16 (an EXR's HALF channels): --half is --precision float16.
inline bool storesHalf(const BakeRequest& r) { return r.precision == Precision::Float16; }

// The accepted ranges (plan/plan.h and the command line check them).
constexpr int kMinSize = 1;
constexpr int kMaxSize = 8192;
constexpr int kMaxVolumeSize = 1024;  // per axis of a 3D table
constexpr double kMinVolumeRoughness = 0.01;

// The built-in default set (no arguments): ggx + smith-correlated, every table at its default size.
BakeRequest defaultRequest();

}  // namespace brdfbake
