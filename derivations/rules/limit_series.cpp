// `by limit x -> p[+|-] [of A] [with ...]`, `by series x -> p [of A]` and
// `by first_order d1, d2 of A`: the limit, first-order series or first-order part of A's
// expression (or, without `of`, of the claim's first side) is derived with the limit helper
// (derivations/calculus/limit_entry.hpp), and the claim must equal it. A limit side may be `oo`, `-oo` or
// `undefined` (the limit does not exist: one-sided limits differ, oscillation, no real value).
#include "derivations/calculus/big_o.hpp"
#include "derivations/calculus/limit_entry.hpp"
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

// `limit(g, x, p)` written as a side of the claim: g must be f (after the rule's
// substitutions), x and p the rule's.
Verdict written_limit_matches(StepContext& c, const Node& n, const ex& f, const std::optional<ex>& ref_lhs,
                              const ex& x, const ex& point, int inf, const Substitutions& subs) {
  const RuleSpec& rule = c.rule();
  const SymbolTable& symbols = c.d.symbols;
  ex gx = to_ginac(n.args[1], symbols);
  int ginf = 0;
  bool same_point;
  if (is_infinity(n.args[2], ginf) || inf) same_point = ginf == inf;
  else same_point = prove_equal(to_ginac(n.args[2], symbols), point, symbols, c.opt).holds();
  if (!gx.is_equal(x) || !same_point)
    c.fail(n.pos, "this limit is not the one of the rule ('" + rule.text + "')", n.length);
  ex g = apply_subs(to_ginac(n.args[0], symbols), subs);
  // `of A` with A: v(t) = f: the limit of v(t) is the limit of f
  if (ref_lhs) {
    Verdict w = prove_equal(g, *ref_lhs, symbols, c.opt);
    if (w.kind == VerdictKind::Proved) {
      w.method = prefix_method("limit argument (the cited step's left side)", w.method);
      return w;
    }
  }
  Verdict v = prove_equal(g, f, symbols, c.opt);
  v.method = prefix_method("limit argument", v.method);
  return v;
}

bool is_limit_call(const Node& n) { return n.kind == NodeKind::Call && n.text == "limit" && n.args.size() == 3; }


// `by series x -> p to order N`: every compared side g of the claim satisfies
// f - g = O((x - p)^N) (big_o.hpp), from the rule's side.
Verdict series_to_order(StepContext& c, const Relation& claim, const ex& f, const std::optional<ex>& ref_lhs,
                        std::size_t first_compared, const ex& x, const ex& point, int inf) {
  const RuleSpec& rule = c.rule();
  const SymbolTable& symbols = c.d.symbols;
  const GiNaC::symbol& xs = GiNaC::ex_to<GiNaC::symbol>(x);
  c.res.derived = c.text(f) + " + " + big_o_text(xs, inf ? ex(0) : point, inf, *rule.order, symbols);
  Combiner all;
  for (std::size_t i = first_compared; i < claim.sides.size(); ++i) {
    // name the side only when several are compared (`f = L1 = L2`, or `of A` with two sides)
    std::string what = claim.sides.size() > first_compared + 1 ? "side " + std::to_string(i + 1) : "";
    if (i == 0 && ref_lhs) {
      Verdict v = prove_equal(c.conv(claim.sides[0]), *ref_lhs, symbols, c.opt);
      v.method = prefix_method("series (left-hand side)", v.method);
      all.add(v, what, true);
      continue;
    }
    ex g = c.conv(claim.sides[i]);
    Verdict v = remainder_is_big_o(f - g, xs, inf ? ex(0) : point, inf, inf ? 0 : rule.dir, *rule.order, symbols);
    v.method = "series to order " + std::to_string(*rule.order) + ": " + v.method;
    all.add(v, what);
  }
  return all.result();
}

Verdict limit_or_series(StepContext& c, const Relation& named_claim, bool is_limit) {
  // `v_T = limit(v(t), t, oo) = m*g/b`: v_T only names the limit; the rest is the claim
  Relation own = named_claim;
  if (c.s.names_result) own.sides.erase(own.sides.begin());
  const Relation& claim = own;
  const RuleSpec& rule = c.rule();
  const SymbolTable& symbols = c.d.symbols;
  const std::string rname = is_limit ? "limit" : "series";
  auto subs = c.substitutions(rule.with, nullptr);
  ex x = c.symbol_of(*rule.var);
  int inf = 0;
  ex point;
  if (!is_infinity(rule.point->value, inf)) point = c.conv(rule.point->value);
  if (!is_limit && !rule.order && inf != 0)
    c.fail(rule.point->pos, "a first-order series needs a finite point (or say 'to order N')", rule.point->length);
  if (!is_limit && !rule.order && rule.dir != 0)
    c.fail(rule.point->pos, "a one-sided expansion needs 'to order N' ('by series x -> 0+ to order 2 of A')",
           rule.point->length);

  // The expression f: the last side of the step named by `of`, or else the claim's own first
  // side (`lim: (1 - cos(x))/x^2 = 1/2  by limit x -> 0`), which is then not compared.
  ex f;
  std::size_t first_compared = 0;
  std::optional<ex> ref_lhs;   // `of A` where A has two or more sides: A's first side
  if (!rule.into.empty()) {
    std::vector<ex> as = c.sides(claim_of(c.ref_step(rule.into[0])));
    for (auto& e : as) e = apply_subs(e, subs);
    f = as.back();
    if (as.size() >= 2) ref_lhs = as[0];
  } else {
    if (claim.sides.size() < 2)
      c.fail(c.s.claim_pos, "without 'of LABEL' the claim of 'by " + rname + "' must be 'EXPRESSION = " +
                                (is_limit ? "LIMIT" : "SERIES") + "': the expression comes first");
    const Node& n0 = claim.sides[0];
    if (limit_value_side(c.s, n0, symbols))
      c.fail(n0.pos, "the first side of the claim is the expression whose limit is taken", n0.length);
    if (is_limit && is_limit_call(n0)) {
      Node r = resolve_definitions(c.d, n0);
      f = apply_subs(to_ginac(r.args[0], symbols), subs);
    } else {
      f = apply_subs(c.conv(n0), subs);
    }
    first_compared = 1;
  }

  if (!is_limit && rule.order) return series_to_order(c, claim, f, ref_lhs, first_compared, x, point, inf);

  // What the helper derives
  ex value;
  std::string how;
  int value_inf = 0;
  bool does_not_exist = false;
  std::string dne_reason;
  if (is_limit) {
    LimitResult L = compute_limit(f, GiNaC::ex_to<GiNaC::symbol>(x), inf ? ex(0) : point, inf, rule.dir, symbols);
    if (L.does_not_exist) {
      does_not_exist = true;
      dne_reason = L.reason;
      how = "limit (" + L.method + (L.confirmed_numerically ? ", confirmed numerically" : "") + ")";
      c.res.derived = "undefined (" + L.reason + ")";
    } else {
      if (!L.ok) return undecided("limit", L.reason.empty() ? "the limit helper could not decide" : L.reason);
      value = L.value;
      value_inf = L.infinite;
      how = "limit (" + L.method + (L.confirmed_numerically ? ", confirmed numerically" : "") + ")";
      c.res.derived = value_inf ? (value_inf > 0 ? "oo" : "-oo") : c.text(value);
    }
  } else {
    std::string why;
    auto s = series_first_order(f, GiNaC::ex_to<GiNaC::symbol>(x), point, &why, &symbols);
    if (!s) return undecided("series", why.empty() ? "series expansion failed" : why);
    value = *s;
    how = "series (first order)";
    c.res.derived = c.text(value);
  }
  const std::string derived_text =
      does_not_exist ? "undefined" : value_inf ? (value_inf > 0 ? "oo" : "-oo") : c.text(value);

  // The helper's reason for "does not exist" usually says so itself.
  const std::string dne_detail = dne_reason.find("does not exist") != std::string::npos
                                     ? dne_reason
                                     : "the limit does not exist: " + dne_reason;
  // A side that disagrees with what the helper found (a value, an infinity, or no limit). As
  // in every comparison below, the left value is the limit (of the claim's first side, or of
  // A's) and the right value the side as written.
  auto refuted_by_limit = [&](const Node& written) {
    Verdict v;
    v.kind = VerdictKind::Refuted;
    v.method = how;
    v.detail = does_not_exist ? dne_detail : "the limit is " + derived_text + ", the claim says " + to_text(written);
    v.lhs_value = derived_text;
    v.rhs_value = to_text(written);
    return v;
  };

  // Each compared side of the claim against it
  Combiner all;
  for (std::size_t i = first_compared; i < claim.sides.size(); ++i) {
    const Node& written = claim.sides[i];
    // name the side only when several are compared (`f = L1 = L2`, or `of A` with two sides)
    std::string what = claim.sides.size() > first_compared + 1 ? "side " + std::to_string(i + 1) : "";
    if (limit_value_side(c.s, written, symbols)) {
      int sinf = 0;
      bool says_undefined = !is_infinity(written, sinf);
      bool agrees = says_undefined ? does_not_exist : (!does_not_exist && sinf == value_inf);
      if (agrees) {
        all.add(proved(how, does_not_exist ? dne_detail : std::string()), what);
      } else {
        all.add(refuted_by_limit(written), what);
      }
      continue;
    }
    Node n = resolve_definitions(c.d, written);
    if (is_limit && is_limit_call(n)) {
      all.add(written_limit_matches(c, n, f, ref_lhs, x, point, inf, subs), what, true);
      continue;
    }
    if (i == 0 && ref_lhs) {
      Verdict v = prove_equal(c.conv(written), *ref_lhs, symbols, c.opt);
      v.method = prefix_method(rname + " (left-hand side)", v.method);
      all.add(v, what, true);
      continue;
    }
    if (does_not_exist || value_inf) {
      // A finite expression against a limit that is infinite or does not exist.
      all.add(refuted_by_limit(written), what);
      continue;
    }
    Verdict v;
    try {
      v = prove_equal(value, to_ginac(n, symbols), symbols, c.opt);
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
