// Can the assumptions hold? (see satisfiable.hpp)
#include "derivations/decide/satisfiable.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include <cln/rational.h>
#include <cln/real.h>

#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/kernel/sample.hpp"

namespace dc {

namespace {

using GiNaC::ex;
using GiNaC::numeric;
using Op = Constraint::Op;

constexpr int kTries = 2000;
constexpr int kMaxExponent = 300;   // magnitudes 1e-300 .. 1e300

using detail::collect_symbols;
using detail::pow10;

bool has_symbol_or_application(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e) || detail::is_abstract_application(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_symbol_or_application(e.op(i))) return true;
  return false;
}

std::string quoted(const Constraint& c) { return "'" + c.text + "'"; }

// Float evaluation of a constant is trusted only when no exp or trigonometric function has an
// argument too large for the working precision (GiNaC/CLN return 1.0 for exp(1e300) and 0.0
// for sin(1e300)). The rigorous kernel will replace this with ball arithmetic.
bool evaluation_trustworthy(const ex& e, long digits) {
  // Operands first: evaluating x^(y^z) as a whole when y^z is astronomic asks CLN to round a
  // float of about 10^(10^12) to an integer (an 855 GB allocation).
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!evaluation_trustworthy(e.op(i), digits)) return false;
  if (GiNaC::is_a<GiNaC::function>(e)) {
    std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    bool big_exp = name == "exp" || name == "sinh" || name == "cosh";
    bool trig = name == "sin" || name == "cos" || name == "tan";
    if (big_exp || trig) {
      ex a;
      try {
        DigitsGuard g(30);
        a = e.op(0).evalf();
      } catch (const std::exception&) {
        return false;
      }
      if (!GiNaC::is_a<numeric>(a)) return false;
      numeric m = GiNaC::abs(GiNaC::ex_to<numeric>(a));
      if (big_exp && m > numeric(100000)) return false;
      if (trig && m > pow10(static_cast<int>(digits / 3))) return false;
    }
  }
  if (GiNaC::is_a<GiNaC::power>(e) && !GiNaC::is_a<numeric>(e.op(1))) {
    // x^y with a symbolic exponent: evaluated as exp(y log x)
    try {
      DigitsGuard g(30);
      ex a = (e.op(1) * GiNaC::log(GiNaC::abs(e.op(0)))).evalf();
      if (!GiNaC::is_a<numeric>(a) || GiNaC::abs(GiNaC::ex_to<numeric>(a)) > numeric(100000)) return false;
    } catch (const std::exception&) {
      return false;
    }
  }
  return true;
}

// The sign of a constant expression: exact for rationals; otherwise evaluated at 60 and 200
// digits and trusted only when both agree. not_real: the value is not a real number.
struct ConstSign {
  bool decided = false;
  bool not_real = false;
  int sign = 0;
};

ConstSign constant_sign(const ex& d) {
  ConstSign out;
  if (GiNaC::is_a<numeric>(d)) {
    const numeric& n = GiNaC::ex_to<numeric>(d);
    if (!n.is_real()) {
      out.decided = out.not_real = true;
      return out;
    }
    if (n.is_rational()) {
      out.decided = true;
      out.sign = n.is_zero() ? 0 : (n.is_positive() ? 1 : -1);
      return out;
    }
  }
  if (!evaluation_trustworthy(d, 200)) return out;
  numeric v[2];
  const long digits[2] = {60, 200};
  for (int k = 0; k < 2; ++k) {
    ex e;
    try {
      DigitsGuard g(digits[k]);
      e = d.evalf();
    } catch (const std::exception&) {
      out.decided = out.not_real = true;   // undefined (1/0, log(0)): not a real number
      return out;
    }
    if (!GiNaC::is_a<numeric>(e)) return out;
    numeric n = GiNaC::ex_to<numeric>(e);
    if (!n.is_real()) {
      if (GiNaC::abs(n.imag()) > GiNaC::abs(n.real()) * pow10(static_cast<int>(-(digits[k] - 15))) &&
          GiNaC::abs(n.imag()) > pow10(static_cast<int>(-(digits[k] - 15)))) {
        if (k == 1) {
          out.decided = out.not_real = true;
          return out;
        }
      }
      n = n.real();
    }
    v[k] = n;
  }
  // rounding level at 200 digits; an exact zero was caught above (rational)
  if (v[1].is_zero() || GiNaC::abs(v[1]) < pow10(-150)) return out;
  if (v[0].is_positive() != v[1].is_positive()) return out;
  if (GiNaC::abs(v[0] - v[1]) > GiNaC::abs(v[1]) * pow10(-20)) return out;
  out.decided = true;
  out.sign = v[1].is_positive() ? 1 : -1;
  return out;
}

std::optional<int> compare(const ex& a, const ex& b) {
  ConstSign s = constant_sign(a - b);
  if (!s.decided || s.not_real) return std::nullopt;
  return s.sign;
}

// --- exact analysis of single-symbol linear constraints -------------------------------------

struct Bound {
  bool inf = true;
  ex value;
  bool open = true;
};

struct Feasible {
  Bound lo, hi;
  std::vector<ex> excluded;                  // x != value
  std::vector<const Constraint*> linear;     // the constraints that shaped it
  bool exact = true;                         // false when a comparison could not be decided
};

Feasible from_domain(const Domain& d) {
  Feasible f;
  using K = Domain::Kind;
  switch (d.kind) {
    case K::Real: break;
    case K::Positive: f.lo = {false, 0, true}; break;
    case K::Nonnegative: f.lo = {false, 0, false}; break;
    case K::Negative: f.hi = {false, 0, true}; break;
    case K::Interval:
      f.lo = {false, d.lo, d.lo_open};
      f.hi = {false, d.hi, d.hi_open};
      break;
  }
  return f;
}

void tighten(Feasible& f, bool lower, const ex& v, bool open) {
  Bound& b = lower ? f.lo : f.hi;
  if (b.inf) {
    b = {false, v, open};
    return;
  }
  auto c = compare(v, b.value);
  if (!c) {
    f.exact = false;
    return;
  }
  int tighter = lower ? *c : -*c;
  if (tighter > 0 || (tighter == 0 && open)) b = {false, v, open};
}

// Empty? nullopt when undecided.
std::optional<bool> empty(const Feasible& f) {
  if (!f.exact) return std::nullopt;
  if (f.lo.inf || f.hi.inf) return false;
  auto c = compare(f.lo.value, f.hi.value);
  if (!c) return std::nullopt;
  if (*c > 0) return true;
  if (*c < 0) return false;
  if (f.lo.open || f.hi.open) return true;
  for (const ex& x : f.excluded) {
    auto e = compare(x, f.lo.value);
    if (!e) return std::nullopt;
    if (*e == 0) return true;
  }
  return false;
}

// a*x + b OP 0 with a, b constants: the constraint restated as x OP' t. nullopt when the
// constraint is not of that form (or the sign of a is not decided).
struct Linear {
  ex sym;
  Op op;
  ex t;
};

std::optional<Linear> single_symbol_linear(const Constraint& c) {
  ex d;
  try {
    d = (c.lhs - c.rhs).expand();
  } catch (const std::exception&) {
    return std::nullopt;
  }
  GiNaC::exset syms;
  collect_symbols(d, syms);
  if (syms.size() != 1 || detail::has_abstract_application(d)) return std::nullopt;
  ex x = *syms.begin();
  const GiNaC::symbol& xs = GiNaC::ex_to<GiNaC::symbol>(x);
  if (!d.is_polynomial(xs) || d.degree(xs) != 1) return std::nullopt;
  ex a = d.coeff(xs, 1), b = d.coeff(xs, 0);
  if (has_symbol_or_application(a) || has_symbol_or_application(b)) return std::nullopt;
  ConstSign sa = constant_sign(a);
  if (!sa.decided || sa.not_real || sa.sign == 0) return std::nullopt;
  ConstSign sb = constant_sign(b);
  if (sb.not_real) return std::nullopt;
  Linear l;
  l.sym = x;
  l.op = sa.sign > 0 ? c.op : flipped(c.op);
  l.t = GiNaC::normal(-b / a);
  return l;
}

// --- pairs whose sum or ratio is a contradictory constant ------------------------------------

// c as p > 0 (strict) or p >= 0; nullopt for !=.
std::optional<std::pair<ex, bool>> oriented(const Constraint& c) {
  switch (c.op) {
    case Op::Gt: return std::make_pair(c.lhs - c.rhs, true);
    case Op::Ge: return std::make_pair(c.lhs - c.rhs, false);
    case Op::Lt: return std::make_pair(c.rhs - c.lhs, true);
    case Op::Le: return std::make_pair(c.rhs - c.lhs, false);
    case Op::Ne: return std::nullopt;
  }
  return std::nullopt;
}

std::string pair_contradiction(const Constraint& a, const Constraint& b) {
  auto pa = oriented(a), pb = oriented(b);
  if (!pa || !pb) return "";
  bool strict = pa->second || pb->second;
  try {
    ex sum = GiNaC::normal(pa->first + pb->first);
    if (!has_symbol_or_application(sum)) {
      ConstSign s = constant_sign(sum);
      if (s.decided && !s.not_real && (s.sign < 0 || (s.sign == 0 && strict))) {
        std::ostringstream os;
        os << sum;
        return "the assumptions " + quoted(a) + " and " + quoted(b) + " cannot both hold: adding them gives " +
               os.str() + (strict ? " > 0" : " >= 0");
      }
    }
    ex ratio = GiNaC::normal(pb->first / pa->first);
    if (!has_symbol_or_application(ratio)) {
      ConstSign s = constant_sign(ratio);
      if (s.decided && !s.not_real && s.sign < 0 && strict)
        return "the assumptions " + quoted(a) + " and " + quoted(b) +
               " cannot both hold: one side of each is a negative multiple of the other's";
    }
  } catch (const std::exception&) {
  }
  return "";
}

// --- the search -------------------------------------------------------------------------------

// An exact rational close to x (a CLN float or rational).
numeric to_rational(const numeric& x) {
  if (x.is_rational()) return x;
  cln::cl_R r = cln::the<cln::cl_R>(x.to_cl_N());
  return numeric(cln::cl_N(cln::rational(r)));
}

std::optional<numeric> numeric_value(const ex& e) {
  if (GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_rational()) return GiNaC::ex_to<numeric>(e);
  if (!evaluation_trustworthy(e, 60)) return std::nullopt;
  try {
    DigitsGuard g(60);
    ex v = e.evalf();
    if (!GiNaC::is_a<numeric>(v) || !GiNaC::ex_to<numeric>(v).is_real()) return std::nullopt;
    return to_rational(GiNaC::ex_to<numeric>(v));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Does c hold at p? Exact when the difference is rational there; otherwise evaluated at 60 and
// 120 digits and trusted only when both agree clearly.
bool holds_surely(const Constraint& c, const GiNaC::exmap& p) {
  ex d;
  try {
    d = detail::subs_point(c.lhs - c.rhs, p);
  } catch (const std::exception&) {
    return false;
  }
  if (has_symbol_or_application(d)) return false;
  if (GiNaC::is_a<numeric>(d)) {
    const numeric& n = GiNaC::ex_to<numeric>(d);
    if (!n.is_real()) return false;
    if (n.is_rational()) return sign_satisfies(c.op, n.is_zero() ? 0 : (n.is_positive() ? 1 : -1));
  }
  if (!evaluation_trustworthy(d, 60)) return false;
  numeric v[2];
  const long digits[2] = {60, 120};
  for (int k = 0; k < 2; ++k) {
    try {
      DigitsGuard g(digits[k]);
      ex e = d.evalf();
      if (!GiNaC::is_a<numeric>(e)) return false;
      const numeric& n = GiNaC::ex_to<numeric>(e);
      if (!n.is_real()) return false;
      v[k] = n;
    } catch (const std::exception&) {
      return false;
    }
  }
  if (v[1].is_zero() || GiNaC::abs(v[0] - v[1]) > GiNaC::abs(v[1]) * pow10(-20)) return false;
  if (v[0].is_positive() != v[1].is_positive()) return false;
  return sign_satisfies(c.op, v[1].is_positive() ? 1 : -1);
}

// A random exact rational m * 10^e with 1 <= |m| < 10 not an integer (so powers with sampled
// exponents stay algebraic); e uniform in [lo_exp, hi_exp].
numeric random_magnitude(detail::Rng& rng, int lo_exp, int hi_exp) {
  int e = lo_exp + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi_exp - lo_exp + 1)));
  numeric q = numeric(static_cast<long>(1009 + rng.below(98983)));
  numeric m = numeric(static_cast<long>(1000 + rng.below(9000)), 1000) + numeric(1) / q;
  return m * pow10(e);
}

enum class Spread { Narrow, Mid, Wide };

void exponent_range(Spread s, int& lo, int& hi) {
  switch (s) {
    case Spread::Narrow: lo = -2; hi = 1; return;
    case Spread::Mid: lo = -6; hi = 5; return;
    case Spread::Wide: lo = -kMaxExponent; hi = kMaxExponent - 1; return;
  }
}

// A value from a feasible set (its bounds are exact constants).
std::optional<numeric> draw_from(const Feasible& f, detail::Rng& rng, Spread s) {
  int lo_e, hi_e;
  exponent_range(s, lo_e, hi_e);
  std::optional<numeric> lo, hi;
  if (!f.lo.inf) lo = numeric_value(f.lo.value);
  if (!f.hi.inf) hi = numeric_value(f.hi.value);
  if ((!f.lo.inf && !lo) || (!f.hi.inf && !hi)) return std::nullopt;
  if (lo && hi) {
    numeric w = *hi - *lo;
    if (!w.is_positive()) return *lo;   // a single point [a, a]
    numeric t;
    if (s == Spread::Wide && rng.below(2)) {
      // close to one end: w * 10^-k
      numeric off = w * random_magnitude(rng, -kMaxExponent, -1) / 10;
      return rng.below(2) ? *lo + off : *hi - off;
    }
    t = numeric(static_cast<long>(1 + rng.below(999998)), 1000000);
    return *lo + w * t;
  }
  numeric m = random_magnitude(rng, lo_e, hi_e);
  if (lo) return *lo + m;
  if (hi) return *hi - m;
  return rng.below(2) ? m : -m;
}

class Search {
 public:
  Search(const SymbolTable& ctx, std::vector<const Constraint*> cons, std::vector<ex> syms,
         std::vector<Feasible> feas, std::uint64_t seed)
      : ctx_(ctx), cons_(std::move(cons)), syms_(std::move(syms)), feas_(std::move(feas)), rng_(seed),
        held_(cons_.size(), 0) {}

  bool run(int tries, GiNaC::exmap& found) {
    for (int i = 0; i < tries; ++i) {
      Spread s = i < 100 ? (i % 2 ? Spread::Mid : Spread::Narrow)
                         : (i % 3 == 0 ? Spread::Mid : Spread::Wide);
      GiNaC::exmap p;
      if (!draw(s, p)) continue;
      if (admissible(p, true)) {
        found = p;
        return true;
      }
      if (i % 2 == 1 && repair(p) && admissible(p, false)) {
        found = p;
        return true;
      }
    }
    return false;
  }

  const std::vector<int>& held() const { return held_; }

 private:
  const SymbolTable& ctx_;
  std::vector<const Constraint*> cons_;
  std::vector<ex> syms_;
  std::vector<Feasible> feas_;
  detail::Rng rng_;
  std::vector<int> held_;

  bool draw(Spread s, GiNaC::exmap& p) {
    for (std::size_t i = 0; i < syms_.size(); ++i) {
      auto v = draw_from(feas_[i], rng_, s);
      if (!v) return false;
      p[syms_[i]] = integer(i) ? nearest_integer(*v) : *v;
    }
    return true;
  }

  bool integer(std::size_t i) const { return detail::domain_of(syms_[i], ctx_).integer; }
  static numeric nearest_integer(const numeric& v) {
    return numeric(cln::floor1(cln::the<cln::cl_R>((v + numeric(1, 2)).to_cl_N())));
  }

  bool in_domain(std::size_t i, const numeric& v) const {
    return detail::domain_of(syms_[i], ctx_).contains(v);
  }

  bool admissible(const GiNaC::exmap& p, bool count) {
    for (std::size_t i = 0; i < syms_.size(); ++i) {
      auto it = p.find(syms_[i]);
      if (it == p.end() || !in_domain(i, GiNaC::ex_to<numeric>(it->second))) return false;
    }
    bool all = true;
    for (std::size_t j = 0; j < cons_.size(); ++j) {
      bool h = holds_surely(*cons_[j], p);
      if (h && count) ++held_[j];
      if (!h) {
        all = false;
        if (!count) return false;
      }
    }
    return all;
  }

  // Move one symbol of each violated constraint just beyond the constraint's boundary: for a
  // constraint linear in symbol s (s alone on one side is the common case), s = t + offset with
  // the boundary t computed from the other symbols and a relative or absolute offset.
  bool repair(GiNaC::exmap& p) {
    bool changed = false;
    for (int round = 0; round < 4; ++round) {
      bool any = false;
      for (const Constraint* c : cons_) {
        if (holds_surely(*c, p)) continue;
        any = true;
        changed = move_beyond(*c, p) || changed;
      }
      if (!any) break;
    }
    return changed;
  }

  bool move_beyond(const Constraint& c, GiNaC::exmap& p) {
    // candidates: symbols in which c is linear, a symbol alone on one side first
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < syms_.size(); ++i)
      if (c.lhs.is_equal(syms_[i]) || c.rhs.is_equal(syms_[i])) order.push_back(i);
    for (std::size_t i = 0; i < syms_.size(); ++i)
      if (std::find(order.begin(), order.end(), i) == order.end()) order.push_back(i);
    for (std::size_t i : order) {
      auto bound = detail::linear_bound(c, syms_[i], p, numeric_value);
      if (!bound) continue;
      const numeric& t = bound->at;
      const Op op = bound->op;
      // direction: +1 above the boundary, -1 below
      int dir = 0;
      if (op == Op::Gt || op == Op::Ge) dir = 1;
      else if (op == Op::Lt || op == Op::Le) dir = -1;
      else dir = rng_.below(2) ? 1 : -1;
      numeric off;
      if ((op == Op::Ge || op == Op::Le) && rng_.below(4) == 0)
        off = 0;   // on the boundary: x >= y, y >= x holds only at x = y
      else if (rng_.below(2) && !t.is_zero())
        off = GiNaC::abs(t) * random_magnitude(rng_, -15, -1) / 10;   // relative
      else
        off = random_magnitude(rng_, -kMaxExponent, kMaxExponent - 1);  // absolute
      numeric v = t + dir * off;
      if (integer(i)) v = off.is_zero() ? nearest_integer(t) : dir > 0 ? nearest_integer(v) + 1 : nearest_integer(v) - 1;
      if (!in_domain(i, v)) continue;
      p[syms_[i]] = v;
      return true;
    }
    return false;
  }
};

}  // namespace

ConstantTruth constant_truth(const Constraint& c) {
  ex d;
  try {
    d = GiNaC::normal(c.lhs - c.rhs);
  } catch (const std::exception&) {
    return ConstantTruth::False;   // e.g. a division by zero in a constant
  }
  if (has_symbol_or_application(d)) return ConstantTruth::NotConstant;
  ConstSign s = constant_sign(d);
  if (!s.decided) return ConstantTruth::Undecidable;
  if (s.not_real) return ConstantTruth::False;
  return sign_satisfies(c.op, s.sign) ? ConstantTruth::True : ConstantTruth::False;
}

void require_possible_assumption(const Constraint& c, int length) {
  switch (constant_truth(c)) {
    case ConstantTruth::False:
      throw InputError(c.pos, "the assumption '" + c.text + "' can never hold", std::max(1, length));
    case ConstantTruth::Undecidable:
      throw InputError(c.pos,
                       "the assumption '" + c.text +
                           "' compares two constants whose order cannot be decided (they agree to 200 digits)",
                       std::max(1, length));
    default: return;
  }
}

Satisfiability decide_satisfiable(const SymbolTable& ctx, std::uint64_t seed) {
  Satisfiability out;
  auto unsat = [&](std::string why) {
    out.status = Satisfiability::Status::Unsatisfiable;
    out.reason = std::move(why);
    return out;
  };
  for (const auto& s : ctx.all())
    if (s.domain.empty()) return unsat("the domain '" + s.domain.to_string() + "' of '" + s.name + "' is empty");
  // constant relations: decided on their own; true ones have no effect
  std::vector<const Constraint*> cons;
  for (const auto& c : ctx.constraints()) {
    switch (constant_truth(c)) {
      case ConstantTruth::False: return unsat("the assumption " + quoted(c) + " can never hold");
      case ConstantTruth::True: break;
      case ConstantTruth::Undecidable:
        out.status = Satisfiability::Status::Unknown;
        out.reason = "the assumption " + quoted(c) + " compares two constants whose order cannot be decided";
        return out;
      case ConstantTruth::NotConstant: cons.push_back(&c); break;
    }
  }
  if (cons.empty()) return out;

  // the symbols of the constraints, in declaration order, with their feasible intervals
  GiNaC::lst all;
  for (const Constraint* c : cons) all.append(c->lhs - c->rhs);
  std::vector<ex> syms = detail::ordered_symbols(all, ctx);
  std::vector<Feasible> feas;
  for (const ex& s : syms) feas.push_back(from_domain(detail::domain_of(s, ctx)));
  for (const Constraint* c : cons) {
    auto l = single_symbol_linear(*c);
    if (!l) continue;
    std::size_t i = std::find_if(syms.begin(), syms.end(), [&](const ex& s) { return s.is_equal(l->sym); }) - syms.begin();
    if (i >= syms.size()) continue;
    Feasible& f = feas[i];
    f.linear.push_back(c);
    switch (l->op) {
      case Op::Gt: tighten(f, true, l->t, true); break;
      case Op::Ge: tighten(f, true, l->t, false); break;
      case Op::Lt: tighten(f, false, l->t, true); break;
      case Op::Le: tighten(f, false, l->t, false); break;
      case Op::Ne: f.excluded.push_back(l->t); break;
    }
  }
  for (std::size_t i = 0; i < syms.size(); ++i) {
    auto e = empty(feas[i]);
    if (!e || !*e) continue;
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(syms[i]).get_name();
    std::string list;
    for (std::size_t k = 0; k < feas[i].linear.size(); ++k)
      list += (k == 0 ? "" : (k + 1 == feas[i].linear.size() ? " and " : ", ")) + quoted(*feas[i].linear[k]);
    std::string dom = detail::domain_of(syms[i], ctx).to_string();
    if (feas[i].linear.size() == 1)
      return unsat("the assumption " + list + " never holds for '" + name + "' " + dom);
    return unsat("the assumptions " + list + " never hold together for '" + name + "' " + dom);
  }
  for (std::size_t a = 0; a < cons.size(); ++a)
    for (std::size_t b = a + 1; b < cons.size(); ++b) {
      std::string why = pair_contradiction(*cons[a], *cons[b]);
      if (!why.empty()) return unsat(why);
    }

  Search search(ctx, cons, syms, feas, seed);
  GiNaC::exmap p;
  if (search.run(kTries, p)) {
    out.point = p;
    return out;
  }
  out.status = Satisfiability::Status::Unknown;
  out.tries = kTries;
  std::string never;
  for (std::size_t j = 0; j < cons.size(); ++j)
    if (search.held()[j] == 0) never += (never.empty() ? "" : ", ") + quoted(*cons[j]);
  out.reason = "no point found that satisfies all assumptions after " + std::to_string(kTries) +
               " tries over magnitudes 1e-300..1e300";
  if (!never.empty()) out.reason += " (" + never + " held at none of the points drawn)";
  return out;
}

std::string unsatisfiable_message(const Satisfiability& s) {
  if (s.status == Satisfiability::Status::Unsatisfiable) return "the assumptions cannot all hold (" + s.reason + ")";
  if (s.status == Satisfiability::Status::Unknown) return s.reason;
  return "";
}

std::string check_satisfiable(const SymbolTable& ctx, std::uint64_t seed) {
  return decide_satisfiable(ctx, seed).reason;
}

}  // namespace dc
