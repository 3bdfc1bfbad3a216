// Every subcommand and option of the command line, in two tables (commands.cpp, option_table.cpp). Each subcommand's
// --help, the check that an option belongs to the command it is given to, "did you mean" for misspelt commands and
// options, and the bash completion script are generated from them, so that they cannot disagree with each other.
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

// One bit per subcommand; an option's `commands` is the set that takes it.
enum CommandBit : unsigned {
  kCmdBake = 1u << 0,
  kCmdEnergy = 1u << 1,
  kCmdVerify = 1u << 2,
  kCmdStress = 1u << 3,
  kCmdConvergence = 1u << 4,
  kCmdPlan = 1u << 5,       // plan SCENE
  kCmdSceneBake = 1u << 6,  // bake SCENE
  kCmdShader = 1u << 7,
  kCmdInfo = 1u << 8,
  kCmdSample = 1u << 9,
  kCmdDevices = 1u << 10,
  kCmdCompletion = 1u << 11,
  kCmdHelp = 1u << 12,
  kCmdRender = 1u << 13,
};

struct CommandInfo {
  std::string name;  // as typed: "bake"; "bake SCENE" for the scene form
  unsigned bit;
  std::string synopsis;               // "brdfbake verify [options]"
  std::string summary;                // one line for the overview
  std::string details;                // what it writes or prints, its exit codes (may be empty)
  std::vector<std::string> examples;  // command lines, each tested (tests/cli_help_test.cpp)
  std::string refusal;                // why another command's option is refused here
};

struct OptionInfo {
  std::string name;                 // "--output"
  std::string alias;                // "-o", or empty
  std::string value;                // "DIR"; empty for a flag
  unsigned commands;                // CommandBit set
  std::string group;                // heading in --help
  std::string help;                 // lines after the first are indented under it
  std::vector<std::string> values;  // the accepted names, for completion (empty: free text)
  // the help for some commands where theirs differs (their CommandBit set, the text): a default or
  // a meaning of their own
  std::vector<std::pair<unsigned, std::string>> helpFor = {};
  // the help this option shows under command `bit`
  const std::string& helpOf(unsigned bit) const {
    for (const auto& [bits, text] : helpFor)
      if (bits & bit) return text;
    return help;
  }
};

const std::vector<CommandInfo>& commandInfos();
const std::vector<OptionInfo>& optionInfos();
// The command named `name` ("bake SCENE" included), or nullptr.
const CommandInfo* findCommand(const std::string& name);
// The option spelt `opt` (name or alias), or nullptr.
const OptionInfo* findOption(const std::string& opt);

// `brdfbake --help`: every command in a line, then the bake options (brdfbake [options] bakes).
std::string overviewHelp();
// `brdfbake COMMAND --help`: its synopsis, what it does, only its options, examples.
std::string commandHelp(const std::string& name);
// " (did you mean 'X'?)" for a refused value of `option`, X the nearest of the names its table
// lists (or the one name the value begins); "" when none is near.
std::string nearestValue(const std::string& option, const std::string& got);
// Every command's help as Markdown, from the same tables: the reference part of docs/commands.md
// (`brdfbake help --markdown`; tests/cli_help_test.cpp fails when the page differs).
std::string markdownHelp();
// `brdfbake completion bash`: a bash completion script for commands, options and names.
std::string bashCompletion();

// Throws Error(kExitUsage): the unknown subcommand with the nearest name, the list of commands.
[[noreturn]] void unknownCommand(const std::string& word);
// Throws Error(kExitUsage) for `opt` given to `command` (its CommandInfo name):
//  - an option of another command: "OPT: not a CMD option (why; brdfbake CMD --help)";
//  - no option at all: "CMD: unknown option 'OPT' (did you mean --x?); brdfbake CMD --help lists them".
[[noreturn]] void refuseOption(const std::string& command, const std::string& opt);
// Whether `command` takes `opt` (a name or alias).
bool takesOption(const std::string& command, const std::string& opt);

}  // namespace brdfbake
