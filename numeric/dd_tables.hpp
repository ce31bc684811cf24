// The constants and tables of the double-double functions (dd_functions.hpp), each entry a
// double-double with a rigorous bound on its error. They are computed once, on first use, from
// Arb enclosures at 256 bits (derivations/kernel/ball.hpp) and the exact rational arithmetic of
// CLN, so that no hand-typed digit can be wrong: a table entry is the midpoint of the enclosure
// split into two doubles, and its bound is the enclosure's radius plus the exact splitting error,
// rounded up.
#pragma once
#include <cstddef>

namespace dc::num::dde {

// c = p[0] + p[1] + p[2] + r with |r| <= res3, and |c - p[0] - p[1]| <= res2.
struct Split3 {
  double p[3];
  double res2, res3;
};

struct Tables {
  static constexpr std::size_t kExp = 64;      // 2^(j/64), j = 0..63
  static constexpr std::size_t kLog = 256;     // r_j ~ 1/(1 + j/256), j = -64..128 (index j + 64); r = 1 beyond
  static constexpr std::size_t kSinCos = 128;  // sin, cos of j pi/64, j = 0..127

  Split3 ln2, ln2_64, pi_64;
  double exp_h[kExp], exp_l[kExp], exp_e[kExp];
  double log_r[kLog], log_h[kLog], log_l[kLog], log_e[kLog];   // r_j (a double) and -log(r_j)
  double sin_h[kSinCos], sin_l[kSinCos], sin_e[kSinCos];
  double cos_h[kSinCos], cos_l[kSinCos], cos_e[kSinCos];
  double minus_sixth[3];                                        // -1/6 as h, l, e
};

// Built on first use (thread-safe); throws std::logic_error if an enclosure fails (never
// expected: every entry is a well-conditioned constant).
const Tables& tables();

}  // namespace dc::num::dde
