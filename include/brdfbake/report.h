// What a bake that writes files reports: one line per file (brdfbake/brdfbake.h bakeToDirectory,
// the command line's table).
#pragma once
#include <string>

namespace brdfbake {

// One line of the bake's report: a file written, its table, size and claimed error.
struct TableReport {
  std::string path;
  std::string table, ndf, gaf;
  int width = 0, height = 0, depth = 1;
  double errorBound = 0;  // brdf.error
  double seconds = 0;     // kernel time for this table
};

}  // namespace brdfbake
