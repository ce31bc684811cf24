// `by coefficients A [, B, ...] for x, t, ...`: comparing coefficients.
//
// The first reference A is read as holding for every value of the variables x, t, ... (an
// identity in them, as the author states it: "for all x and t"; the evidence repeats it). Each
// equation of A, written as one fraction N/D with N and D polynomials in the variables, holds
// for all of them only if N is the zero polynomial, since a polynomial that vanishes on an open
// set of points has only zero coefficients. So every coefficient of N, a monomial x^i t^j at a
// time, is 0. The claim must follow from these coefficient equations (and the equations of
// the further references, which hold at the point) as for `rewrite`: proved when it follows,
// refuted at a point that satisfies them all and not the claim. That point makes A hold for
// every x, t, so it is a counterexample to the step itself.
//
// An equation of A that is not a polynomial in the variables after clearing denominators
// (sin(x), sqrt(t)) is an input error: its coefficients are not defined. A coefficient that is a
// nonzero number means A cannot hold for every x, t: also an input error, naming it.
//
// The Lorentz transformation is the classic use: x' = gamma*(x - v*t), t' = gamma*(t - v*x/c^2)
// and the invariance x'^2 - c^2*t'^2 = x^2 - c^2*t^2 for every event give, from the
// coefficients of x^2, t^2 and x*t, gamma^2*(1 - v^2/c^2) = 1.
#include "derivations/rules/dispatch.hpp"
#include "derivations/steps/follows.hpp"

namespace dc::rules {

namespace {

// The coefficients of the polynomial p in vars[k..], each with its monomial as text.
void coefficients_of(StepContext& c, const ex& p, const std::vector<ex>& vars, std::size_t k, const std::string& monomial,
                     std::vector<std::pair<std::string, ex>>& out) {
  if (p.is_zero()) return;
  if (k == vars.size()) {
    out.push_back({monomial.empty() ? "1" : monomial, p});
    return;
  }
  const ex& x = vars[k];
  for (int i = p.ldegree(x); i <= p.degree(x); ++i) {
    const ex ci = p.coeff(x, i).expand();
    std::string m = monomial;
    if (i > 0) m += (m.empty() ? "" : "*") + c.text(x) + (i > 1 ? "^" + std::to_string(i) : "");
    coefficients_of(c, ci, vars, k + 1, m, out);
  }
}

}  // namespace

Verdict coefficients(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  std::vector<ex> vars;
  GiNaC::lst var_list;
  std::string names;   // "x, t"
  for (const auto& u : rule.unknowns) {
    vars.push_back(c.symbol_of(u));
    var_list.append(vars.back());
    names += (names.empty() ? "" : ", ") + c.text(vars.back());
  }
  const RuleArg& a = rule.refs[0];
  std::vector<Eq> eqs;
  std::string shown;
  for (const Eq& q : c.equations(a)) {
    const ex nd = GiNaC::normal(q.e).numer_denom();
    const ex num = nd.op(0).expand();
    if (!num.is_polynomial(var_list))
      c.fail(a.pos, "'" + a.label + "' is not a polynomial in " + names +
                        " after clearing denominators: its coefficients are not defined", a.length);
    std::vector<std::pair<std::string, ex>> cs;
    coefficients_of(c, num, vars, 0, "", cs);
    for (const auto& [monomial, coeff] : cs) {
      if (GiNaC::is_a<GiNaC::numeric>(coeff))
        c.fail(a.pos, "'" + a.label + "' cannot hold for every " + names + ": the coefficient of " + monomial +
                          " is " + c.text(coeff), a.length);
      eqs.push_back({coeff, ex(), a.label});
      shown += (shown.empty() ? "" : "; ") + monomial + ": " + c.text(coeff) + " = 0";
    }
  }
  c.res.derived = "'" + a.label + "' for every " + names + ", coefficient by coefficient: " + shown;
  for (std::size_t i = 1; i < rule.refs.size(); ++i)
    for (auto& q : c.equations(rule.refs[i])) eqs.push_back(q);
  return links_follow(c, c.sides(claim), eqs, "coefficients");
}

}  // namespace dc::rules
