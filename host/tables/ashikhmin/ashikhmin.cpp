// The Ashikhmin-Shirley family (--table ashikhmin-shirley): the three factorised textures of the
// anisotropic Ashikhmin-Shirley BRDF, closed forms on the host (tables/ashikhmin/ashikhmin_textures.h), one file
// each.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "tables/ashikhmin/ashikhmin_textures.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "tables/family.h"
#include "tables/registry.h"
#include "tables/ladder.h"

namespace brdfbake {

namespace {

class Ashikhmin final : public TableFamily {
 public:
  std::string name() const override { return "ashikhmin-shirley"; }
  std::vector<KindInfo> describe() const override {
    KindInfo k{TableKind::AshikhminShirley, "ashikhmin-shirley"};
    k.defaultSize = 128;
    k.shader = ShaderLookup::OwnShader;
    return {k};
  }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (!req.merl.empty() || !req.preset.empty()) return {};
    if (std::find(req.tables.begin(), req.tables.end(), TableKind::AshikhminShirley) == req.tables.end()) return {};
    if (req.fresnel)
      throw Error(kExitUsage, "--fresnel " + fresnelNames()[req.fresnel->model] +
                                  ": --table ashikhmin-shirley holds Schlick's F split as R_s R + G (R_s enters in "
                                  "the shader); bake it without --fresnel");
    int n = req.size ? *req.size : brdfbake::defaultSize(TableKind::AshikhminShirley);
    checkAshikhminRequest(n, storesHalf(req), req.nodeGrid);
    if (req.diffuse >= 0)
      throw Error(kExitUsage, "--diffuse " + diffuseNames()[req.diffuse] +
                                  ": --table ashikhmin-shirley has its own diffuse texture (Tex0); bake it "
                                  "without --diffuse");
    std::vector<Job> jobs;
    for (int t = 0; t < kAsTextures; ++t) {
      TableJob job = TableJob::of(TableKind::AshikhminShirley).texels(n, n).storingHalf(storesHalf(req));
      job.texture = t;
      job.path = req.outDir + "/" + ashikhminFileName(t);
      applyFormats(req, job);
      jobs.push_back(makeJob(this, job.kind, job));
    }
    return jobs;
  }

  BakedTable compute(BakeContext&, const Job& job) const override {
    const TableJob j = job.get<TableJob>();
    auto t0 = std::chrono::steady_clock::now();
    BakedTable t;
    t.image = ashikhminTexture(j.texture, j.width, j.half);
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return t;
  }

  // Resolution: the three textures at N = 16 2^L texels per axis (levels L), each looked up
  // bilinearly at 1024 points of the (2, 3) Halton sequence against the formulas as printed (long
  // double), relative to max(1, |v|). Points in [1/16, 1]^2, where every grid of the ladder has
  // texels (Tex1's upper-node grid starts at 1/N).
  Ladder convergence(BakeContext&, const BakeRequest& req, TableKind, const LadderBudgets& budgets) const override {
    if (!req.ndfs.empty() && req.ndfs.size() != 1)
      throw Error(kExitUsage, "--ndf: ashikhmin-shirley has its own model");
    const int points = 1024;
    auto radical = [](int i, int b) {
      double f = 1, r = 0;
      for (; i > 0; i /= b) f /= b, r += f * (i % b);
      return r;
    };
    std::vector<std::array<double, 2>> pts;
    for (int k = 1; k <= points; ++k) pts.push_back({0.0625 + 0.9375 * radical(k, 2), 0.0625 + 0.9375 * radical(k, 3)});
    std::vector<double> ref;
    for (int t = 0; t < kAsTextures; ++t)
      for (int c = 0; c < (t == 1 ? 3 : 1); ++c)
        for (const auto& p : pts) ref.push_back(ashikhminExact(t, c, p[0], p[1]));
    Ladder L;
    L.table = "ashikhmin-shirley Tex0, Tex1 (R, G, B), Tex2: bilinear lookups at " + std::to_string(points) +
              " points of [1/16, 1]^2";
    std::vector<double> prev;
    for (int level : budgets.levels) {
      const int n = 16 << level;
      std::vector<double> v;
      double secs = ladder::now();
      for (int t = 0; t < kAsTextures; ++t) {
        TableImage img = ashikhminTexture(t, n, false);
        for (int c = 0; c < (t == 1 ? 3 : 1); ++c)
          for (const auto& p : pts) {
            // grid coordinate: nodes i/(n-1), or Tex1's (i+1)/n
            double gx = ashikhminNodeGrid(t) ? p[0] * (n - 1) : p[0] * n - 1;
            double gy = ashikhminNodeGrid(t) ? p[1] * (n - 1) : p[1] * n - 1;
            int x0 = std::clamp(static_cast<int>(std::floor(gx)), 0, n - 2),
                y0 = std::clamp(static_cast<int>(std::floor(gy)), 0, n - 2);
            double fx = gx - x0, fy = gy - y0;
            auto at = [&](int x, int y) { return static_cast<double>(img.planes[c][static_cast<size_t>(y) * n + x]); };
            v.push_back((1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
                        fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1)));
          }
      }
      secs = ladder::now() - secs;
      const std::vector<double> e = ladder::changeFrom(prev, v);
      prev = v;
      L.rungs.push_back(
          ladder::rung("bilinear lookup (float texels)", std::to_string(n) + " texels per axis", secs, v, e, ref));
    }
    L.note =
        "The reference: the seed's formulas as printed, in long double (tables/ashikhmin/ashikhmin_textures.cpp); a "
        "rung's "
        "estimate is its change from the previous rung\n";
    return L;
  }

  // The textures' edges, where the formulas are stiffest: Tex1's corner texel (1/(u v) = n^2), Tex2
  // at u = 1 (its limit exp(-v^2/2)) and at the v axis' ends, Tex0 at the origin; the stored float
  // against the formulas as printed in long double.
  void stress(BakeContext&, std::vector<StressPoint>& out) const override {
    const int n = 128;
    struct Case {
      int t, c, i, j;
      const char* limit;
    };
    const Case cases[] = {{0, 0, 0, 0, "Tex0(0, 0) = 0"},
                          {1, 2, 0, 0, "Tex1 B(1/n, 1/n) = n^2"},
                          {1, 0, 0, n - 1, ""},
                          {2, 0, n - 1, 0, "Tex2(1, v) = exp(-v^2/2)"},
                          {2, 0, n - 1, n / 2, "Tex2(1, 0) = 1"},
                          {2, 0, n - 2, n - 1, ""}};
    for (const Case& k : cases) {
      TableImage img = ashikhminTexture(k.t, n, false);
      const double u = ashikhminCoord(k.t, k.i, n), y = ashikhminCoord(k.t, k.j, n);
      StressPoint p = stressPoint("ashikhmin-shirley Tex" + std::to_string(k.t) + " edges",
                                  "u=" + fmt4(u) + " y=" + fmt4(y) + " channel " + std::string(1, "RGB"[k.c]),
                                  img.planes[k.c][static_cast<size_t>(k.j) * n + k.i], ashikhminExact(k.t, k.c, u, y),
                                  img.floats.at("brdf.error"));
      if (*k.limit) {
        const double v = k.t == 2 ? kAsTex2Scale * (y - kAsTex2Offset) : y;
        const double want = k.t == 0 ? 0.0 : k.t == 1 ? 1.0 / (u * y) : std::exp(-v * v / 2);
        p.limit = k.limit;
        p.limitMet = p.finite && ladder::rel(p.value, want) <= 1e-6;
      }
      out.push_back(p);
    }
  }

  std::string key(const Job& job) const override { return tableJobKey(job.get<TableJob>()); }
  JobSummary summary(const Job& job) const override { return tableJobSummary(job.get<TableJob>()); }
};

}  // namespace

const TableFamily& ashikhminFamily() {
  static const Ashikhmin family;
  return family;
}

}  // namespace brdfbake
