// Does the claim follow from the references? (follows.hpp)
#include "derivations/steps/follows.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "derivations/symbolic/functions.hpp"
#include "derivations/steps/counterexample.hpp"

namespace dc::rules {

namespace {

std::vector<std::string> source_labels(const std::vector<int>& sources, const std::vector<Eq>& eqs) {
  std::vector<int> idx = sources;
  std::sort(idx.begin(), idx.end());
  std::vector<std::string> out;
  auto add = [&](const std::string& l) {
    if (std::find(out.begin(), out.end(), l) == out.end()) out.push_back(l);
  };
  for (int i : idx) {
    add(eqs[i].from);
    for (const auto& l : eqs[i].also) add(l);
  }
  return out;
}

std::string quoted_list(const std::vector<std::string>& labels) {
  std::string out;
  for (std::size_t i = 0; i < labels.size(); ++i)
    out += (i == 0 ? "" : i + 1 == labels.size() ? " and " : ", ") + ("'" + labels[i] + "'");
  return out;
}

// The rule argument that names a label (for error positions); the rule itself otherwise.
std::pair<SourcePos, int> argument_position(const RuleSpec& rule, const std::string& label) {
  for (const auto* group : {&rule.refs, &rule.into, &rule.with})
    for (const auto& a : *group)
      if (a.label == label) return {a.pos, a.length};
  return {rule.pos, 2};
}

void application_args(const ex& e, std::vector<ex>& out) {
  if (pool_function_index(e) >= 0 && e.nops() >= 1) {
    for (const auto& o : out)
      if (o.is_equal(e.op(0))) return;
    out.push_back(e.op(0));
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) application_args(e.op(i), out);
}

// An equation between function applications of one parameter s (p(t) = m*v(t)) holds for
// every value of s: add its instances at the other arguments the claim uses (t1, t2). An
// equation without applications is between plain symbols, each one value: it is used as is.
// Is every function application in e at its function's declared parameter s (v(t) for a
// function declared v(t))? Only such an equation holds for every s: y(T) = 0 at the landing
// time T says nothing about y(t).
bool at_declared_parameter(const StepContext& c, const ex& e, const ex& s) {
  const int k = pool_function_index(e);
  if (k >= 0 && e.nops() >= 1) {
    for (const auto& info : c.d.symbols.all())
      if (info.is_function && c.d.symbols.function_index(info.name) == k) {
        if (info.params.size() != 1) return false;
        const SymbolInfo* p = c.d.symbols.find(info.params[0]);
        return p && p->sym.is_equal(s);
      }
    return false;
  }
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!at_declared_parameter(c, e.op(i), s)) return false;
  return true;
}

// A divisor of e (a base under a negative power) that the eliminations of `red` reduce to zero,
// as text; "" when there is none.
std::string divisor_made_zero(StepContext& c, const ex& e, const Reduction& red) {
  std::vector<ex> divisors;
  std::function<void(const ex&)> walk = [&](const ex& x) {
    if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_negative())
      divisors.push_back(x.op(0));
    for (std::size_t i = 0; i < x.nops(); ++i) walk(x.op(i));
  };
  walk(e);
  for (const auto& d : divisors) {
    try {
      if (GiNaC::normal(reduced(c, d, red)).is_zero()) return c.text(d);
    } catch (const std::exception&) {
      return c.text(d);   // dividing by zero while reducing it
    }
  }
  return "";
}

std::vector<Eq> instantiate(const StepContext& c, const std::vector<Eq>& eqs, const ex& claim) {
  // the points: where the claim and the references apply the functions (x0 = A cos(phi) from
  // x(0) = x0 and x(t) = A cos(omega t + phi) needs the latter at t = 0)
  std::vector<ex> want;
  application_args(claim, want);
  for (const auto& q : eqs) application_args(q.e, want);
  std::sort(want.begin(), want.end(), [&](const ex& x, const ex& y) { return c.text(x) < c.text(y); });
  std::vector<Eq> out = eqs;
  if (want.empty()) return out;
  // the derivatives the claim or a reference takes (v'(t)): a reference's derivative is used
  // only when it brings in no other (m v'' + b v' = 0 beside m v' + b v = 0 would let the elimination
  // pin m = b = 0, where the claim is undefined)
  // (a derivative by its function and order, wherever it is applied: p'(t) and p'(t2) alike)
  using Key = std::pair<unsigned, std::vector<unsigned>>;
  std::set<Key> claim_derivatives;
  std::function<void(const ex&, std::set<Key>&)> derivatives = [&](const ex& e, std::set<Key>& out) {
    if (GiNaC::is_a<GiNaC::fderivative>(e)) {
      const auto& f = GiNaC::ex_to<GiNaC::fderivative>(e);
      out.insert({f.get_serial(), std::vector<unsigned>(f.derivatives().begin(), f.derivatives().end())});
    }
    for (std::size_t i = 0; i < e.nops(); ++i) derivatives(e.op(i), out);
  };
  derivatives(claim, claim_derivatives);
  const bool claim_has_derivative = !claim_derivatives.empty();
  for (const auto& q : eqs) derivatives(q.e, claim_derivatives);   // or that a reference takes
  for (const auto& q : eqs) {
    std::vector<ex> args;
    application_args(q.e, args);
    if (args.size() != 1 || !GiNaC::is_a<GiNaC::symbol>(args[0]) || !at_declared_parameter(c, q.e, args[0])) continue;
    const GiNaC::symbol& s = GiNaC::ex_to<GiNaC::symbol>(args[0]);
    // it holds for every s, so its derivative in s holds too (p(t) = m v(t) gives p' = m v')
    std::vector<ex> forms{q.e};
    if (claim_has_derivative) {
      ex d = q.e.diff(s);
      std::set<Key> brought;
      derivatives(d, brought);
      bool only_the_claims = true;
      for (const auto& x : brought) only_the_claims = only_the_claims && claim_derivatives.count(x);
      if (!d.is_zero() && only_the_claims) forms.push_back(d);
    }
    for (std::size_t k = 0; k < forms.size(); ++k) {
      if (k > 0) out.push_back({forms[k], ex(), q.from});
      for (const auto& w : want)
        if (!w.is_equal(args[0]))
          out.push_back({forms[k].subs(args[0] == w, GiNaC::subs_options::no_pattern), ex(), q.from});
    }
  }
  return out;
}

}  // namespace

std::string reference_names(const std::vector<int>& sources, const std::vector<Eq>& eqs) {
  std::vector<std::string> labels = source_labels(sources, eqs);
  return (labels.size() == 1 ? "reference " : "references ") + quoted_list(labels);
}

void reject_contradictions(StepContext& c, const Reduction& red, const std::vector<Eq>& eqs) {
  for (const auto& l : red.leftover) {
    ex e = c.atoms.restore(l.e);
    if (!free_of_unknowns(e)) continue;
    bool contradiction = GiNaC::is_a<GiNaC::numeric>(e)
                             ? !e.is_zero()
                             : prove_zero(e, c.d.symbols, c.opt).kind == VerdictKind::Refuted;
    if (!contradiction) continue;
    std::vector<std::string> labels = source_labels(l.sources, eqs);
    std::string msg = labels.size() == 1
                          ? "the reference '" + labels[0] + "' contradicts itself: it leaves " + c.text(e) + " = 0"
                          : "the references " + quoted_list(labels) + " contradict each other: together they leave " +
                                c.text(e) + " = 0";
    if (!l.used.empty()) {
      std::string names;
      for (const auto& u : l.used) names += (names.empty() ? "" : ", ") + c.text(c.atoms.restore(u));
      msg += " (after eliminating " + names + ")";
    }
    auto [pos, len] = argument_position(c.rule(), labels.back());
    throw StepError{positioned(c.d, pos, msg, len), true};
  }
}

bool has_application_at(const ex& e, const ex& s) {
  if (pool_function_index(e) >= 0 && e.nops() >= 1 && e.op(0).is_equal(s)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_application_at(e.op(i), s)) return true;
  return false;
}

// Does the proof rest on one component of the references' solution set? The eliminations divide
// by coefficients that are nonzero generically, but where the references' solution set has
// several components (m_r*g = 0; or u_e*mu = 0 hidden in three equations) a division by a
// quantity that vanishes on one of them keeps only the others, and there a quantity may be
// forced to zero. Two signs of it, each with a description returned ("" when neither):
//  - an elimination read a product that is zero as one of its factors (reads_one_factor);
//  - a symbol's value is identically zero once every elimination is in, though nothing
//    written as `x = number` (D = 0, e = 1, m_1/m_2 = 0) makes its own equation say so (u_e = 0
//    from m_r*a = u_e*mu - m_r*g, its derivative in t and m_r*v' = -u_e*m_r' - m_r*g).
// The claim x = 0 itself (a = 0 from m*a = F, F = 0) is the cancellation the author made, and
// the claim c*x = 0 is what the references say: both are exempt (up to a number), a claim that
// merely has x as a factor is not.
static std::string pinned_product(StepContext& c, const Reduction& red, const ex& claim) {
  const ex t = c.atoms(claim);
  // the claim is x = 0 (or the zero product itself), up to a number: not m*(g + v^2/L - …) = 0,
  // which m = 0 would "prove" whatever the bracket
  auto claim_is = [&](const ex& x) {
    try {
      return !x.is_zero() && !t.is_zero() && GiNaC::is_a<GiNaC::numeric>(GiNaC::normal(t / x));
    } catch (const std::exception&) {
      return false;
    }
  };
  auto zero = [](const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return e.is_zero();
    if (GiNaC::is_a<GiNaC::symbol>(e)) return false;
    try {
      return GiNaC::normal(e).is_zero();
    } catch (const std::exception&) {
      return false;
    }
  };
  // x = 0, e = 1 as written (a number times x, and a number), and the factor the claim itself
  // reads as zero: what a symbol's value may be zero because of
  GiNaC::exmap written;
  for (const auto& el : red.eliminated)
    if ((!el.factor_of_zero && GiNaC::is_a<GiNaC::numeric>(el.coef_checked) &&
         GiNaC::is_a<GiNaC::numeric>(el.value_then)) ||
        (el.factor_of_zero && (claim_is(el.var) || claim_is(el.product))))
      written[el.var] = el.value_then;
  // (the cheap tests first: claim_is and zero normalise)
  for (const auto& el : red.eliminated) {
    if (el.factor_of_zero) {
      if (claim_is(el.var) || claim_is(el.product)) continue;
      return c.text(c.atoms.restore(el.product)) + " = 0";
    }
    // (a symbol only: a derivative that the references make zero, E'(t) = 0 from Newton's
    // law, is what they say, not a component)
    if (written.count(el.var) || !GiNaC::is_a<GiNaC::symbol>(c.atoms.restore(el.var)) || !zero(el.value)) continue;
    if (claim_is(el.var)) continue;
    if (!zero(el.value_then.subs(written, GiNaC::subs_options::no_pattern)))
      return c.text(c.atoms.restore(el.var)) + " = 0";
  }
  return "";
}

// follows() on the equations as given (instantiated: false) or with their instances at the
// claim's points and their derivatives (true).
static Verdict follows_from(StepContext& c, const ex& a, const ex& b, const std::vector<Eq>& eqs0,
                            const std::vector<ex>& preferred, bool instantiated, bool* pinned, bool* gap_out = nullptr) {
  std::vector<Eq> eqs = instantiated ? instantiate(c, eqs0, a - b) : eqs0;
  Bans bans;
  Reduction red;
  Verdict v;
  for (int attempt = 0;; ++attempt) {
    red = reduce(c, eqs, a - b, preferred, false, bans);
    reject_contradictions(c, red, eqs);
    ex ra = reduced(c, a, red), rb = reduced(c, b, red);
    v = prove_equal(ra, rb, c.d.symbols, c.opt);
    if (v.kind != VerdictKind::Refuted) break;
    Gap gap = counterexample_gap(c, red, eqs, v);
    // a divisor of the claim that the eliminations make zero (m = b = 0 from m v' = -b v and
    // its derivative): the point is one where the claim is undefined, no counterexample
    if (gap.why.empty())
      if (std::string d = divisor_made_zero(c, a - b, red); !d.empty())
        gap.why = "the eliminations make the claim's divisor " + d + " zero there";
    if (gap.why.empty()) break;
    if (gap.elimination && attempt < 4) {
      // That choice banned; when the same quantity is eliminated again (the references hold at
      // several points, each instance can eliminate it), it is banned from every equation: it
      // stays free, sampled in its declared domain.
      const std::string& key = gap.elimination->key;
      const bool again = std::any_of(bans.begin(), bans.end(), [&](const auto& b) { return b.second == key; });
      bool added = bans.insert({gap.elimination->equation, key}).second;
      if (again)
        for (int i = 0; i < static_cast<int>(eqs.size()); ++i) added = bans.insert({i, key}).second || added;
      if (added) continue;
    }
    // no other elimination left, and the point's eliminated quantities leave their declared
    // domain (c < 0 for a positive c): other points of the same reduction may stay inside it
    // (fixed seeds: deterministic)
    for (int k = 1; k <= 8 && gap.why.find("outside its domain") != std::string::npos; ++k) {
      ProveOptions o = c.opt;
      o.seed = c.opt.seed + 104729u * static_cast<unsigned>(k);
      Verdict w = prove_equal(ra, rb, c.d.symbols, o);
      if (w.kind != VerdictKind::Refuted) break;
      Gap g = counterexample_gap(c, red, eqs, w);
      if (g.why.empty()) v = w;
      gap = g;
    }
    if (gap.why.empty()) break;
    std::string after = red.eliminated.empty() ? "" : " after eliminating " + eliminated_text(c, red);
    Verdict u = undecided(v.method, "the difference does not vanish" + after + ", but " + gap.why);
    u.residual = c.text(ra - rb);
    v = u;
    if (gap_out) *gap_out = true;   // (the point fails a reference: follows() may reorder)
    break;
  }
  if (red.degenerate && v.holds())
    v = undecided(v.method, "every order of elimination divides by a coefficient that vanishes identically");
  // The eliminations cover the solution set of the references only where every coefficient
  // divided by is nonzero; a product read as one of its factors (m_r*g = 0 read as m_r = 0)
  // covers one component of it, and from m_r = 0 anything about m_r follows.
  if (v.holds())
    if (std::string p = pinned_product(c, red, a - b); !p.empty() && (*pinned = true))
      v = undecided(v.method, "the proof holds where the references give " + p + ", " + kOneComponent +
                                  " (it divides by a quantity that is zero on another); not shown on the others");
  if (red.resource_limit && !v.holds()) {
    v = undecided(v.method,
                  "resource limit: an equation would expand beyond " + std::to_string(c.opt.max_terms) + " terms");
  }
  if (!red.eliminated.empty()) {
    std::string el = "eliminating " + eliminated_text(c, red) + " with the references";
    v.detail = v.detail.empty() ? el : v.detail + "; " + el;
  }
  return v;
}

Verdict follows(StepContext& c, const ex& a, const ex& b, const std::vector<Eq>& eqs0, const std::vector<ex>& preferred) {
  if (eqs0.empty()) return prove_equal(a, b, c.d.symbols, c.opt);
  bool pinned = false, gap = false;
  Verdict v = follows_from(c, a, b, eqs0, preferred, true, &pinned, &gap);
  // the elimination takes the references in their order, and which quantities it eliminates
  // decides whether the point it leaves satisfies them all (`gamma = 1/sqrt(1 - v^2/c^2)`
  // before `beta = v/c` leaves `gamma*sqrt(1 - beta^2) = 1` unfixed): a point that does not is
  // no counterexample, so the references are taken once more, the first last (one more try:
  // each costs a whole elimination). Either verdict carries its own evidence (a refutation
  // only at a point that satisfies them all).
  if (gap && !pinned && eqs0.size() > 1 && c.opt.reorder_references) {
    std::vector<Eq> rotated(eqs0.begin() + 1, eqs0.end());
    rotated.push_back(eqs0.front());
    bool again = false;
    Verdict w = follows_from(c, a, b, rotated, preferred, true, &again);
    if (!again && (w.holds() || w.kind == VerdictKind::Refuted)) return w;
  }
  // the instances may be what pins (m_r = m_r(t) and its derivative in t give m_r' = 0): the
  // equations as written may prove the claim without them
  if (pinned) {
    bool again = false;
    Verdict w = follows_from(c, a, b, eqs0, preferred, false, &again);
    if (w.holds() && !again) return w;
  }
  return v;
}

Verdict links_follow(StepContext& c, const std::vector<ex>& sd, const std::vector<Eq>& eqs,
                     const std::string& rule_method, const std::vector<ex>& preferred) {
  Combiner all;
  for (std::size_t i = 0; i + 1 < sd.size(); ++i) {
    Verdict v = follows(c, sd[i], sd[i + 1], eqs, preferred);
    v.method = prefix_method(rule_method, v.method);
    all.add(v, sd.size() > 2 ? "link " + std::to_string(i + 1) + " (" + c.text(sd[i]) + " = " + c.text(sd[i + 1]) + ")"
                             : "");
  }
  return all.result();
}

}  // namespace dc::rules
