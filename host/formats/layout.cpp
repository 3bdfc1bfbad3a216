// Layouts and presets: see layout.h. The presets follow the engines' sampling code (conventions
// and facts cited, no code taken):
#include "formats/layout.h"

#include <algorithm>

#include "common/errors.h"
#include "common/models.h"

namespace brdfbake {

const std::vector<LayoutPreset>& layoutPresets() {
  // Each engine samples its LUT at uv = (NoV, perceptual roughness) (mu along x, r along y, r the
  // baker's roughness axis: alpha = r^2) with texel-center addressing and texel row 0 at uv.y = 0
  // (row 0 = r 0: no flip); they differ in the channels and the file. unity-hdrp-sqrt alone samples
  // x = sqrt(NoV) on a node grid.
  static const std::vector<LayoutPreset> presets = {
      {"filament",
       {false, false, false, {"B", "A+B"}},
       FileFormat::Ktx2,
       Precision::Float16,
       128,
       "google/filament shaders/src/light_indirect.fs: PrefilteredDFG_LUT = textureLod(light_iblDFG, vec2(NoV, "
       "roughness), 0.0).rg; specularDFG = mix(dfg.xxx, dfg.yyy, f0) (multiple scattering): R = B, G = A + B"},
      {"bevy",
       {false, false, false, {"A", "B"}},
       FileFormat::Ktx2,
       Precision::Float16,
       64,
       "bevyengine/bevy crates/bevy_pbr/src/environment_map/environment_map.wgsl: f_ab = "
       "textureSample(environment_map_brdf_lut, s, vec2(NdotV, perceptual_roughness)).rg; FssEss = kS * f_ab.x + "
       "f_ab.y: R = A, G = B"},
      {"unity-hdrp",
       {false, false, false, {"B", "A+B"}},
       FileFormat::Exr,
       Precision::Float16,
       64,
       "Unity-Technologies/Graphics com.unity.render-pipelines.high-definition/HDRP/Material/PreIntegratedFGD/"
       "PreIntegratedFGD.hlsl: preFGD = SAMPLE_TEXTURE2D_LOD(_PreIntegratedFGD_GGXDisneyDiffuse, "
       "s_linear_clamp_sampler, float2(NdotV, perceptualRoughness), 0); specularFGD = lerp(preFGD.xxx, "
       "preFGD.yyy, fresnel0): R = B, G = A + B (the linear-NdotV form; later HDRP samples sqrt(NdotV) on a node "
       "grid: unity-hdrp-sqrt)"},
      // HDRP's current form: x = sqrt(NdotV) on a node grid (Remap01ToHalfTexelCoord), so the preset bakes the
      // sqrt mu axis (--mu-axis sqrt) on nodes (--grid node)
      {"unity-hdrp-sqrt",
       {false, false, false, {"B", "A+B"}},
       FileFormat::Exr,
       Precision::Float16,
       64,
       "Unity-Technologies/Graphics com.unity.render-pipelines.high-definition/Runtime/Material/PreIntegratedFGD/"
       "PreIntegratedFGD.hlsl: GetPreIntegratedFGDGGXAndDisneyDiffuse: coordLUT = Remap01ToHalfTexelCoord("
       "float2(sqrt(NdotV), perceptualRoughness), FGDTEXTURE_RESOLUTION); preFGD = SAMPLE_TEXTURE2D_LOD("
       "_PreIntegratedFGD_GGXDisneyDiffuse, s_linear_clamp_sampler, coordLUT, 0).xyz; specularFGD = "
       "lerp(preFGD.xxx, preFGD.yyy, fresnel0); com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl: "
       "Remap01ToHalfTexelCoord maps [0, 1] onto [0.5/size, 1 - 0.5/size] (texel i holds i/(size-1): a node grid); "
       "preIntegratedFGD_GGXDisneyDiffuse.shader: NdotV = x * x, perceptualRoughness = y (alpha = its square); "
       "PreIntegratedFGD.cs.hlsl: FGDTEXTURE_RESOLUTION 64; core ImageBasedLighting.hlsl "
       "IntegrateGGXAndDisneyDiffuseFGD: x += w (1 - V.H)^5, y += w: R = B, G = A + B (z, the Disney diffuse "
       "albedo - 0.5, is not baked)",
       true,
       true},
      {"unreal",
       {false, false, false, {"A", "B"}},
       FileFormat::Dds,
       Precision::Unorm16,
       128,
       "Epic Games' Unreal Engine (its repository is access-restricted; read in the public mirror "
       "chenyong2github/UnrealEngine) Engine/Shaders/Private/BRDF.ush: EnvBRDF: AB = Texture2DSampleLevel("
       "PreIntegratedGF, PreIntegratedGFSampler, float2(NoV, Roughness), 0).rg; SpecularColor * AB.x + "
       "saturate(50.0 * SpecularColor.g) * AB.y; Engine/Source/Runtime/Renderer/Private/SystemTextures.cpp "
       "(PreintegratedGF): x is NoV = (x + 0.5) / width, y is Roughness = (y + 0.5) / height, PF_G16R16 with "
       "Dest[0] = A, Dest[1] = B as unorm16: R = A, G = B, row 0 = roughness 0"},
      {"gltf-sample-viewer",
       {false, false, false, {}},
       FileFormat::Png16,
       Precision::Unorm16,
       128,
       "KhronosGroup/glTF-Sample-Viewer source/Renderer/shaders/ibl.glsl: brdf = texture(u_GGXLUT, "
       "clamp(vec2(NdotV, perceptualRoughness), 0.0, 1.0)).rg; specularColor * brdf.x + brdf.y: R = A, G = B "
       "(the baker's B = A + B rides along in the PNG's third channel); source/Renderer/webgl.js setTexture: "
       "UNPACK_FLIP_Y_WEBGL false, texImage2D(RGBA, UNSIGNED_BYTE) of the PNG (linear: gltfTextureInfo's "
       "default in source/gltf/texture.js): the PNG's first row is texel row 0, roughness 0; the browser "
       "hands the viewer 8 bits of each 16-bit sample"},
  };
  return presets;
}

std::string layoutName(const std::optional<std::string>& preset, const TableLayout& layout) {
  if (preset) return *preset;
  if (layout.identity()) return "";
  std::string n = layout.rAlongX ? "r-mu" : "mu-r";
  if (layout.flipX) n += "_flip-x";
  if (layout.flipY) n += "_flip-y";
  if (!layout.channels.empty()) {
    n += "_";
    for (size_t c = 0; c < layout.channels.size(); ++c)
      n += (c ? "-" : "") + (layout.channels[c] == "A+B" ? std::string("AB") : layout.channels[c]);
  }
  return n;
}

const LayoutPreset& layoutPreset(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& p : layoutPresets()) {
    if (p.name == name) return p;
    names.push_back(p.name);
  }
  throw Error(kExitUsage, "--layout: unknown preset '" + name + "'" + didYouMean(name, names) +
                              "; presets: " + joinNames(names) +
                              " (or set the layout with --axes mu,r|r,mu, --flip-x, --flip-y, --channels)");
}

std::vector<std::string> parseLayoutChannels(const std::string& list) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t comma = list.find(',', start);
    std::string c = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (c != "A" && c != "B" && c != "A+B")
      throw Error(kExitUsage, "--channels: '" + c + "' is not a split-sum quantity (A, B or A+B)");
    if (std::find(out.begin(), out.end(), c) != out.end()) throw Error(kExitUsage, "--channels: " + c + " twice");
    out.push_back(c);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (out.size() < 2 || out.size() > 3)
    throw Error(kExitUsage, "--channels: give 2 or 3 of A, B, A+B (stored as R, G[, B]), got '" + list + "'");
  if (out.size() == 2 && std::find(out.begin(), out.end(), "A") == out.end() &&
      std::find(out.begin(), out.end(), "B") == out.end())
    throw Error(kExitUsage, "--channels: A+B alone with nothing else cannot give A and B");
  return out;
}

TableImage applyLayout(const TableImage& img, const TableLayout& layout) {
  if (layout.identity()) return img;
  // a layout arranges A and B: a table that stores them as R and G (the split sum's, every variant)
  auto ch = img.strings.find("brdf.channels");
  if (ch == img.strings.end() || ch->second.rfind("R=A,G=B", 0) != 0 || img.planes.size() < 2)
    throw Error(kExitUsage, "--layout, --axes, --flip-x, --flip-y, --channels apply to the splitsum table only");
  const std::vector<std::string> chans =
      layout.channels.empty() ? std::vector<std::string>{"A", "B", "A+B"} : layout.channels;
  const bool thirdIsSum =
      img.planes.size() > 2 && ch != img.strings.end() && ch->second.find("B=A+B") != std::string::npos;
  TableImage out = img;
  const int w = img.width, h = img.height;
  out.width = layout.rAlongX ? h : w;
  out.height = layout.rAlongX ? w : h;
  out.channels.assign(kTableChannels, kTableChannels + chans.size());
  out.planes.assign(chans.size(), std::vector<float>(static_cast<size_t>(w) * h));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const int sx = layout.flipX ? out.width - 1 - x : x, sy = layout.flipY ? out.height - 1 - y : y;
      const int mu = layout.rAlongX ? sy : sx, r = layout.rAlongX ? sx : sy;  // source texel
      const size_t src = static_cast<size_t>(r) * w + mu, dst = static_cast<size_t>(y) * out.width + x;
      const float a = img.planes[0][src], b = img.planes[1][src];
      for (size_t c = 0; c < chans.size(); ++c)
        out.planes[c][dst] = chans[c] == "A" ? a : chans[c] == "B" ? b : thirdIsSum ? img.planes[2][src] : a + b;
    }
  std::string stored;
  for (size_t c = 0; c < chans.size(); ++c) stored += (c ? "," : "") + chans[c];
  out.strings["brdf.axes"] = layout.rAlongX ? "r,mu" : "mu,r";
  out.strings["brdf.channels"] = "";
  for (size_t c = 0; c < chans.size(); ++c)
    out.strings["brdf.channels"] += std::string(c ? "," : "") + "RGB"[c] + "=" + chans[c];
  out.strings["brdf.layout.channels"] = stored;
  out.strings["brdf.layout.flip"] = layout.flipX && layout.flipY ? "x,y"
                                    : layout.flipX               ? "x"
                                    : layout.flipY               ? "y"
                                                                 : "none";
  return out;
}

}  // namespace brdfbake
