// The numeric half of every verdict (docs/soundness.md): sample points from the declared
// domain, compare both sides with ball arithmetic, and turn the outcome into a verdict.
#include "derivations/kernel/probe.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/integral_atom.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/kernel/ball.hpp"

namespace dc::kernel {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// ------------------------------------------------------------------ stage 4: numeric probe
//
// Every comparison goes through the kernel (derivations/kernel/ball.hpp): both sides are
// enclosed in Arb balls at the sample point, precision raised until the balls decide.
//   Differ / one side real and the other certified not real  -> a certified counterexample
//   Agree (difference bounded below the tolerance, rigorously) -> the point supports the claim
//   neither side real, an exact pole, or undecided at the cap  -> the point is not counted

CompareOptions compare_options(const ProveOptions& opt) {
  CompareOptions co;
  co.start_digits = opt.digits;
  co.tol_exponent = std::lround(opt.rel_tol_exponent);
  return co;
}

// An agreement is confirmed once at four times the digits: a false claim whose difference
// lies below the tolerance (cos(10^-40*x) = 1 differs by ~1e-80) separates there.
CompareOptions confirmation(const CompareOptions& co) {
  CompareOptions co4 = co;
  co4.start_digits = 4 * std::max<long>(co.start_digits, -co.tol_exponent + 15);
  return co4;
}

// "lhs = 1.5, rhs = 2.25" / "lhs = 0.4 is real, rhs is not real (log of a negative number)"
std::string difference_text(const PointComparison& c) {
  using K = PointComparison::Kind;
  if (c.kind == K::LhsOnly) return "lhs = " + c.lhs_text() + " is real, rhs is " + c.rhs_text();
  if (c.kind == K::RhsOnly) return "rhs = " + c.rhs_text() + " is real, lhs is " + c.lhs_text();
  return "lhs = " + c.lhs_text() + ", rhs = " + c.rhs_text();
}

void set_refuted(Verdict& v, const PointComparison& c) {
  v.kind = VerdictKind::Refuted;
  v.digits = static_cast<int>(c.digits);
  v.lhs_value = c.lhs_text();
  v.rhs_value = c.rhs_text();
  v.max_rel_diff = c.rel_diff;
}

// Magnitude tier of the k-th draw: of every ten points six lie in 10^[-2, 2] (with assumptions,
// two of them drawn inside the region the assumptions leave, symbol by symbol, and one moved
// next to the boundary of an assumption), two in
// 10^[-6, 6] and two in 10^[-30, 30] (for interval domains: within 1e-9 of the lower and of
// the upper end), so large and tiny values and the ends of the declared domain are tested too
// (a claim that fails only for x > 10^6, or only beyond pi in [0, 355/113], is found; so is one
// that fails only where a chain of assumptions x > y > -1 lets x be negative).
// `failing`: most points so far were unusable (every fourth is then drawn inside the region
// the assumptions leave).
constexpr int kBoundarySweep = 10;   // extra points for claims with assumptions (see probe)
constexpr int kCapStreak = 24;       // points undecided at the precision cap, and no other, end the search

int tier_of(int attempt, bool failing, bool assumptions) {
  if (failing) return assumptions && attempt % 4 == 3 ? 5 : 1 + attempt % 3;
  switch (attempt % 10) {
    case 1:
    case 3: return assumptions ? 5 : 0;   // inside the region the assumptions leave
    case 5: return 4;   // next to the boundary of an assumption (an ordinary point without one)
    case 6:
    case 7: return 1;
    case 8: return 2;   // extreme magnitudes; interval domains: near the lower end
    case 9: return 3;   // extreme magnitudes; interval domains: near the upper end
    default: return 0;
  }
}

bool has_imaginary_number(const ex& e) {
  if (GiNaC::is_a<numeric>(e)) return !GiNaC::ex_to<numeric>(e).is_real();
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_imaginary_number(e.op(i))) return true;
  return false;
}

struct Substituted {
  bool ok = false;
  ex l, r;
};

Substituted substitute_point(const ex& lhs, const ex& rhs, const GiNaC::exmap& p, bool abstract, std::uint64_t fseed) {
  Substituted s;
  try {
    s.l = lhs.subs(p, GiNaC::subs_options::no_pattern);
    s.r = rhs.subs(p, GiNaC::subs_options::no_pattern);
    if (abstract) {
      s.l = detail::replace_abstract(s.l, fseed);
      s.r = detail::replace_abstract(s.r, fseed);
    }
    s.ok = true;
  } catch (const std::exception&) {
    // an exact division by zero while substituting: an isolated point, not a counterexample
  }
  return s;
}

// The values the abstract applications of lhs and rhs took at the point (drawn from the seed,
// as in substitute_point): "theta(t) = 0.41, diff(theta(t), t) = -1.2", so a reader sees the
// function values that make the sides differ. At most six, ordered by their text.
std::string function_values(const ex& lhs, const ex& rhs, const GiNaC::exmap& p, std::uint64_t fseed,
                            const SymbolTable& ctx) {
  std::map<std::string, ex> apps;
  std::function<void(const ex&)> collect = [&](const ex& e) {
    if (detail::is_abstract_application(e)) {
      apps.emplace(print_text(e, ctx), e);
      return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i));
  };
  collect(lhs);
  collect(rhs);
  std::string out;
  int shown = 0;
  for (const auto& [text, app] : apps) {
    if (shown == 6) {
      out += ", ...";
      break;
    }
    try {
      const ex value = detail::replace_abstract(app.subs(p, GiNaC::subs_options::no_pattern), fseed).evalf();
      if (!GiNaC::is_a<numeric>(value)) continue;
      out += (out.empty() ? "" : ", ") + text + " = " + print_number(value, 6);
      ++shown;
    } catch (const std::exception&) {
    }
  }
  return out;
}

}  // namespace

namespace {
Verdict probe_points(const ex& lhs, const ex& rhs, const SymbolTable& ctx, const ProveOptions& opt,
                     const std::string& residual);
}  // namespace

// An integral of a declared function is drawn as an independent quantity (symbolic/integral_atom.hpp):
// agreement at such draws shows the sides agree whatever values the integrals take, but a
// difference may come from a relation between two integrals that the draws ignore (a change of
// variable, adjacent intervals). So a claim containing one is never refuted here.
Verdict probe(const ex& lhs, const ex& rhs, const SymbolTable& ctx, const ProveOptions& opt,
              const std::string& residual) {
  Verdict v = probe_points(lhs, rhs, ctx, opt, residual);
  if (v.kind == VerdictKind::Refuted && (has_integral_quantity(lhs) || has_integral_quantity(rhs))) {
    Verdict u;
    u.kind = VerdictKind::Undecided;
    u.method = v.method;
    u.residual = residual;
    u.reason = "the sides differ when each integral of a declared function is drawn as an independent quantity, "
               "but relations between such integrals (a change of variable, adjacent intervals, integration by "
               "parts) are not known to the checker";
    u.detail = u.reason;
    return u;
  }
  return v;
}

namespace {
Verdict probe_points(const ex& lhs, const ex& rhs, const SymbolTable& ctx, const ProveOptions& opt,
                     const std::string& residual) {
  using K = PointComparison::Kind;
  Verdict v;
  v.method = "numeric probe";
  v.residual = residual;
  const CompareOptions co = compare_options(opt);
  const long tol_exp = co.tol_exponent;
  v.digits = static_cast<int>(std::max<long>(opt.digits, -tol_exp + 15));

  if (has_imaginary_number(lhs) || has_imaginary_number(rhs)) {
    // The probe decides claims about real quantities (a non-real intermediate means "not
    // defined here"); a claim written with I is complex-valued by intent.
    v.kind = VerdictKind::Undecided;
    v.reason = "the claim contains the imaginary unit: the numeric probe decides real-valued claims only";
    v.detail = v.reason;
    return v;
  }
  detail::PointSampler sampler({lhs, rhs}, ctx);
  bool abstract = detail::has_abstract_application(lhs) || detail::has_abstract_application(rhs);
  std::uint64_t fn_seed = opt.seed ^ 0xA5A5A5A55A5A5A5Aull;

  const CompareOptions co4 = confirmation(co);
  if (sampler.symbols().empty() && !abstract) {
    PointComparison c = compare_constants(lhs, rhs, co);
    if (c.kind == K::Agree) {
      PointComparison c4 = compare_constants(lhs, rhs, co4);
      if (certified_counterexample(c4)) c = c4;
    }
    if (certified_counterexample(c)) {
      set_refuted(v, c);
      v.detail = "the constants differ: " + difference_text(c) + " (certified by ball arithmetic at " +
                 std::to_string(c.digits) + " digits)";
      return v;
    }
    if (c.kind == K::Agree) {
      v.kind = VerdictKind::HoldsNumerically;
      v.points = 1;
      v.digits = static_cast<int>(c.digits);
      v.lhs_value = c.lhs_text();
      v.rhs_value = c.rhs_text();
      v.max_rel_diff = c.rel_diff;
      // The bound itself is not printed: its last digits follow GiNaC's term order, which
      // changes between processes. The tolerance it was checked against is deterministic.
      v.false_accept = "constant claim: |lhs - rhs| <= 1e" + std::to_string(tol_exp) +
                       " relative, a rigorous ball-arithmetic bound at " + std::to_string(c.digits) +
                       " digits; only a false identity closer than that could pass";
      v.detail = "constants agree: " + c.lhs_text() + " (difference bounded rigorously below 1e" +
                 std::to_string(tol_exp) + " relative at " + std::to_string(c.digits) + " digits)";
      return v;
    }
    v.kind = VerdictKind::Undecided;
    v.reason = "the constant claim cannot be decided: " + c.why;
    v.detail = v.reason;
    return v;
  }

  detail::Rng rng(opt.seed);
  const int need = std::max(1, opt.probe_points);
  const int max_attempts = std::max(100, need * 40);
  int agreed = 0, attempts = 0, excluded = 0, undefined = 0, neither_real = 0, unknown = 0;
  std::string unknown_why;
  double max_rel = 0;
  long max_digits = 0;
  // One point drawn at `tier` and compared. A certified difference refutes (v is set, true is
  // returned); an agreement and the reasons a point is unusable are counted when `counting`.
  // Special values where formulas degenerate: a closed end of a declared domain (0 of a
  // nonnegative symbol, a and b of [a, b]) and 0 of a real one. The draws above avoid them;
  // after an agreement they are tried, one symbol at a time, and can only refute (a claim false
  // only at a = 0, such as sqrt(x^2 + a^2) = abs(a) + O(x^2), is caught there).
  std::vector<std::pair<ex, ex>> specials;
  for (const auto& sym : sampler.symbols()) {
    const Domain dom = detail::domain_of(sym, ctx);
    if (dom.kind == Domain::Kind::Real || dom.kind == Domain::Kind::Nonnegative) specials.push_back({sym, 0});
    if (dom.kind == Domain::Kind::Interval && !dom.integer) {
      if (!dom.lo_open) specials.push_back({sym, dom.lo});
      if (!dom.hi_open) specials.push_back({sym, dom.hi});
    }
  }
  int special = -1;   // >= 0: try_point sets specials[special] on a tier-0 point
  GiNaC::exmap last_point;   // the point try_point drew last
  auto try_point = [&](int tier, bool counting) {
    bool admissible = false;
    GiNaC::exmap p = sampler.draw(rng, tier, &admissible);
    last_point = p;
    if (special >= 0) {
      const auto& [sym, value] = specials[static_cast<std::size_t>(special)];
      p[sym] = value;
      admissible = true;
      for (const Constraint* k : sampler.constraints()) admissible = admissible && kernel::holds_at(*k, p);
    }
    if (!admissible) {
      if (counting) ++excluded;
      return false;
    }
    std::uint64_t fseed = fn_seed + 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(attempts + 1);
    PointComparison c;
    Substituted s;
    if (abstract) {
      // abstract applications get their random values from their (substituted) arguments
      s = substitute_point(lhs, rhs, p, abstract, fseed);
      if (!s.ok) {
        if (counting) ++undefined;
        return false;
      }
    }
    auto compare = [&](const CompareOptions& o) {
      return abstract ? compare_constants(s.l, s.r, o) : compare_at(lhs, rhs, &p, o);
    };
    c = compare(co);
    if (c.kind == K::Agree && agreed == 0) {
      PointComparison c4 = compare(co4);
      if (certified_counterexample(c4)) c = c4;
    }
    if (!certified_counterexample(c)) {
      if (!counting) return false;
      if (c.kind == K::Agree) {
        ++agreed;
        max_rel = std::max(max_rel, c.rel_diff);
        max_digits = std::max(max_digits, c.digits);
      } else if (c.kind == K::NeitherReal) {
        ++neither_real;
      } else if (c.kind == K::IsolatedPole) {
        ++undefined;
      } else {
        ++unknown;
        if (unknown_why.empty()) unknown_why = c.why;
      }
      return false;
    }
    set_refuted(v, c);
    v.points = agreed;
    v.point = sampler.describe(p);
    std::string where = v.point.empty() ? std::string("an abstract-function sample") : detail::join_point(v.point);
    v.detail = "differs at " + where + ": " + difference_text(c) + " (certified by ball arithmetic at " +
               std::to_string(c.digits) + " digits)";
    if (abstract) {
      const std::string values = function_values(lhs, rhs, p, fseed, ctx);
      v.function_values = values;
      v.detail += values.empty() ? " (abstract function values drawn at random)"
                                 : " (abstract function values drawn at random: " + values + ")";
    }
    return true;
  };
  // A refutation at extreme magnitudes (m = 1e-10, where both sides agree to fourteen digits)
  // is certified but tells the reader little; when a point of ordinary size (every value 0 or
  // of magnitude 10^[-2, 2]) refutes too, that one is reported. Only the witness changes.
  auto ordinary = [&](const GiNaC::exmap& pt) {
    for (const auto& [sym, val] : pt) {
      if (!GiNaC::is_a<numeric>(val)) return false;
      const numeric a = GiNaC::abs(GiNaC::ex_to<numeric>(val));
      if (!a.is_zero() && (a < numeric(1, 100) || a > numeric(100))) return false;
    }
    return true;
  };
  auto prefer_ordinary_witness = [&]() {
    if (ordinary(last_point)) return;
    const Verdict found = v;
    for (int k = 0; k < 40; ++k, ++attempts) {
      const int tier = !sampler.constraints().empty() && k % 2 == 1 ? 5 : 0;
      if (try_point(tier, false) && ordinary(last_point)) return;
    }
    v = found;
  };
  for (; attempts < max_attempts && agreed < need; ++attempts) {
    if (try_point(tier_of(attempts, attempts >= need * 10, !sampler.constraints().empty()), true)) {
      prefer_ordinary_witness();
      return v;
    }
    // every point so far undecided at the precision cap (a divisor that is zero on the whole
    // sample box, not syntactically): more points of the same box cost seconds each and
    // decide nothing
    if (unknown >= kCapStreak && unknown == attempts + 1) {
      ++attempts;
      break;
    }
  }
  // With assumptions, ten more points, alternately next to the boundary of an assumption and
  // inside the region the assumptions leave, which can only refute: a claim false in a thin
  // slice the assumptions leave open (abs(x - 1) = x - 1 with x > 1 - 1e-9) is met far more
  // often, while the points an acceptance rests on are drawn as before.
  if (agreed >= need && !sampler.constraints().empty())
    for (int k = 0; k < kBoundarySweep; ++k, ++attempts)
      if (try_point(k % 2 == 0 ? 4 : 5, false)) return v;
  if (agreed >= need)
    for (std::size_t k = 0; k < specials.size() && k < 8; ++k, ++attempts) {
      special = static_cast<int>(k);
      const bool refuted = try_point(0, false);
      special = -1;
      if (refuted) return v;
    }
  if (agreed >= need) {
    v.kind = VerdictKind::HoldsNumerically;
    v.points = agreed;
    v.max_rel_diff = max_rel;
    v.digits = static_cast<int>(std::max<long>(v.digits, max_digits));
    // False-accept bound (stated, heuristic for transcendental differences): each symbol is
    // drawn from roughly 1e9 distinct rationals (random denominator ~1e5, magnitudes over 4,
    // 12 and 60 decades). A nonzero polynomial/rational difference of degree <= 1000 vanishes
    // on at most 1000 values per line through the sample box (Schwartz-Zippel), i.e. on < 1e-6
    // of the draws; an analytic difference that is not identically zero behaves the same way
    // away from its (measure-zero) zero set. Each agreement is a rigorous bound (ball
    // arithmetic), so rounding can never make a difference look like agreement.
    std::ostringstream fa;
    fa << "< 1e-6 per point, < 1e-" << 6 * agreed << " for all " << agreed
       << " points (Schwartz-Zippel-type count: a nonzero difference of degree <= 1000 vanishes on"
          " < 1e-6 of ~1e9 sampled values per symbol; heuristic for transcendental differences;"
          " each difference is bounded rigorously below 1e"
       << tol_exp << " relative)";
    bool integers = false;
    for (const auto& sym : sampler.symbols()) integers = integers || detail::domain_of(sym, ctx).integer;
    if (integers)
      fa << "; integer symbols are drawn from the integers (half of them in [-12, 12]), where a nonzero difference"
            " may vanish more often: the count is for the other symbols";
    v.false_accept = fa.str();
    v.detail = std::to_string(agreed) + " random points agree: |lhs - rhs| <= 1e" + std::to_string(tol_exp) +
               " relative at each, rigorous bounds from ball arithmetic at up to " + std::to_string(v.digits) + " digits";
    if (abstract) v.detail += "; abstract functions replaced by independent random values";
    return v;
  }
  v.kind = VerdictKind::Undecided;
  v.points = agreed;
  std::ostringstream why;
  if (agreed == 0 && excluded == attempts)
    why << "no valid sample points: the constraints exclude every point tried (" << attempts << ")";
  else {
    why << "only " << agreed << " of " << need << " sample points were usable (" << attempts
        << " tried: " << excluded << " outside the assumptions, " << undefined << " undefined, "
        << neither_real << " where neither side is real, " << unknown << " undecided at the precision cap)";
    if (!unknown_why.empty()) why << "; " << unknown_why;
  }
  v.reason = why.str();
  v.detail = v.reason;
  return v;
}

}  // namespace

bool certified_counterexample(const PointComparison& c) {
  using K = PointComparison::Kind;
  return c.kind == K::Differ || c.kind == K::LhsOnly || c.kind == K::RhsOnly;
}

PointComparison compare_point(const ex& lhs, const ex& rhs, const GiNaC::exmap& point, const ProveOptions& opt) {
  const CompareOptions co = compare_options(opt);
  PointComparison c = compare_at(lhs, rhs, &point, co);
  if (c.kind == PointComparison::Kind::Agree) {
    PointComparison c4 = compare_at(lhs, rhs, &point, confirmation(co));
    if (certified_counterexample(c4)) c = c4;
  }
  return c;
}

// A symbolic proof is re-witnessed at one admissible point: if the balls there certify a
// difference, the symbolic stage is wrong (a bug, or a rewrite applied outside its domain).
// Returns the contradiction's description, or "" when the witness agrees or cannot decide.
std::string witness_contradiction(const ex& lhs, const ex& rhs, const SymbolTable& ctx, const ProveOptions& opt) {
  // the kernel decides real values only (probe): a claim written with I has no real witness
  if (has_imaginary_number(lhs) || has_imaginary_number(rhs)) return "";
  detail::PointSampler sampler({lhs, rhs}, ctx);
  bool abstract = detail::has_abstract_application(lhs) || detail::has_abstract_application(rhs);
  detail::Rng rng(opt.seed ^ 0x5157A1E55ull);
  const CompareOptions co = compare_options(opt);
  for (int attempt = 0; attempt < 12; ++attempt) {
    bool admissible = false;
    GiNaC::exmap p = sampler.draw(rng, attempt % 3, &admissible);
    if (!admissible) continue;
    PointComparison c;
    if (abstract) {
      Substituted s = substitute_point(lhs, rhs, p, abstract, opt.seed + 977 * (attempt + 1));
      if (!s.ok) continue;
      c = compare_constants(s.l, s.r, co);
    } else {
      c = compare_at(lhs, rhs, &p, co);
    }
    if (certified_counterexample(c))
      return "at " + detail::join_point(sampler.describe(p)) + ": " + difference_text(c);
    if (c.kind == PointComparison::Kind::Agree) return "";
  }
  return "";
}


}  // namespace dc::kernel
