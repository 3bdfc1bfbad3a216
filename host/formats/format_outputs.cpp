// One table, every requested format: see format_outputs.h.
#include "formats/format_outputs.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/errors.h"
#include "common/format.h"
#include "formats/layout.h"
#include "formats/writers.h"

namespace brdfbake {

Precision effectivePrecision(FileFormat f, Precision p) { return f == FileFormat::Png16 ? Precision::Unorm16 : p; }

std::string pathStem(const std::string& path) {
  const size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  return dot == std::string::npos || (slash != std::string::npos && dot < slash) ? path : path.substr(0, dot);
}

std::vector<std::string> formatPaths(const std::string& stem, FileFormat f) {
  if (f == FileFormat::Header) return {stem + ".h", stem + ".mjs"};
  return {stem + formatExtension(f)};
}

namespace {

// "R16G16B16A16_SFLOAT" (Vulkan) or "R16G16B16A16_FLOAT" (DXGI) for n channels of precision p.
std::string componentName(int n, Precision p, bool vulkan) {
  std::string s;
  const std::string bits = std::to_string(8 * bytesPerChannel(p));
  for (int c = 0; c < n; ++c) s += std::string(1, "RGBA"[c]) + bits;
  return s + (isUnorm(p) ? "_UNORM" : vulkan ? "_SFLOAT" : "_FLOAT");
}

// Texel channels in the binary formats: an RGB table gets A = 1, since no 3-component 16- or
// 8-bit format is sampleable everywhere (DXGI has none; Vulkan's are optional).
int binaryChannels(int channels) { return channels == 3 ? 4 : channels; }

// The metadata of the file of `f`: the table's own, plus the format and precision, with
// brdf.error = the table's error without storage + `storage`.
}  // namespace

TableImage formatMetadata(const TableImage& src, FileFormat f, Precision p, double computeError, double storage,
                          int channels) {
  TableImage m = headerOf(src);
  const int out = f == FileFormat::Ktx2 || f == FileFormat::Dds ? binaryChannels(channels) : channels;
  std::string desc = formatName(f);
  if (f == FileFormat::Ktx2) desc += " VK_FORMAT_" + componentName(out, p, true);
  if (f == FileFormat::Dds) desc += " DXGI_FORMAT_" + componentName(out, p, false);
  m.strings["brdf.format"] = desc;
  m.strings["brdf.precision"] = precisionName(p);
  if (out > channels) m.strings["brdf.channels"] += "; A=1 (padding)";
  m.floats["brdf.error"] = static_cast<float>(computeError + storage);
  m.strings["brdf.error.storage"] = fmtG(storage, 3) + " (" + precisionName(p) + " rounding in " + formatName(f) +
                                    ", relative to max(1, |v|), included in brdf.error)";
  return m;
}

OutputFile formatWriter(const std::string& path, FileFormat f, Precision p, const TableImage& meta,
                        const SliceSource& src, const std::string& stem, bool js) {
  OutputFile o;
  o.path = path;
  const int out = binaryChannels(src.channels);
  const uint64_t texels = uint64_t(src.width) * src.height * src.depth;
  // header: .h and .mjs, at most 18 characters per value ("-1.23456789e-05f, "); else texels and a header
  o.bytesBound = f == FileFormat::Header ? 2 * (texels * out * 18 + 65536) : texels * out * 4 + 65536;
  const std::string name = "brdf_" + stem.substr(stem.find_last_of('/') + 1);
  o.write = [f, p, meta, src, out, name, js, path](const std::string& tmp) {
    if (f == FileFormat::Ktx2)
      writeKtx2Temporary(tmp, path, meta, src, out, p);
    else if (f == FileFormat::Dds)
      writeDdsTemporary(tmp, path, src, out, p);
    else
      writeHeaderTemporary(tmp, path, meta, src, p, name, js);
  };
  return o;
}

std::vector<PlannedFile> tableOutputs(const FileSpec& job, const TableImage& baked, std::deque<TableImage>& keep) {
  // the engine's layout (formats/layout.h): every file of the set holds the same arrangement
  const TableImage* arranged = &baked;
  if (!job.layout.identity() || !job.layoutName.empty()) {
    TableImage& l = keep.emplace_back(job.layout.identity() ? baked : applyLayout(baked, job.layout));
    // the preset by name, and how the engine samples it (`info` prints both)
    l.strings["brdf.layout"] = job.layoutName;
    for (const LayoutPreset& p : layoutPresets())
      if (p.name == job.layoutName) l.strings["brdf.layout.sampling"] = p.citation;
    arranged = &l;
  }
  const TableImage& img = *arranged;
  const std::string stem = pathStem(job.path);
  const Precision exrPrecision = job.half ? Precision::Float16 : Precision::Float32;
  double exrStorage = 0;
  for (const auto& plane : img.planes) exrStorage = std::max(exrStorage, storageError(plane, exrPrecision));
  double lo0 = img.planes.empty() || img.planes[0].empty() ? 0 : img.planes[0][0], hi0 = lo0;
  for (const auto& plane : img.planes)
    for (float v : plane) lo0 = std::min<double>(lo0, v), hi0 = std::max<double>(hi0, v);
  const double stated = img.floats.count("brdf.error") ? img.floats.at("brdf.error") : 0.0;
  const double computeError = std::max(0.0, stated - exrStorage);
  const std::string table = img.strings.count("brdf.table") ? img.strings.at("brdf.table") : "table";
  for (FileFormat f : job.formats)
    if (f != FileFormat::Png16 && f != FileFormat::Exr && isUnorm(job.precision) &&
        (lo0 < -kUnormSlack || hi0 > 1 + kUnormSlack))
      throw Error(kExitUsage, stem + formatExtension(f) + ": the " + table + " table's values span [" + fmtG(lo0) +
                                  ", " + fmtG(hi0) + "], outside [0, 1], which " + precisionName(job.precision) +
                                  " cannot hold; float32 or float16 (exr, ktx2, dds, header) can, and png16 maps the "
                                  "range onto its 16 bits; nothing was written");

  std::vector<PlannedFile> files;
  const int nchan = static_cast<int>(img.channels.size());
  if (nchan < 3 && std::find(job.formats.begin(), job.formats.end(), FileFormat::Png16) != job.formats.end())
    throw Error(kExitUsage, stem + ".png: --format png16 stores RGB or RGBA, and this " + table + " table has " +
                                std::to_string(nchan) +
                                " channels (--channels); give three (e.g. --channels A,B,A+B) or "
                                "another format (ktx2, dds, exr, header); nothing was written");
  SliceSource src;
  src.width = img.width;
  src.height = img.height;
  src.channels = nchan;
  src.fill = [&img](int, int, std::vector<std::vector<float>>& planes) { planes = img.planes; };
  for (FileFormat f : job.formats) {
    const Precision p = effectivePrecision(f, job.precision);
    if (f == FileFormat::Exr) {
      files.push_back({OutputFile{stem + ".exr", &img, job.half, {}}, stated});
      continue;
    }
    if (f == FileFormat::Png16) {
      // value = png / 65535 * scale + offset over [min(0, lo), max(1, hi)]: the identity for [0, 1] tables
      const double offset = std::min(0.0, lo0), scale = std::max(1.0, hi0) - offset;
      double storage = 0;
      for (const auto& plane : img.planes)
        for (float v : plane) {
          const double back = std::nearbyint((v - offset) / scale * 65535.0) / 65535.0 * scale + offset;
          storage = std::max(storage, std::fabs(back - v) / std::max(1.0, std::fabs(static_cast<double>(v))));
        }
      storage += std::ldexp(1.0, -24);
      TableImage& m = keep.emplace_back(formatMetadata(img, f, p, computeError, storage, nchan));
      m.planes = img.planes;
      m.strings["brdf.mapping"] =
          "value = png / 65535 * scale + offset (scale = brdf.mapping.scale, offset = "
          "brdf.mapping.offset; png the 16-bit sample)";
      m.strings["brdf.mapping.scale"] = fmtG(scale, 17);
      m.strings["brdf.mapping.offset"] = fmtG(offset, 17);
      const std::string path = stem + ".png";
      OutputFile o;
      o.path = path;
      o.bytesBound = uint64_t(m.width) * m.height * 4 * 2 + 65536;  // 16-bit RGBA at most, and chunks
      o.write = [&m, path, scale, offset](const std::string& tmp) { writePng16Temporary(tmp, path, m, scale, offset); };
      files.push_back({o, m.floats["brdf.error"]});
      continue;
    }
    double storage = 0;
    for (const auto& plane : img.planes) storage = std::max(storage, storageError(plane, p));
    const TableImage& m = keep.emplace_back(formatMetadata(img, f, p, computeError, storage, nchan));
    const std::vector<std::string> paths = formatPaths(stem, f);
    for (size_t k = 0; k < paths.size(); ++k)
      files.push_back({formatWriter(paths[k], f, p, m, src, stem, k == 1), m.floats.at("brdf.error")});
  }
  return files;
}

}  // namespace brdfbake
