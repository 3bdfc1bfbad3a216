// The brdf3d family (--table brdf3d): f of one material over three angles, (theta_i, theta_o,
// phi) or Rusinkiewicz's (theta_h, theta_d, phi_d), as an EXR atlas of z-slices, 3D KTX2/DDS
// textures, a header, or MERL's binary layout. Baked slab by slab while the files are written, so
// a table is never whole in memory (tables/volume.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <tuple>

#include "formats/format_outputs.h"
#include "tables/volume.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "tables/brdf3d/brdf3d.h"
#include "tables/family.h"
#include "tables/ladder.h"

namespace brdfbake {

std::string volumeFileName(const VolumeJob& job) {
  const Brdf3dSpec& s = job.spec;
  std::string name = "brdf3d_" + ndfNames()[s.ndf] + "_" + gafNames()[s.gaf];
  if (!s.fresnel.isOne()) name += "_" + fresnelNames()[s.fresnel.model];
  if (s.diffuse >= 0) name += "_" + diffuseNames()[s.diffuse];
  if (job.merl) return name + ".binary";
  return name + (s.param == Brdf3dParam::Angles ? "_angles" : "_rusinkiewicz") + ".exr";
}

std::pair<int, int> atlasGrid(int depth) {
  for (int rows = static_cast<int>(std::sqrt(static_cast<double>(depth))); rows >= 1; --rows) {
    if (depth % rows != 0) continue;
    int cols = depth / rows;
    if (cols <= 4 * rows) return {cols, rows};
    break;
  }
  int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(depth))));
  return {cols, (depth + cols - 1) / cols};
}

namespace {

std::string vec(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ",") + fmtG9(x);
  return s;
}

// The brdf3d jobs of a request: one per NDF/GAF pair.
std::vector<Job> planVolumes(const TableFamily* family, const BakeRequest& req) {
  std::vector<Job> jobs;
  const auto& v = req.volume;
  for (int ndf : req.ndfs) {
    for (int gaf : req.gafs) {
      VolumeJob job;
      Brdf3dSpec& s = job.spec;
      s.ndf = ndf;
      s.gaf = gaf;
      s.roughness = v.roughness;
      s.fresnel = fresnelOf(req);
      s.diffuse = req.diffuse;
      s.rho = v.rho;
      // the diffuse model's own parameter: F0 (the Shirley forms: the specular's, else 0.04),
      // sigma (oren-nayar, --sigma, default 0.5) or the specular's roughness (burley)
      if (req.diffuse == DIFFUSE_OREN_NAYAR || req.diffuse == DIFFUSE_OREN_NAYAR_AS_PRINTED)
        s.diffuseParam = req.sigma ? *req.sigma : 0.5;
      else if (req.diffuse == DIFFUSE_BURLEY)
        s.diffuseParam = v.roughness;
      else
        s.diffuseParam = fresnelOf(req).f0.empty() ? DIFFUSE_DEFAULT_F0 : fresnelOf(req).f0[0];
      s.param = v.param;
      s.thetaHSqrt = v.thetaHSqrt;
      s.timesCos = v.timesCos;
      job.merl = v.merl;
      job.half = storesHalf(req);
      if (v.merl) {
        s.grid = Brdf3dGrid::CellStart;
        s.nx = 90;
        s.ny = 90;
        s.nz = 180;
      } else {
        s.grid = req.nodeGrid ? Brdf3dGrid::Node : Brdf3dGrid::TexelCenter;
        if (req.size && *req.size > kMaxVolumeSize)
          throw Error(kExitUsage, "--size: each axis of a brdf3d table must be an integer in 1.." +
                                      std::to_string(kMaxVolumeSize) + ", got " + std::to_string(*req.size));
        std::array<int, 3> n =
            v.size
                ? *v.size
                : std::array<int, 3>{{req.size ? *req.size : 32, req.size ? *req.size : 32, req.size ? *req.size : 32}};
        if (req.nodeGrid && std::min({n[0], n[1], n[2]}) < 2)
          throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
        s.nx = n[0];
        s.ny = n[1];
        s.nz = n[2];
        std::tie(job.cols, job.rows) = v.atlas ? *v.atlas : atlasGrid(s.nz);
        if (static_cast<long>(job.cols) * job.rows < s.nz)
          throw Error(kExitUsage, "--atlas " + std::to_string(job.cols) + "x" + std::to_string(job.rows) + " holds " +
                                      std::to_string(job.cols * job.rows) + " slices, fewer than the table's " +
                                      std::to_string(s.nz));
        if (static_cast<long>(job.cols) * s.nx > 65536 || static_cast<long>(job.rows) * s.ny > 65536)
          throw Error(kExitUsage, "--atlas: the atlas would be " + std::to_string(static_cast<long>(job.cols) * s.nx) +
                                      "x" + std::to_string(static_cast<long>(job.rows) * s.ny) +
                                      " texels; at most 65536 per side (choose fewer columns or rows)");
      }
      job.path = req.outDir + "/" + volumeFileName(job);
      if (!v.merl) {
        job.formats = req.formats.empty() ? std::vector<FileFormat>{FileFormat::Exr} : req.formats;
        job.precision = req.precision.value_or(Precision::Float32);
      }
      jobs.push_back(makeJob(family, TableKind::Brdf3d, job));
    }
  }
  return jobs;
}

class Brdf3d final : public TableFamily {
 public:
  std::string name() const override { return "brdf3d"; }
  std::vector<KindInfo> describe() const override {
    KindInfo k{TableKind::Brdf3d, "brdf3d"};
    k.sizeAxes = 3;
    k.volume = true;
    k.sceneUses = kUseWholeMaterial;
    k.shader = ShaderLookup::Volume;
    k.inScenes = true;
    return {k};
  }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (!req.merl.empty() || !req.preset.empty()) return {};
    if (std::find(req.tables.begin(), req.tables.end(), TableKind::Brdf3d) == req.tables.end()) return {};
    return planVolumes(this, req);
  }

  std::vector<KernelNeed> kernels(const Job& job) const override {
    const VolumeJob& v = job.get<VolumeJob>();
    return {brdf3dKernel(v.spec.ndf, v.spec.gaf)};
  }

  void preflight(BakeContext&, const std::string& outDir, const std::vector<const Job*>& jobs) const override {
    std::vector<VolumeJob> volumes;
    for (const Job* j : jobs) volumes.push_back(j->get<VolumeJob>());
    checkVolumeSpace(outDir, volumes);
  }

  // The whole table in memory (the library's bake()): the header and every slice.
  BakedTable compute(BakeContext& ctx, const Job& job) const override {
    const VolumeJob v = job.get<VolumeJob>();
    BakedTable t;
    t.image = volumeHeader(v);
    auto t0 = std::chrono::steady_clock::now();
    t.volume = brdf3dSlab(ctx.runner(), v.spec, 0, v.spec.nz);
    if (t.volume.size() == 1) t.volume = {t.volume[0], t.volume[0], t.volume[0]};  // R=G=B tables
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    t.depth = v.spec.nz;
    return t;
  }

  // A table compute() made: its EXR atlas, written from memory (the library's write()). The
  // other formats stream from the device (addFiles, bakeToDirectory).
  void addBakedFiles(const Job& job, BakedTable& baked, FileSet& set) const override {
    const VolumeJob v = job.get<VolumeJob>();
    for (FileFormat f : v.formats)
      if (v.merl || f != FileFormat::Exr)
        throw Error(kExitUsage, "write: " + v.path +
                                    ": a brdf3d table held in memory is written as its EXR atlas; "
                                    "for ktx2, dds, header or merl, bakeToDirectory streams it from the device");
    TableReport r;
    r.path = v.path;
    r.table = "brdf3d";
    r.ndf = ndfNames()[v.spec.ndf];
    r.gaf = gafNames()[v.spec.gaf];
    r.width = v.spec.nx;
    r.height = v.spec.ny;
    r.depth = v.spec.nz;
    r.seconds = baked.seconds;
    r.errorBound = baked.image.floats["brdf.error"];
    set.reports.push_back(r);
    const BakedTable* t = &baked;
    OutputFile o;
    o.path = v.path;
    o.write = [t, v](const std::string& tmp) {
      const size_t slice = static_cast<size_t>(v.spec.nx) * v.spec.ny;
      auto slab = [t, slice](int z0, int zn) {
        std::vector<std::vector<float>> p(t->volume.size());
        for (size_t c = 0; c < p.size(); ++c)
          p[c].assign(t->volume[c].begin() + static_cast<std::ptrdiff_t>(z0 * slice),
                      t->volume[c].begin() + static_cast<std::ptrdiff_t>((z0 + zn) * slice));
        return p;
      };
      writeAtlasTemporary(tmp, v.path, t->image, v.half, {v.spec.nx, v.spec.ny, v.spec.nz}, v.cols, slab,
                          "brdf3d " + ndfNames()[v.spec.ndf] + "+" + gafNames()[v.spec.gaf]);
    };
    set.files.push_back(std::move(o));
  }

  // Streamed: each file bakes its slabs while the set writes it; the kernel time reaches the
  // report lines once the set has landed.
  void addFiles(BakeContext& ctx, const Job& job, FileSet& set) const override {
    const VolumeJob v = job.get<VolumeJob>();
    TableImage& header = set.keep.emplace_back(volumeHeader(v));
    auto it = set.extraStrings.find(job.path);
    if (it != set.extraStrings.end())
      for (const auto& [k, val] : it->second) header.strings[k] = val;
    TableReport r;
    r.table = v.merl ? "brdf3d (merl)" : "brdf3d";
    r.ndf = ndfNames()[v.spec.ndf];
    r.gaf = gafNames()[v.spec.gaf];
    r.width = v.spec.nx;
    r.height = v.spec.ny;
    r.depth = v.spec.nz;
    auto secs = std::make_shared<double>(0.0);
    const size_t first = set.reports.size();
    const bool exr = v.merl || std::find(v.formats.begin(), v.formats.end(), FileFormat::Exr) != v.formats.end();
    if (exr) {
      r.path = v.path;
      r.errorBound = header.floats["brdf.error"];
      set.files.push_back(volumeOutput(ctx.runner(), v, header, secs.get()));
      set.reports.push_back(r);
    }
    for (PlannedFile& pf : volumeFormatOutputs(ctx.runner(), v, header, secs.get())) {
      r.path = pf.file.path;
      r.errorBound = pf.errorBound;
      set.files.push_back(std::move(pf.file));
      set.reports.push_back(r);
    }
    const size_t last = set.reports.size();
    set.afterCommit.push_back([&set, secs, first, last] {
      for (size_t k = first; k < last; ++k) set.reports[k].seconds = *secs;
    });
  }

  // Resolution: the table at N = 8 2^L texels per axis (levels L) baked on the device, looked up
  // trilinearly at 2048 points of the (7, 11, 13) Halton sequence over the axes' ranges against f
  // evaluated in double on the host (the BRDF itself: nothing is integrated), relative to
  // max(1, |f|); the estimate is what the file claims (brdf.interp-error + brdf.error).
  Ladder convergence(BakeContext& ctx, const BakeRequest& req, TableKind, const LadderBudgets& budgets) const override {
    if (req.ndfs.size() != 1 || req.gafs.size() != 1)
      throw Error(kExitUsage, "convergence measures one pair: give one --ndf and one --gaf");
    auto radical = [](int i, int b) {
      double f = 1, r = 0;
      for (; i > 0; i /= b) f /= b, r += f * (i % b);
      return r;
    };
    Ladder L;
    std::vector<double> prev;
    for (int level : budgets.levels) {
      BakeRequest r = req;
      r.size = 8 << level;
      r.volume.size.reset();
      r.volume.atlas.reset();
      r.volume.merl = false;
      const VolumeJob v = planVolumes(this, r).front().get<VolumeJob>();
      const Brdf3dSpec& s = v.spec;
      if (L.table.empty())
        L.table = "brdf3d of " + ndfNames()[s.ndf] + "+" + gafNames()[s.gaf] + ", r " + fmtG(s.roughness) + ", " +
                  (s.param == Brdf3dParam::Angles ? "angles" : "rusinkiewicz") + ": trilinear lookups at 2048 points";
      KernelRunner& kr = ctx.runner();
      kr.prepare(brdf3dKernel(s.ndf, s.gaf));
      std::vector<std::vector<float>> planes;
      double secs = ladder::best3([&] { planes = brdf3dSlab(kr, s, 0, s.nz); });
      const auto ax = s.axes();
      std::vector<double> val, ref, est;
      const TableImage header = volumeHeader(v);
      const double claim = header.floats.at("brdf.interp-error") + header.floats.at("brdf.error");
      for (int k = 1; k <= 2048; ++k) {
        double t[3] = {radical(k, 7), radical(k, 11), radical(k, 13)};
        glm::dvec3 ang, idx;
        for (int a = 0; a < 3; ++a) {
          ang[a] = ax[a].hi * (a == 0 && s.param == Brdf3dParam::Rusinkiewicz && s.thetaHSqrt ? t[a] * t[a] : t[a]);
          idx[a] = texelIndex(s, a, ang[a]);
        }
        Directions d =
            s.param == Brdf3dParam::Angles ? fromAngles(ang.x, ang.y, ang.z) : fromRusinkiewicz(ang.x, ang.y, ang.z);
        val.push_back(trilinear(s, planes[0], idx));
        ref.push_back(hostBrdf(s, d, 0));
        est.push_back(claim);
      }
      L.rungs.push_back(ladder::rung("trilinear lookup (device table)", std::to_string(s.nx) + " texels per axis", secs,
                                     val, est, ref));
    }
    L.note =
        "The reference: f itself, evaluated in double on the host (common/brdf3d_grid.h hostBrdf); a rung's "
        "estimate is the file's claim, brdf.interp-error (measured at 4096 other points) + brdf.error\n";
    return L;
  }

  // Grazing and nearly smooth: a node grid of 3 per axis (theta 0, 45 and 90 degrees, phi 0, 90
  // and 180) at r 0.01 and 1, the device's f at the texels where a direction grazes against f in
  // double on the host, and reciprocity f(i, o) = f(o, i) as the limit.
  void stress(BakeContext& ctx, std::vector<StressPoint>& out) const override {
    for (double rough : {kMinVolumeRoughness, 1.0}) {
      BakeRequest r = defaultRequest();
      r.tables = {TableKind::Brdf3d};
      r.size = 3;
      r.nodeGrid = true;
      r.volume.roughness = rough;
      const VolumeJob v = planVolumes(this, r).front().get<VolumeJob>();
      const Brdf3dSpec& s = v.spec;
      KernelRunner& kr = ctx.runner();
      kr.prepare(brdf3dKernel(s.ndf, s.gaf));
      const std::vector<float> f = brdf3dSlab(kr, s, 0, s.nz).front();
      auto at = [&](int x, int y, int z) {
        return static_cast<double>(f[(static_cast<size_t>(z) * s.ny + y) * s.nx + x]);
      };
      const int texels[][3] = {{2, 1, 0}, {1, 2, 1}, {2, 2, 0}, {2, 2, 2}, {0, 2, 1}};
      for (const auto& t : texels) {
        glm::dvec3 ang = texelAngles(s, t[0], t[1], t[2]);
        StressPoint p = stressPoint("brdf3d grazing, r " + fmtG(rough),
                                    "theta_i=" + fmt4(ang.x * 180 / M_PI) + " theta_o=" + fmt4(ang.y * 180 / M_PI) +
                                        " phi=" + fmt4(ang.z * 180 / M_PI),
                                    at(t[0], t[1], t[2]), hostBrdf(s, texelDirections(s, t[0], t[1], t[2]), 0),
                                    volumeHeader(v).floats.at("brdf.error"));
        p.limit = "f(i, o) = f(o, i)";
        p.limitMet = p.finite && ladder::rel(p.value, at(t[1], t[0], t[2])) <= 1e-6;
        out.push_back(p);
      }
    }
  }

  std::string key(const Job& job) const override {
    const VolumeJob v = job.get<VolumeJob>();
    const Brdf3dSpec& s = v.spec;
    return "table=brdf3d;ndf=" + std::to_string(s.ndf) + ";gaf=" + std::to_string(s.gaf) + ";r=" + fmtG9(s.roughness) +
           ";fresnel=" + s.fresnel.describe() + ";diffuse=" + std::to_string(s.diffuse) +
           ";dparam=" + fmtG9(s.diffuseParam) + ";rho=" + vec(s.rho) + ";param=" + std::to_string(s.kernelParam()) +
           ";grid=" + std::to_string(s.kernelGrid()) + ";cos=" + (s.timesCos ? "1" : "0") +
           ";size=" + std::to_string(s.nx) + "x" + std::to_string(s.ny) + "x" + std::to_string(s.nz) +
           ";atlas=" + std::to_string(v.cols) + "x" + std::to_string(v.rows) + ";half=" + (v.half ? "1" : "0") +
           ";merl=" + (v.merl ? "1" : "0");
  }

  JobSummary summary(const Job& job) const override {
    const VolumeJob v = job.get<VolumeJob>();
    JobSummary s;
    s.table = "brdf3d";
    s.models = ndfNames()[v.spec.ndf] + " + " + gafNames()[v.spec.gaf] + ", r " + fmtG(v.spec.roughness);
    s.size = std::to_string(v.spec.nx) + "x" + std::to_string(v.spec.ny) + "x" + std::to_string(v.spec.nz);
    s.texels = static_cast<double>(v.spec.nx) * v.spec.ny * v.spec.nz;
    s.cost = s.texels * 1.5e-7;
    return s;
  }
};

}  // namespace

const TableFamily& brdf3dFamily() {
  static const Brdf3d family;
  return family;
}

}  // namespace brdfbake
