// Numbers in messages, metadata and reports: printf's %.*g, as a string.
#pragma once
#include <cstdio>
#include <string>

namespace brdfbake {

inline std::string fmtG(double v, int digits = 6) {
  char b[40];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

inline std::string fmt3(double v) { return fmtG(v, 3); }
// An estimate of seconds: three decimals below 0.1 s, one above ("0.066", "141.3").
inline std::string fmtSeconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, s < 0.1 ? "%.3f" : "%.1f", s);
  return b;
}
inline std::string fmt4(double v) { return fmtG(v, 4); }
inline std::string fmtG9(double v) { return fmtG(v, 9); }

// Text kept on one line (`info`'s attribute values): backslashes, newlines, tabs and other control
// characters escaped (\\, \n, \t, \xHH).
inline std::string escapeText(const std::string& s) {
  std::string out;
  for (unsigned char ch : s) {
    if (ch == '\\') {
      out += "\\\\";
    } else if (ch == '\n') {
      out += "\\n";
    } else if (ch == '\t') {
      out += "\\t";
    } else if (ch < 0x20 || ch == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      out += buf;
    } else {
      out += static_cast<char>(ch);
    }
  }
  return out;
}

}  // namespace brdfbake
