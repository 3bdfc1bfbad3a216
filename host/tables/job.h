// A planned table: which family bakes it, where it lands, and the family's own description of it.
// The plan (plan/plan.h) is a list of these; only the family that made a job reads its spec.
#pragma once
#include <memory>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>

#include "brdfbake/table_kind.h"
#include "common/brdf3d_grid.h"
#include "common/errors.h"
#include "common/material.h"
#include "common/models.h"
#include "formats/layout.h"
#include "formats/storage.h"

namespace brdfbake {

class TableFamily;  // tables/family.h

// The part of a job that only its family reads. Each family's job type derives from it; a Job holds
// it typed, and Job::get<T>() checks the type.
struct JobSpec {
  virtual ~JobSpec() = default;
  std::string path;  // the output file
};

// A 2D (or 1D) table over (mu, r), r, or eta: the microfacet family, fresnel-avg, the
// Ashikhmin-Shirley textures and a measured material's tables.
struct TableJob : JobSpec {
  TableKind kind = TableKind::SplitSum;
  int ndf = -1;
  int gaf = -1;               // GAF_NONE for kp, which depends on the NDF only
  int width = 0, height = 1;  // x = mu (2D tables) or r (1D), y = r (2D) or 1
  bool nodeGrid = false;
  bool half = false;
  FresnelChoice fresnel = {};  // albedo, albedo-avg: the model in B (one: F = 1); splitsum: schlick or f82-tint
  int diffuse = -1;            // albedo: a diffuse model's albedo (ndf, gaf unused); splitsum: burley in B
  int texture = -1;            // ashikhmin-shirley: Tex0, Tex1 or Tex2 (one file each)
  // the files written (path's extension replaced per format) and the precision of their channels;
  // half == (precision == float16), what the EXR file stores
  std::vector<FileFormat> formats = {FileFormat::Exr};
  Precision precision = Precision::Float32;
  TableLayout layout = {};      // splitsum: axis order, flips, channels (formats/layout.h)
  std::string layoutName = {};  // --layout NAME, or a name for --axes/--flip/--channels; "" as baked
  bool muSqrt = false;          // splitsum, albedo: x holds u = sqrt(mu), texel i at mu = u_i^2 (--mu-axis sqrt)
  std::string merl = {};        // a measured material's MERL file (tables/measured/measured.cpp), or ""

  // A job set up by name, the fields not named at their defaults:
  //   TableJob::of(kind).forPair(ndf, gaf).texels(n, n).onNodeGrid(grid).storingHalf(half)
  static TableJob of(TableKind k) {
    TableJob j;
    j.kind = k;
    return j;
  }
  TableJob& forPair(int n, int g) {
    ndf = n;
    gaf = g;
    return *this;
  }
  TableJob& texels(int w, int h) {
    width = w;
    height = h;
    return *this;
  }
  TableJob& onNodeGrid(bool on) {
    nodeGrid = on;
    return *this;
  }
  TableJob& storingHalf(bool on) {
    half = on;
    return *this;
  }
};

// A 3D table (--table brdf3d): one per NDF/GAF pair, baked and written slab by slab.
struct VolumeJob : JobSpec {
  Brdf3dSpec spec;
  bool half = false;
  bool merl = false;                                    // MERL's binary layout instead of an EXR atlas
  int cols = 1, rows = 1;                               // the EXR atlas: slices left to right, then top to bottom
  std::vector<FileFormat> formats = {FileFormat::Exr};  // ktx2, dds: 3D textures; header; exr: the atlas
  Precision precision = Precision::Float32;
};

// A rough-dielectric table (--table dielectric: 3D over (mu, r, eta coordinate), an EXR atlas of
// eta slices; dielectric-avg: 2D over (r, eta coordinate)). tables/dielectric/dielectric_bake.h.
struct DielectricJob : JobSpec {
  int ndf = 0, gaf = 0;
  bool avg = false;               // dielectric-avg
  int nx = 32, ny = 32, nz = 32;  // mu, r, eta (avg: nx = r, ny = eta, nz = 1)
  bool nodeGrid = false, half = false;
  double etaLo = 0.4, etaHi = 2.5;
  int cols = 1, rows = 1;  // the atlas (3D)
};

struct Job {
  const TableFamily* family = nullptr;
  TableKind kind = TableKind::SplitSum;
  std::string path;                     // the output file (its extension replaced per format); scenes may rename it
  std::shared_ptr<const JobSpec> spec;  // the family's own: TableJob, VolumeJob, DielectricJob or its own type

  // Whether the spec is a T.
  template <class T>
  bool is() const {
    return dynamic_cast<const T*>(spec.get()) != nullptr;
  }
  // The spec as the T its family made, with the job's path in it (the families' helpers read the
  // path from their spec). Error(kExitSoftware) when it is another type: a family read a job it did
  // not plan.
  template <class T>
  T get() const {
    const T* s = dynamic_cast<const T*>(spec.get());
    if (!s) throw Error(kExitSoftware, "internal: the job for " + path + " holds another family's spec");
    T copy = *s;
    copy.path = path;
    return copy;
  }
};

template <class T>
Job makeJob(const TableFamily* family, TableKind kind, const T& spec) {
  static_assert(std::is_base_of_v<JobSpec, T>, "a job's spec derives from JobSpec");
  return Job{family, kind, spec.path, std::make_shared<const T>(spec)};
}

}  // namespace brdfbake
