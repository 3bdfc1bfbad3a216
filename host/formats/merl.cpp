// MERL binary files: see merl.h. Byte order is explicit (little-endian whatever the host's).
#include "formats/merl.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "common/errors.h"
#include "common/format.h"
#include "common/input_file.h"
#include "formats/commit_record.h"  // replaceWhole
#include "formats/storage.h"        // TempFileWriter

namespace brdfbake {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string errnoText(int err) { return std::strerror(err); }

void putU32(unsigned char* p, uint32_t v) {
  for (int b = 0; b < 4; ++b) p[b] = static_cast<unsigned char>(v >> (8 * b));
}
uint32_t getU32(const unsigned char* p) {
  uint32_t v = 0;
  for (int b = 0; b < 4; ++b) v |= uint32_t(p[b]) << (8 * b);
  return v;
}
void putF64(unsigned char* p, double d) {
  uint64_t v;
  std::memcpy(&v, &d, 8);
  for (int b = 0; b < 8; ++b) p[b] = static_cast<unsigned char>(v >> (8 * b));
}
double getF64(const unsigned char* p) {
  uint64_t v = 0;
  for (int b = 0; b < 8; ++b) v |= uint64_t(p[b]) << (8 * b);
  double d;
  std::memcpy(&d, &v, 8);
  return d;
}

// The bin's sample configuration (its lower edges) has both directions above the horizon:
// n.i = cos td cos th - sin td cos pd sin th, n.o = cos td cos th + sin td cos pd sin th.
bool binAboveHorizon(int th, int td, int pd) {
  double t = double(th) / kMerlThetaH, thetaH = t * t * kPi / 2, thetaD = double(td) / kMerlThetaD * kPi / 2;
  double phiD = double(pd) / kMerlPhiD * kPi;
  double a = std::cos(thetaD) * std::cos(thetaH), b = std::fabs(std::sin(thetaD) * std::cos(phiD) * std::sin(thetaH));
  return a - b > 0;
}

}  // namespace

Brdf3dSpec merlSpec(Brdf3dSpec s) {
  s.param = Brdf3dParam::Rusinkiewicz;
  s.thetaHSqrt = true;
  s.grid = Brdf3dGrid::CellStart;
  s.timesCos = false;
  s.nx = kMerlThetaH;
  s.ny = kMerlThetaD;
  s.nz = kMerlPhiD;
  return s;
}

void writeMerlTemporary(const std::string& tmp, const std::string& path,
                        const std::vector<std::vector<float>>& planes) {
  if (planes.size() != 1 && planes.size() != 3)
    throw Error(kExitDataErr,
                "cannot write " + path + ": a MERL file holds 1 or 3 channels, got " + std::to_string(planes.size()));
  for (const auto& p : planes)
    if (p.size() != kMerlBins)
      throw Error(kExitDataErr, "cannot write " + path + ": a MERL table has 90x90x180 = " + std::to_string(kMerlBins) +
                                    " values per channel, got " + std::to_string(p.size()));
  // everything is encoded (and checked) before the file is created
  std::vector<unsigned char> buf(kMerlFileBytes);
  putU32(buf.data(), kMerlThetaH);
  putU32(buf.data() + 4, kMerlThetaD);
  putU32(buf.data() + 8, kMerlPhiD);
  for (int c = 0; c < 3; ++c) {
    const std::vector<float>& p = planes[planes.size() == 3 ? c : 0];
    unsigned char* plane = buf.data() + 12 + size_t(c) * kMerlBins * 8;
    for (int z = 0; z < kMerlPhiD; ++z)
      for (int y = 0; y < kMerlThetaD; ++y)
        for (int x = 0; x < kMerlThetaH; ++x) {
          float v = p[(size_t(z) * kMerlThetaD + y) * kMerlThetaH + x];
          if (!std::isfinite(v))
            throw Error(kExitDataErr, "cannot write " + path + ": channel " + "RGB"[c] + " bin (theta_h " +
                                          std::to_string(x) + ", theta_d " + std::to_string(y) + ", phi_d " +
                                          std::to_string(z) + ") is not finite; nothing was written");
          putF64(plane + merlIndex(x, y, z) * 8, double(v) / kMerlScale[c]);
        }
  }
  TempFileWriter out(tmp, path);  // created, written, synced; removed on any failure
  out.write(buf.data(), buf.size());
  out.finish();
}

void writeMerl(const std::string& path, const std::vector<std::vector<float>>& planes) {
  replaceWhole(path, [&](const std::string& tmp) { writeMerlTemporary(tmp, path, planes); });
}

std::vector<std::vector<float>> merlPlanesFromSpec(const Brdf3dSpec& material) {
  Brdf3dSpec s = merlSpec(material);
  int channels = s.channels();
  std::vector<std::vector<float>> planes(channels, std::vector<float>(kMerlBins));
  for (int z = 0; z < s.nz; ++z)
    for (int y = 0; y < s.ny; ++y)
      for (int x = 0; x < s.nx; ++x) {
        Directions d = texelDirections(s, x, y, z);
        for (int c = 0; c < channels; ++c)
          planes[c][(size_t(z) * s.ny + y) * s.nx + x] = static_cast<float>(hostBrdf(s, d, c));
      }
  return planes;
}

std::array<double, 3> MerlData::coordinates(double thetaH, double thetaD, double phiD) {
  double u = std::sqrt(std::max(thetaH, 0.0) / (kPi / 2)) * kMerlThetaH;
  double v = thetaD / (kPi / 2) * kMerlThetaD;
  double w = std::fmod(phiD / kPi * kMerlPhiD, double(kMerlPhiD));
  if (w < 0) w += kMerlPhiD;
  return {u, v, w};
}

double MerlData::nearest(int c, double thetaH, double thetaD, double phiD) const {
  auto [u, v, w] = coordinates(thetaH, thetaD, phiD);
  auto bin = [](double t, int n) { return std::clamp(static_cast<int>(std::floor(t)), 0, n - 1); };
  return f[c][merlIndex(bin(u, kMerlThetaH), bin(v, kMerlThetaD), bin(w, kMerlPhiD))];
}

bool MerlData::trilinear(double u, double v, double w, double out[3]) const {
  u = std::clamp(u, 0.0, double(kMerlThetaH - 1));
  v = std::clamp(v, 0.0, double(kMerlThetaD - 1));
  int x0 = std::min(static_cast<int>(u), kMerlThetaH - 2), y0 = std::min(static_cast<int>(v), kMerlThetaD - 2);
  int z0 = std::min(static_cast<int>(w), kMerlPhiD - 1), z1 = (z0 + 1) % kMerlPhiD;
  double wx = u - x0, wy = v - y0, wz = w - z0;
  size_t idx[8];
  double wt[8];
  for (int k = 0; k < 8; ++k) {
    int dx = k & 1, dy = (k >> 1) & 1, dz = (k >> 2) & 1;
    idx[k] = merlIndex(x0 + dx, y0 + dy, dz ? z1 : z0);
    wt[k] = (dx ? wx : 1 - wx) * (dy ? wy : 1 - wy) * (dz ? wz : 1 - wz);
  }
  bool all = true;
  for (int c = 0; c < 3; ++c) {
    double sum = 0, wsum = 0;
    bool any = false;
    for (int k = 0; k < 8; ++k)
      if (usable[c][idx[k]]) {
        sum += wt[k] * f[c][idx[k]];
        wsum += wt[k];
        any = true;
      }
    // a usable corner of weight 0 (the point on a face) counts as support: take the nearest usable
    if (any && wsum <= 0) {
      double best = 2;
      for (int k = 0; k < 8; ++k) {
        int dx = k & 1, dy = (k >> 1) & 1, dz = (k >> 2) & 1;
        double dist = std::fabs(dx - wx) + std::fabs(dy - wy) + std::fabs(dz - wz);
        if (usable[c][idx[k]] && dist < best) best = dist, sum = f[c][idx[k]], wsum = 1;
      }
    }
    out[c] = any ? sum / wsum : 0.0;
    all = all && any;
  }
  return all;
}

bool MerlData::lookup(double thetaH, double thetaD, double phiD, double out[3]) const {
  auto [u, v, w] = coordinates(thetaH, thetaD, phiD);
  return trilinear(u, v, w, out);
}

MerlData readMerl(const std::string& path) {
  int fd;
  do {
    fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);  // a FIFO's open would block
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) throw Error(kExitNoInput, "cannot read MERL file " + path + ": " + errnoText(errno));
  struct stat st;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error(kExitNoInput,
                "cannot read MERL file " + path + ": " + fileTypeName(st.st_mode) + ", not a regular file");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  auto readAll = [&](unsigned char* p, size_t n) {
    size_t done = 0;
    while (done < n) {
      ssize_t r = ::read(fd, p + done, n - done);
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) {
        const int err = r < 0 ? errno : EIO;
        ::close(fd);
        throw Error(kExitNoInput,
                    "cannot read MERL file " + path + ": " + (r < 0 ? errnoText(err) : "file shrank while reading"));
      }
      done += static_cast<size_t>(r);
    }
  };
  const uint64_t size = static_cast<uint64_t>(st.st_size);
  unsigned char head[12];
  if (size >= 12) readAll(head, 12);
  const bool headOk =
      size >= 12 && getU32(head) == kMerlThetaH && getU32(head + 4) == kMerlThetaD && getU32(head + 8) == kMerlPhiD;
  if (size >= 12 && !headOk) {
    ::close(fd);
    char found[96];
    std::snprintf(found, sizeof found, "%d %d %d", int32_t(getU32(head)), int32_t(getU32(head + 4)),
                  int32_t(getU32(head + 8)));
    throw Error(kExitDataErr, "MERL file " + path +
                                  ": bad header: expected the dimensions 90 90 180 (three "
                                  "little-endian int32), found " +
                                  found);
  }
  if (size != kMerlFileBytes) {
    ::close(fd);
    throw Error(kExitDataErr, "MERL file " + path + ": wrong size: expected " + std::to_string(kMerlFileBytes) +
                                  " bytes (12-byte header and 3 x 90x90x180 doubles), found " + std::to_string(size));
  }
  std::vector<unsigned char> buf(kMerlFileBytes - 12);
  readAll(buf.data(), buf.size());
  ::close(fd);

  MerlData d;
  d.path = path;
  std::vector<uint8_t> above(kMerlBins);
  for (int th = 0; th < kMerlThetaH; ++th)
    for (int td = 0; td < kMerlThetaD; ++td)
      for (int pd = 0; pd < kMerlPhiD; ++pd) {
        bool a = binAboveHorizon(th, td, pd);
        above[merlIndex(th, td, pd)] = a;
        d.belowHorizon += !a;
      }
  for (int c = 0; c < 3; ++c) {
    d.f[c].resize(kMerlBins);
    d.usable[c].resize(kMerlBins);
    for (size_t i = 0; i < kMerlBins; ++i) {
      double raw = getF64(buf.data() + (size_t(c) * kMerlBins + i) * 8);
      if (!std::isfinite(raw)) {
        int th = int(i / (kMerlThetaD * kMerlPhiD)), td = int(i / kMerlPhiD % kMerlThetaD), pd = int(i % kMerlPhiD);
        throw Error(kExitDataErr, "MERL file " + path + ": channel " + "RGB"[c] + " bin (theta_h " +
                                      std::to_string(th) + ", theta_d " + std::to_string(td) + ", phi_d " +
                                      std::to_string(pd) +
                                      ") is not finite; expected a finite value (negative = not measured)");
      }
      d.f[c][i] = raw * kMerlScale[c];
      d.negative[c] += raw < 0;
      d.usable[c][i] = raw >= 0 && above[i];
    }
  }
  const size_t lit = kMerlBins - d.belowHorizon;
  for (int c = 0; c < 3; ++c) {
    size_t measured = 0;
    for (size_t i = 0; i < kMerlBins; ++i) measured += d.usable[c][i];
    d.measuredShare[c] = lit ? double(measured) / double(lit) : 0.0;
    if (d.measuredShare[c] < kMerlMinMeasured)
      throw Error(kExitDataErr, "MERL file " + path + ": channel " + "RGB"[c] + " measures " +
                                    std::to_string(measured) + " of the " + std::to_string(lit) +
                                    " bins above the horizon (" + fmtG(100 * d.measuredShare[c], 3) +
                                    "%); a material needs at least " + fmtG(100 * kMerlMinMeasured, 3) +
                                    "% (negative values mark unmeasured bins)");
  }
  return d;
}

}  // namespace brdfbake
