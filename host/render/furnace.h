// The white furnace grid: spheres of roughness 0 to 1 across, one material per row, under a uniform
// white environment (radiance 1 everywhere, the background 1), each pixel shaded on GL by the
// generated lookup code sampling baked files, read back as an engine loads them; and the
// measurement: each pixel is held to a bound built from the texels its lookups read
// (render/furnace_bounds.h): the Kulla-Conty row to 1, the single-scattering row to the independent
// reference's E(n.v, r), the glass row to the reference's E_R + E_T (and never above 1); the rows
// that are 1 by algebra to float rounding. `brdfbake render` and the report pages draw it.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "brdfbake/brdfbake.h"
#include "render/gl_context.h"

namespace brdfbake {

// The rows a furnace render can draw, in order, and what each shades.
struct FurnaceRow {
  std::string name, what;
  bool conserves;  // should vanish into the background (E = 1)
  // What the row's measurement tests: the tables (its pixels move with their values: single and
  // glass against the reference, kulla-conty against 1), algebra only (1 whatever the tables hold:
  // single-table, dielectric-lambert check the shading code), or nothing (gold, sheen: for the eye).
  enum class Checks { Tables, Algebra, None } checks;
  std::string against;  // what the deviation is measured against, as printed
  std::string expect;   // what a reader of the picture should see, under the row's name in the PNG
};
const std::vector<FurnaceRow>& furnaceRows();
int furnaceRowIndex(const std::string& name);  // -1 for none
// Whether a row applies to the pair: the microfacet rows to every NDF but charlie, the glass row to
// the pairs the rough dielectric takes (ggx, beckmann with smith, smith-correlated); the sheen row
// is charlie + charlie-smith whatever the pair.
bool furnaceRowFits(int row, int ndf, int gaf);

// The glass row's material: eta 1.5 (crown glass), seen from outside.
constexpr double kGlassEta = 1.5;

struct FurnaceSpec {
  int ndf = 0, gaf = 0;
  int cell = 48, columns = 11;
  std::vector<int> rows;          // furnaceRows() indices, top to bottom
  int glassMu = 32, glassR = 16;  // the glass row's table: texels over mu and r (one eta slice)
};

// The files the rows sample (empty: not needed), and each read back as an engine loads it.
struct FurnaceTables {
  std::string splitsum, albedo, albedoAvg, sheen, glass;
  std::map<std::string, Table> read;  // by path
  std::vector<std::string> all() const;
};
// Bakes what the rows need into `dir` as `brdfbake bake` does (one locked, atomic set per request):
// the pair's split sum, albedo and albedo-avg; charlie + charlie-smith's split sum for the sheen row;
// for the glass row a dielectric table of one eta slice at kGlassEta (glassMu x glassR x 1).
FurnaceTables bakeFurnaceTables(const FurnaceSpec& s, const std::string& dir, const std::string& device, bool noWait);

struct RowMeasure {
  double worst = 0, worstBound = 0;  // the largest deviation and the bound at that pixel
  double largestBound = 0;           // the largest of the measured pixels' bounds
  long over = 0, pixels = 0;         // pixels past their bound, sphere pixels
  long created = 0;                  // glass pixels above 1 (more light out than in)
  bool measured = false;
};
struct FurnacePicture {
  int width = 0, height = 0;
  std::vector<std::vector<float>> rgb;  // linear planes R, G, B
  std::vector<RowMeasure> rows;         // per row of the spec
  std::string renderer;                 // GL_RENDERER
  bool fail = false;                    // a measured row has pixels past their bound
};
// The table as an RGBA32F texture on texture unit `unit`, bilinear and clamped to the edge: what
// the generated lookup code expects. The caller deletes the returned texture.
GLuint bindTableTexture(const GlContext& gl, const Table& t, int unit);
// The same for planes (one per channel, missing channels 1): RGBA32F, linear, clamped to the edge.
GLuint bindPlanesTexture(const GlContext& gl, int width, int height, const std::vector<std::vector<float>>& planes,
                         int unit);

// Renders and measures. Error(kExitSoftware) for a pixel that is not finite.
FurnacePicture renderFurnace(const GlContext& gl, const FurnaceSpec& s, const FurnaceTables& t);

// The measurement as a table, one line per row: name, conserves, largest deviation (what it is
// against), its bound, pixels over.
std::string furnaceTable(const FurnaceSpec& s, const FurnacePicture& p);

}  // namespace brdfbake
