// Certified double results (see certified.hpp).
#include "numeric/certified/certified.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "derivations/kernel/ball.hpp"
#include "numeric/certified/certified_batch.hpp"
#include "numeric/certified/certified_fast.hpp"
#include "numeric/evaluator.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/formula_evaluator.hpp"
#include "numeric/reference/reference.hpp"

namespace dc::num {
namespace {

using GiNaC::numeric;

constexpr long kStartBits = 96;
constexpr long kMaxBits = 1L << 16;

// The true value, enclosed: [lo, hi] exact, or (huge) a value far outside double's range.
struct Enclosure {
  numeric lo, hi;
  bool outside = false;   // beyond 2^(2^20) or below 2^-(2^20)
  double outside_value = 0;   // +-inf or +-0 for an outside value
  std::string outside_text;   // its magnitude, "1.2e+40769447553"
  long bits = 0;
};

// Narrows until `good(lo, hi)` or the cap. Throws domain_error for a point without a real value.
template <class Good>
Enclosure enclose_until(const Formula& f, const GiNaC::exmap& point, Good good, bool* decided) {
  Enclosure e;
  *decided = false;
  std::string why = "the enclosure did not narrow";
  bool have = false;
  for (long prec = kStartBits; prec <= kMaxBits; prec *= 2) {
    std::optional<kernel::Ball> enclosed = enclose_formula(f.expr, point, prec, &why);
    if (!enclosed) continue;
    const kernel::Ball& b = *enclosed;
    e.bits = prec;
    numeric lo, hi;
    if (!b.exact_bounds(lo, hi)) {
      if (b.rel_accuracy_bits() < 8) continue;
      e.outside = true;
      e.outside_value = b.to_double();   // +-inf or +-0: far beyond double's range either way
      e.outside_text = b.text(6);
      *decided = true;
      return e;
    }
    e.lo = lo;
    e.hi = hi;
    have = true;
    if (good(lo, hi)) {
      *decided = true;
      return e;
    }
  }
  if (!have) throw std::range_error("the value could not be enclosed within " + std::to_string(kMaxBits) + " bits (" + why + ")");
  return e;
}

numeric abs_num(const numeric& x) { return x < 0 ? -x : x; }

// A certified upper bound of max(|r - lo|, |r - hi|) in units of the double spacing at the true
// value (the smaller spacing of the two ends, so the bound is never too small).
double bound_in_ulps(const numeric& r, const numeric& lo, const numeric& hi) {
  numeric err = std::max(abs_num(r - lo), abs_num(r - hi));
  numeric ulp = std::min(double_ulp(lo), double_ulp(hi));
  numeric q = err / ulp;
  if (q.is_zero()) return 0;   // exact
  double d = q.to_double();
  return std::nextafter(d * (1 + 1e-12), std::numeric_limits<double>::infinity());   // rounded up
}

std::string values_text(const std::vector<std::pair<std::string, numeric>>& v) {
  std::string s;
  for (const auto& [n, x] : v) s += (s.empty() ? "" : ", ") + n + " = " + shortest_text(x.to_double());
  return s;
}

// The inputs of the fast stages at an exact point, in the order of f.params: each as a
// double-double (the nearest double, the nearest double to the rest) with a bound on what is
// left, so that a decimal such as 0.7 is known to ~2^-106 and not to half an ulp; and, for the
// long double stage, which takes the double alone, the bound on the whole rest.
struct FastInputs {
  std::vector<double> x, lo, err, err_ld;
};

std::optional<FastInputs> fast_inputs(const Derivation& d, const Formula& f, const GiNaC::exmap& point) {
  const double inf = std::numeric_limits<double>::infinity();
  auto up = [&](const numeric& r) {   // |r| as a double, rounded up well beyond to_double's error
    const double e = abs_num(r).to_double();
    return e == 0 ? 0.0 : std::nextafter(e * (1 + 0x1p-40), inf) + std::numeric_limits<double>::denorm_min();
  };
  FastInputs in;
  for (const auto& s : f.params) {
    const numeric v = GiNaC::ex_to<numeric>(point.at(d.symbols.find(s.get_name())->sym));
    const double xd = nearest_double(v);
    if (!std::isfinite(xd)) return std::nullopt;
    const numeric rest = v - exact_rational(xd);
    const double xl = rest.is_zero() ? 0.0 : nearest_double(rest);
    in.x.push_back(xd);
    in.lo.push_back(xl);
    in.err.push_back(up(rest - exact_rational(xl)));
    in.err_ld.push_back(up(rest));
  }
  return in;
}

// Stage 1 of Auto (certified_batch.hpp) at one point: the answer when it decides.
std::optional<CertifiedDouble> double_double_stage(const CertifiedBatch& batch, const FastInputs& in) {
  std::vector<const double*> cols, lows, errs;
  for (std::size_t i = 0; i < in.x.size(); ++i) {
    cols.push_back(&in.x[i]);
    lows.push_back(&in.lo[i]);
    errs.push_back(&in.err[i]);
  }
  double hi = 0, lo = 0, e = 0;
  batch.eval_dd_block({cols.data(), lows.data(), errs.data()}, 0, 1, &hi, &lo, &e);
  const std::optional<double> v = round_certified(hi, lo, e);
  if (!v || !std::isfinite(*v)) return std::nullopt;   // +-inf: the long double stage says how far out
  CertifiedDouble out;
  out.value = *v;
  char bound[32];
  std::snprintf(bound, sizeof bound, "%.1e", e);
  out.method = std::string("auto (correctly rounded: double-double with a running error bound, ") + bound + ")";
  out.error_ulps = 0.5;
  if (*v == 0 && hi != 0) out.note = "the true value rounds to 0 (below half the smallest subnormal)";
  return out;
}

std::optional<CertifiedBatch> compile_batch(const Formula& f) {
  try {
    return CertifiedBatch(compile(f.expr, f.params));
  } catch (const std::exception&) {
    return std::nullopt;   // not compilable to a tape: Arb evaluates it
  }
}

// The fast stages of Auto: the tape in double-double, then in long double, each with a running
// error bound (certified_batch.hpp, certified_fast.hpp). nullopt when neither can decide the
// rounding: the caller escalates to Arb.
std::optional<CertifiedDouble> fast_first_try(const Derivation& d, const Formula& f, const GiNaC::exmap& point) {
  const std::optional<FastInputs> in = fast_inputs(d, f, point);
  if (!in) return std::nullopt;
  const std::optional<CertifiedBatch> batch = compile_batch(f);
  if (!batch) return std::nullopt;
  if (auto r = double_double_stage(*batch, *in)) return r;
  const std::vector<double>& x = in->x;
  const FastCertified r = batch->long_double_stage()(x.data(), in->err_ld.data());
  if (!r.decided) return std::nullopt;
  CertifiedDouble out;
  out.value = r.value;
  char bound[32];
  std::snprintf(bound, sizeof bound, "%.1Le", r.bound);
  out.method = std::string("auto (correctly rounded: long double with a running error bound, ") + bound + ")";
  if (std::isinf(r.value)) {
    char mag[48];
    std::snprintf(mag, sizeof mag, "%.5Le", r.approx);
    out.note = std::string("the true value, about ") + mag + ", overflows double";
    return out;
  }
  out.error_ulps = 0.5;
  if (r.value == 0 && r.approx != 0)
    out.note = "the true value rounds to 0 (below half the smallest subnormal)";
  return out;
}

}  // namespace

std::optional<DoubleMethod> parse_double_method(const std::string& name) {
  if (name == "auto") return DoubleMethod::Auto;
  if (name == "double") return DoubleMethod::Double;
  if (name == "long-double") return DoubleMethod::LongDouble;
  if (name == "compensated") return DoubleMethod::Compensated;
  if (name == "stable") return DoubleMethod::Stable;
  return std::nullopt;
}

const char* to_string(DoubleMethod m) {
  switch (m) {
    case DoubleMethod::Auto: return "auto";
    case DoubleMethod::Double: return "double";
    case DoubleMethod::LongDouble: return "long-double";
    case DoubleMethod::Compensated: return "compensated";
    case DoubleMethod::Stable: return "stable";
  }
  return "?";
}

double nearest_double(const numeric& x) {
  if (x.is_zero()) return 0.0;
  const double big = std::numeric_limits<double>::max();
  // the overflow threshold: max + half its spacing (2^1024 - 2^970) rounds to inf
  static const numeric threshold = exact_rational(big) + double_ulp(exact_rational(big)) / 2;
  if (abs_num(x) >= threshold) return x > 0 ? std::numeric_limits<double>::infinity()
                                            : -std::numeric_limits<double>::infinity();
  double c = round_to_double(x);
  if (std::isinf(c)) c = x > 0 ? big : -big;
  double best = c;
  numeric best_err = abs_num(x - exact_rational(c));
  for (double n : {std::nextafter(c, -std::numeric_limits<double>::infinity()),
                   std::nextafter(c, std::numeric_limits<double>::infinity())}) {
    if (std::isinf(n)) continue;
    numeric err = abs_num(x - exact_rational(n));
    bool even = (std::bit_cast<std::uint64_t>(n) & 1U) == 0;
    if (err < best_err || (err == best_err && even)) {
      best = n;
      best_err = err;
    }
  }
  return best;
}

std::string shortest_text(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  for (int p = 1; p <= 17; ++p) {
    std::snprintf(buf, sizeof buf, "%.*g", p, x);
    if (std::strtod(buf, nullptr) == x) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::vector<std::optional<CertifiedDouble>> certified_auto_first_stage(
    const Derivation& d, const std::string& label,
    const std::vector<std::vector<std::pair<std::string, numeric>>>& points) {
  std::vector<std::optional<CertifiedDouble>> out(points.size());
  const Formula f = formula(d, label);
  const std::optional<CertifiedBatch> batch = compile_batch(f);
  if (!batch) return out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    try {
      if (const std::optional<FastInputs> in = fast_inputs(d, f, bind_point(d, f, points[i])))
        out[i] = double_double_stage(*batch, *in);
    } catch (const std::exception&) {
      // does not bind (outside the domain, a missing name, ...): certified_eval says why
    }
  }
  return out;
}

CertifiedDouble certified_eval(const Derivation& d, const std::string& label,
                               const std::vector<std::pair<std::string, numeric>>& at, DoubleMethod m) {
  const Formula f = formula(d, label);
  CertifiedDouble out;
  bool decided = false;

  if (m == DoubleMethod::Auto) {
    const GiNaC::exmap point = bind_point(d, f, at);
    if (auto fast = fast_first_try(d, f, point)) return *fast;
    Enclosure e = enclose_until(f, point, [](const numeric& lo, const numeric& hi) {
      return nearest_double(lo) == nearest_double(hi);
    }, &decided);
    if (e.outside) {
      out.value = e.outside_value;
      out.method = "auto (Arb enclosure at " + std::to_string(e.bits) + " bits)";
      out.note = std::string("the true value, about ") + e.outside_text + ", " +
                 (std::isinf(e.outside_value) ? "overflows double" : "underflows double (below half the smallest subnormal)");
      out.error_ulps = -1;
      return out;
    }
    const numeric mid = (e.lo + e.hi) / 2;
    out.value = nearest_double(decided ? e.lo : mid);
    out.method = std::string("auto (") + (decided ? "correctly rounded: " : "") + "Arb enclosure at " +
                 std::to_string(e.bits) + " bits" + (decided ? ")" : "; the rounding is not decided within the cap)");
    if (std::isinf(out.value)) {
      out.note = "the true value, " + format_significant(mid, 6) + ", overflows double";
      return out;
    }
    out.error_ulps = decided ? 0.5 : bound_in_ulps(exact_rational(out.value), e.lo, e.hi);
    if (out.value == 0 && !(e.lo.is_zero() && e.hi.is_zero()))
      out.note = "the true value, " + format_significant(mid, 6) + ", rounds to 0 (below half the smallest subnormal)";
    return out;
  }

  // A double method: the inputs rounded to the nearest double.
  std::vector<std::pair<std::string, numeric>> rounded;
  bool changed = false;
  for (const auto& [name, v] : at) {
    double x = nearest_double(v);
    if (!std::isfinite(x)) throw std::domain_error("'" + name + "' is beyond double's range");
    numeric xr = exact_rational(x);
    changed = changed || xr != v;
    rounded.emplace_back(name, xr);
  }
  const GiNaC::exmap point = bind_point(d, f, rounded);
  std::vector<double> x;
  for (const auto& s : f.params)   // exact: the values are doubles
    x.push_back(GiNaC::ex_to<numeric>(point.at(d.symbols.find(s.get_name())->sym)).to_double());

  FormulaEvaluator fe(d, label, m == DoubleMethod::Compensated ? EvalMode::Compensated : EvalMode::Fast);
  switch (m) {
    case DoubleMethod::Double:
      out.value = fe.naive(x);
      out.method = "double (the formula's tape)";
      break;
    case DoubleMethod::LongDouble: {
      Evaluator<long double> ld(compile(f.expr, f.params));
      std::vector<long double> xl(x.begin(), x.end());
      long double v = ld(xl);
      out.value = std::isfinite(static_cast<double>(v)) ? nearest_double(exact_rational(v)) : static_cast<double>(v);
      out.method = "long-double (the formula's tape, rounded to double)";
      break;
    }
    case DoubleMethod::Compensated:
      out.value = fe.compensated_value(x);
      out.method = std::string("compensated (double-double") + (fe.has_stable() ? ", the stable form in its regime)" : ")");
      break;
    case DoubleMethod::Stable:
      out.value = fe.fast(x);
      out.method = fe.has_stable() ? "stable (" + fe.stable_label() + " in its regime, in double)"
                                   : "stable (the file has no stable form of this formula: the formula's tape)";
      break;
    case DoubleMethod::Auto: break;
  }
  Enclosure e = enclose_until(f, point, [&](const numeric& lo, const numeric& hi) {
    // narrow enough that the bound is within 1/1000 ulp of the error it certifies
    return (hi - lo) < std::min(double_ulp(lo), double_ulp(hi)) / 1000;
  }, &decided);
  if (changed) out.note = "inputs rounded to the nearest double: " + values_text(rounded);
  if (e.outside) {
    out.error_ulps = -1;
    out.note += std::string(out.note.empty() ? "" : "; ") + "the true value, about " + e.outside_text + ", is outside double's range";
    return out;
  }
  if (!std::isfinite(out.value)) {
    out.error_ulps = -1;
    const numeric mid = (e.lo + e.hi) / 2;
    out.note += std::string(out.note.empty() ? "" : "; ") + "the true value is " + format_significant(mid, 17) +
                (std::isinf(nearest_double(mid)) ? " (overflows double)" : " (finite: this method overflowed)");
    return out;
  }
  out.error_ulps = bound_in_ulps(exact_rational(out.value), e.lo, e.hi);
  return out;
}

}  // namespace dc::num
