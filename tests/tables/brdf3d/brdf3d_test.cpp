// 3D isotropic BRDF tables (--table brdf3d): the device's texels against the host's independent
// evaluation (GLM directions, double), reciprocity and the phi symmetries, the EXR atlas written
// slab by slab and read back, the interpolation-error estimate, `brdfbake sample`, bad input.
// Needs an OpenCL device (selectDevice throws otherwise: the test fails loudly).
#include <gtest/gtest.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>

#include "cli_run.h"
#include "tables/volume.h"
#include "common/brdf3d_grid.h"
#include "common/brdf_host.h"
#include "common/models.h"
#include "doc_figures.h"
#include "common/errors.h"
#include "formats/exr/table_file.h"
#include "formats/merl.h"
#include "tables/brdf3d/brdf3d.h"
#include "test_device.h"

namespace fs = std::filesystem;
namespace {
using namespace brdfbake;
using testing_device::runner;
constexpr double kPi = 3.14159265358979323846;

using testing_cli::bytes;
using testing_cli::CmdResult;
using testing_cli::run;
fs::path freshDir(const std::string& name) { return testing_cli::freshDir("b3", name); }

Brdf3dSpec spec(int ndf, int gaf, Brdf3dParam param, bool sqrtIndex, Brdf3dGrid grid, int n, double r = 0.5) {
  Brdf3dSpec s;
  s.ndf = ndf;
  s.gaf = gaf;
  s.roughness = r;
  s.param = param;
  s.thetaHSqrt = sqrtIndex;
  s.grid = grid;
  s.nx = s.ny = s.nz = n;
  return s;
}

// Largest error of the device's table against hostBrdf: relative to |f| where |f| > 1e-3 max f,
// and relative to max(1, |f|) everywhere.
struct Agreement {
  double rel = 0, relMax1 = 0;
  size_t worst = 0;  // texel of the largest rel
  double got = 0, want = 0;
};
Agreement compare(const Brdf3dSpec& s) {
  auto planes = brdf3dSlab(runner(), s, 0, s.nz);
  Agreement a;
  double peak = 0;
  std::vector<double> want(planes[0].size());
  for (int z = 0; z < s.nz; ++z)
    for (int y = 0; y < s.ny; ++y)
      for (int x = 0; x < s.nx; ++x) {
        size_t t = (static_cast<size_t>(z) * s.ny + y) * s.nx + x;
        want[t] = hostBrdf(s, texelDirections(s, x, y, z), 0);
        peak = std::max(peak, std::fabs(want[t]));
      }
  for (size_t t = 0; t < want.size(); ++t) {
    double d = std::fabs(planes[0][t] - want[t]);
    EXPECT_TRUE(std::isfinite(planes[0][t]))
        << ndfNames()[s.ndf] << "+" << gafNames()[s.gaf] << " param " << s.kernelParam() << " grid " << s.kernelGrid()
        << " texel " << t << " host " << want[t];
    a.relMax1 = std::max(a.relMax1, d / std::max(1.0, std::fabs(want[t])));
    if (std::fabs(want[t]) > 1e-3 * peak && d / std::fabs(want[t]) > a.rel) {
      a.rel = d / std::fabs(want[t]);
      a.worst = t;
      a.got = planes[0][t];
      a.want = want[t];
    }
  }
  return a;
}

// Texel values are the analytic BRDF at the grid points to float precision: every NDF, Smith and
// two other GAFs, both parameterisations, the three grids, a rough and a sharp lobe.
TEST(Brdf3d, KernelMatchesHostEvaluation) {
  double worstRel = 0, worstMax1 = 0;
  for (int ndf = 0; ndf < NDF_COUNT; ++ndf)
    for (int gaf :
         {GAF_SMITH_CORRELATED, GAF_SMITH, GAF_COOK_TORRANCE, GAF_SCHLICK_GGX, GAF_CHARLIE_SMITH, GAF_NEUBELT})
      if (pairSupported(ndf, gaf))
        for (auto [param, sq] : {std::pair{Brdf3dParam::Angles, false}, std::pair{Brdf3dParam::Rusinkiewicz, true},
                                 std::pair{Brdf3dParam::Rusinkiewicz, false}})
          for (Brdf3dGrid grid : {Brdf3dGrid::TexelCenter, Brdf3dGrid::Node, Brdf3dGrid::CellStart})
            for (double r : {0.15, 0.6}) {
              Brdf3dSpec s = spec(ndf, gaf, param, sq, grid, 12, r);
              Agreement a = compare(s);
              worstRel = std::max(worstRel, a.rel);
              worstMax1 = std::max(worstMax1, a.relMax1);
              EXPECT_LT(a.rel, 1e-6) << ndfNames()[ndf] << "+" << gafNames()[gaf] << " param " << s.kernelParam()
                                     << " grid " << s.kernelGrid() << " r " << r << " texel " << a.worst % s.nx << ","
                                     << a.worst / s.nx % s.ny << "," << a.worst / s.nx / s.ny << ": " << a.got << " vs "
                                     << a.want;
            }
  std::string said;
  testing_docs::say(said, "worst relative error %.3g (where |f| > 1e-3 max), %.3g relative to max(1, |f|)\n", worstRel,
                    worstMax1);
  testing_docs::expectPagesQuote(said);
}

// A whole material: RGB conductor Fresnel, a diffuse lobe with RGB albedo, f cos(theta_i).
TEST(Brdf3d, WholeMaterialChannelsMatchHost) {
  Brdf3dSpec s = spec(NDF_GGX, GAF_SMITH_CORRELATED, Brdf3dParam::Angles, false, Brdf3dGrid::Node, 10, 0.4);
  s.fresnel.model = FRESNEL_CONDUCTOR;
  s.fresnel.eta = {0.2, 0.92, 1.1};
  s.fresnel.k = {3.9, 2.45, 2.14};
  validateFresnel(s.fresnel);
  s.diffuse = DIFFUSE_BURLEY;
  s.diffuseParam = 0.4;
  s.rho = {0.8, 0.5, 0.2};
  s.timesCos = true;
  ASSERT_EQ(s.channels(), 3);
  auto planes = brdf3dSlab(runner(), s, 0, s.nz);
  ASSERT_EQ(planes.size(), 3u);
  for (int c = 0; c < 3; ++c)
    for (int z = 0; z < s.nz; ++z)
      for (int y = 0; y < s.ny; ++y)
        for (int x = 0; x < s.nx; ++x) {
          double want = hostBrdf(s, texelDirections(s, x, y, z), c);
          double got = planes[c][(static_cast<size_t>(z) * s.ny + y) * s.nx + x];
          ASSERT_NEAR(got, want, 1e-6 * std::max(1.0, std::fabs(want))) << c << " " << x << " " << y << " " << z;
        }
  // grazing i (theta_i = 90 deg on the node grid): f cos theta_i -> 0 (bounded f times 1e-6)
  for (int z = 0; z < s.nz; ++z) EXPECT_LT(planes[0][(static_cast<size_t>(z) * s.ny + 3) * s.nx + 9], 1e-5);
}

// Reciprocity f(i, o) = f(o, i): in (theta_i, theta_o, phi) the table is symmetric in x and y; in
// Rusinkiewicz's angles it is f(phi_d) = f(phi_d + pi), with the mirror symmetry f(phi_d) =
// f(-phi_d) of an isotropic BRDF: f(phi_d) = f(pi - phi_d), slice z against slice nz - 1 - z.
TEST(Brdf3d, ReciprocityAndPhiSymmetry) {
  for (int ndf = 0; ndf < NDF_COUNT; ++ndf) {
    if (!pairSupported(ndf, GAF_SMITH_CORRELATED)) continue;
    Brdf3dSpec a = spec(ndf, GAF_SMITH_CORRELATED, Brdf3dParam::Angles, false, Brdf3dGrid::TexelCenter, 14, 0.3);
    auto p = brdf3dSlab(runner(), a, 0, a.nz)[0];
    for (int z = 0; z < a.nz; ++z)
      for (int y = 0; y < a.ny; ++y)
        for (int x = 0; x < y; ++x) {
          float u = p[(static_cast<size_t>(z) * a.ny + y) * a.nx + x],
                v = p[(static_cast<size_t>(z) * a.ny + x) * a.nx + y];
          ASSERT_NEAR(u, v, 1e-6 * std::max(1.0f, std::fabs(u))) << ndfNames()[ndf] << " " << x << " " << y << " " << z;
        }
    Brdf3dSpec r = spec(ndf, GAF_SMITH_CORRELATED, Brdf3dParam::Rusinkiewicz, true, Brdf3dGrid::TexelCenter, 14, 0.3);
    auto q = brdf3dSlab(runner(), r, 0, r.nz)[0];
    for (int z = 0; z < r.nz; ++z)
      for (int y = 0; y < r.ny; ++y)
        for (int x = 0; x < r.nx; ++x) {
          float u = q[(static_cast<size_t>(z) * r.ny + y) * r.nx + x];
          float v = q[(static_cast<size_t>(r.nz - 1 - z) * r.ny + y) * r.nx + x];
          ASSERT_NEAR(u, v, 2e-6 * std::max(1.0f, std::fabs(u))) << ndfNames()[ndf] << " " << x << " " << y << " " << z;
        }
    // the angles table's phi in [0, pi] stands for -phi too: the host at -phi gives the same f
    for (int z = 0; z < a.nz; z += 3) {
      glm::dvec3 ang = texelAngles(a, 5, 9, z);
      double f = hostBrdf(a, fromAngles(ang.x, ang.y, -ang.z), 0);
      EXPECT_NEAR(p[(static_cast<size_t>(z) * a.ny + 9) * a.nx + 5], f, 1e-6 * std::max(1.0, f));
    }
  }
}

// The GLM geometry: Rusinkiewicz's angles there and back, and the half-vector they name.
TEST(Brdf3d, RusinkiewiczRoundTrip) {
  for (double th : {0.0, 0.2, 0.7, 1.2, 1.5})
    for (double td : {0.05, 0.4, 0.9, 1.5})
      for (double pd : {0.1, 1.0, 2.0, 3.0, 4.5}) {
        Directions d = fromRusinkiewicz(th, td, pd);
        EXPECT_NEAR(glm::length(d.i), 1.0, 1e-14);
        EXPECT_NEAR(glm::length(d.o), 1.0, 1e-14);
        glm::dvec3 h = glm::normalize(d.i + d.o);
        EXPECT_NEAR(std::acos(h.z), th, 1e-7);
        glm::dvec3 back = toRusinkiewicz(d);
        EXPECT_NEAR(back.x, th, 1e-7);
        EXPECT_NEAR(back.y, td, 1e-7);
        if (th > 0) {
          EXPECT_NEAR(back.z, pd, 1e-7) << th << " " << td << " " << pd;
        }
      }
}

// The atlas: written slab by slab through the CLI, read back by OpenEXR, its slices equal the
// device's table; unused slots hold 0; the header names the atlas; the streamed file is
// byte-identical to the same image written whole.
TEST(Brdf3d, AtlasRoundTrip) {
  fs::path dir = freshDir("atlas");
  CmdResult r = run("bake --table brdf3d --param rusinkiewicz --theta-h sqrt --size 12,10,7 --roughness 0.35 -o '" +
                    dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  fs::path file = dir / "brdf3d_ggx_smith-correlated_rusinkiewicz.exr";
  TableImage img = readTableExr(file.string());
  EXPECT_EQ(img.strings["brdf.atlas"], "3x3");  // 7 slices: no exact split, ceil(sqrt 7) = 3 columns
  EXPECT_EQ(img.floats["brdf.depth"], 7.0f);
  EXPECT_EQ(img.width, 36);
  EXPECT_EQ(img.height, 30);
  int cols = 0, rows = 0;
  Brdf3dSpec s = specFromHeader(file.string(), img, &cols, &rows);
  EXPECT_EQ(s.nx, 12);
  EXPECT_EQ(s.ny, 10);
  EXPECT_EQ(s.nz, 7);
  EXPECT_TRUE(s.thetaHSqrt);
  EXPECT_DOUBLE_EQ(s.roughness, 0.35f);
  auto want = brdf3dSlab(runner(), s, 0, s.nz)[0];
  auto got = volumeFromAtlas(img, s, cols);
  ASSERT_EQ(got[0].size(), want.size());
  for (size_t t = 0; t < want.size(); ++t) ASSERT_EQ(got[0][t], want[t]) << t;
  for (int c = 0; c < 3; ++c) EXPECT_EQ(got[c], got[0]);  // one channel: R = G = B
  for (int slot = 7; slot < 9; ++slot)                    // the two unused slots
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 12; ++x)
        EXPECT_EQ(img.planes[0][static_cast<size_t>((slot / 3) * 10 + y) * 36 + (slot % 3) * 12 + x], 0.0f);
  fs::path whole = dir / "whole.exr";
  writeTableExr(whole.string(), img, false);
  EXPECT_EQ(bytes(whole), bytes(file)) << "streamed and whole writes differ";
}

// --format merl: the kernel's table in MERL's layout equals the host's evaluation of the same
// material written by the host (formats/merl.h merlPlanesFromSpec) to float precision, in every bin.
TEST(Brdf3d, MerlFormatFromTheKernelMatchesTheHostWriter) {
  fs::path dir = freshDir("merl");
  CmdResult r =
      run("bake --table brdf3d --format merl --fresnel conductor --eta 0.2,0.92,1.1 --k 3.9,2.45,2.14 "
          "--roughness 0.4 -o '" +
          dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  fs::path file = dir / "brdf3d_ggx_smith-correlated_conductor.binary";
  ASSERT_EQ(fs::file_size(file), kMerlFileBytes);
  Brdf3dSpec s = spec(NDF_GGX, GAF_SMITH_CORRELATED, Brdf3dParam::Rusinkiewicz, true, Brdf3dGrid::CellStart, 0, 0.4);
  s.fresnel.model = FRESNEL_CONDUCTOR;
  s.fresnel.eta = {0.2, 0.92, 1.1};
  s.fresnel.k = {3.9, 2.45, 2.14};
  validateFresnel(s.fresnel);
  s = merlSpec(s);
  fs::path hostFile = dir / "host.binary";
  writeMerl(hostFile.string(), merlPlanesFromSpec(s));
  MerlData kernel = readMerl(file.string()), host = readMerl(hostFile.string());
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for (size_t b = 0; b < kMerlBins; ++b)
      worst = std::max(worst, std::fabs(kernel.f[c][b] - host.f[c][b]) / std::max(1.0, std::fabs(host.f[c][b])));
  EXPECT_LT(worst, 2e-7) << "largest difference between the kernel's and the host's MERL file";
  // bad combinations with --format merl
  CmdResult bad = run("bake --table brdf3d,albedo --format merl -o '" + (dir / "x").string() + "'");
  EXPECT_EQ(bad.code, 64) << bad.out;
  EXPECT_FALSE(fs::exists(dir / "x"));
}

TEST(Brdf3d, AtlasGrid) {
  EXPECT_EQ(atlasGrid(180), std::make_pair(15, 12));
  EXPECT_EQ(atlasGrid(512), std::make_pair(32, 16));
  EXPECT_EQ(atlasGrid(32), std::make_pair(8, 4));
  EXPECT_EQ(atlasGrid(64), std::make_pair(8, 8));
  EXPECT_EQ(atlasGrid(97), std::make_pair(10, 10));  // prime: 3 empty slots
  EXPECT_EQ(atlasGrid(1), std::make_pair(1, 1));
}

// The interpolation-error estimate: away from grazing (both directions within 80 deg of the
// normal) trilinear lookups are second order, the error falls ~4x per doubling of the resolution
// (asserted: at least 3x); over the whole table the horizon (f jumps to 0 below it) and the
// grazing growth of f keep the largest error from falling, which the estimate must show.
TEST(Brdf3d, InterpolationErrorFallsWithResolution) {
  for (auto [param, sq] : {std::pair{Brdf3dParam::Angles, false}, std::pair{Brdf3dParam::Rusinkiewicz, true}})
    for (bool cosine : {false, true}) {
      double last = 1e9;
      for (int n : {16, 32, 64}) {
        Brdf3dSpec s = spec(NDF_GGX, GAF_SMITH_CORRELATED, param, sq, Brdf3dGrid::TexelCenter, n, 0.5);
        s.timesCos = cosine;
        InterpError e = interpolationError(s, 4096);
        std::printf("param %d cos %d n %d: max %.3g rms %.3g; interior max %.3g rms %.3g\n", s.kernelParam(), cosine, n,
                    e.max, e.rms, e.maxInterior, e.rmsInterior);
        EXPECT_GE(e.max, e.maxInterior);
        EXPECT_GE(e.max, e.rms);
        EXPECT_LT(e.rmsInterior, last / 3) << n;
        last = e.rmsInterior;
      }
      if (param == Brdf3dParam::Rusinkiewicz && !cosine) {
        Brdf3dSpec s = spec(NDF_GGX, GAF_SMITH_CORRELATED, param, sq, Brdf3dGrid::TexelCenter, 64);
        EXPECT_GT(interpolationError(s).max, 1.0);  // the horizon's jump, at any resolution
      }
    }
}

// `brdfbake sample`: the exact value it prints is the host's BRDF, and the lookup is within the
// interpolation error of the exact value.
TEST(Brdf3d, SampleCommand) {
  fs::path dir = freshDir("sample");
  ASSERT_EQ(run("bake --table brdf3d --size 48 --roughness 0.6 -o '" + dir.string() + "'").code, 0);
  fs::path file = dir / "brdf3d_ggx_smith-correlated_angles.exr";
  CmdResult r = run("sample '" + file.string() + "' --at 30,40,120");
  ASSERT_EQ(r.code, 0) << r.out;
  Brdf3dSpec s = spec(NDF_GGX, GAF_SMITH_CORRELATED, Brdf3dParam::Angles, false, Brdf3dGrid::TexelCenter, 48, 0.6f);
  double exact = hostBrdf(s, fromAngles(30 * kPi / 180, 40 * kPi / 180, 120 * kPi / 180), 0);
  double lookup = 0, printed = 0;
  size_t at = r.out.find("R=G=B");
  ASSERT_NE(at, std::string::npos) << r.out;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "R=G=B %lf %lf", &lookup, &printed), 2) << r.out;
  EXPECT_NEAR(printed, exact, 1e-7 * exact);
  EXPECT_NEAR(lookup, exact, 0.02 * exact);
  EXPECT_NE(r.out.find("theta_i = 30"), std::string::npos) << r.out;
}

TEST(Brdf3d, BadInputIsRejectedBeforeAnythingIsWritten) {
  fs::path dir = freshDir("bad");
  fs::path out = dir / "o";
  struct Case {
    std::string args, message;
    int code;
  } cases[] = {
      {"--table brdf3d --size 0,8,8",
       "--size: each axis of a brdf3d or dielectric table must be an integer in 1..1024, got '0'", 64},
      {"--table brdf3d --size 8,8,2000", "got '2000'", 64},
      {"--table brdf3d --size 2000", "--size: each axis of a brdf3d table must be an integer in 1..1024, got 2000", 64},
      {"--table brdf3d --param polar", "--param must be angles or rusinkiewicz, got 'polar'", 64},
      {"--table brdf3d --theta-h sqrt", "--theta-h: only --param rusinkiewicz has a theta_h axis", 64},
      {"--table brdf3d --roughness 0", "--roughness must be one value in [0.01, 1]", 64},
      {"--table brdf3d --value radiance", "--value must be f or f-cos", 64},
      {"--table albedo --param angles", "--param: only --table brdf3d takes it", 64},
      {"--table brdf3d --atlas 2x2 --size 8", "--atlas 2x2 holds 4 slices, fewer than the table's 8", 64},
      {"--table brdf3d --format merl --size 8,8,8", "--format merl has MERL's fixed layout", 64},
      {"--table brdf3d --format tiff",
       "--format must be one or more of exr, ktx2, dds, png16, header (merl: brdf3d only)", 64},
      {"--table brdf3d --size 4 --grid node --size 4", "--size given twice", 64},
  };
  for (const Case& c : cases) {
    CmdResult r = run("bake " + c.args + " -o '" + out.string() + "'");
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  CmdResult r = run("sample '" + (dir / "none.exr").string() + "' --at 10,10,10");
  EXPECT_EQ(r.code, 66) << r.out;
  r = run("sample x.exr --at 10,95,10");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--at: angle 2 must be in [0, 90] degrees"), std::string::npos) << r.out;
}

// Not enough free space: the check before anything is written answers 73 with the need and what
// is free (volumes that together exceed the free space of the test's directory).
TEST(Brdf3d, FreeSpaceIsCheckedFirst) {
  fs::path dir = freshDir("space");
  struct statvfs st {};
  ASSERT_EQ(::statvfs(dir.c_str(), &st), 0);
  uint64_t free = static_cast<uint64_t>(st.f_bavail) * st.f_frsize;
  VolumeJob big;
  big.spec.nx = big.spec.ny = big.spec.nz = 1024;
  std::tie(big.cols, big.rows) = atlasGrid(1024);
  std::vector<VolumeJob> jobs(free / volumeBytesBound(big) + 1, big);
  try {
    checkVolumeSpace((dir / "sub" / "dir").string(), jobs);
    FAIL() << "no error for " << jobs.size() << " tables of " << volumeBytesBound(big) << " bytes";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), kExitIoErr);  // short of space: 74, as for the 2D tables
    EXPECT_NE(std::string(e.what()).find("not enough space"), std::string::npos) << e.what();
  }
  VolumeJob small;
  small.spec.nx = small.spec.ny = small.spec.nz = 8;
  EXPECT_NO_THROW(checkVolumeSpace(dir.string(), {small}));
}

}  // namespace
