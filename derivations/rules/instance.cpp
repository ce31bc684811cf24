// `KE1 = m*v1^2/2  by instance of ke [with x = value, ...]`: the claim is the cited law with its
// symbols renamed. The rule searches for the renaming: a function from the law's symbols (those
// the author pins with `with` aside, which may map to any expression) to the claim's symbols of
// the same dimension, or to themselves. The law read as written (its first and last sides; a
// name a step defined is the name, not its value) is renamed and compared side by side with the
// claim, in either order, by prove_equal: only a renaming under which both sides are proved (or
// hold numerically) equal proves the claim, and the renaming is the evidence.
//   - Candidates are tried in an order of preference: a symbol the claim also uses maps to itself
//     first (g stays g), then to claim symbols whose names extend its own (v -> v1), then to the
//     others. A prefilter at one double-precision point skips the hopeless ones; it never
//     decides a verdict.
//   - The law says nothing outside its own declarations: a renamed symbol's declared domain must
//     lie inside the law symbol's (v positive -> v1 real is undecided), and an assumption on the
//     law's symbols (`assume v < c`) must be declared for their images too, or the step is
//     undecided naming it.
//   - Refuted when every renaming (at most kCertifyAtMost) is refuted, each by a certified
//     counterexample on one side in both orders; the evidence shown is the preferred one's.
//     Declared functions are not renamed (a law about x(t) is one about x).
#include <algorithm>
#include <cmath>
#include <string>

#include "derivations/rules/dispatch.hpp"
#include "derivations/rules/in_domain.hpp"

namespace dc::rules {

namespace {

constexpr std::size_t kSearchAtMost = 4096;
constexpr std::size_t kCertifyAtMost = 24;

const SymbolInfo* info_of(const SymbolTable& t, const ex& s) {
  for (const auto& info : t.all())
    if (!info.is_function && info.sym.is_equal(s)) return &info;
  return nullptr;
}

double num(const ex& e) { return GiNaC::ex_to<GiNaC::numeric>(e.evalf()).to_double(); }
bool constant(const ex& e) { return GiNaC::is_a<GiNaC::numeric>(e.evalf()); }

// Every value of `in` is a value of `out` (conservative: false when not evident).
bool domain_within(const Domain& in, const Domain& out) {
  using K = Domain::Kind;
  if (out.kind == K::Real) return true;
  auto lo_at_least = [&](double b, bool strict) {   // every value of `in` > b (strict) or >= b
    if (in.kind == K::Positive) return b <= 0;
    if (in.kind == K::Nonnegative) return b < 0 || (b == 0 && !strict);
    if (in.kind != K::Interval || !constant(in.lo)) return false;
    const double l = num(in.lo);
    return l > b || (l == b && (!strict || in.lo_open));
  };
  auto hi_at_most = [&](double b, bool strict) {
    if (in.kind == K::Negative) return b >= 0;
    if (in.kind != K::Interval || !constant(in.hi)) return false;
    const double h = num(in.hi);
    return h < b || (h == b && (!strict || in.hi_open));
  };
  if (in.kind == out.kind && out.kind != K::Interval) return true;
  if (out.kind == K::Positive) return lo_at_least(0, true);
  if (out.kind == K::Nonnegative) return lo_at_least(0, false);
  if (out.kind == K::Negative) return hi_at_most(0, true);
  if (!constant(out.lo) || !constant(out.hi)) return false;
  return lo_at_least(num(out.lo), out.lo_open) && hi_at_most(num(out.hi), out.hi_open);
}

// How well claim symbol b continues law symbol a: v1 for v (2), same first letter (1).
int likeness(const std::string& a, const std::string& b) {
  if (b.size() > a.size() && b.compare(0, a.size(), a) == 0) return 2;
  return !a.empty() && !b.empty() && a[0] == b[0] ? 1 : 0;
}

// A double-precision look at one point: false only when the two are certainly far apart in
// doubles (then the renaming is not worth a proof attempt); never used as a verdict.
bool maybe_equal(const ex& a, const ex& b, const GiNaC::exmap& pt) {
  try {
    const ex va = a.subs(pt, GiNaC::subs_options::no_pattern).evalf();
    const ex vb = b.subs(pt, GiNaC::subs_options::no_pattern).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(va) || !GiNaC::is_a<GiNaC::numeric>(vb)) return true;
    const auto na = GiNaC::ex_to<GiNaC::numeric>(va), nb = GiNaC::ex_to<GiNaC::numeric>(vb);
    if (!na.is_real() || !nb.is_real()) return true;
    const double x = na.to_double(), y = nb.to_double();
    return std::abs(x - y) <= 1e-6 * std::max({std::abs(x), std::abs(y), 1e-12});
  } catch (const std::exception&) {
    return true;
  }
}

}  // namespace

Verdict instance(StepContext& c, const Relation& claim) {
  const RuleSpec& rule = c.rule();
  const SymbolTable& t = c.d.symbols;
  const Step& law_step = c.ref_step(rule.into[0]);
  const Relation& law = claim_of(law_step);
  if (law.sides.size() < 2) c.fail(rule.into[0].pos, "'" + law_step.label + "' is no equation: nothing to apply", rule.into[0].length);
  if (claim.sides.size() != 2) c.fail(c.s.claim_pos, "the claim of 'by instance' is one equation 'a = b'");
  const ex L0 = to_ginac(law.sides.front(), t), L1 = to_ginac(law.sides.back(), t);
  const ex C0 = to_ginac(claim.sides[0], t), C1 = to_ginac(claim.sides[1], t);
  const std::vector<ex> law_syms = c.symbols_in({L0, L1});
  const std::vector<ex> claim_syms = c.symbols_in({C0, C1});

  // `with x = value`: pinned images
  GiNaC::exmap pinned;
  std::vector<std::string> pinned_text;
  for (const auto& w : rule.with) {
    const Node& lhs = w.equation.sides[0];
    const ex a = to_ginac(lhs, t);
    if (lhs.kind != NodeKind::Symbol || std::none_of(law_syms.begin(), law_syms.end(), [&](const ex& s) { return s.is_equal(a); }))
      c.fail(w.pos, "'" + to_text(lhs) + "' is not a symbol of the law '" + law_step.label + "'", w.length);
    pinned[a] = to_ginac(w.equation.sides[1], t);
    pinned_text.push_back(c.text(a) + " -> " + c.text(pinned[a]));
  }
  // candidates of every other law symbol, in order of preference
  std::vector<ex> free;
  std::vector<std::vector<ex>> cand;
  std::size_t count = 1;
  for (const auto& a : law_syms) {
    if (pinned.count(a)) continue;
    const SymbolInfo* ai = info_of(t, a);
    std::vector<std::pair<int, ex>> scored;
    bool self_in_claim = false;
    for (std::size_t i = 0; i < claim_syms.size(); ++i) {
      const ex& b = claim_syms[i];
      if (b.is_equal(a)) { self_in_claim = true; continue; }
      const SymbolInfo* bi = info_of(t, b);
      if (ai && bi && ai->has_dimension && bi->has_dimension && !(ai->dimension == bi->dimension)) continue;
      scored.push_back({ai && bi ? likeness(ai->name, bi->name) : 0, b});
    }
    std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    std::vector<ex> list;
    if (self_in_claim) list.push_back(a);
    for (const auto& s : scored) list.push_back(s.second);
    if (!self_in_claim) list.push_back(a);
    free.push_back(a);
    cand.push_back(list);
    count *= list.size();
    if (count > kSearchAtMost)
      return undecided("instance", "too many renamings of the law's symbols to search (more than " +
                                       std::to_string(kSearchAtMost) + "): state some with 'with x = value'");
  }

  // one point for the prefilter: every symbol of law and claim at a distinct value in (1/2, 2)
  GiNaC::exmap pt;
  {
    int k = 0;
    for (const auto* group : {&law_syms, &claim_syms})
      for (const auto& s : *group)
        if (!pt.count(s)) pt[s] = GiNaC::numeric(53 + 37 * (k++ % 29), 71);
  }
  auto renaming_of = [&](const std::vector<std::size_t>& idx) {
    GiNaC::exmap m = pinned;
    for (std::size_t i = 0; i < free.size(); ++i) m[free[i]] = cand[i][idx[i]];
    return m;
  };
  auto describe = [&](const GiNaC::exmap& m) {
    std::string moved, kept;
    for (const auto& a : law_syms) {
      const ex b = m.count(a) ? m.at(a) : a;
      if (b.is_equal(a)) kept += (kept.empty() ? "" : ", ") + c.text(a);
      else moved += (moved.empty() ? "" : ", ") + c.text(a) + " -> " + c.text(b);
    }
    return (moved.empty() ? std::string("no symbol renamed") : moved) + (kept.empty() ? "" : " (" + kept + " unchanged)");
  };
  auto rename = [&](const ex& e, const GiNaC::exmap& m) { return e.subs(m, GiNaC::subs_options::no_pattern); };

  // enumerate, preferred first
  std::vector<std::size_t> idx(free.size(), 0);
  // each renaming with the law it gives; one under which the law has no value (c -> v1 and
  // v -> v1 in 1/sqrt(1 - v^2/c^2)) cannot make it the claim and is left out
  struct Renamed { GiNaC::exmap m; ex R0, R1; };
  std::vector<Renamed> all_renamings;
  for (std::size_t n = 0; n < count; ++n) {
    GiNaC::exmap m = renaming_of(idx);
    try {
      const ex R0 = rename(L0, m), R1 = rename(L1, m);
      all_renamings.push_back({m, R0, R1});
    } catch (const std::exception&) {
    }
    for (std::size_t i = free.size(); i-- > 0;) {
      if (++idx[i] < cand[i].size()) break;
      idx[i] = 0;
    }
  }
  std::string law_text = to_text(law.sides.front()) + " = " + to_text(law.sides.back());
  std::optional<Verdict> domain_trouble;
  for (const auto& [m, R0, R1] : all_renamings) {
    for (int order = 0; order < 2; ++order) {
      const ex& A = order ? R1 : R0;
      const ex& B = order ? R0 : R1;
      if (!maybe_equal(C0, A, pt) || !maybe_equal(C1, B, pt)) continue;
      Combiner both;
      both.add(prove_equal(C0, A, t, c.opt), "left side");
      if (both.result().holds()) both.add(prove_equal(C1, B, t, c.opt), "right side");
      Verdict v = both.result();
      if (!v.holds()) continue;
      c.res.derived = c.text(R0) + " = " + c.text(R1);
      // the law's declarations must cover the images
      std::string needs;
      for (const auto& [a, b] : m) {
        const SymbolInfo* ai = info_of(t, a);
        if (!ai || b.is_equal(a)) continue;
        if (GiNaC::is_a<GiNaC::symbol>(b)) {
          const SymbolInfo* bi = info_of(t, b);
          if (bi && !domain_within(bi->domain, ai->domain))
            needs += (needs.empty() ? "" : "; ") + c.text(b) + " is declared " + bi->domain.to_string() + " but the law's " +
                     c.text(a) + " is " + ai->domain.to_string();
        } else if (ai->domain.kind != Domain::Kind::Real) {
          Verdict in = value_in_domain(b, ai->domain, t, c.opt);
          if (!in.holds())
            needs += (needs.empty() ? "" : "; ") + c.text(b) + " is not shown to lie in the law's domain of " + c.text(a) +
                     " (" + ai->domain.to_string() + ")";
        }
      }
      for (const auto& k : t.constraints()) {
        const ex lhs = rename(k.lhs, m), rhs = rename(k.rhs, m);
        if (lhs.is_equal(k.lhs) && rhs.is_equal(k.rhs)) continue;
        const bool declared = std::any_of(t.constraints().begin(), t.constraints().end(), [&](const Constraint& o) {
          const ex d = GiNaC::normal(o.lhs - o.rhs - (lhs - rhs)), s = GiNaC::normal(o.lhs - o.rhs + (lhs - rhs));
          return (o.op == k.op && d.is_zero()) || (o.op == flipped(k.op) && s.is_zero());
        });
        if (!declared)
          needs += (needs.empty() ? "" : "; ") + std::string("the law assumes ") + k.text + ", so the instance needs 'assume " +
                   c.text(lhs) + " " + op_text(k.op) + " " + c.text(rhs) + "'";
      }
      const std::string found = "instance of '" + law_step.label + "' (" + law_text + ") with " + describe(m) +
                                (order ? ", sides exchanged" : "");
      if (!needs.empty()) {
        if (!domain_trouble) domain_trouble = undecided("instance", found + ", but " + needs);
        continue;
      }
      v.method = prefix_method("instance", v.method);
      v.detail = found + (v.detail.empty() ? "" : "; " + v.detail);
      return v;
    }
  }
  if (domain_trouble) return *domain_trouble;

  // nothing holds: refuted only when each renaming is refuted, in both orders, with a point
  const std::string none = "no renaming of the symbols of '" + law_step.label + "' (" + law_text +
                           ") into the claim's symbols of the same dimensions makes it the claim";
  if (all_renamings.size() > kCertifyAtMost)
    return undecided("instance", none + " at a sampled point; " + std::to_string(all_renamings.size()) +
                                     " renamings are too many to certify each (state the renaming with 'with x = value')");
  std::optional<Verdict> evidence;
  if (all_renamings.empty())
    return undecided("instance", none + ": the law has no value under any renaming of matching dimensions");
  for (const auto& [m, R0, R1] : all_renamings) {
    for (int order = 0; order < 2; ++order) {
      const ex& A = order ? R1 : R0;
      const ex& B = order ? R0 : R1;
      Verdict v = prove_equal(C0, A, t, c.opt);
      if (v.kind != VerdictKind::Refuted) v = prove_equal(C1, B, t, c.opt);
      if (v.kind != VerdictKind::Refuted)
        return undecided("instance", none + " at a sampled point, but the renaming " + describe(m) +
                                         " is not refuted: " + (v.reason.empty() ? to_string(v.kind) : v.reason));
      if (!evidence) {
        evidence = v;
        evidence->detail = "the closest renaming, " + describe(m) + ", gives " + c.text(R0) + " = " + c.text(R1) + ", and the claim's " +
                           (prove_equal(C0, A, t, c.opt).kind == VerdictKind::Refuted ? "left" : "right") + " side differs";
        c.res.derived = c.text(R0) + " = " + c.text(R1);
      }
    }
  }
  Verdict r = *evidence;
  r.method = prefix_method("instance", r.method);
  r.detail = none + " (" + std::to_string(all_renamings.size()) + " renaming" + (all_renamings.size() == 1 ? "" : "s") +
             ", each refuted at a point in both orders); " + r.detail;
  return r;
}

}  // namespace dc::rules
