// brdfbake verify: numerical checks of the models over a set of NDF/GAF pairs: the white furnace
// (E <= 1 everywhere, with a heat map of E(mu, r)), the weak white furnace of the Smith pairs, the
// NDF's normalisation (int D (n.h) dw = 1), reciprocity at random direction pairs, and the energy a
// single-scattering lobe loses (1 - E) against roughness. A summary line per pair, a page with
// plots, CSV data, and an exit status a CI job can use.
#pragma once
#include <string>
#include <vector>

#include "brdfbake/request.h"

namespace brdfbake {

struct VerifyCheck {
  std::string name;  // "white furnace", ...
  bool pass = true;
  bool applies = true;  // false: not meaningful for this pair (e.g. weak furnace of a non-Smith GAF)
  double worst = 0;     // the worst measured violation or deviation
  std::string where;    // where it occurs
  std::string detail;   // what was compared, with the tolerance
};

struct VerifyResult {
  int ndf, gaf;
  std::vector<VerifyCheck> checks;
  bool pass() const;
  std::string summary() const;  // one line
};

// Runs the checks for every pair of the request (size: grid nodes per axis, default 33) and writes
// the page into `<outDir>/verify`. *pageLine: where the page is (or how to get its plots).
std::vector<VerifyResult> runVerify(const BakeRequest& req, std::string* pageLine);

}  // namespace brdfbake
