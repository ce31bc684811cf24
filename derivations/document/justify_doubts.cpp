// When a counterexample the search found is no evidence against the author (search.hpp): the
// reading of the row is in doubt (a name reused, a regime in words, a condition stated earlier,
// a root the row chooses, a sign the document does not declare), or the rows it rests on hold
// a slip themselves.
#include <algorithm>

#include <ginac/ginac.h>

#include "derivations/document/search.hpp"

namespace dc::document_detail {

// A condition the text stated earlier in the section (`$T_1 = T_2$`), not in force here by the
// reader's rule, under which the row follows from the same rows: the author may still mean it.
// `a = \alpha r` after `m a = m g\sin\beta - f` and `f r = I\alpha`: the counterexample chose
// the subject's value, so the rows may leave it free, and the row adds a relation they do not
// make: a law or a condition as likely as a slip. Unless solving the rows for it (the names
// they have and the row has not eliminated) shows that they determine it, and the row's value
// is not theirs: then `evidence` holds that refutation.
std::string Search::free_subject(const StepResult& r, const std::vector<std::string>& refs, StepResult& evidence) {
  const std::string x = set_name(s_);
  if (x.empty() || s_.claim.sides.front().kind != NodeKind::Symbol) return "";
  bool chosen = false;
  for (const auto& [name, value] : r.verdict.point) chosen = chosen || name == x;
  if (!chosen) return "";
  const std::string doubt = "the rows leave '" + x + "' free (the counterexample chooses it), so this row may "
                            "state a law or a condition about it that they do not";
  if (late()) return doubt;
  std::set<std::string> mine, theirs, chosen_names;
  for (const auto& side : s_.claim.sides) names_of(side, mine);
  for (const auto& [name, value] : r.verdict.point) chosen_names.insert(name);
  for (const auto& label : refs)
    if (const Step* st = d_.find(label); st && st->document_row && st->document_row->relation != "inline")
      for (const auto& side : st->claim.sides) names_of(side, theirs);
  // unknowns: the subject and the names the rows determine (the rewrite eliminated them)
  std::set<std::string> skip = mine;
  skip.insert(chosen_names.begin(), chosen_names.end());
  StepResult s = attempt_rule(solve_spec(refs, s_.claim.sides.front(), theirs, skip));
  const Verdict& v = s.verdict;
  if (!usable(s) || v.kind != VerdictKind::Refuted || side_condition_only(v) ||
      v.detail.find("do not determine") != std::string::npos || v.reason.find("do not determine") != std::string::npos)
    return doubt;
  // (only a linear system the rows determine: substituting a nonlinear claim back can fail an
  // equation that the rows leave unrelated to the subject)
  if (v.method.rfind("lsolve", 0) != 0) return doubt;
  evidence = s;
  return "";
}

std::string Search::earlier_condition(const std::vector<std::string>& refs) {
  std::set<std::string> mine;
  for (const auto& side : s_.claim.sides) names_of(side, mine);
  for (const auto& label : row_.earlier) {
    const Step* st = d_.find(label);
    if (!st || !st->document_row || row_.display - st->document_row->display > 3) continue;   // a few displays back
    std::set<std::string> theirs;
    for (const auto& side : st->claim.sides) names_of(side, theirs);
    bool shared = false;
    for (const auto& n : theirs) shared = shared || mine.count(n);
    if (!shared) continue;
    std::vector<std::string> with = refs;
    with.push_back(label);
    StepResult r = attempt(with);
    if (usable(r) && r.verdict.holds())
      return "the row follows from them under " + st->claim_text + ", which the text states earlier (" + label +
             ") and may still mean here";
  }
  return "";
}

// A refutation against a row that its own search refutes is a refutation against the slip
// before it: the author's later rows continue from the right result. Each row of the set is
// searched for itself (one level deep).
std::string Search::untrusted_row(const std::vector<std::string>& refs) {
  if (nested_) return "";
  for (const auto& label : refs) {
    const Step* st = d_.find(label);
    if (!st || !st->document_row || st->document_row->relation == "inline") continue;
    const Own& own = own_search(*st);
    // (a row that holds once its names are positive counts as derived: the counterexample
    // against this row is one of that reading, checked before this doubt is asked)
    const std::string why = own.refuted       ? "is itself refuted by its own search"
                            : own.cut         ? "could not be checked itself within the search's tries"
                            : own.established || own.holds_if_positive
                                ? ""
                                : "is not derived itself (its own search leaves it undecided)";
    if (!why.empty())
      return label + " " + why + ", and the counterexample rests on it: this row may continue from the right result";
  }
  return "";
}

// Every name of the claim occurs in the rows of the refutation: otherwise the claim speaks
// of something those rows leave free, and a point where it fails says nothing.
bool Search::rows_speak_of_claim(const std::vector<std::string>& refs) const {
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
std::string Search::set_name(const Step& st) {
  const Node* n = &st.claim.sides.front();
  if (n->kind == NodeKind::Pow) n = &n->args[0];
  return n->kind == NodeKind::Symbol || n->kind == NodeKind::Call ? to_text(*n) : std::string();
}

// A name of the claim that some earlier row sets while none of the refuting rows does: the
// counterexample gives it a value that row forbids, so it says nothing against the author
// (`a = g\sin\beta/(1 + I/(m r^2)) = \frac{5}{7} g \sin\beta` needs `I = \frac{2}{5} m r^2`).
std::string Search::unset_name(const std::vector<std::string>& refs) const {
  // the names of the claim and of the rows: a name the rows leave free (`a` in
  // `f = m g\sin\beta - m a`) takes any value in the counterexample too. Compared by their
  // base (`v` and `v__of_t(t)`, the same letter as a function of t in another display)
  auto base = [](std::string n) {
    const std::size_t of = n.find("__of_");
    return of == std::string::npos ? n : n.substr(0, of);
  };
  std::set<std::string> mine, set_by_refs;
  for (const auto& side : s_.claim.sides) names_of(side, mine);
  for (const auto& label : refs)
    if (const Step* st = d_.find(label)) {
      set_by_refs.insert(base(set_name(*st)));
      for (const auto& side : st->claim.sides) names_of(side, mine);
    }
  {
    std::set<std::string> bases;
    for (const auto& n : mine) bases.insert(base(n));
    mine = bases;
  }
  for (const auto& st : d_.steps) {
    if (&st == &s_) break;
    if (!st.document_row) continue;
    // (a row the reader could not read may set it: `W_{12} = \int_{V_1}^{V_2} p\,dV` with p
    // varying; the counterexample gives the name a value that row may forbid)
    if (const std::string& u = st.document_row->unread_sets; !u.empty() && mine.count(base(u)) && !set_by_refs.count(base(u)))
      return "'" + base(u) + "' is set by " + st.label + ", which is not read, so the counterexample may contradict it";
    if (!st.document_row->not_read.empty()) continue;
    if (st.document_row->relation != "=" && st.document_row->relation != "inline") continue;
    if (!in_force(st)) continue;   // a row of a special case not in force here does not count
    const std::string n = base(set_name(st));
    if (!n.empty() && mine.count(n) && !set_by_refs.count(n))
      return "'" + n + "' is set by " + st.label + ", which is not among them";
  }
  return "";
}

// The rows in force that set a name of the claim or of `refs` that none of `refs` sets (the
// latest such row for each name).
std::vector<std::string> Search::unset_setters(const std::vector<std::string>& refs) const {
  std::set<std::string> mine, set_by_refs;
  for (const auto& side : s_.claim.sides) names_of(side, mine);
  for (const auto& label : refs)
    if (const Step* st = d_.find(label)) {
      set_by_refs.insert(set_name(*st));
      for (const auto& side : st->claim.sides) names_of(side, mine);
    }
  std::map<std::string, std::string> latest;
  for (const auto& st : d_.steps) {
    if (&st == &s_) break;
    if (!st.document_row || !st.document_row->not_read.empty()) continue;
    if (st.document_row->relation != "=" && st.document_row->relation != "inline") continue;
    if (!in_force(st)) continue;
    const std::string n = set_name(st);
    if (!n.empty() && mine.count(n) && !set_by_refs.count(n)) latest[n] = st.label;
  }
  std::vector<std::string> out;
  for (const auto& [n, label] : latest)
    if (std::find(refs.begin(), refs.end(), label) == refs.end()) out.push_back(label);
  return out;
}

// The one non-injective function through which the rows mention the claim's subject x:
// cos(x), sin(x), tan(x), x^2 (an even power), |x|. Null when x also appears bare, or under
// two different ones.
std::optional<Node> Search::branch_wrapper(const std::vector<std::string>& refs, const std::string& x) const {
  static const std::set<std::string> kPeriodic = {"cos", "sin", "tan", "cot", "sec", "csc", "cosh", "abs"};
  std::optional<Node> wrapper;
  bool bare = false, mixed = false, seen = false;
  std::function<void(const Node&)> visit = [&](const Node& n) {
    auto wraps_x = [&](const Node& w) {
      if (w.kind == NodeKind::Call && kPeriodic.count(w.text) && w.args.size() == 1 &&
          w.args[0].kind == NodeKind::Symbol && w.args[0].text == x)
        return true;
      if (w.kind == NodeKind::Pow && w.args[0].kind == NodeKind::Symbol && w.args[0].text == x &&
          w.args[1].kind == NodeKind::Number && w.args[1].text.find_first_not_of("0123456789") == std::string::npos &&
          (w.args[1].text.back() - '0') % 2 == 0)
        return true;
      return false;
    };
    if (wraps_x(n)) {
      seen = true;
      if (wrapper && to_text(*wrapper) != to_text(n)) mixed = true;
      if (!wrapper) wrapper = n;
      return;
    }
    if (n.kind == NodeKind::Symbol && n.text == x) bare = true;
    for (const auto& a : n.args) visit(a);
  };
  for (const auto& label : refs)
    if (const Step* st = d_.find(label))
      for (const auto& side : st->claim.sides) visit(side);
  if (!seen || bare || mixed) return std::nullopt;
  return wrapper;
}

// A refutation of `x = G` where the rows give only w(x) (cos(x), x^2): the claim with both
// sides under w is checked from the same rows. Refuted: a slip in what the rows do give, and
// `wrapped` holds that evidence. Holds: the row picks one root of several, and the reason the
// counterexample is no evidence (naming the declaration that would decide) is returned.
std::string Search::branch_doubt(const std::vector<std::string>& refs, std::optional<StepResult>& wrapped) {
  const Node& subject = s_.claim.sides.front();
  if (subject.kind != NodeKind::Symbol || s_.claim.sides.size() != 2) return "";
  const std::optional<Node> w = branch_wrapper(refs, subject.text);
  if (!w) return "";
  auto wrap = [&](const Node& side) {
    Node n = *w;
    if (n.kind == NodeKind::Call) n.args[0] = side;
    else n.args[0] = side;
    return n;
  };
  Relation claim;
  claim.sides = {wrap(s_.claim.sides[0]), wrap(s_.claim.sides[1])};
  StepResult r = attempt_positive(refs, &claim);
  if (!usable(r)) return "";
  if (r.verdict.kind == VerdictKind::Refuted && !side_condition_only(r.verdict)) {
    r.verdict.detail = "the rows give " + to_text(*w) + ", and the row's value of it differs" +
                       (r.verdict.detail.empty() ? "" : "; " + r.verdict.detail);
    wrapped = r;
    return "";
  }
  if (!r.verdict.holds() && !side_condition_only(r.verdict)) return "";
  const Node& rhs = s_.claim.sides[1];
  std::string decl;
  if (w->kind == NodeKind::Pow || w->text == "abs")
    decl = "assume " + subject.text + (rhs.kind == NodeKind::Neg ? " < 0" : " > 0");
  else if (rhs.kind == NodeKind::Call && rhs.text == "acos")
    decl = "assume 0 <= " + subject.text + " <= pi";
  else if (rhs.kind == NodeKind::Call && (rhs.text == "asin" || rhs.text == "atan"))
    decl = "assume -pi/2 <= " + subject.text + " <= pi/2";
  else
    decl = "assume … (the range of " + subject.text + ")";
  return "the rows give " + to_text(*w) + " only, and the row picks one value of " + subject.text +
         " with it (a root the claim chooses); a declaration such as `" + decl + "` decides it";
}

// A refutation only because one side is undefined where the other is defined (the sides hold
// equal wherever both are): in a document that declares no ranges, that is a range the
// author did not state, not a slip.
bool Search::side_condition_only(const Verdict& v) {
  return v.kind == VerdictKind::Refuted && v.method.find("+ side condition") != std::string::npos;
}

// The rows among refs that differentiate a function the row applies (label, function name).
std::vector<std::pair<std::string, std::string>> Search::equations_for_applied(
    const std::vector<std::string>& refs) const {
  std::set<std::string> applied;
  for (const auto& side : s_.claim.sides)
    walk_nodes(side, [&](const Node& x) {
      if (x.kind == NodeKind::Call && x.text.find("__of_") != std::string::npos) applied.insert(x.text);
    });
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& label : refs) {
    const Step* st = d_.find(label);
    if (!st) continue;
    std::string differentiated;
    for (const auto& side : st->claim.sides)
      walk_nodes(side, [&](const Node& x) {
        if (x.kind == NodeKind::Call && x.text == "diff" && !x.args.empty() && x.args[0].kind == NodeKind::Call &&
            applied.count(x.args[0].text))
          differentiated = x.args[0].text;
      });
    if (!differentiated.empty()) out.push_back({label, differentiated.substr(0, differentiated.find("__of_"))});
  }
  return out;
}

// The rows among refs that are givens of this row's own display (they introduced names).
std::vector<std::string> Search::own_display_givens(const std::vector<std::string>& refs) const {
  std::vector<std::string> out;
  for (const auto& label : refs) {
    const Step* st = d_.find(label);
    if (!st || !st->document_row || st->document_row->relation == "inline") continue;
    if (st->document_row->display == row_.display && !new_names_of(*st).empty()) out.push_back(label);
  }
  return out;
}

// A later link of a chain that ends in an expression computes the quantity its first side
// names: `K = \tfrac12 m v^2 = q^2 B^2 R^2/(2m)` with the display's `R = m v/(qB)` is no new law.
// A chain that ends in a constant, `… = m_p v_p - m_c v_c = 0`, may state one; so may a link
// whose left side is a name a given of the display leaves free (`i = \dot q = -\omega_0 Q_0
// \sin\omega_0 t`, \dot q read as a new name).
bool Search::chain_computes(const std::vector<std::string>& refs) const {
  if (row_.link < 2) return false;
  const Node& first = s_.claim.sides.front();
  const Node& last = s_.claim.sides.back();
  if (last.kind == NodeKind::Number ||
      (last.kind == NodeKind::Neg && !last.args.empty() && last.args[0].kind == NodeKind::Number))
    return false;
  if (first.kind != NodeKind::Symbol) return true;
  // (a given that introduces it alone determines it, `\tfrac12 m v^2 = G M m/R` then
  // `v = \sqrt{2 G M/R}`; one that introduces it beside another name, `i = \dot q`, does not)
  for (const auto& label : own_display_givens(refs))
    if (const Step* st = d_.find(label)) {
      const auto fresh = new_names_of(*st);
      if (fresh.size() > 1 && std::find(fresh.begin(), fresh.end(), first.text) != fresh.end()) return false;
    }
  return true;
}

// `W = F d = \tfrac12 m v^2` with d new in the first link: nothing but that link relates d, and
// the second link may be the law that fixes it (work and energy), so a point that fails it is
// no evidence. A name counts when a given of this display introduces it beside the name it sets
// (a given that introduces one name alone determines it, and one that sets no name relates its
// new names to each other). Not when the row's difference, the
// display's givens put in, is a function of the name times one without it: `K = \tfrac12 m v^2
// = q^2 B R^2/(2m)` with `R = m v/(qB)` leaves v^2 (1 - 1/B) m/2, which fixes B, not v.
std::string Search::law_about_new_name() const {
  if (law_) return *law_;
  law_ = std::string();
  std::string& out = *law_;
  std::set<std::string> mine;
  for (const auto& side : s_.claim.sides) names_of(side, mine);
  std::vector<std::string> loose;
  std::vector<const Step*> givens;
  for (const auto& st : d_.steps) {
    if (&st == &s_) break;
    if (!st.document_row || st.document_row->display != row_.display || st.document_row->relation == "inline" ||
        !st.document_row->not_read.empty() || st.claim.sides.size() != 2)
      continue;
    const auto fresh = new_names_of(st);
    if (fresh.empty()) continue;
    givens.push_back(&st);
    const std::string set = set_name(st);
    if (fresh.size() > 1 && !set.empty())   // (a relation that sets no name, W/(2\tan\theta) = \mu W, fixes one of its new names)
      for (const auto& n : fresh)
        if (n != set && mine.count(n)) loose.push_back(n);
  }
  if (loose.empty()) return "";
  try {
    GiNaC::ex diff = to_ginac(s_.claim.sides.front(), d_.symbols) - to_ginac(s_.claim.sides.back(), d_.symbols);
    for (const Step* g : givens)
      if (g->claim.sides[0].kind == NodeKind::Symbol)
        diff = diff.subs(to_ginac(g->claim.sides[0], d_.symbols) == to_ginac(g->claim.sides[1], d_.symbols),
                         GiNaC::subs_options::no_pattern);
    for (const auto& n : loose) {
      Node name;
      name.kind = NodeKind::Symbol;
      name.text = n;
      const GiNaC::ex x = to_ginac(name, d_.symbols);
      if (!diff.has(x)) continue;
      const GiNaC::symbol a("law_a"), b("law_b");
      const GiNaC::ex ratio = GiNaC::normal(diff.subs(x == a, GiNaC::subs_options::no_pattern) /
                                            diff.subs(x == b, GiNaC::subs_options::no_pattern));
      bool separable = true;
      for (GiNaC::const_preorder_iterator it = ratio.preorder_begin(); it != ratio.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(a) && !it->is_equal(b)) separable = false;
      if (!separable)
        return out = "'" + n + "' is new in this display and nothing but its first relation relates it, so the row "
                     "may be the law that fixes it";
    }
  } catch (const std::exception&) {
    out = "the row's difference could not be formed to see whether it fixes a name new in this display";
  }
  return out;
}

bool Search::calculus_of_constants() const {
  // the names that are a function of a variable somewhere in the document: v for v__of_t
  std::set<std::string> varying;
  for (const auto& info : d_.symbols.all()) {
    const std::size_t of = info.name.find("__of_");
    if (of != std::string::npos) varying.insert(info.name.substr(0, of));
    if (info.is_function) varying.insert(info.name);
  }
  bool ok = true, any = false;
  for (const auto& side : s_.claim.sides)
    walk_nodes(side, [&](const Node& x) {
      if (x.kind != NodeKind::Call) return;
      if (x.text == "limit") ok = false;   // a limit's regime may be stated only in words
      if (x.text != "diff" && x.text != "integral") return;
      any = true;
      if (x.args.empty()) return;
      walk_nodes(x.args[0], [&](const Node& y) {
        if (y.kind == NodeKind::Call && y.text.find("__of_") != std::string::npos) ok = false;
        if (y.kind == NodeKind::Symbol && (varying.count(y.text) || y.text.find("__of_") != std::string::npos)) ok = false;
        if (y.kind == NodeKind::Call && (y.text == "diff" || y.text == "integral" || y.text == "limit")) ok = false;
      });
    });
  return any && ok;
}

// Why a counterexample is no evidence against the author here ("" when it is).
std::string Search::reading_in_doubt(const StepResult& r, const std::vector<std::string>& refs) const {
  if (side_condition_only(r.verdict))
    return "the sides agree wherever both are defined, and they need different conditions (" + r.verdict.detail +
           ")";
  if (std::string unset = unset_name(refs); !unset.empty()) return unset;
  {   // `\sum_i^n p_i` read as one quantity: linearity, the terms, the index are not seen
    std::set<std::string> mine;
    for (const auto& side : s_.claim.sides) names_of(side, mine);
    for (const auto& n : mine)
      if (n.rfind("Sum_", 0) == 0)
        return "the row has a sum over an index it does not count out, read as one quantity (" + n +
               "): its terms are not seen";
  }
  // a display that lists a system (`m a = …`, `f r = I\alpha`, `a = \alpha r`) or a chain that
  // names its quantities and then states a law (`\Delta p = p_p + p_c = m_p v_p - m_c v_c = 0`):
  // against rows before it in the same display that introduced names (givens), the row may be
  // one more equation of the system rather than a consequence of it
  if (std::string law = law_about_new_name(); !law.empty()) return law;
  if (const auto own = own_display_givens(refs); !own.empty() && !chain_computes(refs))
    return "the counterexample rests on " + own.front() + ", a given of this same display, so the row may be one "
           "more law of the system it lists";
  // `… = m_p v_p - m_c v_c = 0` after links that only name the sum: the counterexample chose
  // every name of the row freely, so the rows relate none of them, and the row adds a
  // relation among them (a conservation law) as likely as a slip
  {
    std::set<std::string> mine, chosen;
    for (const auto& side : s_.claim.sides) names_of(side, mine);
    for (const auto& [name, value] : r.verdict.point) chosen.insert(name);
    bool all_chosen = !mine.empty() && !r.verdict.point.empty();
    for (const auto& n : mine) all_chosen = all_chosen && chosen.count(n);
    if (all_chosen)
      return "the rows relate none of the row's names (the counterexample chooses them all), so the row may "
             "state a law about them";
  }
  // `ΔT = …` against an earlier display's `ΔT = …`: documents reuse a name for the quantity
  // of the next case (the energy lost in an inelastic impact, then in any impact)
  const Node& subject = s_.claim.sides.front();
  // (not when the text says the row substitutes into the rows before it: the same quantity)
  const bool substitutes = row_.hint.find("substitut") != std::string::npos ||
                           row_.hint.find("insert") != std::string::npos || row_.hint.find("plug") != std::string::npos;
  if ((subject.kind == NodeKind::Symbol || subject.kind == NodeKind::Call) && !substitutes)
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
  if (!r.verdict.hint.empty()) return std::string(kHoldsIfDeclared) + " (" + r.verdict.hint + ")";
  // (a derivative or integral of an explicit expression in constants, d/dt ln(m_0/(m_0 - k t)),
  // that is false read alone is a slip whatever the rows say: no name in it can vary)
  static const std::set<std::string> calculus = {"diff", "integral", "limit"};
  const bool certain = identity_refuted_ && calculus_of_constants();
  for (const auto& side : s_.claim.sides)
    if (has_call(side, calculus) && !certain)
      return "the row takes a limit, a derivative or an integral, whose reading (which names vary, the "
             "regime) is not certain";
  // `\theta(x) = \theta_b e^{-mx}` against `\theta'' = m^2\theta` and `\theta(0) = \theta_b`: the
  // rows give a differential equation for a function the row applies, and which of its
  // solutions the row takes is fixed by conditions the text may state only in words (the
  // excess dies away far from the wall)
  if (const auto odes = equations_for_applied(refs); !odes.empty())
    return odes.front().first + " is a differential equation for " + odes.front().second +
           ", and which of its solutions the row takes is fixed by conditions the text may state in words";
  // (an identity of explicit calculus that is false alone is no step of an operation the text
  // names, "integrating from 0 to t we use …"; a regime it names still counts)
  if (prose_names_a_regime(row_.hint, !certain))
    return "the text before the display names a regime or a law the search does not read";
  return "";
}

}  // namespace dc::document_detail
