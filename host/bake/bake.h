// Plan -> every table computed by its family -> files that land together, and a report. Every table
// is computed and checked before the first file is written, so a failure leaves no partial output.
#pragma once
#include <string>
#include <vector>

#include "formats/exr/table_file.h"
#include "plan/plan.h"
#include "tables/family.h"

namespace brdfbake {

// Runs the plan and writes the files. Returns one report per file.
std::vector<TableReport> runPlan(const Plan& plan);

std::string formatReport(const std::vector<TableReport>& reports);

// For `info`: a warning line when an energy table (splitsum A+B, albedo, albedo-avg) exceeds 1 by
// more than its error bound, naming the cause; "" otherwise.
std::string energyWarnings(const TableImage& table);

}  // namespace brdfbake
