#include "tables/volume.h"

#include <chrono>

#include "formats/format_outputs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cl/runner.h"
#include "tables/brdf3d/brdf3d.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/models.h"
#include "formats/exr/table_file.h"
#include "formats/merl.h"
#include "formats/output_set.h"
#include "version.h"

namespace brdfbake {

namespace {

constexpr double kRadToDeg = 57.295779513082320876798;

// The float evaluation's error relative to max(1, |f|), measured against the host's double
// evaluation over every texel of the tests' tables (tests/tables/brdf3d/brdf3d_test.cpp: at most 4e-7 for all
// four NDFs); the bound keeps a margin of 2.5.
constexpr double kVolumeFloatError = 1e-6;

std::string gridName(Brdf3dGrid g) {
  return g == Brdf3dGrid::TexelCenter ? "texel-center" : g == Brdf3dGrid::Node ? "node" : "cell-start";
}

std::string describeRho(const std::vector<double>& rho) {
  if (rho.empty()) return "1";
  std::string s;
  for (double r : rho) s += (s.empty() ? "" : ",") + fmtG9(r);
  return s;
}

}  // namespace

TableImage volumeHeader(const VolumeJob& job) {
  const Brdf3dSpec& s = job.spec;
  TableImage img;
  img.width = s.nx * job.cols;
  img.height = s.ny * job.rows;
  img.channels = {"R", "G", "B"};
  auto& str = img.strings;
  str["brdf.schema"] = "brdfbake/1";
  str["brdf.table"] = "brdf3d";
  str["brdf.ndf"] = ndfNames()[s.ndf];
  str["brdf.gaf"] = gafNames()[s.gaf];
  str["brdf.roughness"] = roughnessMapping(s.ndf);
  img.floats["brdf.r"] = static_cast<float>(s.roughness);
  str["brdf.fresnel"] = fresnelNames()[s.fresnel.model];
  for (const auto& [name, value] : s.fresnel.parameters()) str["brdf.fresnel." + name] = value;
  str["brdf.diffuse"] = s.diffuse >= 0 ? diffuseNames()[s.diffuse] : "none";
  if (s.diffuse >= 0) {
    str["brdf.rho"] = describeRho(s.rho);
    img.floats["brdf.diffuse.param"] = static_cast<float>(s.diffuseParam);
  }
  auto ax = s.axes();
  str["brdf.param"] = s.param == Brdf3dParam::Angles ? "angles" : "rusinkiewicz";
  str["brdf.axes"] = ax[0].name + "," + ax[1].name + "," + ax[2].name;
  for (const auto& a : ax) img.v2f["brdf." + a.name + ".range"] = {static_cast<float>(a.lo), static_cast<float>(a.hi)};
  if (s.param == Brdf3dParam::Rusinkiewicz)
    str["brdf.theta_h.index"] =
        s.thetaHSqrt ? "sqrt (x = sqrt(theta_h/(pi/2)), MERL's)" : "linear (x = theta_h/(pi/2))";
  str["brdf.grid"] = gridName(s.grid);
  str["brdf.size"] = std::to_string(s.nx) + "x" + std::to_string(s.ny) + "x" + std::to_string(s.nz);
  str["brdf.atlas"] = std::to_string(job.cols) + "x" + std::to_string(job.rows);
  img.floats["brdf.depth"] = static_cast<float>(s.nz);
  str["brdf.atlas.order"] = "slice z (third axis) at column z % " + std::to_string(job.cols) + ", row z / " +
                            std::to_string(job.cols) +
                            " (left to right, then top to bottom); texel (x, y) of a slice at "
                            "pixel (column * " +
                            std::to_string(s.nx) + " + x, row * " + std::to_string(s.ny) + " + y); unused slots hold 0";
  str["brdf.value"] = s.timesCos ? "f cos(theta_i)" : "f";
  str["brdf.channels"] =
      s.channels() == 3 ? "R,G,B = " + str["brdf.value"] + " per colour channel" : "R=G=B=" + str["brdf.value"];
  str["brdf.grazing"] =
      "n.i and n.o floored at 1e-6 (a sample at theta = 90 deg is f at cos = 1e-6): the limit from inside for GAFs "
      "whose f stays bounded at grazing (smith family, schlick-*, implicit, kelemen, cook-torrance), large but finite "
      "where it grows as 1/cos (none; neumann and ashikhmin-premoze with both directions grazing); f = 0 below the "
      "horizon";
  str["brdf.method"] =
      "f(i, o) = F D G/(4 (n.i)(n.o)) + rho f_d, evaluated in float at each grid point from directions "
      "formed in double (cospi/sinpi of exact grid fractions); brdf.error: float evaluation + storage "
      "rounding; brdf.interp-error: trilinear lookup against f at 4096 Halton points, relative to "
      "max(1, |f|), max and rms, over the table and over its interior (both directions within 80 "
      "deg of the normal)";
  str["brdf.generator"] = std::string("brdfbake ") + BRDFBAKE_VERSION + " (git " + BRDFBAKE_GIT_REV + ")";
  InterpError ie = interpolationError(s);
  img.floats["brdf.interp-error"] = static_cast<float>(ie.max);
  img.floats["brdf.interp-error.rms"] = static_cast<float>(ie.rms);
  img.floats["brdf.interp-error.interior"] = static_cast<float>(ie.maxInterior);
  img.floats["brdf.interp-error.interior-rms"] = static_cast<float>(ie.rmsInterior);
  // storage: float's half ulp, or HALF's (11 significant bits), relative to max(1, |f|)
  img.floats["brdf.error"] = static_cast<float>(kVolumeFloatError + std::ldexp(1.0, job.half ? -11 : -24));
  return img;
}

uint64_t volumeBytesBound(const VolumeJob& job) {
  const Brdf3dSpec& s = job.spec;
  if (job.merl) return 12 + 3ull * 90 * 90 * 180 * 8;
  uint64_t w = static_cast<uint64_t>(s.nx) * job.cols, h = static_cast<uint64_t>(s.ny) * job.rows;
  const uint64_t texels = static_cast<uint64_t>(s.nx) * s.ny * s.nz;
  uint64_t bytes = 0;
  for (FileFormat f : job.formats) {
    if (f == FileFormat::Exr)  // the slices side by side in one image
      bytes += tableExrBytesBound(w, h, 3, job.half);
    else if (f == FileFormat::Header)  // .h and .mjs: at most 17 characters per value ("-1.23456789e-05f, ")
      bytes += 2 * (texels * 3 * 18 + 65536);
    else  // KTX2, DDS: RGBA texels and a header
      bytes += texels * 4 * bytesPerChannel(job.precision) + 65536;
  }
  return bytes;
}

void checkVolumeSpace(const std::string& dir, const std::vector<VolumeJob>& volumes) {
  if (volumes.empty()) return;
  uint64_t need = 0;
  for (const auto& v : volumes) need += volumeBytesBound(v);
  std::string cur;
  const uint64_t free = freeBytesAt(dir, &cur);  // UINT64_MAX when unknown: checkOutputDir reports what is wrong
  if (need > free) {
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "not enough space for the brdf3d table(s) in %s: they may need up to %.1f MB, %.1f MB free "
                  "on %s; choose a smaller --size, --half, or another -o",
                  dir.c_str(), need / 1e6, free / 1e6, cur.c_str());
    throw Error(kExitIoErr, msg);  // short of space: 74, as for the 2D tables (formats/output_set.cpp)
  }
}

void writeAtlasTemporary(const std::string& tmp, const std::string& path, const TableImage& header, bool half,
                         std::array<int, 3> n, int cols,
                         const std::function<std::vector<std::vector<float>>(int z0, int zn)>& slab,
                         const std::string& what) {
  const int nx = n[0], ny = n[1], nz = n[2];
  // one atlas row of slices per block: slices z0 .. z0 + cols - 1, ny scanlines
  const size_t w = static_cast<size_t>(nx) * cols;
  writeTableExrRowsTemporary(tmp, path, header, half, ny, [&](int y0, int rows, std::vector<std::vector<float>>& out) {
    int z0 = (y0 / ny) * cols, zn = std::min(cols, nz - z0);
    std::vector<std::vector<float>> planes;
    if (zn > 0) planes = slab(z0, zn);
    int nchan = static_cast<int>(planes.size());
    out.assign(3, std::vector<float>(w * rows, 0.0f));
    for (int c = 0; c < 3; ++c) {
      if (nchan == 0) break;
      const std::vector<float>& src = planes[nchan == 3 ? c : 0];
      for (int zl = 0; zl < zn; ++zl)
        for (int y = 0; y < ny; ++y)
          std::copy_n(src.begin() + static_cast<std::ptrdiff_t>((static_cast<size_t>(zl) * ny + y) * nx), nx,
                      out[c].begin() + static_cast<std::ptrdiff_t>(y * w + static_cast<size_t>(zl) * nx));
    }
    for (const auto& p : out)
      for (float v : p)
        if (!std::isfinite(v))
          throw Error(kExitSoftware,
                      "internal error: " + what + " has a value that is not finite; nothing was written");
  });
}

OutputFile volumeOutput(KernelRunner& runner, const VolumeJob& job, const TableImage& header, double* seconds,
                        uint64_t* peakSlab) {
  OutputFile f;
  f.path = job.path;
  f.half = job.half;
  const Brdf3dSpec s = job.spec;
  auto timed = [seconds, peakSlab, &runner, s, path = job.path](int z0, int zn) {
    auto t0 = std::chrono::steady_clock::now();
    runner.setProgressLabel(path);
    auto planes = brdf3dSlab(runner, s, z0, zn);
    runner.progress("slices", z0 + zn, s.nz);
    if (seconds) *seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (peakSlab) *peakSlab = std::max<uint64_t>(*peakSlab, planes.size() * planes[0].size() * sizeof(float));
    return planes;
  };
  if (job.merl) {
    f.write = [timed, s, path = job.path](const std::string& tmp) {
      // 90 x 90 x 180 x 3 floats: small enough to bake whole (17 MB)
      writeMerlTemporary(tmp, path, timed(0, s.nz));
    };
    return f;
  }
  f.write = [timed, s, cols = job.cols, header, half = job.half, path = job.path](const std::string& tmp) {
    writeAtlasTemporary(tmp, path, header, half, {s.nx, s.ny, s.nz}, cols, timed,
                        "brdf3d " + ndfNames()[s.ndf] + "+" + gafNames()[s.gaf]);
  };
  return f;
}

namespace {
std::string need(const std::string& path, const TableImage& img, const std::string& key) {
  auto it = img.strings.find(key);
  if (it == img.strings.end())
    throw Error(kExitDataErr, path + ": not a brdf3d table written by brdfbake (no " + key + " attribute)");
  return it->second;
}
float needFloat(const std::string& path, const TableImage& img, const std::string& key) {
  auto it = img.floats.find(key);
  if (it == img.floats.end())
    throw Error(kExitDataErr, path + ": not a brdf3d table written by brdfbake (no " + key + " attribute)");
  return it->second;
}
}  // namespace

Brdf3dSpec specFromHeader(const std::string& path, const TableImage& img, int* cols, int* rows) {
  if (need(path, img, "brdf.table") != "brdf3d")
    throw Error(kExitDataErr, path + ": brdf.table is '" + need(path, img, "brdf.table") + "', not brdf3d");
  Brdf3dSpec s;
  s.ndf = ndfId(need(path, img, "brdf.ndf"), path + ": brdf.ndf");
  s.gaf = gafId(need(path, img, "brdf.gaf"), path + ": brdf.gaf");
  s.roughness = needFloat(path, img, "brdf.r");
  s.fresnel.model = fresnelId(need(path, img, "brdf.fresnel"), path + ": brdf.fresnel");
  for (const char* p : {"f0", "eta", "k", "f82"}) {
    auto it = img.strings.find(std::string("brdf.fresnel.") + p);
    if (it == img.strings.end()) continue;
    std::vector<double>& slot = std::string(p) == "f0"    ? s.fresnel.f0
                                : std::string(p) == "eta" ? s.fresnel.eta
                                : std::string(p) == "k"   ? s.fresnel.k
                                                          : s.fresnel.f82;
    slot = parseValues(path + ": brdf.fresnel." + p, it->second);
  }
  validateFresnel(s.fresnel);
  std::string d = need(path, img, "brdf.diffuse");
  if (d != "none") {
    s.diffuse = diffuseId(d, path + ": brdf.diffuse");
    s.diffuseParam = needFloat(path, img, "brdf.diffuse.param");
    s.rho = parseValues(path + ": brdf.rho", need(path, img, "brdf.rho"));
  }
  s.param = need(path, img, "brdf.param") == "angles" ? Brdf3dParam::Angles : Brdf3dParam::Rusinkiewicz;
  if (s.param == Brdf3dParam::Rusinkiewicz) s.thetaHSqrt = need(path, img, "brdf.theta_h.index").rfind("sqrt", 0) == 0;
  std::string g = need(path, img, "brdf.grid");
  s.grid = g == "node" ? Brdf3dGrid::Node : g == "cell-start" ? Brdf3dGrid::CellStart : Brdf3dGrid::TexelCenter;
  s.timesCos = need(path, img, "brdf.value") != "f";
  if (std::sscanf(need(path, img, "brdf.size").c_str(), "%dx%dx%d", &s.nx, &s.ny, &s.nz) != 3 ||
      std::sscanf(need(path, img, "brdf.atlas").c_str(), "%dx%d", cols, rows) != 2 || s.nx < 1 || s.ny < 1 ||
      s.nz < 1 || *cols < 1 || *rows < 1 || static_cast<long>(*cols) * *rows < s.nz || img.width != s.nx * *cols ||
      img.height != s.ny * *rows)
    throw Error(kExitDataErr, path + ": brdf.size / brdf.atlas do not match the image's " + std::to_string(img.width) +
                                  "x" + std::to_string(img.height) + " texels");
  return s;
}

std::vector<std::vector<float>> volumeFromAtlas(const TableImage& img, const Brdf3dSpec& s, int cols) {
  std::vector<std::vector<float>> planes(img.planes.size(),
                                         std::vector<float>(static_cast<size_t>(s.nx) * s.ny * s.nz));
  for (size_t c = 0; c < img.planes.size(); ++c)
    for (int z = 0; z < s.nz; ++z)
      for (int y = 0; y < s.ny; ++y)
        for (int x = 0; x < s.nx; ++x) {
          size_t px = static_cast<size_t>(z % cols) * s.nx + x, py = static_cast<size_t>(z / cols) * s.ny + y;
          planes[c][(static_cast<size_t>(z) * s.ny + y) * s.nx + x] = img.planes[c][py * img.width + px];
        }
  return planes;
}

std::string sampleReport(const std::string& path, const std::array<double, 3>& at) {
  TableImage img = readTableExr(path);
  int cols = 0, rows = 0;
  Brdf3dSpec s = specFromHeader(path, img, &cols, &rows);
  std::vector<std::vector<float>> planes = volumeFromAtlas(img, s, cols);
  glm::dvec3 rad(at[0] / kRadToDeg, at[1] / kRadToDeg, at[2] / kRadToDeg);
  glm::dvec3 idx(texelIndex(s, 0, rad.x), texelIndex(s, 1, rad.y), texelIndex(s, 2, rad.z));
  Directions d =
      s.param == Brdf3dParam::Angles ? fromAngles(rad.x, rad.y, rad.z) : fromRusinkiewicz(rad.x, rad.y, rad.z);
  auto ax = s.axes();
  char line[512];
  std::string out = path + ": " + need(path, img, "brdf.ndf") + " + " + need(path, img, "brdf.gaf") +
                    ", r = " + fmtG(s.roughness) + ", " + need(path, img, "brdf.param") + " " +
                    need(path, img, "brdf.size") + ", " + need(path, img, "brdf.grid") + " grid, value " +
                    need(path, img, "brdf.value") + "\n";
  std::snprintf(line, sizeof line, "at %s = %g, %s = %g, %s = %g deg (texel index %.4f, %.4f, %.4f)\n",
                ax[0].name.c_str(), at[0], ax[1].name.c_str(), at[1], ax[2].name.c_str(), at[2], idx.x, idx.y, idx.z);
  out += line;
  std::snprintf(line, sizeof line, "%-8s %16s %16s %12s %12s\n", "channel", "trilinear", "exact", "abs error",
                "rel error");
  out += line;
  const char* names[3] = {"R", "G", "B"};
  int nchan = s.channels();
  for (int c = 0; c < (nchan == 3 ? 3 : 1); ++c) {
    double lookup = trilinear(s, planes[c], idx), exact = hostBrdf(s, d, c);
    double abs = std::fabs(lookup - exact);
    std::snprintf(line, sizeof line, "%-8s %16.9g %16.9g %12.3e %12.3e\n", nchan == 3 ? names[c] : "R=G=B", lookup,
                  exact, abs, abs / std::max(std::fabs(exact), 1e-300));
    out += line;
  }
  auto ie = img.floats.find("brdf.interp-error");
  if (ie != img.floats.end())
    out += "the file's interpolation-error estimate, relative to max(1, |f|) over 4096 points: max " +
           fmtG(ie->second) + " (brdf.interp-error), " +
           fmtG(img.floats.count("brdf.interp-error.interior") ? img.floats.at("brdf.interp-error.interior") : 0.0f) +
           " with both directions within 80 deg of the normal (brdf.interp-error.interior)\n";
  return out;
}

std::vector<PlannedFile> volumeFormatOutputs(KernelRunner& runner, const VolumeJob& job, const TableImage& atlasHeader,
                                             double* seconds) {
  std::vector<PlannedFile> files;
  const Brdf3dSpec s = job.spec;
  const std::string stem = pathStem(job.path);
  TableImage base = atlasHeader;
  base.width = s.nx;
  base.height = s.ny;
  base.strings.erase("brdf.atlas");
  base.strings.erase("brdf.atlas.order");
  const double exrStorage = job.half ? std::ldexp(1.0, -11) : std::ldexp(1.0, -24);
  const double computeError = std::max(0.0, atlasHeader.floats.at("brdf.error") - exrStorage);
  SliceSource src;
  src.width = s.nx;
  src.height = s.ny;
  src.depth = s.nz;
  src.channels = 3;
  src.slicesPerBlock = std::max(1, job.cols);  // one atlas row's slices: the EXR path's slab
  src.fill = [&runner, s, seconds, path = job.path](int z0, int zn, std::vector<std::vector<float>>& planes) {
    auto t0 = std::chrono::steady_clock::now();
    runner.setProgressLabel(path);
    planes = brdf3dSlab(runner, s, z0, zn);
    runner.progress("slices", z0 + zn, s.nz);
    if (seconds) *seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (planes.size() == 1) planes = {planes[0], planes[0], planes[0]};  // R=G=B tables
  };
  for (FileFormat f : job.formats) {
    if (f == FileFormat::Exr) continue;  // the atlas, volumeOutput
    if (f == FileFormat::Png16)
      throw Error(kExitUsage,
                  "--format png16: a 3D table has no PNG form (PNG is 2D); use ktx2 or dds (3D "
                  "textures), exr (an atlas) or header");
    const Precision p = job.precision;
    TableImage meta = formatMetadata(base, f, p, computeError, storageErrorBound(p), 3);
    meta.strings["brdf.error.storage"] = fmtG(storageErrorBound(p), 3) + " (" + precisionName(p) +
                                         " rounding, a priori: the values are streamed; relative to max(1, |v|))";
    meta.strings["brdf.layout"] = "3D texture: x = first axis, y = second, z = third (slices z-major)";
    const std::vector<std::string> paths = formatPaths(stem, f);
    for (size_t k = 0; k < paths.size(); ++k)
      files.push_back({formatWriter(paths[k], f, p, meta, src, stem, k == 1), meta.floats.at("brdf.error")});
  }
  return files;
}

}  // namespace brdfbake
