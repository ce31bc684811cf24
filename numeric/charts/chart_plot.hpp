// Figures for the charts: one description (axes with units, log scales, series with optional
// min-max bars) written as a gnuplot script (PNG + SVG) and as a pgfplots tikzpicture for the
// LaTeX handouts. All files are written atomically (dc::write_file_atomic; gnuplot renders
// into a temporary file that is then renamed).
#pragma once
#include <cmath>
#include <string>
#include <vector>

namespace dc::chart {

struct PlotPoint {
  double x = 0, y = 0;
  double ylo = 0, yhi = 0;   // min-max bar (used when Series::bars)
};
struct PlotSeries {
  std::string name;          // legend (plain text; TeX-escaped for pgfplots)
  std::vector<PlotPoint> points;
  bool bars = false;         // draw ylo..yhi bars
  bool lines = true;         // connect the points
};
struct Plot {
  std::string title, xlabel, ylabel;   // labels with units: "time per evaluation [s]"
  bool logx = true, logy = true;
  std::vector<PlotSeries> series;
  // Optional vertical reference lines (x, label), e.g. omega h = 2.
  std::vector<std::pair<double, std::string>> vlines;
  // Categorical x axis: point x = i sits at the tick labelled xcategories[i] (logx ignored).
  std::vector<std::string> xcategories;
  // Known bounds of the data (a fraction never exceeds 1, bits lost are never negative): the
  // axis stops there instead of padding beyond it. NaN: automatic.
  double ymin = std::nan(""), ymax = std::nan("");
};

// Series whose drawn points coincide exactly are merged into one, named "A = B", so that no
// series hides under another (both writers call it).
Plot merge_identical_series(const Plot& p);

// The gnuplot script for `p` rendering to `out_path` with terminal "pngcairo" or "svg".
std::string gnuplot_script(const Plot& p, const std::string& terminal, const std::string& out_path);
// A pgfplots tikzpicture (\begin{tikzpicture}...), loglog axes as requested.
std::string pgfplots(const Plot& p);

// Writes STEM.png, STEM.svg (via gnuplot, if it is installed) and STEM.tex. Returns the list of
// files written; throws std::runtime_error if gnuplot exists but fails.
std::vector<std::string> write_figures(const Plot& p, const std::string& stem);

// Points with non-positive (or non-finite) coordinates cannot sit on log axes; they are
// dropped by the writers. Exposed for the tests.
bool plottable(const Plot& p, const PlotPoint& q);

}  // namespace dc::chart
