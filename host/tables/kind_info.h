// A table kind as the family that defines it describes it. Stages outside the families (the shader
// generator, scene manifests, bake reports, argument checks, the furnace) ask this and never switch
// over kinds. The registry collects every family's descriptions; tableName and tableKind
// (brdfbake/table_kind.h) read the names given here.
#pragma once
#include <functional>
#include <string>

#include "brdfbake/table_kind.h"
#include "formats/shader_lang.h"
#include "formats/table_image.h"

namespace brdfbake {

// Which lookup code `brdfbake shader` writes for a table of the kind.
enum class ShaderLookup {
  Value,        // one value per (mu, r), (r) or (eta): P_<shaderValue>(tex, ...)
  SplitSum,     // A, B and the Fresnel forms built on them (P_AB, P_Schlick, ...)
  EtaAverages,  // E_R,avg, E_T,avg and their sum over (r, eta)
  Volume,       // a 3D texture over the BRDF's angles (brdf3d)
  EtaVolume,    // an atlas of eta slices over (mu, r) (dielectric)
  OwnShader,    // textures that come with their own shader (ashikhmin-shirley): none written
  Family,       // the family writes the accessors itself (KindInfo::shaderCode)
};

// Lookup code a family writes for its kind (ShaderLookup::Family): the generator writes the grid's
// lookups (P_lookup, P_lookupExact) and asks the family for the accessors built on them.
struct ShaderCode {
  // the accessors on one path: variant "" reads P_lookup (the hardware filter), "Exact" P_lookupExact;
  // header: the table's attributes
  std::function<std::string(const shadergen::Lang& lang, const std::string& prefix, const TableImage& header,
                            const std::string& variant)>
      accessors;
  // written once after the files' lookups when a table of the kind is among them (empty: nothing)
  std::function<std::string(const shadergen::Lang& lang)> once;
};

// What a scene's shading reads a kind for: scene/scene_plan.cpp plans, for each material, the
// kinds that serve each use it has (kindsServing, tables/registry.h).
enum SceneUse : unsigned {
  kUseIbl = 1u << 0,            // image-based lighting through a Schlick or F82 split (the split sum)
  kUseIblFresnel = 1u << 1,     // image-based lighting for a Fresnel model with no split (its weighted albedo)
  kUseMultiscatter = 1u << 2,   // Kulla-Conty compensation: E and E_avg with F = 1
  kUseNormalisation = 1u << 3,  // analytic lights on an NDF whose normalisation has no closed form (k_p)
  kUseAlbedoScaling = 1u << 4,  // the albedo-scaling coupling: E_F and E_F,avg
  kUseWholeMaterial = 1u << 5,  // a 3D table of the whole material (brdf3d = true)
  kUseTransmission = 1u << 6,   // rough glass: E_R, E_T and their averages
  kUseSheen = 1u << 7,          // KHR_materials_sheen's albedo scaling (E of the Charlie lobe)
  kUseSheenIbl = 1u << 8,       // KHR_materials_sheen under image-based lighting
};

struct KindInfo {
  TableKind kind;
  std::string name;      // --table NAME, a scene's [output.size] key, a file's brdf.table
  int defaultSize = 32;  // --size's default
  int sizeAxes = 1;      // 3: --size takes NX,NY,NZ (brdf3d, dielectric)
  bool volume = false;   // a 3D texture written slab by slab, with brdf3d's options; [output.size] takes N or [X, Y, Z]
  bool inDefaultSet = false;  // `brdfbake` with no --table bakes it
  bool albedo =
      false;  // a hemispherical albedo or its average: what a Fresnel model or a measured material enters by default
  bool average = false;    // an average over mu of another kind (albedo-avg, dielectric-avg)
  unsigned sceneUses = 0;  // SceneUse bits
  // the quantity a lossless surface keeps at or below 1, and the channel that holds it ("" when the
  // kind has none): `info` and bakes warn when it exceeds 1
  std::string energy = {}, energyChannel = {};
  ShaderLookup shader = ShaderLookup::Value;
  std::string shaderValue = {};  // ShaderLookup::Value: the accessor's name ("E" -> P_E(tex, mu, r))
  ShaderCode shaderCode = {};    // ShaderLookup::Family: the family's accessors
  bool inScenes = false;         // a scene manifest names it ([output.size] keys) and plans it
  bool furnace = false;          // the furnace render and the report pages' renders read it
  bool muRAxes = false;          // x = mu, y = r: --mu-axis sqrt spaces its x texels in sqrt(mu)
  bool layouts = false;          // --layout presets and --axes/--flip/--channels arrange it
};

}  // namespace brdfbake
