// `by integrate A with x1 = a1, x2 = a2, ...`, A a differential equation (differential.hpp)
//
//   c_1 d(x_1) + c_2 d(x_2) + ... = 0,
//
// integrated along any path that satisfies A, from the stated start x_i = a_i to the current
// values x_i. This is the separation of variables of the seed handout (§9.4: dv = -u_e dm_r/m_r
// - g dt, "integrated taking v = 0 at t = 0").
//
// Separation: A as written, or divided by one of its coefficients k, must have each
// coefficient c_i a function of x_i alone and of quantities without a differential in A. Those
// are constant along the path (the evidence names them), and a quantity that a premise of the
// file gives as a function of a differential quantity (`a = -k*v^2`) is not: the step is then
// undecided. The divisor k must be nonzero on the declared domain. With each c_i separated,
// along the path
//
//   integral(c_1, s, a_1, x_1) + integral(c_2, s, a_2, x_2) + ... = 0
//
// by the substitution rule, when c_i is continuous on every interval the path sweeps. Each
// integral is computed by integrals::definite_integral, which guarantees continuity on
// (a_i, x_i) for every admissible value of the quantities, so on the whole declared range of
// x_i; where it cannot, the step is undecided with its reason. The claim is then checked as
// `rewrite` from the integrated equation (and the further cited equations): proved when it
// follows, refuted at a point that satisfies them. A differential equation that no division
// separates is undecided ("not separated").
#include <set>

#include "derivations/calculus/definite.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/rules/dispatch.hpp"
#include "derivations/steps/follows.hpp"
#include "derivations/symbolic/differential.hpp"
#include "derivations/symbolic/functions.hpp"
#include "derivations/symbolic/inspect.hpp"

namespace dc::rules {

namespace {

struct Term {
  DifferentialOf d;
  ex c;       // its coefficient
  ex start;   // a_i
  bool has_start = false;
};

bool mentions_function(const ex& e) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (pool_function_index(*it) >= 0) return true;
  return false;
}

// Is every coefficient c_i / k free of the other differential quantities (and of differentials)?
bool separated_by(const std::vector<Term>& terms, const ex& k, std::vector<ex>& out) {
  out.clear();
  for (std::size_t i = 0; i < terms.size(); ++i) {
    ex q = GiNaC::normal(terms[i].c / k);
    for (std::size_t j = 0; j < terms.size(); ++j)
      if ((j != i && q.has(terms[j].d.x)) || q.has(terms[j].d.d)) return false;
    out.push_back(q);
  }
  return true;
}

// A fresh name for the variable of integration.
std::string fresh_name(const SymbolTable& t) {
  for (int i = 0;; ++i) {
    std::string n = i == 0 ? "s" : "s" + std::to_string(i);
    if (!t.find(n)) return n;
  }
}

}  // namespace

Verdict integrate_differential(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  const SymbolTable& table = c.d.symbols;
  const std::vector<Eq> a_eqs = c.equations(rule.refs[0]);
  if (a_eqs.size() != 1)
    c.fail(rule.refs[0].pos, "'" + rule.refs[0].label + "' must be one differential equation to integrate",
           rule.refs[0].length);
  const ex e = a_eqs[0].e;
  if (mentions_function(e))
    c.fail(rule.refs[0].pos,
           "'" + rule.refs[0].label + "' holds functions of a variable: integrate its derivative form with 'wrt'",
           rule.refs[0].length);

  // the terms c_i d(x_i): each term holds exactly one differential
  std::vector<Term> terms;
  ex rest = e;
  for (const auto& d : differentials_in(e, table)) {
    ex ci = GiNaC::normal(e.diff(GiNaC::ex_to<GiNaC::symbol>(d.d)));
    terms.push_back({d, ci, ex()});
    rest -= ci * d.d;
  }
  bool linear = GiNaC::normal(rest).is_zero();
  for (const auto& t : terms)
    for (const auto& u : terms) linear = linear && !t.c.has(u.d.d);
  if (!linear)
    c.fail(rule.refs[0].pos,
           "'" + rule.refs[0].label + "' is not a differential equation: each of its terms must hold exactly one "
           "differential, d(v) = a*d(t)",
           rule.refs[0].length);

  // where the integration starts: `with x = a` for every differential quantity
  for (const auto& w : rule.with) {
    const Relation& r = w.equation;
    ex x = r.sides.empty() ? ex() : c.conv(r.sides.front());
    Term* hit = nullptr;
    for (auto& t : terms)
      if (r.sides.size() == 2 && t.d.x.is_equal(x)) hit = &t;
    if (!hit)
      c.fail(w.pos, "expected 'x = start' for a quantity x whose differential is in '" + rule.refs[0].label + "'",
             w.length);
    hit->start = c.conv(r.sides.back());
    hit->has_start = true;
  }
  std::string missing;
  for (const auto& t : terms)
    if (!t.has_start) missing += (missing.empty() ? "" : ", ") + t.d.info->name + " = ...";
  if (!missing.empty())
    c.fail(rule.pos, "say where the integration starts for every quantity with a differential: with " + missing,
           static_cast<int>(rule.text.size()));

  // separate: as written, or divided by a coefficient that is nonzero on the declared domain
  std::vector<ex> q;
  ex divisor = 1;
  bool separated = separated_by(terms, divisor, q);
  for (std::size_t j = 0; j < terms.size() && !separated; ++j) {
    if (!detail::provably_nonzero(terms[j].c, table)) continue;
    divisor = terms[j].c;
    separated = separated_by(terms, divisor, q);
  }
  if (!separated)
    return undecided("integrate", "the variables of '" + rule.refs[0].label +
                                      "' are not separated: no coefficient divides it into terms c(x)*d(x)");

  // the quantities without a differential are constants along the path
  std::set<std::string> constants;
  for (std::size_t i = 0; i < terms.size(); ++i)
    for (const auto& s : c.symbols_in({q[i]}))
      if (!s.is_equal(terms[i].d.x)) constants.insert(c.text(s));
  for (const Step& st : c.d.steps) {
    if (&st == &c.s) break;
    if ((st.rule.name != "given" && st.rule.name != "definition") || st.claim.sides.size() < 2) continue;
    const Node& lhs = st.claim.sides.front();
    if (lhs.kind != NodeKind::Symbol || !constants.count(lhs.text)) continue;
    for (std::size_t k = 1; k < st.claim.sides.size(); ++k) {
      ex v;
      try {
        v = c.conv(st.claim.sides[k]);
      } catch (const std::exception&) {
        continue;
      }
      for (const auto& t : terms)
        if (v.has(t.d.x))
          return undecided("integrate", lhs.text + " is treated as constant along the path, but step '" + st.label +
                                            "' gives it through " + t.d.info->name);
    }
  }

  // integrate each separated term from its start
  const GiNaC::symbol s(fresh_name(table));   // a real variable the table does not know
  ex integrated = 0;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const ex f = q[i].subs(terms[i].d.x == s);
    const integrals::Definite r = integrals::definite_integral(f, s, terms[i].start, 0, terms[i].d.x, 0, table);
    if (r.kind != integrals::Definite::Kind::Value)
      return undecided("integrate", "the integral of " + c.text(q[i]) + " over " + terms[i].d.info->name + " from " +
                                        c.text(terms[i].start) + " was not found: " +
                                        (r.why.empty() ? std::string("it diverges or does not exist") : r.why));
    integrated += r.value;
  }
  c.res.derived = c.text(integrated) + " = 0";
  if (!divisor.is_equal(ex(1))) c.res.derived = "divided by " + c.text(divisor) + ": " + c.res.derived;
  if (!constants.empty()) {
    std::string names;
    for (const auto& n : constants) names += (names.empty() ? "" : ", ") + n;
    c.res.derived += "; constant along the path: " + names;
  }

  std::vector<Eq> eqs{{integrated, ex(), rule.refs[0].label}};
  for (std::size_t i = 1; i < rule.refs.size(); ++i)
    for (auto& q2 : c.equations(rule.refs[i])) eqs.push_back(q2);
  return links_follow(c, c.sides(claim), eqs, "integrate (separated variables)");
}

}  // namespace dc::rules
