#include "cli/args.h"
#include "cli/commands.h"
#include "cli/layout_args.h"
#include "cli/render_args.h"
#include "cli/scene_args.h"
#include "cli/tool_args.h"
#include "cli/volume_args.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "tables/registry.h"

namespace brdfbake {

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

namespace {

// The albedo kinds (a Fresnel model's or a measured material's default tables), or the first of
// them alone (convergence measures one kind).
std::vector<TableKind> albedoKinds(bool firstOnly) {
  std::vector<TableKind> v = kindsWhere([](const KindInfo& k) { return k.albedo; });
  if (firstOnly) v.resize(1);
  return v;
}

int parseSize(const std::string& text) {
  errno = 0;
  char* end = nullptr;
  long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < kMinSize || v > kMaxSize)
    throw Error(kExitUsage, "--size must be an integer in " + std::to_string(kMinSize) + ".." +
                                std::to_string(kMaxSize) + ", got " + text);
  return static_cast<int>(v);
}

template <class T>
void addUnique(std::vector<T>& v, T x) {
  if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
}

// --format and --precision together: every format named must hold the precision asked for
// (png16 is unorm16 with its own mapping; exr stores float32 or float16), and PNG is 2D only.
void checkFormatOptions(BakeRequest& req) {
  if (req.layoutPreset) {  // a layout preset's format and precision, where the request gives none
    const LayoutPreset& lp = layoutPreset(*req.layoutPreset);
    if (req.formats.empty()) req.formats = {lp.format};
    // a DDS holds no metadata: its KTX2 twin (the same texels) is what info and shader read
    if (req.formats == std::vector<FileFormat>{FileFormat::Dds}) req.formats.push_back(FileFormat::Ktx2);
    if (!req.precision && formatHolds(req.formats[0], lp.precision)) req.precision = lp.precision;
  }
  if (req.formats.empty() && !req.volume.merl) req.formats = {FileFormat::Exr};
  if (req.precision)
    for (FileFormat f : req.formats)
      if (!formatHolds(f, *req.precision))
        throw Error(kExitUsage,
                    "--precision " + precisionName(*req.precision) + ": --format " + formatName(f) +
                        (f == FileFormat::Exr ? " stores float32 or float16 (ktx2, dds and header store all four)"
                                              : " stores unorm16 only (its values mapped onto [0, 1]); leave "
                                                "--precision out or give unorm16"));
  const bool png = std::find(req.formats.begin(), req.formats.end(), FileFormat::Png16) != req.formats.end();
  if (png && std::any_of(req.tables.begin(), req.tables.end(), [](TableKind t) { return kindInfo(t).volume; }))
    throw Error(kExitUsage,
                "--format png16: a 3D table (brdf3d) has no PNG form (PNG is 2D); use ktx2 or dds (3D "
                "textures), exr (an atlas of slices) or header");
}

}  // namespace

Command parseArgs(const std::vector<std::string>& rawArgs) {
  Command cmd;
  // GNU style --opt=value is the same as --opt value
  std::vector<std::string> args;
  for (const auto& a : rawArgs) {
    size_t eq = a.find('=');
    if (a.rfind("--", 0) == 0 && eq != std::string::npos && eq > 2) {
      args.push_back(a.substr(0, eq));
      args.push_back(a.substr(eq + 1));
    } else {
      args.push_back(a);
    }
  }
  if (args.empty()) {
    cmd.bake = defaultRequest();
    return cmd;
  }
  size_t i = 0;
  const std::string& first = args[0];
  const bool isCommand = first.rfind("-", 0) != 0;
  if (isCommand && !findCommand(first)) unknownCommand(first);
  // help: `help [COMMAND]`, `--help`, or -h/--help anywhere after a command (SCENE or not)
  if (first == "help") {
    if (args.size() > 2) throw Error(kExitUsage, "help: expected at most one command name, e.g. brdfbake help bake");
    const bool self = args.size() == 2 && (args[1] == "--help" || args[1] == "-h");  // help's own help
    if (args.size() == 2 && args[1] == "--markdown") {  // every command's help as Markdown (docs/commands.md)
      cmd.kind = Command::Kind::Help;
      cmd.helpFor = "--markdown";
      return cmd;
    }
    if (args.size() == 2 && !self && !findCommand(args[1])) unknownCommand(args[1]);
    cmd.kind = Command::Kind::Help;
    cmd.helpFor = self ? "help" : args.size() == 2 ? args[1] : "";
    return cmd;
  }
  for (const auto& a : args)
    if (a == "--help" || a == "-h") {
      cmd.kind = Command::Kind::Help;
      cmd.helpFor = isCommand ? first : "";
      return cmd;
    }
  if (first == "--version") {
    cmd.kind = Command::Kind::Version;
    return cmd;
  }
  if (parseToolCommand(args, cmd)) return cmd;
  if (parseSceneCommand(args, cmd)) return cmd;
  if (parseRenderCommand(args, cmd)) return cmd;
  BakeRequest req;
  // --fresnel and its parameters as given (the parameters may come first); the request holds the
  // Fresnel only when --fresnel names one
  FresnelChoice fresnel;
  bool fresnelGiven = false;
  std::vector<std::string> volumeFlags;  // the brdf3d-only options given (cli/volume_args.h)
  if (first == "bake") {
    i = 1;
  } else if (first == "energy") {
    i = 1;
    cmd.kind = Command::Kind::Energy;
  } else if (first == "verify") {
    i = 1;
    cmd.kind = Command::Kind::Verify;
  } else if (first == "stress") {
    i = 1;
    cmd.kind = Command::Kind::Stress;
  } else if (first == "convergence") {
    i = 1;
    cmd.kind = Command::Kind::Convergence;
  }
  const std::string command = isCommand ? first : "bake";
  // `brdfbake [options]` is `brdfbake bake [options]`: every bake option works at the top level.
  std::vector<std::string> seen;  // scalar options given so far: each at most once
  auto once = [&](const std::string& opt, const std::string& canonical) {
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end())
      throw Error(kExitUsage, opt + " given twice; give it once");
    seen.push_back(canonical);
  };
  std::string gridName;
  for (; i < args.size(); ++i) {
    const std::string& opt = args[i];
    // the option's value: the next argument, unless that is another option (a negative number is
    // a value, so that --size -5 is answered with the range)
    auto value = [&]() -> const std::string& {
      bool next = i + 1 < args.size();
      bool looksLikeOption = next && args[i + 1].size() > 1 && args[i + 1][0] == '-' &&
                             !std::isdigit(static_cast<unsigned char>(args[i + 1][1]));
      if (!next || looksLikeOption) throw Error(kExitUsage, opt + ": missing value");
      return args[++i];
    };
    if (!takesOption(command, opt)) refuseOption(command, opt);
    if (opt == "--ndf") {
      for (const auto& n : splitCommas(value())) addUnique(req.ndfs, ndfId(n));
    } else if (opt == "--gaf") {
      for (const auto& n : splitCommas(value())) addUnique(req.gafs, gafId(n));
    } else if (opt == "--table") {
      for (const auto& n : splitCommas(value())) addUnique(req.tables, tableKind(n));
    } else if (opt == "--size") {
      once(opt, "--size");
      const std::string& v = value();
      if (v.find(',') == std::string::npos) {
        req.size = parseSize(v);
      } else {
        parseVolumeSize(v, req, volumeFlags);
      }
    } else if (parseVolumeOption(opt, value, req, volumeFlags)) {
      // a brdf3d option (cli/volume_args.cpp)
    } else if (parseLayoutOption(
                   opt, value, [&](const std::string& o) { once(o, o); }, req)) {
      // --layout, --axes, --flip-x, --flip-y, --channels, --mu-axis (cli/layout_args.cpp)
    } else if (opt == "--grid") {
      once(opt, "--grid");
      gridName = value();
      if (gridName == "node")
        req.nodeGrid = true;
      else if (gridName == "texel-center")
        req.nodeGrid = false;
      else
        throw Error(kExitUsage,
                    "--grid must be texel-center or node, got '" + gridName + "'" + nearestValue("--grid", gridName));
    } else if (opt == "--half" || opt == "--precision") {
      // --half is --precision float16
      if (std::find(seen.begin(), seen.end(), "--precision") != seen.end())
        throw Error(kExitUsage, opt + ": --half is --precision float16; give one of them, once");
      seen.push_back("--precision");
      if (opt == "--half") seen.push_back("--half");
      req.precision = opt == "--half" ? Precision::Float16 : parsePrecision(opt, value());
    } else if (opt == "--format") {
      once(opt, "--format");
      for (const auto& n : splitCommas(value())) {
        if (n == "merl") {
          req.volume.merl = true;
          volumeFlags.push_back("--format merl");
        } else {
          addUnique(req.formats, parseFormat(opt, n));
        }
      }
      if (req.volume.merl && !req.formats.empty())
        throw Error(kExitUsage,
                    "--format merl writes MERL's binary file alone (brdf3d only); give it without other formats");
    } else if (opt == "-o" || opt == "--output") {
      once(opt, "--output");
      req.outDir = value();
      if (req.outDir.empty()) throw Error(kExitUsage, opt + ": empty directory name");
      cmd.outputGiven = true;
    } else if (opt == "--no-wait") {
      once(opt, opt);
      req.noWait = true;
    } else if (opt == "--progress") {
      cmd.progress = true;
    } else if (opt == "--dry-run") {
      once(opt, opt);
      cmd.dryRun = true;
    } else if (opt == "--timings" || opt == "--quiet") {
      once(opt, opt);
      (opt == "--timings" ? cmd.timings : cmd.quiet) = true;
    } else if (opt == "--device") {
      once(opt, "--device");
      req.device = value();
    } else if (opt == "--cache-dir") {
      once(opt, "--cache-dir");
      req.cacheDir = value();
      if (req.cacheDir.empty()) throw Error(kExitUsage, "--cache-dir: empty directory name");
    } else if (opt == "--fresnel") {
      once(opt, "--fresnel");
      fresnel.model = fresnelId(value());
      fresnelGiven = true;
    } else if (opt == "--sigma") {
      once(opt, opt);
      std::vector<double> v = parseValues(opt, value());
      if (v.size() != 1 || v[0] < 0 || v[0] > 1.5707963267948966)
        throw Error(kExitUsage, "--sigma must be one angle in [0, 1.5708] (radians, 0..pi/2)");
      req.sigma = v[0];
    } else if (opt == "--eta-range") {
      once(opt, opt);
      const std::string text = value();
      std::vector<double> v;
      for (const auto& item : splitCommas(text)) {
        char* end = nullptr;
        double x = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !std::isfinite(x)) v.clear();
        if (item.empty() || *end != '\0' || !std::isfinite(x)) break;
        v.push_back(x);
      }
      if (v.size() != 2 || !(v[0] > 0) || !(v[1] > v[0]) || v[1] > 100)
        throw Error(kExitUsage,
                    "--eta-range must be LO,HI with 0 < LO < HI <= 100 (the relative IOR eta_t/eta_i; "
                    "below 1 leaves the denser medium), got '" +
                        text + "'");
      req.etaRange = std::make_pair(v[0], v[1]);
    } else if (opt == "--transmission") {
      once(opt, opt);
      cmd.energy.transmission = true;
    } else if (opt == "--coupling") {
      once(opt, opt);
      cmd.energy.coupling = value();
      if (cmd.energy.coupling != "sum" && cmd.energy.coupling != "albedo-scaling")
        throw Error(kExitUsage, "--coupling must be sum or albedo-scaling, got '" + cmd.energy.coupling + "'" +
                                    nearestValue("--coupling", cmd.energy.coupling));
    } else if (opt == "--levels" || opt == "--samples") {
      // a budget ladder: increasing integers in range
      once(opt, opt);
      bool lv = opt == "--levels";
      long lo = lv ? 0 : 1, hi = lv ? 5 : 1 << 22;
      std::string range = lv ? "0..5" : "1..4194304";
      std::vector<int> ladder;
      for (const auto& item : splitCommas(value())) {
        errno = 0;
        char* end = nullptr;
        long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || errno != 0 || v < lo || v > hi)
          throw Error(kExitUsage, opt + " must be a comma-separated, increasing list of integers in " + range +
                                      ", got '" + item + "'");
        if (!ladder.empty() && v <= ladder.back())
          throw Error(kExitUsage, opt + " must be increasing (a ladder of budgets), got " + std::to_string(v) +
                                      " after " + std::to_string(ladder.back()));
        ladder.push_back(static_cast<int>(v));
      }
      (lv ? cmd.ladder.levels : cmd.ladder.samples) = ladder;
    } else if (opt == "--preset") {
      once(opt, "--preset");
      req.preset = value();
      if (req.preset != "gltf")
        throw Error(kExitUsage, "--preset: unknown preset '" + req.preset + "'" + nearestValue("--preset", req.preset) +
                                    "; valid: gltf");
    } else if (opt == "--brdf") {
      once(opt, "--brdf");
      const std::string& v = value();
      if (v.rfind("merl:", 0) != 0 || v.size() == 5)
        throw Error(kExitUsage,
                    "--brdf must be merl:FILE.binary (a measured material in MERL's layout), got '" + v + "'");
      req.merl = v.substr(5);
    } else if (opt == "--diffuse") {
      once(opt, "--diffuse");
      req.diffuse = diffuseId(value());
    } else if (opt == "--f0" || opt == "--eta" || opt == "--k" || opt == "--f82") {
      once(opt, opt);
      std::vector<double>& slot = opt == "--f0"    ? fresnel.f0
                                  : opt == "--eta" ? fresnel.eta
                                  : opt == "--k"   ? fresnel.k
                                                   : fresnel.f82;
      slot = parseValues(opt, value());
    } else {
      throw Error(kExitSoftware, "internal: " + opt + " is in the option table (cli/option_table.cpp) but not parsed");
    }
  }
  checkFormatOptions(req);
  BakeRequest def = defaultRequest();
  const bool modelsGiven = !req.ndfs.empty() || !req.gafs.empty() || req.diffuse >= 0;
  if (!req.merl.empty()) {
    // a measured material: the data is the whole material, and only the 2D tables' kinds have a form
    if (cmd.kind != Command::Kind::Bake && cmd.kind != Command::Kind::Convergence)
      throw Error(kExitUsage, "--brdf: only bake and convergence take a measured material");
    if (modelsGiven || fresnelGiven || !fresnel.f0.empty() || !fresnel.eta.empty() || !fresnel.k.empty() ||
        !fresnel.f82.empty())
      throw Error(kExitUsage, "--brdf merl:" + req.merl +
                                  ": the measured data is the whole material; --ndf, --gaf, "
                                  "--fresnel, --diffuse and their parameters do not apply");
    if (req.tables.empty()) req.tables = albedoKinds(cmd.kind == Command::Kind::Convergence);
    const std::vector<TableKind> measured = kindsFor(req);  // the measured family's kinds
    for (TableKind t : req.tables)
      if (std::find(measured.begin(), measured.end(), t) == measured.end())
        throw Error(kExitUsage, "--brdf merl:" + req.merl + ": --table " + tableName(t) +
                                    " has no measured form; a measured material bakes " + kindNames(measured));
  }
  if (!req.preset.empty()) {
    // the preset names its own models and tables (plan/plan.cpp makePresetPlan)
    if (modelsGiven || fresnelGiven || !req.tables.empty() || !req.merl.empty())
      throw Error(kExitUsage, "--preset " + req.preset +
                                  " bakes its own models and tables; --ndf, --gaf, --table, "
                                  "--fresnel, --diffuse and --brdf do not apply (--size, --grid, --half, -o do)");
    req.ndfs = {NDF_GGX, NDF_CHARLIE};
    req.gafs = {GAF_SMITH_CORRELATED, GAF_NEUBELT, GAF_CHARLIE_SMITH};
    req.tables = kindsWhere([](const KindInfo& k) { return k.muRAxes; });  // the preset's split sums and albedos
  }
  // the sheen NDF alone without --gaf: its own visibility (the default smith-correlated does not pair)
  if (req.gafs.empty() && !req.ndfs.empty() && std::all_of(req.ndfs.begin(), req.ndfs.end(), isSheenNdf))
    req.gafs = {GAF_CHARLIE_SMITH};
  if (req.ndfs.empty()) req.ndfs = def.ndfs;
  if (req.gafs.empty()) req.gafs = def.gafs;
  if (req.preset.empty() && req.merl.empty()) {
    // every pair of the product must be a model: a sheen visibility with a non-sheen NDF, or charlie
    // with a microfacet GAF, is refused here, before anything is computed or written
    for (int n : req.ndfs)
      for (int g : req.gafs) checkPair(n, g);
    bool sheen = std::any_of(req.ndfs.begin(), req.ndfs.end(), isSheenNdf);
    if (sheen && (fresnelGiven || req.diffuse >= 0))
      throw Error(kExitUsage,
                  std::string(fresnelGiven ? "--fresnel" : "--diffuse") +
                      ": the sheen NDF (charlie) has no Fresnel or diffuse form (KHR_materials_sheen: F = 1, "
                      "the sheen colour scales the lobe); bake charlie without it");
  }
  if (cmd.kind == Command::Kind::Energy) {
    if (req.sigma && req.diffuse != DIFFUSE_OREN_NAYAR && req.diffuse != DIFFUSE_OREN_NAYAR_AS_PRINTED)
      throw Error(kExitUsage, "--sigma: only --diffuse oren-nayar and oren-nayar-as-printed take it");
    if (cmd.energy.transmission && (fresnel.model != FRESNEL_DIELECTRIC || req.diffuse >= 0))
      throw Error(kExitUsage, "--transmission: rough glass takes --fresnel dielectric (its --eta) and no --diffuse");
  }
  if (cmd.kind == Command::Kind::Convergence) {
    if (req.tables.size() > 1)
      throw Error(kExitUsage,
                  "--table: convergence measures one table kind at a time, got " + std::to_string(req.tables.size()));
    if (req.tables.empty()) req.tables = albedoKinds(true);
  }
  if (req.sigma && cmd.kind == Command::Kind::Bake) {
    if (req.diffuse != DIFFUSE_OREN_NAYAR && req.diffuse != DIFFUSE_OREN_NAYAR_AS_PRINTED)
      throw Error(kExitUsage, "--sigma: only --diffuse oren-nayar and oren-nayar-as-printed take it");
    volumeFlags.push_back("--sigma");
  }
  validateVolumeOptions(cmd.kind == Command::Kind::Bake, req, volumeFlags);
  if (!req.tables.empty()) {
  } else if (req.diffuse >= 0) {
    req.tables = kindsWhere([](const KindInfo& k) { return k.albedo && k.muRAxes; });  // the diffuse model's albedo
  } else if (fresnelGiven) {
    req.tables = albedoKinds(false);  // the tables a Fresnel model enters
  } else if (req.layoutPreset || !req.layout.identity()) {
    req.tables = kindsWhere([](const KindInfo& k) { return k.layouts; });  // the one table a layout arranges
  } else if (req.muSqrt.value_or(false)) {
    req.tables = kindsWhere([](const KindInfo& k) { return k.muRAxes; });  // the tables over (mu, r)
  } else {
    req.tables = def.tables;
  }
  if (!fresnelGiven && (!fresnel.f0.empty() || !fresnel.eta.empty() || !fresnel.k.empty() || !fresnel.f82.empty()))
    throw Error(kExitUsage, "--f0, --eta, --k and --f82 need --fresnel MODEL (" + joinNames(fresnelNames()) + ")");
  validateFresnel(fresnel);
  if (fresnelGiven) req.fresnel = fresnel;
  validateMuAxis(!gridName.empty(), req);
  if (req.nodeGrid && req.size && *req.size < 2)
    throw Error(kExitUsage, "--size must be at least 2 on the node grid, got " + std::to_string(*req.size));
  cmd.bake = req;
  return cmd;
}

}  // namespace brdfbake
