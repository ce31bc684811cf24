// Truncated generalized power series in w (w -> 0+), the expansion step of Gruntz's algorithm.
//
//   s = c_1 w^e_1 + c_2 w^e_2 + ... + O(w^order),   e_1 < e_2 < ... < order
//
// Exponents are real constants (rationals, or expressions such as log(5)/log(3)); coefficients
// are expressions free of w that may still contain the limit variable x (which varies more
// slowly than any power of w as x -> oo) and parameters. log(w) never appears: it is replaced
// by `logw`, an expression in x (Gruntz's rewriting fixes it).
//
// Which coefficients vanish, which exponent is smaller and what sign a coefficient has as
// x -> oo are not decided here: the expander asks an Oracle (the Gruntz engine), which decides
// them from the declarations and rigorous evaluation, or throws Undecided.
#pragma once
#include <functional>
#include <map>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/limit_engine/budget.hpp"

namespace dc::limits {

struct Term {
  GiNaC::ex exp;    // real constant
  GiNaC::ex coeff;  // free of w, not syntactically 0
};

struct WSeries {
  std::vector<Term> terms;  // strictly increasing exponents
  bool exact = false;       // no remainder (a polynomial in powers of w)
  GiNaC::ex order;          // !exact: the remainder is O(w^order)

  static WSeries zero() { WSeries s; s.exact = true; return s; }
  static WSeries monomial(const GiNaC::ex& c, const GiNaC::ex& e) {
    WSeries s = zero();
    if (!c.is_zero()) s.terms.push_back({e, c});
    return s;
  }
};

// The questions the expansion cannot answer on its own (implemented by the Gruntz engine).
class Oracle {
 public:
  virtual ~Oracle() = default;
  // -1, 0, +1 for a < b, a = b, a > b (real constants); throws Undecided.
  virtual int compare_exponents(const GiNaC::ex& a, const GiNaC::ex& b) = 0;
  // Whether a coefficient vanishes identically (as a function of x and the parameters);
  // throws Undecided when neither can be shown.
  virtual bool coefficient_is_zero(const GiNaC::ex& c) = 0;
  // The sign of a coefficient for all large x (+1 or -1; 0 when identically zero); throws
  // Undecided (e.g. the sign of a parameter expression the declarations do not fix).
  virtual int eventual_sign(const GiNaC::ex& c) = 0;
  // lim c as x -> oo.
  virtual LimitValue limit_of(const GiNaC::ex& c) = 0;
  virtual Budget& budget() = 0;
};

class SeriesExpander {
 public:
  // w: the positive symbol; x: the limit variable (only to recognise coefficients);
  // logw: what log(w) stands for; relative_order: every series keeps the terms up to
  // w^(e + relative_order), e its first exponent (the rest is its O-term).
  SeriesExpander(Oracle& oracle, const GiNaC::ex& w, const GiNaC::ex& x, const GiNaC::ex& logw, long relative_order);

  // The series of e. Throws NeedMoreTerms (raise the cutoff), Undecided, Oscillates, NotRealNear.
  WSeries expand(const GiNaC::ex& e);

  // Drops leading coefficients that vanish identically; true when a nonzero leading term
  // remains (then s.terms[0] is it), false when s is exactly 0; throws NeedMoreTerms when
  // every known term vanished but the remainder is not known to be 0.
  bool settle_lead(WSeries& s);

 private:
  Oracle& o_;
  GiNaC::ex w_, x_, logw_;
  long rel_;
  std::map<GiNaC::ex, WSeries, GiNaC::ex_is_less> memo_;

  int cmp(const GiNaC::ex& a, const GiNaC::ex& b);
  GiNaC::ex min_order(const GiNaC::ex& a, const GiNaC::ex& b);
  void insert_term(std::vector<Term>& v, const GiNaC::ex& e, const GiNaC::ex& c);
  WSeries finish(WSeries s);
  GiNaC::ex low_valuation(const WSeries& s);   // a lower bound of the valuation

  WSeries add(const WSeries& a, const WSeries& b);
  WSeries mul(const WSeries& a, const WSeries& b);
  WSeries scale(const WSeries& a, const GiNaC::ex& c, const GiNaC::ex& e);   // c w^e * a
  // sum_k d(k) r^k for r of positive valuation.
  WSeries compose(const std::function<GiNaC::ex(int)>& d, const WSeries& r);
  // s = c0 w^e0 (1 + r): returns r (and c0, e0); s must have a settled leading term.
  WSeries split_lead(const WSeries& s, GiNaC::ex& c0, GiNaC::ex& e0);

  WSeries inverse(WSeries s);
  WSeries power(WSeries s, const GiNaC::ex& p);
  WSeries exp_of(WSeries s);
  WSeries log_of(WSeries s);
  WSeries abs_of(WSeries s);
  WSeries function_of(const GiNaC::ex& e, WSeries s);

  WSeries expand_uncached(const GiNaC::ex& e);
  void require_real(const GiNaC::ex& coefficient);
};

}  // namespace dc::limits
