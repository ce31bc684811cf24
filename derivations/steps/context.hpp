// What every rule works with (derivations/steps/, shared by the rules): the step being checked, its
// references read as equations, substitutions, verdict helpers and the error a rule throws when
// the step cannot be checked as written.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/decide/prove.hpp"
#include "derivations/steps/step_result.hpp"

namespace dc::rules {

using GiNaC::ex;

// Thrown inside a rule when the step cannot be checked as written (reported as an error).
// input: the input itself is unusable (references that contradict each other): exit code 2.
struct StepError {
  InputError error;
  bool input = false;
};

InputError positioned(const Derivation& d, const SourcePos& p, const std::string& msg, int len = 1);
InputError with_line(const Derivation& d, const InputError& e);

// --- verdicts -------------------------------------------------------------------------
Verdict undecided(const std::string& method, const std::string& reason);
Verdict proved(const std::string& method, const std::string& detail = {});
std::string prefix_method(const std::string& rule_method, const std::string& prove_method);

// How bad a verdict is for the step: proved 0, holds numerically 1, undecided 2, refuted 3.
int severity(VerdictKind k);

// The worst verdict decides; proved methods are listed once each, in order.
struct Combiner {
  Verdict worst;
  bool any = false;
  std::vector<std::string> methods;
  // silent: a consistency check whose method is not worth naming when it holds
  void add(Verdict v, const std::string& what, bool silent = false);
  Verdict result() const;
};

// --- atoms: abstract function applications and integrals of them (symbolic/integral_atom.hpp)
// become symbols while eliminating
struct Atomizer : GiNaC::map_function {
  GiNaC::exmap fwd, back;
  int n = 0;
  ex operator()(const ex& e) override;
  ex restore(const ex& e) const { return back.empty() ? e : e.subs(back, GiNaC::subs_options::no_pattern); }
};

// No symbol and no abstract application: a constant (possibly irrational: pi - 3).
bool free_of_unknowns(const ex& e);
bool has_any(const ex& e, const std::vector<ex>& syms);

// An equation E = 0 with an optional hint: the symbol the author wrote alone on its left.
struct Eq {
  Eq(ex e_, ex hint_ = ex(), std::string from_ = {}, std::vector<std::string> also_ = {})
      : e(std::move(e_)), hint(std::move(hint_)), from(std::move(from_)), also(std::move(also_)) {}
  ex e;
  ex hint;
  std::string from;                // label, for messages
  std::vector<std::string> also;   // further references it rests on (substitutions applied to it)
};

using Substitutions = std::vector<std::pair<ex, ex>>;

// The step being checked. One per step: the atoms and the cache of coefficients shown nonzero
// are shared by everything the rule derives for it.
struct StepContext {
  StepContext(const Derivation& d_, const Step& s_, const ProveOptions& opt_, StepResult& res_)
      : d(d_), s(s_), opt(opt_), res(res_) {}

  const Derivation& d;
  const Step& s;
  const ProveOptions& opt;
  StepResult& res;
  Atomizer atoms;
  std::map<ex, bool, GiNaC::ex_is_less> nonzero_cache;   // see nonzero_coefficient (elimination.hpp)


  // A cited step `integral(f, x) = F` (an antiderivative, which the `integrate` rule checks by
  // differentiation) is no equation between values: it is instantiated. Every definite
  // integral of f between a and b in what this step converts becomes F(b) - F(a)
  // (`eval_between(F, x, a, b)`), where F is continuous on the whole line (so the fundamental
  // theorem holds between any limits); an indefinite integral is never replaced by F as a
  // value (two antiderivatives differ by a constant).
  struct Antiderivative {
    std::string label;
    Node F, x;       // as written
    ex f, xs, Fe;    // the integrand and F in the declared variable xs
  };
  const std::vector<Antiderivative>& antiderivatives() const;
  bool is_antiderivative(const RuleArg& a) const;

  const RuleSpec& rule() const { return s.rule; }
  [[noreturn]] void fail(const SourcePos& p, const std::string& msg, int len = 1) const;
  std::string text(const ex& e) const;
  ex conv(const Node& n) const;
  std::vector<ex> sides(const Relation& r) const;
  ex symbol_of(const RuleArg& a) const;   // the argument as a symbol (fails otherwise)

  const Step& ref_step(const RuleArg& a) const;
  // Equations of a referenced step (adjacent sides), or of an inline equation.
  std::vector<Eq> equations(const RuleArg& a) const;
  std::vector<Eq> all_equations(const std::vector<RuleArg>& args) const;
  // Substitutions `x = value` (inline or a label `x = expr`), applied in order. A reference
  // that is not of that form goes to `rest` as an equation (an error when rest is null).
  // labels (optional): the label of each substitution, for messages.
  Substitutions substitutions(const std::vector<RuleArg>& args, std::vector<Eq>* rest,
                              std::vector<std::string>* labels = nullptr) const;

  // The symbols of the expressions, each once, in declaration order (then by name).
  std::vector<ex> symbols_in(const std::vector<ex>& es) const;
  int declaration_index(const ex& s) const;
  bool real_domain(const ex& s) const;

 private:
  mutable std::optional<std::vector<Antiderivative>> antiderivatives_;
  Node instantiated(const Node& n) const;
};

// Names that are functions of t by a cited step: a `definition` whose value contains t
// (resolved everywhere already), or a `given` `q = expr` with q a plain symbol and t in expr.
// The given's q is then expr at every t, in the claim of this step: `sides` gives the claim
// with it replaced (a reference that only mentions q at one value, y = F0*t, says nothing
// about an integral of F0*t, which does not mention y). `evidence`: "p is a function of t by
// its definition s1; ...".
struct ThroughT {
  std::map<std::string, Node> given_values;
  std::string evidence;
  std::vector<ex> sides(const StepContext& c, const Relation& claim) const;
  Node resolve(const Node& n) const;
};
ThroughT names_through(const StepContext& c, const ex& t);

// A claim with differentials (d(y) = 2*x*d(x)) speaks of the changes along a path, and every
// equation of the references that is not a differential equation holds along it (y = x^2):
// its total differential is appended to `eqs` (symbolic/differential.hpp). A quantity whose
// differential the file never writes gets an unknown change of its own, so nothing is assumed
// constant.
void add_path_differentials(const StepContext& c, const std::vector<ex>& claim, std::vector<Eq>& eqs);
// The prefix of such an unknown change's name: δz for z (counterexample.cpp reads it back).
inline constexpr std::string_view kUnknownChange = "\u03b4";

// A step's claim as checked: the corrected form when the step declares an erratum.
const Relation& claim_of(const Step& st);

// Substitutions are applied repeatedly until nothing changes (so they may be given in any
// order); a cycle x = y, y = x stops after a fixed number of rounds.
// `used` (optional, one flag per substitution) records which substitutions changed something.
ex apply_subs(ex e, const Substitutions& subs, std::vector<bool>* used = nullptr);
// Apply substitutions to an equation, recording the ones that changed it as references it
// rests on.
void apply_to(Eq& q, const Substitutions& subs, const std::vector<std::string>& labels);

}  // namespace dc::rules
