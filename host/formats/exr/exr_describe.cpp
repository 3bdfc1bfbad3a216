// The `brdfbake info` description of an EXR table.  See table_file.h for the contract.
#include <ImfAttribute.h>
#include <ImfBoxAttribute.h>
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfDoubleAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfPixelType.h>
#include <ImfStringAttribute.h>
#include <ImfStringVectorAttribute.h>
#include <ImfVecAttribute.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/format.h"
#include "formats/exr/exr_internal.h"
#include "formats/exr/table_file.h"

namespace brdfbake {
namespace {

using exr::as;
using exr::dataWindowOf;
using exr::isStandardAttribute;
using exr::openExr;
using exr::readPlanes;
using exr::Window;

const char* pixelTypeName(Imf::PixelType t) {
  switch (t) {
    case Imf::UINT:
      return "UINT";
    case Imf::HALF:
      return "HALF";
    case Imf::FLOAT:
      return "FLOAT";
    default:
      return "UNKNOWN";
  }
}

const char* compressionName(Imf::Compression c) {
  switch (c) {
    case Imf::NO_COMPRESSION:
      return "NONE";
    case Imf::RLE_COMPRESSION:
      return "RLE";
    case Imf::ZIPS_COMPRESSION:
      return "ZIPS";
    case Imf::ZIP_COMPRESSION:
      return "ZIP";
    case Imf::PIZ_COMPRESSION:
      return "PIZ";
    case Imf::PXR24_COMPRESSION:
      return "PXR24";
    case Imf::B44_COMPRESSION:
      return "B44";
    case Imf::B44A_COMPRESSION:
      return "B44A";
    case Imf::DWAA_COMPRESSION:
      return "DWAA";
    case Imf::DWAB_COMPRESSION:
      return "DWAB";
    default:
      return "UNKNOWN";
  }
}

std::string attributeValue(const Imf::Attribute& a) {
  if (auto s = as<Imf::StringAttribute>(a)) return escapeText(s->value());
  if (auto f = as<Imf::FloatAttribute>(a)) return fmtG9(f->value());
  if (auto d = as<Imf::DoubleAttribute>(a)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", d->value());
    return buf;
  }
  if (auto i = as<Imf::IntAttribute>(a)) return std::to_string(i->value());
  if (auto v = as<Imf::V2fAttribute>(a)) return "(" + fmtG9(v->value().x) + ", " + fmtG9(v->value().y) + ")";
  if (auto v = as<Imf::V2dAttribute>(a)) return "(" + fmtG9(v->value().x) + ", " + fmtG9(v->value().y) + ")";
  if (auto v = as<Imf::V2iAttribute>(a))
    return "(" + std::to_string(v->value().x) + ", " + std::to_string(v->value().y) + ")";
  if (auto v = as<Imf::V3fAttribute>(a))
    return "(" + fmtG9(v->value().x) + ", " + fmtG9(v->value().y) + ", " + fmtG9(v->value().z) + ")";
  if (auto v = as<Imf::V3iAttribute>(a))
    return "(" + std::to_string(v->value().x) + ", " + std::to_string(v->value().y) + ", " +
           std::to_string(v->value().z) + ")";
  if (auto b = as<Imf::Box2iAttribute>(a)) {
    const Imath::Box2i& v = b->value();
    return "(" + std::to_string(v.min.x) + ", " + std::to_string(v.min.y) + ") - (" + std::to_string(v.max.x) + ", " +
           std::to_string(v.max.y) + ")";
  }
  if (auto b = as<Imf::Box2fAttribute>(a)) {
    const Imath::Box2f& v = b->value();
    return "(" + fmtG9(v.min.x) + ", " + fmtG9(v.min.y) + ") - (" + fmtG9(v.max.x) + ", " + fmtG9(v.max.y) + ")";
  }
  if (auto sv = as<Imf::StringVectorAttribute>(a)) {
    std::string out = "[";
    for (size_t i = 0; i < sv->value().size(); ++i) {
      if (i) out += ", ";
      out += "\"" + escapeText(sv->value()[i]) + "\"";
    }
    return out + "]";
  }
  return "<value not shown>";
}

}  // namespace

std::string describeTableExr(const std::string& path) {
  std::unique_ptr<Imf::InputFile> file = openExr(path);
  const Imf::Header& h = file->header();
  const Window win = dataWindowOf(path, h);

  std::ostringstream out;
  out << path << "\n";
  out << "  size: " << win.width << "x" << win.height << "\n";
  if (win.box.min.x != 0 || win.box.min.y != 0)
    out << "  data window origin: (" << win.box.min.x << ", " << win.box.min.y << ")\n";

  // Channels in R, G, B, A order, then any others in the file's (alphabetical) order.
  std::vector<std::pair<std::string, const Imf::Channel*>> channels;
  for (const char* c : kTableChannels)
    if (const Imf::Channel* ch = h.channels().findChannel(c)) channels.emplace_back(c, ch);
  for (Imf::ChannelList::ConstIterator it = h.channels().begin(); it != h.channels().end(); ++it)
    if (tableChannelRank(it.name()) < 0) channels.emplace_back(it.name(), &it.channel());

  std::vector<std::string> names;  // unsubsampled channels
  std::vector<std::string> subsampled;
  out << "  channels:";
  for (size_t i = 0; i < channels.size(); ++i) {
    const Imf::Channel& ch = *channels[i].second;
    out << (i ? ", " : " ") << channels[i].first << " (" << pixelTypeName(ch.type) << ")";
    if (ch.xSampling == 1 && ch.ySampling == 1)
      names.push_back(channels[i].first);
    else
      subsampled.push_back(channels[i].first);
  }
  if (channels.empty()) out << " none";
  out << "\n";
  out << "  compression: " << compressionName(h.compression()) << "\n";

  // Header iteration is in name order already.
  for (Imf::Header::ConstIterator it = h.begin(); it != h.end(); ++it) {
    if (isStandardAttribute(it.name())) continue;
    out << "  " << it.name() << " (" << it.attribute().typeName() << "): " << attributeValue(it.attribute()) << "\n";
  }

  const std::vector<std::vector<float>> planes = readPlanes(path, *file, win, names);
  for (size_t i = 0; i < names.size(); ++i) {
    float lo = 0.0f, hi = 0.0f;
    bool any = false;
    size_t nonFinite = 0;
    for (float v : planes[i]) {
      if (!std::isfinite(v)) {
        ++nonFinite;
        continue;
      }
      if (!any || v < lo) lo = v;
      if (!any || v > hi) hi = v;
      any = true;
    }
    out << "  channel " << names[i] << ":";
    if (any)
      out << " min " << fmtG9(lo) << " max " << fmtG9(hi);
    else
      out << " no finite values";
    if (nonFinite) out << " (" << nonFinite << " non-finite values)";
    out << "\n";
  }
  for (const std::string& c : subsampled) out << "  channel " << c << ": subsampled, not read\n";
  return out.str();
}

}  // namespace brdfbake
