// Plan -> every table computed by its family -> files that land together, and a report. Every table
// is computed and checked before the first file is written, so a failure leaves no partial output.
#pragma once
#include <string>
#include <vector>

#include "formats/exr/table_file.h"
#include "plan/plan.h"
#include "tables/family.h"

namespace brdfbake {

// Before the first table: each family's checks over its jobs (free space, inputs read once), in
// registry order, with `outDir` where the files will land ("" when none are written).
void preflight(BakeContext& ctx, const Plan& plan, const std::string& outDir);
// Whether any job runs on the device, and every kernel the jobs need, built together.
bool usesDevice(const Plan& plan);
void buildKernels(BakeContext& ctx, const Plan& plan);

// Builds from source the programs a first bake most often needs (the default set's pair, and the
// program every pair shares when a bake names three or more) on `device`, and stores their
// binaries in `dir` (cl/program_cache.h). The build runs it (`brdfbake devices --prepare DIR`), so
// that a fresh checkout's first bake loads them. Returns one line per program.
std::string preparePrograms(const std::string& dir, const std::string& device);

// Runs the plan and writes the files. Returns one report per file.
std::vector<TableReport> runPlan(const Plan& plan);

std::string formatReport(const std::vector<TableReport>& reports);

// The table of a plan as `plan SCENE` and `bake --dry-run` print it: its header, and a line per
// table (the table's name tableWidth wide, its size, texels, estimated seconds, status statusWidth
// wide, file).
std::string planHeader(size_t tableWidth, size_t statusWidth);
std::string planLine(size_t tableWidth, size_t statusWidth, const std::string& table, const std::string& size,
                     double texels, double seconds, const std::string& status, const std::string& file);

// `bake --dry-run`: the tables the plan would write (table, size, texels, the family's estimate of
// its seconds on PoCL with two cores, whether its file is new or would be replaced, the file), the
// models of each, and the total. Reads nothing but the directory; computes and writes nothing.
std::string formatPlan(const Plan& plan);

// For `info`: a warning line when an energy table (splitsum A+B, albedo, albedo-avg) exceeds 1 by
// more than its error bound, naming the cause; "" otherwise.
std::string energyWarnings(const TableImage& table);

}  // namespace brdfbake
