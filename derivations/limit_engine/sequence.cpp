// check_sequence: the numeric witness of a limit (see limits.hpp).
//
// f is evaluated with Arb balls (kernel/ball.hpp) at x_k = point +- 10^-k (or +-10^k),
// k = 2, 4, 8, 16, 32, 64, the parameters at a sampled admissible point. The precision is
// raised at each x_k until the sign of f - L is decided (up to 8192 bits), so cancellation
// ((1 - cos(x))/x^2 at x = 1e-64) cannot fake a value: a ball that does not decide is not
// used. Magnitudes from a sign-decided ball are right within a factor 2; the thresholds of a
// contradiction are certified with a second ball (|f - L| - thr > 0).
#include <cmath>
#include <sstream>

#include "derivations/symbolic/printer.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/kernel/ball.hpp"
#include "derivations/limit_engine/budget.hpp"
#include "derivations/limit_engine/limits.hpp"

namespace dc::limits {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

constexpr long kStartBits = 128;
constexpr long kMaxBits = 1 << 13;
constexpr double kMaxSeconds = 0.5;

struct Sample {
  int k;          // x_k = point +- 10^-k or +-10^k
  double mag;     // |f - L| (finite L) or |f| (infinite L), within a factor 2; 0 when exactly 0
  int sign;       // sign of f - L (or of f); 0: exactly 0 or not separated from 0 at the cap
  GiNaC::exmap at;
};

numeric pow10(long k) { return GiNaC::pow(numeric(10), numeric(k)); }

bool certified_above(const ex& d, const GiNaC::exmap& at, double thr) {
  kernel::Ball b = kernel::enclose_sign_at(GiNaC::abs(d) - numeric(thr), &at, kStartBits, kMaxBits);
  return b.positive();
}

std::string fmt(double v) {
  std::ostringstream os;
  os.precision(3);
  os << v;
  return os.str();
}

}  // namespace

SequenceCheck check_sequence(const ex& f, const ex& x, const ex& point, int at_infinity, int dir, const LimitOutcome& target,
                             const SymbolTable& ctx) {
  SequenceCheck out;
  const bool finite = target.kind == LimitOutcome::Kind::Value;
  if (!finite && !target.infinite()) {
    out.note = "nothing to check numerically";
    return out;
  }
  const int want = target.kind == LimitOutcome::Kind::MinusInfinity ? -1 : 1;
  std::vector<ex> exprs{f, point};
  if (finite) exprs.push_back(target.value);
  detail::PointSampler sampler(exprs, ctx);
  detail::Rng rng(20261205);
  std::string last_problem = "no admissible parameter point";
  // parameters: a few admissible points; none: one evaluation of the sequence is all there is
  const bool has_params = sampler.symbols().size() > (f.has(x) ? 1u : 0u);
  const double start = cpu_seconds();
  for (int attempt = 0; attempt < (has_params ? 4 : 1); ++attempt) {
    bool adm = false;
    GiNaC::exmap p = sampler.draw(rng, 0, &adm);
    if (!adm) continue;
    p.erase(x);
    ex L = finite ? target.value.subs(p, GiNaC::subs_options::no_pattern) : ex(0);
    double scale = 1;
    if (finite) {
      kernel::Ball lb = kernel::enclose_sign(L, kStartBits, kMaxBits);
      if (lb.status != kernel::BallStatus::Value) {
        last_problem = "the limit has no real value at the sampled parameters";
        continue;
      }
      scale = std::max(1.0, std::fabs(lb.to_double()));
      if (!std::isfinite(scale)) {   // exp(1e9): no double thresholds; the engine's value stands alone
        last_problem = "the limit's magnitude is beyond double's range, so the sequence is not compared with it";
        continue;
      }
    }
    const ex D = finite ? f - L : f;
    std::vector<Sample> samples;
    for (int k : {2, 4, 8, 16, 32, 64}) {
      GiNaC::exmap q = p;
      q[x] = at_infinity != 0 ? ex(at_infinity * pow10(k)) : point.subs(p, GiNaC::subs_options::no_pattern) + dir * pow10(-k);
      if (cpu_seconds() - start > kMaxSeconds) {
        out.note = "budget: the numeric sequence took more than " + fmt(kMaxSeconds) + " s of CPU time";
        return out;
      }
      // one evaluation at the start precision first: a point whose evaluation is both
      // undecided and slow (Arb reducing exp(2^(2^20)) before it gives up) ends the sequence;
      // a decided one is the answer enclose_sign_at would give, so it is kept
      const double t0 = cpu_seconds();
      kernel::Ball quick = kernel::enclose_at(D, &q, kStartBits);
      const double spent = cpu_seconds() - t0;
      if (quick.status == kernel::BallStatus::Unknown && spent > 0.05) break;
      kernel::Ball b = kernel::sign_decided(quick) ? std::move(quick) : kernel::enclose_sign_at(D, &q, 4 * kStartBits, kMaxBits);
      // not decided at the precision cap: points closer to the limit need more still
      if (b.status == kernel::BallStatus::Unknown) break;
      if (b.status != kernel::BallStatus::Value) continue;
      Sample s{k, 0, 0, q};
      if (b.positive() || b.negative()) {
        s.sign = b.positive() ? 1 : -1;
        s.mag = std::fabs(b.to_double());
        if (std::isnan(s.mag)) continue;
      } else if (!b.exact_zero()) {
        // not separated from 0 at the cap: used only when certainly tiny
        kernel::Ball t = kernel::enclose_sign_at(GiNaC::abs(D) - numeric(1, 1000000) * pow10(-30), &q, kStartBits, kMaxBits);
        if (!t.negative()) continue;
      }
      samples.push_back(std::move(s));
    }
    if (samples.size() < 2) {
      last_problem = "fewer than two points of the sequence could be evaluated";
      continue;
    }
    const Sample& first = samples.front();
    const Sample& last = samples.back();
    std::string where = at_infinity != 0 ? std::string("x = ") + (at_infinity < 0 ? "-" : "") + "1e" + std::to_string(last.k)
                                         : std::string("x = point ") + (dir > 0 ? "+" : "-") + " 1e-" + std::to_string(last.k);
    // certified: f stays away from the target at the last two points while it no longer
    // moves between them (true limits that converge slowly, such as 1/log(x), move by as
    // much as their distance to the limit)
    const Sample& prev = samples[samples.size() - 2];
    const ex x1 = pooled_symbol("x_seq", 0);
    const ex x2 = pooled_symbol("x_seq", 1);
    GiNaC::exmap both = p;
    both[x1] = last.at.at(x);
    both[x2] = prev.at.at(x);
    const ex step = GiNaC::abs(f.subs(x == x1, GiNaC::subs_options::no_pattern) -
                               f.subs(x == x2, GiNaC::subs_options::no_pattern));
    auto certified_negative = [&](const ex& e, const GiNaC::exmap& at) {
      return kernel::enclose_sign_at(e, &at, kStartBits, kMaxBits).negative();
    };
    if (finite) {
      if (last.mag < 1e-6 * scale && last.mag <= first.mag) {
        out.kind = SequenceCheck::Kind::Confirmed;
        out.note = "|f - L| = " + fmt(last.mag) + " at " + where;
        return out;
      }
      const double thr = 1e-3 * scale;
      if (certified_above(D, last.at, thr) && certified_above(D, prev.at, thr) &&
          certified_negative(step - numeric(thr / 100), both)) {
        out.kind = SequenceCheck::Kind::Contradicted;
        out.note = "f settles at a distance above " + fmt(thr) + " from the limit (|f - L| = " + fmt(last.mag) + " at " +
                   where + ", and f moves by less than " + fmt(thr / 100) + " from the previous point)";
        return out;
      }
      out.note = "|f - L| = " + fmt(last.mag) + " at " + where + ": not yet below 1e-6 (slow convergence?)";
      return out;
    }
    // infinite limit
    if (last.sign == want && last.mag > 1e6 && last.mag > first.mag) {
      out.kind = SequenceCheck::Kind::Confirmed;
      out.note = std::string("f = ") + (want < 0 ? "-" : "") + fmt(last.mag) + " at " + where;
      return out;
    }
    if (certified_negative(GiNaC::abs(D) - 1000000, last.at) && certified_negative(step - numeric(1, 1000), both)) {
      out.kind = SequenceCheck::Kind::Contradicted;
      out.note = "f settles at a finite value (|f| < 1e6 at " + where +
                 ", and f moves by less than 1e-3 from the previous point)";
      return out;
    }
    out.note = "|f| = " + fmt(last.mag) + " at " + where + ": divergence not yet evident (slow growth?)";
    return out;
  }
  out.note = last_problem;
  return out;
}

}  // namespace dc::limits
