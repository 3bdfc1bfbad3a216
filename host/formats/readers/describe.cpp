// `brdfbake info FILE` for every format the baker writes (EXR: exr/table_file.h describeTableExr).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/format.h"
#include "formats/exr/table_file.h"
#include "formats/readers/table_reader.h"

namespace brdfbake {

namespace {

std::string container(FileFormat f) {
  switch (f) {
    case FileFormat::Exr:
      return "OpenEXR";
    case FileFormat::Ktx2:
      return "KTX 2.0";
    case FileFormat::Dds:
      return "DDS, DX10 header";
    case FileFormat::Png16:
      return "PNG";
    case FileFormat::Header:
      return "brdfbake's header format";
  }
  return "";
}

// "channel R: min <v> max <v>" per channel, as describeTableExr prints them.
void channelRanges(const TableFile& f, std::ostringstream& out) {
  for (size_t c = 0; c < f.table.planes.size(); ++c) {
    float lo = 0, hi = 0;
    bool any = false;
    size_t nonFinite = 0;
    for (float v : f.table.planes[c]) {
      if (!std::isfinite(v)) {
        ++nonFinite;
        continue;
      }
      lo = any ? std::min(lo, v) : v;
      hi = any ? std::max(hi, v) : v;
      any = true;
    }
    out << "  channel " << f.table.channels[c] << ":";
    if (any)
      out << " min " << fmtG9(lo) << " max " << fmtG9(hi);
    else
      out << " no finite values";
    if (nonFinite) out << " (" << nonFinite << " non-finite values)";
    out << "\n";
  }
}

}  // namespace

std::string describeTableFile(const TableFile& f) {
  if (f.format == FileFormat::Exr) return describeTableExr(f.path);
  std::ostringstream out;
  out << f.path << "\n";
  out << "  format: " << formatName(f.format) << " (" << container(f.format) << "), " << f.storage;
  if (f.storage.rfind(precisionName(f.precision), 0) != 0) out << " (" << precisionName(f.precision) << ")";
  out << "\n";
  out << "  size: " << f.table.width << "x" << f.table.height;
  if (f.depth > 1) out << "x" << f.depth;
  out << "\n  channels:";
  for (size_t c = 0; c < f.table.channels.size(); ++c) out << (c ? ", " : " ") << f.table.channels[c];
  out << "\n";
  if (f.format == FileFormat::Png16) {
    auto num = [&](const char* k, const char* fallback) {
      auto it = f.table.strings.find(k);
      return it == f.table.strings.end() ? std::string(fallback) : it->second;
    };
    out << "  values: png / 65535 * scale + offset, scale " << num("brdf.mapping.scale", "1 (no brdf.mapping.scale)")
        << ", offset " << num("brdf.mapping.offset", "0 (no brdf.mapping.offset)")
        << " (the channel ranges below are values)\n";
  }
  if (f.format == FileFormat::Dds) {
    TableImage meta;
    const std::string beside = ddsMetadataFile(f, &meta);
    out << "  metadata: none (DDS has no place for it); "
        << (beside.empty() ? "no .ktx2, .exr, .png, .h or .mjs beside it holds this table"
                           : beside + " beside it holds this table's (brdfbake info " + beside + ")")
        << "\n";
  }
  std::vector<std::pair<std::string, std::string>> text = f.text;
  std::stable_sort(text.begin(), text.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [k, v] : text) out << "  " << escapeText(k) << " (text): " << escapeText(v) << "\n";
  channelRanges(f, out);
  return out.str();
}

}  // namespace brdfbake
