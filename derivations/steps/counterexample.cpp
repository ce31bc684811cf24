// Checking a counterexample against the references (counterexample.hpp).
#include "derivations/steps/counterexample.hpp"

#include <algorithm>

#include "derivations/symbolic/inspect.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/kernel/probe.hpp"
#include "derivations/steps/follows.hpp"

namespace dc::rules {

namespace {

// Is `value` (the symbol's value at the counterexample) inside the declared domain of the
// symbol `s`? "" when it is, otherwise why not (`formula`: the value before the point was
// substituted, for the message).
std::string domain_gap(const StepContext& c, const ex& s, const ex& value, const ex& formula) {
  const SymbolInfo* info = c.d.symbols.find(GiNaC::ex_to<GiNaC::symbol>(s));
  if (!info) return "";
  const Domain& dom = info->domain;
  if (!free_of_unknowns(value)) {
    if (dom.unrestricted()) return "";   // any real value of what remains will do
    return "need not keep " + info->name + " " + dom.to_string() + " (" + info->name + " = " + c.text(formula) + ")";
  }
  detail::RealValue rv = detail::eval_real(value, 60);
  if (!rv.ok) return "gives " + info->name + " = " + c.text(value) + ", which is " + rv.why;
  bool inside = dom.contains(rv.value);
  if (!rv.exact) {
    // an approximation: inside only when it is clearly away from the bounds
    GiNaC::numeric tiny = GiNaC::numeric(1, 10).power(40);
    inside = inside && dom.contains(rv.value * (1 + tiny)) && dom.contains(rv.value * (1 - tiny));
  }
  if (inside) return "";
  return "gives " + info->name + " = " + c.text(value) + ", outside its domain (" + dom.to_string() + ")";
}

const char* const kUndefined = "the references are undefined at the counterexample";

// The symbol s of an eliminated power atom s^n (n a positive integer >= 2), else 0: the
// references give s^n, and s is computed from it (a root), never drawn at random.
ex power_atom_base(const ex& var) {
  if (!GiNaC::is_a<GiNaC::power>(var) || !GiNaC::is_a<GiNaC::symbol>(var.op(0))) return 0;
  const ex n = var.op(1);
  if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_pos_integer() ||
      GiNaC::ex_to<GiNaC::numeric>(n) < 2)
    return 0;
  return var.op(0);
}

// Does the point fix every quantity of e (no symbol without a value, no abstract application)?
bool fixed_by(const StepContext& c, const ex& e, const GiNaC::exmap& Q) {
  if (detail::has_abstract_application(e)) return false;
  for (const auto& s : c.symbols_in({e}))
    if (!Q.count(s)) return false;
  return true;
}

// a = b at the point Q, decided by the kernel with the point's values (exact rationals, or the
// values the references give eliminated quantities) read during the evaluation.
kernel::PointComparison::Kind compare(const StepContext& c, const ex& a, const ex& b, const GiNaC::exmap& Q) {
  return kernel::compare_point(a, b, Q, c.opt).kind;
}

// The checks of counterexample_gap at one full point Q (the counterexample plus values for the
// free quantities `completed`).
Gap gap_at(StepContext& c, const Reduction& red, const std::vector<Eq>& eqs,
           const std::vector<const Leftover*>& constraining, GiNaC::exmap Q, const std::vector<ex>& completed) {
  const SymbolTable& symbols = c.d.symbols;
  try {
    using K = kernel::PointComparison::Kind;
    for (const Leftover* l : constraining) {
      ex L = c.atoms.restore(l->e);
      if (!fixed_by(c, L, Q))
        return {"the counterexample need not satisfy " + reference_names(l->sources, eqs) + " (" + c.text(L) +
                " = 0, which determines nothing linearly, is not fixed by the point)"};
      K k = compare(c, L, 0, Q);
      if (k == K::IsolatedPole) return {kUndefined};
      if (k != K::Agree)
        return {"the counterexample does not satisfy " + reference_names(l->sources, eqs) + " (" + c.text(L) + " = 0)"};
    }
    const GiNaC::exmap open = Q;   // the values the eliminated quantities are computed from
    std::vector<ex> assigned = completed;
    for (const auto& el : red.eliminated) {
      ex var = c.atoms.restore(el.var);
      ex value = c.atoms.restore(el.value).subs(open, GiNaC::subs_options::no_pattern);
      ex coef = c.atoms.restore(el.coef);
      bool coef_ok;
      if (fixed_by(c, coef, open)) {
        kernel::PointComparison at = kernel::compare_point(coef, 0, open, c.opt);
        if (at.kind == K::IsolatedPole) return {kUndefined};
        coef_ok = kernel::certified_counterexample(at);
      } else {
        coef_ok = nonzero_coefficient(c, c.atoms(coef.subs(open, GiNaC::subs_options::no_pattern)));
      }
      if (!coef_ok)
        return {"the counterexample need not satisfy " + reference_names(el.sources, eqs) + " (" + c.text(var) +
                    " was obtained by dividing by " + c.text(c.atoms.restore(el.coef)) + ", which vanishes there)",
                &el};
      if (GiNaC::is_a<GiNaC::symbol>(var) && symbols.find(GiNaC::ex_to<GiNaC::symbol>(var))) {
        std::string gap = domain_gap(c, var, value, c.atoms.restore(el.value));
        if (!gap.empty()) return {"the counterexample " + gap + " by " + reference_names(el.sources, eqs), &el};
        Q[var] = value;
        assigned.push_back(var);
      } else if (const ex base = power_atom_base(var);
                 el.function_atom && !base.is_zero() && !Q.count(base) && fixed_by(c, value, open)) {
        // s^n = value: s is its real n-th root, with the sign the domain of s allows
        const int n = GiNaC::ex_to<GiNaC::numeric>(var.op(1)).to_int();
        detail::RealValue rv = detail::eval_real(value, 60);
        if (!rv.ok) return {kUndefined};
        const SymbolInfo* info = symbols.find(GiNaC::ex_to<GiNaC::symbol>(base));
        if (n % 2 == 0 && rv.value.is_negative())
          return {"the counterexample gives " + c.text(var) + " = " + c.text(value) + ", so " + c.text(base) +
                      " is not real: outside its domain (" + (info ? info->domain.to_string() : "real") + ")",
                  &el};
        const bool negative = n % 2 == 0 ? (info && info->domain.kind == Domain::Kind::Negative) : rv.value.is_negative();
        const ex root = GiNaC::pow(negative && n % 2 == 1 ? -value : value, GiNaC::numeric(1, n));
        const ex s_value = negative ? -root : root;
        std::string gap = domain_gap(c, base, s_value, c.atoms.restore(el.value));
        if (!gap.empty()) return {"the counterexample " + gap + " by " + reference_names(el.sources, eqs), &el};
        Q[base] = s_value;
        assigned.push_back(base);
      } else if (el.function_atom) {
        K k = fixed_by(c, var, open) && fixed_by(c, c.atoms.restore(el.value), open)
                  ? compare(c, var, c.atoms.restore(el.value), open)
                  : K::Unknown;
        if (k == K::IsolatedPole) return {kUndefined};
        if (k != K::Agree)
          return {"the counterexample need not satisfy " + reference_names(el.sources, eqs) + " (it gives " +
                      c.text(var) + " = " + c.text(c.atoms.restore(el.value)) + ")",
                  &el};
      }
    }
    for (const auto& k : symbols.constraints()) {
      bool touched = false;
      for (const auto& s : assigned) touched = touched || k.lhs.has(s) || k.rhs.has(s);
      if (touched && !kernel::holds_at(k, Q))
        return {"the counterexample need not satisfy the assumption " + k.text +
                " once the quantities the references determine are computed from it"};
    }
  } catch (const std::exception&) {
    return {kUndefined};
  }
  return {};
}

}  // namespace

bool point_values(const StepContext& c, const Verdict& v, GiNaC::exmap& out) {
  for (const auto& [name, value] : v.point) {
    const SymbolInfo* info = c.d.symbols.find(name);
    if (!info || info->is_function) return false;
    try {
      GiNaC::parser reader;
      ex x = reader(value);
      if (!free_of_unknowns(x)) return false;
      out[info->sym] = x;
    } catch (const std::exception&) {
      return false;
    }
  }
  return true;
}

Gap counterexample_gap(StepContext& c, const Reduction& red, const std::vector<Eq>& eqs, const Verdict& v) {
  GiNaC::exmap P;
  for (const auto& [name, value] : v.point)   // an unknown change δg (add_path_differentials)
    if (name.rfind(kUnknownChange, 0) == 0) {
      const std::string g = name.substr(kUnknownChange.size());
      return {"the counterexample needs " + g + " to change along the path, which no cited step says; if " + g +
              " is constant, cite a step d(" + g + ") = 0"};
    }
  if (!point_values(c, v, P)) return {"the counterexample cannot be checked against the references"};
  std::vector<const Leftover*> constraining;   // leftovers that are not identities
  std::vector<ex> involved;                    // what the checks evaluate
  for (const auto& l : red.leftover) {
    ex L = c.atoms.restore(l.e);
    if (prove_zero(L, c.d.symbols, c.opt).holds()) continue;   // an identity constrains nothing
    constraining.push_back(&l);
    involved.push_back(L);
  }
  for (const auto& el : red.eliminated) {
    involved.push_back(c.atoms.restore(el.value));
    involved.push_back(c.atoms.restore(el.coef));
    if (el.function_atom) involved.push_back(c.atoms.restore(el.var));
  }
  std::vector<ex> free = c.symbols_in(involved);   // symbols left open by the point and the eliminations
  free.erase(std::remove_if(free.begin(), free.end(),
                            [&](const ex& s) {
                              if (P.count(s)) return true;
                              for (const auto& el : red.eliminated)
                                if (c.atoms.restore(el.var).is_equal(s) ||
                                    (el.function_atom && power_atom_base(c.atoms.restore(el.var)).is_equal(s)))
                                  return true;
                              return false;
                            }),
             free.end());
  std::sort(free.begin(), free.end(), [&](const ex& x, const ex& y) { return c.text(x) < c.text(y); });
  Gap first;
  const int draws = free.empty() ? 1 : 8;
  for (int k = 0; k < draws; ++k) {
    GiNaC::exmap Q = P;
    detail::Rng rng(c.opt.seed + 0x51ED270B7u * static_cast<std::uint64_t>(k + 1));
    for (const auto& s : free) Q[s] = detail::sample_value(detail::domain_of(s, c.d.symbols), rng, false);
    Gap g = gap_at(c, red, eqs, constraining, Q, free);
    if (g.why.empty()) return g;
    if (k == 0) first = g;
  }
  return first;
}

}  // namespace dc::rules
