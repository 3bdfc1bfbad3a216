// Format-independent checks of a TableImage.  See table_image.h for the contract.
#include "formats/table_image.h"

#include <cmath>
#include <cstdio>
#include <set>

#include "common/errors.h"
#include "common/format.h"

namespace brdfbake {
namespace {

constexpr float kHalfMax = 65504.0f;

[[noreturn]] void dataError(const std::string& path, const std::string& what) {
  throw Error(kExitDataErr, "cannot write " + path + ": " + what);
}

}  // namespace

int tableChannelRank(const std::string& name) {
  for (int i = 0; i < 4; ++i)
    if (name == kTableChannels[i]) return i;
  return -1;
}

void validateTableHeader(const std::string& path, const TableImage& img, const TableFormatRules& rules) {
  if (img.width < 1 || img.height < 1)
    dataError(path, "invalid table size " + std::to_string(img.width) + "x" + std::to_string(img.height));
  if (img.channels.empty()) dataError(path, "no channels");
  int lastRank = -1;
  for (const std::string& c : img.channels) {
    const int rank = tableChannelRank(c);
    if (rank < 0) dataError(path, "channel \"" + c + "\" is not one of R, G, B, A");
    if (rank <= lastRank) dataError(path, "channel " + c + " is duplicated or out of R, G, B, A order");
    lastRank = rank;
  }

  // Checked name by name, strings then v2f then floats, so the first offending name
  // in that order is the one reported.
  std::set<std::string> seen;
  auto checkName = [&](const std::string& name) {
    if (name.empty()) dataError(path, "empty attribute name");
    if (rules.isReservedAttribute && rules.isReservedAttribute(name))
      dataError(path, "attribute name \"" + name + "\" is reserved by " + rules.formatName);
    if (!seen.insert(name).second) dataError(path, "attribute \"" + name + "\" is given with two different types");
  };
  for (const auto& kv : img.strings) checkName(kv.first);
  for (const auto& kv : img.v2f) checkName(kv.first);
  for (const auto& kv : img.floats) checkName(kv.first);
}

void validateTableRows(const std::string& path, const TableImage& img, const std::vector<std::vector<float>>& planes,
                       int y0, int rows, const TableFormatRules& rules) {
  if (planes.size() != img.channels.size())
    dataError(path, std::to_string(img.channels.size()) + " channels but " + std::to_string(planes.size()) + " planes");
  const size_t w = static_cast<size_t>(img.width);
  const size_t count = w * static_cast<size_t>(rows);
  for (size_t ci = 0; ci < img.channels.size(); ++ci) {
    const std::string& c = img.channels[ci];
    const std::vector<float>& plane = planes[ci];
    if (plane.size() != count)
      dataError(path, "channel " + c + " has " + std::to_string(plane.size()) + " values, expected " +
                          std::to_string(img.width) + "*" + std::to_string(rows) + " = " + std::to_string(count));
    for (size_t i = 0; i < count; ++i) {
      const float v = plane[i];
      const char* problem = nullptr;
      if (std::isnan(v))
        problem = "is NaN";
      else if (std::isinf(v))
        problem = "is infinite";
      else if (rules.halfRange && std::fabs(v) > kHalfMax)
        problem = "exceeds the HALF range (|v| <= 65504)";
      if (problem)
        dataError(path, "channel " + c + " texel (x=" + std::to_string(i % w) + ", y=" + std::to_string(y0 + i / w) +
                            ") value " + fmtG9(v) + " " + problem);
    }
  }
}

void validateTableImage(const std::string& path, const TableImage& img, const TableFormatRules& rules) {
  validateTableHeader(path, img, rules);
  validateTableRows(path, img, img.planes, 0, img.height, rules);
}

}  // namespace brdfbake
