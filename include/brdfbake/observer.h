// Watching a bake as it runs: where the time goes (brdfbake bake --timings) and how far each table
// has come (the progress line on a terminal). Give one in BakeRequest::observer; every call comes
// from the thread that called bake() or bakeToDirectory(), in order.
#pragma once
#include <string>

namespace brdfbake {

class BakeObserver {
 public:
  virtual ~BakeObserver() = default;
  // A stage finished, with its wall seconds. kind: "device" (platform, device and context; `what`
  // names the device and the seconds the platforms took to list, "(platforms listed in 0.019 s)"),
  // "program" (one OpenCL program loaded from its binary or compiled; `what` says which and how),
  // "table" (one table computed: `what` is its file), "write" (the files landing as one set,
  // 3D tables streamed into them).
  virtual void stage(const std::string& /*kind*/, const std::string& /*what*/, double /*seconds*/) {}
  // Progress within a table: `done` of `total` units (texels, slabs) of the table `what`, after
  // `seconds` of it. Called at most a few times a second; the last call has done == total.
  virtual void progress(const std::string& /*what*/, const std::string& /*unit*/, double /*done*/, double /*total*/,
                        double /*seconds*/) {}
};

}  // namespace brdfbake
