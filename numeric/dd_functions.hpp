// exp, expm1, log, log1p, sin, cos, tan, asin, acos, atan, pow and hypot in double-double with a
// running error bound, for the certified batch (certified_batch.hpp); the arithmetic and the
// error model are those of double_double.hpp, and every constant comes from dd_tables.hpp.
//
// Each function is reduced to a small argument by a table (exp: 2^(j/64); log: 193 values of
// log r_j around 1; sin and cos: the values at j pi/64), then summed as a Taylor series: the
// first terms in double-double, the rest in double with their own bound (DE), plus the
// truncation error of the series at the largest argument the bound allows. asin, acos and atan
// correct a double guess y0 (glibc's, whose accuracy we do not need) by one Newton step through
// the certified sin and cos of y0, with the second-order remainder bounded from the derivative.
// The results are good to 2^-70 relative or better, so that a point is undecided only when its true
// value lies that close to a rounding boundary of double.
//
// A function gives up (bound NaN) outside its range (|x| > 708 for exp, |x| > 2^20 for sin and
// cos, asin and acos within 2^-30 of +-1, ...); the caller then takes the long double step.
#pragma once
#include <cstddef>

#include "numeric/double_double.hpp"
#include "numeric/evaluator.hpp"

namespace dc::num::dde {

// Whether op has a double-double kernel here.
bool has_kernel(Op op);

// op over n <= 64 points: d = op(a) or op(a, b), as the block operations of the certified batch
// (a destination never aliases an operand).
void function_block(Op op, double* dh, double* dl, double* de, const double* ah, const double* al, const double* ae,
                    const double* bh, const double* bl, const double* be, std::size_t n);

// One point (tests).
DDE apply(Op op, DDE a, DDE b = {});

}  // namespace dc::num::dde
