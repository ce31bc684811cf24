// The scene table (one place declaring every scene's parameters, DOFs and assumptions),
// parameter parsing and validation, and the figure writers.
#include "numeric/scenes/spec.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

ParamSpec positive(std::string name, std::string unit, double def, std::string what) {
  return {std::move(name), std::move(unit), def, 0, kInf, true, false, {}, {}, std::move(what)};
}
ParamSpec nonneg(std::string name, std::string unit, double def, std::string what) {
  return {std::move(name), std::move(unit), def, 0, kInf, false, false, {}, {}, std::move(what)};
}
ParamSpec real(std::string name, std::string unit, double def, std::string what) {
  return {std::move(name), std::move(unit), def, -kInf, kInf, false, false, {}, {}, std::move(what)};
}
ParamSpec restitution(std::string name, double def, std::string what) {
  return {std::move(name), "1", def, 0, 1, false, false, {}, {}, std::move(what)};
}
ParamSpec gravity(double def = 9.81) {
  return positive("g", "m/s^2", def, "gravitational acceleration");
}

const std::vector<Method> kAll = {Method::euler, Method::rk4, Method::dopri5, Method::verlet, Method::rosenbrock};
const std::vector<Method> kFirstOrder = {Method::euler, Method::rk4, Method::dopri5, Method::rosenbrock};

std::vector<SceneSpec> make_table() {
  std::vector<SceneSpec> t;
  {
    SceneSpec s;
    s.name = "spring";
    s.title = "Two masses and a spring";
    s.handout = "Example 9.3";
    s.dofs = "x1, x2: positions of the two masses along the spring's line (2 DOF, 1-D)";
    s.assumptions = {"motion along the spring's axis only (v0 along the spring)",
                     "linear massless spring F = k (x2 - x1 - L0); no gravity, friction or other external force",
                     "start: x1 = 0, x2 = L0 (spring relaxed), m1 at rest, m2 given v0",
                     "no collision of the masses is modelled (the spring may be compressed below zero length)"};
    s.params = {positive("m1", "kg", 1, "mass 1 (handout: 1 kg)"),
                positive("m2", "kg", 2, "mass 2 (handout: 2 kg)"),
                positive("k", "N/m", 5, "spring stiffness (handout: 5 N/m)"),
                positive("L0", "m", 1, "rest length (handout: 1 m)"),
                real("v0", "m/s", 2, "initial velocity of m2 (handout: 2 m/s)"),
                positive("t_end", "s", 10, "simulated time")};
    s.methods = kAll;
    s.default_h = 0.01;
    s.run = run_spring;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "pendulum";
    s.title = "Ballistic pendulum";
    s.handout = "Example 9.5";
    s.dofs = "theta: swing angle of the box (1 DOF; the bifilar suspension keeps the box level, so it moves as a particle on a circle of radius L)";
    s.assumptions = {"perfectly inelastic impact (e = 0), instantaneous: the box does not move during it (momentum, §9.3.1)",
                     "inextensible massless strings, no air drag",
                     "the strings stay taut: this needs the swing to stay at or below the horizontal (theta_max <= pi/2). "
                     "At the turning point the string tension is (M+m) g cos(theta_max), negative above the horizontal, so "
                     "the strings would go slack before the box got there and the closed form no longer applies. "
                     "The rigid-rod bound (acos argument >= -1, over the top) is weaker and is not used."};
    s.params = {positive("m", "kg", 0.01, "projectile mass (handout gives no numbers)"),
                positive("M", "kg", 2, "box mass"),
                nonneg("v0", "m/s", 300, "projectile velocity"),
                positive("L", "m", 1, "string length"),
                gravity()};
    s.methods = kAll;
    s.default_h = 1e-3;
    s.run = run_pendulum;
    s.check = check_pendulum;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "bounce";
    s.title = "Two-ball bounce";
    s.handout = "Example 9.6";
    s.dofs = "y1, y2: heights of the centres of the tennis ball (1) and the basket ball (2) (2 DOF, vertical)";
    s.assumptions = {"both balls released from rest together; the tennis ball's bottom is s above the basket ball's top",
                     "free flight under gravity between impacts (exact parabolas; event times solved exactly)",
                     "instantaneous impacts: ball 2 with the ground (restitution e2), ball 1 with ball 2 (e12)",
                     "no air drag; the ground is fixed (infinite mass)",
                     "reported: the velocities right after the first ball-ball impact (the closed form's v'1, v'2)"};
    s.params = {positive("m1", "kg", 0.057, "tennis ball mass (handout gives no numbers)"),
                positive("m2", "kg", 0.6, "basket ball mass"),
                positive("r1", "m", 0.033, "tennis ball radius"),
                positive("r2", "m", 0.12, "basket ball radius"),
                {"y2", "m", 1.0, 0, kInf, true, false, "r2", {}, "initial height of the basket ball's centre"},
                nonneg("s", "m", 1e-3, "initial separation between the balls"),
                restitution("e2", 1, "restitution ball 2 - ground"),
                restitution("e12", 1, "restitution ball 1 - ball 2"),
                gravity()};
    s.run = run_bounce;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "rocket";
    s.title = "Ideal rocket with gravity";
    s.handout = "§9.4";
    s.dofs = "z: height (1 DOF, vertical); the mass m_r(t) = m0 - mu t is prescribed";
    s.assumptions = {"constant burn rate mu and exhaust velocity u_e; no drag; vertical flight (theta = 0); constant g",
                     "starts at rest, v(0) = 0; no launch pad: if u_e mu < m0 g the rocket accelerates downwards, as the equation says",
                     "simulated until burnout, when the mass reaches m_r"};
    s.params = {positive("m0", "kg", 1000, "wet mass (handout gives no numbers)"),
                {"m_r", "kg", 300, 0, kInf, true, false, {}, "m0", "mass at burnout (dry mass)"},
                positive("mu", "kg/s", 10, "burn rate"),
                positive("u_e", "m/s", 2500, "relative exhaust velocity"),
                {"g", "m/s^2", 9.81, 0, kInf, false, false, {}, {}, "gravitational acceleration"}};
    s.methods = kAll;
    s.default_h = 0.1;
    s.run = run_rocket;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "chain";
    s.title = "Chain falling on a scale";
    s.handout = "Example 9.7";
    s.dofs = "x: length of chain already on the scale = distance fallen by the upper end (1 DOF)";
    s.assumptions = {"perfectly flexible chain, held vertically with its lower end touching the scale, released from rest",
                     "the falling part is in free fall (the links landing exert no force on it): x'' = g",
                     "each link stops on landing (perfectly inelastic); the scale's force is the weight on it plus the momentum flux rho v^2",
                     "integrated as x'' = g from x = 0, x' = 0: the first-order form x' = sqrt(2 g x) also admits x = 0 for all t "
                     "and a numerical method started at x = 0 never leaves it"};
    s.params = {positive("m", "kg", 1, "chain mass (handout gives no numbers)"),
                positive("L", "m", 1, "chain length"),
                gravity(),
                {"x", "m", 0.5, 0, kInf, false, false, {}, "L", "fallen length at which N is reported"}};
    s.methods = kAll;
    s.default_h = 1e-3;
    s.run = run_chain;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "ladder";
    s.title = "Sliding ladder";
    s.handout = "Example 9.2";
    s.dofs = "theta: angle between ladder and floor (1 DOF while the top touches the wall)";
    s.assumptions = {"uniform rod of length l, frictionless wall and floor, released from rest at theta0",
                     "planar motion; the top stays on the wall until the wall reaction N_w = m x_G'' would become negative",
                     "the wall's horizontal impulse int N_w dt is integrated alongside theta and compared with m v_Gx at separation"};
    s.params = {positive("m", "kg", 10, "ladder mass (handout gives no numbers)"),
                positive("l", "m", 4, "ladder length"),
                {"theta0", "deg", 60, 0, 90, true, true, {}, {}, "initial angle from the floor (90: unstable equilibrium, never starts)"},
                gravity()};
    s.methods = kFirstOrder;
    s.default_h = 1e-3;
    s.run = run_ladder;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "cradle";
    s.title = "Newton's cradle";
    s.handout = "§9.3.1 (elastic impact, equal masses)";
    s.dofs = "v_1 ... v_n: velocities of the n balls along the line (n DOF, impacts only)";
    s.assumptions = {"n equal balls in a row, just touching; ball 1 arrives with v0, the others at rest",
                     "sequential pairwise impacts: the approaching pair with the lowest index is resolved first "
                     "(each impact solved as the linear system (9.6)+(9.7)), until no pair approaches",
                     "swinging (gravity) is not modelled: velocities right after the impacts"};
    ParamSpec n{"n", "1", 5, 2, 1000, false, false, {}, {}, "number of balls", true};
    s.params = {n, positive("m", "kg", 0.1, "mass of each ball"), positive("v0", "m/s", 1, "velocity of ball 1"),
                restitution("e", 1, "coefficient of restitution")};
    s.run = run_cradle;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "cannon";
    s.title = "Cannon recoil from a finite force pulse";
    s.handout = "Example 9.1";
    s.dofs = "x_p, x_c: positions of projectile and cannon along the bore (2 DOF)";
    s.assumptions = {"gun free to roll without friction, bore horizontal, both at rest before firing",
                     "the charge pushes both with equal and opposite force F(t) for 0 <= t <= tau (several pulse shapes); no other horizontal force",
                     "the projectile stays in the bore during the pulse (the pulse ends before it leaves)"};
    s.params = {positive("m_p", "kg", 10, "projectile mass (handout gives no numbers)"),
                positive("m_c", "kg", 1000, "cannon mass"),
                positive("F0", "N", 1e5, "peak force of the pulse"),
                positive("tau", "s", 0.01, "pulse duration")};
    s.methods = kAll;
    s.default_h = 1e-4;
    s.run = run_cannon;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "impact";
    s.title = "Direct central impact as a linear system";
    s.handout = "§9.3.1, (9.6) and (9.7)";
    s.dofs = "v'1, v'2 (2 unknowns of a 2x2 linear system)";
    s.assumptions = {"instantaneous impact along the line of centres; only the contact force acts",
                     "the particles approach: v1 > v2"};
    s.params = {positive("m1", "kg", 1, "mass 1"), positive("m2", "kg", 2, "mass 2"),
                {"v1", "m/s", 3, -kInf, kInf, true, false, "v2", {}, "velocity of 1 before impact"},
                real("v2", "m/s", -1, "velocity of 2 before impact"),
                restitution("e", 0.8, "coefficient of restitution")};
    s.run = run_impact;
    t.push_back(s);
  }
  {
    SceneSpec s;
    s.name = "oblique";
    s.title = "Oblique central impact as a linear system";
    s.handout = "§9.3.2";
    s.dofs = "v'1n, v'1t, v'2n, v'2t (4 unknowns of a 4x4 linear system)";
    s.assumptions = {"smooth spheres: the contact force acts along n only, so each particle keeps its t-momentum",
                     "the particles approach along n: v1n > v2n"};
    s.params = {positive("m1", "kg", 1, "mass 1"), positive("m2", "kg", 2, "mass 2"),
                {"v1n", "m/s", 3, -kInf, kInf, true, false, "v2n", {}, "normal velocity of 1"},
                real("v1t", "m/s", 1, "tangential velocity of 1"),
                real("v2n", "m/s", -1, "normal velocity of 2"),
                real("v2t", "m/s", 2, "tangential velocity of 2"),
                restitution("e", 0.8, "coefficient of restitution")};
    s.run = run_oblique;
    t.push_back(s);
  }
  return t;
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string with_unit(double v, const std::string& unit) {
  return unit == "1" ? fmt(v) : fmt(v) + " " + unit;
}

double parse_number(const std::string& scene, const std::string& name, const std::string& text) {
  auto parse = [&](std::string_view s) {
    double v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || s.empty())
      throw std::invalid_argument(scene + ": cannot read " + name + " = '" + text + "' as a number");
    return v;
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) return parse(text);
  return parse(std::string_view(text).substr(0, slash)) / parse(std::string_view(text).substr(slash + 1));
}

std::string bound_text(const SceneSpec& spec, const ParamSpec& ps, const Params& p) {
  auto lo = ps.lo_ref.empty() ? ps.lo : p.at(ps.lo_ref);
  auto hi = ps.hi_ref.empty() ? ps.hi : p.at(ps.hi_ref);
  auto lo_s = ps.lo_ref.empty() ? fmt(lo) : ps.lo_ref + " = " + fmt(lo);
  auto hi_s = ps.hi_ref.empty() ? fmt(hi) : ps.hi_ref + " = " + fmt(hi);
  std::string u = ps.unit == "1" ? "" : " " + ps.unit;
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return lo_s + (ps.lo_open ? " < " : " <= ") + ps.name + (ps.hi_open ? " < " : " <= ") + hi_s + u;
  if (has_lo) return ps.name + (ps.lo_open ? " > " : " >= ") + lo_s + u;
  if (has_hi) return ps.name + (ps.hi_open ? " < " : " <= ") + hi_s + u;
  return ps.name + " finite";
}

}  // namespace

double Comparison::rel_error() const {
  const double d = std::abs(simulated - closed_form);
  return closed_form == 0 ? d : d / std::abs(closed_form);
}

std::string Series::to_csv() const {
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + columns[i];
  out += "\n";
  char buf[40];
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%.17g", row[i]);
      if (i) out += ",";
      out += buf;
    }
    out += "\n";
  }
  return out;
}

const Comparison& SceneResult::get(const std::string& q) const {
  for (const auto& c : comparisons)
    if (c.quantity == q) return c;
  throw std::out_of_range("no comparison '" + q + "' in this scene's result");
}

double SceneResult::metric(const std::string& name) const {
  auto it = metrics.find(name);
  if (it == metrics.end()) throw std::out_of_range("no metric '" + name + "' in this scene's result");
  return it->second;
}

const std::vector<SceneSpec>& scene_specs() {
  static const std::vector<SceneSpec> table = make_table();
  return table;
}

const SceneSpec& find_scene(std::string_view name) {
  std::string names;
  for (const auto& s : scene_specs()) {
    if (s.name == name) return s;
    names += (names.empty() ? "" : ", ") + s.name;
  }
  throw std::invalid_argument("unknown scene '" + std::string(name) + "'; scenes: " + names);
}

Params defaults(const SceneSpec& spec) {
  Params p;
  for (const auto& ps : spec.params) p[ps.name] = ps.def;
  return p;
}

Params resolve(const SceneSpec& spec, const std::vector<std::string>& assignments) {
  Params p = defaults(spec);
  for (const auto& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument(spec.name + ": --set expects NAME=VALUE, got '" + a + "'");
    std::string name = a.substr(0, eq), value = a.substr(eq + 1);
    auto trim = [](std::string& s) {
      s.erase(0, s.find_first_not_of(" \t"));
      s.erase(s.find_last_not_of(" \t") + 1);
    };
    trim(name);
    trim(value);
    if (!p.count(name)) {
      std::string names;
      for (const auto& ps : spec.params) names += (names.empty() ? "" : ", ") + ps.name;
      throw std::invalid_argument(spec.name + ": unknown parameter '" + name + "'; parameters: " + names);
    }
    p[name] = parse_number(spec.name, name, value);
  }
  validate(spec, p);
  return p;
}

void out_of_bounds(const std::string& scene, const std::string& name, double value, const std::string& unit,
                   const std::string& need) {
  throw std::domain_error(scene + ": " + name + " = " + with_unit(value, unit) + " is out of bounds: need " + need);
}

void validate(const SceneSpec& spec, const Params& p) {
  for (const auto& ps : spec.params) {
    auto it = p.find(ps.name);
    if (it == p.end()) throw std::invalid_argument(spec.name + ": parameter '" + ps.name + "' is missing");
    const double v = it->second;
    if (!std::isfinite(v)) out_of_bounds(spec.name, ps.name, v, ps.unit, ps.name + " finite (not NaN or inf)");
  }
  for (const auto& ps : spec.params) {
    const double v = p.at(ps.name);
    const double lo = ps.lo_ref.empty() ? ps.lo : p.at(ps.lo_ref);
    const double hi = ps.hi_ref.empty() ? ps.hi : p.at(ps.hi_ref);
    const bool ok_lo = ps.lo_open ? v > lo : v >= lo;
    const bool ok_hi = ps.hi_open ? v < hi : v <= hi;
    if (!ok_lo || !ok_hi) out_of_bounds(spec.name, ps.name, v, ps.unit, bound_text(spec, ps, p));
    if (ps.integer && v != std::floor(v)) out_of_bounds(spec.name, ps.name, v, ps.unit, ps.name + " an integer");
  }
  if (spec.check) spec.check(p);
}

void check_run_options(const SceneSpec& spec, const RunOptions& opt) {
  if (!(opt.h > 0) || !std::isfinite(opt.h)) out_of_bounds(spec.name, "step h", opt.h, "s", "h > 0 (finite)");
  if (!(opt.tol > 0) || !std::isfinite(opt.tol)) out_of_bounds(spec.name, "tolerance tol", opt.tol, "1", "tol > 0 (finite)");
}

SceneResult run_scene(const SceneSpec& spec, const Params& p, RunOptions opt) {
  validate(spec, p);
  if (!spec.methods.empty()) {
    if (opt.h == 0) opt.h = spec.default_h;
    check_run_options(spec, opt);
    if (std::find(spec.methods.begin(), spec.methods.end(), opt.method) == spec.methods.end()) {
      std::string names;
      for (auto m : spec.methods) names += (names.empty() ? "" : ", ") + std::string(method_name(m));
      throw std::invalid_argument(spec.name + ": method '" + std::string(method_name(opt.method)) +
                                  "' does not fit this scene; methods: " + names);
    }
  }
  SceneResult r = spec.run(p, opt);
  r.method = opt.method;
  r.h = opt.h;
  return r;
}

std::string describe(const SceneSpec& spec) {
  std::ostringstream o;
  o << spec.name << ": " << spec.title << " (" << spec.handout << ")\n";
  o << "  degrees of freedom: " << spec.dofs << "\n";
  o << "  assumptions:\n";
  for (const auto& a : spec.assumptions) o << "    - " << a << "\n";
  o << "  parameters (--set NAME=VALUE):\n";
  const Params p = defaults(spec);
  for (const auto& ps : spec.params) {
    char line[160];
    std::snprintf(line, sizeof line, "    %-7s %-6s default %-10s", ps.name.c_str(), ("[" + ps.unit + "]").c_str(),
                  fmt(ps.def).c_str());
    o << line << " need " << bound_text(spec, ps, p) << "; " << ps.description << "\n";
  }
  if (spec.methods.empty()) {
    o << "  method: exact (event times of parabolas / linear algebra), no step\n";
  } else {
    o << "  methods (--method):";
    for (auto m : spec.methods) o << " " << method_name(m) << (m == spec.default_method ? " (default)" : "");
    o << "; default step h = " << fmt(spec.default_h) << " s\n";
  }
  return o.str();
}

std::string describe_markdown(const SceneSpec& spec) {
  std::ostringstream o;
  o << "### `" << spec.name << "` — " << spec.title << " (" << spec.handout << ")\n\n";
  o << "Degrees of freedom: " << spec.dofs << ".\n\nAssumptions:\n\n";
  for (const auto& a : spec.assumptions) o << "- " << a << "\n";
  o << "\n| parameter | unit | default | bound | meaning |\n|---|---|---|---|---|\n";
  const Params p = defaults(spec);
  for (const auto& ps : spec.params)
    o << "| `" << ps.name << "` | " << ps.unit << " | " << fmt(ps.def) << " | " << bound_text(spec, ps, p) << " | "
      << ps.description << " |\n";
  o << "\n";
  return o.str();
}

std::string figure_pgfplots(const SceneResult& r, const std::string& title, std::size_t max_points) {
  const auto& f = r.figure;
  if (f.y.empty() || r.series.rows.empty()) return {};
  auto col = [&](const std::string& name) -> std::size_t {
    auto it = std::find(r.series.columns.begin(), r.series.columns.end(), name);
    if (it == r.series.columns.end()) throw std::logic_error("figure: no column '" + name + "'");
    return static_cast<std::size_t>(it - r.series.columns.begin());
  };
  const std::size_t n = r.series.rows.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + max_points - 1) / max_points);
  std::ostringstream o;
  o << "% " << title << " -- generated by `derivcheck simulate`; needs \\usepackage{pgfplots}\n";
  o << "\\begin{tikzpicture}\n\\begin{axis}[width=0.9\\linewidth, height=0.5\\linewidth, xlabel={" << f.xlabel
    << "}, ylabel={" << f.ylabel << "}, legend pos=north west, grid=major, title={" << title << "}]\n";
  const std::size_t xc = col(f.x);
  char buf[64];
  for (const auto& [name, legend] : f.y) {
    const std::size_t yc = col(name);
    o << "\\addplot[thick, mark=none] coordinates {";
    for (std::size_t i = 0; i < n; i += stride) {
      std::snprintf(buf, sizeof buf, "(%.6g,%.6g)", r.series.rows[i][xc], r.series.rows[i][yc]);
      o << buf;
    }
    if ((n - 1) % stride != 0) {
      std::snprintf(buf, sizeof buf, "(%.6g,%.6g)", r.series.rows[n - 1][xc], r.series.rows[n - 1][yc]);
      o << buf;
    }
    o << "};\n\\addlegendentry{" << legend << "}\n";
  }
  o << "\\end{axis}\n\\end{tikzpicture}\n";
  return o.str();
}

std::string figure_gnuplot(const SceneResult& r, const std::string& title, const std::string& csv_path,
                           const std::string& png_path) {
  const auto& f = r.figure;
  if (f.y.empty()) return {};
  auto col = [&](const std::string& name) {
    auto it = std::find(r.series.columns.begin(), r.series.columns.end(), name);
    return static_cast<int>(it - r.series.columns.begin()) + 1;
  };
  auto plain = [](std::string s) {  // TeX legend -> plain text
    std::string out;
    for (char c : s)
      if (c != '$' && c != '\\' && c != '{' && c != '}') out += c;
    return out;
  };
  std::ostringstream o;
  o << "set terminal pngcairo size 900,500 font 'DejaVu Sans,11'\n";
  if (!png_path.empty()) o << "set output '" << png_path << "'\n";
  o << "set datafile separator ','\nset key top left\nset grid\n";
  o << "set title '" << title << "'\nset xlabel '" << plain(f.xlabel) << "'\nset ylabel '" << plain(f.ylabel) << "'\n";
  o << "plot ";
  for (std::size_t i = 0; i < f.y.size(); ++i)
    o << (i ? ", \\\n     " : "") << "'" << csv_path << "' using " << col(f.x) << ":" << col(f.y[i].first)
      << " with lines lw 2 title '" << plain(f.y[i].second) << "'";
  o << "\n";
  return o.str();
}

}  // namespace dc::scenes
