// How a figure on a page in docs/ is compared with the output that produces it, shared by the docs
// tests (readme_test.cpp, which run the commands the pages name) and by the tests whose own printout
// the pages quote (expectPagesQuote, which check the pages against what they have just printed, so
// a run of minutes is not run twice).
//
// A page ties a figure to a test's printout with a comment after its paragraph, unseen where the
// page is read:
//   <!-- figure X after "WORDS" [#N] in: Suite.Name -->    one figure in the prose above
//   <!-- rows in: Suite.Name -->                           every body row of the table above
// (and, for commands the docs tests run, "from: COMMAND" in place of "in: Suite.Name").
// BRDFBAKE_SOURCE_DIR is the source tree (tests/CMakeLists.txt, SOURCE_DIR).
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdarg>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace brdfbake::testing_docs {

// Half a unit in the last digit a figure is written with ("1.2e-7": 5e-9; "31.04": 0.005).
inline double halfUnit(const std::string& figure) {
  const size_t e = figure.find_first_of("eE");
  const std::string mantissa = figure.substr(0, e);
  const size_t dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  const int exponent = e == std::string::npos ? 0 : std::atoi(figure.c_str() + e + 1);
  return 0.5 * std::pow(10.0, exponent - decimals);
}

// Whether the word `got` is the word `shown`: the same text, or the same number (within 2% and half
// a unit in the shown figure's last digit) with the same text around it ("(3.65e-2)" is "(3.650e-02)",
// "2.6x" is "2.62x").
inline bool shownWordMatches(const std::string& shown, const std::string& got) {
  if (shown == got) return true;
  const size_t sa = shown.find_first_not_of("(["), ga = got.find_first_not_of("([");
  if (sa == std::string::npos || ga == std::string::npos || shown.compare(0, sa, got, 0, ga) != 0) return false;
  const char *ps = shown.c_str() + sa, *pg = got.c_str() + ga;
  char *es = nullptr, *eg = nullptr;
  const double x = std::strtod(ps, &es), y = std::strtod(pg, &eg);
  if (es == ps || eg == pg || std::string(es) != std::string(eg)) return false;
  const std::string figure(ps, static_cast<size_t>(es - ps));
  return std::fabs(x - y) <= 0.02 * std::max(std::fabs(x), std::fabs(y)) + halfUnit(figure);
}

// Whether an output line is the line a page shows. Words are compared one by one: a number as
// shownWordMatches compares it (the figures a page quotes to three or four digits, rounding that
// may differ between CPUs' vector widths), a word the page marks with a leading "~" not at all
// (seconds, and what varies from run to run), every other word exactly. A shown line ending in
// "..." shows the output line's first words (the last one's beginning where "..." follows it
// without a space).
inline bool shownLineMatches(const std::string& shownLine, const std::string& got) {
  std::string shown = shownLine;
  const bool prefix = shown.size() > 3 && shown.compare(shown.size() - 3, 3, "...") == 0;
  if (prefix) shown.resize(shown.size() - 3);
  const bool partialLast = prefix && !shown.empty() && shown.back() != ' ';
  std::istringstream ws(shown), wg(got);
  std::vector<std::string> a, b;
  for (std::string w; ws >> w;) a.push_back(w);
  for (std::string w; wg >> w;) b.push_back(w);
  if (prefix ? a.size() > b.size() : a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (partialLast && i + 1 == a.size()) return b[i].compare(0, a[i].size(), a[i]) == 0;
    if (a[i][0] == '~' || shownWordMatches(a[i], b[i])) continue;
    return false;
  }
  return true;
}

// v in the short scientific form the pages write: "8.1e-8", "2.63e-3", "0" (digits after the point).
inline std::string sci(double v, int digits) {
  if (v == 0) return "0";
  char b[32];
  std::snprintf(b, sizeof b, "%.*e", digits, v);
  std::string s = b;
  const size_t e = s.find('e');
  std::string exp = s.substr(e + 1);
  const bool negative = exp[0] == '-';
  exp.erase(0, exp.find_first_not_of("+-0"));
  return s.substr(0, e) + (exp.empty() ? "" : "e" + std::string(negative ? "-" : "") + exp);
}

// The n-th number (1-based) in `text` at or after `from` (as a command prints figures: "8.20e-07",
// "0.0159", "2592"; "128x128" is two), or NaN when there are fewer.
inline double numberAfter(const std::string& text, size_t from, int n) {
  static const std::regex number("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");
  const std::string rest = text.substr(from);
  int k = 0;
  for (std::sregex_iterator it(rest.begin(), rest.end(), number), end; it != end; ++it)
    if (++k == n) return std::strtod(it->str().c_str(), nullptr);
  return std::nan("");
}

// Whether `output` prints `figure` as the nth number after `words` on one of its lines: to the
// digits it is written with and within 2%.
inline bool printsFigure(const std::string& output, const std::string& figure, const std::string& words, int nth) {
  const double want = std::strtod(figure.c_str(), nullptr), tolerance = halfUnit(figure) + 0.02 * std::fabs(want);
  std::istringstream os(output);
  for (std::string line; std::getline(os, line);) {
    const size_t at = line.find(words);
    if (at != std::string::npos && std::fabs(numberAfter(line, at + words.size(), nth) - want) <= tolerance)
      return true;
  }
  return false;
}

// A figure note: <!-- figure X after "WORDS" [#N] (from: COMMAND | in: Suite.Name) -->, at most
// three spaces in (a list item's; four or more make it code, an example of the form).
inline const std::regex& figureNote() {
  static const std::regex note(
      "^ {0,3}<!-- figure (\\S+) after \"([^\"]+)\"(?: #(\\d+))? (?:from: (brdfbake-bench .+|brdfbake(?: .*)?|ctest -R "
      "[\\w./]+ -V)|in: ([\\w./]+)) -->");
  return note;
}

// A table note, right under the table's last row: <!-- rows in: Suite.Name --> (that test checks
// the rows against its printout) or <!-- rows from: COMMAND --> (the docs test runs the command, a
// source of the figure notes' form, and checks them against its output).
inline const std::regex& rowsNote() {
  static const std::regex note(
      "^<!-- rows (?:in: ([\\w./]+)|from: (brdfbake-bench .+|brdfbake(?: .*)?|ctest -R [\\w./]+ -V)) -->");
  return note;
}

// Whether `output` has a line (leading spaces and ctest -V's "N: " left out) that is `row`
// (shownLineMatches).
inline bool printsRow(const std::string& output, const std::string& row) {
  static const std::regex prefix("^ *(\\d+: )?");
  std::istringstream os(output);
  for (std::string line; std::getline(os, line);)
    if (shownLineMatches(row, std::regex_replace(line, prefix, "", std::regex_constants::format_first_only)))
      return true;
  return false;
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

inline std::string fileText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The pages: README.md and docs/*.md, in a fixed order.
inline std::vector<std::filesystem::path> pages() {
  std::vector<std::filesystem::path> out{std::filesystem::path(BRDFBAKE_SOURCE_DIR) / "README.md"};
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(BRDFBAKE_SOURCE_DIR) / "docs"))
    if (e.path().extension() == ".md") out.push_back(e.path());
  std::sort(out.begin() + 1, out.end());
  return out;
}

// The body rows of the table whose last row is page[end - 1]: its lines starting with "|" above,
// less the header and the |---| line.
inline std::vector<std::string> tableRowsAbove(const std::vector<std::string>& page, size_t end) {
  size_t begin = end;
  while (begin > 0 && page[begin - 1].rfind("|", 0) == 0) --begin;
  std::vector<std::string> rows;
  for (size_t k = begin + 2; k < end; ++k) rows.push_back(page[k]);
  return rows;
}

// Prints a line and appends it to `said`: a test that the pages quote keeps what it prints, to hand
// to expectPagesQuote below.
__attribute__((format(printf, 2, 3))) inline void say(std::string& said, const char* format, ...) {
  char line[400];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  std::fputs(line, stdout);
  said += line;
}

// The test that calls this has just printed `printout`. Every figure and table the pages tie to
// this test ("in: Suite.Name", its whole gtest name) is checked against it: a figure as the docs
// tests check one (it stands in its paragraph; printsFigure), a table's every body row as a line
// of the printout (shownLineMatches: numbers within 2%, "~" words skipped). A test that calls this
// with no page quoting it fails, so a renamed test or a dropped note shows.
inline void expectPagesQuote(const std::string& printout) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string self = std::string(info->test_suite_name()) + "." + info->name();
  int quoted = 0;
  for (const std::filesystem::path& path : pages()) {
    const std::vector<std::string> page = lines(fileText(path));
    for (size_t i = 0; i < page.size(); ++i) {
      std::smatch m;
      const std::string where = path.filename().string() + ":" + std::to_string(i + 1);
      if (std::regex_search(page[i], m, figureNote()) && m[5].matched && m[5].str() == self) {
        ++quoted;
        const std::string figure = m[1].str();
        bool inProse = false;
        for (size_t k = i; k-- > 0 && !page[k].empty();) inProse |= page[k].find(figure) != std::string::npos;
        EXPECT_TRUE(inProse) << where << ": " << figure << " is not in the paragraph above its note";
        const int nth = m[3].matched ? std::atoi(m[3].str().c_str()) : 1;
        EXPECT_TRUE(printsFigure(printout, figure, m[2].str(), nth))
            << where << ": " << self << " prints " << figure << " nowhere as number " << nth << " after \"" << m[2]
            << "\"";
      } else if (std::regex_search(page[i], m, rowsNote()) && m[1].matched && m[1].str() == self) {
        const std::vector<std::string> rows = tableRowsAbove(page, i);
        EXPECT_FALSE(rows.empty()) << where << ": no table right above the note";
        for (const std::string& row : rows) {
          ++quoted;
          EXPECT_TRUE(printsRow(printout, row))
              << where << ": " << self << " prints no line that is the row\n  " << row;
        }
      }
    }
  }
  EXPECT_GT(quoted, 0) << "no page quotes " << self << " (<!-- rows in: " << self << " --> or <!-- figure X after "
                       << "\"WORDS\" in: " << self << " -->)";
}

}  // namespace brdfbake::testing_docs
