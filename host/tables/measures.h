// What a family says of its tables besides the tables themselves (tables/family.h): the rungs of
// its convergence ladders, its points under stress, and its jobs' lines in a scene's plan.
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

// One rung of a convergence ladder: a method at one budget, its wall time, its own error estimate
// and its true error against the independent reference, each the largest over the points measured
// (relative to max(1, |v|)).
struct Rung {
  std::string method;  // "quadrature (device, float)", ...
  std::string budget;  // "level 0", "1024 samples", "32 texels per axis"
  double seconds = 0, estimate = 0, error = 0;
};

// The budgets a convergence ladder climbs (brdfbake convergence --levels, --samples).
struct LadderBudgets {
  std::vector<int> levels = {0, 1, 2, 3};                              // quadrature levels
  std::vector<int> samples = {16, 64, 256, 1024, 4096, 16384, 65536};  // Monte Carlo samples
};

// A table kind's error against run time (brdfbake convergence --table KIND).
struct Ladder {
  std::string table;  // what was measured: the table, models, points
  std::vector<Rung> rungs;
  std::string note;  // the reference: what it is, its time, how it agrees with the finest rung
};

// One point of `brdfbake stress`: a table's value at a stiff or extreme case against the independent
// reference, its claimed bound, and the expected limit.
struct StressPoint {
  std::string sweep, label;  // "alpha -> 0, ggx+smith-correlated albedo", "r=0.01 mu=0.5"
  double value = 0, reference = 0, error = 0, bound = 0;
  bool finite = true, withinBound = true;
  std::string limit;  // the expected limit, "" when none
  bool limitMet = true;
  bool pass() const { return finite && withinBound && limitMet; }
};

// A stress point from a value and its reference: finite, its error relative to max(1, |reference|),
// within `bound` (+ `slack`, the reference's own accuracy). The caller adds the limit, if any.
StressPoint stressPoint(const std::string& sweep, const std::string& label, double value, double reference,
                        double bound, double slack = 0);

// A scene plan's line for a job.
struct JobSummary {
  std::string table;   // "splitsum"
  std::string models;  // "ggx + smith-correlated, Schlick split (...)"
  std::string size;    // "128x128"
  double texels = 0;
  double cost = 0;  // estimated seconds on PoCL, 2 cores (a guide for shards, not a promise)
  // the files it writes when they are not just the job's path (the LTC's two), in its first format
  std::vector<std::string> files = {};
};

}  // namespace brdfbake
