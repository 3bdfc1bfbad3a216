// The help texts, the refusals of unknown commands and options, and the bash completion script,
// all made from the command and option tables (cli/commands.cpp).
#include <algorithm>
#include <cctype>
#include <sstream>

#include "cli/commands.h"
#include "common/errors.h"
#include "common/models.h"

namespace brdfbake {

namespace {

// `text`'s lines, each wrapped at spaces to fit 100 columns after `pad`, joined with "\n" + pad.
std::string indent(const std::string& text, const std::string& pad) {
  const size_t width = 100 - pad.size();
  std::string out;
  std::istringstream lines(text);
  bool first = true;
  for (std::string line; std::getline(lines, line);) {
    while (true) {
      size_t cut = line.size() <= width ? std::string::npos : line.rfind(' ', width);
      out += (first ? "" : "\n" + pad) + line.substr(0, cut);
      first = false;
      if (cut == std::string::npos) break;
      line = line.substr(cut + 1);
    }
  }
  return out;
}

// The options of one command, grouped under their headings in table order.
std::string optionsText(unsigned bit) {
  std::string out, group;
  for (const auto& o : optionInfos()) {
    if (!(o.commands & bit) || o.name == "--help") continue;
    if (o.group != group) {
      group = o.group;
      out += "\n" + group + ":\n";
    }
    std::string head = "  " + (o.alias.empty() ? "" : o.alias + ", ") + o.name + (o.value.empty() ? "" : " " + o.value);
    const std::string pad(22, ' ');
    if (head.size() + 2 > pad.size()) head += "\n" + pad;
    else head += std::string(pad.size() - head.size(), ' ');
    out += head + indent(o.help, pad) + "\n";
  }
  return out;
}

const char* const kExitCodes =
    "Exit codes: 0 ok, 1 a check failed (verify, stress, energy), 64 usage, 65 bad input data, 66 unreadable\n"
    "input, 69 no OpenCL device, 70 internal error, 73 cannot create output, 74 write error (e.g. disk full),\n"
    "128+N interrupted by signal N.\n";

std::vector<std::string> visibleCommandNames() {
  std::vector<std::string> v;
  for (const auto& c : commandInfos())
    if (c.name.find(' ') == std::string::npos) v.push_back(c.name);
  return v;
}

}  // namespace

std::string overviewHelp() {
  std::string out = "usage: brdfbake COMMAND [options]   (brdfbake [options] is brdfbake bake [options])\n\ncommands:\n";
  for (const auto& c : commandInfos()) {
    std::string head = "  " + c.name;
    head += std::string(head.size() < 16 ? 16 - head.size() : 1, ' ');
    out += head + c.summary + "\n";
  }
  out += "\n'brdfbake COMMAND --help' lists that command's options with examples. The bake options:\n";
  out += optionsText(kCmdBake);
  out += "\nModels, formulas and table conventions: docs/MODELS.md; every command: docs/commands.md.\n";
  out += kExitCodes;
  return out;
}

std::string commandHelp(const std::string& name) {
  const CommandInfo* c = findCommand(name);
  if (!c) unknownCommand(name);
  std::string out = "usage: " + c->synopsis + "\n\n" + c->summary + "\n";
  if (!c->details.empty()) out += indent(c->details, "") + "\n";
  const std::string opts = optionsText(c->bit);
  out += opts.empty() ? "\n(no options)\n" : opts;
  // bake's help also shows the scene form, whose options differ
  if (c->bit == kCmdBake) {
    const CommandInfo& s = *findCommand("bake SCENE");
    out += "\nusage: " + s.synopsis + "\n" + s.summary + "\n" + optionsText(s.bit);
  }
  out += "\nexamples:\n";
  for (const auto& e : c->examples) out += "  " + e + "\n";
  out += "\n";
  out += kExitCodes;
  return out;
}

void unknownCommand(const std::string& word) {
  const std::vector<std::string> names = visibleCommandNames();
  throw Error(kExitUsage, "unknown command '" + word + "'" + didYouMean(word, names) + "; valid: " + joinNames(names) +
                              " (brdfbake --help)");
}

void refuseOption(const std::string& command, const std::string& opt) {
  const CommandInfo* c = findCommand(command);
  const std::string shown = c && c->bit == kCmdSceneBake ? "bake SCENE" : command;
  const std::string helpCmd = c && c->bit == kCmdSceneBake ? "bake" : command;
  if (const OptionInfo* o = findOption(opt)) {
    const std::string article = std::string("aeiou").find(shown[0]) != std::string::npos ? "an " : "a ";
    // the command's own reason, else the commands that take the option
    std::string why = c ? c->refusal : std::string();
    if (why.empty()) {
      std::vector<std::string> takers;
      for (const auto& k : commandInfos())
        if (o->commands & k.bit) takers.push_back(k.name);
      why = (takers.empty() ? std::string("no command") : joinNames(takers)) + (takers.size() == 1 ? " takes it" : " take it");
    }
    throw Error(kExitUsage, opt + ": not " + article + shown + " option (" + why + "; brdfbake " + helpCmd +
                                " --help lists them)");
  }
  // the nearest of this command's options, else of any command's
  std::vector<std::string> own, all;
  for (const auto& o : optionInfos()) {
    (c && (o.commands & c->bit) ? own : all).push_back(o.name);
  }
  std::string near;
  if (opt.size() == 2 && opt[0] == '-') {
    // a short option: only another short option differing in case (-O for -o), never a long one
    // two edits away (-O had been offered --k)
    for (const auto& o : optionInfos())
      if (c && (o.commands & c->bit) && o.alias.size() == 2 && std::tolower(static_cast<unsigned char>(o.alias[1])) ==
                                                            std::tolower(static_cast<unsigned char>(opt[1])))
        near = " (did you mean '" + o.alias + "'?)";
  } else {
    near = didYouMean(opt, own);
    if (near.empty()) near = didYouMean(opt, all);
  }
  throw Error(kExitUsage, shown + ": unknown option '" + opt + "'" + near + "; brdfbake " + helpCmd +
                              " --help lists its options");
}

std::string bashCompletion() {
  std::string s =
      "# bash completion for brdfbake, generated by `brdfbake completion bash`.\n"
      "# Load it with: source <(brdfbake completion bash)\n"
      "_brdfbake() {\n"
      "  local cur prev cmd i\n"
      "  cur=\"${COMP_WORDS[COMP_CWORD]}\"\n"
      "  prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
      "  cmd=bake\n"
      "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
      "    case \"${COMP_WORDS[i]}\" in -*) ;; *) cmd=\"${COMP_WORDS[i]}\"; break ;; esac\n"
      "  done\n"
      "  case \"$prev\" in\n";
  for (const auto& o : optionInfos()) {
    if (o.values.empty()) continue;
    std::string words;
    for (const auto& v : o.values) words += (words.empty() ? "" : " ") + v;
    s += "    " + o.name + ") COMPREPLY=($(compgen -W \"" + words + "\" -- \"$cur\")); return ;;\n";
  }
  s += "  esac\n"
       "  if [[ $COMP_CWORD -eq 1 && \"$cur\" != -* ]]; then\n"
       "    COMPREPLY=($(compgen -W \"";
  const std::vector<std::string> names = visibleCommandNames();
  for (size_t i = 0; i < names.size(); ++i) s += (i ? " " : "") + names[i];
  s += "\" -- \"$cur\")); return\n"
       "  fi\n"
       "  local opts\n"
       "  case \"$cmd\" in\n";
  for (const auto& c : commandInfos()) {
    if (c.name.find(' ') != std::string::npos) continue;
    unsigned bits = c.bit | (c.bit == kCmdBake ? kCmdSceneBake : 0u);
    std::string words;
    for (const auto& o : optionInfos())
      if (o.commands & bits) {
        if (words.find(o.name + " ") == std::string::npos) words += o.name + " ";
        if (!o.alias.empty() && words.find(o.alias + " ") == std::string::npos) words += o.alias + " ";
      }
    s += "    " + c.name + ") opts=\"" + words + "\" ;;\n";
  }
  s += "    *) opts=\"\" ;;\n"
       "  esac\n"
       "  if [[ \"$cur\" == -* ]]; then COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\")); return; fi\n"
       "  COMPREPLY=($(compgen -f -- \"$cur\"))\n"
       "}\n"
       "complete -o filenames -F _brdfbake brdfbake\n";
  return s;
}

}  // namespace brdfbake
