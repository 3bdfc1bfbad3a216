// The command line helps: every subcommand has its own --help listing only its options and
// examples that parse; misspelt commands, options and names get the nearest one; another
// command's option is refused naming the command; the bash completion script completes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/args.h"
#include "cli/commands.h"
#include "cli_run.h"
#include "common/errors.h"

namespace fs = std::filesystem;
using namespace brdfbake;
using namespace brdfbake::testing_cli;

namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

bool mentions(const std::string& text, const std::string& opt) {
  // the option as a whole word in an option line: "  --ndf NAME" or "  -o, --output DIR"
  return text.find("  " + opt + " ") != std::string::npos || text.find("  " + opt + "\n") != std::string::npos ||
         text.find(", " + opt + " ") != std::string::npos;
}

}  // namespace

TEST(CliHelp, EveryCommandListsOnlyItsOptionsAndExamplesThatParse) {
  for (const CommandInfo& c : commandInfos()) {
    if (c.name.find(' ') != std::string::npos) continue;  // bake SCENE: shown in bake's help
    for (const std::string& form : {c.name + " --help", "help " + c.name, c.name + " -h"}) {
      CmdResult r = run(form);
      EXPECT_EQ(r.code, 0) << form << "\n" << r.out;
      EXPECT_EQ(r.out.rfind("usage: " + c.synopsis, 0), 0u) << form << "\n" << r.out;
      EXPECT_NE(r.out.find("examples:\n  brdfbake "), std::string::npos) << form;
      const unsigned bits = c.bit | (c.bit == kCmdBake ? kCmdSceneBake : 0u);
      for (const OptionInfo& o : optionInfos()) {
        if (o.name == "--help") continue;
        const bool own = (o.commands & bits) != 0;
        // an option some other command shares under the same name (-o) is listed by either entry
        bool sharedName = false;
        for (const OptionInfo& p : optionInfos()) sharedName |= p.name == o.name && (p.commands & bits);
        if (own) {
          EXPECT_TRUE(mentions(r.out, o.name)) << c.name << " --help omits " << o.name;
        } else if (!sharedName) {
          EXPECT_FALSE(mentions(r.out, o.name)) << c.name << " --help lists " << o.name;
        }
      }
    }
    // every example parses (nothing runs: the files it names need not exist)
    for (const std::string& e : c.examples) {
      std::vector<std::string> w = words(e);
      ASSERT_EQ(w[0], "brdfbake");
      w.erase(w.begin());
      EXPECT_NO_THROW(parseArgs(w)) << e;
    }
  }
  // energy's options are energy's: no table or output options in its help
  CmdResult r = run("energy --help");
  for (const char* o : {"--table", "--format", "--grid", "--layout", "--levels"})
    EXPECT_FALSE(mentions(r.out, o)) << o << "\n" << r.out;
  for (const char* o : {"--ndf", "--fresnel", "--diffuse", "--coupling", "--transmission"})
    EXPECT_TRUE(mentions(r.out, o)) << o << "\n" << r.out;
  // the overview names every command and the bake options
  r = run("--help");
  EXPECT_EQ(r.code, 0);
  for (const CommandInfo& c : commandInfos()) {
    if (c.name.find(' ') != std::string::npos) continue;  // "bake SCENE" is listed under bake
    EXPECT_NE(r.out.find("\n  " + c.name + " "), std::string::npos) << c.name;
  }
  EXPECT_TRUE(mentions(r.out, "--table"));
  EXPECT_EQ(run("help").out, r.out);
}

TEST(CliHelp, SuggestsTheNearestNameAndWritesNothing) {
  const fs::path d = freshDir("help", "suggest", false);
  const std::string o = " -o '" + d.string() + "'";
  struct Case {
    std::string args, says;
  } cases[] = {
      {"bak", "unknown command 'bak' (did you mean 'bake'?)"},
      {"convergance --table albedo", "(did you mean 'convergence'?)"},
      {"help bakk", "(did you mean 'bake'?)"},
      {"bake --tabel splitsum" + o, "bake: unknown option '--tabel' (did you mean '--table'?)"},
      {"--sise 8" + o, "(did you mean '--size'?)"},
      {"verify --ndff ggx" + o, "verify: unknown option '--ndff' (did you mean '--ndf'?)"},
      {"--ndf gxx" + o, "--ndf: unknown NDF 'gxx' (did you mean 'ggx'?)"},
      {"--gaf smith-corelated" + o, "(did you mean 'smith-correlated'?)"},
      {"--table splitsun" + o, "--table: unknown table 'splitsun' (did you mean 'splitsum'?)"},
      {"--layout filamnet" + o, "--layout: unknown preset 'filamnet' (did you mean 'filament'?)"},
      {"--format ktx" + o, "(did you mean 'ktx2'?)"},
      {"--precision flaot16" + o, "(did you mean 'float16'?)"},
      {"--fresnel schlik" + o, "(did you mean 'schlick'?)"},
      {"--table albedo --diffuse lamberd" + o, "(did you mean 'lambert'?)"},
      // values of every option with a fixed set of names, whichever parser refuses them
      {"--grid nodes" + o, "--grid must be texel-center or node, got 'nodes' (did you mean 'node'?)"},
      {"--mu-axis sqr" + o, "got 'sqr' (did you mean 'sqrt'?)"},
      {"--preset gltff" + o, "--preset: unknown preset 'gltff' (did you mean 'gltf'?)"},
      {"shader --lang gls x.exr", "--lang must be glsl or hlsl, got 'gls' (did you mean 'glsl'?)"},
      {"energy --coupling albedo-scale", "got 'albedo-scale' (did you mean 'albedo-scaling'?)"},
      {"render --rows kulla" + o, "--rows: unknown row 'kulla' (did you mean 'kulla-conty'?)"},
      // a short option: its own case, not a long option two edits away ('-O' had been offered '--k')
      {"-O out", "bake: unknown option '-O' (did you mean '-o'?)"},
      // another command's option: refused naming this command and its help
      {"verify --format exr" + o, "--format: not a verify option"},
      {"energy --table albedo", "--table: not an energy option (energy writes no tables"},
      {"stress --ndf ggx" + o, "--ndf: not a stress option"},
      {"shader --lang glsl x.exr --ndf ggx", "--ndf: not a shader option"},
      {"plan scene.toml --table albedo", "--table: not a plan option"},
      // bake gives no reason of its own: the commands that take the option instead
      {"bake --at 1,2,3" + o, "--at: not a bake option (sample takes it; brdfbake bake --help lists them)"},
  };
  for (const Case& c : cases) {
    CmdResult r = run(c.args);
    EXPECT_EQ(r.code, 64) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.says), std::string::npos) << c.args << "\n" << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one line: " << c.args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(d)) << c.args;
  }
  // nothing close: no suggestion, the list instead
  CmdResult r = run("frobnicate");
  EXPECT_EQ(r.code, 64);
  EXPECT_EQ(r.out.find("did you mean"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("valid: bake, plan"), std::string::npos) << r.out;
}

// The completion script is valid bash and completes commands, each command's own options, and
// names after the options that take them.
TEST(CliHelp, BashCompletionCompletes) {
  const fs::path d = freshDir("help", "completion");
  CmdResult r = run("completion bash");
  ASSERT_EQ(r.code, 0) << r.out;
  const fs::path script = d / "brdfbake.bash";
  std::ofstream(script) << r.out;
  auto complete = [&](const std::string& line) {
    // COMP_WORDS from the line; the cursor on its last word (empty after a trailing space)
    const CmdResult c = shell("bash -c 'source \"" + script.string() + "\"; COMP_WORDS=(" + line +
                              "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _brdfbake; echo \"${COMPREPLY[*]}\"'");
    EXPECT_EQ(c.code, 0) << line << "\n" << c.out;
    return c.out;
  };
  EXPECT_EQ(complete("brdfbake ba"), "bake\n");
  EXPECT_EQ(complete("brdfbake conv"), "convergence\n");
  EXPECT_EQ(complete("brdfbake bake --nd"), "--ndf\n");
  EXPECT_EQ(complete("brdfbake bake --ndf g"), "ggx gaussian\n");
  EXPECT_EQ(complete("brdfbake --layout fil"), "filament\n");
  EXPECT_EQ(complete("brdfbake energy --coup"), "--coupling\n");
  EXPECT_EQ(complete("brdfbake energy --tab"), "\n");  // energy takes no --table
  EXPECT_EQ(complete("brdfbake bake --table dielectric"), "dielectric dielectric-avg\n");
  EXPECT_EQ(complete("brdfbake shader --lang h"), "hlsl\n");
}
