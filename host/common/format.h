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
inline std::string fmt4(double v) { return fmtG(v, 4); }
inline std::string fmtG9(double v) { return fmtG(v, 9); }

}  // namespace brdfbake
