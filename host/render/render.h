// `brdfbake render`: the white furnace through a real GL pipeline. A grid of spheres (roughness 0
// to 1 across, one material per row) under a uniform white environment, each pixel shaded on the
// GPU (llvmpipe without one) by the generated lookup code sampling the baked files, read back as an
// engine loads them. Writes a linear EXR to measure and an sRGB PNG to look at, and measures: rows
// that conserve energy must be 1 within what the tables' claims and interpolation errors predict,
// the single-scattering row must match the independent reference's E(n.v, r).
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

struct RenderOptions {
  std::string outDir = "out/render";
  int cell = 48;     // pixels per sphere's square, 16..256
  int columns = 11;  // roughness steps 0..1, 2..33
  std::vector<std::string> rows;  // empty: every row
  std::string device, cacheDir;
  bool noWait = false;
};

// The rows a furnace render draws, in order, and what each shades.
struct FurnaceRow {
  std::string name, what;
  bool conserves;  // should vanish into the background (E = 1)
};
const std::vector<FurnaceRow>& furnaceRows();

// Checks the options (Error(kExitUsage) naming the option and its range), opens GL (kExitUnavailable
// naming the packages), bakes the tables, renders, writes DIR/furnace.exr and DIR/furnace.png as
// one set, prints the measurement. Returns 0, or 1 when a row that should conserve does not.
int runRender(const RenderOptions& o);

}  // namespace brdfbake
