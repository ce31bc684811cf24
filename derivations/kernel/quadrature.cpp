// Rigorous quadrature (see quadrature.hpp). The integrand is evaluated on complex balls so that
// Arb can bound the quadrature error by analyticity; every branch point or kink (log, roots,
// abs, asin/acos, atan) is checked against the ball when Arb asks for an analytic evaluation,
// and an evaluation that cannot certify analyticity returns an indeterminate ball (Arb then
// subdivides, or the enclosure stays wide and the verdict undecided).
#include "derivations/kernel/quadrature.hpp"

#include <acb.h>
#include <acb_calc.h>

#include <algorithm>

#include "derivations/symbolic/inspect.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/kernel/ball_impl.hpp"

namespace dc::kernel {

using GiNaC::ex;

namespace {

struct Acb {
  acb_t v;
  Acb() { acb_init(v); }
  ~Acb() { acb_clear(v); }
  Acb(const Acb&) = delete;
  Acb& operator=(const Acb&) = delete;
};

class ComplexEvaluator {
 public:
  ComplexEvaluator(const GiNaC::symbol& x, const acb_t z, bool analytic, slong prec)
      : x_(x), z_(z), analytic_(analytic), prec_(prec) {}

  // false: unsupported, or analyticity on the ball cannot be certified
  bool eval(const ex& e, acb_t out) {
    if (!e.has(x_)) {
      Ball b = enclose(e, prec_);
      if (b.status != BallStatus::Value) return false;
      acb_set_arb(out, b.impl->v);
      return true;
    }
    if (e.is_equal(x_)) {
      acb_set(out, z_);
      return true;
    }
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
      bool is_add = GiNaC::is_a<GiNaC::add>(e);
      acb_set_si(out, is_add ? 0 : 1);
      Acb t;
      for (std::size_t i = 0; i < e.nops(); ++i) {
        if (!eval(e.op(i), t.v)) return false;
        if (is_add) acb_add(out, out, t.v, prec_);
        else acb_mul(out, out, t.v, prec_);
      }
      return true;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      Acb b;
      if (!eval(e.op(0), b.v)) return false;
      const ex& k = e.op(1);
      if (GiNaC::is_a<GiNaC::numeric>(k) && GiNaC::ex_to<GiNaC::numeric>(k).is_integer() &&
          GiNaC::ex_to<GiNaC::numeric>(k).is_integer() && std::abs(GiNaC::ex_to<GiNaC::numeric>(k).to_long()) < 100000) {
        acb_pow_si(out, b.v, GiNaC::ex_to<GiNaC::numeric>(k).to_long(), prec_);
        return acb_is_finite(out);
      }
      Acb w;
      if (!eval(k, w.v)) return false;
      acb_pow_analytic(out, b.v, w.v, analytic_, prec_);
      return acb_is_finite(out);
    }
    if (!GiNaC::is_a<GiNaC::function>(e) || e.nops() != 1) return false;
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    Acb a;
    if (!eval(e.op(0), a.v)) return false;
    acb_t& z = a.v;
    if (name == "exp") acb_exp(out, z, prec_);
    else if (name == "log") acb_log_analytic(out, z, analytic_, prec_);
    else if (name == "sin") acb_sin(out, z, prec_);
    else if (name == "cos") acb_cos(out, z, prec_);
    else if (name == "tan") acb_tan(out, z, prec_);
    else if (name == "sinh") acb_sinh(out, z, prec_);
    else if (name == "cosh") acb_cosh(out, z, prec_);
    else if (name == "tanh") acb_tanh(out, z, prec_);
    else if (name == "abs") acb_real_abs(out, z, analytic_, prec_);
    else if (name == "atan" || name == "asin" || name == "acos") {
      // branch cuts: atan on the imaginary axis beyond +-i, asin/acos on the real axis beyond
      // +-1; analytic only when the ball stays clear of them
      if (analytic_) {
        arb_t t, one;
        arb_init(t);
        arb_init(one);
        arb_one(one);
        arb_abs(t, name == "atan" ? acb_imagref(z) : acb_realref(z));
        bool clear = arb_lt(t, one);
        arb_clear(t);
        arb_clear(one);
        if (!clear) return false;
      }
      if (name == "atan") acb_atan(out, z, prec_);
      else if (name == "asin") acb_asin(out, z, prec_);
      else acb_acos(out, z, prec_);
    } else {
      return false;
    }
    return acb_is_finite(out);
  }

 private:
  const GiNaC::symbol& x_;
  const acb_struct* z_;
  bool analytic_;
  slong prec_;
};

struct Integrand {
  const ex* f;
  const GiNaC::symbol* x;
};

int integrand(acb_ptr out, const acb_t inp, void* param, slong order, slong prec) {
  const Integrand* p = static_cast<const Integrand*>(param);
  bool ok = false;
  try {
    ComplexEvaluator ev(*p->x, inp, order == 1, prec);
    ok = ev.eval(*p->f, out);
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok) acb_indeterminate(out);
  return 0;
}

}  // namespace

Ball integrate_constant(const ex& f, const GiNaC::symbol& x, const ex& a, const ex& b, long prec_bits) {
  Ball out;
  out.prec_bits = prec_bits;
  Ball ba = enclose(a, prec_bits), bb = enclose(b, prec_bits);
  if (ba.status != BallStatus::Value || bb.status != BallStatus::Value) {
    out.status = BallStatus::Unknown;
    out.why = "a limit of integration cannot be evaluated";
    return out;
  }
  Acb A, B, res;
  acb_set_arb(A.v, ba.impl->v);
  acb_set_arb(B.v, bb.impl->v);
  Integrand p{&f, &x};
  acb_calc_integrate_opt_t options;
  acb_calc_integrate_opt_init(options);
  options->eval_limit = 200000;   // a budget: beyond it the enclosure stays wide (undecided)
  mag_t tol;
  mag_init(tol);
  mag_set_ui_2exp_si(tol, 1, -prec_bits);
  acb_calc_integrate(res.v, integrand, &p, A.v, B.v, prec_bits, tol, options, prec_bits);
  mag_clear(tol);
  if (!acb_is_finite(res.v)) {
    out.status = BallStatus::Unknown;
    out.why = "the integrand is not analytic near the path of integration, or not supported";
    return out;
  }
  if (!arb_contains_zero(acb_imagref(res.v))) {
    out.status = BallStatus::NotReal;
    out.why = "the integrand is not real on the interval";
    return out;
  }
  arb_set(out.impl->v, acb_realref(res.v));
  out.status = BallStatus::Value;
  return out;
}

Verdict probe_definite_integral(const ex& f, const GiNaC::symbol& x, const ex& a, const ex& b, const ex& G,
                                const SymbolTable& ctx, const ProveOptions& opt) {
  using K = PointComparison::Kind;
  Verdict v;
  v.method = "rigorous quadrature";
  GiNaC::realsymbol dummy("dc_quadrature_dummy");
  ex f0 = f.subs(x == dummy, GiNaC::subs_options::no_pattern);
  detail::PointSampler sampler({a, b, G, f0}, ctx);
  detail::Rng rng(opt.seed ^ 0x1D7E6A11ull);
  const int need = std::max(1, opt.probe_points);
  int agreed = 0, attempts = 0, unusable = 0, integral_failures = 0;
  double max_rel = 0;
  std::string why, failed_at;
  // The integral and the closed form at a parameter point; `unknown` when the integral could
  // not be enclosed, `usable` false when the point could not be substituted.
  auto evaluate = [&](const GiNaC::exmap& p, bool& usable, bool& unknown) {
    PointComparison c;
    usable = true;
    unknown = false;
    ex fp, ap, bp, Gp;
    try {
      fp = f.subs(p, GiNaC::subs_options::no_pattern);
      ap = a.subs(p, GiNaC::subs_options::no_pattern);
      bp = b.subs(p, GiNaC::subs_options::no_pattern);
      Gp = G.subs(p, GiNaC::subs_options::no_pattern);
    } catch (const std::exception&) {
      usable = false;
      return c;
    }
    for (long prec = 160; prec <= 640; prec *= 2) {
      Ball I = integrate_constant(fp, x, ap, bp, prec);
      if (I.status == BallStatus::Unknown) {
        // Not finite (a singularity near the path, or the evaluation budget ran out): more
        // precision does not help, and another point rarely does (1/x from -1 to b).
        unknown = true;
        c.kind = K::Unknown;
        c.why = "lhs: " + I.why;
        break;
      }
      Ball g = enclose(Gp, prec);
      c = compare_balls(std::move(I), std::move(g), std::lround(opt.rel_tol_exponent));
      c.digits = prec * 3 / 10;
      if (c.kind != K::Unknown) break;
    }
    return c;
  };
  auto differs = [](const PointComparison& c) { return c.kind == K::Differ || c.kind == K::LhsOnly || c.kind == K::RhsOnly; };
  auto refute = [&](const PointComparison& c, const GiNaC::exmap& p) {
    v.kind = VerdictKind::Refuted;
    std::vector<std::pair<std::string, std::string>> pt;
    for (const auto& [name, value] : sampler.describe(p))
      if (name != "dc_quadrature_dummy") pt.push_back({name, value});
    v.point = pt;
    v.lhs_value = c.lhs_text();
    v.rhs_value = c.rhs_text();
    v.digits = static_cast<int>(c.digits);
    v.max_rel_diff = c.rel_diff;
    v.detail = "the integral (rigorous quadrature) = " + c.lhs_text() + ", the closed form = " + c.rhs_text();
    return v;
  };
  for (; attempts < need * 20 && agreed < need; ++attempts) {
    bool admissible = false;
    GiNaC::exmap p = sampler.draw(rng, attempts % 6 == 5 ? 1 : 0, &admissible);
    p.erase(dummy);
    if (!admissible) {
      ++unusable;
      continue;
    }
    bool usable = true, integral_unknown = false;
    const PointComparison c = evaluate(p, usable, integral_unknown);
    if (!usable) {
      ++unusable;
      continue;
    }
    if (c.kind == K::Agree) {
      ++agreed;
      max_rel = std::max(max_rel, c.rel_diff);
      continue;
    }
    if (differs(c)) return refute(c, p);
    ++unusable;
    if (why.empty()) why = c.why;
    if (integral_unknown && integral_failures == 0) {
      for (const auto& [name, value] : sampler.describe(p))
        if (name != "dc_quadrature_dummy") failed_at += (failed_at.empty() ? "" : ", ") + name + " = " + value;
    }
    if (integral_unknown && ++integral_failures >= 3 && agreed == 0) break;
  }
  // After agreement, special values where formulas degenerate (a closed end of a declared
  // domain, 0 of a real symbol), one symbol at a time: they can only refute
  // (integral(a/(a^2 + x^2), x, 0, 1) = pi/2 - atan(a) fails at a = 0 only).
  if (agreed >= need && integral_failures == 0) {
    std::vector<std::pair<ex, ex>> specials;
    for (const auto& sym : sampler.symbols()) {
      if (sym.is_equal(dummy)) continue;
      const Domain dom = detail::domain_of(sym, ctx);
      if (dom.kind == Domain::Kind::Real || dom.kind == Domain::Kind::Nonnegative) specials.push_back({sym, 0});
      if (dom.kind == Domain::Kind::Interval && !dom.integer) {
        if (!dom.lo_open) specials.push_back({sym, dom.lo});
        if (!dom.hi_open) specials.push_back({sym, dom.hi});
      }
    }
    for (std::size_t k = 0; k < specials.size() && k < 6; ++k) {
      bool admissible = false;
      GiNaC::exmap p = sampler.draw(rng, 0, &admissible);
      p.erase(dummy);
      p[specials[k].first] = specials[k].second;
      admissible = true;
      for (const Constraint* cons : sampler.constraints()) admissible = admissible && kernel::holds_at(*cons, p);
      if (!admissible) continue;
      bool usable = true, unknown = false;
      const PointComparison c = evaluate(p, usable, unknown);
      if (usable && differs(c)) return refute(c, p);
    }
  }
  // An admissible point where the integral could not be enclosed (a singularity on the path:
  // the integral may diverge there) means the closed form is not shown to hold on the whole
  // domain, however many other points agree.
  if (integral_failures > 0) {
    v.kind = VerdictKind::Undecided;
    v.reason = "rigorous quadrature could not enclose the integral at an admissible point" +
               (failed_at.empty() ? std::string() : " (" + failed_at + ")") +
               ": it may diverge there (a singularity on the path of integration)" + (why.empty() ? "" : "; " + why) +
               (agreed ? "; " + std::to_string(agreed) + " other points agree" : "");
    v.detail = v.reason;
    return v;
  }
  if (agreed >= need) {
    v.kind = VerdictKind::HoldsNumerically;
    v.points = agreed;
    v.digits = 48;
    v.max_rel_diff = max_rel;
    v.false_accept = "< 1e-6 per point (a nonzero difference of analytic functions of the parameters vanishes on a "
                     "null set; heuristic), each integral enclosed rigorously";
    v.detail = std::to_string(agreed) + " parameter points: the rigorous quadrature agrees with the closed form";
    return v;
  }
  v.kind = VerdictKind::Undecided;
  v.reason = "rigorous quadrature could not decide at enough points (" + std::to_string(agreed) + " of " +
             std::to_string(need) + ")" + (why.empty() ? "" : ": " + why);
  v.detail = v.reason;
  return v;
}

}  // namespace dc::kernel
