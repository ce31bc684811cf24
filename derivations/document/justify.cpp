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
#include <set>

#include "derivations/document/document.hpp"
#include "derivations/rules/context.hpp"
#include "derivations/syntax/document.hpp"

namespace dc {
namespace {

using rules::undecided;   // the verdicts the rules build, one construction for both
using rules::proved;

void names_of(const Node& n, std::set<std::string>& out) {
  if (n.kind == NodeKind::Symbol && !is_reserved_name(n.text)) out.insert(n.text);
  if (n.kind == NodeKind::Call && !is_builtin_function(n.text)) out.insert(n.text);
  for (const auto& a : n.args) names_of(a, out);
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
bool prose_names_a_regime(const std::string& hint) {
  static const char* const kWords[] = {"assum", "suppos", "approx", "neglect",
                                       "small", "large", "infinite", "negligible", "much", "limit", "tend",
                                       "order", "\\gg", "\\ll", "ignor", "roughly", "about", "estimat",
                                       "integrat", "differentiat", "solution"};
  for (const char* w : kWords)
    if (hint.find(w) != std::string::npos) return true;
  return false;
}

class Search {
 public:
  Search(const Derivation& d, const Step& s, const ProveOptions& opt, bool nested = false)
      : d_(d), s_(s), row_(*s.document_row), opt_(opt), nested_(nested) {}

  StepResult run() {
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
    // 2. a new name: a given
    if (row_.relation == "=" && introduces_names()) {
      res.premise = true;
      res.found_rule = "given";
      Verdict v = proved("given", "introduces " + join(new_names_) + ": a law or a definition, taken as written");
      return finish(res, v);
    }
    // 3. follows from earlier rows
    std::vector<std::pair<StepResult, std::vector<std::string>>> refutations;
    for (const auto& refs : candidate_sets()) {
      StepResult r = attempt(refs);
      if (!usable(r)) continue;
      if (r.verdict.holds() && !rests_on_a_slip(refs)) return found(r, "rewrite", refs);
      if (r.verdict.kind == VerdictKind::Refuted && rows_speak_of_claim(refs)) refutations.push_back({r, refs});
    }
    if (row_.relation == "approx")
      return finish(res, undecided("approximation", "an approximate relation: it does not follow exactly "
                                                            "from the rows nearby, and the regime it holds in (first "
                                                            "order, a limit) is not searched yet"));
    // the first refutation whose reading is not in doubt refutes; otherwise the first doubt is
    // the reason the row stays undecided
    for (const auto& [r, refs] : refutations)
      if (reading_in_doubt(r, refs).empty()) return found(r, "rewrite", refs);
    if (!refutations.empty()) {
      const auto& [first, refs] = refutations.front();
      Verdict v = undecided("refutation withheld",
                                    "a counterexample satisfies " + join(refs) + ", but " + reading_in_doubt(first, refs));
      v.point = first.verdict.point;
      v.lhs_value = first.verdict.lhs_value;
      v.rhs_value = first.verdict.rhs_value;
      return finish(res, v);
    }
    std::string tried = join(tried_);
    return finish(res, undecided("search", "not an identity, and it does not follow from " +
                                                       (tried.empty() ? std::string("the rows before it") : tried)));
  }

 private:
  StepResult finish(StepResult& res, Verdict v) {
    res.verdict = std::move(v);
    return res;
  }

  StepResult found(StepResult r, const std::string& rule, const std::vector<std::string>& refs) {
    r.step = &s_;
    r.found_rule = rule;
    r.found_rows = refs;
    return r;
  }

  // A candidate's result can be used unless its references could not be (contradictory
  // references, an undefined name): then that set is no evidence either way.
  static bool usable(const StepResult& r) { return !r.input_error && r.errors.empty(); }

  StepResult attempt(const std::vector<std::string>& refs) {
    Step t = s_;
    t.document_row.reset();
    t.rule = RuleSpec{};
    t.rule.name = t.rule.written_name = "rewrite";
    t.rule.pos = s_.claim_pos;
    for (const auto& label : refs) {
      RuleArg a;
      a.kind = RuleArg::Kind::Label;
      a.label = label;
      a.pos = s_.claim_pos;
      t.rule.refs.push_back(std::move(a));
    }
    if (!refs.empty()) tried_.push_back("{" + join(refs) + "}");
    try {
      return check_step(d_, t, opt_);
    } catch (const InputError& e) {
      StepResult r;
      r.step = &s_;
      r.input_error = true;
      r.errors.push_back(e);
      return r;
    }
  }

  // The names of the claim that no earlier step mentions.
  bool introduces_names() {
    std::set<std::string> mine, before;
    for (const auto& side : s_.claim.sides) names_of(side, mine);
    for (const auto& st : d_.steps) {
      if (&st == &s_) break;
      if (st.document_row && !st.document_row->not_read.empty() && st.document_row->relation != "inline") continue;
      for (const auto& side : st.claim.sides) names_of(side, before);
    }
    for (const auto& n : mine)
      if (!before.count(n)) new_names_.push_back(n);
    return !new_names_.empty();
  }

  // Small sets first: what the author cites, then the nearest rows, then more of them; the
  // inline givens in force join every set.
  std::vector<std::vector<std::string>> candidate_sets() const {
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
    for (std::size_t i = 0; i < 4 && i < row_.nearby.size(); ++i) add(with_locals({row_.nearby[i]}));
    add(with_locals(nearest(2)));
    add(with_locals(nearest(4)));
    // then the rows that speak most of the claim's names, wherever they stand (the law (9.6)
    // and the definition (9.7) for the general impact, pages after them)
    const std::vector<std::string> relevant = most_relevant();
    for (std::size_t n : {2u, 3u, 4u})
      if (relevant.size() >= n - 1)
        add(with_locals(std::vector<std::string>(relevant.begin(),
                                                 relevant.begin() + static_cast<long>(std::min(n, relevant.size())))));
    // (no wider set: the more rows, the likelier two of them — a slip and the row it garbles —
    // pin a quantity to a special value from which anything about it follows)
    return out;
  }

  // A proof from several rows is worth nothing when one of them is a slip: the slip and the row
  // it garbles pin a quantity to a special value, and from that anything about it follows
  // (`w_2 = …/(m_1 + m_1)` beside the right `w_2` "proves" m_1 m_2 = 0). So each row used that
  // is not a given is searched for itself (one level deep), and a refuted one voids the proof.
  bool rests_on_a_slip(const std::vector<std::string>& refs) const {
    if (nested_) return false;
    std::size_t rows = 0;
    for (const auto& label : refs)
      if (const Step* st = d_.find(label); st && st->document_row && st->document_row->relation != "inline") ++rows;
    if (rows < 2) return false;
    for (const auto& label : refs) {
      const Step* st = d_.find(label);
      if (!st || !st->document_row || st->document_row->relation == "inline") continue;
      StepResult own = Search(d_, *st, opt_, true).run();
      if (own.verdict.kind == VerdictKind::Refuted) return true;
    }
    return false;
  }

  // Is an earlier document step in force for this row: its conditions (the equations of the
  // text it was read under) hold here too, and an equation of the text itself is in force only
  // for the displays it is a condition of.
  bool in_force(const Step& st) const {
    auto mine = [&](const std::string& label) {
      return std::find(row_.locals.begin(), row_.locals.end(), label) != row_.locals.end();
    };
    for (const auto& c : st.document_row->locals)
      if (!mine(c)) return false;
    return st.document_row->relation != "inline" || mine(st.label);
  }

  // Earlier rows in force here (their conditions hold here too), by how many of the claim's
  // names they mention, the nearer first on a tie.
  std::vector<std::string> most_relevant() const {
    std::set<std::string> mine;
    for (const auto& side : s_.claim.sides) names_of(side, mine);
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
  bool usable_ref(const std::string& label) const {
    const Step* st = d_.find(label);
    if (!st || !st->document_row) return false;
    const DocumentRow& r = *st->document_row;
    return r.not_read.empty() && (r.relation == "=" || r.relation == "inline");
  }

  // Every name of the claim occurs in the rows of the refutation: otherwise the claim speaks
  // of something those rows leave free, and a point where it fails says nothing.
  bool rows_speak_of_claim(const std::vector<std::string>& refs) const {
    std::set<std::string> mine, theirs;
    for (const auto& side : s_.claim.sides) names_of(side, mine);
    for (const auto& label : refs)
      if (const Step* st = d_.find(label))
        for (const auto& side : st->claim.sides) names_of(side, theirs);
    for (const auto& n : mine)
      if (!theirs.count(n)) return false;
    return true;
  }

  // The name a row sets: its first side when that is a name, or a power of one (`\omega_d^2 = …`).
  static std::string set_name(const Step& st) {
    const Node* n = &st.claim.sides.front();
    if (n->kind == NodeKind::Pow) n = &n->args[0];
    return n->kind == NodeKind::Symbol || n->kind == NodeKind::Call ? to_text(*n) : std::string();
  }

  // A name of the claim that some earlier row sets while none of the refuting rows does: the
  // counterexample gives it a value that row forbids, so it says nothing against the author
  // (`a = g\sin\beta/(1 + I/(m r^2)) = \frac{5}{7} g \sin\beta` needs `I = \frac{2}{5} m r^2`).
  std::string unset_name(const std::vector<std::string>& refs) const {
    // the names of the claim and of the rows: a name the rows leave free (`a` in
    // `f = m g\sin\beta - m a`) takes any value in the counterexample too
    std::set<std::string> mine, set_by_refs;
    for (const auto& side : s_.claim.sides) names_of(side, mine);
    for (const auto& label : refs)
      if (const Step* st = d_.find(label)) {
        set_by_refs.insert(set_name(*st));
        for (const auto& side : st->claim.sides) names_of(side, mine);
      }
    for (const auto& st : d_.steps) {
      if (&st == &s_) break;
      if (!st.document_row || !st.document_row->not_read.empty()) continue;
      if (st.document_row->relation != "=" && st.document_row->relation != "inline") continue;
      if (!in_force(st)) continue;   // a row of a special case not in force here does not count
      const std::string n = set_name(st);
      if (!n.empty() && mine.count(n) && !set_by_refs.count(n))
        return "'" + n + "' is set by " + st.label + ", which is not among them";
    }
    return "";
  }

  // Why a counterexample is no evidence against the author here ("" when it is).
  std::string reading_in_doubt(const StepResult& r, const std::vector<std::string>& refs) const {
    if (std::string unset = unset_name(refs); !unset.empty()) return unset;
    // `ΔT = …` against an earlier display's `ΔT = …`: documents reuse a name for the quantity
    // of the next case (the energy lost in an inelastic impact, then in any impact)
    const Node& subject = s_.claim.sides.front();
    if (subject.kind == NodeKind::Symbol || subject.kind == NodeKind::Call)
      for (const auto& label : refs) {
        const Step* st = d_.find(label);
        if (!st || !st->document_row || st->document_row->display == row_.display) continue;
        const Node& theirs = st->claim.sides.front();
        if (theirs.kind == subject.kind && to_text(theirs) == to_text(subject))
          return "'" + to_text(subject) + "' is set by " + label +
                 " in an earlier display, and this row may give the name to another quantity";
      }
    // a name that varies with t in one display (dv/dt) and is a plain quantity in another
    std::set<std::string> mine, theirs;
    for (const auto& side : s_.claim.sides) names_of(side, mine);
    for (const auto& label : refs)
      if (const Step* st = d_.find(label))
        for (const auto& side : st->claim.sides) names_of(side, theirs);
    auto base = [](const std::string& n) {
      const std::size_t of = n.find("__of_");
      return of == std::string::npos ? n : n.substr(0, of);
    };
    for (const auto& a : mine)
      for (const auto& b : theirs)
        if (a != b && base(a) == base(b))
          return "'" + base(a) + "' varies with a variable in one of these rows and is a plain quantity in the other";
    if (!r.verdict.hint.empty()) return "the row holds under a declaration the document does not make (" + r.verdict.hint + ")";
    static const std::set<std::string> calculus = {"diff", "integral", "limit"};
    for (const auto& side : s_.claim.sides)
      if (has_call(side, calculus))
        return "the row takes a limit, a derivative or an integral, whose reading (which names vary, the "
               "regime) is not certain";
    if (prose_names_a_regime(row_.hint))
      return "the text before the display names a regime or a law the search does not read";
    return "";
  }

  const Derivation& d_;
  const Step& s_;
  const DocumentRow& row_;
  const ProveOptions& opt_;
  std::vector<std::string> new_names_;
  std::vector<std::string> tried_;
  bool nested_ = false;
};

}  // namespace

StepResult justify_step(const Derivation& d, const Step& s, const ProveOptions& opt) {
  if (!s.document_row) return check_step(d, s, opt);
  return Search(d, s, opt).run();
}

StepResult check_any_step(const Derivation& d, const Step& s, const ProveOptions& opt) {
  return s.document_row ? justify_step(d, s, opt) : check_step(d, s, opt);
}

}  // namespace dc
