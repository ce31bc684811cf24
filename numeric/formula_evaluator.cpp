#include "numeric/formula_evaluator.hpp"

#include <stdexcept>

#include "derivations/core/expr.hpp"
#include "derivations/core/source.hpp"
#include "derivations/core/symbols.hpp"

namespace dc::num {
namespace {

const Step* stable_step_for(const Derivation& d, const std::string& label) {
  for (const Step& s : d.steps)
    if (s.stable_of && *s.stable_of == label) return &s;
  return nullptr;
}

}  // namespace

std::optional<RegimeCondition> parse_regime(const Derivation& d, const Step& s,
                                            const std::vector<GiNaC::symbol>& inputs) {
  const std::string& t = s.stable_regime;
  if (t.rfind("when ", 0) != 0) return std::nullopt;
  const auto colon = t.find(':');
  if (colon == std::string::npos)
    throw InputError(s.pos, "regime of '" + s.label + "': expected 'when CONDITION: text'",
                     static_cast<int>(s.label.size()));
  const std::string cond = t.substr(5, colon - 5);
  RegimeCondition rc;
  rc.text = cond;
  std::size_t at = std::string::npos, len = 1;
  for (std::size_t i = 0; i < cond.size(); ++i) {
    if (cond[i] == '<' || cond[i] == '>') {
      at = i;
      const bool eq = i + 1 < cond.size() && cond[i + 1] == '=';
      len = eq ? 2 : 1;
      rc.rel = cond[i] == '<' ? (eq ? RegimeCondition::Rel::Le : RegimeCondition::Rel::Lt)
                              : (eq ? RegimeCondition::Rel::Ge : RegimeCondition::Rel::Gt);
      break;
    }
  }
  if (at == std::string::npos)
    throw InputError(s.pos, "regime condition '" + cond + "' of '" + s.label +
                                "': expected a comparison with <, <=, > or >=",
                     static_cast<int>(s.label.size()));
  const Node l = parse_expression(cond.substr(0, at), s.pos);
  const Node r = parse_expression(cond.substr(at + len), s.pos);
  try {
    rc.lhs = compile(to_ginac(l, d.symbols), inputs);
    rc.rhs = compile(to_ginac(r, d.symbols), inputs);
  } catch (const std::invalid_argument& e) {
    throw InputError(s.pos, "regime condition '" + cond + "' of '" + s.label + "': " + e.what(),
                     static_cast<int>(s.label.size()));
  }
  return rc;
}

FormulaEvaluator::FormulaEvaluator(const Derivation& d, const std::string& label)
    : formula_(dc::formula(d, label)), naive_(compile(formula_.expr, formula_.params)) {
  if (const Step* s = stable_step_for(d, label)) {
    try {
      stable_.emplace(compile(dc::formula(d, s->label).expr, formula_.params));
    } catch (const std::invalid_argument&) {
      return;  // the stable form needs other inputs: not usable for this formula
    }
    stable_label_ = s->label;
    regime_ = s->stable_regime;
    condition_ = parse_regime(d, *s, formula_.params);
    if (condition_) {
      cond_lhs_.emplace(condition_->lhs);
      cond_rhs_.emplace(condition_->rhs);
    }
  }
}

bool FormulaEvaluator::in_regime(const double* x) const {
  if (!stable_) return false;
  if (!condition_) return true;
  const double l = (*cond_lhs_)(x), r = (*cond_rhs_)(x);
  switch (condition_->rel) {
    case RegimeCondition::Rel::Lt: return l < r;
    case RegimeCondition::Rel::Le: return l <= r;
    case RegimeCondition::Rel::Gt: return l > r;
    case RegimeCondition::Rel::Ge: return l >= r;
  }
  return false;
}

double FormulaEvaluator::operator()(const std::vector<double>& x) const {
  if (x.size() != formula_.params.size())
    throw std::invalid_argument("formula '" + formula_.label + "' takes " +
                                std::to_string(formula_.params.size()) + " values, got " +
                                std::to_string(x.size()));
  return in_regime(x.data()) ? (*stable_)(x.data()) : naive_(x.data());
}

void FormulaEvaluator::eval_batch(const Eigen::ArrayXXd& in, Eigen::ArrayXd& out) const {
  if (static_cast<std::size_t>(in.cols()) != formula_.params.size())
    throw std::invalid_argument("formula '" + formula_.label + "': expected " +
                                std::to_string(formula_.params.size()) + " columns");
  if (!stable_) {
    naive_.eval_batch(in, out);
    return;
  }
  Eigen::ArrayXd s;
  stable_->eval_batch(in, s);
  if (!condition_) {
    out = s;
    return;
  }
  naive_.eval_batch(in, out);
  Eigen::ArrayXd l, r;
  cond_lhs_->eval_batch(in, l);
  cond_rhs_->eval_batch(in, r);
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    bool use = false;
    switch (condition_->rel) {
      case RegimeCondition::Rel::Lt: use = l(i) < r(i); break;
      case RegimeCondition::Rel::Le: use = l(i) <= r(i); break;
      case RegimeCondition::Rel::Gt: use = l(i) > r(i); break;
      case RegimeCondition::Rel::Ge: use = l(i) >= r(i); break;
    }
    if (use) out(i) = s(i);
  }
}

}  // namespace dc::num
