#include "derivations/calculus/integral_equal.hpp"

#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/calculus/definite.hpp"
#include "derivations/kernel/quadrature.hpp"

namespace dc {

using GiNaC::ex;

namespace {

bool is_integral(const Node& n) { return n.kind == NodeKind::Call && n.text == "integral"; }

bool contains_integral(const Node& n) {
  if (is_integral(n)) return true;
  for (const auto& a : n.args)
    if (contains_integral(a)) return true;
  return false;
}

Verdict undecided_because(const std::string& why) {
  Verdict v;
  v.kind = VerdictKind::Undecided;
  v.method = "integral";
  v.reason = why;
  return v;
}

// +1 for oo, -1 for -oo, 0 otherwise.
int infinity_sign(const Node& n) {
  const bool neg = n.kind == NodeKind::Neg;
  const Node& v = neg ? n.args[0] : n;
  return v.kind == NodeKind::Symbol && v.text == "oo" ? (neg ? -1 : 1) : 0;
}

std::string prefixed(const std::string& head, const std::string& method) {
  return method.empty() ? head : head + " + " + method;
}

thread_local std::string improper_note_;   // why by_antiderivative gave no verdict

// integral(f, x, a, b) = G through an antiderivative (derivations/calculus/definite.hpp):
// proved or refuted by comparing its value with G; refuted when it diverges or does not exist.
// x is the fresh variable of integration of `bound` (integrand_of); G lives in `table`.
std::optional<Verdict> by_antiderivative(const ex& f, const GiNaC::symbol& x, const ex& a, int a_inf, const ex& b,
                                         int b_inf, const ex& G, const SymbolTable& bound, const SymbolTable& table,
                                         const ProveOptions& opt) {
  improper_note_.clear();
  const integrals::Definite d = integrals::definite_integral(f, x, a, a_inf, b, b_inf, bound);
  using K = integrals::Definite::Kind;
  if (d.kind == K::Unknown) {
    improper_note_ = d.why;
    return std::nullopt;
  }
  if (d.kind == K::Value) {
    Verdict v = prove_equal(d.value, G, table, opt);
    if (v.kind != VerdictKind::Proved && v.kind != VerdictKind::Refuted && v.kind != VerdictKind::HoldsNumerically) {
      improper_note_ = "its value " + print_text(d.value, table) + " (" + d.evidence + ") was not decided equal to the claim";
      return std::nullopt;
    }
    v.method = prefixed("integral (" + d.evidence + ", value " + print_text(d.value, table) + ")", v.method);
    return v;
  }
  Verdict v;
  v.kind = VerdictKind::Refuted;
  v.method = "integral (" + d.evidence + ")";
  v.detail = d.kind == K::Diverges
                 ? std::string("the integral diverges") + (d.infinite > 0 ? " to oo" : d.infinite < 0 ? " to -oo" : "") +
                       ", so it equals no finite expression"
                 : "the integral does not exist (a limit of the antiderivative at an end does not exist)";
  v.lhs_value = d.kind == K::Diverges ? "diverges" : "does not exist";
  v.rhs_value = print_text(G, table);
  return v;
}

}  // namespace


namespace {


// Integrals inside larger expressions: to_ginac evaluates them (a polynomial integrand exactly,
// d/dx of an integral by Leibniz's rule) or says why it cannot (UndecidedLimit).
std::optional<Verdict> integrals_in_expressions(const Node& lhs, const Node& rhs, const SymbolTable& table,
                                                const ProveOptions& opt) {
  ex l, r;
  try {
    l = to_ginac(lhs, table);
    r = to_ginac(rhs, table);
  } catch (const UndecidedLimit& e) {
    return undecided_because(e.what());
  }
  Verdict v = prove_equal(l, r, table, opt);
  v.method = prefixed("integral (evaluated in the expression: polynomial integrands exactly, others by a proved antiderivative, d/dx by Leibniz's rule)",
                      v.method);
  return v;
}

// integral(f, x) = F: F is an antiderivative of f on x's declared domain: dF/dx = f, and F
// defined (without a jump) wherever f is (require_antiderivative_defined). Here x is the
// quantity itself, not a bound variable: F is a function of it.
Verdict indefinite(const Node& integral, const Node& other, const SymbolTable& table, const ProveOptions& opt) {
  const ex f = to_ginac(integral.args[0], table);
  const ex xe = to_ginac(integral.args[1], table);
  if (!GiNaC::is_a<GiNaC::symbol>(xe))
    throw InputError(integral.args[1].pos, "the variable of integration must be a symbol", integral.args[1].length);
  const GiNaC::symbol& x = GiNaC::ex_to<GiNaC::symbol>(xe);
  const ex F = to_ginac(other, table);
  Verdict v = prove_equal(F.diff(x), f, table, opt);
  v.method = prefixed("indefinite integral: d/d" + x.get_name() + " of the closed form", v.method);
  v.side_conditions = side_conditions_of_tree(other, table);
  require_antiderivative_defined(v, f, x.get_name(), table);
  return v;
}

}  // namespace

std::optional<Verdict> integral_equality(const Node& lhs, const Node& rhs, const SymbolTable& table,
                                         const ProveOptions& opt) {
  const bool in_l = contains_integral(lhs), in_r = contains_integral(rhs);
  if (!in_l && !in_r) return std::nullopt;
  const Node* integral = nullptr;
  const Node* other = nullptr;
  if (is_integral(lhs) && !in_r) integral = &lhs, other = &rhs;
  else if (is_integral(rhs) && !in_l) integral = &rhs, other = &lhs;
  if (!integral) return integrals_in_expressions(lhs, rhs, table, opt);
  if (integral->args.size() == 2) return indefinite(*integral, *other, table, opt);
  if (integral->args.size() != 4)
    throw InputError(integral->pos, "expected integral(f, x) or integral(f, x, a, b)", integral->length);
  int a_inf = infinity_sign(integral->args[2]), b_inf = infinity_sign(integral->args[3]);
  if (a_inf != 0 && a_inf == b_inf) return undecided_because("both limits of integration are infinite on the same side");
  // f in a fresh variable of integration: x ranges over (a, b), whatever is declared of x
  const Integrand in = integrand_of(*integral, table);
  const ex& f = in.f;
  const GiNaC::symbol& x = GiNaC::ex_to<GiNaC::symbol>(in.x);
  ex a = a_inf ? ex(0) : to_ginac(integral->args[2], table);
  ex b = b_inf ? ex(0) : to_ginac(integral->args[3], table);
  ex G = to_ginac(*other, table);
  const bool exchanged = a_inf > 0 || b_inf < 0;
  if (exchanged) {   // from oo (or to -oo): integral(f, x, oo, r) = G is integral(f, x, r, oo) = -G
    std::swap(a, b);
    std::swap(a_inf, b_inf);
    G = -G;
  }
  if (a_inf || b_inf) {
    if (auto v = by_antiderivative(f, x, a, a_inf, b, b_inf, G, in.table, table, opt)) {
      if (exchanged) v->method = "limits exchanged (the integral is minus the one from " + print_text(a, table) + "), " + v->method;
      return *v;
    }
    return undecided_because("improper integral: " + improper_note_);
  }

  // 1. A polynomial integrand: GiNaC integrates it exactly. (Only then: eval_integ also
  // "integrates" 1/x to log across 0, where the integral diverges.)
  if (f.is_polynomial(x)) try {
    ex exact = GiNaC::integral(x, a, b, f).eval_integ();
    if (!exact.has(GiNaC::integral(x, a, b, f)) && !GiNaC::is_a<GiNaC::integral>(exact)) {
      bool residual = false;
      for (GiNaC::const_preorder_iterator it = exact.preorder_begin(); it != exact.preorder_end(); ++it)
        residual = residual || GiNaC::is_a<GiNaC::integral>(*it);
      if (!residual) {
        Verdict v = prove_equal(exact, G, table, opt);
        if (v.kind == VerdictKind::Proved || v.kind == VerdictKind::Refuted) {
          v.method = prefixed("integral (polynomial integrand, integrated exactly: " + print_text(exact, table) + ")",
                              v.method);
          return v;
        }
      }
    }
  } catch (const std::exception&) {
  }

  // 2. G as an antiderivative in the upper limit.
  std::string symbolic_note;
  // Both f (in x) and G (in b) must be continuous: G = exp(b) + atan(1/b) + atan(b) has the
  // derivative exp(b) wherever it is defined, but jumps by pi at b = 0.
  if (GiNaC::is_a<GiNaC::symbol>(b) && !f.has(b) && !a.has(b) && continuous_everywhere(f, x) &&
      continuous_everywhere(G, GiNaC::ex_to<GiNaC::symbol>(b))) {
    const GiNaC::symbol& bs = GiNaC::ex_to<GiNaC::symbol>(b);
    Verdict d = prove_equal(G.diff(bs), f.subs(x == b), table, opt);
    if (d.kind == VerdictKind::Proved) {
      Verdict z = prove_equal(G.subs(b == a), 0, table, opt);
      if (z.kind == VerdictKind::Proved) {
        Verdict v;
        v.kind = VerdictKind::Proved;
        v.method = "integral: d/d" + bs.get_name() + " of the closed form is the integrand at " + bs.get_name() +
                   " (" + d.method + "), and the closed form is 0 at " + bs.get_name() + " = " + print_text(a, table) +
                   " (" + z.method + ")";
        return v;
      }
    }
    symbolic_note = "; d/d" + bs.get_name() + " of the closed form is " + (d.holds() ? "the integrand" : "not proved to be the integrand");
  }

  // 3. An antiderivative found by rules and proved by differentiation, continuity on (a, b).
  if (auto v = by_antiderivative(f, x, a, 0, b, 0, G, in.table, table, opt)) return *v;

  // 4. Rigorous quadrature at sampled parameter values.
  Verdict v = kernel::probe_definite_integral(f, x, a, b, G, table, opt);
  v.method = prefixed("integral", v.method);
  if (v.kind == VerdictKind::Undecided && !symbolic_note.empty()) v.reason += symbolic_note;
  return v;
}

}  // namespace dc
