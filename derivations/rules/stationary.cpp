// `x = p  by stationary of F wrt x`, `by maximum of F wrt x`, `by minimum of F wrt x`: F (a
// step's last side, or an expression) has a stationary point at x = p, and for maximum/minimum
// a strict local extremum of that kind there.
//   - p lies in x's declared domain (in_domain.hpp), for every admissible parameter value;
//   - dF/dx at x = p is identically zero (prove_zero): a point where it is not, certified by the
//     probe, refutes with the derivative's value there;
//   - maximum/minimum: the first derivative of order n >= 2 that is not identically zero at p
//     (at most kMaxOrder) decides. n odd: an inflection, neither maximum nor minimum (refuted at
//     a point where that derivative is certainly nonzero). n even: its sign over the declared
//     domain, proved by range analysis or decide_sign (sign.hpp). A point where the sign is the
//     wrong one (a minimum called a maximum) refutes, with the value there; when both signs occur
//     the claim holds only under an assumption, which the undecided verdict names.
#include <string>

#include "derivations/kernel/range.hpp"
#include "derivations/kernel/sign.hpp"
#include "derivations/rules/dispatch.hpp"
#include "derivations/rules/in_domain.hpp"

namespace dc::rules {

namespace {

constexpr int kMaxOrder = 8;

// A certified point where e has the sign `sign` (+1 or -1): |e| = -sign*e fails exactly where
// sign*e > 0, so the probe's counterexample to it is such a point (with |e| and -sign*e there).
std::optional<Verdict> point_with_sign(const ex& e, int sign, const SymbolTable& t, const ProveOptions& opt) {
  Verdict v = prove_equal(GiNaC::abs(e), -sign * e, t, opt);
  if (v.kind != VerdictKind::Refuted || v.point.empty()) return std::nullopt;
  return v;
}

// e > 0 (sign +1) or e < 0 (sign -1) on the whole declared domain: the method, or "".
std::string proved_sign(const ex& e, int sign, const SymbolTable& t) {
  const ex s = sign * e;
  if (GiNaC::is_a<GiNaC::numeric>(s.evalf()) && s.info(GiNaC::info_flags::positive)) return "exact value";
  if (detail::provably_positive(s, t)) return "range analysis";
  if (auto m = kernel::decide_sign(s, kernel::SignWant::Positive, t)) return *m;
  return {};
}

// The condition under which e has the sign wanted, with the factors whose sign the declarations
// fix taken out: `2*a < 0` reads `a < 0`.
std::string assumption_for(const ex& e, int sign, StepContext& c) {
  ex f = GiNaC::factor(GiNaC::normal(e));
  ex rest = 1;
  int s = sign;
  auto one = [&](const ex& k) {
    if (GiNaC::is_a<GiNaC::numeric>(k)) {
      if (GiNaC::ex_to<GiNaC::numeric>(k).is_negative()) s = -s;
      return;
    }
    if (detail::provably_positive(k, c.d.symbols)) return;
    if (detail::provably_positive(-k, c.d.symbols)) { s = -s; return; }
    rest *= k;
  };
  if (GiNaC::is_a<GiNaC::mul>(f))
    for (std::size_t i = 0; i < f.nops(); ++i) one(f.op(i));
  else
    one(f);
  return c.text(rest) + (s > 0 ? " > 0" : " < 0");
}

std::string order_name(int n) {
  return n == 2 ? "second derivative" : n == 3 ? "third derivative" : "derivative of order " + std::to_string(n);
}

}  // namespace

Verdict stationary(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  const std::string& kind = rule.name;   // stationary, maximum or minimum
  const SymbolTable& t = c.d.symbols;
  // x = p
  if (claim.sides.size() != 2 || claim.sides[0].kind != NodeKind::Symbol)
    c.fail(c.s.claim_pos, "the claim of 'by " + kind + "' is the point, 'x = value' (x the variable)");
  const ex x = c.conv(claim.sides[0]);
  if (!GiNaC::is_a<GiNaC::symbol>(x)) c.fail(c.s.claim_pos, "the claim of 'by " + kind + "' is the point, 'x = value'");
  if (rule.var && !c.symbol_of(*rule.var).is_equal(x))
    c.fail(rule.var->pos, "the claim is a value of '" + claim.sides[0].text + "', but the rule says 'wrt " +
                              rule.var->label + "'",
           rule.var->length);
  const GiNaC::symbol& xs = GiNaC::ex_to<GiNaC::symbol>(x);
  const ex p = c.conv(claim.sides[1]);
  if (p.has(x)) c.fail(claim.sides[1].pos, "the point must not contain the variable '" + c.text(x) + "'",
                       claim.sides[1].length);
  const RuleArg& of = rule.into[0];
  const ex f = of.kind == RuleArg::Kind::Label ? c.conv(claim_of(c.ref_step(of)).sides.back()) : c.conv(of.value);
  if (!f.has(x)) c.fail(of.pos, "'" + of.label + "' does not depend on " + c.text(x), of.length);
  const std::string at = c.text(x) + " = " + c.text(p);
  const GiNaC::exmap to_p{{x, p}};
  auto at_p = [&](const ex& e) -> std::optional<ex> {
    try {
      return e.subs(to_p);
    } catch (const std::exception&) {
      return std::nullopt;   // a pole at p
    }
  };

  Combiner all;
  // p in x's declared domain
  const SymbolInfo* xi = t.find(claim.sides[0].text);
  if (xi && xi->domain.kind != Domain::Kind::Real) {
    Verdict in = value_in_domain(p, xi->domain, t, c.opt);
    if (in.kind == VerdictKind::Refuted) {
      in.detail = at + " is not in the declared domain of " + c.text(x) + " (" + xi->domain.to_string() + ")" +
                  (in.detail.empty() ? "" : "; " + in.detail);
      in.method = prefix_method(kind, in.method);
      return in;
    }
    all.add(in, "in the domain", true);
  }
  // F'(p) = 0
  const ex f1 = f.diff(xs);
  c.res.derived = "diff(F, " + c.text(x) + ") = " + c.text(f1);
  const auto d1 = at_p(f1);
  if (!d1) return undecided(kind, "the derivative " + c.text(f1) + " has no value at " + at);
  Verdict z = prove_zero(*d1, t, c.opt);
  if (z.kind == VerdictKind::Refuted) {
    z.method = prefix_method(kind, z.method);
    z.detail = "the derivative " + c.text(f1) + " does not vanish at " + at;
    z.lhs_label = "derivative (at " + at + ")";
    z.rhs_label = "required";
    z.rhs_value = "0";
    return z;
  }
  all.add(z, "derivative");
  std::string detail = "the derivative " + c.text(f1) + " vanishes at " + at;
  if (kind == "stationary" || !all.result().holds()) {
    Verdict v = all.result();
    v.method = prefix_method(kind, v.method);
    v.detail = detail + (v.detail.empty() ? "" : "; " + v.detail);
    return v;
  }

  // maximum / minimum: the first derivative of order >= 2 that does not vanish identically at p
  const int want = kind == "maximum" ? -1 : 1;
  ex fn = f1;
  for (int n = 2; n <= kMaxOrder; ++n) {
    fn = fn.diff(xs);
    const auto e = at_p(fn);
    if (!e) return undecided(kind, detail + "; the " + order_name(n) + " " + c.text(fn) + " has no value at " + at);
    const ex E = GiNaC::normal(*e);
    Verdict zn = prove_zero(E, t, c.opt);
    if (zn.holds()) {
      all.add(zn, order_name(n));
      detail += "; the " + order_name(n) + " vanishes there too";
      continue;
    }
    const std::string named = "the " + order_name(n) + " at " + at + " is " + c.text(E);
    if (zn.kind != VerdictKind::Refuted)
      return undecided(kind, detail + "; " + named + ", and whether it vanishes is undecided: " + zn.reason);
    auto refuted_at = [&](const Verdict& w, const std::string& value, const std::string& why) {
      Verdict r;
      r.kind = VerdictKind::Refuted;
      r.method = prefix_method(kind, order_name(n) + " test");
      r.point = w.point;
      r.detail = detail + "; " + named + why;
      r.lhs_label = order_name(n) + " (at " + at + ")";
      r.lhs_value = value;
      r.rhs_label = "required";
      r.rhs_value = n % 2 ? "0 or an even order" : want < 0 ? "negative" : "positive";
      return r;
    };
    if (n % 2 == 1) {
      // an odd order: an inflection wherever E != 0; only a point certified nonzero refutes,
      // and only when the lower derivatives vanish identically (proved, not sampled)
      if (all.result().kind != VerdictKind::Proved)
        return undecided(kind, detail + "; " + named + ", not identically zero: an inflection where it is nonzero");
      return refuted_at(zn, zn.lhs_value, ", nonzero at this point while the lower derivatives vanish: a stationary "
                                          "inflection, neither a maximum nor a minimum");
    }
    const std::string how = proved_sign(E, want, t);
    if (!how.empty()) {
      Verdict v = all.result();
      v.method = prefix_method(kind, v.method + " + " + order_name(n) + " sign (" + how + ")");
      v.detail = detail + "; " + named + (want < 0 ? " < 0" : " > 0") + ": a strict local " + kind;
      return v;
    }
    const auto wrong = point_with_sign(E, -want, t, c.opt);
    const auto right = point_with_sign(E, want, t, c.opt);
    if (wrong && right)
      return undecided(kind, detail + "; " + named + ", whose sign depends on the parameters: a " + kind + " needs " +
                                 assumption_for(E, want, c) + " (declare it with assume)");
    if (wrong) {
      // E > 0 there (maximum claimed): |E| = E is the left value; E < 0 (minimum claimed): the
      // right value is E itself
      return refuted_at(*wrong, want < 0 ? wrong->lhs_value : wrong->rhs_value,
                        std::string(want < 0 ? " > 0" : " < 0") + " at this point: a strict local " +
                            (want < 0 ? "minimum" : "maximum") + ", not a " + kind);
    }
    return undecided(kind, detail + "; " + named + ": its sign is not decided on the declared domain (a " + kind +
                               " needs " + assumption_for(E, want, c) + ")");
  }
  return undecided(kind, detail + "; every derivative up to order " + std::to_string(kMaxOrder) +
                             " vanishes at " + at + ": not decided");
}

}  // namespace dc::rules
