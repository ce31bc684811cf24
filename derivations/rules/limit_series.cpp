// `by limit x -> p of A [with ...]`, `by series x -> p of A` and `by first_order d1, d2 of A`:
// the referenced expression's limit, first-order series or first-order part is derived with
// the limit helper (derivations/core/limit.hpp), and the claim must equal it.
#include "derivations/core/limit.hpp"
#include "derivations/rules/dispatch.hpp"
#include "derivations/rules/follows.hpp"

namespace dc::rules {

namespace {

bool is_infinity(const Node& n, int& sign) {
  if (n.kind == NodeKind::Symbol && n.text == "oo") { sign = 1; return true; }
  if (n.kind == NodeKind::Neg && n.args[0].kind == NodeKind::Symbol && n.args[0].text == "oo") { sign = -1; return true; }
  if (n.kind == NodeKind::Sub || n.kind == NodeKind::Add) return false;
  return false;
}

Verdict limit_or_series(StepContext& c, const Relation& claim, bool is_limit) {
  const RuleSpec& rule = c.rule();
  const SymbolTable& symbols = c.d.symbols;
  const std::string rname = is_limit ? "limit" : "series";
  const Relation& ar = claim_of(c.ref_step(rule.into[0]));
  auto subs = c.substitutions(rule.with, nullptr);
  std::vector<ex> as = c.sides(ar);
  for (auto& e : as) e = apply_subs(e, subs);
  ex f = as.back();
  bool has_lhs = as.size() >= 2;
  ex x = c.symbol_of(*rule.var);
  int inf = 0;
  ex point;
  if (!is_infinity(rule.point->value, inf)) point = c.conv(rule.point->value);
  if (!is_limit && inf != 0) c.fail(rule.point->pos, "a first-order series needs a finite point", rule.point->length);

  // What the helper derives
  ex value;
  std::string how;
  int value_inf = 0;
  if (is_limit) {
    LimitResult L = compute_limit(f, GiNaC::ex_to<GiNaC::symbol>(x), inf ? ex(0) : point, inf, symbols);
    if (!L.ok) return undecided("limit", L.reason.empty() ? "the limit helper could not decide" : L.reason);
    value = L.value;
    value_inf = L.infinite;
    how = "limit (" + L.method + (L.confirmed_numerically ? ", confirmed numerically" : "") + ")";
    c.res.derived = value_inf ? (value_inf > 0 ? "oo" : "-oo") : c.text(value);
  } else {
    std::string why;
    auto s = series_first_order(f, GiNaC::ex_to<GiNaC::symbol>(x), point, &why, &symbols);
    if (!s) return undecided("series", why.empty() ? "series expansion failed" : why);
    value = *s;
    how = "series (first order)";
    c.res.derived = c.text(value);
  }

  // Each side of the claim against it
  Combiner all;
  for (std::size_t i = 0; i < claim.sides.size(); ++i) {
    Node n = resolve_definitions(c.d, claim.sides[i]);
    std::string what = claim.sides.size() > 1 ? "side " + std::to_string(i + 1) : "";
    if (is_limit && n.kind == NodeKind::Call && n.text == "limit" && n.args.size() == 3) {
      // limit(g, x, p) written in the claim: g must be the referenced f, x and p the rule's.
      ex gx = to_ginac(n.args[1], symbols);
      int ginf = 0;
      bool same_point;
      if (is_infinity(n.args[2], ginf) || inf) same_point = ginf == inf;
      else same_point = prove_equal(to_ginac(n.args[2], symbols), point, symbols, c.opt).holds();
      if (!gx.is_equal(x) || !same_point)
        c.fail(n.pos, "this limit is not the one of the rule ('" + rule.text + "')", n.length);
      ex g = apply_subs(to_ginac(n.args[0], symbols), subs);
      Verdict v = prove_equal(g, f, symbols, c.opt);
      v.method = prefix_method("limit argument", v.method);
      all.add(v, what, true);
      continue;
    }
    if (i == 0 && has_lhs) {
      Verdict v = prove_equal(c.conv(claim.sides[0]), as[0], symbols, c.opt);
      v.method = prefix_method(rname + " (left-hand side)", v.method);
      all.add(v, what, true);
      continue;
    }
    int sinf = 0;
    if (is_infinity(n, sinf) || value_inf) {
      if (sinf == value_inf) all.add(proved(how), what);
      else {
        Verdict v;
        v.kind = VerdictKind::Refuted;
        v.method = how;
        v.detail = "the limit is " + (value_inf ? std::string(value_inf > 0 ? "oo" : "-oo") : c.text(value)) +
                   ", the claim says " + to_text(claim.sides[i]);
        v.lhs_value = to_text(claim.sides[i]);
        v.rhs_value = value_inf ? (value_inf > 0 ? "oo" : "-oo") : c.text(value);
        all.add(v, what);
      }
      continue;
    }
    Verdict v;
    try {
      v = prove_equal(to_ginac(n, symbols), value, symbols, c.opt);
    } catch (const UndecidedLimit& e) {
      v = undecided("limit", e.what());
    }
    v.method = prefix_method(how, v.method);
    all.add(v, what);
  }
  return all.result();
}

}  // namespace

Verdict limit(StepContext& c, const Relation& claim) { return limit_or_series(c, claim, true); }

Verdict series(StepContext& c, const Relation& claim) { return limit_or_series(c, claim, false); }

Verdict first_order(StepContext& c, const Relation& claim) {
  std::vector<GiNaC::symbol> smalls;
  for (const auto& a : c.rule().smalls) smalls.push_back(GiNaC::ex_to<GiNaC::symbol>(c.symbol_of(a)));
  const Step& A = c.ref_step(c.rule().into[0]);
  std::vector<Eq> eqs;
  std::string derived;
  for (auto& q : c.equations(c.rule().into[0])) {
    ex e = dc::first_order(q.e.expand(), smalls);
    derived += (derived.empty() ? "" : "; ") + c.text(e) + " = 0";
    eqs.push_back({e, ex(), A.label});
  }
  c.res.derived = derived;
  std::vector<ex> sd = c.sides(claim);
  if (sd.size() < 2) c.fail(c.s.claim_pos, "the claim of 'by first_order' must be an equation");
  return links_follow(c, sd, eqs, "first order");
}

}  // namespace dc::rules
