// Gruntz's algorithm: limits of exp-log functions as x -> +oo (D. Gruntz, "On Computing
// Limits in a Symbolic Manipulation System", ETH Zurich 1996).
//
//   1. mrv(f): the set of most rapidly varying subexpressions of f (x itself or exponentials
//      exp(g) with g -> +-oo), compared by lim log(a)/log(b);
//   2. if x is among them, replace x by exp(x) (same limit) and start again;
//   3. pick w in the mrv class with w -> 0 and rewrite every element as exp(h) w^c, h of a
//      lower class;
//   4. expand in w: f = c0 w^e0 + ... (wseries.hpp); e0 > 0: 0, e0 < 0: +-oo with the sign
//      of c0, e0 = 0: the limit of c0 (which is of lower class: recursion).
//
// Signs of parameter expressions (log(e) for e in (0, 1)) come from the declared domains;
// whether a series coefficient vanishes is shown symbolically (normal, the prove cascade) or
// refuted by a rigorous Arb evaluation at one point. Whatever cannot be shown throws
// Undecided with the question; nothing is assumed. sin, cos and atan with an argument that
// has a finite limit are expanded as analytic functions; sin/cos of an argument that tends
// to infinity throw Oscillates (handled by the caller, oscillation.cpp).
#pragma once
#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"
#include "derivations/limit_engine/budget.hpp"
#include "derivations/limit_engine/wseries.hpp"

namespace dc::limits {

// Rewrites f (a function of the positive symbol x) into the form the algorithm works on:
// powers with a variable exponent become exp(p log b), powers of exp are merged into it,
// hyperbolic functions and their inverses
// are written with exp and log. Throws Undecided for functions outside exp-log-trig.
GiNaC::ex make_tractable(const GiNaC::ex& f, const GiNaC::ex& x);

class Gruntz : public Oracle {
 public:
  // x: a GiNaC::possymbol, the variable that tends to +oo. ctx: the declarations of the
  // parameters (every other symbol).
  Gruntz(const GiNaC::ex& x, const SymbolTable& ctx, Budget& budget);

  // lim f as x -> +oo; f must be in make_tractable form.
  LimitValue limit(const GiNaC::ex& f);
  // The sign of f for all large x (+1, -1, or 0 when f vanishes there identically).
  int sign(const GiNaC::ex& f);
  // The sign of an x-free expression from the declarations and rigorous evaluation.
  int constant_sign(const GiNaC::ex& c);

  // Oracle (the series expander's questions)
  int compare_exponents(const GiNaC::ex& a, const GiNaC::ex& b) override;
  bool coefficient_is_zero(const GiNaC::ex& c) override;
  int eventual_sign(const GiNaC::ex& c) override { return sign(c); }
  LimitValue limit_of(const GiNaC::ex& c) override { return limit(c); }
  Budget& budget() override { return b_; }

  const GiNaC::ex& variable() const { return x_; }

 private:
  struct Lead {
    GiNaC::ex c0, e0;   // f ~ c0 w^e0 (c0 may contain x: it is of lower class than w)
  };
  Lead leadterm(const GiNaC::ex& f);

  // mrv.cpp
  std::vector<GiNaC::ex> mrv(const GiNaC::ex& f);
  std::vector<GiNaC::ex> mrv_max(const std::vector<GiNaC::ex>& a, const std::vector<GiNaC::ex>& b);
  int compare_classes(const GiNaC::ex& f, const GiNaC::ex& g);   // -1: f < g, 0: same class, +1: f > g
  GiNaC::ex moveup(const GiNaC::ex& f);
  // f with the mrv set omega expressed through w (w -> 0+); sets logw to what log(w) is.
  GiNaC::ex rewrite(const GiNaC::ex& f, const std::vector<GiNaC::ex>& omega, const GiNaC::ex& w, GiNaC::ex& logw);

  std::string text(const GiNaC::ex& e) const;

  GiNaC::ex x_;
  const SymbolTable& ctx_;
  Budget& b_;
  std::map<GiNaC::ex, LimitValue, GiNaC::ex_is_less> limit_cache_;
  std::map<GiNaC::ex, int, GiNaC::ex_is_less> sign_cache_, const_sign_cache_, zero_cache_;
  std::map<GiNaC::ex, std::vector<GiNaC::ex>, GiNaC::ex_is_less> mrv_cache_;
};

}  // namespace dc::limits
