// Reference values kept in tests/data/reference_values.txt.
//
// The independent reference (host/reference: nested adaptive Gauss-Kronrod in double, 1e-11 per
// integral) is what the slowest tests spent their time on: 96% of the average-albedo rule's tests,
// about 95% of the Fresnel albedo's and the sheen average's (perf), some 500 s of the
// suite's ~1900 s of CPU. Its values depend only on their arguments, so they are kept:
//   - a test asks `cached(key, compute)`; the key names the quantity and its exact arguments
//     (`keyOf`, doubles as hexadecimal floats);
//   - a key missing from the file fails the test (the value is computed and used meanwhile);
//   - every key whose hash falls in one sixteenth is recomputed on every run and must match the
//     file to 1e-12 of max(1, |value|) (deterministic: the same keys each run, spread over all);
//   - BRDFBAKE_REFERENCE=write computes every value the tests ask for and merges them into the file
//     (under flock, so ctest may run the writers in parallel): after a change to host/reference,
//     `BRDFBAKE_REFERENCE=write ctest -R "AvgRule|Fresnel|Sheen"` in build/.
#pragma once
#include "common/hash.h"
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

namespace brdfbake::testing_ref {

inline const std::string& valuesFile() {
  static const std::string path = std::string(BRDFBAKE_SOURCE_DIR) + "/tests/data/reference_values.txt";
  return path;
}

inline bool writing() {
  const char* e = std::getenv("BRDFBAKE_REFERENCE");
  return e && std::string(e) == "write";
}

// "what a1 a2 ...", each number as a hexadecimal float (exact, and the same text for the same value).
inline std::string keyOf(const std::string& what, std::initializer_list<double> args) {
  std::string k = what;
  char buf[64];
  for (double a : args) {
    std::snprintf(buf, sizeof buf, " %a", a);
    k += buf;
  }
  return k;
}

using Values = std::vector<double>;
using Table = std::map<std::string, Values>;

// The file: "key | v1 v2 ..." per line, values to 17 digits; '#' lines are comments.
inline Table parseValues(const std::string& text) {
  Table t;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const size_t bar = line.find(" | ");
    if (line.empty() || line[0] == '#' || bar == std::string::npos) continue;
    std::istringstream vs(line.substr(bar + 3));
    Values v;
    for (double x; vs >> x;) v.push_back(x);
    t[line.substr(0, bar)] = v;
  }
  return t;
}

struct Store {
  std::mutex lock;
  Table table, computed;
  Store() {
    FILE* f = std::fopen(valuesFile().c_str(), "rb");
    if (!f) return;
    std::string text;
    char buf[65536];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
    table = parseValues(text);
  }
  ~Store();
};

// With BRDFBAKE_REFERENCE=write: merge what this process computed into the file, under flock.
inline void mergeIntoFile(const Table& computed) {
  int fd = ::open(valuesFile().c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0 || ::flock(fd, LOCK_EX) != 0) {
    std::fprintf(stderr, "cannot lock %s\n", valuesFile().c_str());
    if (fd >= 0) ::close(fd);
    return;
  }
  std::vector<char> bytes;
  char buf[65536];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) bytes.insert(bytes.end(), buf, buf + n);
  Table merged = parseValues(std::string(bytes.begin(), bytes.end()));
  for (const auto& [k, v] : computed) merged[k] = v;
  std::string out =
      "# Values of the independent reference (host/reference) that the tests compare with; see\n"
      "# tests/reference_cache.h. Written by BRDFBAKE_REFERENCE=write (ctest in build/).\n";
  char num[40];
  for (const auto& [k, v] : merged) {
    out += k + " |";
    for (double x : v) {
      std::snprintf(num, sizeof num, " %.17g", x);
      out += num;
    }
    out += "\n";
  }
  if (::ftruncate(fd, 0) != 0 || ::lseek(fd, 0, SEEK_SET) != 0 ||
      ::write(fd, out.data(), out.size()) != static_cast<ssize_t>(out.size()))
    std::fprintf(stderr, "cannot write %s\n", valuesFile().c_str());
  ::close(fd);  // releases the lock
  std::fprintf(stderr, "merged %zu reference values into %s\n", computed.size(), valuesFile().c_str());
}

inline Store::~Store() {
  if (writing() && !computed.empty()) mergeIntoFile(computed);
}

inline Store& store() {
  static Store s;
  return s;
}

// FNV-1a of the key: which keys are recomputed each run, the same ones every time.
inline uint64_t keyHash(const std::string& k) { return brdfbake::fnv1a(k); }

// The reference's values for `key`: from the file, recomputed for one key in sixteen (and checked),
// computed and a failure where the file lacks them. Thread-safe (compute runs unlocked).
inline Values cached(const std::string& key, const std::function<Values()>& compute) {
  Store& s = store();
  Values kept;
  bool found = false;
  if (!writing()) {
    std::lock_guard<std::mutex> g(s.lock);
    auto it = s.table.find(key);
    if (it != s.table.end()) kept = it->second, found = true;
  }
  if (found && keyHash(key) % 16 != 0) return kept;
  Values now = compute();
  if (writing()) {
    std::lock_guard<std::mutex> g(s.lock);
    s.computed[key] = now;
  } else if (!found) {
    ADD_FAILURE() << "reference value \"" << key << "\" is not in " << valuesFile()
                  << " (computed instead); add it with BRDFBAKE_REFERENCE=write (tests/reference_cache.h)";
  } else {
    EXPECT_EQ(now.size(), kept.size()) << key;
    for (size_t i = 0; i < std::min(now.size(), kept.size()); ++i)
      EXPECT_NEAR(now[i], kept[i], 1e-12 * std::max(1.0, std::fabs(now[i])))
          << "the reference no longer gives the kept value of \"" << key << "\" (" << valuesFile() << ")";
  }
  return now;
}

inline double cached1(const std::string& key, const std::function<double()>& compute) {
  return cached(key, [&] { return Values{compute()}; })[0];
}

}  // namespace brdfbake::testing_ref
