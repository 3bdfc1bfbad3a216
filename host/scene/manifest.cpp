// The TOML scene manifest (toml++, Debian libtomlplusplus-dev): every key checked, every message
// with file, line and column. The keys are documented in README.md ("Scenes").
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "brdfbake/request.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "common/format.h"
#include "common/models.h"
#include "scene/scene.h"

namespace brdfbake {

std::string SourcePos::str() const { return file + ":" + std::to_string(line) + ":" + std::to_string(column); }

namespace {

struct Reader {
  std::string file;

  SourcePos pos(const toml::node& n) const {
    return {file, static_cast<int>(n.source().begin.line), static_cast<int>(n.source().begin.column)};
  }
  [[noreturn]] void fail(const toml::node& n, const std::string& what) const {
    throw Error(kExitDataErr, pos(n).str() + ": " + what);
  }
  // Every key of `t` must be one of `valid`.
  void keysIn(const toml::table& t, const std::string& where, const std::vector<std::string>& valid) const {
    for (auto&& [k, v] : t) {
      std::string key(k.str());
      if (std::find(valid.begin(), valid.end(), key) != valid.end()) continue;
      std::string near = closestName(key, valid);
      throw Error(
          kExitDataErr,
          SourcePos{file, static_cast<int>(k.source().begin.line), static_cast<int>(k.source().begin.column)}.str() +
              ": unknown key '" + key + "' in " + where + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
              "; valid: " + joinNames(valid));
    }
  }
  const toml::table& table(const toml::node& n, const std::string& what) const {
    if (!n.is_table()) fail(n, what + " must be a table");
    return *n.as_table();
  }
  bool boolean(const toml::node& n, const std::string& what) const {
    if (!n.is_boolean()) fail(n, what + " must be true or false");
    return n.as_boolean()->get();
  }
  std::string string(const toml::node& n, const std::string& what) const {
    if (!n.is_string()) fail(n, what + " must be a string");
    return n.as_string()->get();
  }
  double number(const toml::node& n, const std::string& what, double lo, double hi) const {
    double v;
    if (n.is_integer())
      v = static_cast<double>(n.as_integer()->get());
    else if (n.is_floating_point())
      v = n.as_floating_point()->get();
    else
      fail(n, what + " must be a number in [" + fmtG(lo) + ", " + fmtG(hi) + "]");
    if (!(v >= lo && v <= hi)) fail(n, what + " must be in [" + fmtG(lo) + ", " + fmtG(hi) + "], got " + fmtG(v));
    return v;
  }
  int integer(const toml::node& n, const std::string& what, int lo, int hi) const {
    if (!n.is_integer()) fail(n, what + " must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
    int64_t v = n.as_integer()->get();
    if (v < lo || v > hi)
      fail(n, what + " must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
                  std::to_string(v));
    return static_cast<int>(v);
  }
  // One number, or three (R, G, B).
  std::vector<double> values(const toml::node& n, const std::string& what, double lo, double hi) const {
    if (!n.is_array()) return {number(n, what, lo, hi)};
    const toml::array& a = *n.as_array();
    if (a.size() != 1 && a.size() != 3)
      fail(n, what + " must be one number or three (R, G, B), got " + std::to_string(a.size()));
    std::vector<double> v;
    for (const auto& x : a) v.push_back(number(x, what, lo, hi));
    return v;
  }
  // A name from `names`, by id.
  int name(const toml::node& n, const std::string& what, const std::vector<std::string>& names) const {
    std::string s = string(n, what);
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i] == s) return static_cast<int>(i);
    std::string near = closestName(s, names);
    fail(n, "unknown " + what + " '" + s + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                "; valid: " + joinNames(names));
  }
};

void readOutput(const Reader& r, const toml::table& t, SceneOutput& out) {
  r.keysIn(t, "[output]", {"dir", "precision", "grid", "size"});
  if (auto* n = t.get("dir")) {
    out.dir = r.string(*n, "output.dir");
    if (out.dir.empty()) r.fail(*n, "output.dir must not be empty");
  }
  if (auto* n = t.get("precision")) {
    std::string p = r.string(*n, "output.precision");
    if (p != "float" && p != "half") r.fail(*n, "output.precision must be \"float\" or \"half\", got \"" + p + "\"");
    out.half = p == "half";
  }
  if (auto* n = t.get("grid")) {
    std::string g = r.string(*n, "output.grid");
    if (g != "texel-center" && g != "node")
      r.fail(*n, "output.grid must be \"texel-center\" or \"node\", got \"" + g + "\"");
    out.nodeGrid = g == "node";
  }
  if (auto* n = t.get("size")) {
    // kept as written: the planner checks each key and value against the kind's description
    const toml::table& s = r.table(*n, "output.size");
    auto integerOf = [](const toml::node& v) {
      return v.is_integer() ? std::optional<int64_t>(v.as_integer()->get()) : std::nullopt;
    };
    for (auto&& [k, v] : s) {
      SceneSize e;
      e.kind = std::string(k.str());
      e.keyPos = SourcePos{r.file, static_cast<int>(k.source().begin.line), static_cast<int>(k.source().begin.column)};
      e.valuePos = r.pos(v);
      if (const toml::array* a = v.as_array()) {
        e.array = true;
        for (const toml::node& item : *a) {
          e.itemPos.push_back(r.pos(item));
          e.values.push_back(integerOf(item));
        }
      } else {
        e.values.push_back(integerOf(v));
      }
      out.sizes.push_back(e);
    }
  }
}

void readLighting(const Reader& r, const toml::table& t, SceneLighting& l) {
  r.keysIn(t, "[lighting]", {"ibl", "analytic", "multiscatter"});
  if (auto* n = t.get("ibl")) l.ibl = r.boolean(*n, "lighting.ibl");
  if (auto* n = t.get("analytic")) l.analytic = r.boolean(*n, "lighting.analytic");
  if (auto* n = t.get("multiscatter")) l.multiscatter = r.boolean(*n, "lighting.multiscatter");
}

SceneMaterial readMaterial(const Reader& r, const toml::table& t, int index) {
  static const std::vector<std::string> keys = {"name", "ndf",       "gaf",      "fresnel", "f0",
                                                "eta",  "k",         "f82",      "diffuse", "sigma",
                                                "rho",  "roughness", "coupling", "brdf3d",  "transmission"};
  r.keysIn(t, "[[material]]", keys);
  SceneMaterial m;
  m.pos = r.pos(t);
  if (auto* n = t.get("name")) {
    m.name = r.string(*n, "material.name");
    if (m.name.empty()) r.fail(*n, "material.name must not be empty");
  } else {
    r.fail(t, "material " + std::to_string(index + 1) + " has no name (name = \"...\")");
  }
  if (auto* n = t.get("ndf")) m.ndf = r.name(*n, "NDF", ndfNames());
  if (auto* n = t.get("gaf")) m.gaf = r.name(*n, "GAF", gafNames());
  m.fresnel.model = FRESNEL_SCHLICK;  // glTF's and most engines' default: F0 0.04
  if (auto* n = t.get("fresnel")) m.fresnel.model = r.name(*n, "Fresnel model", fresnelNames());
  const std::pair<const char*, std::vector<double>*> params[] = {
      {"f0", &m.fresnel.f0}, {"eta", &m.fresnel.eta}, {"k", &m.fresnel.k}, {"f82", &m.fresnel.f82}};
  for (auto [key, slot] : params)
    if (auto* n = t.get(key)) *slot = r.values(*n, std::string("material.") + key, 0.0, 100.0);
  try {
    validateFresnel(m.fresnel);
  } catch (const Error& e) {
    // the CLI's message names the flag (--eta ...); here the key
    std::string msg = e.what();
    for (std::string flag : {"--f0", "--eta", "--k", "--f82", "--fresnel"}) {
      size_t at;
      while ((at = msg.find(flag)) != std::string::npos) msg.replace(at, flag.size(), flag.substr(2));
    }
    // point at the key the message is about
    const toml::node* at = t.get("fresnel");
    for (const char* key : {"f0", "eta", "k", "f82"})
      if (msg.rfind(std::string(key) + " ", 0) == 0 && t.get(key)) at = t.get(key);
    r.fail(at ? *at : static_cast<const toml::node&>(t), "material '" + m.name + "': " + msg);
  }
  if (auto* n = t.get("diffuse")) m.diffuse = r.name(*n, "diffuse model", diffuseNames());
  if (auto* n = t.get("sigma")) {
    m.sigma = r.number(*n, "material.sigma", 0.0, 1.5707963267948966);
    if (m.diffuse != DIFFUSE_OREN_NAYAR && m.diffuse != DIFFUSE_OREN_NAYAR_AS_PRINTED)
      r.fail(*n, "material.sigma: only diffuse = \"oren-nayar\" (or oren-nayar-as-printed) takes it");
  }
  if (auto* n = t.get("rho")) m.rho = r.values(*n, "material.rho", 0.0, 1.0);
  if (auto* n = t.get("roughness")) {
    if (n->is_array()) {
      const toml::array& a = *n->as_array();
      if (a.size() != 2) r.fail(*n, "material.roughness must be a number or a range [lo, hi]");
      m.roughnessLo = r.number(a[0], "material.roughness", 0.0, 1.0);
      m.roughnessHi = r.number(a[1], "material.roughness", 0.0, 1.0);
      if (m.roughnessLo > m.roughnessHi) r.fail(*n, "material.roughness range [lo, hi] must have lo <= hi");
    } else {
      m.roughnessLo = m.roughnessHi = r.number(*n, "material.roughness", 0.0, 1.0);
    }
  }
  if (auto* n = t.get("coupling")) {
    m.coupling = r.string(*n, "material.coupling");
    if (m.coupling != "sum" && m.coupling != "albedo-scaling")
      r.fail(*n, "material.coupling must be \"sum\" or \"albedo-scaling\", got \"" + m.coupling + "\"");
    if (m.coupling == "albedo-scaling" && m.diffuse < 0)
      r.fail(*n, "material.coupling = \"albedo-scaling\" scales a diffuse lobe: give the material a diffuse model");
  }
  if (auto* n = t.get("transmission")) {
    m.transmission = r.boolean(*n, "material.transmission");
    if (m.transmission &&
        ((m.ndf != NDF_GGX && m.ndf != NDF_BECKMANN) || (m.gaf != GAF_SMITH && m.gaf != GAF_SMITH_CORRELATED)))
      r.fail(*n, "material '" + m.name +
                     "': transmission = true needs ndf ggx or beckmann with gaf smith or "
                     "smith-correlated (the rough-dielectric tables' models)");
  }
  if (auto* n = t.get("brdf3d")) {
    m.brdf3d = r.boolean(*n, "material.brdf3d");
    if (m.brdf3d && (m.roughnessLo != m.roughnessHi || m.roughnessLo < kMinVolumeRoughness))
      r.fail(*n, "material '" + m.name + "': brdf3d = true needs one roughness in [0.01, 1] (roughness = R), got " +
                     (m.roughnessLo == m.roughnessHi ? fmtG(m.roughnessLo) : "a range"));
  }
  return m;
}

// TOML 1.0 allows characters outside ASCII only inside strings and comments, no control characters
// but tab (and CR before LF), and only UTF-8. toml++ 3.3 (Debian's) reaches an "unreachable" branch
// (undefined behaviour) when it classifies some non-ASCII characters as whitespace (found by
// fuzzing: U+00A1..U+0499 and U+FC96..U+FEFE, outside strings, or after a control character in
// one), so such input is rejected here first, with the verdict TOML gives and a position.
void screenNonAscii(const std::string& text, const std::string& file) {
  enum { Normal, Comment, Basic, Literal, MlBasic, MlLiteral } st = Normal;
  int line = 1, col = 0;
  size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // a UTF-8 byte order mark
  for (size_t i = start; i < text.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    ++col;
    auto at = [&](const char* s) { return text.compare(i, std::strlen(s), s) == 0; };
    if (c == '\n') {
      if (st == Comment || st == Basic || st == Literal) st = Normal;
      ++line;
      col = 0;
      continue;
    }
    if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7F)
      throw Error(kExitDataErr, file + ":" + std::to_string(line) + ":" + std::to_string(col) +
                                    ": TOML syntax: control character " + std::to_string(c) +
                                    " (TOML allows none but tab)");
    if (c == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n'))
      throw Error(kExitDataErr, file + ":" + std::to_string(line) + ":" + std::to_string(col) +
                                    ": TOML syntax: a carriage return not followed by a line feed");
    if (c >= 0x80) {
      // one UTF-8 sequence: its length from the lead byte, continuation bytes 10xxxxxx
      int len = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 0;
      bool ok = len > 0 && i + len <= text.size();
      for (int k = 1; ok && k < len; ++k) ok = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
      if (!ok)
        throw Error(kExitDataErr, file + ":" + std::to_string(line) + ":" + std::to_string(col) +
                                      ": not UTF-8 (TOML files are UTF-8)");
    }
    if (c >= 0x80 && (st == Normal)) {
      throw Error(kExitDataErr, file + ":" + std::to_string(line) + ":" + std::to_string(col) +
                                    ": TOML syntax: a character outside ASCII is allowed only inside a string or a "
                                    "comment");
    }
    switch (st) {
      case Normal:
        if (c == '#')
          st = Comment;
        else if (at("\"\"\"")) {
          st = MlBasic;
          i += 2;
          col += 2;
        } else if (at("'''")) {
          st = MlLiteral;
          i += 2;
          col += 2;
        } else if (c == '"')
          st = Basic;
        else if (c == '\'')
          st = Literal;
        break;
      case Basic:
        if (c == '\\') {
          ++i;
          ++col;
        } else if (c == '"')
          st = Normal;
        break;
      case MlBasic:
        if (c == '\\') {
          ++i;
          ++col;
        } else if (at("\"\"\"")) {
          st = Normal;
          i += 2;
          col += 2;
        }
        break;
      case Literal:
        if (c == '\'') st = Normal;
        break;
      case MlLiteral:
        if (at("'''")) {
          st = Normal;
          i += 2;
          col += 2;
        }
        break;
      default:
        break;
    }
  }
}

// toml++ parses nested tables, arrays and dotted keys by recursion, one level per part: a 100 KB
// key of 50,000 parts overflows the stack. The manifest's own keys nest at most three deep, so
// anything past kMaxNesting is refused here, before the parser sees the text: brackets and braces
// open at once, or parts of one dotted key (a '.' outside strings, not between digits: 1.5 is a
// value). Strings and comments are skipped as TOML defines them.
constexpr int kMaxNesting = 32;
void screenNesting(const std::string& text, const std::string& name) {
  int line = 1, col = 0, depth = 0, parts = 1;
  auto fail = [&](const std::string& what) {
    throw Error(kExitDataErr, SourcePos{name, line, col}.str() + ": " + what + " nest deeper than " +
                                  std::to_string(kMaxNesting) + " levels; a manifest needs at most 3");
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    ++col;
    if (c == '\n') {
      ++line;
      col = 0;
      parts = 1;
      continue;
    }
    if (c == '#') {  // a comment, to the end of the line
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
      continue;
    }
    if (c == '"' || c == '\'') {
      const bool multi = text.compare(i, 3, std::string(3, c)) == 0;
      const std::string close = multi ? std::string(3, c) : std::string(1, c);
      size_t j = i + close.size();
      while (j < text.size() && text.compare(j, close.size(), close) != 0) {
        if (c == '"' && text[j] == '\\') ++j;  // basic strings escape; literal ones do not
        if (j < text.size() && text[j] == '\n') {
          ++line;
          col = 0;
        }
        ++j;
      }
      i = std::min(text.size(), j + close.size()) - 1;
      continue;
    }
    if (c == '[' || c == '{') {
      if (++depth > kMaxNesting) fail("arrays, tables and inline tables");
    } else if (c == ']' || c == '}') {
      depth = std::max(0, depth - 1);
    } else if (c == '=' || c == ',') {
      parts = 1;
    } else if (c == '.') {
      const bool digits = i > 0 && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i - 1])) &&
                          std::isdigit(static_cast<unsigned char>(text[i + 1]));
      if (!digits && ++parts > kMaxNesting) fail("the parts of a dotted key");
    }
  }
}

}  // namespace

Scene parseManifest(const std::string& text, const std::string& name) {
  Reader r{name};
  screenNonAscii(text, name);
  screenNesting(text, name);
  toml::table root;
  try {
    root = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw Error(
        kExitDataErr,
        SourcePos{name, static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column)}.str() +
            ": TOML syntax: " + std::string(e.description()));
  }
  Scene s;
  r.keysIn(root, "the manifest", {"scene", "output", "lighting", "material"});
  if (auto* n = root.get("scene")) {
    const toml::table& t = r.table(*n, "[scene]");
    r.keysIn(t, "[scene]", {"name"});
    if (auto* nm = t.get("name")) s.name = r.string(*nm, "scene.name");
  }
  if (auto* n = root.get("output")) readOutput(r, r.table(*n, "[output]"), s.output);
  if (auto* n = root.get("lighting")) readLighting(r, r.table(*n, "[lighting]"), s.lighting);
  if (auto* n = root.get("material")) {
    if (!n->is_array_of_tables()) r.fail(*n, "material must be an array of tables ([[material]] sections)");
    const toml::array& a = *n->as_array();
    std::map<std::string, SourcePos> seen;
    for (size_t i = 0; i < a.size(); ++i) {
      SceneMaterial m = readMaterial(r, *a[i].as_table(), static_cast<int>(i));
      auto [it, fresh] = seen.emplace(m.name, m.pos);
      if (!fresh)
        throw Error(kExitDataErr,
                    m.pos.str() + ": duplicate material name '" + m.name + "' (first at " + it->second.str() + ")");
      s.materials.push_back(m);
    }
  }
  if (s.materials.empty())
    throw Error(kExitDataErr, name + ":1:1: the scene has no materials ([[material]] with name, ndf, gaf, ...)");
  return s;
}

Scene readManifest(const std::string& path) {
  Scene s = parseManifest(readInputFile(path, "scene", kCapManifest), path);
  s.path = path;
  size_t slash = path.find_last_of('/');
  s.baseDir = slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
  if (s.name.empty()) {
    std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    s.name = base.substr(0, base.find_last_of('.'));
  }
  return s;
}

}  // namespace brdfbake
