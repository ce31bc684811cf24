#include "numeric/dd_tables.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <ginac/ginac.h>

#include "derivations/kernel/ball.hpp"
#include "numeric/double_double.hpp"

namespace dc::num::dde {
namespace {

using GiNaC::ex;
using GiNaC::numeric;

// the exact rational value of a finite double
numeric exact_of(double x) {
  if (x == 0) return numeric(0);
  int e = 0;
  const double m = std::frexp(x, &e);   // x = m 2^e, 1/2 <= |m| < 1
  return numeric(static_cast<long>(std::ldexp(m, 53))) * numeric(2).power(e - 53);
}

// an upper bound, as a double, of a non-negative rational
double up(const numeric& x) {
  return x.to_double() * (1 + 0x1p-40) + 0x1p-1074;
}

// the enclosure of a constant expression: exact rational end points lo <= c <= hi
void enclose(const ex& c, numeric& lo, numeric& hi) {
  const kernel::Ball b = kernel::enclose(c, 256);
  if (b.status != kernel::BallStatus::Value || !b.exact_bounds(lo, hi))
    throw std::logic_error("dd tables: no enclosure of a constant");
}

// h + l with a bound e: the enclosure's midpoint split into two doubles (renormalised exactly)
void split2(const ex& c, double& h, double& l, double& e) {
  numeric lo, hi;
  enclose(c, lo, hi);
  const numeric mid = (lo + hi) / 2;
  const double h0 = mid.to_double();
  const double l0 = (mid - exact_of(h0)).to_double();
  two_sum(h0, l0, h, l);
  e = up(GiNaC::abs(mid - exact_of(h) - exact_of(l)) + (hi - lo) / 2);
}

Split3 split3(const ex& c) {
  numeric lo, hi;
  enclose(c, lo, hi);
  const numeric mid = (lo + hi) / 2, rad = (hi - lo) / 2;
  Split3 s{};
  numeric rest = mid;
  for (double& p : s.p) {
    p = rest.to_double();
    rest -= exact_of(p);
  }
  s.res3 = up(GiNaC::abs(rest) + rad);
  s.res2 = up(GiNaC::abs(rest + exact_of(s.p[2])) + rad);
  return s;
}

Tables build() {
  Tables t{};
  const ex ln2 = GiNaC::log(ex(2));
  t.ln2 = split3(ln2);
  t.ln2_64 = split3(ln2 / 64);
  t.pi_64 = split3(GiNaC::Pi / 64);
  for (std::size_t j = 0; j < Tables::kExp; ++j)
    split2(GiNaC::exp(ln2 * numeric(static_cast<long>(j), 64)), t.exp_h[j], t.exp_l[j], t.exp_e[j]);
  for (std::size_t i = 0; i < Tables::kLog; ++i) {
    const long j = static_cast<long>(i) - 64;
    // any double will do (-log r is tabled); r_0 = 1, and 1 in the padding beyond j = 128
    const double r = j <= 128 ? 1.0 / (1.0 + static_cast<double>(j) / 256) : 1.0;
    t.log_r[i] = r;
    if (r == 1) {
      t.log_h[i] = t.log_l[i] = t.log_e[i] = 0;   // -log(1) = 0 exactly
    } else {
      split2(-GiNaC::log(ex(exact_of(r))), t.log_h[i], t.log_l[i], t.log_e[i]);
    }
  }
  for (std::size_t j = 0; j < Tables::kSinCos; ++j) {
    if (j % 32 == 0) {   // exact: 0, +-1 (so that sin(k pi) and cos(pi/2 + k pi) keep relative accuracy)
      const double s[4] = {0, 1, 0, -1}, c[4] = {1, 0, -1, 0};
      t.sin_h[j] = s[j / 32];
      t.cos_h[j] = c[j / 32];
      t.sin_l[j] = t.sin_e[j] = t.cos_l[j] = t.cos_e[j] = 0;
      continue;
    }
    const ex a = GiNaC::Pi * numeric(static_cast<long>(j), 64);
    split2(GiNaC::sin(a), t.sin_h[j], t.sin_l[j], t.sin_e[j]);
    split2(GiNaC::cos(a), t.cos_h[j], t.cos_l[j], t.cos_e[j]);
  }
  split2(ex(numeric(-1, 6)), t.minus_sixth[0], t.minus_sixth[1], t.minus_sixth[2]);
  return t;
}

}  // namespace

const Tables& tables() {
  static const Tables t = build();
  return t;
}

}  // namespace dc::num::dde
