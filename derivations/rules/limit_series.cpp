// `by limit x -> p[+|-] [of A] [with ...]`, `by series x -> p[+|-] [to order N] [of A]` and
// `by first_order d1, d2 of A`. A limit of A's expression (or, without `of`, of the claim's
// first side) is derived with the limit helper (derivations/calculus/limit_entry.hpp), and the
// claim must equal it; a limit side may be `oo`, `-oo` or `undefined` (the limit does not
// exist: one-sided limits differ, oscillation, no real value). A series claim holds when the
// expression and each further side differ by O((x - p)^N) (N = 2 without `to order N`: agreement
// to first order), decided by the remainder gauge (big_o.hpp). first_order: agreement to first
// order in small quantities scaled by one eps (see first_order below).
#include <algorithm>
#include <functional>
#include <map>

#include "derivations/calculus/big_o.hpp"
#include "derivations/calculus/limit_entry.hpp"
#include "derivations/kernel/range.hpp"
#include "derivations/symbolic/functions.hpp"
#include "derivations/rules/dispatch.hpp"
#include "derivations/steps/follows.hpp"

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


// `by series x -> p [to order N]`: every compared side g of the claim satisfies
// f - g = O((x - p)^N) (big_o.hpp), from the rule's side; without `to order N` the first-order
// form, N = 2 (agreement to first order). The derived expansion (GiNaC's Laurent series of f,
// confirmed) is the evidence: the right coefficients next to a wrong one.
Verdict series_to_order(StepContext& c, const Relation& claim, const ex& f, const std::optional<ex>& ref_lhs,
                        std::size_t first_compared, const ex& x, const ex& point, int inf, int order,
                        bool first_order_form) {
  const RuleSpec& rule = c.rule();
  const SymbolTable& symbols = c.d.symbols;
  const GiNaC::symbol& xs = GiNaC::ex_to<GiNaC::symbol>(x);
  const ex p = inf ? ex(0) : point;
  const std::string o = big_o_text(xs, p, inf, order, symbols);
  const std::string what_rule =
      first_order_form ? "series (first order, " + o + ")" : "series to order " + std::to_string(order);
  c.res.derived = c.text(f) + " + " + o;
  // the expansion, computed only for a refuted side (evidence) and shown once confirmed
  std::optional<std::optional<ex>> expansion;
  bool confirmed = false;   // f - expansion = O(gauge) shown
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
    Verdict v = remainder_is_big_o(f - g, xs, p, inf, inf ? 0 : rule.dir, order, symbols);
    v.method = what_rule + ": " + v.method;
    if (v.kind == VerdictKind::Refuted) {
      if (!expansion) {
        expansion = laurent_expansion(f, xs, p, inf, order);
        confirmed = *expansion && remainder_is_big_o(f - **expansion, xs, p, inf, inf ? 0 : rule.dir, order,
                                                     symbols).kind == VerdictKind::Proved;
        if (confirmed) c.res.derived = c.text(**expansion) + " + " + o;
      }
      // the right coefficients next to the wrong ones
      if (confirmed) v.detail += "; the expansion is " + c.text(**expansion) + " + " + o;
    }
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

  // a series: to order N, or without `to order N` to first order (N = 2)
  if (!is_limit)
    return series_to_order(c, claim, f, ref_lhs, first_compared, x, point, inf, rule.order ? *rule.order : 2,
                           !rule.order);

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
    v.lhs_label = "limit";
    v.rhs_label = "claimed";
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
    // the values compared are the limit and the side as written (at the counterexample)
    if (v.kind == VerdictKind::Refuted && (!v.lhs_value.empty() || !v.rhs_value.empty())) {
      v.lhs_label = "limit";
      v.rhs_label = "claimed";
    }
    all.add(v, what);
  }
  return all.result();
}

}  // namespace

Verdict limit(StepContext& c, const Relation& claim) { return limit_or_series(c, claim, true); }

Verdict series(StepContext& c, const Relation& claim) { return limit_or_series(c, claim, false); }

namespace {

// The table with one more positive symbol, eps: the common scale of the small quantities.
SymbolTable with_scale(const SymbolTable& t, ex& eps) {
  SymbolTable out = t;
  std::string name = "eps";
  for (int k = 1; out.find(name); ++k) name = "eps" + std::to_string(k);
  SymbolInfo info;
  info.name = name;
  info.domain = Domain::positive();
  eps = out.declare(info).sym;
  return out;
}

// d = L - R is O(eps^2) after every small quantity d_i becomes eps*d_i, as eps -> 0+ (the
// gauge of big_o.hpp in eps, d_i fixed: each direction of approach on its own).
Verdict second_order_in_eps(StepContext& c, const ex& d, const std::vector<ex>& smalls, const std::string& how) {
  std::string e;
  Verdict v = second_order_in_smalls(d, smalls, c.d.symbols, &e);
  v.method = "first order (" + how + "; each small quantity scaled by " + e + "): " + v.method;
  if (v.kind == VerdictKind::Refuted && !v.point.empty())
    v.detail += " (each small quantity is " + e + " times its value at this point)";
  return v;
}

// e stays bounded as eps -> 0+ with every small quantity d_i = eps*d_i (e = O(1)).
bool bounded_in_eps(StepContext& c, const ex& e, const std::vector<ex>& smalls) {
  ex eps;
  const SymbolTable scaled = with_scale(c.d.symbols, eps);
  GiNaC::exmap by_eps;
  for (const ex& s : smalls) by_eps[s] = eps * s;
  try {
    const ex r = e.subs(by_eps, GiNaC::subs_options::no_pattern);
    if (!r.has(eps)) return true;
    return remainder_is_big_o(r, GiNaC::ex_to<GiNaC::symbol>(eps), 0, 0, +1, 0, scaled).kind == VerdictKind::Proved;
  } catch (const std::exception&) {
    return false;
  }
}

std::string names_of(const std::vector<ex>& xs, const StepContext& c) {
  std::string out;
  for (const ex& x : xs) out += (out.empty() ? "" : ", ") + c.text(x);
  return out;
}

}  // namespace

// `C  by first_order d1, d2 of A`: C agrees with A to first order in the small quantities:
// with every d_i = eps*delta_i, the claim's sides differ by O(eps^2) on A. Three ways, in order:
//   1. the truncated form: A with its terms of order >= 2 dropped implies C (the rocket's
//      `m*dv = u*dm`);
//   2. C's first side is A's: each further side differs from A's last side by O(eps^2); or A
//      is `q = expr` (q not small): with q replaced by expr, C's sides differ by O(eps^2);
//   3. A's first-order part sum c_i d_i = 0 (no term of order 0) gives one small quantity d_j
//      (c_j nonzero by the declarations) in terms of the others; substituted, each side of C
//      minus its first is O(eps^2).
// 2 and 3 are decided by the remainder gauge (big_o.hpp), so they also refute; 1 only proves
// (an exact claim such as y^2 = 1 + d for y = sqrt(1 + d) agrees to first order, yet does not
// follow from the truncated y = 1 + d/2).
Verdict first_order(StepContext& c, const Relation& claim) {
  const RuleArg& ref = c.rule().into[0];
  const Step& A = c.ref_step(ref);
  std::vector<ex> sd = c.sides(claim);
  if (sd.size() < 2) c.fail(c.s.claim_pos, "the claim of 'by first_order' must be an equation");
  std::vector<Eq> a_eqs = c.equations(ref);
  std::vector<ex> as = c.sides(claim_of(A));
  // The small quantities as symbols. A small declared function theta is small with all its
  // derivatives (theta = eps*delta makes theta(t), diff(theta(t), t), ... each eps times a
  // value): every application and derivative of it in A and the claim becomes a stand-in
  // symbol named as written.
  std::vector<GiNaC::symbol> smalls;
  std::vector<ex> small_ex;
  GiNaC::exmap standin;
  for (const auto& a : c.rule().smalls) {
    const SymbolInfo* info = a.kind == RuleArg::Kind::Symbol ? c.d.symbols.find(a.label) : nullptr;
    int fn = info && info->is_function ? c.d.symbols.function_index(a.label) : -1;
    if (a.kind == RuleArg::Kind::Value) {
      const ex e = c.conv(a.value);
      if (pool_derivative_order(e) != 0)
        c.fail(a.pos, "expected a small quantity: a symbol or a declared function such as theta(t)", a.length);
      fn = pool_function_index(e);
    }
    if (fn < 0) {
      small_ex.push_back(c.symbol_of(a));
      smalls.push_back(GiNaC::ex_to<GiNaC::symbol>(small_ex.back()));
      continue;
    }
    std::map<std::string, ex> found;   // by text: a deterministic order
    std::function<void(const ex&)> collect = [&](const ex& e) {
      if (pool_function_index(e) == fn) {
        found.emplace(c.text(e), e);
        return;
      }
      for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i));
    };
    for (const auto& q : a_eqs) collect(q.e);
    for (const auto& e : sd) collect(e);
    if (found.empty())
      c.fail(a.pos, "the small function '" + a.label + "' appears neither in the claim nor in " + A.label, a.length);
    for (const auto& [text, e] : found) {
      if (standin.count(e)) continue;
      GiNaC::realsymbol s(text);
      standin[e] = s;
      smalls.push_back(s);
      small_ex.push_back(s);
    }
  }
  if (!standin.empty()) {
    for (auto& q : a_eqs) q.e = q.e.subs(standin, GiNaC::subs_options::no_pattern);
    for (auto& e : sd) e = e.subs(standin, GiNaC::subs_options::no_pattern);
    for (auto& e : as) e = e.subs(standin, GiNaC::subs_options::no_pattern);
  }
  std::vector<Eq> eqs;
  std::vector<ex> truncated;
  std::string derived;
  std::string singular;
  for (auto& q : a_eqs) {
    try {
      ex e = dc::first_order(q.e.expand(), smalls);
      derived += (derived.empty() ? "" : "; ") + c.text(e) + " = 0";
      eqs.push_back({e, ex(), A.label});
      truncated.push_back(e);
    } catch (const std::domain_error& e) {
      singular = e.what();
    }
  }
  c.res.derived = derived;
  // 1. the truncated form
  Verdict t;
  if (singular.empty()) {
    t = links_follow(c, sd, eqs, "first order");
    if (t.holds()) return t;
  }
  // 2. the same first side as A
  if (as.size() >= 2 && prove_equal(sd[0], as[0], c.d.symbols, c.opt).kind == VerdictKind::Proved) {
    Combiner all;
    for (std::size_t i = 1; i < sd.size(); ++i)
      all.add(second_order_in_eps(c, as.back() - sd[i], small_ex, "side " + std::to_string(i + 1) + " against the last side of " + A.label),
              sd.size() > 2 ? "side " + std::to_string(i + 1) : "");
    return all.result();
  }
  // 2b. A defines a quantity q = expr (q not small): q replaced by expr in the claim
  if (as.size() >= 2 && GiNaC::is_a<GiNaC::symbol>(as[0]) && !as.back().has(as[0]) &&
      std::none_of(small_ex.begin(), small_ex.end(), [&](const ex& s) { return s.is_equal(as[0]); })) {
    Combiner all;
    for (std::size_t i = 1; i < sd.size(); ++i) {
      const ex d = (sd[0] - sd[i]).subs(as[0] == as.back(), GiNaC::subs_options::no_pattern);
      all.add(second_order_in_eps(c, d, small_ex, c.text(as[0]) + " replaced by its value in " + A.label),
              sd.size() > 2 ? "side " + std::to_string(i + 1) : "");
    }
    return all.result();
  }
  // 3. one small quantity eliminated with A's first-order part
  if (singular.empty() && truncated.size() == 1) {
    const ex lin = truncated[0].expand();
    GiNaC::exmap zero;
    for (const ex& s : small_ex) zero[s] = 0;
    bool homogeneous = false;
    try {
      homogeneous = GiNaC::normal(lin.subs(zero, GiNaC::subs_options::no_pattern)).is_zero();
    } catch (const std::exception&) {
    }
    if (homogeneous) {
      for (std::size_t j = 0; j < small_ex.size(); ++j) {
        const ex cj = lin.coeff(small_ex[j], 1);
        if (cj.is_zero() || !detail::provably_nonzero(cj, c.d.symbols)) continue;
        const ex dj = GiNaC::normal(small_ex[j] - lin / cj);   // d_j from c_j d_j + rest = 0
        if (dj.has(small_ex[j])) continue;
        std::vector<ex> others;
        for (std::size_t i = 0; i < small_ex.size(); ++i)
          if (i != j) others.push_back(small_ex[i]);
        // d_j on A is dj + O(eps^2); replacing it by dj changes a side by O(eps^2) only when the
        // side's derivative in d_j stays bounded there (not for dv/dm)
        bool smooth = true;
        for (std::size_t i = 0; i < sd.size() && smooth; ++i) {
          const ex dd = GiNaC::diff(sd[i], GiNaC::ex_to<GiNaC::symbol>(small_ex[j]))
                            .subs(small_ex[j] == dj, GiNaC::subs_options::no_pattern);
          smooth = bounded_in_eps(c, dd, others);
        }
        if (!smooth)
          return undecided("first order", "the claim does not follow from the first-order part of " + A.label +
                                              ", and with " + c.text(small_ex[j]) + " = " + c.text(dj) +
                                              " from it a side's derivative in " + c.text(small_ex[j]) +
                                              " is not shown bounded, so the O(eps^2) error of that form "
                                              "need not stay O(eps^2) in the claim");
        Combiner all;
        for (std::size_t i = 1; i < sd.size(); ++i) {
          const ex d = (sd[0] - sd[i]).subs(small_ex[j] == dj, GiNaC::subs_options::no_pattern);
          all.add(second_order_in_eps(c, d, others, c.text(small_ex[j]) + " = " + c.text(dj) + " from the first-order part of " + A.label),
                  sd.size() > 2 ? "side " + std::to_string(i + 1) : "");
        }
        return all.result();
      }
    }
  }
  if (!singular.empty())
    return undecided("first order", singular + "; and the claim's first side is not " + A.label + "'s");
  return undecided("first order",
                   "the claim does not follow from the first-order part of " + A.label + " (" + t.detail +
                       "), and it cannot be compared to first order: its first side is not " + A.label +
                       "'s, and the first-order part of " + A.label + " gives none of " + names_of(small_ex, c) +
                       " in terms of the others (a term of order 0, or no coefficient nonzero by the declarations)");
}

}  // namespace dc::rules
