// One operation of the running error analysis in long double (numeric/certified/certified_fast.cpp): the
// value of an operation at operands known within bounds, with a bound on its error. Shared by the
// long double tape (CertifiedTape) and by the double-double batch (certified_batch.hpp), which
// takes the functions other than + - * / sqrt from here.
#pragma once
#include "numeric/evaluator.hpp"

namespace dc::num::certified {

// v approximates f at the true operands and e >= |v - f(true operands)| (before the factor
// kSafe, which covers the roundings of the bound's own arithmetic); why is set instead when no
// bound is available (v and e are then meaningless).
struct Step {
  long double v, e;
  const char* why = nullptr;
};

inline constexpr long double kSafe = 1 + 0x1p-50L;

// |a' - a| <= ea (and |b' - b| <= eb): op at the true operands a', b'.
Step unary(Op op, long double a, long double ea);
Step binary(Op op, long double a, long double ea, long double b, long double eb);

}  // namespace dc::num::certified
