// The justification search of one document step (justify.cpp), internal to the document stage.
// Its members live in three files: justify.cpp (the order of the search, the candidate sets
// of rows), justify_rules.cpp (the rules other than rewrite it tries: a limit, solve, first
// order) and justify_doubts.cpp (when a counterexample is no evidence against the author).
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "derivations/document/document.hpp"
#include "derivations/steps/context.hpp"

namespace dc::document_detail {

using rules::undecided;   // the verdicts the rules build, one construction for both
using rules::proved;

// The names a node mentions (symbols and applied functions that are not built in).
void names_of(const Node& n, std::set<std::string>& out);
void walk_nodes(const Node& n, const std::function<void(const Node&)>& f);
// Every plain name of n that `values` maps, except `keep`, replaced by its node (the position
// of the name kept); the base names replaced are added to `replaced` when given.
void replace_names(Node& n, const std::map<std::string, Node>& values, const std::string& keep = "",
                   std::set<std::string>* replaced = nullptr);
// d with every name it declares no domain for (except `except`) positive: the usual physical
// reading, in which a counterexample of a document's row must also hold.
Derivation positive_reading(const Derivation& d, const std::set<std::string>& except);
// Every application of function `id` in n replaced by `value` (the position kept).
void replace_calls(Node& n, const std::string& id, const Node& value);
bool has_call(const Node& n, const std::set<std::string>& names);
std::string join(const std::vector<std::string>& xs);
// Words in the prose around a display that announce a regime or a law.
bool prose_names_a_regime(const std::string& hint, bool operations = true);

class Search {
 public:
  Search(const Derivation& d, const Step& s, const ProveOptions& opt, bool nested = false, int* work = nullptr)
      : d_(d), s_(s), row_(*s.document_row), opt_(opt), nested_(nested), work_(work ? work : &own_work_) {}

  StepResult run();

 private:
  StepResult finish(StepResult& res, Verdict v);

  StepResult found(StepResult r, const std::string& rule, const std::vector<std::string>& refs);

  // A candidate's result can be used unless its references could not be (contradictory
  // references, an undefined name): then that set is no evidence either way.
  static bool usable(const StepResult& r) { return !r.input_error && r.errors.empty(); }

  RuleArg label_arg(const std::string& label) const;

  RuleArg node_arg(const Node& n, RuleArg::Kind kind) const;

  StepResult attempt(const std::vector<std::string>& refs);

  // The step checked with one rule of the .dc language (its rows and arguments filled in).
  // The rewrite from `refs` in the reading where every name of the document without a declared
  // domain is positive (masses, lengths, speeds of the usual physical reading).
  StepResult attempt_positive(const std::vector<std::string>& refs, const Relation* claim = nullptr,
                              const RuleSpec* rule = nullptr);   // (a rule other than rewrite)

  StepResult attempt_rule(RuleSpec rule, const Relation* claim = nullptr, const Derivation* on = nullptr);

  // The rows a rule may start from: the nearest and the most relevant rows in force, each once.
  std::vector<std::string> source_rows() const;

  // The locals as `with x = value` substitutions: those whose first side is a name and that do
  // not mention `skip` (a condition on the limit variable cannot hold along the limit).
  std::vector<RuleArg> local_substitutions(const std::vector<std::string>& labels, const std::string& skip) const;

  // `v'_1 = \lim_{m_2\to\infty} …` after `v'_1 = f(m_2)`: the limit of that row's expression,
  // with the conditions in force (those on the limit variable dropped). An approximate row
  // under a condition `x \approx 0` (or `= 0`): the limit x -> 0 of a row with the same subject.
  std::optional<StepResult> by_limit();

  // `theta = \arccos(…)` from rows that give cos(theta): solved for the subject, the names of
  // the rows that the claim does not mention eliminated.
  // (a refutation it meets, the claim substituted back into the rows, is added to `refutations`
  // for the doubts to weigh like any other)
  struct Refutation {
    StepResult r;
    std::vector<std::string> refs;
    bool solved = false;   // found by solving for the subject (its positive reading solves too)
  };
  using Refutations = std::vector<Refutation>;
  std::optional<StepResult> by_solve(Refutations& refutations);
  // `solve REFS for` the row's subject and the names of REFS it does not mention
  RuleSpec solve_for_subject(const std::vector<std::string>& refs) const;
  static bool substituted_back_refutes(const StepResult& r);
  RuleSpec solve_spec(const std::vector<std::string>& refs, const Node& subject, const std::set<std::string>& names,
                      const std::set<std::string>& skip) const;

  // `… = m_r\Delta v - u_e\Delta m` "where the higher-order term was neglected": the two sides
  // differ by terms of second order in the small quantities (the names the text writes with
  // \Delta or \delta), each scaled by one eps -> 0. Only when the text says so; never refutes.
  std::optional<StepResult> by_first_order();

  // `m_r\frac{dv}{dt} - u_e\frac{dm}{dt} = 0` "taking the time derivative" of the balance
  // `m_r\Delta v - u_e\Delta m = 0`: a relation linear in the increments (each Delta_x times a
  // factor free of increments, Delta_t the step of the variable) holds for the increments over
  // any interval, so divided by it and in the limit each Delta_x becomes dx/dt (Delta_t
  // becomes 1). Only when the text speaks of a derivative, a rate or a limit.
  std::optional<StepResult> by_rates();

  // The rewrite from `refs` with their plain names read as the claim's functions of its
  // variable (`m_r a = u_e\mu - m_r g` as m_r(t) a = …, beside `m_r\frac{dv}{dt}`): a law
  // holds at every instant. The name a row sets keeps its value (`v = v_0` is one instant).
  // nullopt when no name needs lifting.
  std::optional<StepResult> attempt_lifted(const std::vector<std::string>& refs);

  // `v = -u_e\ln(m_r/m_0) - g t` "integrated" from `m_r\frac{dv}{dt} = -u_e\frac{dm_r}{dt} - m_r g`,
  // `x = A\cos(\omega_0 t + \phi)` "the general solution" of `\ddot x + \omega_0^2 x = 0`: the
  // row's value of its subject, with the names the equation makes functions of its variable
  // read so, put into the equation leaves an identity, and the names the row introduces (m_0;
  // A, phi) are its constants of integration. Only when the text says so ("integrat",
  // "solution", "solving"). When it leaves no identity whatever the constants (and every other
  // name of the row is one of the equation's, and a counterexample holds at positive values):
  // refuted.
  std::optional<StepResult> by_integration();
  std::vector<std::string> equation_rows() const;

  // `\frac{dv_y}{dt} = -g` "differentiating" the earlier `v_y = v_0\sin\alpha - g t`: the row's
  // derivatives of a name an earlier row sets (its subject, as a function of the derivative's
  // variable) replaced by the derivative of that row's value leave an identity. Only when the
  // text says so ("differentiat", "derivative"). When they leave none (every other name of the
  // row one of that row's, a counterexample at positive values): refuted.
  std::optional<StepResult> by_differentiation();

  // The names of the claim that no earlier step mentions.
  bool introduces_names();
  std::vector<std::string> new_names_of(const Step& s) const;

  // Small sets first: what the author cites, then the nearest rows, then more of them; the
  // inline givens in force join every set.
  std::vector<std::vector<std::string>> candidate_sets() const;

  // A proof from several rows is worth nothing when one of them is a slip: the slip and the row
  // it garbles pin a quantity to a special value, and from that anything about it follows
  // (`w_2 = …/(m_1 + m_1)` beside the right `w_2` "proves" m_1 m_2 = 0). So each row used that
  // is not a given is searched for itself (one level deep), and a refuted one voids the proof.
  bool rests_on_a_slip(const std::vector<std::string>& refs, std::vector<std::string>* slips = nullptr) const;

  // A condition the text stated earlier in the section (`$T_1 = T_2$`), not in force here by the
  // reader's rule, under which the row follows from the same rows: the author may still mean it.
  std::string earlier_condition(const std::vector<std::string>& refs);
  std::string free_subject(const StepResult& r, const std::vector<std::string>& refs, StepResult& evidence);

  // A refutation against a row that its own search refutes is a refutation against the slip
  // before it: the author's later rows continue from the right result. Each row of the set is
  // searched for itself (one level deep).
  std::string untrusted_row(const std::vector<std::string>& refs);

  // Is an earlier document step in force for this row: its conditions (the equations of the
  // text it was read under) hold here too, and an equation of the text itself is in force only
  // for the displays it is a condition of.
  bool in_force(const Step& st) const;

  // Earlier rows in force here (their conditions hold here too), by how many of the claim's
  // names they mention, the nearer first on a tie.
  std::vector<std::string> most_relevant() const;

  // A reference must be an equation that was read.
  bool usable_ref(const std::string& label) const;

  // Every name of the claim occurs in the rows of the refutation: otherwise the claim speaks
  // of something those rows leave free, and a point where it fails says nothing.
  bool rows_speak_of_claim(const std::vector<std::string>& refs) const;

  // The name a row sets: its first side when that is a name, or a power of one (`\omega_d^2 = …`).
  static std::string set_name(const Step& st);

  // A name of the claim that some earlier row sets while none of the refuting rows does: the
  // counterexample gives it a value that row forbids, so it says nothing against the author
  // (`a = g\sin\beta/(1 + I/(m r^2)) = \frac{5}{7} g \sin\beta` needs `I = \frac{2}{5} m r^2`).
  std::string unset_name(const std::vector<std::string>& refs) const;
  std::vector<std::string> unset_setters(const std::vector<std::string>& refs) const;

  // The one non-injective function through which the rows mention the claim's subject x:
  // cos(x), sin(x), tan(x), x^2 (an even power), |x|. Null when x also appears bare, or under
  // two different ones.
  std::optional<Node> branch_wrapper(const std::vector<std::string>& refs, const std::string& x) const;

  // A refutation of `x = G` where the rows give only w(x) (cos(x), x^2): the claim with both
  // sides under w is checked from the same rows. Refuted: a slip in what the rows do give, and
  // `wrapped` holds that evidence. Holds: the row picks one root of several, and the reason the
  // counterexample is no evidence (naming the declaration that would decide) is returned.
  std::string branch_doubt(const std::vector<std::string>& refs, std::optional<StepResult>& wrapped);

  // A refutation only because one side is undefined where the other is defined (the sides hold
  // equal wherever both are): in a document that declares no ranges, that is a range the
  // author did not state, not a slip.
  static bool side_condition_only(const Verdict& v);

  // Why a counterexample is no evidence against the author here ("" when it is).
  std::string reading_in_doubt(const StepResult& r, const std::vector<std::string>& refs) const;
  std::vector<std::string> own_display_givens(const std::vector<std::string>& refs) const;
  bool chain_computes(const std::vector<std::string>& refs) const;
  std::string law_about_new_name() const;   // (the same for every refutation: computed once)
  mutable std::optional<std::string> law_;
  std::vector<std::pair<std::string, std::string>> equations_for_applied(const std::vector<std::string>& refs) const;

  const Derivation& d_;
  const Step& s_;
  const DocumentRow& row_;
  const ProveOptions& opt_;
  // What a row's own (nested) search found, once per row: refuted, a given or derived, or cut
  // short by the count of tries (then neither a proof nor a refutation may rest on it).
  // The doubt of a row whose counterexample a declaration of sign would rule out.
  static constexpr const char* kHoldsIfDeclared = "the row holds under a declaration the document does not make";
  struct Own {
    bool refuted = false;
    bool withheld = false;   // a counterexample satisfies the rows before it, refutation withheld
    bool established = false;
    bool cut = false;
    // undecided only for want of a sign: it holds where the names the document declares nothing
    // about are positive (the reading a refutation of a later row is confirmed in)
    bool holds_if_positive = false;
  };
  mutable std::map<std::string, Own> own_;
  const Own& own_search(const Step& st) const;
  std::unique_ptr<Derivation> positive_;   // d_ with every undeclared name positive (made when needed)
  std::vector<std::string> new_names_;
  std::vector<std::string> tried_;
  std::string voided_;   // the first proof voided by a row that may be a slip, for the reason
  bool nested_ = false;
  // The row is false read alone, as an identity (a certified counterexample that is no
  // side-condition difference): what its calculus means then does not depend on the rows.
  bool identity_refuted_ = false;
  // Every derivative and integral of the row is of an explicit expression: no name in it
  // applies a function or is a function of a variable anywhere in the document.
  bool calculus_of_constants() const;
  // The rules tried so far (a nested search counts into its parent's). Past kMaxWork the
  // search tries nothing more that could prove, and a counterexample it has not finished
  // checking is no evidence: a count, not a clock, so the verdict is the same on any machine
  // and at any --jobs, and the step stays inside its budget (default 2 s).
  int own_work_ = 0;
  int* work_;
  static constexpr int kMaxWork = 60;
  static constexpr std::size_t kMaxWidened = 8;   // rows in a refutation's set widened by setters
  bool late() const { return *work_ >= kMaxWork; }
};

}  // namespace dc::document_detail
