// A table kind as the family that defines it describes it. Stages outside the families (the shader
// generator, scene manifests, bake reports, argument checks, the furnace) ask this and never switch
// over kinds; the kind's name is tableName(kind) (common/models.h, the one list of ids and names).
#pragma once
#include <string>

#include "common/models.h"

namespace brdfbake {

// Which lookup code `brdfbake shader` writes for a table of the kind.
enum class ShaderLookup {
  Value,             // one value per (mu, r), (r) or (eta): P_<shaderValue>(tex, ...)
  SplitSum,          // A, B and the Fresnel forms built on them (P_AB, P_Schlick, ...)
  EtaAverages,       // E_R,avg, E_T,avg and their sum over (r, eta)
  Volume,            // a 3D texture over the BRDF's angles (brdf3d)
  EtaVolume,         // an atlas of eta slices over (mu, r) (dielectric)
  OwnShader,         // textures that come with their own shader (ashikhmin-shirley): none written
};

struct KindInfo {
  TableKind kind;
  int defaultSize = 32;      // --size's default
  int sizeAxes = 1;          // 3: --size and [output.size] take X,Y,Z (brdf3d)
  // the quantity a lossless surface keeps at or below 1, and the channel that holds it ("" when the
  // kind has none): `info` and bakes warn when it exceeds 1
  std::string energy = {}, energyChannel = {};
  ShaderLookup shader = ShaderLookup::Value;
  std::string shaderValue = {};  // ShaderLookup::Value: the accessor's name ("E" -> P_E(tex, mu, r))
  bool inScenes = false;     // a scene manifest names it ([output.size] keys) and plans it
  bool furnace = false;      // the furnace render and the report pages' renders read it
  bool muRAxes = false;      // x = mu, y = r: --mu-axis sqrt spaces its x texels in sqrt(mu)
  bool layouts = false;      // --layout presets and --axes/--flip/--channels arrange it
};

}  // namespace brdfbake
