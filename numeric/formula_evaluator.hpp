// The evaluator a user of a derivation's formula gets: the formula compiled to a tape, plus the
// file's stable form (a step `stable LABEL "regime"`) used in its regime.
//
// Regime: a stable form is used everywhere, unless its regime text starts with a condition
//     stable velocity_symbols "when m_r > m0/2: m_r close to m0 ..."
// ("when" LHS OP RHS ":" with OP one of < <= > >=, sides in the expression language over the
// formula's parameters); then it is used exactly where the condition holds at the point and the
// formula itself elsewhere. This is needed where the stable form is itself ill-conditioned
// outside its regime: log1p(-(m0 - m_r)/m0) is perfect for m_r close to m0 and loses digits
// for m_r << m0, where log(m_r/m0) is perfect.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "derivations/reader/derivation.hpp"
#include "numeric/compensated.hpp"
#include "numeric/evaluator.hpp"

namespace dc::num {

struct RegimeCondition {
  enum class Rel { Lt, Le, Gt, Ge } rel = Rel::Gt;
  Program lhs, rhs;
  std::string text;  // "m_r > m0/2"
};

// Parses the "when COND:" prefix of a stable step's regime text (nullopt without one). The
// condition's symbols must be among `inputs`. Malformed conditions throw InputError at the step.
std::optional<RegimeCondition> parse_regime(const Derivation& d, const Step& stable_step,
                                            const std::vector<GiNaC::symbol>& inputs);

// Can the tape cancel? A sign analysis over the program with the inputs' declared domains
// (positive, negative, interval bounds; constants by value): true iff some add/sub may combine
// operands of opposite sign (after the subtraction's negation) and at least one of them is a
// computed value (a temporary), i.e. carries rounding errors a cancellation would amplify.
// x - y of two inputs or constants is one rounding (relative error <= 1/2 ulp) and does not count.
bool may_cancel(const Program& p, const SymbolTable& symbols);

// How FormulaEvaluator::operator() evaluates.
//   Fast:        the tapes in double.
//   Compensated: the tapes in double-double (compensated.hpp), rounded at the end: ~20x slower (docs/performance.md).
//   Auto:        Compensated iff the tape used (the stable form where the file has one, and in
//                its regime; the formula otherwise) may cancel (may_cancel); otherwise Fast.
//                A formula with a sign change in its domain (v'1, the rocket's v) may cancel;
//                ΔT's stable form, θ's asin form, Δh = 2 L sin²(θ/2) cannot and stay Fast.
enum class EvalMode { Auto, Fast, Compensated };

class FormulaEvaluator {
 public:
  // Throws InputError for an unknown label; std::invalid_argument if the formula cannot be
  // compiled (abstract functions, derivatives). A stable form that needs inputs the formula
  // does not have is ignored (stable_label() is then empty).
  FormulaEvaluator(const Derivation& d, const std::string& label, EvalMode mode = EvalMode::Auto);

  const Formula& formula() const { return formula_; }
  const std::vector<GiNaC::symbol>& params() const { return formula_.params; }
  bool has_stable() const { return stable_.has_value(); }
  const std::string& stable_label() const { return stable_label_; }
  const std::string& regime() const { return regime_; }
  const std::optional<RegimeCondition>& condition() const { return condition_; }

  // Does the stable form apply at x (always true without a condition)?
  bool in_regime(const double* x) const;
  // Does operator() evaluate in double-double (the mode, with Auto resolved)?
  bool compensated() const { return compensated_; }
  double operator()(const std::vector<double>& x) const;
  // The stable form in its regime, the formula elsewhere: in double / in double-double.
  double fast(const std::vector<double>& x) const;
  double compensated_value(const std::vector<double>& x) const;
  double naive(const std::vector<double>& x) const { return naive_(x); }
  // One column per parameter; the regime is decided per point.
  void eval_batch(const Eigen::ArrayXXd& in, Eigen::ArrayXd& out) const;

 private:
  void check_size(std::size_t n) const;
  Formula formula_;
  Evaluator<double> naive_;
  std::optional<Evaluator<double>> stable_;
  CompensatedEvaluator naive_dd_;
  std::optional<CompensatedEvaluator> stable_dd_;
  bool compensated_ = false;
  std::string stable_label_, regime_;
  std::optional<RegimeCondition> condition_;
  std::optional<Evaluator<double>> cond_lhs_, cond_rhs_;
};

}  // namespace dc::num
