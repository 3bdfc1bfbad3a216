// Reading the header format back: the C header (.h) and the ECMAScript module (.mjs) the baker
// writes with `--format header`. Not a C or JavaScript parser: the few constructs the writer emits,
// line by line, each checked, with the line number in the message when one is not as expected.
//   C:  #define <ID>_WIDTH n / _HEIGHT / _DEPTH / _CHANNELS, #define <ID>_PRECISION "p",
//       the attribute table  {"key", "value"},  and the data array  <ID>_data[N] = { v, v, ... };
//   JS: export const width = W, height = H, depth = D, channels = C;  export const precision = "p";
//       the attributes  "key": "value",  inside Object.freeze({ ... });  and  .from([ v, v, ... ]);
// String literals: C escapes (\" \\ \? \ooo) or JS ones (\" \\ \xHH). Values: float32 literals,
// float16 bit patterns (0xHHHH), unorm codes.
#include <cstdlib>
#include <sstream>

#include "formats/readers/reader_internal.h"

namespace brdfbake {
namespace readers {

namespace {

struct Parser {
  const std::string& path;
  const char* format;
  int line = 0;
  [[noreturn]] void fail(const std::string& what) const {
    bad(path, format, "line " + std::to_string(line) + ": " + what);
  }

  // The string literal starting at s[*at] (a '"'); *at moves past it.
  std::string literal(const std::string& s, size_t* at) const {
    if (*at >= s.size() || s[*at] != '"') fail("expected a string literal");
    std::string out;
    size_t i = *at + 1;
    while (i < s.size() && s[i] != '"') {
      char ch = s[i++];
      if (ch != '\\') {
        out += ch;
        continue;
      }
      if (i >= s.size()) break;
      const char e = s[i++];
      if (e == 'x') {  // \xHH
        if (i + 2 > s.size()) fail("short \\x escape");
        out += static_cast<char>(std::strtol(s.substr(i, 2).c_str(), nullptr, 16));
        i += 2;
      } else if (e >= '0' && e <= '7') {  // \ooo
        size_t j = i - 1, end = std::min(s.size(), j + 3);
        int v = 0;
        while (j < end && s[j] >= '0' && s[j] <= '7') v = v * 8 + (s[j++] - '0');
        out += static_cast<char>(v);
        i = j;
      } else {
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e;  // \" \\ \? and the like
      }
    }
    if (i >= s.size()) fail("unterminated string literal");
    *at = i + 1;
    return out;
  }
};

bool startsWith(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }
bool endsWith(const std::string& s, const std::string& p) {
  return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(' ');
  return a == std::string::npos ? std::string() : s.substr(a, s.find_last_not_of(' ') - a + 1);
}

// A non-negative integer from text, or -1.
long long integer(const std::string& s) {
  if (s.empty()) return -1;
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  return *end == '\0' && v >= 0 ? v : -1;
}

}  // namespace

void readHeader(const std::string& text, bool js, bool pixels, TableFile& t) {
  Parser p{t.path, js ? "ECMAScript module (brdfbake header format)" : "C header (brdfbake header format)"};
  long long width = -1, height = -1, depth = -1, channels = -1;
  std::string precision;
  enum class In { Top, Attributes, Data } in = In::Top;
  std::vector<std::string> values;
  bool complete = false;  // its last line seen
  std::istringstream lines(text);
  std::string s;
  while (std::getline(lines, s)) {
    ++p.line;
    if (in == In::Attributes) {
      const std::string end = js ? "});" : "};";
      if (s == end) {
        in = In::Top;
        continue;
      }
      size_t at = s.find_first_not_of(' ');
      if (!js) {
        if (at == std::string::npos || s[at] != '{') p.fail("expected {\"key\", \"value\"}, in the attribute table");
        ++at;
      }
      std::string key = p.literal(s, &at);
      const std::string sep = js ? ": " : ", ";
      if (s.compare(at, sep.size(), sep) != 0) p.fail("expected '" + sep + "' after the attribute name");
      at += sep.size();
      std::string value = p.literal(s, &at);
      t.text.emplace_back(std::move(key), std::move(value));
      continue;
    }
    if (in == In::Data) {
      if (s == (js ? "]);" : "};")) {
        in = In::Top;
        complete = js;  // the module's last line; the header's is #endif
        continue;
      }
      std::istringstream items(s);
      std::string item;
      while (std::getline(items, item, ',')) {
        item = trim(item);
        if (!item.empty()) values.push_back(item);
      }
      continue;
    }
    if (startsWith(s, "//") || s.empty()) continue;
    if (js) {
      if (startsWith(s, "export const width = ")) {
        std::istringstream in2(s.substr(13));
        std::string part;
        while (std::getline(in2, part, ',')) {
          const size_t eq = part.find('=');
          if (eq == std::string::npos) p.fail("expected name = value");
          const std::string name = trim(part.substr(0, eq));
          std::string v = trim(part.substr(eq + 1));
          if (endsWith(v, ";")) v.pop_back();
          long long* dst = name == "width"      ? &width
                           : name == "height"   ? &height
                           : name == "depth"    ? &depth
                           : name == "channels" ? &channels
                                                : nullptr;
          if (dst) *dst = integer(v);
        }
      } else if (startsWith(s, "export const precision = ")) {
        size_t at = s.find('"');
        precision = p.literal(s, &at);
      } else if (startsWith(s, "export const attributes = Object.freeze({")) {
        in = In::Attributes;
      } else if (startsWith(s, "export const data = ") && endsWith(s, ".from([")) {
        in = In::Data;
      }
      continue;
    }
    if (startsWith(s, "#endif")) {
      complete = true;
    } else if (startsWith(s, "#define ")) {
      const size_t sp = s.find(' ', 8);
      if (sp == std::string::npos) continue;
      const std::string name = s.substr(8, sp - 8), v = s.substr(sp + 1);
      if (endsWith(name, "_WIDTH"))
        width = integer(v);
      else if (endsWith(name, "_HEIGHT"))
        height = integer(v);
      else if (endsWith(name, "_DEPTH"))
        depth = integer(v);
      else if (endsWith(name, "_CHANNELS"))
        channels = integer(v);
      else if (endsWith(name, "_PRECISION")) {
        size_t at = 0;
        precision = p.literal(v, &at);
      }
    } else if (s.find("_attributes[][2] = {") != std::string::npos) {
      in = In::Attributes;
    } else if (s.find("_data[") != std::string::npos && endsWith(s, "] = {")) {
      in = In::Data;
    }
  }
  if (!complete)
    bad(t.path, p.format, std::string("ends before its last line (") + (js ? "]);" : "#endif") + "): truncated");
  if (in != In::Top)
    p.fail("the " + std::string(in == In::Data ? "data" : "attribute") + " list does not end (truncated?)");
  auto need = [&](long long v, const char* what, long long lo, long long hi) {
    if (v < lo || v > hi)
      bad(t.path, p.format,
          std::string(what) + (v < 0 ? " is missing or not a number"
                                     : " " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " +
                                           std::to_string(hi) + "]"));
  };
  need(width, js ? "width" : "<ID>_WIDTH", 1, 65536);
  need(height, js ? "height" : "<ID>_HEIGHT", 1, 65536);
  need(depth, js ? "depth" : "<ID>_DEPTH", 1, 65536);
  need(channels, js ? "channels" : "<ID>_CHANNELS", 1, 4);
  try {
    t.precision = parsePrecision("precision", precision);
  } catch (const std::exception&) {
    bad(t.path, p.format, "precision '" + precision + "' is not float32, float16, unorm16 or unorm8");
  }
  const uint64_t texels = static_cast<uint64_t>(width) * height * depth;
  if (values.size() != texels * channels)
    bad(t.path, p.format,
        "holds " + std::to_string(values.size()) + " values; width * height * depth * channels is " +
            std::to_string(texels * channels) + " (truncated?)");
  t.storage = precisionName(t.precision) + (js ? " values (ECMAScript module)" : " literals (C header)");
  t.depth = static_cast<int>(depth);
  t.table.width = static_cast<int>(width);
  t.table.height = static_cast<int>(height);
  setChannels(t, static_cast<int>(channels));
  // every value checked, whether or not the caller wants them
  if (pixels) t.table.planes.assign(static_cast<size_t>(channels), std::vector<float>(texels));
  for (size_t i = 0; i < values.size(); ++i) {
    std::string v = values[i];
    if (!js && t.precision == Precision::Float32 && endsWith(v, "f")) v.pop_back();
    char* end = nullptr;
    const bool hex = t.precision == Precision::Float16;
    const double x = hex ? static_cast<double>(std::strtoul(v.c_str(), &end, 16)) : std::strtod(v.c_str(), &end);
    if (end == v.c_str() || *end != '\0' || (t.precision != Precision::Float32 && x < 0) || (hex && x > 0xFFFF) ||
        (isUnorm(t.precision) && x > (t.precision == Precision::Unorm8 ? 255 : 65535)))
      bad(t.path, p.format,
          "value " + std::to_string(i) + " '" + values[i] + "' is not a " + precisionName(t.precision) + " " +
              (hex                    ? "bit pattern"
               : isUnorm(t.precision) ? "code"
                                      : "number"));
    if (pixels)
      t.table.planes[i % channels][i / channels] = static_cast<float>(
          t.precision == Precision::Float32 ? x : decodeStored(static_cast<uint32_t>(x), t.precision));
  }
}

}  // namespace readers
}  // namespace brdfbake
