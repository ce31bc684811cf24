// Is the claimed root the only one? (solve.hpp, only_root)
//
// Substituting the claim u = G back into the equations shows that G is a root; the rule says
// more: that the equations determine u. Another root in u's declared domain (y = -w besides
// y = w for y^2 = w^2 with y real) makes the claim false there. The equations are reduced to
// equations in u alone (the other unknowns and the intermediate quantities eliminated, never
// by dividing by an expression in u), and one of them must leave G as the only root:
//   - it is continuous and strictly monotonic in u on u's domain (the sign of its derivative
//     on the interior of the domain is fixed by range analysis): sin(theta) = k with theta in
//     (0, pi/2), v^2 = 2*g*x with v nonnegative;
//   - or it is polynomial in u, and its cofactor Q (P = (u - G)*Q) has no root in the domain:
//     Q provably nonzero there, or Q linear with its root r equal to G (a double root), or r
//     outside the domain (r <= 0 for u positive, ...).
// When r may lie in the domain, a point where it does and differs from G is sought; it is a
// certified counterexample once the point (the parameters and u = r) satisfies the references,
// the domains and the assumptions, and ball arithmetic separates u from G there.
#include <set>

#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/kernel/ball.hpp"
#include "derivations/steps/counterexample.hpp"
#include "derivations/steps/elimination.hpp"
#include "derivations/rules/solve.hpp"

namespace dc::rules {

namespace {

// Is e continuous in x wherever the other quantities put it? Polynomials in x, and x only
// inside functions continuous on the whole real line.
bool continuous_in(const ex& e, const ex& x) {
  if (!e.has(x) || GiNaC::is_a<GiNaC::symbol>(e)) return true;
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!continuous_in(e.op(i), x)) return false;
    return true;
  }
  if (GiNaC::is_a<GiNaC::power>(e))   // 1/x, sqrt(x), x^y: poles or ends of the real domain
    return !e.op(1).has(x) && e.op(1).info(GiNaC::info_flags::posint) && continuous_in(e.op(0), x);
  if (GiNaC::is_a<GiNaC::function>(e) && !detail::is_abstract_application(e)) {
    static const std::set<std::string> smooth = {"sin", "cos", "exp", "sinh", "cosh", "tanh", "atan", "asinh"};
    if (!smooth.count(GiNaC::ex_to<GiNaC::function>(e).get_name())) return false;
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!continuous_in(e.op(i), x)) return false;
    return true;
  }
  return false;
}

// The symbol table with x's domain replaced by its interior: a function continuous on an
// interval whose derivative has one sign inside it is strictly monotonic on all of it.
SymbolTable with_interior(const SymbolTable& t, const ex& x) {
  SymbolTable out = t;
  const SymbolInfo* info = GiNaC::is_a<GiNaC::symbol>(x) ? t.find(GiNaC::ex_to<GiNaC::symbol>(x)) : nullptr;
  if (!info) return out;
  Domain d = info->domain;
  if (d.kind == Domain::Kind::Nonnegative) d = Domain::positive();
  if (d.kind == Domain::Kind::Interval) d.lo_open = d.hi_open = true;
  out.narrow_domain(info->name, d);
  return out;
}

struct RootsOutcome {
  Verdict v;
  std::string note;   // how the other roots were excluded
};

RootsOutcome unique(const std::string& method, const std::string& note) { return {proved("only root (" + method + ")"), note}; }

// The counterexample `candidate` (a refutation of r = G or of r's sign, at parameter values)
// extended by x = r: a certified point where another root lies in the domain and the claim fails.
std::optional<Verdict> other_root_point(StepContext& c, const Reduction& red, const std::vector<Eq>& eqs,
                                        const Verdict& candidate, const ex& X, const ex& r, const ex& G) {
  const SymbolTable& symbols = c.d.symbols;
  const SymbolInfo* info = symbols.find(GiNaC::ex_to<GiNaC::symbol>(X));
  GiNaC::exmap P;
  if (!info || !point_values(c, candidate, P) || P.count(X)) return std::nullopt;
  ex rv, gv;
  try {
    rv = r.subs(P, GiNaC::subs_options::no_pattern);
    gv = G.subs(P, GiNaC::subs_options::no_pattern);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!GiNaC::is_a<GiNaC::numeric>(rv) || !GiNaC::ex_to<GiNaC::numeric>(rv).is_rational() || !free_of_unknowns(gv) ||
      !info->domain.contains(GiNaC::ex_to<GiNaC::numeric>(rv)))
    return std::nullopt;
  P[X] = rv;
  for (const auto& k : symbols.constraints())
    if ((k.lhs.has(X) || k.rhs.has(X)) && !kernel::holds_at(k, P)) return std::nullopt;
  Verdict v;
  for (const auto& s : symbols.all()) {
    auto it = P.find(s.sym);
    if (it != P.end()) v.point.push_back({s.name, detail::exact_text(GiNaC::ex_to<GiNaC::numeric>(it->second))});
  }
  if (!counterexample_gap(c, red, eqs, v).why.empty()) return std::nullopt;
  kernel::CompareOptions co;
  co.start_digits = c.opt.digits;
  kernel::PointComparison pc = kernel::compare_at(X, G, &P, co);
  using K = kernel::PointComparison::Kind;
  if (pc.kind != K::Differ && pc.kind != K::LhsOnly) return std::nullopt;
  v.kind = VerdictKind::Refuted;
  v.method = "another root";
  v.lhs_value = pc.lhs_text();
  v.rhs_value = pc.rhs_text();
  v.digits = static_cast<int>(pc.digits);
  v.detail = "the equations have another root " + c.text(X) + " = " + c.text(r) + " in the declared domain (" +
             info->name + " " + info->domain.to_string() + "): at " + detail::join_point(v.point) +
             " it satisfies the references and differs from the claim (certified by ball arithmetic at " +
             std::to_string(pc.digits) + " digits)";
  return v;
}

// The other root r of a quadratic: excluded from the domain of X, equal to G, or a certified
// counterexample.
RootsOutcome other_root(StepContext& c, const Unknowns& u, const Reduction& red, const std::vector<Eq>& eqs, const ex& X,
                   const ex& r, const ex& G) {
  const SymbolTable& symbols = c.d.symbols;
  const std::string name = c.text(X);
  if (detail::provably_nonzero(X - r, symbols))
    return unique("range analysis", "the other root " + name + " = " + c.text(r) + " is excluded by the domains");
  const SymbolInfo* info = GiNaC::is_a<GiNaC::symbol>(X) ? symbols.find(GiNaC::ex_to<GiNaC::symbol>(X)) : nullptr;
  // an assumption on X that r can never meet: X != r itself, or a strict inequality that r
  // violates at every point (X < 0 with r = sqrt(...): r >= 0 everywhere)
  for (const auto& k : info ? symbols.constraints() : std::vector<Constraint>{}) {
    if (!k.lhs.has(X) && !k.rhs.has(X)) continue;
    ex d = (k.lhs - k.rhs).subs(X == r, GiNaC::subs_options::no_pattern);
    using Op = Constraint::Op;
    std::string note = "the other root " + name + " = " + c.text(r) + " is excluded by the assumption " + k.text;
    if (k.op == Op::Ne) {
      bool zero = false;
      try {
        zero = GiNaC::normal(d).is_zero();
      } catch (const std::exception&) {
      }
      if (zero) return unique("assumption", note);
    } else if (k.op == Op::Gt || k.op == Op::Lt) {
      Verdict s = prove_equal(GiNaC::sqrt(GiNaC::pow(d, 2)), k.op == Op::Gt ? -d : d, symbols, c.opt);
      if (s.holds()) {
        s.method = prefix_method("other root excluded by an assumption", s.method);
        return {s, note};
      }
    }
  }
  std::optional<Verdict> candidate;
  using DK = Domain::Kind;
  if (info && (info->domain.kind == DK::Positive || info->domain.kind == DK::Negative ||
               info->domain.kind == DK::Nonnegative)) {
    // r <= 0 for X positive (and r != 0 for X nonnegative), r >= 0 for X negative
    bool negative = info->domain.kind == DK::Negative;
    Verdict s = prove_equal(GiNaC::sqrt(GiNaC::pow(r, 2)), negative ? r : -r, symbols, c.opt);
    bool zero = info->domain.kind == DK::Nonnegative && GiNaC::normal(r).is_zero();
    if (s.holds() && !zero) {
      s.method = prefix_method("other root outside the domain", s.method);
      return {s, "the other root " + name + " = " + c.text(r) + " is outside the declared domain (" + info->name + " " +
                     info->domain.to_string() + ")"};
    }
    if (s.kind == VerdictKind::Refuted) candidate = s;
  }
  Verdict e = prove_equal(r, G, symbols, c.opt);
  if (e.holds()) {
    e.method = prefix_method("double root", e.method);
    return {e, "a double root"};
  }
  if (e.kind == VerdictKind::Refuted && (!candidate || e.point.size() > candidate->point.size())) candidate = e;
  if (candidate && info && u.standin.empty())
    if (auto v = other_root_point(c, red, eqs, *candidate, X, r, G)) return {*v, ""};
  return {undecided("solve", "the equations have another root " + name + " = " + c.text(r) +
                                 ", which the declared domain of " + name + " does not exclude"),
          ""};
}

// One equation P = 0 in x alone (atomized numerator, stand-in form).
RootsOutcome check_equation(StepContext& c, const Unknowns& u, const Reduction& red, const std::vector<Eq>& eqs,
                       const ex& P, const ex& x, const ex& G) {
  const SymbolTable& symbols = c.d.symbols;
  const GiNaC::symbol& xs = GiNaC::ex_to<GiNaC::symbol>(x);
  const ex X = u.out(c, x);
  const std::string name = c.text(X);
  auto outside = [&](const ex& e) { return c.atoms.restore(u.out(c, e)); };
  if (continuous_in(P, x)) {
    detail::Range slope = detail::range_of(c.atoms.restore(P.diff(xs)), with_interior(symbols, x));
    if (slope.positive() || slope.negative())
      return unique("monotonic", "the only root: the equation is strictly monotonic in " + name + " on its domain");
  }
  if (!P.is_polynomial(x))
    return {undecided("solve", "the equation in " + name + " is neither polynomial nor shown monotonic: other roots are "
                               "not excluded"),
            ""};
  const int n = P.degree(x);
  std::vector<ex> a(n + 1), b(n);   // P = sum a_k x^k = (x - G) * sum b_k x^k
  for (int k = 0; k <= n; ++k) a[k] = P.coeff(x, k);
  b[n - 1] = a[n];
  for (int k = n - 1; k >= 1; --k) b[k - 1] = (a[k] + G * b[k]).expand();
  bool divides = false;
  try {
    divides = GiNaC::normal(a[0] + G * b[0]).is_zero() ||
              prove_zero(outside(a[0] + G * b[0]), symbols, c.opt).kind == VerdictKind::Proved;
  } catch (const std::exception&) {
  }
  if (!divides)
    return {undecided("solve", "the claimed root does not divide the equation in " + name + " exactly"), ""};
  if (n == 1) {
    if (!nonzero_coefficient(c, a[1]))
      return {undecided("solve", "the coefficient of " + name + " may vanish: other roots are not excluded"), ""};
    return unique("linear", "the only root: the equation is linear in " + name);
  }
  ex Q = 0;
  for (int k = 0; k < n; ++k) Q += b[k] * GiNaC::pow(x, k);
  if (detail::provably_nonzero(outside(Q), symbols))
    return unique("range analysis", "the other roots are excluded by the domains");
  if (n > 2)
    return {undecided("solve", "the other roots of an equation of degree " + std::to_string(n) + " in " + name +
                                   " are not excluded"),
            ""};
  if (!nonzero_coefficient(c, b[1]))
    return {undecided("solve", "the leading coefficient of the equation in " + name + " may vanish"), ""};
  ex r = -b[0] / b[1];
  try {
    r = GiNaC::normal(r);
  } catch (const std::exception&) {
  }
  if (GiNaC::normal(r - G).is_zero()) return unique("double root", "a double root");
  return other_root(c, u, red, eqs, X, outside(r), outside(G));
}

}  // namespace

Verdict only_root(StepContext& c, const Unknowns& u, const std::vector<Eq>& eqs, std::size_t which, const ex& G,
                  const std::vector<ex>& elim, std::string& note) {
  const ex& x = u.syms[which];
  const std::string name = c.text(u.out(c, x));
  // Eliminating an intermediate by dividing by an expression in x loses the roots where that
  // expression vanishes -- unless it vanishes nowhere on the declared domain (J*b = ... with b
  // positive). Otherwise another order of elimination is tried, without that division.
  Reduction red;
  Bans bans;
  for (int attempt = 0;; ++attempt) {
    red = reduce(c, eqs, ex(0), elim, true, bans);
    if (red.resource_limit || red.degenerate)
      return undecided("solve", "other roots are not excluded: the equations in " + name + " alone cannot be formed");
    const Elimination* lossy = nullptr;
    for (const auto& el : red.eliminated)
      if (el.coef.has(x) && !detail::provably_nonzero(c.atoms.restore(u.out(c, el.coef)), c.d.symbols)) {
        lossy = &el;
        break;
      }
    if (!lossy) break;
    if (attempt >= 3 || !bans.insert({lossy->equation, lossy->key}).second)
      return undecided("solve", "other roots are not excluded: eliminating " +
                                    c.text(c.atoms.restore(u.out(c, lossy->var))) + " divides by an expression in " + name);
  }
  std::optional<RootsOutcome> first;
  for (const auto& l : red.leftover) {
    if (!l.e.has(x) || has_any(l.e, elim)) continue;
    RootsOutcome o = check_equation(c, u, red, eqs, l.e, x, G);
    if (o.v.holds()) {
      note = o.note;
      return o.v;
    }
    if (!first || (o.v.kind == VerdictKind::Refuted && first->v.kind != VerdictKind::Refuted)) first = o;
  }
  if (first) return first->v;
  return undecided("solve", "other roots are not excluded: no equation in " + name + " alone remains");
}

}  // namespace dc::rules
