// `brdfbake render`: the white furnace through a real GL pipeline (render/furnace.h: the grid, its
// rows and its measurement) and the lobe picture: one sphere per roughness under a directional
// light, single scattering against the Kulla-Conty compensated, so the added lobe can be seen.
// Writes linear EXRs to measure and sRGB PNGs to look at, as one set.
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

struct RenderOptions {
  std::string outDir = "out/render";
  std::string ndf = "ggx", gaf = "smith-correlated";  // the pair the microfacet and glass rows shade
  int cell = 48;                                      // pixels per sphere's square, 16..256
  int columns = 11;                                   // roughness steps 0..1, 2..33
  std::vector<std::string> rows;                      // empty: every row that fits the pair
  std::string light = "furnace";                      // furnace, or quad (render/ltc_render.h)
  std::string device, cacheDir;
  bool noWait = false;
};

// Checks the options (Error(kExitUsage) naming the option and its range), opens GL (kExitUnavailable
// naming the packages), bakes the tables, renders, writes DIR/furnace.{exr,png} and DIR/lobe.{exr,png}
// as one set, prints the measurement. Returns 0, or 1 when a measured row is past its bound.
int runRender(const RenderOptions& o);

}  // namespace brdfbake
