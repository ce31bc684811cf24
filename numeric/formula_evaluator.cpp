#include "numeric/formula_evaluator.hpp"

#include <cmath>
#include <stdexcept>

#include "derivations/decide/prove.hpp"
#include "numeric/reference/exact.hpp"

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/source.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace dc::num {
namespace {

const Step* stable_step_for(const Derivation& d, const std::string& label) {
  for (const Step& s : d.steps)
    if (s.stable_of && *s.stable_of == label) return &s;
  return nullptr;
}

// Sign of a register: what can be proved from the domains. pos/neg: may the value be > 0 / < 0.
struct Sign {
  bool pos = true, neg = true;
  static Sign of(double v) { return {v > 0 || std::isnan(v), v < 0 || std::isnan(v)}; }
  Sign flip() const { return {neg, pos}; }
};

Sign input_sign(const SymbolInfo* info) {
  if (!info) return {};
  switch (info->domain.kind) {
    case Domain::Kind::Positive: case Domain::Kind::Nonnegative: return {true, false};
    case Domain::Kind::Negative: return {false, true};
    case Domain::Kind::Real: return {};
    case Domain::Kind::Interval: {
      DigitsGuard guard(30);
      const GiNaC::ex lo = GiNaC::evalf(info->domain.lo), hi = GiNaC::evalf(info->domain.hi);
      Sign s;
      if (GiNaC::is_a<GiNaC::numeric>(lo) && round_to_double(GiNaC::ex_to<GiNaC::numeric>(lo)) >= 0) s.neg = false;
      if (GiNaC::is_a<GiNaC::numeric>(hi) && round_to_double(GiNaC::ex_to<GiNaC::numeric>(hi)) <= 0) s.pos = false;
      return s;
    }
  }
  return {};
}

}  // namespace

bool may_cancel(const Program& p, const SymbolTable& symbols) {
  std::vector<Sign> sg(p.n_registers);
  for (std::size_t i = 0; i < p.n_inputs(); ++i) sg[i] = input_sign(symbols.find(p.inputs[i]));
  for (std::size_t c = 0; c < p.const_double.size(); ++c) sg[p.n_inputs() + c] = Sign::of(p.const_double[c]);
  const std::size_t first_temp = p.first_temp();
  for (const Instr& in : p.code) {
    const Sign a = sg[in.a], b = sg[in.b];
    Sign r;
    switch (in.op) {
      case Op::Add:
      case Op::Sub: {
        const Sign bb = in.op == Op::Sub ? b.flip() : b;
        const bool opposite = (a.pos && bb.neg) || (a.neg && bb.pos);
        if (opposite && (in.a >= first_temp || in.b >= first_temp)) return true;
        r = {a.pos || bb.pos, a.neg || bb.neg};
        break;
      }
      case Op::Mul: case Op::Div:
        r = {(a.pos && b.pos) || (a.neg && b.neg), (a.pos && b.neg) || (a.neg && b.pos)};
        break;
      case Op::Neg: r = a.flip(); break;
      case Op::Sqrt: case Op::Exp: case Op::Abs: case Op::Hypot: case Op::Acos: r = {true, false}; break;
      case Op::Expm1: case Op::Log1p: case Op::Asin: case Op::Atan: case Op::Sin: case Op::Tan: r = a; break;
      default: r = {}; break;  // log, cos, pow: either sign
    }
    sg[in.dst] = r;
  }
  return false;
}

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

FormulaEvaluator::FormulaEvaluator(const Derivation& d, const std::string& label, EvalMode mode)
    : formula_(dc::formula(d, label)), naive_(compile(formula_.expr, formula_.params)),
      naive_dd_(naive_.program()) {
  // Auto: the tapes operator() would use in double; in a regime the formula's own tape is used
  // outside the condition, so both count
  auto resolve = [&] {
    if (mode != EvalMode::Auto) return mode == EvalMode::Compensated;
    const bool stable_everywhere = stable_ && !condition_;
    if (stable_ && may_cancel(stable_->program(), d.symbols)) return true;
    return !stable_everywhere && may_cancel(naive_.program(), d.symbols);
  };
  if (const Step* s = stable_step_for(d, label)) {
    try {
      stable_.emplace(compile(dc::formula(d, s->label).expr, formula_.params));
    } catch (const std::invalid_argument&) {
      compensated_ = resolve();
      return;  // the stable form needs other inputs: not usable for this formula
    }
    stable_dd_.emplace(stable_->program());
    stable_label_ = s->label;
    regime_ = s->stable_regime;
    condition_ = parse_regime(d, *s, formula_.params);
    if (condition_) {
      cond_lhs_.emplace(condition_->lhs);
      cond_rhs_.emplace(condition_->rhs);
    }
  }
  compensated_ = resolve();
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

void FormulaEvaluator::check_size(std::size_t n) const {
  if (n != formula_.params.size())
    throw std::invalid_argument("formula '" + formula_.label + "' takes " +
                                std::to_string(formula_.params.size()) + " values, got " +
                                std::to_string(n));
}

double FormulaEvaluator::fast(const std::vector<double>& x) const {
  check_size(x.size());
  return in_regime(x.data()) ? (*stable_)(x.data()) : naive_(x.data());
}

double FormulaEvaluator::compensated_value(const std::vector<double>& x) const {
  check_size(x.size());
  return in_regime(x.data()) ? (*stable_dd_)(x.data()) : naive_dd_(x.data());
}

double FormulaEvaluator::operator()(const std::vector<double>& x) const {
  return compensated_ ? compensated_value(x) : fast(x);
}

void FormulaEvaluator::eval_batch(const Eigen::ArrayXXd& in, Eigen::ArrayXd& out) const {
  if (static_cast<std::size_t>(in.cols()) != formula_.params.size())
    throw std::invalid_argument("formula '" + formula_.label + "': expected " +
                                std::to_string(formula_.params.size()) + " columns");
  auto run_naive = [&](Eigen::ArrayXd& o) {
    if (compensated_) naive_dd_.eval_batch(in, o);
    else naive_.eval_batch(in, o);
  };
  if (!stable_) {
    run_naive(out);
    return;
  }
  Eigen::ArrayXd s;
  if (compensated_) stable_dd_->eval_batch(in, s);
  else stable_->eval_batch(in, s);
  if (!condition_) {
    out = s;
    return;
  }
  run_naive(out);
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
