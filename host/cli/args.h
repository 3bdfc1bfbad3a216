// Command line -> Command. Pure parsing and validation: nothing is read or written here.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "common/material.h"
#include "common/models.h"

namespace brdfbake {

struct BakeRequest {
  std::vector<int> ndfs;             // NDF_* ids; their product with gafs is baked
  std::vector<int> gafs;             // GAF_* ids
  std::vector<TableKind> tables;
  std::optional<int> size;           // texels per axis; default per table (defaultSize)
  std::string outDir = "out";
  bool half = false;                 // HALF instead of FLOAT channels
  bool nodeGrid = false;             // samples at i/(n-1) instead of texel centres (i+0.5)/n
  std::string device;                // substring of the device (or platform) name; "" = first CPU
  std::string cacheDir;              // PoCL kernel cache (POCL_CACHE_DIR); "" = PoCL's default
  FresnelChoice fresnel;             // --fresnel and its parameters (validated)
  bool fresnelGiven = false;
  int diffuse = -1;                  // --diffuse: DIFFUSE_* id, or -1
  std::string merl;                  // --brdf merl:FILE: a measured material's MERL file, or ""
  std::optional<double> sigma;       // energy: --sigma for oren-nayar (else swept)
  std::string coupling = "sum";      // energy: --coupling sum | albedo-scaling
  std::vector<int> levels = {0, 1, 2, 3};                           // convergence: quadrature levels
  std::vector<int> samples = {16, 64, 256, 1024, 4096, 16384, 65536};  // convergence: MC samples
};

struct Command {
  enum class Kind { Bake, Energy, Verify, Stress, Convergence, Devices, Info, Help, Version } kind = Kind::Bake;
  BakeRequest bake;
  std::string file;  // for Info
};

constexpr int kMinSize = 1;
constexpr int kMaxSize = 8192;

// The built-in default set (no arguments): ggx + smith-correlated, every table at its default size.
BakeRequest defaultRequest();
int defaultSize(TableKind kind);  // splitsum 128, others 32

// Throws Error(kExitUsage) with a message naming the option and the accepted values.
Command parseArgs(const std::vector<std::string>& args);

std::string usageText();

}  // namespace brdfbake
