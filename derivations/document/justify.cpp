// The justification search for a document step (document.hpp).
//
// The author wrote no rule, so the checker tries, in order:
//   1. the relation is an identity (`rewrite` with no references: the link of a chain, a limit
//      or a derivative carried out);
//   2. a relation that mentions a name no earlier row mentions is a given (a law or a
//      definition), listed as such so the author sees what was taken on faith;
//   3. it follows from earlier rows (`rewrite` with references: elimination, then
//      prove_equal), trying small sets first: the rows the author cites with the inline
//      givens in force, then the nearest rows, then more of them.
// The first proof wins; its rule and the rows it used are the evidence.
//
// A refutation is the second worst wrong call, and a document says much that the search does
// not read: a regime in words ("m_2 can be considered infinite", "neglecting …"), a physical
// law stated as the next link of a chain, a name that is a function of time in one display and
// a constant in another. So a counterexample found against some earlier rows refutes the row
// only where its reading is not in doubt: an equation (not ≈ or an inequality), no limit,
// derivative or integral in it, no words of a regime or a law in the prose before the display,
// and no declaration under which it would hold. Anything else is undecided with the reason.
#include <algorithm>
#include <functional>
#include <map>
#include <cctype>

#include "derivations/document/search.hpp"
#include "derivations/steps/follows.hpp"
#include "derivations/syntax/document.hpp"

namespace dc {
namespace document_detail {

void names_of(const Node& n, std::set<std::string>& out) {
  if (n.kind == NodeKind::Symbol && !is_reserved_name(n.text)) out.insert(n.text);
  if (n.kind == NodeKind::Call && !is_reserved_name(n.text)) out.insert(n.text);
  for (const auto& a : n.args) names_of(a, out);
}

// The names of a step's claim without the variables of its functions (t in dp/dt says
// nothing about which rows a row uses or shares a quantity with).
static std::set<std::string> quantities_of(const Step& st) {
  std::set<std::string> out;
  for (const auto& side : st.claim.sides) names_of(side, out);
  for (const auto& n : std::set<std::string>(out))
    if (const std::size_t of = n.find("__of_"); of != std::string::npos) out.erase(n.substr(of + 5));
  return out;
}

void walk_nodes(const Node& n, const std::function<void(const Node&)>& f) {
  f(n);
  for (const auto& a : n.args) walk_nodes(a, f);
}

Derivation positive_reading(const Derivation& d, const std::set<std::string>& except) {
  Derivation out = d;
  for (const auto& info : d.symbols.all())
    if (!info.is_function && info.domain.unrestricted() && !except.count(info.name))
      out.symbols.narrow_domain(info.name, Domain::positive());
  out.index();
  return out;
}

void replace_calls(Node& n, const std::string& id, const Node& value) {
  if (n.kind == NodeKind::Call && n.text == id) {
    const SourcePos pos = n.pos;
    n = value;
    n.pos = pos;
    return;
  }
  for (auto& a : n.args) replace_calls(a, id, value);
}

void replace_names(Node& n, const std::map<std::string, Node>& values, const std::string& keep,
                   std::set<std::string>* replaced) {
  if (n.kind == NodeKind::Symbol && n.text != keep)
    if (auto it = values.find(n.text); it != values.end()) {
      const SourcePos pos = n.pos;
      if (replaced) replaced->insert(it->first);
      n = it->second;
      n.pos = pos;
      return;
    }
  for (auto& a : n.args) replace_names(a, values, keep, replaced);
}

bool has_call(const Node& n, const std::set<std::string>& names) {
  if (n.kind == NodeKind::Call && names.count(n.text)) return true;
  for (const auto& a : n.args)
    if (has_call(a, names)) return true;
  return false;
}

std::string join(const std::vector<std::string>& xs) {
  std::string out;
  for (const auto& x : xs) out += (out.empty() ? "" : ", ") + x;
  return out;
}

// Words in the prose before a display that announce a regime or a law: the row may hold only
// there, so the search's counterexample is no evidence against the author.
bool prose_names_a_regime(const std::string& hint, bool operations) {
  // whole words (a stem where its forms all say it: neglect, neglecting, neglected)
  static const char* const kStems[] = {"assum", "suppos", "approx", "neglect", "negligib", "ignor", "estimat",
                                       "lineari", "expan", "\\gg", "\\ll"};
  // operations on an equation the search does not follow (integrating it, differentiating it)
  static const char* const kOperations[] = {"integrat", "differentiat"};
  if (operations)
    for (const char* w : kOperations)
      if (hint.find(w) != std::string::npos) return true;
  static const char* const kWords[] = {"small", "smaller", "large", "larger", "infinite", "infinity", "much",
                                       "limit", "limiting", "tend", "tends", "tending", "roughly", "solution",
                                       "series", "expand"};
  static const char* const kPhrases[] = {"first order", "first-order", "second order", "second-order",
                                         "higher order", "higher-order", "leading order", "this order", "to order"};
  for (const char* w : kStems)
    if (hint.find(w) != std::string::npos) return true;
  for (const char* w : kPhrases)
    if (hint.find(w) != std::string::npos) return true;
  for (const char* w : kWords) {
    const std::string word = w;
    for (std::size_t p = hint.find(word); p != std::string::npos; p = hint.find(word, p + 1)) {
      const bool starts = p == 0 || !std::isalpha(static_cast<unsigned char>(hint[p - 1]));
      const std::size_t e = p + word.size();
      const bool ends = e >= hint.size() || !std::isalpha(static_cast<unsigned char>(hint[e]));
      if (starts && ends) return true;
    }
  }
  return false;
}

StepResult Search::run() {
  StepResult res;
  res.step = &s_;
  if (!row_.not_read.empty()) return finish(res, undecided("not read", row_.not_read));
  if (row_.relation == "inline") {
    res.premise = true;
    res.found_rule = "given";
    return finish(res, proved("given", "an equation in the text, in force for the display after it"));
  }
  if (row_.relation != "=" && row_.relation != "approx")
    return finish(res, undecided("not read", "inequalities ('" + row_.relation +
                                                          "') in a document are not checked yet"));
  // 1. an identity
  StepResult id = attempt({});
  if (id.verdict.holds() && usable(id)) return found(id, "identity", {});
  identity_refuted_ = usable(id) && id.verdict.kind == VerdictKind::Refuted && !side_condition_only(id.verdict);
  // 2. a new name: a given
  if (row_.relation == "=" && introduces_names()) {
    // new only as rates: dv/dt where the rows before speak of the increment Delta_v (and t
    // where they speak of Delta_t) — the rates of an earlier balance, if they follow from it
    bool rates_only = !nested_;
    std::set<std::string> before;
    for (const auto& st : d_.steps) {
      if (&st == &s_) break;
      for (const auto& side : st.claim.sides) names_of(side, before);
    }
    for (const auto& n : new_names_) {
      const std::size_t of = n.find("__of_");
      const std::string increment = "Delta_" + (of == std::string::npos ? n : n.substr(0, of));
      rates_only = rates_only && before.count(increment) > 0;
    }
    if (rates_only)
      if (auto r = by_rates()) return *r;
    // new only as functions: dv_y/dt where the rows before speak of v_y (a derivative of a
    // quantity an earlier row sets)
    // (its variable may be new too: t)
    bool functions_only = !nested_;
    std::set<std::string> variables;
    for (const auto& n : new_names_)
      if (const std::size_t of = n.find("__of_"); of != std::string::npos) variables.insert(n.substr(of + 5));
    for (const auto& n : new_names_) {
      const std::size_t of = n.find("__of_");
      functions_only = functions_only && (of != std::string::npos ? before.count(n.substr(0, of)) > 0 : variables.count(n) > 0);
    }
    if (functions_only)
      if (auto r = by_differentiation()) return *r;
    // a solution of an earlier rate row whose new names are its constants of integration
    if (!nested_)
      if (auto r = by_integration()) return *r;
    res.premise = true;
    res.found_rule = "given";
    Verdict v = proved("given", "introduces " + join(new_names_) + ": a law or a definition, taken as written");
    return finish(res, v);
  }
  // 3. follows from earlier rows
  Refutations refutations;
  int positive_tries = 0;
  for (const auto& refs : candidate_sets()) {
    if (late()) break;
    StepResult r = attempt(refs);
    if (!usable(r)) continue;
    // the rows with their plain names read at the instant, as the claim's functions
    if (!r.verdict.holds() && !late())
      if (auto lifted = attempt_lifted(refs); lifted && usable(*lifted) && lifted->verdict.holds()) r = *lifted;
    // a proof on one component of the rows' solutions: a slip among them may be what pins
    // (`v_1/v_0 = …` without its square root beside the two energy rows forces mu = 0)
    const bool one_component = r.verdict.kind == VerdictKind::Undecided &&
                               r.verdict.reason.find(rules::kOneComponent) != std::string::npos;
    if (r.verdict.holds() || one_component) {
      std::vector<std::string> slips;
      if (!rests_on_a_slip(refs, &slips) && r.verdict.holds()) return found(r, "rewrite", refs);
      // the same rows without the slip among them (a later row may follow from the right ones)
      std::vector<std::string> rest;
      for (const auto& l : refs)
        if (std::find(slips.begin(), slips.end(), l) == slips.end()) rest.push_back(l);
      if (!slips.empty() && rest.size() < refs.size() && !late()) {
        StepResult w = attempt(rest);
        if (usable(w) && w.verdict.holds() && !rests_on_a_slip(rest)) return found(w, "rewrite", rest);
      }
      if (voided_.empty() && !slips.empty() && r.verdict.holds())
        voided_ = "it follows from " + join(refs) + ", but " + join(slips) +
                  " among them is refuted, or left standing only by a doubt (a counterexample satisfies the rows "
                  "before it); a slip beside the row it garbles pins a quantity, and from that anything follows";
    }
    if (r.verdict.kind == VerdictKind::Refuted && rows_speak_of_claim(refs)) refutations.push_back({r, refs, false});
    // undecided where the names take any real value (V^gamma at a negative volume): the
    // reading with every undeclared name positive may still find a counterexample, which is
    // one of the unrestricted reading too
    if (r.verdict.kind == VerdictKind::Undecided && row_.relation == "=" && rows_speak_of_claim(refs) &&
        positive_tries++ < 3) {
      StepResult pos = attempt_positive(refs);
      if (usable(pos) && pos.verdict.kind == VerdictKind::Refuted && !side_condition_only(pos.verdict))
        refutations.push_back({pos, refs, false});
    }
  }
  // (a nested search only asks whether the row is refuted: the rules below only prove)
  if (!nested_) {
    // 4. a limit the row takes, or the regime an approximate row holds in (`$\mu \approx 0$`)
    if (auto r = by_limit()) return *r;
    // 5. solved for its subject from earlier rows (theta = arccos(...) from cos(theta) = ...)
    if (auto r = by_solve(refutations)) return *r;
    // 6. agreement to first order in the small quantities the text neglects
    if (auto r = by_first_order()) return *r;
    // 7. the rates of a balance of increments ("taking the time derivative")
    if (auto r = by_rates()) return *r;
  }
  if (row_.relation == "approx")
    return finish(res, undecided("approximation", "an approximate relation: it does not follow exactly "
                                                          "from the rows nearby, and the regime it holds in (first "
                                                          "order, a limit) is not searched yet"));
  // the first refutation whose reading is not in doubt refutes; otherwise the first doubt is
  // the reason the row stays undecided
  std::string first_doubt;
  std::vector<std::string> doubt_refs;
  bool doubt_names_declaration = false;
  for (auto [r, refs, solved] : refutations) {
    // a name of the claim or the rows that an earlier row in force sets: the counterexample must
    // satisfy that row too, so the set is widened by it (a few rounds) and tried again
    for (int round = 0; round < 3 && !late(); ++round) {
      const std::vector<std::string> more = unset_setters(refs);
      if (more.empty()) break;
      std::vector<std::string> wider = refs;
      wider.insert(wider.end(), more.begin(), more.end());
      // (no wider than a handful of rows: eliminating through many rows with radicals can
      // outrun any budget, and the doubt that asked for the widening then stands)
      if (wider.size() > kMaxWidened) break;
      StepResult w = attempt(wider);
      if (!usable(w)) break;
      if (w.verdict.holds() && !rests_on_a_slip(wider)) return found(w, "rewrite", wider);
      if (w.verdict.kind == VerdictKind::Undecided && row_.relation == "=" && !late()) {
        StepResult pos = attempt_positive(wider);   // ln(p_2/p_1) at negative pressures
        if (usable(pos) && pos.verdict.kind == VerdictKind::Refuted && !side_condition_only(pos.verdict)) w = pos;
      }
      if (w.verdict.kind != VerdictKind::Refuted) break;
      r = w;
      refs = wider;
    }
    // a given of this display among the rows may not be needed by the counterexample at all
    // (link 2 of `E = ½mv² - GMm/r = -GMm/r`, against `E = …` and `v² = GM/r`): without it,
    // a counterexample to the rest is no "one more law of the system". (Not so for a
    // differential equation for a function the row applies: without it the function's value is
    // free, and any value "refutes".)
    // (a chain that computes keeps the givens that introduce a name it uses, `\tfrac12 m v^2 =
    // G M m/R` beside `v = \sqrt{2 G M/R}`: see chain_computes)
    const std::vector<std::string> own = own_display_givens(refs);
    if (!own.empty() && !late()) {
      const bool computes = chain_computes(refs);
      std::set<std::string> mine;
      for (const auto& side : s_.claim.sides) names_of(side, mine);
      std::vector<std::string> rest;
      for (const auto& l : refs) {
        bool keep = std::find(own.begin(), own.end(), l) == own.end();
        if (!keep && computes)
          if (const Step* st = d_.find(l))
            for (const auto& n : new_names_of(*st)) keep = keep || mine.count(n) > 0;
        if (keep) rest.push_back(l);
      }
      StepResult w = rest.size() < refs.size() ? attempt(rest) : StepResult{};
      // (not when that leaves a name of the row unset that the dropped given sets: `R` of the
      // display's `R = m v/(qB)` would then be free)
      if (rest.size() < refs.size() && usable(w) && w.verdict.kind == VerdictKind::Refuted &&
          (unset_name(rest).empty() || !unset_name(refs).empty())) {
        r = w;
        refs = rest;
      }
    }
    std::string doubt = reading_in_doubt(r, refs);
    if (doubt.empty() && late())
      doubt = "the search used up its tries before it could check that the reading of the row is not in doubt";
    StepResult evidence = r;
    if (doubt.empty()) {
      // the document declares no signs: a counterexample at a negative mass or length is no
      // evidence unless one with every quantity positive is found too (and that one is
      // a counterexample of the unrestricted reading as well)
      const RuleSpec solve = solved ? solve_for_subject(refs) : RuleSpec{};
      StepResult pos = attempt_positive(refs, nullptr, solved ? &solve : nullptr);
      if (!usable(pos) || pos.verdict.kind != VerdictKind::Refuted || side_condition_only(pos.verdict) ||
          (solved && !substituted_back_refutes(pos)))
        doubt = "every counterexample found needs a negative value of a quantity the document declares no sign "
                "for" + std::string(pos.verdict.holds() ? " (the row holds when they are positive: declare "
                                                            "them positive, e.g. `symbol m : positive`)" : "");
      else
        evidence = pos;
    }
    if (doubt.empty()) {
      // the rows give only cos(theta) (or v^2, |v|): the row's choice of root is no slip,
      // but a slip in what the rows do give is one
      std::optional<StepResult> wrapped;
      doubt = branch_doubt(refs, wrapped);
      if (wrapped) return found(*wrapped, "rewrite", refs);
    }
    if (doubt.empty()) {
      const StepResult chosen = evidence;
      doubt = free_subject(chosen, refs, evidence);
    }
    if (doubt.empty()) doubt = untrusted_row(refs);
    if (doubt.empty()) doubt = earlier_condition(refs);
    if (doubt.empty()) return found(evidence, "rewrite", refs);
    // the reason shown: the first that names a declaration deciding it, else the first
    const bool names_declaration = doubt.find("declar") != std::string::npos;
    if (first_doubt.empty() || (names_declaration && !doubt_names_declaration)) {
      first_doubt = doubt;
      doubt_refs = refs;
      doubt_names_declaration = names_declaration;
    }
  }
  if (!refutations.empty()) {
    const auto& first = refutations.front().r;
    const auto& refs = doubt_refs;
    Verdict v = undecided("refutation withheld",
                                  "a counterexample satisfies " + join(refs) + ", but " + first_doubt);
    v.point = first.verdict.point;
    v.lhs_value = first.verdict.lhs_value;
    v.rhs_value = first.verdict.rhs_value;
    return finish(res, v);
  }
  std::string tried = join(tried_);
  // the same sets with every undeclared name positive: `T = 2\pi/\omega_0 = 2\pi\sqrt{m/k}` holds
  // there. Not derived (the author declared no sign), but the declaration that decides it is named
  if (row_.relation == "=" && !nested_)
    for (const auto& refs : candidate_sets()) {
      if (late()) break;
      StepResult pos = attempt_positive(refs);
      if (usable(pos) && pos.verdict.holds() && !rests_on_a_slip(refs)) {
        std::set<std::string> names;
        for (const auto& side : s_.claim.sides) names_of(side, names);
        std::string list;
        for (const auto& n : names)
          if (const SymbolInfo* info = d_.symbols.find(n); info && !info->is_function && info->domain.unrestricted())
            list += (list.empty() ? "" : ", ") + n;
        return finish(res, undecided("declaration", "it follows from " + join(refs) +
                                                        " when the names are positive, which the document does not "
                                                        "declare: `symbol " + list + " : positive` would decide it"));
      }
    }
  if (!voided_.empty()) return finish(res, undecided("search", voided_));
  return finish(res, undecided("search", "not an identity, and it does not follow from " +
                                                     (tried.empty() ? std::string("the rows before it") : tried)));
}

StepResult Search::finish(StepResult& res, Verdict v) {
  res.verdict = std::move(v);
  return res;
}

StepResult Search::found(StepResult r, const std::string& rule, const std::vector<std::string>& refs) {
  r.step = &s_;
  r.found_rule = rule;
  r.found_rows = refs;
  return r;
}

RuleArg Search::label_arg(const std::string& label) const {
  RuleArg a;
  a.kind = RuleArg::Kind::Label;
  a.label = label;
  a.pos = s_.claim_pos;
  return a;
}

RuleArg Search::node_arg(const Node& n, RuleArg::Kind kind) const {
  RuleArg a;
  a.kind = kind;
  a.label = to_text(n);
  a.value = n;
  a.pos = s_.claim_pos;
  return a;
}

std::optional<StepResult> Search::attempt_lifted(const std::vector<std::string>& refs) {
  // the claim's functions by base name (m_r -> m_r__of_t(t))
  std::map<std::string, Node> lift;
  for (const auto& side : s_.claim.sides)
    walk_nodes(side, [&](const Node& n) {
      if (n.kind != NodeKind::Call || n.args.size() != 1 || n.args[0].kind != NodeKind::Symbol) return;
      const std::size_t of = n.text.find("__of_");
      if (of != std::string::npos && n.text.substr(of + 5) == n.args[0].text) lift[n.text.substr(0, of)] = n;
    });
  if (lift.empty()) return std::nullopt;
  RuleSpec rule;
  rule.name = rule.written_name = "rewrite";
  std::set<std::string> lifted;
  for (const auto& label : refs) {
    const Step* st = d_.find(label);
    if (!st || st->claim.sides.size() < 2) return std::nullopt;
    // the subject a row sets keeps its value at the instant it speaks of (`v = v_0`)
    const std::string subject = st->claim.sides.front().kind == NodeKind::Symbol ? st->claim.sides.front().text : "";
    RuleArg a = label_arg(label);
    a.kind = RuleArg::Kind::Equation;
    a.equation.sides = {st->claim.sides.front(), st->claim.sides.back()};
    for (auto& side : a.equation.sides) replace_names(side, lift, subject, &lifted);
    rule.refs.push_back(std::move(a));
  }
  if (lifted.empty()) return std::nullopt;
  StepResult r = attempt_rule(std::move(rule));
  std::string names;
  for (const auto& n : lifted) names += (names.empty() ? "" : ", ") + n;
  r.verdict.method = "rows read with " + names + " at the instant (as functions of the claim's variable): " + r.verdict.method;
  r.found_line.clear();   // the rows as written do not give it in .dc
  return r;
}

StepResult Search::attempt(const std::vector<std::string>& refs) {
  RuleSpec rule;
  rule.name = rule.written_name = "rewrite";
  for (const auto& label : refs) rule.refs.push_back(label_arg(label));
  if (!refs.empty()) tried_.push_back("{" + join(refs) + "}");
  return attempt_rule(std::move(rule));
}

// The step checked with one rule of the .dc language (its rows and arguments filled in).
// The rewrite from `refs` in the reading where every name of the document without a declared
// domain is positive (masses, lengths, speeds of the usual physical reading).
StepResult Search::attempt_positive(const std::vector<std::string>& refs, const Relation* claim, const RuleSpec* as) {
  if (!positive_) {
    // (not a name that an equation of the text in force here, or for the rows of the two
    // displays before, sets to zero or below: `neglect D`, `$\theta = 0$`)
    std::set<std::string> conditions(row_.locals.begin(), row_.locals.end());
    conditions.insert(row_.where.begin(), row_.where.end());
    for (const auto& st : d_.steps)
      if (st.document_row && st.document_row->relation != "inline" && st.document_row->display < row_.display &&
          st.document_row->display + 2 >= row_.display)
        conditions.insert(st.document_row->locals.begin(), st.document_row->locals.end());
    std::set<std::string> zero;
    for (const auto& label : conditions)
      if (const Step* st = d_.find(label); st && st->claim.sides.size() == 2 && st->claim.sides[0].kind == NodeKind::Symbol) {
        const Node& v = st->claim.sides[1];
        if ((v.kind == NodeKind::Number && (v.text == "0" || v.text == "0.0")) || v.kind == NodeKind::Neg)
          zero.insert(st->claim.sides[0].text);
      }
    positive_ = std::make_unique<Derivation>(positive_reading(d_, zero));
  }
  if (as) return attempt_rule(*as, claim, positive_.get());
  RuleSpec rule;
  rule.name = rule.written_name = "rewrite";
  for (const auto& label : refs) rule.refs.push_back(label_arg(label));
  return attempt_rule(std::move(rule), claim, positive_.get());
}

StepResult Search::attempt_rule(RuleSpec rule, const Relation* claim, const Derivation* on) {
  Step t = s_;
  t.document_row.reset();
  if (claim) {
    t.claim = *claim;
    t.claim_text = to_text(*claim);
  }
  rule.pos = s_.claim_pos;
  t.rule = std::move(rule);
  try {
    ++*work_;
    ProveOptions o = opt_;
    o.reorder_references = false;   // see ProveOptions: the search tries too many sets to pay for it
    StepResult r = check_step(on ? *on : d_, t, o);
    r.step = &s_;
    r.found_line = rule_line_text(t.rule);
    if (claim) r.found_claim = t.claim_text;
    return r;
  } catch (const InputError& e) {
    StepResult r;
    r.step = &s_;
    r.input_error = true;
    r.errors.push_back(e);
    return r;
  } catch (const std::exception& e) {   // a rule that cannot take these arguments: no evidence
    StepResult r;
    r.step = &s_;
    r.input_error = true;
    return r;
  }
}

// The names of the claim that no earlier step mentions.
bool Search::introduces_names() {
  new_names_ = new_names_of(s_);
  return !new_names_.empty();
}

// The names of step `s` that no step before it mentions (a row that was not read mentions
// nothing).
std::vector<std::string> Search::new_names_of(const Step& s) const {
  std::set<std::string> mine, before;
  for (const auto& side : s.claim.sides) names_of(side, mine);
  for (const auto& st : d_.steps) {
    if (&st == &s) break;
    if (st.document_row && !st.document_row->not_read.empty() && st.document_row->relation != "inline") continue;
    for (const auto& side : st.claim.sides) names_of(side, before);
  }
  std::vector<std::string> out;
  for (const auto& n : mine)
    if (!before.count(n)) out.push_back(n);
  return out;
}

// Small sets first: what the author cites, then the nearest rows, then more of them; the
// inline givens in force join every set.
std::vector<std::vector<std::string>> Search::candidate_sets() const {
  std::vector<std::vector<std::string>> out;
  auto add = [&](std::vector<std::string> refs) {
    std::vector<std::string> uniq;
    for (const auto& r : refs)
      if (std::find(uniq.begin(), uniq.end(), r) == uniq.end() && usable_ref(r)) uniq.push_back(r);
    if (uniq.empty()) return;
    if (std::find(out.begin(), out.end(), uniq) == out.end()) out.push_back(std::move(uniq));
  };
  auto with_locals = [&](std::vector<std::string> refs) {
    refs.insert(refs.end(), row_.locals.begin(), row_.locals.end());
    refs.insert(refs.end(), row_.where.begin(), row_.where.end());
    return refs;
  };
  // the same rows under the conditions of the text just before the display only (a special
  // case of the display before, `$m_1 = m_2$`, is over when the next one adds `$v_2 = 0$`)
  const bool carried = row_.fresh.size() < row_.locals.size();
  auto with_fresh = [&](std::vector<std::string> refs) {
    const std::vector<std::string> rows = refs;
    refs.insert(refs.end(), row_.fresh.begin(), row_.fresh.end());
    refs.insert(refs.end(), row_.where.begin(), row_.where.end());
    for (const auto& label : rows)   // the conditions each row was written under
      if (const Step* st = d_.find(label); st && st->document_row)
        refs.insert(refs.end(), st->document_row->locals.begin(), st->document_row->locals.end());
    return refs;
  };
  auto nearest = [&](std::size_t n) {
    std::vector<std::string> r;
    for (std::size_t i = 0; i < n && i < row_.nearby.size(); ++i) r.push_back(row_.nearby[i]);
    return r;
  };
  if (!row_.cited.empty()) add(with_locals(row_.cited));
  add(with_locals({}));
  // one row at a time first: a wider set can make elimination divide by what another row
  // sets to zero (v'_1 = v_2 from the elastic v'_1 and m_1 = m_2, not with v'_2 beside it)
  for (std::size_t i = 0; i < 4 && i < row_.nearby.size(); ++i) {
    add(with_locals({row_.nearby[i]}));
    if (carried) add(with_fresh({row_.nearby[i]}));
  }
  add(with_locals(nearest(2)));
  add(with_locals(nearest(4)));
  if (carried) add(with_fresh(nearest(4)));
  // then the rows that speak most of the claim's names, wherever they stand (the law (9.6)
  // and the definition (9.7) for the general impact, pages after them)
  const std::vector<std::string> relevant = most_relevant();
  // (the most relevant row alone first: beside it, a slip that shares its names may pin a
  // quantity, and then the pair proves nothing although the one row proves the claim)
  if (!relevant.empty()) add(with_locals({relevant.front()}));
  for (std::size_t n : {2u, 3u, 4u})
    if (relevant.size() >= n - 1)
      add(with_locals(std::vector<std::string>(relevant.begin(),
                                               relevant.begin() + static_cast<long>(std::min(n, relevant.size())))));
  // the most relevant row with the other links of its chain (`F = m a = m dv/dt = d(mv)/dt =
  // dp/dt` is one statement; a later `dp/dt = F` uses all of it)
  if (!relevant.empty()) {
    std::vector<std::string> chain;
    const Step* top = d_.find(relevant.front());
    for (const auto& st : d_.steps) {
      if (&st == &s_) break;
      if (top && st.document_row && st.document_row->relation != "inline" && st.pos.line == top->pos.line &&
          st.document_row->display == top->document_row->display)
        chain.push_back(st.label);
    }
    if (chain.size() > 1) add(with_locals(chain));
  }
  // (no wider set: the more rows, the likelier two of them — a slip and the row it garbles —
  // pin a quantity to a special value from which anything about it follows)
  return out;
}

// A proof from several rows is worth nothing when one of them is a slip: the slip and the row
// it garbles pin a quantity to a special value, and from that anything about it follows
// (`w_2 = …/(m_1 + m_1)` beside the right `w_2` "proves" m_1 m_2 = 0). So each row used that
// is not a given is searched for itself (one level deep), and a refuted one voids the proof.
const Search::Own& Search::own_search(const Step& st) const {
  auto it = own_.find(st.label);
  if (it == own_.end()) {
    const StepResult r = Search(d_, st, opt_, true, work_).run();
    Own o;
    o.refuted = r.verdict.kind == VerdictKind::Refuted;
    o.withheld = r.verdict.kind == VerdictKind::Undecided && r.verdict.method == "refutation withheld";
    o.established = r.premise || r.verdict.holds();
    o.cut = late();
    const std::string& why = r.verdict.reason;
    o.holds_if_positive = r.verdict.kind == VerdictKind::Undecided && why.find(kHoldsIfDeclared) != std::string::npos &&
                          why.find("positive") != std::string::npos;
    it = own_.emplace(st.label, o).first;
  }
  return it->second;
}

bool Search::rests_on_a_slip(const std::vector<std::string>& refs, std::vector<std::string>* slips) const {
  if (nested_) return false;
  // (an equation of the text counts: `$s_o s_i = f(s_o + s_i)$` beside a garbled lens row pins f = 0)
  if (refs.size() < 2) return false;
  std::vector<std::set<std::string>> names(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i)
    if (const Step* st = d_.find(refs[i])) names[i] = quantities_of(*st);
  // a row pins nothing with rows that share no name with it (`dv = …` from one row beside
  // `$D = 0$`, `$\theta = 0$`): the proof is then from that row alone, a step of its own
  auto shares = [&](std::size_t i) {
    for (std::size_t j = 0; j < refs.size(); ++j)
      if (j != i)
        for (const auto& n : names[i])
          if (names[j].count(n)) return true;
    return false;
  };
  bool any = false;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const std::string& label = refs[i];
    const Step* st = d_.find(label);
    if (!st || !st->document_row || st->document_row->relation == "inline" || !shares(i)) continue;
    if (late()) return true;   // not checked in time: no proof rests on it
    const Own& own = own_search(*st);
    if (own.cut) return true;
    // a row that a counterexample to the rows before it leaves standing only by a doubt may
    // be a slip as well (`\omega_0 Q_0 = Q_0\sqrt{LC}` beside `\omega_0 = 1/\sqrt{LC}` pins LC = 1)
    // (not one that holds once its names are positive: undecided for want of a sign, no slip)
    if (own.refuted || (own.withheld && !own.holds_if_positive)) {
      any = true;
      if (slips) slips->push_back(label);
    }
  }
  return any;
}

// Is an earlier document step in force for this row: its conditions (the equations of the
// text it was read under) hold here too, and an equation of the text itself is in force only
// for the displays it is a condition of.
bool Search::in_force(const Step& st) const {
  auto mine = [&](const std::string& label) {
    return std::find(row_.locals.begin(), row_.locals.end(), label) != row_.locals.end() ||
           std::find(row_.where.begin(), row_.where.end(), label) != row_.where.end();
  };
  for (const auto& c : st.document_row->locals)
    if (!mine(c)) return false;
  return st.document_row->relation != "inline" || mine(st.label);
}

// Earlier rows in force here (their conditions hold here too), by how many of the claim's
// names they mention, the nearer first on a tie.
std::vector<std::string> Search::most_relevant() const {
  const std::set<std::string> mine = quantities_of(s_);
  std::vector<std::pair<int, std::size_t>> scored;   // (-score, -index)
  std::size_t index = 0;
  for (const auto& st : d_.steps) {
    if (&st == &s_) break;
    ++index;
    if (!st.document_row || st.document_row->relation == "inline" || !usable_ref(st.label)) continue;
    if (!in_force(st)) continue;
    std::set<std::string> theirs;
    for (const auto& side : st.claim.sides) names_of(side, theirs);
    int score = 0;
    for (const auto& n : mine) score += theirs.count(n) ? 1 : 0;
    if (score > 0) scored.push_back({-score, index - 1});
  }
  std::sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : a.second > b.second;
  });
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scored.size() && i < 4; ++i) out.push_back(d_.steps[scored[i].second].label);
  return out;
}

// A reference must be an equation that was read.
bool Search::usable_ref(const std::string& label) const {
  const Step* st = d_.find(label);
  if (!st || !st->document_row) return false;
  const DocumentRow& r = *st->document_row;
  // an approximate row is a reference for an approximate row only
  return r.not_read.empty() && (r.relation == "=" || r.relation == "inline" ||
                                (r.relation == "approx" && row_.relation == "approx"));
}

}  // namespace document_detail

using document_detail::Search;

StepResult justify_step(const Derivation& d, const Step& s, const ProveOptions& opt) {
  if (!s.document_row) return check_step(d, s, opt);
  if (s.document_row->authors_rule) {   // `% by solve (9.6) for v`: checked as the .dc step, no search
    StepResult r = check_step(d, s, opt);
    if (r.verdict.kind == VerdictKind::Refuted) {
      // the document declares no signs: as for a found rule, a counterexample needs one with
      // every undeclared quantity positive (which is one of the unrestricted reading too)
      StepResult pos = check_step(document_detail::positive_reading(d, {}), s, opt);
      if (pos.verdict.kind == VerdictKind::Refuted) {
        pos.step = r.step;
        r = pos;
      } else {
        Verdict v = r.verdict;
        v.kind = VerdictKind::Undecided;
        v.method = "refutation withheld";
        v.reason = "a counterexample refutes the author's rule, but every one found needs a negative value of a "
                   "quantity the document declares no sign for" +
                   std::string(pos.verdict.holds() ? " (the row holds when they are positive: declare them positive, "
                                                     "e.g. `symbol m : positive`)"
                                                   : "");
        r.verdict = v;
      }
    }
    r.found_rule = s.rule.written_name;
    r.found_line = rule_line_text(s.rule);
    for (const auto* group : {&s.rule.refs, &s.rule.into})
      for (const auto& a : *group)
        if (a.kind == RuleArg::Kind::Label) r.found_rows.push_back(a.label);
    return r;
  }
  return Search(d, s, opt).run();
}

StepResult check_any_step(const Derivation& d, const Step& s, const ProveOptions& opt) {
  return s.document_row ? justify_step(d, s, opt) : check_step(d, s, opt);
}

}  // namespace dc

