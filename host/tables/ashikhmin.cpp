// The Ashikhmin-Shirley family (--table ashikhmin-shirley): the three factorised textures of the
// anisotropic Ashikhmin-Shirley BRDF, closed forms on the host (bake/ashikhmin_textures.h), one file
// each.
#include <chrono>

#include "bake/ashikhmin_textures.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "tables/family.h"

namespace brdfbake {

namespace {

class Ashikhmin final : public TableFamily {
 public:
  std::string name() const override { return "ashikhmin-shirley"; }
  std::vector<TableKind> kinds() const override { return {TableKind::AshikhminShirley}; }
  int defaultSize(TableKind) const override { return 128; }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (!req.merl.empty() || !req.preset.empty()) return {};
    if (std::find(req.tables.begin(), req.tables.end(), TableKind::AshikhminShirley) == req.tables.end()) return {};
    if (req.fresnelGiven)
      throw Error(kExitUsage, "--fresnel " + fresnelNames()[req.fresnel.model] +
                                  ": --table ashikhmin-shirley holds Schlick's F split as R_s R + G (R_s enters in "
                                  "the shader); bake it without --fresnel");
    int n = req.size ? *req.size : defaultSize(TableKind::AshikhminShirley);
    checkAshikhminRequest(n, req.half, req.nodeGrid);
    if (req.diffuse >= 0)
      throw Error(kExitUsage, "--diffuse " + diffuseNames()[req.diffuse] +
                                  ": --table ashikhmin-shirley has its own diffuse texture (Tex0); bake it "
                                  "without --diffuse");
    std::vector<Job> jobs;
    for (int t = 0; t < kAsTextures; ++t) {
      TableJob job{TableKind::AshikhminShirley, -1, -1, n, n, false, req.half, "", {}, -1, t};
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

  std::string key(const Job& job) const override { return tableJobKey(job.get<TableJob>()); }
  JobSummary summary(const Job& job) const override { return tableJobSummary(job.get<TableJob>()); }
};

}  // namespace

const TableFamily& ashikhminFamily() {
  static const Ashikhmin family;
  return family;
}

}  // namespace brdfbake
