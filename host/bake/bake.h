// Plan -> OpenCL jobs -> EXR files and a report. Every table is computed and checked before
// the first file is written, so a failure leaves no partial output.
#pragma once
#include <string>
#include <vector>

#include "exr/table_file.h"
#include "plan/plan.h"

namespace brdfbake {

struct TableReport {
  std::string path;
  std::string table, ndf, gaf;
  int width = 0, height = 0, depth = 1;
  double errorBound = 0;  // brdf.error
  double seconds = 0;     // kernel time for this table
};

// Computes one planned table (kernel + header attributes) without writing it. texelBounds, when
// given, receives each texel's claimed bound (relative to max(1, |value|), every stored channel,
// what the file's brdf.error is the largest of), in the table's texel order.
TableImage computeTable(class KernelRunner& runner, const TableJob& job, double* seconds,
                        std::vector<double>* texelBounds = nullptr);

// Runs the plan on its device and writes the files. Returns one report per table.
std::vector<TableReport> runPlan(const Plan& plan);

std::string formatReport(const std::vector<TableReport>& reports);

// For `info`: a warning line when an energy table (splitsum A+B, albedo, albedo-avg) exceeds 1 by
// more than its error bound, naming the cause; "" otherwise.
std::string energyWarnings(const TableImage& table);

}  // namespace brdfbake
