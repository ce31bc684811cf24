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

#include "derivations/core/derivation.hpp"
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

class FormulaEvaluator {
 public:
  // Throws InputError for an unknown label; std::invalid_argument if the formula cannot be
  // compiled (abstract functions, derivatives). A stable form that needs inputs the formula
  // does not have is ignored (stable_label() is then empty).
  FormulaEvaluator(const Derivation& d, const std::string& label);

  const Formula& formula() const { return formula_; }
  const std::vector<GiNaC::symbol>& params() const { return formula_.params; }
  bool has_stable() const { return stable_.has_value(); }
  const std::string& stable_label() const { return stable_label_; }
  const std::string& regime() const { return regime_; }
  const std::optional<RegimeCondition>& condition() const { return condition_; }

  // Does the stable form apply at x (always true without a condition)?
  bool in_regime(const double* x) const;
  double operator()(const std::vector<double>& x) const;
  double naive(const std::vector<double>& x) const { return naive_(x); }
  // One column per parameter; the regime is decided per point.
  void eval_batch(const Eigen::ArrayXXd& in, Eigen::ArrayXd& out) const;

 private:
  Formula formula_;
  Evaluator<double> naive_;
  std::optional<Evaluator<double>> stable_;
  std::string stable_label_, regime_;
  std::optional<RegimeCondition> condition_;
  std::optional<Evaluator<double>> cond_lhs_, cond_rhs_;
};

}  // namespace dc::num
