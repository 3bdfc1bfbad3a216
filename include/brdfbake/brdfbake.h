// The brdfbake library: bake BRDF lookup tables in memory, read and write them in any format.
//
//   brdfbake::BakeRequest req = brdfbake::defaultRequest();   // ggx + smith-correlated
//   req.tables = {brdfbake::tableKind("splitsum")};
//   req.size = 64;
//   std::vector<brdfbake::Table> tables = brdfbake::bake(req);  // values, claims, metadata
//   float a = tables[0].at(10, 20, 0);                          // A at texel (10, 20)
//   brdfbake::write(tables, "out");                             // the request's formats, all or nothing
//
// The command line (brdfbake bake), scenes, reports and the benchmark bake through the same
// families (host/tables/); the values are the same bits as the files `brdfbake bake` writes.
// Errors are brdfbake::Error (brdfbake/error.h): what() names the option or file, code() is the
// sysexits code the command line exits with.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "brdfbake/error.h"
#include "brdfbake/report.h"
#include "brdfbake/request.h"

namespace brdfbake {

struct TablePlanRecord;  // defined inside the library (host/api/library.cpp)

// One baked table in memory.
struct Table {
  std::string path;  // where write() puts it (under the request's outDir), e.g. out/splitsum_ggx_smith-correlated.exr
  std::string kind;  // --table name: "splitsum", "albedo", ...
  int width = 0, height = 0, depth = 1;
  std::vector<std::string> channels;            // "R", "G", "B" (what each plane holds: metadata["brdf.channels"])
  std::vector<std::vector<float>> planes;       // one per channel, [(z * height + y) * width + x]
  std::vector<double> texelBounds;              // 2D tables: each texel's claimed error (relative to max(1, |v|))
  double errorBound = 0;                        // the largest claim (brdf.error)
  std::map<std::string, std::string> metadata;  // every attribute, numbers as text (brdf.ndf, brdf.axes, ...)

  float at(int x, int y, int channel, int z = 0) const {
    return planes[static_cast<size_t>(channel)][(static_cast<size_t>(z) * height + y) * width + x];
  }
  // The library's own record of how the table was planned (its family and job), opaque to callers:
  // write() uses it.
  std::shared_ptr<const TablePlanRecord> internal;
};

// Bakes every table of `req` in memory, on req.device (default: the first CPU device). Throws
// Error(64) for a request that cannot be honoured, Error(69) when no OpenCL device is found.
std::vector<Table> bake(const BakeRequest& req);

// Writes tables baked by bake() into `dir` (the request's outDir when empty), in each table's
// requested formats, as one set: every file lands or none does.
void write(const std::vector<Table>& tables, const std::string& dir = "");

// bake() and write() in one step, as `brdfbake bake` does: 3D tables are baked slab by slab while
// they are written, never whole in memory. Returns one report per file written.
std::vector<TableReport> bakeToDirectory(const BakeRequest& req);

// Reads a table file brdfbake wrote (.exr, .ktx2, .dds, .png, .h, .mjs).
Table readTable(const std::string& path);

}  // namespace brdfbake
