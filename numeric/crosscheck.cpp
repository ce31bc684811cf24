#include "numeric/crosscheck.hpp"

#include "derivations/kernel/ball.hpp"
#include "derivations/kernel/sample.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <stdexcept>

#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/functions.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"

namespace dc::num {
namespace {

using GiNaC::ex;

const Step* stable_step_for(const Derivation& d, const std::string& label) {
  for (const Step& s : d.steps)
    if (s.stable_of && *s.stable_of == label) return &s;
  return nullptr;
}

double bound_to_double(const ex& b) {
  DigitsGuard guard(40);
  const ex v = GiNaC::evalf(b);
  if (!GiNaC::is_a<GiNaC::numeric>(v)) throw std::invalid_argument("domain bound is not a number");
  return round_to_double(GiNaC::ex_to<GiNaC::numeric>(v));
}

std::string fmt(double x, const char* f = "%.3g") {
  if (std::isinf(x)) return "inf";
  if (std::isnan(x)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

void free_symbol_names(const ex& e, std::set<std::string>& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    out.insert(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) free_symbol_names(e.op(i), out);
}

// The stress magnitudes of a quantity with a physical unit (docs/numeric.md, "Stress points").
constexpr double kPhysicalTiny = 1e-60, kPhysicalHuge = 1e60;

// The user's name of the first declared function in e (v for v(t) or a derivative of it);
// "" when there is none.
std::string declared_function_in(const ex& e, const SymbolTable& t) {
  if (const SymbolInfo* s = declared_function_of(e, t)) return s->name;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (std::string n = declared_function_in(e.op(i), t); !n.empty()) return n;
  return {};
}

struct Candidate {
  std::vector<double> x;
  std::string kind;  // "random" or a stress description
};

class Checker {
 public:
  Checker(const Derivation& d, const Formula& f, const CrossCheckOptions& opt, std::uint64_t seed)
      : d_(d), f_(f), opt_(opt), rng_(seed) {
    for (const auto& s : f.params) {
      const SymbolInfo* info = d.symbols.find(s.get_name());
      if (!info) throw std::invalid_argument("parameter '" + s.get_name() + "' is not declared");
      infos_.push_back(info);
    }
  }

  // A random value in the symbol's declared domain (typical magnitudes).
  double draw(const SymbolInfo& info) {
    std::uniform_real_distribution<double> u(-opt_.typical_decades, opt_.typical_decades);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double mag = std::pow(10.0, u(rng_));
    switch (info.domain.kind) {
      case Domain::Kind::Positive:
      case Domain::Kind::Nonnegative: return mag;
      case Domain::Kind::Negative: return -mag;
      case Domain::Kind::Real: return unit(rng_) < 0.5 ? -mag : mag;
      case Domain::Kind::Interval: {
        const double lo = bound_to_double(info.domain.lo), hi = bound_to_double(info.domain.hi);
        for (int k = 0; k < 100; ++k) {
          const double x = lo + (hi - lo) * unit(rng_);
          if (x > lo && x < hi) return x;
        }
        return 0.5 * (lo + hi);
      }
    }
    return mag;
  }

  // Exact point, or nullopt if a value is outside its domain or a constraint fails.
  std::optional<GiNaC::exmap> exact_point(const std::vector<double>& x) {
    GiNaC::exmap p;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!std::isfinite(x[i])) return std::nullopt;
      const GiNaC::numeric v = exact_rational(x[i]);
      if (!infos_[i]->domain.contains(v)) return std::nullopt;
      p[infos_[i]->sym] = v;  // the table's symbol: f.params holds sliced copies
    }
    for (const Constraint& c : d_.symbols.constraints()) {
      std::set<std::string> rest;
      free_symbol_names(c.lhs.subs(p), rest);
      free_symbol_names(c.rhs.subs(p), rest);
      if (!rest.empty()) continue;
      if (!kernel::holds_at(c, p)) return std::nullopt;
    }
    return p;
  }

  // The reference value, or nullopt if undefined / not representable in double (then
  // *not_double is set).
  std::optional<GiNaC::numeric> reference(const GiNaC::exmap& p, bool* not_double = nullptr) {
    // CLN's evalf wraps its exponent silently on a huge value (exp(6e159) came back as a
    // finite "reference"): Arb encloses the magnitude first, and a value outside double's range
    // is left out before CLN sees it.
    for (long bits : {64L, 256L}) {
      kernel::Ball b = kernel::enclose_at(f_.expr, &p, bits);
      GiNaC::numeric lo, hi;
      const bool beyond = b.status == kernel::BallStatus::Value &&
                          ((!b.contains_zero() && std::isinf(b.to_double())) || !b.exact_bounds(lo, hi));
      // Unknown twice: typically an exponent beyond the range Arb is allowed (exp(6e159))
      if (beyond || (b.status == kernel::BallStatus::Unknown && bits == 256)) {
        if (not_double) *not_double = true;
        return std::nullopt;
      }
      if (b.status != kernel::BallStatus::Unknown) break;
    }
    try {
      GiNaC::numeric r = reference_value(f_.expr, p, opt_.digits);
      const double approx = round_to_double(r);
      if (!std::isfinite(approx)) {  // beyond DBL_MAX
        if (not_double) *not_double = true;
        return std::nullopt;
      }
      return r;
    } catch (const std::domain_error&) {
      return std::nullopt;
    }
  }

  std::vector<Candidate> stress_candidates(const std::vector<double>& base) {
    std::vector<Candidate> out;
    const std::size_t n = base.size();
    auto with = [&](std::size_t i, double v, std::string what) {
      Candidate c{base, std::move(what)};
      c.x[i] = v;
      out.push_back(std::move(c));
    };
    for (std::size_t i = 0; i < n; ++i) {
      const SymbolInfo& s = *infos_[i];
      const std::string& nm = s.name;
      if (s.domain.kind == Domain::Kind::Interval) {
        const double lo = bound_to_double(s.domain.lo), hi = bound_to_double(s.domain.hi);
        const double w = hi - lo;
        with(i, lo + w * 1e-9, nm + " -> " + fmt(lo) + " (+1e-9)");
        with(i, hi - w * 1e-9, nm + " -> " + fmt(hi) + " (-1e-9)");
        with(i, lo, nm + " = " + fmt(lo));
        with(i, hi, nm + " = " + fmt(hi));
        continue;
      }
      if (s.domain.kind == Domain::Kind::Nonnegative) with(i, 0.0, nm + " = 0");
      const double sign = base[i] < 0 ? -1.0 : 1.0;
      for (double f : {1e-8, 1e8}) with(i, base[i] * f, nm + " * " + fmt(f, "%g"));
      // A quantity with a unit is driven to magnitudes beyond every physical value in SI units
      // (Planck time 5e-44 s, mass of the observable universe 1e53 kg) but no further: a length
      // of 1e160 m says nothing about a formula's accuracy. A pure number may take any double.
      const bool physical = s.has_dimension && !s.dimension.dimensionless();
      const std::vector<double> extremes =
          physical ? std::vector<double>{kPhysicalTiny, kPhysicalHuge} : std::vector<double>{1e-160, 1e160, 1e-300, 1e300};
      for (double a : extremes) with(i, sign * a, nm + " = " + fmt(sign * a, "%g"));
    }
    // like symbols (same declared dimension, not intervals) approaching each other
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        if (i == j) continue;
        const SymbolInfo &a = *infos_[i], &b = *infos_[j];
        if (!a.has_dimension || !b.has_dimension || !(a.dimension == b.dimension)) continue;
        if (a.domain.kind == Domain::Kind::Interval || b.domain.kind == Domain::Kind::Interval) continue;
        for (double r : {1e-9, -1e-9, 1e-13})
          with(j, base[i] * (1 - r), b.name + " -> " + a.name + " (rel " + fmt(r, "%g") + ")");
      }
    return out;
  }

  const std::vector<const SymbolInfo*>& infos() const { return infos_; }
  std::mt19937_64& rng() { return rng_; }

 private:
  const Derivation& d_;
  const Formula& f_;
  const CrossCheckOptions& opt_;
  std::mt19937_64 rng_;
  std::vector<const SymbolInfo*> infos_;
};

struct Acc {
  std::vector<double> errs;
  double max_random = 0, max_stress = 0, max = -1;
  std::size_t n_stress = 0, non_finite = 0;
  std::vector<double> worst_x;
  std::string worst_kind;
  void add(double err, bool finite_result, const Candidate& c) {
    errs.push_back(err);
    const bool stress = c.kind != "random";
    if (stress) {
      ++n_stress;
      max_stress = std::max(max_stress, err);
    } else {
      max_random = std::max(max_random, err);
    }
    if (!finite_result) ++non_finite;
    if (err > max) {
      max = err;
      worst_x = c.x;
      worst_kind = c.kind;
    }
  }
};

std::uint64_t mix(std::uint64_t seed, const std::string& s) {
  std::uint64_t h = seed ^ 0x9E3779B97F4A7C15ULL;  // FNV-1a over the label, seeded
  for (unsigned char ch : s) h = (h ^ ch) * 0x100000001B3ULL;
  return h;
}

}  // namespace

namespace {

// The seeded random points (opt.points accepted, from the declared domains) and then the stress
// points around the first accepted one, each offered to `use`, which returns false to reject
// it. Returns how many were rejected. One sampler for crosscheck() and crosscheck_points(), so
// both see the same points.
template <class Use>
int sample_points(Checker& ck, const CrossCheckOptions& opt, Use&& use) {
  std::optional<std::vector<double>> base;
  int accepted = 0, tries = 0, rejected = 0;
  while (accepted < opt.points && tries < 50 * opt.points + 100) {
    ++tries;
    Candidate c{{}, "random"};
    for (const SymbolInfo* s : ck.infos()) c.x.push_back(ck.draw(*s));
    if (use(c)) {
      ++accepted;
      if (!base) base = c.x;
    } else {
      ++rejected;
    }
  }
  if (opt.stress && base)
    for (const Candidate& c : ck.stress_candidates(*base))
      if (!use(c)) ++rejected;
  return rejected;
}

}  // namespace

std::vector<FormulaReport> crosscheck(const Derivation& d, const CrossCheckOptions& opt) {
  std::vector<FormulaReport> reports;
  int index = -1;
  for (const Formula& f : formulas(d)) {
    if (++index, opt.only_formula >= 0 && index != opt.only_formula) continue;
    FormulaReport rep;
    rep.file = d.source.name;
    rep.label = f.label;
    rep.target = f.target;
    if (f.step && f.step->stable_of) rep.stable_of = *f.step->stable_of;
    std::optional<Program> naive;
    // a function of t (x(t), or its derivative) has no value at a sampled point: say which
    if (std::string fn = declared_function_in(f.expr, d.symbols); !fn.empty()) {
      const SymbolInfo* info = d.symbols.find(fn);
      std::string params;
      for (std::size_t i = 0; info && i < info->params.size(); ++i) params += (i ? ", " : "") + info->params[i];
      rep.skipped = "it uses the function " + fn + "(" + params + "), which has no value at a sampled point "
                    "(crosscheck samples the declared symbols only)";
      reports.push_back(std::move(rep));
      continue;
    }
    try {
      naive = compile(f.expr, f.params);
    } catch (const std::invalid_argument& e) {
      rep.skipped = e.what();
      reports.push_back(std::move(rep));
      continue;
    }
    std::string stable_problem;
    std::optional<FormulaEvaluator> fe;
    if (const Step* s = stable_step_for(d, f.label)) {
      rep.stable_label = s->label;
      rep.stable_regime = s->stable_regime;
      try {
        fe.emplace(d, f.label, EvalMode::Fast);
        if (!fe->has_stable()) {
          stable_problem = "needs inputs the formula does not have";
          fe.reset();
        }
      } catch (const std::exception& e) {
        stable_problem = e.what();
        fe.reset();
      }
    }
    Evaluator<double> ev_d(*naive);
    Evaluator<long double> ev_ld(*naive);
    // compensated: the same choice of tape as the stable column (stable form in its regime),
    // each evaluated in double-double; without a usable stable form the formula's own tape
    std::optional<FormulaEvaluator> fc;
    if (fe) fc.emplace(d, f.label, EvalMode::Compensated);
    CompensatedEvaluator ev_dd(*naive);

    Checker ck(d, f, opt, mix(opt.seed, d.source.name + ":" + f.label));
    Acc acc_d, acc_ld, acc_s, acc_c;
    auto run = [&](const Candidate& c) -> bool {
      auto p = ck.exact_point(c.x);
      if (!p) return false;
      bool not_double = false;
      auto ref = ck.reference(*p, &not_double);
      if (!ref) {
        if (not_double) ++rep.reference_not_double;
        return false;
      }
      std::vector<double> xd = c.x;
      std::vector<long double> xl(c.x.begin(), c.x.end());
      const double vd = ev_d(xd);
      acc_d.add(error_in_ulps(vd, *ref), std::isfinite(vd), c);
      const long double vl = ev_ld(xl);
      acc_ld.add(error_in_ulps(vl, *ref), std::isfinite(vl), c);
      const double vc = fc ? fc->compensated_value(xd) : ev_dd(xd);
      acc_c.add(error_in_ulps(vc, *ref), std::isfinite(vc), c);
      if (fe) {
        const double vs = (*fe)(xd);
        if (fe->in_regime(xd.data())) ++rep.in_regime;
        acc_s.add(error_in_ulps(vs, *ref), std::isfinite(vs), c);
      }
      return true;
    };
    rep.rejected += sample_points(ck, opt, run);
    auto stats = [&](const char* name, Acc& a) {
      MethodStats m;
      m.method = name;
      m.points = a.errs.size();
      m.stress_points = a.n_stress;
      m.non_finite = a.non_finite;
      if (!a.errs.empty()) {
        std::vector<double> e = a.errs;
        std::sort(e.begin(), e.end());
        m.median_ulps = e[e.size() / 2];
        m.max_ulps = e.back();
      }
      m.max_ulps_random = a.max_random;
      m.max_ulps_stress = a.max_stress;
      m.worst_kind = a.worst_kind;
      for (std::size_t i = 0; i < a.worst_x.size(); ++i)
        m.worst_point.emplace_back(f.params[i].get_name(), fmt(a.worst_x[i], "%.17g"));
      return m;
    };
    rep.methods.push_back(stats("double", acc_d));
    rep.methods.push_back(stats("long double", acc_ld));
    if (fe) rep.methods.push_back(stats("stable", acc_s));
    else if (!stable_problem.empty()) rep.skipped = "stable form " + rep.stable_label + ": " + stable_problem;
    rep.methods.push_back(stats("compensated", acc_c));
    if (acc_d.errs.empty() && rep.skipped.empty())
      rep.skipped = "no valid point found in the declared domain";
    reports.push_back(std::move(rep));
  }
  return reports;
}

std::string no_formula_reason(const Derivation& d) {
  std::vector<std::string> fns;
  for (const Step& s : d.steps) {
    const Relation& r = s.erratum ? s.erratum->corrected : s.claim;
    if (r.sides.size() < 2 || r.sides[0].kind != NodeKind::Call) continue;
    const SymbolInfo* info = d.symbols.find(r.sides[0].text);
    if (!info || !info->is_function) continue;
    std::string shown = to_text(r.sides[0]);
    if (std::find(fns.begin(), fns.end(), shown) == fns.end()) fns.push_back(shown);
  }
  if (fns.empty())
    return "no step has the form 'y = expression' with y a declared symbol, which is what crosscheck evaluates";
  std::string list;
  for (std::size_t i = 0; i < fns.size() && i < 4; ++i) list += (i ? ", " : "") + fns[i];
  if (fns.size() > 4) list += ", ...";
  return "its results are functions (" + list + "), and crosscheck evaluates steps 'y = expression' with y "
         "a declared symbol: a function of t has no value at a sampled point";
}

std::vector<SamplePoint> crosscheck_points(const Derivation& d, const Formula& f, const CrossCheckOptions& opt) {
  Checker ck(d, f, opt, mix(opt.seed, d.source.name + ":" + f.label));
  std::vector<SamplePoint> out;
  auto take = [&](const Candidate& c) -> bool {
    auto p = ck.exact_point(c.x);
    if (!p) return false;
    auto ref = ck.reference(*p);
    if (!ref) return false;
    out.push_back({c.x, c.kind, *ref});
    return true;
  };
  sample_points(ck, opt, take);
  return out;
}

namespace {
double regime_max(const MethodStats& m, Regime regime) {
  double v = regime == Regime::Random ? m.max_ulps_random : regime == Regime::Stress ? m.max_ulps_stress : m.max_ulps;
  return std::isnan(v) ? INFINITY : v;
}
}  // namespace

const MethodStats* best_method(const FormulaReport& r, Regime regime) {
  const MethodStats* best = nullptr;
  for (const MethodStats& m : r.methods) {
    if (m.method == "long double" || m.points == 0) continue;  // not a double result
    if (regime == Regime::Stress && m.stress_points == 0) continue;
    if (regime == Regime::Random && m.points == m.stress_points) continue;
    if (!best || regime_max(m, regime) < regime_max(*best, regime)) best = &m;
  }
  return best;
}

std::string format_crosscheck(const std::vector<FormulaReport>& reports, const CrossCheckOptions& opt) {
  std::string out;
  std::string file;
  std::vector<std::string> over;
  std::size_t evaluated = 0, not_evaluated = 0;
  char line[512];
  for (const FormulaReport& r : reports) {
    if (r.file != file) {
      file = r.file;
      out += "\n" + file + "\n";
      std::snprintf(line, sizeof line, "  %-28s %-12s %9s %8s %10s %10s  %s\n", "formula", "method",
                    "points", "median", "max(rand)", "max(stress)", "worst at");
      out += line;
    }
    if (r.label.empty()) {   // a file without a formula: why (no_formula_reason)
      out += "  no formula evaluated: " + r.skipped + "\n";
      continue;
    }
    std::string name = r.label;
    if (!r.stable_of.empty()) name += " (stable of " + r.stable_of + ")";
    if (!r.skipped.empty() && r.methods.empty()) {
      out += "  " + name + ": not evaluated: " + r.skipped + "\n";
      ++not_evaluated;
      continue;
    }
    ++evaluated;
    for (std::size_t k = 0; k < r.methods.size(); ++k) {
      const MethodStats& m = r.methods[k];
      std::string where;
      if (m.max_ulps > 4) {
        where = m.worst_kind + ":";
        for (const auto& [n, v] : m.worst_point) where += " " + n + "=" + v;
      }
      const std::string method = m.method == "stable" ? "stable(" + r.stable_label + ")" : m.method;

      std::snprintf(line, sizeof line, "  %-28s %-12s %5zu+%-3zu %8s %10s %10s  %s\n",
                    k == 0 ? name.c_str() : "", method.c_str(), m.points - m.stress_points,
                    m.stress_points, fmt(m.median_ulps).c_str(), fmt(m.max_ulps_random).c_str(),
                    fmt(m.max_ulps_stress).c_str(), where.c_str());
      out += line;
    }
    if (const MethodStats* b = best_method(r)) {
      const MethodStats* br = best_method(r, Regime::Random);
      const MethodStats* bs = best_method(r, Regime::Stress);
      auto shown = [&](const MethodStats* m) { return m->method == "stable" ? "stable(" + r.stable_label + ")" : m->method; };
      // over 4 ulps overall and the regimes disagree: say which method is best where
      if (br && bs && (br != b || bs != b) && !(b->max_ulps <= 4))
        out += "  " + std::string(28, ' ') + " best: random points " + shown(br) + ", max " + fmt(br->max_ulps_random) +
               " ulps; stress points " + shown(bs) + ", max " + fmt(bs->max_ulps_stress) + " ulps\n";
      else
        out += "  " + std::string(28, ' ') + " best: " + b->method + ", max " + fmt(b->max_ulps) + " ulps\n";
      if (!(b->max_ulps <= 4)) {
        // inf/nan where the true value is a finite double: an overflow (or 0*inf) inside the
        // method, not an inaccuracy; say so
        if (!std::isfinite(b->max_ulps) && b->non_finite > 0)
          over.push_back(r.label + " (" + b->method + " overflows: a non-finite result at " +
                         std::to_string(b->non_finite) + " point(s) where the value is a finite double, worst at " +
                         b->worst_kind + ")");
        else
          over.push_back(r.label + " (" + b->method + " " + fmt(b->max_ulps) + ")");
      }
    }
    if (r.reference_not_double > 0)
      out += "  " + std::string(28, ' ') + " note: " + std::to_string(r.reference_not_double) +
             " point(s) left out: the true value is not a finite double there (or too large to enclose)\n";
    if (!r.skipped.empty()) out += "  " + std::string(28, ' ') + " note: " + r.skipped + "\n";
    if (r.stable_regime.rfind("when ", 0) == 0 && !r.methods.empty()) {
      const auto colon = r.stable_regime.find(':');
      out += "  " + std::string(28, ' ') + " note: stable form used at " + std::to_string(r.in_regime) +
             " of " + std::to_string(r.methods[0].points) + " points (" +
             r.stable_regime.substr(0, colon) + ")\n";
    }
  }
  out += "\nbest method within 4 ulps (max over random and stress points): " +
         std::to_string(evaluated - over.size()) + " of " + std::to_string(evaluated) +
         " evaluated formulas (" + std::to_string(not_evaluated) + " not evaluated)\n";
  for (const std::string& o : over) out += "  over 4 ulps: " + o + "\n";
  std::string head = "derivcheck crosscheck: seed " + std::to_string(opt.seed) + ", " +
                     std::to_string(opt.points) + " random points per formula" +
                     (opt.stress ? " + stress points" : "") + ", reference CLN at " +
                     std::to_string(opt.digits) + " digits\n" +
                     "errors in ulps of double at the exact value for the same (double) inputs\n";
  return head + out;
}

}  // namespace dc::num
