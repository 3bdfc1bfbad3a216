#include "cli/commands.h"

namespace brdfbake {

namespace {

std::vector<CommandInfo> makeCommands() {
  return {
      {"bake",
       kCmdBake,
       "brdfbake bake [options]   (or brdfbake [options])",
       "bake tables (default: ggx + smith-correlated, the four default tables, into out/)",
       "Bakes the product of --ndf x --gaf x --table into -o DIR, one file per format; the files land "
       "together or not at all. brdfbake bake SCENE bakes a scene's tables instead (brdfbake plan --help).",
       {"brdfbake bake --table splitsum --size 64 -o out/lut", "brdfbake bake --layout filament -o out/filament",
        "brdfbake bake --ndf ggx --gaf smith-correlated --fresnel dielectric --eta 1.5 -o out/glass"},
       ""},
      {"bake SCENE",
       kCmdSceneBake,
       "brdfbake bake SCENE [options]",
       "bake what a scene (.toml manifest, .gltf/.glb) needs that is new or changed",
       "Bakes the tables the scene's materials use and that are missing or out of date under -o DIR;\n"
       "docs/scenes.md lists the manifest's keys.",
       {"brdfbake bake examples/scenes/pbr-desktop.toml -o out/scene"},
       "the tables come from the scene: brdfbake plan SCENE lists them, baking nothing; docs/scenes.md"},
      {"plan",
       kCmdPlan,
       "brdfbake plan SCENE [options]",
       "the tables a scene needs, why, their cost, and what is up to date",
       "Prints one line per table (or, with --list, only the output paths); writes nothing.",
       {"brdfbake plan examples/scenes/pbr-desktop.toml -o out/scene"},
       "plan writes nothing; the tables come from the scene"},
      {"energy",
       kCmdEnergy,
       "brdfbake energy [options]",
       "does a whole material conserve energy? the worst total albedo over (mu, r, parameter)",
       "Exit 0 if the material conserves energy, 1 if it does not; writes no tables. With -o DIR, also\n"
       "a page with the worst points and each pair's white furnace render in DIR/energy.",
       {"brdfbake energy --fresnel dielectric --eta 1.5 --diffuse lambert --coupling albedo-scaling",
        "brdfbake energy --transmission --fresnel dielectric --eta 1.5"},
       "energy writes no tables: its page goes to -o DIR"},
      {"verify",
       kCmdVerify,
       "brdfbake verify [options]",
       "white and weak furnace, normalisation, reciprocity, energy loss of --ndf x --gaf pairs",
       "Writes a page with plots to DIR/verify (default out/verify); exit 1 when a check fails.",
       {"brdfbake verify --ndf ggx,beckmann --gaf smith-correlated -o out"},
       "verify checks NDF/GAF pairs: --ndf, --gaf, --size, -o"},
      {"stress",
       kCmdStress,
       "brdfbake stress [options]",
       "every table kind through the stiff and extreme cases, against the reference",
       "Writes a page to DIR/stress; exit 1 on NaN/Inf, a missed limit or an error over its bound.",
       {"brdfbake stress -o out"},
       "stress sweeps fixed stiff cases: -o, --device"},
      {"convergence",
       kCmdConvergence,
       "brdfbake convergence [options]",
       "error against run time of each method that computes --table KIND, against its reference",
       "One table kind (default albedo; any kind, or --brdf merl:FILE) for one pair; writes a page to\n"
       "DIR/convergence (docs/convergence.md).",
       {"brdfbake convergence --table splitsum --ndf ggx --gaf smith-correlated -o out"},
       "it measures one --table of one --ndf/--gaf/--fresnel (or --diffuse for ltc); --size, --levels, --samples, -o"},
      {"shader",
       kCmdShader,
       "brdfbake shader --lang glsl|hlsl FILE... [-o OUT]",
       "lookup functions for tables (grid, axes, atlas and channels built in)",
       "FILE: .exr, .ktx2, .png, .h/.mjs, or .dds beside its .ktx2/.exr twin; prints to stdout without -o.",
       {"brdfbake shader --lang glsl out/splitsum_ggx_smith-correlated.exr"},
       "shader reads tables: --lang, -o"},
      {"info",
       kCmdInfo,
       "brdfbake info FILE",
       "a table's metadata and value range (.exr, .ktx2, .dds, .png, .h, .mjs)",
       "",
       {"brdfbake info out/albedo_ggx_smith-correlated.exr"},
       "info takes one file"},
      {"sample",
       kCmdSample,
       "brdfbake sample FILE.exr --at A,B,C",
       "a brdf3d table's trilinear lookup next to the exact BRDF at a point, in degrees",
       "A,B,C: (theta_i, theta_o, phi) or (theta_h, theta_d, phi_d), as the table's --param.",
       {"brdfbake sample out/brdf3d_ggx_smith-correlated_angles.exr --at 30,45,90"},
       "sample takes FILE --at A,B,C"},
      {"render",
       kCmdRender,
       "brdfbake render [options]",
       "the white furnace through GL: spheres over roughness, a material per row, measured",
       "Bakes the tables into DIR/tables, shades every pixel on OpenGL ES 3.1 (EGL; llvmpipe without a GPU)\n"
       "with the generated lookup code, writes DIR/furnace.exr (linear) and DIR/furnace.png (sRGB, labelled), and\n"
       "prints each row's largest deviation from 1 or from the reference against a bound built from the texels each\n"
       "pixel's lookup reads: exit 1 when a pixel is past its bound.\n"
       "DIR/lobe.exr, DIR/lobe.png: spheres under a directional light, single scattering above, the\n"
       "Kulla-Conty lobe added below.\n"
       "Rows: single, kulla-conty, single-table, dielectric-lambert, gold, sheen, glass (docs/reports.md);\n"
       "--ndf/--gaf choose the pair the microfacet and glass rows shade (default ggx + smith-correlated).",
       {"brdfbake render -o out/render", "brdfbake render --rows single,kulla-conty --columns 6 -o out/render",
        "brdfbake render --ndf beckmann --gaf smith -o out/render-beckmann"},
       "render draws the furnace: -o, --ndf, --gaf, --cell, --columns, --rows, --device"},
      {"devices",
       kCmdDevices,
       "brdfbake devices [--prepare DIR]",
       "the OpenCL platforms and devices, and the programs prepared for each",
       "Lists each device with the programs whose binaries are ready for it (loaded instead of built).\n"
       "--prepare DIR builds the default set's programs on --device and stores their binaries in DIR\n"
       "(the build does this into build/programs; cmake --install ships them).",
       {"brdfbake devices", "brdfbake devices --prepare build/programs"},
       "devices lists devices and prepares programs: --prepare, --device, --cache-dir"},
      {"completion",
       kCmdCompletion,
       "brdfbake completion bash",
       "a bash completion script for brdfbake",
       "Load it in the current shell with: source <(brdfbake completion bash)",
       {"brdfbake completion bash"},
       "completion takes the shell's name"},
      {"help",
       kCmdHelp,
       "brdfbake help [COMMAND]",
       "this overview, or one command's options (= COMMAND --help)",
       "",
       {"brdfbake help bake"},
       "help takes a command's name"},
  };
}

}  // namespace

const std::vector<CommandInfo>& commandInfos() {
  static const std::vector<CommandInfo> c = makeCommands();
  return c;
}

const CommandInfo* findCommand(const std::string& name) {
  for (const auto& c : commandInfos())
    if (c.name == name) return &c;
  return nullptr;
}

bool takesOption(const std::string& command, const std::string& opt) {
  const CommandInfo* c = findCommand(command);
  if (!c) return false;
  for (const auto& o : optionInfos())
    if ((o.name == opt || (!o.alias.empty() && o.alias == opt)) && (o.commands & c->bit)) return true;
  return false;
}

}  // namespace brdfbake
