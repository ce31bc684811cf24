// gnuplot and pgfplots writers for the charts (see chart_plot.hpp).
#include "numeric/charts/chart_plot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "derivations/syntax/io.hpp"

namespace dc::chart {

namespace {

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.9g", x);
  return b;
}

std::string gp_quote(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    o += c;
  }
  return o + "\"";
}

std::string tex_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '_': o += "\\_"; break;
      case '%': o += "\\%"; break;
      case '&': o += "\\&"; break;
      case '#': o += "\\#"; break;
      case '^': o += "\\^{}"; break;
      case '$': o += "\\$"; break;
      default: o += c;
    }
  }
  return o;
}

// High-contrast colours on white (Okabe and Ito's palette without its yellow, then darker
// tones): series i uses kColours[i % 10].
const char* const kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#000000",
                                "#E69F00", "#56B4E9", "#882255", "#117733", "#332288"};

bool have_gnuplot() {
  return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

}  // namespace

bool plottable(const Plot& p, const PlotPoint& q) {
  if (!std::isfinite(q.x) || !std::isfinite(q.y)) return false;
  if (p.logx && q.x <= 0) return false;
  if (p.logy && q.y <= 0) return false;
  return true;
}

Plot merge_identical_series(const Plot& in) {
  Plot p = in;
  p.series.clear();
  auto drawn = [&](const PlotSeries& s) {
    std::vector<std::pair<double, double>> v;
    for (const auto& q : s.points)
      if (plottable(in, q)) v.emplace_back(q.x, q.y);
    return v;
  };
  std::vector<bool> used(in.series.size(), false);
  for (std::size_t i = 0; i < in.series.size(); ++i) {
    if (used[i]) continue;
    PlotSeries s = in.series[i];
    const auto pts = drawn(s);
    for (std::size_t j = i + 1; j < in.series.size() && !pts.empty(); ++j)
      if (!used[j] && in.series[j].bars == s.bars && drawn(in.series[j]) == pts) {
        s.name += " = " + in.series[j].name;
        used[j] = true;
      }
    p.series.push_back(std::move(s));
  }
  return p;
}

std::string gnuplot_script(const Plot& in, const std::string& terminal, const std::string& out_path) {
  const Plot p = merge_identical_series(in);
  const bool categorical = !p.xcategories.empty();
  std::ostringstream o;
  if (terminal == "svg")
    o << "set terminal svg size 900,600 dynamic enhanced font 'Helvetica,13' background rgb 'white'\n";
  else
    o << "set terminal pngcairo size 900,600 enhanced font 'Helvetica,11'\n";
  o << "set output " << gp_quote(out_path) << "\n";
  o << "set title " << gp_quote(p.title) << " noenhanced\n";
  o << "set xlabel " << gp_quote(p.xlabel) << " noenhanced\nset ylabel " << gp_quote(p.ylabel) << " noenhanced\n";
  if (p.logx && !categorical) o << "set logscale x\nset format x '10^{%L}'\n";
  if (p.logy) o << "set logscale y\nset format y '10^{%L}'\n";
  o << "set grid xtics ytics mxtics mytics lc rgb '#dddddd'\n";
  // the legend below the x label, with a gap, one column per four entries
  o << "set key outside below center maxrows 4 noenhanced spacing 1.2 height 1\nset xlabel offset 0,-0.3\n";
  if (categorical) {
    o << "set xtics (";
    for (std::size_t i = 0; i < p.xcategories.size(); ++i)
      o << (i ? ", " : "") << gp_quote(p.xcategories[i]) << " " << i;
    o << ") rotate by 35 right noenhanced\nset xrange [-0.6:" << num(static_cast<double>(p.xcategories.size()) - 0.4) << "]\n";
  }
  const bool lo_fixed = std::isfinite(p.ymin), hi_fixed = std::isfinite(p.ymax);
  o << "set offsets " << (categorical ? "0, 0" : "graph 0.04, graph 0.04") << ", graph " << (hi_fixed ? "0" : "0.06")
    << ", graph " << (lo_fixed ? "0" : "0.06") << "\n";
  if (lo_fixed || hi_fixed)
    o << "set yrange [" << (lo_fixed ? num(p.ymin) : "*") << ":" << (hi_fixed ? num(p.ymax) : "*") << "]\n";
  o << "set border lw 1.2\nset pointsize 1.1\n";
  for (const auto& [x, label] : p.vlines)
    o << "set arrow from " << num(x) << ", graph 0 to " << num(x) << ", graph 1 nohead dt 2 lc rgb '#888888'\n"
      << "set label " << gp_quote(label) << " at " << num(x) << ", graph 0.97 offset 0.5,0 noenhanced tc rgb '#555555'\n";
  // data blocks
  int i = 0;
  for (const auto& s : p.series) {
    o << "$d" << i++ << " << EOD\n";
    for (const auto& q : s.points)
      if (plottable(p, q)) o << num(q.x) << " " << num(q.y) << " " << num(q.ylo) << " " << num(q.yhi) << "\n";
    o << "EOD\n";
  }
  o << "plot ";
  i = 0;
  bool first = true;
  for (const auto& s : p.series) {
    const int idx = i++;
    bool any = false;
    for (const auto& q : s.points) any = any || plottable(p, q);
    if (!any) continue;
    if (!first) o << ", \\\n     ";
    first = false;
    const std::string lc = std::string(" lc rgb '") + kColours[idx % 10] + "' lw 1.5";
    const int pt = idx % 13 + 1;
    if (s.bars)
      o << "$d" << idx << " using 1:2:3:4 with yerrorbars" << lc << " pt " << pt << " title " << gp_quote(s.name)
        << (s.lines ? ", $d" + std::to_string(idx) + " using 1:2 with lines" + lc + " notitle" : "");
    else
      o << "$d" << idx << " using 1:2 with " << (s.lines ? "linespoints" : "points") << lc << " pt " << pt
        << " title " << gp_quote(s.name);
  }
  if (first) o << "1/0 notitle";
  o << "\nunset output\n";
  return o.str();
}

std::string pgfplots(const Plot& in) {
  Plot p = merge_identical_series(in);
  if (!p.xcategories.empty()) p.logx = false;
  std::ostringstream o;
  o << "% generated by derivcheck chart; \\usepackage{pgfplots}\n\\begin{tikzpicture}\n\\begin{"
    << (p.logx && p.logy ? "loglogaxis" : p.logx ? "semilogxaxis" : p.logy ? "semilogyaxis" : "axis") << "}[\n"
    << "  title={" << tex_escape(p.title) << "},\n  xlabel={" << tex_escape(p.xlabel) << "},\n  ylabel={"
    << tex_escape(p.ylabel) << "},\n  width=12cm, height=8cm, grid=major,\n"
    << "  legend pos=outer north east, legend style={font=\\footnotesize},\n";
  if (std::isfinite(p.ymin)) o << "  ymin=" << num(p.ymin) << ",\n";
  if (std::isfinite(p.ymax)) o << "  ymax=" << num(p.ymax) << ",\n";
  if (!p.xcategories.empty()) {
    o << "  xtick={";
    for (std::size_t i = 0; i < p.xcategories.size(); ++i) o << (i ? "," : "") << i;
    o << "}, xticklabels={";
    for (std::size_t i = 0; i < p.xcategories.size(); ++i) o << (i ? "," : "") << "{" << tex_escape(p.xcategories[i]) << "}";
    o << "}, x tick label style={rotate=35, anchor=east, font=\\scriptsize},\n";
  }
  o << "]\n";
  for (const auto& s : p.series) {
    bool any = false;
    for (const auto& q : s.points) any = any || plottable(p, q);
    if (!any) continue;
    o << "\\addplot+[" << (s.lines ? "" : "only marks, ")
      << (s.bars ? "error bars/.cd, y dir=both, y explicit" : "mark size=1.5pt") << "] coordinates {\n";
    for (const auto& q : s.points) {
      if (!plottable(p, q)) continue;
      o << "  (" << num(q.x) << ", " << num(q.y) << ")";
      if (s.bars) o << " -= (0, " << num(q.y - q.ylo) << ") += (0, " << num(q.yhi - q.y) << ")";
      o << "\n";
    }
    o << "};\n\\addlegendentry{" << tex_escape(s.name) << "}\n";
  }
  for (const auto& [x, label] : p.vlines)
    o << "\\draw[dashed, gray] ({axis cs:" << num(x) << ",0}|-{rel axis cs:0,0}) -- ({axis cs:" << num(x)
      << ",0}|-{rel axis cs:0,1}) node[below right, font=\\footnotesize] {" << tex_escape(label) << "};\n";
  o << "\\end{" << (p.logx && p.logy ? "loglogaxis" : p.logx ? "semilogxaxis" : p.logy ? "semilogyaxis" : "axis")
    << "}\n\\end{tikzpicture}\n";
  return o.str();
}

std::vector<std::string> write_figures(const Plot& p, const std::string& stem) {
  std::vector<std::string> written;
  write_file_atomic(stem + ".tex", pgfplots(p));
  written.push_back(stem + ".tex");
  if (!have_gnuplot()) return written;
  for (const auto& [term, ext] : {std::pair<std::string, std::string>{"pngcairo", ".png"}, {"svg", ".svg"}}) {
    const std::string out = stem + ext;
    // gnuplot renders into the writer's temporary file (its script goes through a pipe), so
    // a failed or interrupted run leaves the previous figure and no stray files.
    write_file_atomic_at(out, [&](const std::string& tmp) {
      const std::string script = gnuplot_script(p, term, tmp);
      FILE* g = ::popen("gnuplot 2>/dev/null", "w");
      if (!g) throw std::runtime_error("gnuplot failed to start for " + out);
      const bool sent = std::fwrite(script.data(), 1, script.size(), g) == script.size();
      const int rc = ::pclose(g);
      std::error_code ec;
      if (!sent || rc != 0 || std::filesystem::file_size(tmp, ec) == 0 || ec)
        throw std::runtime_error("gnuplot failed to render " + out);
    });
    written.push_back(out);
  }
  return written;
}

}  // namespace dc::chart
