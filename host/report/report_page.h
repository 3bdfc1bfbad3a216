// One report run's page: sections of text and tables, CSV data, and plots drawn by gnuplot (a
// maintained plotting tool; Debian gnuplot-nox) as SVG, gathered in index.html in the run's
// directory. Without gnuplot the page and the data are still written, with the scripts that draw
// the plots and a line that says how to get them. The directory lands whole: it is written under a
// temporary name beside its target and renamed at the end.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace brdfbake {

class ReportPage {
 public:
  explicit ReportPage(std::string title) : title_(std::move(title)) {}

  // The page's one-line verdict, shown first under the title whatever order the page is built in:
  // PASS or FAIL (a check), or a measurement's summary line (Outcome::Measured).
  enum class Outcome { Pass, Fail, Measured };
  void verdict(Outcome outcome, const std::string& text);
  void heading(const std::string& text);
  void paragraph(const std::string& text);     // HTML-escaped
  void preformatted(const std::string& text);  // the terminal table, as printed
  // A data file (CSV) in the run's directory, linked from the page.
  void data(const std::string& fileName, const std::string& csv);
  // A plot: `script` is gnuplot commands that read data files by name and draw to the output the
  // page sets (SVG, `plotName`.svg); it appears on the page with its caption.
  void plot(const std::string& plotName, const std::string& script, const std::string& caption);
  // An image file (a render's PNG) that `write` makes at the path it is given, shown with its caption.
  void image(const std::string& fileName, const std::string& caption, std::function<void(const std::string&)> write);

  // Writes everything into `dir` (replacing a previous run's), runs gnuplot when it is on PATH.
  // Returns a line for the terminal: where the page is, or how to get the plots.
  std::string write(const std::string& dir) const;

  // gnuplot ($BRDFBAKE_GNUPLOT, else on PATH) can be run.
  static bool gnuplotAvailable();

 private:
  struct Item {
    enum Kind { Heading, Paragraph, Pre, Data, Plot, Image } kind;
    std::string a, b, c;
    std::function<void(const std::string&)> write;  // Image
  };
  std::string title_;
  std::vector<Item> items_;
  Outcome outcome_ = Outcome::Measured;
  std::string verdict_;
};

}  // namespace brdfbake
