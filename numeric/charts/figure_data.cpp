// Figures drawn from a file's formulas or from a scene (see figure_data.hpp).
#include "numeric/charts/figure_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

#include "derivations/reader/figures.hpp"
#include "numeric/scenes/spec.hpp"

namespace dc::chart {

namespace {

constexpr int kPlotIntervals = 200;          // 201 points along the range
constexpr std::size_t kSceneRows = 400;      // at most this many rows of a simulation

[[noreturn]] void fail(const Derivation& d, const SourcePos& p, const std::string& msg, int len = 1) {
  throw InputError(p, msg, std::max(1, len), d.source.line(p.line));
}

int name_length(const FigureName& n) { return static_cast<int>(n.name.size()); }

// A unit as the author wrote it ("m/s^2", "kg*m/s", "m^(-1/2)") in upright TeX math; "" for
// none or a dimensionless "1".
std::string unit_tex(const std::string& u) {
  if (u.empty() || u == "1") return {};
  std::string out;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const char c = u[i];
    if (c == '*') {
      out += "\\,";
    } else if (c == '^') {
      std::string e;
      std::size_t j = i + 1;
      if (j < u.size() && u[j] == '(') {
        for (++j; j < u.size() && u[j] != ')'; ++j) e += u[j];
      } else {
        while (j < u.size() && (std::isdigit(static_cast<unsigned char>(u[j])) || u[j] == '-')) e += u[j++];
        --j;
      }
      out += "^{" + e + "}";
      i = j;
    } else {
      out += c;
    }
  }
  return "$\\mathrm{" + out + "}$";
}

std::string symbol_tex(const SymbolInfo& s) { return "$" + s.tex + "$"; }
std::string with_unit(const std::string& what, const std::string& unit) {
  const std::string u = unit_tex(unit);
  return u.empty() ? what : what + " [" + u + "]";
}

// A constant of the figure line (a `with` value or an end of the range) as an exact GiNaC
// number; its symbols would make it no number at all.
GiNaC::ex constant(const Derivation& d, const Node& n, const std::string& what) {
  GiNaC::ex v;
  try {
    v = resolved_ginac(d, n);
  } catch (const InputError& e) {
    fail(d, n.pos, what + " must be a number: " + e.message(), n.length);
  }
  const GiNaC::ex f = v.evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(f) || !GiNaC::ex_to<GiNaC::numeric>(f).is_real() ||
      !std::isfinite(GiNaC::ex_to<GiNaC::numeric>(f).to_double()))
    fail(d, n.pos, what + " must be a finite real number, not '" + to_text(n) + "'", n.length);
  return v;
}

double to_double(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(e.evalf()).to_double(); }

FigureTable plot_table(const Derivation& d, const FigureSpec& spec) {
  FigureTable t;
  // the curves: steps `y = expression`
  std::vector<Formula> fs;
  for (const auto& c : spec.curves) {
    if (!d.find(c.name)) fail(d, c.pos, "no step labelled '" + c.name + "' in this file to plot", name_length(c));
    try {
      fs.push_back(formula(d, c.name));
    } catch (const InputError& e) {
      fail(d, c.pos, "cannot plot '" + c.name + "': " + e.message(), name_length(c));
    }
  }
  // the horizontal axis
  const SymbolInfo* var = d.symbols.find(spec.var.name);
  if (!var || var->is_function)
    fail(d, spec.var.pos, "'" + spec.var.name + "' is not a declared symbol of this file to plot against",
         name_length(spec.var));
  bool used = false;
  for (const auto& f : fs) used = used || f.expr.has(var->sym);
  if (!used)
    fail(d, spec.var.pos, "no plotted formula depends on '" + spec.var.name + "'", name_length(spec.var));
  const GiNaC::ex lo = constant(d, spec.lo, "the lower end of the range"),
                  hi = constant(d, spec.hi, "the upper end of the range");
  if (!(to_double(lo) < to_double(hi)) || (lo - hi).evalf().is_zero())
    fail(d, spec.range_pos,
         "empty or reversed range " + to_text(spec.lo) + " .. " + to_text(spec.hi) + ": the lower end must be below the upper",
         spec.range_length);
  // the values held fixed
  GiNaC::exmap fixed;
  for (const auto& w : spec.with) {
    const SymbolInfo* s = d.symbols.find(w.name.name);
    if (!s || s->is_function)
      fail(d, w.name.pos, "'" + w.name.name + "' is not a declared symbol of this file", name_length(w.name));
    if (s->name == var->name)
      fail(d, w.name.pos, "'" + w.name.name + "' runs along the horizontal axis; it takes no value after 'with'",
           name_length(w.name));
    const GiNaC::ex v = constant(d, w.value, "the value of '" + w.name.name + "'");
    const GiNaC::ex vf = v.evalf();
    if (GiNaC::is_a<GiNaC::numeric>(v) && !s->domain.contains(GiNaC::ex_to<GiNaC::numeric>(v)))
      fail(d, w.value.pos, "'" + w.name.name + "' = " + to_text(w.value) + " lies outside its declared domain",
           w.value.length);
    if (!GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::is_a<GiNaC::numeric>(vf) &&
        !s->domain.contains(GiNaC::ex_to<GiNaC::numeric>(vf)))
      fail(d, w.value.pos, "'" + w.name.name + "' = " + to_text(w.value) + " lies outside its declared domain",
           w.value.length);
    fixed[s->sym] = v;
  }
  for (std::size_t i = 0; i < fs.size(); ++i)
    for (const auto& p : fs[i].params) {
      const SymbolInfo* s = d.symbols.find(p.get_name());
      if (!s || s->name == var->name || fixed.count(s->sym)) continue;
      fail(d, spec.curves[i].pos,
           "symbol '" + s->name + "' of '" + spec.curves[i].name + "' has no value: give it after 'with' (with " +
               s->name + " = ...)",
           name_length(spec.curves[i]));
    }
  // one axis for every curve: their quantities share a unit
  std::vector<const SymbolInfo*> ys;
  for (const auto& f : fs) ys.push_back(d.symbols.find(f.target));
  for (std::size_t i = 1; i < ys.size(); ++i)
    if (ys[i]->has_dimension && ys[0]->has_dimension && !(ys[i]->dimension == ys[0]->dimension))
      fail(d, spec.curves[i].pos,
           "'" + spec.curves[i].name + "' gives " + ys[i]->name + " [" + ys[i]->unit + "], but '" + spec.curves[0].name +
               "' gives " + ys[0]->name + " [" + ys[0]->unit + "]: curves of one figure share the vertical axis",
           name_length(spec.curves[i]));
  t.xlabel = with_unit(symbol_tex(*var), var->unit);
  std::string names;
  for (std::size_t i = 0; i < ys.size(); ++i) names += (i ? ", " : "") + symbol_tex(*ys[i]);
  t.ylabel = with_unit(names, ys[0]->unit);
  if (ys.size() > 1)
    for (const auto* y : ys) t.legends.push_back(symbol_tex(*y));
  // the points: exact x, exact values, one evaluation to double at the end
  std::vector<GiNaC::ex> exprs;
  for (const auto& f : fs) exprs.push_back(f.expr.subs(fixed));
  for (int i = 0; i <= kPlotIntervals; ++i) {
    const GiNaC::ex x = lo + (hi - lo) * GiNaC::numeric(i, kPlotIntervals);
    std::vector<double> row{to_double(x)};
    for (const auto& e : exprs) {
      double y = std::nan("");
      try {
        const GiNaC::ex v = e.subs(GiNaC::lst{var->sym == x}).evalf();
        if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()) y = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
      } catch (const std::exception&) {
        // undefined here (a division by zero): a gap in the curve
      }
      row.push_back(std::isfinite(y) ? y : std::nan(""));
    }
    t.rows.push_back(std::move(row));
  }
  for (std::size_t c = 0; c < exprs.size(); ++c) {
    bool any = false;
    for (const auto& row : t.rows) any = any || !std::isnan(row[c + 1]);
    if (!any)
      fail(d, spec.curves[c].pos,
           "'" + spec.curves[c].name + "' has no real value anywhere on " + spec.var.name + " = " + to_text(spec.lo) +
               " .. " + to_text(spec.hi) + " with the values given",
           name_length(spec.curves[c]));
  }
  return t;
}

FigureTable scene_table(const Derivation& d, const FigureSpec& spec) {
  const scenes::SceneSpec* sc = nullptr;
  try {
    sc = &scenes::find_scene(spec.scene.name);
  } catch (const std::invalid_argument& e) {
    fail(d, spec.scene.pos, e.what(), name_length(spec.scene));
  }
  scenes::Params p = scenes::defaults(*sc);
  for (const auto& w : spec.with) {
    if (!p.count(w.name.name)) {
      std::string names;
      for (const auto& ps : sc->params) names += (names.empty() ? "" : ", ") + ps.name;
      fail(d, w.name.pos, "scene '" + sc->name + "' has no parameter '" + w.name.name + "'; its parameters: " + names,
           name_length(w.name));
    }
    p[w.name.name] = to_double(constant(d, w.value, "the value of '" + w.name.name + "'"));
  }
  scenes::SceneResult r;
  try {
    scenes::RunOptions opt;             // as `derivcheck simulate` runs it without options
    opt.method = sc->default_method;
    r = scenes::run_scene(*sc, p, opt);
  } catch (const std::exception& e) {   // a parameter out of bounds (domain_error), a bad step
    fail(d, spec.pos, e.what(), 8);
  }
  const auto& f = r.figure;
  if (f.y.empty() || r.series.rows.empty())
    fail(d, spec.scene.pos, "scene '" + sc->name + "' draws no figure", name_length(spec.scene));
  auto col = [&](const std::string& name) {
    auto it = std::find(r.series.columns.begin(), r.series.columns.end(), name);
    if (it == r.series.columns.end()) throw std::logic_error("figure: no column '" + name + "'");
    return static_cast<std::size_t>(it - r.series.columns.begin());
  };
  FigureTable t;
  t.xlabel = f.xlabel;
  t.ylabel = f.ylabel;
  for (const auto& y : f.y) t.legends.push_back(y.second);
  if (t.legends.size() == 1) t.legends.clear();
  std::vector<std::size_t> cols{col(f.x)};
  for (const auto& y : f.y) cols.push_back(col(y.first));
  const std::size_t n = r.series.rows.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + kSceneRows - 1) / kSceneRows);
  for (std::size_t i = 0; i < n; i += stride) {
    std::vector<double> row;
    for (std::size_t c : cols) row.push_back(r.series.rows[i][c]);
    t.rows.push_back(std::move(row));
  }
  if ((n - 1) % stride != 0) {   // the run's last state closes the curve
    std::vector<double> row;
    for (std::size_t c : cols) row.push_back(r.series.rows[n - 1][c]);
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  if (v == 0) return "0";   // also -0
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

std::string FigureTable::text() const {
  std::string out = "x";
  const std::size_t ny = rows.empty() ? 0 : rows[0].size() - 1;
  for (std::size_t i = 1; i <= ny; ++i) out += " y" + std::to_string(i);
  out += "\n";
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size(); ++i) out += (i ? " " : "") + number(r[i]);
    out += "\n";
  }
  return out;
}

std::string FigureTable::pgfplots(const std::string& data_file) const {
  std::ostringstream o;
  o << "\\begin{tikzpicture}\n\\begin{axis}[width=0.8\\linewidth, height=0.45\\linewidth, grid=major,\n"
    << "  xlabel={" << xlabel << "}, ylabel={" << ylabel << "},\n"
    << "  scaled ticks=false, tick label style={/pgf/number format/fixed}, unbounded coords=jump, enlarge x limits=false";
  if (!legends.empty())   // above the axes, in one row: the picture keeps its width
    o << ",\n  legend style={at={(0.5,1.03)}, anchor=south, legend columns=-1, draw=none,\n    /tikz/every even column/.append style={column sep=1em}}";
  o << "]\n";
  const std::size_t ny = rows.empty() ? 0 : rows[0].size() - 1;
  std::string inline_table;
  if (data_file.empty()) {
    std::string t = text();
    for (std::size_t i = 0; i < t.size(); ++i)
      inline_table += t[i] == '\n' ? std::string("\\\\\n") : std::string(1, t[i]);
  }
  for (std::size_t i = 1; i <= ny; ++i) {
    o << "\\addplot+[thick, mark=none] table[x index=0, y index=" << i;
    if (data_file.empty()) o << ", row sep=\\\\] {\n" << inline_table << "};\n";
    else o << "] {" << data_file << "};\n";
    if (!legends.empty()) o << "\\addlegendentry{" << legends[i - 1] << "}\n";
  }
  o << "\\end{axis}\n\\end{tikzpicture}";
  return o.str();
}

namespace {

// Tick values for [lo, hi]: steps of 1, 2 or 5 times a power of ten, about five of them.
std::vector<double> ticks(double lo, double hi) {
  std::vector<double> out;
  const double span = hi - lo;
  if (!(span > 0) || !std::isfinite(span)) return {lo};
  const double raw = span / 5;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double step = raw / p < 1.5 ? p : raw / p < 3.5 ? 2 * p : raw / p < 7.5 ? 5 * p : 10 * p;
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step)
    out.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
  return out;
}

std::string num(double v, const char* fmt = "%.1f") {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

// Text with TeX math between $…$, for the page: escaped for HTML, and the math delimited by
// \( \) as the page's KaTeX auto-render expects.
std::string html_text(const std::string& s) {
  std::string out;
  bool open = false;
  for (char c : s) {
    if (c == '$') {
      out += open ? "\\)" : "\\(";
      open = !open;
    } else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string FigureTable::svg() const {
  constexpr double W = 560, H = 300, L = 64, R = 16, T = 14, B = 36;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  bool any = false;
  for (const auto& row : rows)
    for (std::size_t i = 1; i < row.size(); ++i) {
      if (!std::isfinite(row[i]) || !std::isfinite(row[0])) continue;
      if (!any) {
        x0 = x1 = row[0];
        y0 = y1 = row[i];
        any = true;
      }
      x0 = std::min(x0, row[0]);
      x1 = std::max(x1, row[0]);
      y0 = std::min(y0, row[i]);
      y1 = std::max(y1, row[i]);
    }
  if (!(x1 > x0)) x1 = x0 + 1;
  if (!(y1 > y0)) {
    y0 -= 0.5;
    y1 += 0.5;
  }
  const double pad = (y1 - y0) * 0.05;
  y0 -= pad;
  y1 += pad;
  auto px = [&](double x) { return L + (x - x0) / (x1 - x0) * (W - L - R); };
  auto py = [&](double y) { return T + (y1 - y) / (y1 - y0) * (H - T - B); };
  static const char* const kColours[] = {"#1f5fa8", "#c0392b", "#2e8b57", "#8e44ad", "#d35400"};
  std::ostringstream o;
  o << "<svg class=\"plot\" viewBox=\"0 0 " << W << " " << H << "\" width=\"" << W << "\" height=\"" << H
    << "\" role=\"img\">\n";
  o << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << (W - L - R) << "\" height=\"" << (H - T - B)
    << "\" fill=\"none\" stroke=\"#777\"/>\n";
  for (double t : ticks(x0, x1))
    o << "<line x1=\"" << num(px(t)) << "\" y1=\"" << num(H - B) << "\" x2=\"" << num(px(t)) << "\" y2=\""
      << num(T) << "\" stroke=\"#e4e4e8\"/><text x=\"" << num(px(t)) << "\" y=\"" << num(H - B + 16)
      << "\" font-size=\"11\" text-anchor=\"middle\">" << num(t, "%.6g") << "</text>\n";
  for (double t : ticks(y0, y1))
    o << "<line x1=\"" << num(L) << "\" y1=\"" << num(py(t)) << "\" x2=\"" << num(W - R) << "\" y2=\""
      << num(py(t)) << "\" stroke=\"#e4e4e8\"/><text x=\"" << num(L - 6) << "\" y=\"" << num(py(t) + 4)
      << "\" font-size=\"11\" text-anchor=\"end\">" << num(t, "%.6g") << "</text>\n";
  const std::size_t ny = rows.empty() ? 0 : rows[0].size() - 1;
  for (std::size_t i = 1; i <= ny; ++i) {
    std::string points;
    auto flush = [&] {
      if (points.find(' ') != std::string::npos)
        o << "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" << kColours[(i - 1) % 5] << "\" points=\""
          << points << "\"/>\n";
      points.clear();
    };
    for (const auto& row : rows) {
      if (!std::isfinite(row[0]) || !std::isfinite(row[i])) {
        flush();
        continue;
      }
      points += (points.empty() ? "" : " ") + num(px(row[0])) + "," + num(py(row[i]));
    }
    flush();
  }
  o << "</svg>\n<div class=\"axes\">horizontal: " << html_text(xlabel) << "; vertical: " << html_text(ylabel);
  for (std::size_t i = 0; i < legends.size(); ++i)
    o << "; <span style=\"color:" << kColours[i % 5] << "\">&#9632;</span> " << html_text(legends[i]);
  o << "</div>";
  return o.str();
}

std::map<const Prose*, std::string> svg_figures(const std::vector<const Derivation*>& ds) {
  std::map<const Prose*, std::string> out;
  for (const Derivation* d : ds) {
    const auto specs = figure_specs(*d);
    for (const auto& [index, spec] : specs) out[&d->prose[index]] = figure_table(*d, spec).svg();
  }
  return out;
}

FigureTable figure_table(const Derivation& d, const FigureSpec& spec) {
  switch (spec.kind) {
    case FigureSpec::Kind::Plot: return plot_table(d, spec);
    case FigureSpec::Kind::Scene: return scene_table(d, spec);
    case FigureSpec::Kind::Placeholder: break;
  }
  throw std::logic_error("figure_table: a placeholder draws nothing");
}

DrawnFigures draw_figures(const std::vector<const Derivation*>& ds, const std::string& stem) {
  DrawnFigures out;
  int number = 0;
  for (const Derivation* d : ds) {
    const auto specs = figure_specs(*d);
    for (std::size_t i = 0; i < d->prose.size(); ++i) {
      if (d->prose[i].kind != Prose::Kind::Figure) continue;
      ++number;
      auto it = specs.find(i);
      if (it == specs.end()) continue;
      const FigureTable t = figure_table(*d, it->second);
      if (stem.empty()) {
        out.pictures[&d->prose[i]] = t.pgfplots("");
        continue;
      }
      const std::string name = stem + "-fig" + std::to_string(number) + ".dat";
      out.files.push_back({name, t.text()});
      out.pictures[&d->prose[i]] = t.pgfplots(name);
    }
  }
  return out;
}

}  // namespace dc::chart
