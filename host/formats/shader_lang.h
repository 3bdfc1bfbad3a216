// What generated lookup code shares (shader/shader_gen.cpp, shader/atlas_lookups.cpp, and the families
// that write lookups of their own, tables/kind_info.h ShaderCode):
// the words GLSL and HLSL spell apart, float literals, header attributes.
#pragma once
#include <string>

#include "common/format.h"
#include "formats/table_image.h"

namespace brdfbake::shadergen {

// The few words GLSL (ES 3.00 / 3.30 and later) and HLSL (shader model 4 and later) spell apart.
struct Lang {
  bool hlsl;
  std::string f2() const { return hlsl ? "float2" : "vec2"; }
  std::string f3() const { return hlsl ? "float3" : "vec3"; }
  std::string f4() const { return hlsl ? "float4" : "vec4"; }
  std::string i2() const { return hlsl ? "int2" : "ivec2"; }
  std::string mix() const { return hlsl ? "lerp" : "mix"; }
  std::string cst() const { return hlsl ? "static const" : "const"; }
  std::string texParam() const { return hlsl ? "Texture2D<float4> tex, SamplerState smp" : "sampler2D tex"; }
  std::string texArgs() const { return hlsl ? "tex, smp" : "tex"; }
  std::string sample(const std::string& uv) const {
    return hlsl ? "tex.SampleLevel(smp, " + uv + ", 0.0)" : "textureLod(tex, " + uv + ", 0.0)";
  }
  std::string fetch(const std::string& ij) const {
    return hlsl ? "tex.Load(int3(" + ij + ", 0))" : "texelFetch(tex, " + ij + ", 0)";
  }
};

inline std::string lit(double v) {
  std::string s = fmtG9(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

inline std::string attr(const TableImage& h, const std::string& k, const std::string& fallback = "") {
  auto it = h.strings.find(k);
  return it == h.strings.end() ? fallback : it->second;
}

}  // namespace brdfbake::shadergen
