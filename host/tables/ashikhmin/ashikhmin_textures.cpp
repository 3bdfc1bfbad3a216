#include "tables/ashikhmin/ashikhmin_textures.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "version.h"

namespace brdfbake {

namespace {

// Half's largest finite value: Tex1's corner texel, 1/(u v) = n^2, must stay below it.
constexpr double kHalfMax = 65504.0;
constexpr int kHalfMaxSize = 255;  // 255^2 = 65025; 256^2 = 65536 > 65504

// The exact value of texture `t`'s channel `c` at (u, v) from the seed's formulas as printed (the
// naive power for Tex2, 1 - u^2 factored so that it is exact; u = 1, a node, takes the limit exp(-v^2/2)).
long double exactValue(int t, int c, long double u, long double v) {
  if (t == 0) return (1 - std::pow(1 - u / 2, 5.0L)) * (1 - std::pow(1 - v / 2, 5.0L));
  if (t == 1) {
    long double w = std::pow(1 - u, 5.0L);
    return (c == 0 ? 1 - w : c == 1 ? w : 1.0L) / (u * v);
  }
  return u == 1 ? std::exp(-v * v / 2) : std::pow(u, v * v / ((1 - u) * (1 + u)));
}

double value(int t, int c, double u, double v) {
  if (t == 0) return brdf64::as_tex0(u, v);
  if (t == 1) return c == 0 ? brdf64::as_tex1_rs(u, v) : c == 1 ? brdf64::as_tex1_one(u, v) : 1.0 / (u * v);
  return brdf64::as_tex2(u, v);
}

const char* const kFormula[kAsTextures] = {
    "Tex0(u,v) = (1-(1-u/2)^5)(1-(1-v/2)^5), u = n.l, v = n.v; rho_d = 28/(23 pi) R_d (1-R_s) Tex0 "
    "(Ashikhmin and Shirley 2000, eq. 5)",
    "Tex1(u,v) = F(u)/(u v), F(u) = R_s + (1-R_s)(1-u)^5 (Schlick), so Tex1 = R_s R + G; u = h.l, "
    "v = max(n.l, n.v) (Ashikhmin and Shirley 2000, eq. 4)",
    "Tex2(u,v) = u^(v^2/(1-u^2)) = exp(v^2 log(u)/((1-u)(1+u))), Tex2(1,v) = exp(-v^2/2); u = n.h, "
    "v = scale (t - offset) with t = sqrt(n_u) h.x/scale + offset (or n_v, h.y); rho_s = sqrt((n_u+1)(n_v+1))/(8 pi) "
    "Tex1(h.l, max(n.l,n.v)) Tex2(n.h, sqrt(n_u) h.x) Tex2(n.h, sqrt(n_v) h.y) (Ashikhmin and Shirley 2000, eq. 4)"};
const char* const kAxes[kAsTextures] = {"n.l,n.v", "h.l,max(n.l,n.v)", "n.h,t"};
const char* const kChannels[kAsTextures] = {
    "R=G=B=Tex0", "R=(1-(1-u)^5)/(u v),G=(1-u)^5/(u v),B=1/(u v) (Tex1 = R_s R + G; B = R + G, Tex1 at R_s = 1)",
    "R=G=B=Tex2"};

}  // namespace

double ashikhminExact(int t, int c, double u, double y) {
  double v = t == 2 ? kAsTex2Scale * (y - kAsTex2Offset) : y;
  return static_cast<double>(exactValue(t, c, u, v));
}

bool ashikhminNodeGrid(int texture) { return texture != 1; }
double ashikhminCoord(int texture, int i, int n) { return texture != 1 ? i / (n - 1.0) : (i + 1.0) / n; }

std::string ashikhminFileName(int texture) { return "as_tex" + std::to_string(texture) + ".exr"; }

void checkAshikhminRequest(int size, bool half, bool nodeGrid) {
  if (nodeGrid)
    throw Error(kExitUsage,
                "--grid node: --table ashikhmin-shirley sets its own grids (Tex0 and Tex2 node, so that "
                "u = 1 holds Tex2's limit; Tex1 upper-node, (i+1)/n, as it is infinite at u = 0 and v = 0); "
                "bake it without --grid");
  if (size < 2)
    throw Error(kExitUsage,
                "--size must be an integer in 2..8192 for --table ashikhmin-shirley, got " + std::to_string(size));
  if (half && size > kHalfMaxSize)
    throw Error(kExitUsage, "--size must be an integer in 2.." + std::to_string(kHalfMaxSize) +
                                " for --table ashikhmin-shirley with --half (Tex1 = F/(u v) reaches n^2 at the corner "
                                "texel, above half's 65504 from 256), got " +
                                std::to_string(size));
}

TableImage ashikhminTexture(int t, int n, bool half) {
  TableImage img;
  img.width = img.height = n;
  img.channels = {"R", "G", "B"};
  const int planes = t == 1 ? 3 : 1;
  const bool node = ashikhminNodeGrid(t);  // else Tex1's upper-node grid
  std::vector<std::vector<float>> p(planes, std::vector<float>(static_cast<size_t>(n) * n));
  double worst = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      // Tex0 and Tex2 at nodes i/(n-1), Tex1 at (i+1)/n; Tex2's y is t, its argument v = scale (t - offset)
      double u = ashikhminCoord(t, i, n), y = ashikhminCoord(t, j, n);
      double v = t == 2 ? kAsTex2Scale * (y - kAsTex2Offset) : y;
      for (int c = 0; c < planes; ++c) {
        double x = value(t, c, u, v);
        float f = static_cast<float>(x);
        if (!std::isfinite(f) || (half && std::fabs(x) > kHalfMax))
          throw Error(kExitSoftware, "internal error: ashikhmin-shirley Tex" + std::to_string(t) + " texel (" +
                                         std::to_string(i) + ", " + std::to_string(j) + ") is not finite" +
                                         (half ? " in half" : "") + "; nothing was written");
        double stored = half ? static_cast<double>(static_cast<float>(Imath::half(f))) : static_cast<double>(f);
        long double exact = exactValue(t, c, u, v);
        double err = static_cast<double>(std::fabs(stored - exact) / std::max(1.0L, std::fabs(exact)));
        worst = std::max(worst, err);
        p[c][static_cast<size_t>(j) * n + i] = f;
      }
    }
  }
  img.planes = planes == 3 ? p : std::vector<std::vector<float>>{p[0], p[0], p[0]};

  img.strings["brdf.schema"] = "brdfbake/1";
  img.strings["brdf.table"] = "ashikhmin-shirley";
  img.strings["brdf.texture"] = "tex" + std::to_string(t);
  img.strings["brdf.formula"] = kFormula[t];
  img.strings["brdf.axes"] = kAxes[t];
  img.strings["brdf.grid"] = node ? "node" : "upper-node";
  img.strings["brdf.channels"] = kChannels[t];
  img.v2f["brdf.u.range"] = {0.0f, 1.0f};
  if (t == 2) {
    // the value mapping of Tex2's y axis (seed 001): v = scale (t - offset)
    img.floats["brdf.scale"] = static_cast<float>(kAsTex2Scale);
    img.floats["brdf.offset"] = static_cast<float>(kAsTex2Offset);
    img.v2f["brdf.v.range"] = {static_cast<float>(-kAsTex2Scale * kAsTex2Offset),
                               static_cast<float>(kAsTex2Scale * (1 - kAsTex2Offset))};
    img.strings["brdf.lookup"] = "texture(tex2, (0.5 + (n-1) vec2(n.h, sqrt(n_u) h.x/" + fmtG(kAsTex2Scale) + " + " +
                                 fmtG(kAsTex2Offset) + "))/n).r";
  } else {
    img.v2f["brdf.v.range"] = {0.0f, 1.0f};
    img.strings["brdf.lookup"] = t == 0 ? "texture(tex0, (0.5 + (n-1) vec2(n.l, n.v))/n).r"
                                        : "dot(texture(tex1, vec2(h.l, max(n.l, n.v)) - 0.5/n).rg, vec2(R_s, 1))";
  }
  img.strings["brdf.method"] =
      "closed form in double (kernels/brdf/anisotropic.h), Tex2 without the seed's switch-over "
      "at u > 1-1/256, Tex1 without its epsilon; error: the largest difference of a stored "
      "value from the formula in long double, relative to max(1,|value|)";
  img.strings["brdf.generator"] = std::string("brdfbake ") + BRDFBAKE_VERSION + " (git " + BRDFBAKE_GIT_REV + ")";
  img.floats["brdf.error"] = static_cast<float>(worst);
  return img;
}

}  // namespace brdfbake
