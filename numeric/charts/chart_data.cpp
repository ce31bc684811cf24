// Measurements behind the work-precision charts and stability maps (see chart_data.hpp).
#include "numeric/charts/chart_data.hpp"
#include "numeric/charts/internal/chart_support.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>

#include "derivations/reader/derivation.hpp"
#include "derivations/symbolic/functions.hpp"
#include "derivations/decide/prove.hpp"
#include "numeric/certified/certified.hpp"
#include "numeric/certified/certified_batch.hpp"
#include "numeric/crosscheck.hpp"
#include "numeric/evaluator.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/formula_evaluator.hpp"
#include "numeric/reference/reference.hpp"
#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/scenes.hpp"
#include "numeric/scenes/spec.hpp"

namespace dc::chart {

using GiNaC::ex;
using GiNaC::numeric;

Stat stat_of(std::vector<double> v) {
  if (v.empty()) throw std::invalid_argument("stat_of: no measurements");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  const double med = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  return {med, v.front(), v.back()};
}

Stat time_per_op(const std::function<void()>& f, long ops, int repeats) {
  if (ops <= 0 || repeats <= 0) throw std::invalid_argument("time_per_op: ops and repeats must be positive");
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const auto t1 = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double>(t1 - t0).count() / static_cast<double>(ops));
  }
  return stat_of(std::move(t));
}

std::string fmt(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

std::string Table::to_csv() const {
  auto cell = [](const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  std::ostringstream o;
  for (std::size_t i = 0; i < columns.size(); ++i) o << (i ? "," : "") << cell(columns[i]);
  o << "\n";
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size(); ++i) o << (i ? "," : "") << cell(r[i]);
    o << "\n";
  }
  return o.str();
}

void progress(const std::string& what) {
  if (isatty(STDERR_FILENO)) std::cerr << "\r\033[K" << what << std::flush;
}

namespace {


double rel_error_exact(const numeric& x, const numeric& ref) {
  const numeric r = num::to_exact(ref);
  const numeric d = abs(num::to_exact(x) - r);
  return num::round_to_double(r.is_zero() ? d : d / abs(r));
}

// Seeded random points in the declared domains of `params` that satisfy the file's
// constraints and give a finite double value.
std::vector<std::vector<double>> sample_points(const Derivation& d, const Formula& f, int n,
                                               std::uint64_t seed,
                                               const num::Evaluator<double>& probe) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<std::vector<double>> pts;
  for (int tries = 0; static_cast<int>(pts.size()) < n; ++tries) {
    if (tries > 200 * n + 1000)
      throw std::domain_error("chart: cannot draw valid points for " + f.label +
                              " (the declared domains and constraints admit too few doubles)");
    std::vector<double> x;
    for (const auto& s : f.params) {
      const SymbolInfo* si = d.symbols.find(s.get_name());
      const Domain dom = si ? si->domain : Domain::real();
      double v = 0;
      const double logu = std::exp(std::log(0.1) + u01(rng) * std::log(100.0));  // 0.1 .. 10
      switch (dom.kind) {
        case Domain::Kind::Positive:
        case Domain::Kind::Nonnegative: v = logu; break;
        case Domain::Kind::Negative: v = -logu; break;
        case Domain::Kind::Real: v = -10 + 20 * u01(rng); break;
        case Domain::Kind::Interval: {
          const double lo = GiNaC::ex_to<numeric>(dom.lo.evalf()).to_double();
          const double hi = GiNaC::ex_to<numeric>(dom.hi.evalf()).to_double();
          v = lo + (hi - lo) * u01(rng);
          break;
        }
      }
      x.push_back(v);
    }
    // the file's `assume` constraints among the bound symbols (others are skipped)
    GiNaC::exmap at;
    for (std::size_t j = 0; j < f.params.size(); ++j) {
      const SymbolInfo* si = d.symbols.find(f.params[j].get_name());
      if (si) at[si->sym] = num::exact_rational(x[j]);
    }
    bool ok = true;
    for (const Constraint& c : d.symbols.constraints()) {
      const ex diff = (c.lhs - c.rhs).subs(at).evalf();
      if (!GiNaC::is_a<numeric>(diff)) continue;
      const numeric v = GiNaC::ex_to<numeric>(diff);
      if (!v.is_real()) { ok = false; break; }
      switch (c.op) {
        case Constraint::Op::Lt: ok = v < 0; break;
        case Constraint::Op::Le: ok = v <= 0; break;
        case Constraint::Op::Gt: ok = v > 0; break;
        case Constraint::Op::Ge: ok = v >= 0; break;
        case Constraint::Op::Ne: ok = !v.is_zero(); break;
      }
      if (!ok) break;
    }
    if (!ok) continue;
    if (!std::isfinite(probe(x.data()))) continue;
    pts.push_back(std::move(x));
  }
  return pts;
}

GiNaC::exmap exact_point(const std::vector<GiNaC::symbol>& params, const std::vector<double>& x) {
  GiNaC::exmap m;
  for (std::size_t i = 0; i < params.size(); ++i) m[params[i]] = num::exact_rational(x[i]);
  return m;
}

// Columns of `pts` tiled to at least `n` rows (for batch timings).
std::vector<std::vector<double>> tiled_columns(const std::vector<std::vector<double>>& pts, std::size_t k,
                                               std::size_t n) {
  std::vector<std::vector<double>> cols(k, std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < k; ++j) cols[j][i] = pts[i % pts.size()][j];
  return cols;
}

struct Compiled {
  std::string method;
  num::Program prog;
  std::vector<std::size_t> arg_index;   // program input i <- formula param arg_index[i]
};

std::vector<std::size_t> map_params(const std::vector<GiNaC::symbol>& want, const std::vector<GiNaC::symbol>& have,
                                    const std::string& what) {
  std::vector<std::size_t> idx;
  for (const auto& w : want) {
    auto it = std::find_if(have.begin(), have.end(), [&](const GiNaC::symbol& h) { return h.get_name() == w.get_name(); });
    if (it == have.end()) throw std::invalid_argument(what + ": parameter " + w.get_name() + " is not a parameter of the naive form");
    idx.push_back(static_cast<std::size_t>(it - have.begin()));
  }
  return idx;
}



}  // namespace

namespace support {

double bits_from_ulps(double ulps) {
  if (!std::isfinite(ulps)) return 53;
  return std::min(53.0, std::log2(1 + ulps));
}

// |x - ref| / |ref| exactly (absolute when ref = 0); inf for non-finite x.
double rel_error(long double x, const numeric& ref) {
  if (!std::isfinite(x)) return HUGE_VAL;
  const numeric r = num::to_exact(ref);
  const numeric d = abs(num::exact_rational(x) - r);
  return num::round_to_double(r.is_zero() ? d : d / abs(r));
}

num::CompileOptions naive_options() {
  num::CompileOptions o;
  o.fuse_log1p = o.fuse_expm1 = o.fuse_hypot = o.ratio_first = false;
  return o;
}

// Table symbols named `names` -> fresh plain symbols (see PlainFormula).
std::pair<GiNaC::exmap, std::vector<GiNaC::symbol>> plain_symbols(const Derivation& d,
                                                                  const std::vector<std::string>& names) {
  GiNaC::exmap m;
  std::vector<GiNaC::symbol> out;
  for (const auto& n : names) {
    const SymbolInfo* s = d.symbols.find(n);
    if (!s) throw std::invalid_argument("chart: no symbol " + n);
    GiNaC::symbol p(n);
    m[s->sym] = p;
    out.push_back(p);
  }
  return {m, out};
}

}  // namespace support

using namespace support;

PlainFormula plain_formula(const Derivation& d, const GiNaC::ex& expr) {
  std::vector<std::string> names;
  for (const auto& s : d.symbols.all())
    if (!s.is_function && expr.has(s.sym)) names.push_back(s.name);
  auto [m, syms] = plain_symbols(d, names);
  return {expr.subs(m), syms, names};
}

std::function<double(const double*)> hand_written(const std::string& label, const std::vector<std::string>& params) {
  auto at = [&](const char* name) -> std::size_t {
    auto it = std::find(params.begin(), params.end(), name);
    if (it == params.end()) throw std::invalid_argument(std::string("hand_written(") + label + "): no parameter " + name);
    return static_cast<std::size_t>(it - params.begin());
  };
  if (label == "v1p_general") {  // §9.3.1 general impact
    const auto m1 = at("m1"), m2 = at("m2"), v1 = at("v1"), v2 = at("v2"), e = at("e");
    return [=](const double* x) { return (x[m1] * x[v1] + x[m2] * x[v2] - x[e] * x[m2] * (x[v1] - x[v2])) / (x[m1] + x[m2]); };
  }
  if (label == "v2p_general") {
    const auto m1 = at("m1"), m2 = at("m2"), v1 = at("v1"), v2 = at("v2"), e = at("e");
    return [=](const double* x) { return (x[m1] * x[v1] + x[m2] * x[v2] - x[e] * x[m1] * (x[v2] - x[v1])) / (x[m1] + x[m2]); };
  }
  if (label == "energy_loss_general") {  // ΔT = (1-e²)/2 m1 m2/(m1+m2) (v1-v2)²
    const auto m1 = at("m1"), m2 = at("m2"), v1 = at("v1"), v2 = at("v2"), e = at("e");
    return [=](const double* x) {
      const double dv = x[v1] - x[v2];
      return 0.5 * (1 - x[e] * x[e]) * x[m1] * x[m2] / (x[m1] + x[m2]) * dv * dv;
    };
  }
  if (label == "deflection") {  // Example 9.5
    const auto m = at("m"), M = at("M"), v0 = at("v0"), L = at("L"), g = at("g");
    return [=](const double* x) {
      const double r = x[m] / (x[M] + x[m]);
      return std::acos(1 - r * r * x[v0] * x[v0] / (2 * x[L] * x[g]));
    };
  }
  if (label == "v1p_bounce") {  // Example 9.6
    const auto mu = at("mu"), e2 = at("e2"), e12 = at("e12"), v0 = at("v0");
    return [=](const double* x) { return (x[mu] - x[e2] - x[e12] * (1 + x[e2])) / (x[mu] + 1) * x[v0]; };
  }
  if (label == "wall_impulse") {  // Example 9.2
    const auto m = at("m"), l = at("l"), g = at("g"), th = at("theta0");
    return [=](const double* x) {
      const double s = std::sin(x[th]);
      return x[m] * s * std::sqrt(x[g] * x[l] * s) / 3;
    };
  }
  return {};
}

bool hand_written_batch(const std::string& label, const std::vector<std::string>& params,
                        const double* const* c, double* out, std::size_t n) {
  auto at = [&](const char* name) -> const double* {
    auto it = std::find(params.begin(), params.end(), name);
    if (it == params.end()) throw std::invalid_argument(std::string("hand_written(") + label + "): no parameter " + name);
    return c[it - params.begin()];
  };
  if (label == "v1p_general") {
    const double *m1 = at("m1"), *m2 = at("m2"), *v1 = at("v1"), *v2 = at("v2"), *e = at("e");
    for (std::size_t i = 0; i < n; ++i)
      out[i] = (m1[i] * v1[i] + m2[i] * v2[i] - e[i] * m2[i] * (v1[i] - v2[i])) / (m1[i] + m2[i]);
    return true;
  }
  if (label == "v2p_general") {
    const double *m1 = at("m1"), *m2 = at("m2"), *v1 = at("v1"), *v2 = at("v2"), *e = at("e");
    for (std::size_t i = 0; i < n; ++i)
      out[i] = (m1[i] * v1[i] + m2[i] * v2[i] - e[i] * m1[i] * (v2[i] - v1[i])) / (m1[i] + m2[i]);
    return true;
  }
  if (label == "energy_loss_general") {
    const double *m1 = at("m1"), *m2 = at("m2"), *v1 = at("v1"), *v2 = at("v2"), *e = at("e");
    for (std::size_t i = 0; i < n; ++i) {
      const double dv = v1[i] - v2[i];
      out[i] = 0.5 * (1 - e[i] * e[i]) * m1[i] * m2[i] / (m1[i] + m2[i]) * dv * dv;
    }
    return true;
  }
  if (label == "deflection") {
    const double *m = at("m"), *M = at("M"), *v0 = at("v0"), *L = at("L"), *g = at("g");
    for (std::size_t i = 0; i < n; ++i) {
      const double r = m[i] / (M[i] + m[i]);
      out[i] = std::acos(1 - r * r * v0[i] * v0[i] / (2 * L[i] * g[i]));
    }
    return true;
  }
  if (label == "v1p_bounce") {
    const double *mu = at("mu"), *e2 = at("e2"), *e12 = at("e12"), *v0 = at("v0");
    for (std::size_t i = 0; i < n; ++i) out[i] = (mu[i] - e2[i] - e12[i] * (1 + e2[i])) / (mu[i] + 1) * v0[i];
    return true;
  }
  if (label == "wall_impulse") {
    const double *m = at("m"), *l = at("l"), *g = at("g"), *th = at("theta0");
    for (std::size_t i = 0; i < n; ++i) {
      const double s = std::sin(th[i]);
      out[i] = m[i] * s * std::sqrt(g[i] * l[i] * s) / 3;
    }
    return true;
  }
  return false;
}

std::vector<WpRow> closed_form_wp(const std::string& path, const std::string& label, const ClosedOptions& opt) {
  if (opt.points <= 0 || opt.repeats <= 0) throw std::invalid_argument("chart closed: points and repeats must be positive");
  const Derivation d = load_derivation(path);
  const Formula f = formula(d, label);
  std::string base = path.substr(path.find_last_of('/') + 1);
  const std::string fname = base + ":" + label;
  const std::size_t k = f.params.size();

  const PlainFormula pf = plain_formula(d, f.expr);
  std::vector<Compiled> methods;
  methods.push_back({"double (evaluator)", num::compile(pf.expr, pf.inputs), {}});
  methods.push_back({"double (naive: no rewrites)", num::compile(pf.expr, pf.inputs, naive_options()), {}});
  for (const Step& s : d.steps) {
    if (!s.stable_of || *s.stable_of != label) continue;
    const PlainFormula sf = plain_formula(d, formula(d, s.label).expr);
    Compiled c{"double (stable form " + s.label + ")", num::compile(sf.expr, sf.inputs), map_params(sf.inputs, pf.inputs, s.label)};
    methods.push_back(std::move(c));
  }
  const num::Evaluator<double> probe(methods[0].prog);
  const auto pts = sample_points(d, f, opt.points, opt.seed, probe);

  // the reference (>= 100 digits) at every point
  std::vector<numeric> ref;
  for (const auto& x : pts) ref.push_back(num::reference_value(pf.expr, exact_point(pf.inputs, x), opt.ref_digits));

  std::vector<WpRow> rows;
  const std::size_t n_batch = 1 << 16;
  const auto cols = tiled_columns(pts, k, n_batch);
  std::vector<double> out(n_batch);

  auto add_double_method = [&](const std::string& method, const std::function<double(const double*)>& one,
                               const std::function<void()>& batch, long ops) {
    WpRow r{fname, method, time_per_op(batch, ops, opt.repeats), 0, 0, 0, static_cast<int>(pts.size())};
    std::vector<double> errs;
    double max_ulps = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double y = one(pts[i].data());
      errs.push_back(rel_error(y, ref[i]));
      max_ulps = std::max(max_ulps, num::error_in_ulps(y, ref[i]));
    }
    const Stat s = stat_of(errs);
    r.rel_err_median = s.median, r.rel_err_max = s.max, r.bits_lost_max = bits_from_ulps(max_ulps);
    rows.push_back(r);
  };

  for (const Compiled& c : methods) {
    progress("chart closed " + fname + ": " + c.method);
    const num::Evaluator<double> ev(c.prog);
    std::vector<const double*> cp;
    const std::vector<std::size_t> idx = c.arg_index;
    for (std::size_t i = 0; i < c.prog.n_inputs(); ++i) cp.push_back(cols[idx.empty() ? i : idx[i]].data());
    auto one = [ev, idx](const double* x) {
      if (idx.empty()) return ev(x);
      std::vector<double> a;
      for (std::size_t j : idx) a.push_back(x[j]);
      return ev(a.data());
    };
    ev.eval_batch(cp.data(), out.data(), 1);  // the JIT compiles here, outside the timing
    add_double_method(c.method, one, [&] { ev.eval_batch(cp.data(), out.data(), n_batch); }, static_cast<long>(n_batch));
  }
  // long double through the evaluator
  {
    progress("chart closed " + fname + ": long double");
    const num::Evaluator<long double> ev(methods[0].prog);
    std::vector<std::vector<long double>> lcols(k, std::vector<long double>(n_batch));
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t i = 0; i < n_batch; ++i) lcols[j][i] = cols[j][i];
    std::vector<const long double*> cp;
    for (auto& c : lcols) cp.push_back(c.data());
    std::vector<long double> lout(n_batch);
    WpRow r{fname, "long double (evaluator)",
            time_per_op([&] { ev.eval_batch(cp.data(), lout.data(), n_batch); }, static_cast<long>(n_batch), opt.repeats),
            0, 0, 0, static_cast<int>(pts.size())};
    std::vector<double> errs;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      std::vector<long double> a(pts[i].begin(), pts[i].end());
      errs.push_back(rel_error(ev(a.data()), ref[i]));
    }
    const Stat s = stat_of(errs);
    r.rel_err_median = s.median, r.rel_err_max = s.max;
    r.bits_lost_max = std::min(64.0, std::log2(1 + s.max / std::ldexp(1.0, -64)));
    rows.push_back(r);
  }
  // hand-written C++ (speed limit)
  if (auto hw = hand_written(label, pf.names)) {
    progress("chart closed " + fname + ": hand-written");
    std::vector<const double*> cp;
    for (const auto& c : cols) cp.push_back(c.data());
    add_double_method("hand-written C++", hw, [&] {
      hand_written_batch(label, pf.names, cp.data(), out.data(), n_batch);
    }, static_cast<long>(n_batch));
  }
  // CLN at d digits: inputs rounded to d digits, arithmetic in CLN floats of that precision
  for (int digits : opt.cln_digits) {
    progress("chart closed " + fname + ": CLN " + std::to_string(digits));
    std::vector<numeric> vals(pts.size());
    auto run = [&] {
      DigitsGuard g(digits);
      for (std::size_t i = 0; i < pts.size(); ++i) {
        GiNaC::exmap m;
        for (std::size_t j = 0; j < k; ++j) m[pf.inputs[j]] = num::exact_rational(pts[i][j]).evalf();
        vals[i] = GiNaC::ex_to<numeric>(pf.expr.subs(m).evalf());
      }
    };
    WpRow r{fname, "CLN " + std::to_string(digits) + " digits", time_per_op(run, static_cast<long>(pts.size()), opt.repeats),
            0, 0, 0, static_cast<int>(pts.size())};
    std::vector<double> errs;
    for (std::size_t i = 0; i < pts.size(); ++i) errs.push_back(rel_error_exact(vals[i], ref[i]));
    const Stat s = stat_of(errs);
    r.rel_err_median = s.median, r.rel_err_max = s.max;
    r.bits_lost_max = std::log2(1 + s.max / std::pow(10.0, -digits));
    rows.push_back(r);
  }
  progress("");
  return rows;
}

Table to_table(const std::vector<WpRow>& rows) {
  Table t{{"formula", "method", "seconds_median", "seconds_min", "seconds_max", "rel_error_median", "rel_error_max",
           "bits_lost_max", "ulps_max", "rel_error_max_random", "points"}, {}};
  for (const auto& r : rows)
    t.rows.push_back({r.formula, r.method, fmt(r.seconds.median), fmt(r.seconds.min), fmt(r.seconds.max),
                      fmt(r.rel_err_median), fmt(r.rel_err_max), fmt(r.bits_lost_max),
                      r.ulps_max < 0 ? std::string() : fmt(r.ulps_max),
                      r.rel_err_max_random < 0 ? std::string() : fmt(r.rel_err_max_random), std::to_string(r.points)});
  return t;
}

std::string method_family(const std::string& method) {
  if (method.rfind("stable form", 0) == 0) return "stable form";
  return method;
}

ClosedAllResult closed_forms_wp_all(const std::vector<std::string>& paths, const ClosedAllOptions& opt) {
  if (opt.points <= 0 || opt.repeats <= 0 || opt.batch == 0)
    throw std::invalid_argument("chart closed: points, repeats and batch must be positive");
  ClosedAllResult res;
  for (const auto& path : paths) {
    const Derivation d = load_derivation(path);
    const std::string base = path.substr(path.find_last_of('/') + 1);
    for (const Formula& f : formulas(d)) {
      const std::string fname = base + ":" + f.label;
      std::optional<num::Program> prog;
      try {
        prog = num::compile(f.expr, f.params);
      } catch (const std::invalid_argument& e) {
        res.skipped.push_back(fname + ": " + e.what());
        continue;
      }
      progress("chart closed " + fname);
      num::CrossCheckOptions co;
      co.seed = opt.seed, co.points = opt.points, co.stress = opt.stress, co.digits = opt.ref_digits;
      const auto pts = num::crosscheck_points(d, f, co);
      if (pts.empty()) {
        res.skipped.push_back(fname + ": no valid point in the declared domain");
        continue;
      }
      const std::size_t k = f.params.size(), np = pts.size();
      const std::size_t n = std::max(opt.batch, np);
      std::vector<std::vector<double>> cols(k, std::vector<double>(n));
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < k; ++j) cols[j][i] = pts[i % np].x[j];
      std::vector<const double*> cp;
      for (const auto& c : cols) cp.push_back(c.data());
      std::vector<double> out(n);
      const int npts = static_cast<int>(np);
      auto max_random = [&](const std::vector<double>& errs) {
        double m = 0;
        for (std::size_t i = 0; i < np; ++i)
          if (pts[i].kind == "random") m = std::max(m, errs[i]);
        return m;
      };

      auto add_double = [&](const std::string& method, const std::function<double(const std::vector<double>&)>& one,
                            const std::function<void()>& batch) {
        WpRow r{fname, method, time_per_op(batch, static_cast<long>(n), opt.repeats), 0, 0, 0, npts, 0};
        std::vector<double> errs;
        double max_ulps = 0;
        for (const auto& p : pts) {
          const double y = one(p.x);
          errs.push_back(rel_error(y, p.ref));
          const double u = num::error_in_ulps(y, p.ref);
          max_ulps = std::max(max_ulps, std::isnan(u) ? HUGE_VAL : u);
        }
        const Stat s = stat_of(errs);
        r.rel_err_median = s.median, r.rel_err_max = s.max, r.bits_lost_max = bits_from_ulps(max_ulps);
        r.ulps_max = max_ulps;
        r.rel_err_max_random = max_random(errs);
        res.rows.push_back(r);
      };

      // CLN at d digits: inputs rounded to d digits, arithmetic in CLN floats of that precision
      const PlainFormula pf = plain_formula(d, f.expr);
      const std::vector<std::size_t> idx = map_params(pf.inputs, f.params, fname);
      for (int digits : opt.cln_digits) {
        std::vector<numeric> vals(np);
        std::vector<char> ok(np, 0);
        auto run = [&] {
          DigitsGuard g(digits);
          for (std::size_t i = 0; i < np; ++i) {
            GiNaC::exmap m;
            for (std::size_t j = 0; j < pf.inputs.size(); ++j)
              m[pf.inputs[j]] = num::exact_rational(pts[i].x[idx[j]]).evalf();
            ok[i] = false;
            try {
              const ex v = pf.expr.subs(m).evalf();
              if (GiNaC::is_a<numeric>(v) && GiNaC::ex_to<numeric>(v).is_real()) {
                vals[i] = GiNaC::ex_to<numeric>(v);
                ok[i] = true;
              }
            } catch (const std::exception&) {
              // e.g. log(0) after rounding the inputs to `digits`: counted as a failure
            }
          }
        };
        WpRow r{fname, "CLN " + std::to_string(digits) + " digits",
                time_per_op(run, static_cast<long>(np), opt.repeats), 0, 0, 0, npts, -1};
        std::vector<double> errs;
        for (std::size_t i = 0; i < np; ++i) errs.push_back(ok[i] ? rel_error_exact(vals[i], pts[i].ref) : HUGE_VAL);
        const Stat s = stat_of(errs);
        r.rel_err_median = s.median, r.rel_err_max = s.max;
        r.bits_lost_max = std::log2(1 + s.max / std::pow(10.0, -digits));
        r.rel_err_max_random = max_random(errs);
        res.rows.push_back(r);
      }
      // the evaluator in double and long double
      const num::Evaluator<double> ev(*prog);
      ev.eval_batch(cp.data(), out.data(), 1);  // the JIT compiles here, outside the timing
      add_double("double (evaluator)", [&](const std::vector<double>& x) { return ev(x); },
                 [&] { ev.eval_batch(cp.data(), out.data(), n); });
      {
        const num::Evaluator<long double> evl(*prog);
        std::vector<std::vector<long double>> lcols(k, std::vector<long double>(n));
        for (std::size_t j = 0; j < k; ++j)
          for (std::size_t i = 0; i < n; ++i) lcols[j][i] = cols[j][i];
        std::vector<const long double*> lcp;
        for (auto& c : lcols) lcp.push_back(c.data());
        std::vector<long double> lout(n);
        WpRow r{fname, "long double (evaluator)",
                time_per_op([&] { evl.eval_batch(lcp.data(), lout.data(), n); }, static_cast<long>(n), opt.repeats),
                0, 0, 0, npts, 0};
        std::vector<double> errs;
        double max_ulps = 0;
        for (const auto& p : pts) {
          const std::vector<long double> a(p.x.begin(), p.x.end());
          const long double y = evl(a);
          errs.push_back(rel_error(y, p.ref));
          const double u = num::error_in_ulps(y, p.ref);
          max_ulps = std::max(max_ulps, std::isnan(u) ? HUGE_VAL : u);
        }
        const Stat s = stat_of(errs);
        r.rel_err_median = s.median, r.rel_err_max = s.max;
        r.bits_lost_max = std::min(64.0, std::log2(1 + s.max / std::ldexp(1.0, -64)));
        r.ulps_max = max_ulps;
        r.rel_err_max_random = max_random(errs);
        res.rows.push_back(r);
      }
      // FormulaEvaluator: compensated (double-double) and the file's stable form in double
      Eigen::ArrayXXd in(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(k));
      for (std::size_t j = 0; j < k; ++j)
        for (std::size_t i = 0; i < n; ++i) in(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = cols[j][i];
      Eigen::ArrayXd eout(static_cast<Eigen::Index>(n));
      try {
        const num::FormulaEvaluator fc(d, f.label, num::EvalMode::Compensated);
        add_double("compensated (double-double)", [&](const std::vector<double>& x) { return fc(x); },
                   [&] { fc.eval_batch(in, eout); });
        const num::FormulaEvaluator fs(d, f.label, num::EvalMode::Fast);
        if (fs.has_stable())
          add_double("stable form " + fs.stable_label(), [&](const std::vector<double>& x) { return fs(x); },
                     [&] { fs.eval_batch(in, eout); });
      } catch (const std::exception& e) {
        res.skipped.push_back(fname + ": compensated/stable not evaluated: " + e.what());
      }
      // the certified automatic mode (`eval --method auto`): the double-double and long double
      // stages over the batch (timed with the repeats), then Arb for each point they leave
      // (timed once per point and added for every copy of it in the batch)
      {
        const num::CertifiedBatch cb(*prog);
        std::vector<double> cval(n);
        std::vector<num::CertifiedStage> cstage(n);
        Stat t = time_per_op([&] { cb.eval({cp.data()}, n, cval.data(), cstage.data()); },
                             static_cast<long>(n), opt.repeats);
        double arb_seconds = 0;
        std::vector<double> errs;
        double max_ulps = 0;
        for (std::size_t i = 0; i < np; ++i) {
          double y = cval[i];
          if (cstage[i] == num::CertifiedStage::None) {
            std::vector<std::pair<std::string, numeric>> at;
            for (std::size_t j = 0; j < k; ++j) at.emplace_back(f.params[j].get_name(), num::exact_rational(pts[i].x[j]));
            const auto t0 = std::chrono::steady_clock::now();
            try {
              y = num::certified_eval(d, f.label, at, num::DoubleMethod::Auto).value;
            } catch (const std::exception&) {
              y = std::numeric_limits<double>::quiet_NaN();   // no value: counted as a failure
            }
            const double copies = static_cast<double>(n / np + (i < n % np ? 1 : 0));
            arb_seconds += copies * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          }
          errs.push_back(rel_error(y, pts[i].ref));
          const double u = num::error_in_ulps(y, pts[i].ref);
          max_ulps = std::max(max_ulps, std::isnan(u) ? HUGE_VAL : u);
        }
        const double extra = arb_seconds / static_cast<double>(n);
        t.median += extra, t.min += extra, t.max += extra;
        WpRow r{fname, "certified auto", t, 0, 0, 0, npts, 0};
        const Stat es = stat_of(errs);
        r.rel_err_median = es.median, r.rel_err_max = es.max, r.bits_lost_max = bits_from_ulps(max_ulps);
        r.ulps_max = max_ulps;
        r.rel_err_max_random = max_random(errs);
        res.rows.push_back(r);
      }
      // hand-written C++ (the speed limit) where one is known
      std::vector<std::string> names;
      for (const auto& s : f.params) names.push_back(s.get_name());
      std::function<double(const double*)> hw;
      try {
        hw = hand_written(f.label, names);
      } catch (const std::invalid_argument&) {
        // same label, other parameters (another file's formula): no hand-written version
      }
      if (hw)
        add_double("hand-written C++", [&](const std::vector<double>& x) { return hw(x.data()); },
                   [&] { hand_written_batch(f.label, names, cp.data(), out.data(), n); });
    }
  }
  progress("");
  return res;
}

}  // namespace dc::chart
