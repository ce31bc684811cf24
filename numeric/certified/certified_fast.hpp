// The fast first try of the certified automatic mode (numeric/certified/certified.hpp, DoubleMethod::Auto).
//
// The formula's tape runs once in long double (x87: 64-bit significand) and carries, next to
// every register's value v, a rigorous bound e >= |v - true value| ("running error analysis"):
//   - + - * / and sqrt are correctly rounded in IEEE arithmetic: a rounding adds u|v| (u = 2^-64)
//     plus the smallest subnormal long double for underflow;
//   - a library function (expl, logl, sinl, ...) adds its documented error: glibc lists the known
//     maximum errors of its long double functions on x86_64 (sysdeps/x86_64/fpu/libm-test-ulps:
//     1 to 3 ulps for every function used here); we take 8 ulps, and never assume a correctly
//     rounded libm;
//   - an operand's error is propagated through the operation with a bound on the derivative over
//     the whole interval [v - e, v + e] (exp: e^v (e^e - 1); log: 2e/v when e <= v/2; asin:
//     e / sqrt(1 - |v| - e) ...). Where no such bound is available -- the interval reaches a
//     singularity, the edge of a domain (log of [-e, e]) or a pole of tan -- the fast try gives up.
// Each bound is computed in long double and then multiplied by 1 + 2^-50, which covers the
// roundings of the bound's own arithmetic (at most a few dozen operations of relative error 2^-64).
//
// The true value then lies in [v - e, v + e]. If both ends round to the same double, that double
// is the correctly rounded result, decided with a certificate. Otherwise (the value sits too close
// to a rounding boundary, or the fast try gave up) the caller escalates to Arb ball arithmetic at
// increasing precision (certified.cpp). The long double exponent range (to 2^16383) also means
// that intermediate overflow or underflow of a representable double result does not happen here.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "numeric/evaluator.hpp"

namespace dc::num {

struct FastCertified {
  bool decided = false;      // value is the correctly rounded double of the true value
  double value = 0;          // the correctly rounded double (+-inf: the true value overflows)
  long double approx = 0;    // the long double value and its rigorous error bound
  long double bound = 0;
  std::string why_not;       // when not decided: why ("1/x with x in [-e, e]", "rounding boundary")
};

class CertifiedTape {
 public:
  explicit CertifiedTape(Program p);
  const Program& program() const { return prog_; }

  // x[i]: input i as a double; x_err[i] (may be null): a bound on |x[i] - exact input i|.
  FastCertified operator()(const double* x, const double* x_err = nullptr) const;

 private:
  Program prog_;
  std::vector<bool> binary_;                 // per instruction: two operands
  mutable std::vector<long double> v_, e_;   // registers: values and error bounds
};

}  // namespace dc::num
