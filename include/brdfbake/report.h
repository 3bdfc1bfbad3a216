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
  // The OpenCL program builds (and, on PoCL, kernel compiles) the bake waited for before its first
  // table, shared by its tables: the same on each report of one bake. 0 when every program came
  // from PoCL's cache in a fraction of a millisecond, or no table needed the device.
  double buildSeconds = 0;
  // How the programs were made ready: "1 loaded from its binary", "2 compiled (binaries kept)"; "" when none was.
  std::string buildHow;
  // What the family adds under the file's line, or "": an LTC table's distances and the texels past
  // its fit target.
  std::string note;
};

}  // namespace brdfbake
