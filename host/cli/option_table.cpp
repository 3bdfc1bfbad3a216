// The option table: every option of the command line, the commands that take it, its help (and
// the commands' own help where it differs) and its accepted values (cli/commands.h).
#include <algorithm>

#include "cli/commands.h"
#include "common/errors.h"
#include "common/material.h"
#include "common/models.h"
#include "formats/layout.h"
#include "formats/storage.h"
#include "tables/registry.h"

namespace brdfbake {

namespace {

constexpr unsigned kTableCommands = kCmdBake | kCmdEnergy | kCmdVerify | kCmdConvergence;  // take --ndf, --gaf
constexpr unsigned kDeviceCommands =
    kCmdBake | kCmdEnergy | kCmdVerify | kCmdStress | kCmdConvergence | kCmdSceneBake | kCmdDevices | kCmdRender;

std::vector<std::string> formatNames() {
  std::vector<std::string> v;
  for (FileFormat f : {FileFormat::Exr, FileFormat::Ktx2, FileFormat::Dds, FileFormat::Png16, FileFormat::Header})
    v.push_back(formatName(f));
  v.push_back("merl");
  return v;
}
// --size's defaults as the families describe their kinds: "128 for splitsum, ..., 32 otherwise" (the
// most common default last).
std::string sizeDefaults() {
  std::vector<std::pair<int, std::vector<TableKind>>> groups;
  for (const KindInfo& k : allKinds()) {
    if (k.sizeAxes != 1) continue;
    auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == k.defaultSize; });
    if (g == groups.end())
      groups.push_back({k.defaultSize, {k.kind}});
    else
      g->second.push_back(k.kind);
  }
  auto common = std::max_element(groups.begin(), groups.end(),
                                 [](const auto& a, const auto& b) { return a.second.size() < b.second.size(); });
  std::string s;
  for (auto g = groups.begin(); g != groups.end(); ++g)
    if (g != common) s += std::to_string(g->first) + " for " + kindNames(g->second, "and") + ", ";
  return s + std::to_string(common->first) + " otherwise";
}

std::vector<std::string> precisionNames() {
  std::vector<std::string> v;
  for (Precision p : {Precision::Float32, Precision::Float16, Precision::Unorm16, Precision::Unorm8})
    v.push_back(precisionName(p));
  return v;
}
std::vector<std::string> layoutNames() {
  std::vector<std::string> v;
  for (const auto& p : layoutPresets()) v.push_back(p.name);
  return v;
}

std::vector<OptionInfo> makeOptions();

// The options, with the help of the commands where an option means or defaults to something else.
std::vector<OptionInfo> makeOptionsWithOwnHelp() {
  const unsigned E = kCmdEnergy, V = kCmdVerify, C = kCmdConvergence, P = kCmdPlan, SB = kCmdSceneBake;
  std::vector<OptionInfo> v = makeOptions();
  auto own = [&](const std::string& name, unsigned bits, const std::string& text) {
    for (OptionInfo& o : v)
      if (o.name == name && (o.commands & bits)) o.helpFor.push_back({bits, text});
  };
  own("--ndf", E,
      joinNames(ndfNames()) + " (default ggx): the material's specular NDF; repeat or comma-separate to check each");
  own("--ndf", V, joinNames(ndfNames()) + " (default ggx); repeat or comma-separate: every NDF x GAF pair is checked");
  own("--ndf", C, joinNames(ndfNames()) + " (default ggx): the pair whose table is measured");
  own("--table", C, joinNames(tableNames()) + "\n(default albedo): the one kind whose methods are measured");
  own("--size", E | V, "points per axis of the (mu, r) grid the check evaluates (default 33)");
  own("--size", C,
      "points per axis of the measured grid (each kind has its own default and range; a size out of "
      "it is refused naming them)");
  own("--output", E, "write the page with the worst points and the furnace renders to DIR/energy (no -o: no page)");
  own("--output", V, "the page goes to DIR/verify (default out/verify)");
  own("--output", C, "the page goes to DIR/convergence (default out/convergence)");
  own("--output", P, "the directory whose files are compared with the plan (default: the scene's output.dir)");
  own("--output", SB, "output directory (default: the scene's output.dir), created with its parents");
  return v;
}

std::vector<OptionInfo> makeOptions() {
  const unsigned B = kCmdBake, E = kCmdEnergy, V = kCmdVerify, S = kCmdStress, C = kCmdConvergence;
  const unsigned P = kCmdPlan, SB = kCmdSceneBake;
  return {
      // models
      {"--ndf", "", "NAME", kTableCommands | kCmdRender, "Models",
       joinNames(ndfNames()) +
           " (default ggx); repeat or comma-separate: the product is baked (render: one, not charlie)",
       ndfNames()},
      {"--gaf", "", "NAME", kTableCommands | kCmdRender, "Models",
       joinNames(gafNames()) + "\n(default smith-correlated)", gafNames()},
      {"--brdf",
       "",
       "merl:FILE",
       B | C,
       "Models",
       "a measured material (MERL .binary) for --table albedo, albedo-avg (1x1), splitsum; no --ndf/--gaf/--fresnel",
       {}},
      {"--preset",
       "",
       "NAME",
       B,
       "Models",
       "gltf: glTF's reference-shading tables (the GGX split sum, the sheen IBL term and the sheen "
       "albedo-scaling table); with --size, --grid, --half, -o",
       {"gltf"}},
      // tables
      {"--table", "", "KIND", B | C, "Tables",
       joinNames(tableNames()) + "\n(default: the first four; docs/commands.md describes each)", tableNames()},
      {"--size",
       "",
       "N",
       B | E | V | C,
       "Tables",
       "texels per axis, 1..8192 (default " + sizeDefaults() +
           "); brdf3d and dielectric: N or X,Y,Z, 1..1024; ltc: 2..256",
       {}},
      {"--grid",
       "",
       "G",
       B,
       "Tables",
       "texel-center (default: value at (i+0.5)/n) or node (at i/(n-1), n >= 2)",
       {"texel-center", "node"}},
      {"--mu-axis",
       "",
       "A",
       B,
       "Tables",
       "linear (default: x = mu) or sqrt (x = sqrt(mu), texel i at mu = x_i^2, as HDRP's FGD): "
       "splitsum and albedo only",
       {"linear", "sqrt"}},
      {"--eta-range",
       "",
       "LO,HI",
       B | C,
       "Tables",
       "dielectric tables' eta axis, 0 < LO < HI <= 100 (default 0.4,2.5)",
       {}},
      // output
      {"--format", "", "F[,F..]", B, "Output",
       "exr (default), ktx2, dds, png16 (16-bit PNG, 2D), header (C/C++ .h and JavaScript .mjs): one "
       "file per format; brdf3d also merl (alone)",
       formatNames()},
      {"--precision", "", "P", B, "Output",
       "float32 (default), float16, unorm16, unorm8 (unorm: tables within [0, 1]); exr stores "
       "float32/float16, png16 always unorm16",
       precisionNames()},
      {"--half", "", "", B, "Output", "--precision float16", {}},
      {"--output",
       "-o",
       "DIR",
       B | E | V | S | C | P | SB | kCmdRender,
       "Output",
       "output directory, created with its parents (default out)",
       {}},
      {"--no-wait",
       "",
       "",
       B | SB | kCmdRender,
       "Output",
       "when another bake is writing into -o, exit 75 at once instead of waiting for it",
       {}},
      {"--dry-run",
       "",
       "",
       B,
       "Output",
       "print the tables the bake would write, their sizes and estimated seconds, and whether each file is new; "
       "compute and write nothing",
       {}},
      {"--timings",
       "",
       "",
       B | SB,
       "Output",
       "print each stage's seconds on stderr: device set-up, each program (loaded or compiled), each table, writing",
       {}},
      {"--quiet",
       "",
       "",
       B | SB,
       "Output",
       "no progress line (drawn on stderr for a table that runs over a second, when stderr is a terminal)",
       {}},
      {"--progress",
       "",
       "",
       B | SB,
       "Output",
       "progress also when stderr is a file or a pipe: whole lines, one every 2 s at most (a build log)",
       {}},
      {"--layout", "", "NAME", B, "Engine layout",
       "--table splitsum arranged as an engine samples it (axes, flips, channels, format, precision, "
       "size, grid): " +
           joinNames(layoutNames()) + "\n(unity-hdrp-sqrt: x = sqrt(NdotV), node grid; docs/layouts.md)",
       layoutNames()},
      {"--axes", "", "mu,r|r,mu", B, "Engine layout", "which quantity runs along x", {"mu,r", "r,mu"}},
      {"--flip-x", "", "", B, "Engine layout", "reverse the x axis", {}},
      {"--flip-y", "", "", B, "Engine layout", "reverse the y axis", {}},
      {"--channels", "", "A,B[,A+B]", B, "Engine layout", "the split sum's channels, in order", {}},
      // Fresnel
      {"--fresnel", "", "MODEL", B | E | C, "Fresnel",
       joinNames(fresnelNames()) + "\n(default one: F = 1; with --fresnel the default tables are albedo, albedo-avg)",
       fresnelNames()},
      {"--f0",
       "",
       "V",
       B | E | C,
       "Fresnel",
       "reflectance at normal incidence, [0, 1] (schlick, f82-tint; default 0.04); V or R,G,B",
       {}},
      {"--eta",
       "",
       "V",
       B | E | C,
       "Fresnel",
       "relative IOR, (0, 100] (dielectric, schlick-tir: default 1.5; conductor)",
       {}},
      {"--k", "", "V", B | E | C, "Fresnel", "extinction coefficient, [0, 100] (conductor)", {}},
      {"--f82",
       "",
       "V",
       B | E | C,
       "Fresnel",
       "tint of Schlick's reflectance at mu = 1/7, [0, 1] (f82-tint; default 1)",
       {}},
      // diffuse
      {"--diffuse", "", "MODEL", B | E | C, "Diffuse",
       joinNames(diffuseNames()) +
           "\n(--table albedo: the model's albedo over (mu, its parameter); splitsum: burley in B)",
       diffuseNames()},
      {"--sigma", "", "S", B | E, "Diffuse", "oren-nayar's roughness, radians in [0, pi/2] (default 0.5)", {}},
      // 3D tables
      {"--param",
       "",
       "P",
       B,
       "3D tables (--table brdf3d)",
       "angles (theta_i, theta_o, phi; default) or rusinkiewicz (theta_h, theta_d, phi_d)",
       {"angles", "rusinkiewicz"}},
      {"--theta-h",
       "",
       "I",
       B,
       "3D tables (--table brdf3d)",
       "rusinkiewicz's theta_h index: linear (default) or sqrt (MERL's)",
       {"linear", "sqrt"}},
      {"--roughness",
       "",
       "R",
       B,
       "3D tables (--table brdf3d)",
       "the specular lobe's perceptual roughness, [0.01, 1] (default 0.5)",
       {}},
      {"--value", "", "V", B, "3D tables (--table brdf3d)", "f (default) or f-cos (f cos theta_i)", {"f", "f-cos"}},
      {"--rho",
       "",
       "V",
       B,
       "3D tables (--table brdf3d)",
       "diffuse albedo with --diffuse (one value or R,G,B in [0, 1]; default 1)",
       {}},
      {"--atlas",
       "",
       "CxR",
       B,
       "3D tables (--table brdf3d)",
       "slices per atlas row and column (default: near-square)",
       {}},
      // energy
      {"--transmission", "", "", E, "Energy", "rough glass: E_R + E_T (--fresnel dielectric --eta V)", {}},
      {"--coupling",
       "",
       "C",
       E,
       "Energy",
       "sum (default) or albedo-scaling: how the diffuse layer joins the specular",
       {"sum", "albedo-scaling"}},
      // convergence
      {"--levels",
       "",
       "L,L..",
       C,
       "Convergence",
       "the quadrature's budgets, an increasing list in 0..5 (default 0,1,2,3)",
       {}},
      {"--samples", "", "N,N..", C, "Convergence", "Monte Carlo sample counts, an increasing list in 1..4194304", {}},
      // scenes
      {"--shard",
       "",
       "I/N",
       P | SB,
       "Scenes",
       "part I of N of the scene's tables (1 <= I <= N <= 4096), for parallel jobs",
       {}},
      {"--list", "", "", P, "Scenes", "print the output paths only", {}},
      {"--force", "", "", SB, "Scenes", "bake every table, up to date or not", {}},
      {"--prune", "", "", SB, "Scenes", "remove tables under -o that the scene no longer needs", {}},
      {"--stamp", "", "FILE", SB, "Scenes", "write FILE when the bake succeeds (a build system's output)", {}},
      // device
      {"--device",
       "",
       "TEXT",
       kDeviceCommands,
       "Device",
       "the first OpenCL device whose name or platform contains TEXT (default: the first CPU device, e.g. PoCL)",
       {}},
      {"--cache-dir",
       "",
       "DIR",
       kDeviceCommands,
       "Device",
       "PoCL's kernel cache (default: $POCL_CACHE_DIR, else ~/.cache/pocl)",
       {}},
      {"--prepare",
       "",
       "DIR",
       kCmdDevices,
       "Device",
       "build the default set's programs and store their binaries in DIR (docs/performance.md)",
       {}},
      // render
      {"--light",
       "",
       "L",
       kCmdRender,
       "Render",
       "furnace (default: the white furnace rows) or quad: spheres over roughness under a rectangle light, "
       "shaded with the LTC tables (docs/ltc.md)",
       {"furnace", "quad"}},
      {"--cell", "", "PX", kCmdRender, "Render", "pixels per sphere's square, 16..256 (default 48)", {}},
      {"--columns", "", "N", kCmdRender, "Render", "roughness steps from 0 to 1, 2..33 (default 11)", {}},
      {"--rows",
       "",
       "R[,R..]",
       kCmdRender,
       "Render",
       "single, kulla-conty, single-table, dielectric-lambert, gold, sheen, glass (default: every row the pair "
       "takes, in this order; glass: ggx, beckmann with smith, smith-correlated)",
       {"single", "kulla-conty", "single-table", "dielectric-lambert", "gold", "sheen", "glass"}},
      // shader
      {"--lang", "", "L", kCmdShader, "Shader", "glsl or hlsl", {"glsl", "hlsl"}},
      {"--output", "-o", "OUT", kCmdShader, "Shader", "write the code to OUT instead of stdout", {}},
      {"--at", "", "A,B,C", kCmdSample, "Sample", "the point, three angles in degrees", {}},
      {"--help", "-h", "", ~0u, "Help", "this help", {}},
  };
}

}  // namespace

const std::vector<OptionInfo>& optionInfos() {
  static const std::vector<OptionInfo> o = makeOptionsWithOwnHelp();
  return o;
}

const OptionInfo* findOption(const std::string& opt) {
  for (const auto& o : optionInfos())
    if (o.name == opt || (!o.alias.empty() && o.alias == opt)) return &o;
  return nullptr;
}

}  // namespace brdfbake
