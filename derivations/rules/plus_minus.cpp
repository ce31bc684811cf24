#include "derivations/rules/plus_minus.hpp"

#include <string>
#include <vector>

#include "derivations/steps/context.hpp"

namespace dc::rules {

namespace {

std::vector<const Step*> cited(const Derivation& d, const Step& s) {
  std::vector<const Step*> out;
  for (const auto* group : {&s.rule.refs, &s.rule.into, &s.rule.with})
    for (const auto& a : *group)
      if (a.kind == RuleArg::Kind::Label)
        if (const Step* st = d.find(a.label)) out.push_back(st);
  return out;
}

bool relation_has(const Relation& r) {
  for (const auto& side : r.sides)
    if (has_plus_minus(side)) return true;
  return false;
}

const char* sign_words(int sign) { return sign > 0 ? "with \u00B1 read as + (\u2213 as -)" : "with \u00B1 read as - (\u2213 as +)"; }

Node binary(NodeKind k, Node a, Node b, const SourcePos& pos) {
  Node n;
  n.kind = k;
  n.pos = pos;
  n.args.push_back(std::move(a));
  n.args.push_back(std::move(b));
  return n;
}

bool mentions_symbol(const Node& n, const std::string& x) {
  if (n.kind == NodeKind::Symbol && n.text == x) return true;
  for (const auto& a : n.args)
    if (mentions_symbol(a, x)) return true;
  return false;
}

// x replaced by value in n (a whole symbol)
Node replaced(const Node& n, const std::string& x, const Node& value) {
  if (n.kind == NodeKind::Symbol && n.text == x) {
    Node v = value;
    v.parenthesized = true;
    return v;
  }
  Node out = n;
  for (auto& a : out.args) a = replaced(a, x, value);
  return out;
}

// The two results in one: both hold (the weaker kind), or the sign that does not.
StepResult combined(StepResult plus, StepResult minus) {
  auto worse = [](const StepResult& r) { return severity(r.verdict.kind); };
  const bool minus_worse = worse(minus) > worse(plus);
  StepResult out = minus_worse ? std::move(minus) : std::move(plus);
  const int sign = minus_worse ? -1 : 1;
  if (out.verdict.holds()) {
    out.verdict.method = "both signs of \u00B1: " + out.verdict.method;
  } else {
    const std::string which = sign_words(sign);
    out.verdict.method = std::string(sign > 0 ? "\u00B1 read as +" : "\u00B1 read as -") + ": " + out.verdict.method;
    out.derived = out.derived.empty() ? which : which + ": " + out.derived;
  }
  return out;
}

}  // namespace

Node with_sign(const Node& n, int sign) {
  if (n.kind == NodeKind::Call && (n.text == "pm" || n.text == "mp") && (n.args.size() == 1 || n.args.size() == 2)) {
    const bool plus = (n.text == "pm") == (sign > 0);
    Node b = with_sign(n.args.back(), sign);
    if (b.kind == NodeKind::Add || b.kind == NodeKind::Sub || b.kind == NodeKind::Neg) b.parenthesized = true;
    Node out;
    if (n.args.size() == 2) {
      out = binary(plus ? NodeKind::Add : NodeKind::Sub, with_sign(n.args[0], sign), std::move(b), n.pos);
      out.op_pos = n.op_pos;
    } else if (plus) {
      out = std::move(b);
    } else {
      out.kind = NodeKind::Neg;
      out.pos = n.pos;
      out.args.push_back(std::move(b));
    }
    out.parenthesized = n.parenthesized;
    out.length = n.length;
    return out;
  }
  Node out = n;
  for (auto& a : out.args) a = with_sign(a, sign);
  return out;
}

bool mentions_plus_minus(const Derivation& d, const Step& s) {
  if (relation_has(claim_of(s))) return true;
  for (const Step* st : cited(d, s))
    if (relation_has(claim_of(*st))) return true;
  return false;
}

StepResult check_both_signs(const Derivation& d, const Step& s, const ProveOptions& opt, const CheckOne& one) {
  const Relation& claim = claim_of(s);
  bool refs_have = false;
  for (const Step* st : cited(d, s)) refs_have = refs_have || relation_has(claim_of(*st));
  // (only where the rule's claim is "follows from the references": a limit, series or integral
  // of a reference means something else, and is checked for each sign)
  const bool follows_rule = s.rule.name == "rewrite" || s.rule.name == "substitute" || s.rule.name == "solve";
  const bool values = follows_rule && !refs_have && !cited(d, s).empty() && claim.sides.size() == 2 &&
                      claim.sides[0].kind == NodeKind::Symbol && has_plus_minus(claim.sides[1]) &&
                      !s.erratum && !s.names_result;
  if (!values) {
    // the claim's signs and those of the steps it cites, chosen apart: the claim read with
    // claim_sign, the citations (converted under the scoped sign) with refs_sign
    auto run = [&](int claim_sign, int refs_sign) {
      Step c = s;
      for (auto& side : c.claim.sides) side = with_sign(side, claim_sign);
      if (c.erratum)
        for (auto& side : c.erratum->corrected.sides) side = with_sign(side, claim_sign);
      PlusMinusSign chosen(refs_sign);
      StepResult r = one(d, c, opt);
      r.step = &s;
      return r;
    };
    StepResult out = combined(run(1, 1), run(-1, -1));
    out.step = &s;
    if (!refs_have || out.verdict.holds()) return out;
    // Cited steps with ± too: the signs read alike (the upper with the upper) is the claim. An
    // author who means the opposite pairing writes ∓; one who does not may mean the pairing
    // loosely, so a claim that holds with the signs opposite is undecided, not refuted, and
    // only a claim false both ways is refuted.
    StepResult opposite = combined(run(1, -1), run(-1, 1));
    if (opposite.verdict.holds()) {
      Verdict v;
      v.kind = VerdictKind::Undecided;
      v.method = out.verdict.method;
      v.reason = "it holds with each \u00B1 read opposite to those of the steps it cites (write \u2213 where the "
                 "signs are opposite), not with them read alike";
      v.detail = v.reason;
      out.verdict = v;
      out.derived.clear();
      return out;
    }
    if (out.verdict.kind == VerdictKind::Refuted && opposite.verdict.kind != VerdictKind::Refuted) {
      Verdict v;
      v.kind = VerdictKind::Undecided;
      v.method = out.verdict.method;
      v.reason = "refuted with each \u00B1 read as in the steps it cites, but not with them read opposite: " +
                 (opposite.verdict.reason.empty() ? std::string("undecided") : opposite.verdict.reason);
      v.detail = v.reason;
      out.verdict = v;
      out.derived.clear();
    }
    return out;
  }
  // x = E±: the references' solutions are E+ and E-
  const std::string x = claim.sides[0].text;
  const Node e_plus = with_sign(claim.sides[1], 1), e_minus = with_sign(claim.sides[1], -1);
  Step both = s;
  both.rule.name = "rewrite";
  both.rule.refs.insert(both.rule.refs.end(), s.rule.into.begin(), s.rule.into.end());
  both.rule.into.clear();
  both.rule.unknowns.clear();
  Node left = binary(NodeKind::Sub, claim.sides[0], e_plus, claim.sides[0].pos);
  left.parenthesized = true;
  Node right = binary(NodeKind::Sub, claim.sides[0], e_minus, claim.sides[0].pos);
  right.parenthesized = true;
  Node zero;
  zero.kind = NodeKind::Number;
  zero.text = "0";
  zero.pos = claim.sides[1].pos;
  both.claim.sides = {binary(NodeKind::Mul, left, right, claim.sides[0].pos), zero};
  both.first_side_fresh = false;
  StepResult out = one(d, both, opt);
  out.step = &s;
  const std::string product = "(" + x + " - " + to_text(e_plus) + ")*(" + x + " - " + to_text(e_minus) + ") = 0";
  if (out.verdict.kind == VerdictKind::Refuted) {
    out.verdict.method = "both values of \u00B1: " + out.verdict.method;
    // (a side that is undefined at a point of the domain speaks for itself)
    const bool undefined_side = out.verdict.lhs_value.rfind("undefined", 0) == 0 || out.verdict.rhs_value.rfind("undefined", 0) == 0;
    if (!undefined_side)
      out.derived = "the references have a solution that is neither value of " + x + ": " + product + " does not follow";
    return out;
  }
  if (!out.verdict.holds()) {
    out.verdict.reason = "that the references' solutions are among the two values is not shown: " + out.verdict.reason;
    return out;
  }
  // each value is a solution: every reference that mentions x holds with x = E+ and with E-
  for (int sign : {1, -1}) {
    const Node& value = sign > 0 ? e_plus : e_minus;
    for (const Step* st : cited(d, s)) {
      const Relation& r = claim_of(*st);
      bool mentions = false;
      for (const auto& side : r.sides) mentions = mentions || mentions_symbol(side, x);
      if (!mentions || r.sides.size() < 2) continue;
      Step sub = s;
      sub.rule = RuleSpec{};
      sub.rule.name = "rewrite";
      sub.rule.with = s.rule.with;
      sub.claim.sides.clear();
      for (const auto& side : r.sides) sub.claim.sides.push_back(replaced(side, x, value));
      sub.first_side_fresh = false;
      sub.names_result = false;
      StepResult each = one(d, sub, opt);
      if (!each.verdict.holds()) {
        Verdict v;
        v.kind = VerdictKind::Undecided;
        v.method = out.verdict.method;
        v.reason = "the references' solutions are among the two values, but that " + x + " = " + to_text(value) +
                   " satisfies " + st->label + " is not shown (" + sign_words(sign) + ": " +
                   verdict_words(each.verdict.kind) + ")";
        v.detail = v.reason;
        out.verdict = v;
        return out;
      }
      if (each.verdict.kind == VerdictKind::HoldsNumerically && out.verdict.kind == VerdictKind::Proved)
        out.verdict.kind = VerdictKind::HoldsNumerically;
    }
  }
  out.verdict.method = "both values of \u00B1: " + out.verdict.method;
  out.verdict.detail = "the references imply " + product + ", and each value satisfies them" +
                       (out.verdict.detail.empty() ? "" : "; " + out.verdict.detail);
  return out;
}

}  // namespace dc::rules
