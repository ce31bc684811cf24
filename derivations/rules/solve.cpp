// `by solve E... for u, ...`: the claim `u = G` is the solution of the equations for the
// unknowns (symbols, or expressions such as sin(theta), replaced by stand-in symbols).
//   - Linear in the unknowns: lsolve derives the solution (only when the equations determine
//     the unknowns: some square choice of them has a determinant that is not identically zero)
//     and prove_equal compares the claim with it.
//   - Otherwise the claim is substituted back: with u = G and the other unknowns (and the
//     quantities that only link the equations) eliminated, each equation must reduce to an
//     identity; G must lie in the declared domain of u, and no other root may
//     (solve_roots.cpp).
//   - A claim that is not `u = ...` for an unknown must follow from the equations.
#include <algorithm>
#include <functional>
#include <optional>

#include "derivations/symbolic/functions.hpp"
#include "derivations/rules/dispatch.hpp"
#include "derivations/steps/elimination.hpp"
#include "derivations/steps/follows.hpp"
#include "derivations/rules/in_domain.hpp"
#include "derivations/rules/solve.hpp"

namespace dc::rules {

namespace {




// Does the linear system `nums` (linear in the unknowns) determine them? Only when some
// square choice of its equations has a coefficient determinant that is not identically zero:
// lsolve divides by pivots without knowing that log(a*b) - log(a) - log(b) is zero.
bool determines(StepContext& c, const std::vector<ex>& nums, const std::vector<ex>& unknowns) {
  const std::size_t n = unknowns.size(), m = nums.size();
  if (n == 0 || m < n) return false;
  std::vector<bool> pick(m, false);   // the chosen equations; combinations in lexicographic order
  std::fill(pick.begin(), pick.begin() + static_cast<long>(n), true);
  int tries = 0;
  do {
    GiNaC::matrix A(static_cast<unsigned>(n), static_cast<unsigned>(n));
    unsigned r = 0;
    for (std::size_t i = 0; i < m; ++i) {
      if (!pick[i]) continue;
      for (std::size_t j = 0; j < n; ++j) A(r, static_cast<unsigned>(j)) = nums[i].coeff(unknowns[j], 1);
      ++r;
    }
    try {
      if (nonzero_coefficient(c, A.determinant())) return true;
    } catch (const std::exception&) {
      // an unusable determinant: try the next choice
    }
  } while (++tries < 64 && std::prev_permutation(pick.begin(), pick.end()));
  return false;
}

// The linear case: lsolve, then the claim compared with the solution. nullopt when the
// equations are not linear in the unknowns or lsolve does not determine them.
std::optional<Verdict> solve_linear(StepContext& c, const Unknowns& u, const std::vector<ex>& E,
                                    const std::vector<ex>& sd, bool& undetermined) {
  bool linear = E.size() >= u.syms.size();
  std::vector<ex> nums;
  for (const auto& e : E) {
    ex num;
    try {
      num = GiNaC::numer(GiNaC::normal(e)).expand();
    } catch (const std::exception&) {
      linear = false;
      break;
    }
    nums.push_back(num);
    for (const auto& x : u.syms) {
      ex k = num.coeff(x, 1);
      ex rest = (num - k * x).expand();
      if (rest.has(x) || has_any(k, u.syms)) linear = false;
    }
  }
  if (linear && !determines(c, nums, u.syms)) {
    undetermined = true;
    std::string names;
    for (const auto& x : u.syms) names += (names.empty() ? "" : ", ") + c.text(u.out(c, x));
    return undecided("lsolve", "the equations do not determine " + names +
                                   ": the determinant of their coefficients vanishes identically");
  }
  if (!linear) return std::nullopt;
  GiNaC::lst eqlist, varlist;
  for (const auto& n : nums) eqlist.append(n == 0);
  for (const auto& x : u.syms) varlist.append(x);
  ex sol;
  try {
    sol = GiNaC::lsolve(eqlist, varlist);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!GiNaC::is_a<GiNaC::lst>(sol) || sol.nops() != u.syms.size()) return std::nullopt;
  GiNaC::exmap solmap;
  for (std::size_t i = 0; i < sol.nops(); ++i) {
    ex var = sol.op(i).lhs(), val = sol.op(i).rhs();
    if (has_any(val, u.syms)) return std::nullopt;
    solmap[var] = val;
  }
  std::string derived;
  for (const auto& x : u.syms) {
    ex val = u.out(c, solmap[x]);
    derived += (derived.empty() ? "" : "; ") + c.text(u.out(c, x)) + " = " + c.text(val);
    for (auto& sc : side_conditions(val, c.d.symbols)) c.res.verdict.side_conditions.push_back(sc);
  }
  c.res.derived = derived;
  Combiner all;
  for (std::size_t i = 0; i + 1 < sd.size(); ++i) {
    ex a = u.out(c, u.in(c, sd[i]).subs(solmap)), b = u.out(c, u.in(c, sd[i + 1]).subs(solmap));
    Verdict v = prove_equal(a, b, c.d.symbols, c.opt);
    v.method = prefix_method("lsolve", v.method);
    all.add(v, sd.size() > 2 ? "link " + std::to_string(i + 1) : "");
  }
  return all.result();
}

// The nonlinear case for the claim u = G (u the unknown `which`): G substituted back, and G
// must be the only root (solve_roots.cpp). `eqs`: the equations E with their labels.
Verdict substitute_back(StepContext& c, const Unknowns& u, const std::vector<ex>& E, const std::vector<Eq>& eqs,
                        const std::vector<ex>& sd, std::size_t which) {
  const ex& lhs = u.syms[which];
  Combiner all;
  std::vector<ex> others;
  for (std::size_t i = 0; i < u.syms.size(); ++i)
    if (i != which) others.push_back(u.syms[i]);
  for (std::size_t k = 1; k < sd.size(); ++k) {
    ex G = u.in(c, sd[k]);
    if (G.has(lhs)) c.fail(c.s.claim_pos, "the claimed solution for '" + c.text(u.out(c, lhs)) + "' contains it");
    std::vector<Eq> back;
    // (through the atoms: y(T) stands as an atom, and the claim must reach inside it: y(G))
    for (const auto& e : E) back.push_back({c.atoms(c.atoms.restore(e).subs(lhs == G)), ex(), ""});
    // A function value at the unknown, y(T) in `y(T) = v0*sin(theta)*T - g*T^2/2 = 0`, is an
    // intermediate: the chain's first link only names it (with T = G put in it is y(G), a value
    // the equations determine, not a random one).
    std::vector<ex> apps, apps_orig;
    std::function<void(const ex&)> at_unknown = [&](const ex& e) {
      if (pool_function_index(e) >= 0 && e.has(lhs)) {
        const ex app = c.atoms(e.subs(lhs == G));
        if (!has_any(app, apps)) apps.push_back(app), apps_orig.push_back(c.atoms(e));
        return;
      }
      for (std::size_t i = 0; i < e.nops(); ++i) at_unknown(e.op(i));
    };
    for (const auto& e : E) at_unknown(c.atoms.restore(e));
    // Quantities of the equations that the claim does not mention (v1, dh in the ballistic
    // pendulum) are intermediate: they are eliminated together with the other unknowns.
    // A quantity counts as intermediate when it links at least two of the equations (a
    // parameter such as g in a single equation is not eliminated: that would use the equation
    // up instead of checking it). An equation that only names a function value y(T) (the one
    // equation it appears in) does not count as a link.
    std::vector<ex> elim = others, in_eqs;
    std::vector<const Eq*> linking;
    for (const auto& q : back) {
      in_eqs.push_back(q.e);
      bool names_value = false;
      for (const auto& a : apps) {
        int n = 0;
        for (const auto& r : back) n += r.e.has(a) ? 1 : 0;
        names_value = names_value || (n == 1 && q.e.has(a));
      }
      if (!names_value) linking.push_back(&q);
    }
    for (const auto& sym : c.symbols_in(in_eqs)) {
      int count = 0;
      for (const Eq* q : linking) count += q->e.has(sym) ? 1 : 0;
      if (count >= 2 && !G.has(sym) && !has_any(sym, elim)) elim.push_back(sym);
    }
    std::vector<ex> elim_roots = elim;   // the same intermediates before G is put in (only_root)
    for (std::size_t i = 0; i < apps.size(); ++i) {
      if (!has_any(apps[i], elim)) elim.push_back(apps[i]);
      if (!has_any(apps_orig[i], elim_roots)) elim_roots.push_back(apps_orig[i]);
    }
    Reduction red = reduce(c, back, ex(0), elim, true);
    int checked = 0;
    for (const auto& left : red.leftover) {
      Verdict v = prove_zero(c.atoms.restore(u.out(c, left.e)), c.d.symbols, c.opt);
      v.method = prefix_method("claim substituted back", v.method);
      all.add(v, "equation with " + c.text(u.out(c, lhs)) + " = " + c.text(u.out(c, G)));
      ++checked;
    }
    if (red.resource_limit) all.add(undecided("claim substituted back", "resource limit"), "");
    if (red.degenerate)
      all.add(undecided("claim substituted back",
                        "every order of elimination divides by a coefficient that vanishes identically"),
              "");
    if (checked == 0 && !red.resource_limit) {
      // Every equation was used to eliminate another unknown, or reduced to 0: the claim
      // satisfies all of them identically.
      if (red.vanished == 0)
        all.add(undecided("claim substituted back", "the equations do not determine " + c.text(u.out(c, lhs)) +
                                                        " (they are used up by the other unknowns)"),
                "");
      else
        all.add(proved("claim substituted back (normal)"), "");
    }
    // The declared domain of the unknown picks the root: v0 : negative for v0 = -sqrt(...).
    std::string root_note;
    if (GiNaC::is_a<GiNaC::symbol>(u.out(c, lhs))) {
      const SymbolInfo* info = c.d.symbols.find(GiNaC::ex_to<GiNaC::symbol>(u.out(c, lhs)));
      const bool constant_root = GiNaC::is_a<GiNaC::numeric>(u.out(c, G).evalf());
      if (info && (info->domain.kind == Domain::Kind::Interval || info->domain.integer ||
                   (info->domain.kind != Domain::Kind::Real && constant_root))) {
        // (a constant root is compared exactly: T = 0 is not positive)
        const Verdict v = value_in_domain(u.out(c, G), info->domain, c.d.symbols, c.opt);
        all.add(v, "the claimed root must be " + info->domain.to_string() + " like " + info->name, true);
        root_note = " (the root is the one in the declared domain: " + info->name + " " + info->domain.to_string() + ")";
      } else if (info && info->domain.kind != Domain::Kind::Real) {
        bool neg = info->domain.kind == Domain::Kind::Negative;
        ex g = u.out(c, G);
        Verdict v = prove_equal(GiNaC::sqrt(GiNaC::pow(g, 2)), neg ? -g : g, c.d.symbols, c.opt);
        v.method = prefix_method("root in the declared domain", v.method);
        all.add(v, "the claimed root must be " + info->domain.to_string() + " like " + info->name, true);
        root_note = " (the root is the one in the declared domain: " + info->name + " " + info->domain.to_string() + ")";
      }
    }
    // ... and no other root may lie in the domain (y = w from y^2 = w^2 with y real is false at y = -w)
    std::string how;
    Verdict only = only_root(c, u, eqs, which, G, elim_roots, how);
    all.add(only, "", true);
    if (only.kind == VerdictKind::Refuted) root_note = " (another root lies in the declared domain)";
    else if (!only.holds()) root_note = " (other roots are not excluded)";
    else if (root_note.empty()) root_note = " (" + how + ")";
    c.res.derived = "nonlinear in the unknowns: the claim " + c.text(u.out(c, lhs)) + " = " + c.text(u.out(c, G)) +
                    " was substituted into the equations" + root_note;
  }
  return all.result();
}

}  // namespace

Verdict solve(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  std::vector<Eq> eqs = c.all_equations(rule.refs);
  std::vector<ex> sd = c.sides(claim);
  if (sd.size() < 2) c.fail(c.s.claim_pos, "the claim of 'by solve' must be an equation 'x = expression'");
  Unknowns u;
  int k = 0;
  for (const auto& arg : rule.unknowns) {
    ex e = c.atoms(c.conv(arg.value));
    if (!GiNaC::is_a<GiNaC::symbol>(e)) {
      GiNaC::realsymbol s("dc_unknown" + std::to_string(k++));
      u.standin[e] = s;
      u.standback[s] = e;
      e = s;
    }
    u.syms.push_back(e);
  }
  std::vector<ex> E;
  std::vector<Eq> in_eqs;   // E with the labels
  for (auto& q : eqs) {
    E.push_back(u.in(c, q.e));
    in_eqs.push_back({E.back(), ex(), q.from, q.also});
  }
  for (std::size_t i = 0; i < u.syms.size(); ++i) {
    bool appears = false;
    for (const auto& e : E) appears = appears || e.has(u.syms[i]);
    if (!appears)
      c.fail(rule.unknowns[i].pos, "the unknown '" + rule.unknowns[i].label + "' does not appear in the equations",
             rule.unknowns[i].length);
  }
  bool undetermined = false;
  if (auto v = solve_linear(c, u, E, sd, undetermined)) {
    if (!undetermined) return *v;
    // The equations leave an unknown free: every value of it that satisfies them is a
    // counterexample to a claim that pins it (u = 0 from an identity in u). Whether the claim
    // follows is decided as for `rewrite`, whose counterexamples satisfy the references.
    std::vector<ex> preferred;
    for (auto& x : u.syms) preferred.push_back(u.out(c, x));
    Verdict f = links_follow(c, sd, eqs, "solve (elimination)", preferred);
    if (f.kind == VerdictKind::Refuted || f.holds()) {
      if (f.kind == VerdictKind::Refuted) f.detail += (f.detail.empty() ? "" : "; ") + v->reason;
      return f;
    }
    return *v;
  }
  // Nonlinear (or not uniquely solvable): substitute the claim back. The claim must be
  // `u = G` for an unknown u; each equation, with u = G and the other unknowns eliminated,
  // must reduce to an identity.
  ex lhs = u.in(c, sd[0]);
  std::vector<ex> preferred;
  for (auto& x : u.syms) preferred.push_back(u.out(c, x));
  for (std::size_t i = 0; i < u.syms.size(); ++i) {
    if (!lhs.is_equal(u.syms[i])) continue;
    Verdict back = substitute_back(c, u, E, in_eqs, sd, i);
    if (back.holds() || back.kind == VerdictKind::Refuted) return back;
    // Substituting back could not decide. A claim that follows from the equations (every
    // point satisfying them has u = G) is their only root: the equations that are linear in
    // the unknowns, solved one at a time (an overdetermined linear system, or one made linear
    // by eliminating another unknown first), decide it. A certified point that satisfies the
    // equations with u != G is a root the claim misses: refuted, as for another root.
    const std::string derived = c.res.derived;
    Verdict f = links_follow(c, sd, eqs, "solve (elimination)", preferred);
    if (f.holds() || f.kind == VerdictKind::Refuted) {
      c.res.derived = "the claim " + c.text(u.out(c, lhs)) + " = " + c.text(u.out(c, u.in(c, sd.back()))) +
                      (f.holds() ? " follows from the equations, so it is their only root"
                                 : " does not follow from the equations: a point satisfies them with another value");
      return f;
    }
    c.res.derived = derived;
    return back;
  }
  return links_follow(c, sd, eqs, "solve (elimination)", preferred);
}

}  // namespace dc::rules
