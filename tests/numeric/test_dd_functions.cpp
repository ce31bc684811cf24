// The double-double functions with a running error bound (numeric/dd_functions.hpp) against the
// CLN reference at 60 digits (numeric/reference/reference.hpp), which shares no code with them:
//   - every table entry and constant lies within its stated bound of the true value;
//   - for every function, at random points of its whole range and at the hard places (arguments
//     next to 0, to 1, to multiples of pi/2, to +-1 for asin and acos, huge and tiny), exact and
//     perturbed inputs: the true value lies within the bound;
//   - at ordinary points the bound is that of double-double (below 2^-70 relative), i.e. the
//     kernel, not the long double fallback, answered;
//   - outside a kernel's range the bound is NaN (the caller's long double step takes over).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "numeric/compensated.hpp"
#include "numeric/crosscheck.hpp"
#include "numeric/dd_functions.hpp"
#include "numeric/dd_tables.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"

namespace {

using GiNaC::ex;
using GiNaC::numeric;
using dc::num::Op;
using dc::num::dde::DDE;

numeric abs_num(const numeric& x) { return x < 0 ? -x : x; }
numeric value_of(double h, double l) { return dc::num::exact_rational(h) + dc::num::exact_rational(l); }

// true value within the bound: |truth - (h + l)| <= e
bool within(const numeric& truth, double h, double l, double e) {
  return abs_num(truth - value_of(h, l)) <= dc::num::exact_rational(e);
}

ex apply_ex(Op op, const ex& a, const ex& b) {
  switch (op) {
    case Op::Exp: return GiNaC::exp(a);
    case Op::Expm1: return GiNaC::exp(a) - 1;
    case Op::Log: return GiNaC::log(a);
    case Op::Log1p: return GiNaC::log(1 + a);
    case Op::Sin: return GiNaC::sin(a);
    case Op::Cos: return GiNaC::cos(a);
    case Op::Tan: return GiNaC::tan(a);
    case Op::Asin: return GiNaC::asin(a);
    case Op::Acos: return GiNaC::acos(a);
    case Op::Atan: return GiNaC::atan(a);
    case Op::Pow: return GiNaC::pow(a, b);
    case Op::Hypot: return GiNaC::sqrt(a * a + b * b);
    default: return 0;
  }
}

struct Tally {
  std::size_t points = 0, answered = 0, exact = 0, tight = 0;
};

// One point: a = ad + da exactly (|da| <= ea), likewise b; checks the bound, counts how often it
// is tight (2^-70 relative).
void check_point(Op op, double ad, const numeric& da, double ea, double bd, const numeric& db, double eb, Tally& t,
                 double al = 0) {
  const DDE r = dc::num::dde::apply(op, DDE{ad, al, ea}, DDE{bd, 0.0, eb});
  const ex a = dc::num::exact_rational(ad) + dc::num::exact_rational(al) + da, b = dc::num::exact_rational(bd) + db;
  GiNaC::symbol x("x");
  numeric truth;
  try {
    truth = dc::num::reference_value(apply_ex(op, x, b).subs(x == a), {}, 60);
  } catch (const std::exception&) {
    return;   // no real value (or CLN cannot): nothing to compare
  }
  ++t.points;
  if (!(std::isfinite(r.e) && std::isfinite(r.h))) return;
  ++t.answered;
  INFO(dc::num::op_name(op) << "(" << ad << " + " << da << ", " << bd << "): " << r.h << " + " << r.l << " +- " << r.e
                            << ", truth " << truth.to_double());
  CHECK(within(truth, r.h, r.l, r.e));
  if (ea == 0 && eb == 0 && al == 0) {
    ++t.exact;
    if (r.e <= 0x1p-70 * std::fabs(truth.to_double()) + 0x1p-1000) ++t.tight;
  }
}

double draw(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(0, 1);
  if (lo > 0) return std::exp(std::log(lo) + u(rng) * (std::log(hi) - std::log(lo)));
  return lo + u(rng) * (hi - lo);
}

// points per range (DERIVCHECK_DD_POINTS raises it for a long local sweep)
const int kRandomPoints = std::getenv("DERIVCHECK_DD_POINTS") ? std::atoi(std::getenv("DERIVCHECK_DD_POINTS")) : 60;

struct Range {
  Op op;
  double lo, hi, blo = 0, bhi = 0;
};

}  // namespace

TEST_CASE("the double-double tables hold their values within their bounds", "[numeric][certified][dd]") {
  const auto& T = dc::num::dde::tables();
  using GiNaC::Pi;
  const ex ln2 = GiNaC::log(ex(2));
  auto ref = [](const ex& c) { return dc::num::reference_value(c, {}, 60); };
  auto split = [&](const dc::num::dde::Split3& s, const ex& c) {
    const numeric v = ref(c);
    CHECK(abs_num(v - value_of(s.p[0], s.p[1])) <= dc::num::exact_rational(s.res2));
    CHECK(abs_num(v - value_of(s.p[0], s.p[1]) - dc::num::exact_rational(s.p[2])) <= dc::num::exact_rational(s.res3));
    CHECK(s.res3 < 0x1p-150 * std::fabs(v.to_double()));
  };
  split(T.ln2, ln2);
  split(T.ln2_64, ln2 / 64);
  split(T.pi_64, Pi / 64);
  for (std::size_t j = 0; j < T.kExp; ++j) {
    const numeric v = ref(GiNaC::exp(ln2 * numeric(static_cast<long>(j), 64)));
    CHECK(within(v, T.exp_h[j], T.exp_l[j], T.exp_e[j]));
    CHECK(T.exp_e[j] < 0x1p-100);
  }
  for (std::size_t i = 0; i < T.kLog; ++i) {
    const numeric v = ref(-GiNaC::log(ex(dc::num::exact_rational(T.log_r[i]))));
    CHECK(within(v, T.log_h[i], T.log_l[i], T.log_e[i]));
    // |f r - 1| <= 0.0027 for f within 1/512 of 1 + j/256
    if (i > 192) continue;   // padding
    const double c = 1 + (static_cast<double>(i) - 64) / 256;
    CHECK(std::fabs((c + 1.0 / 512) * T.log_r[i] - 1) <= 0.0027);
    CHECK(std::fabs((c - 1.0 / 512) * T.log_r[i] - 1) <= 0.0027);
  }
  for (std::size_t j = 0; j < T.kSinCos; ++j) {
    const ex a = Pi * numeric(static_cast<long>(j), 64);
    CHECK(within(ref(GiNaC::sin(a)), T.sin_h[j], T.sin_l[j], T.sin_e[j]));
    CHECK(within(ref(GiNaC::cos(a)), T.cos_h[j], T.cos_l[j], T.cos_e[j]));
  }
  CHECK(within(numeric(-1, 6), T.minus_sixth[0], T.minus_sixth[1], T.minus_sixth[2]));
}

TEST_CASE("every double-double function keeps the true value within its bound", "[numeric][certified][dd]") {
  std::mt19937_64 rng(20261126);
  const std::vector<Range> ranges = {
      {Op::Exp, -708, 708},       {Op::Exp, -1e-3, 1e-3},     {Op::Expm1, -40, 40},       {Op::Expm1, -1e-12, 1e-12},
      {Op::Log, 1e-300, 1e300},   {Op::Log, 0.999, 1.001},    {Op::Log1p, -0.9, 1e6},     {Op::Log1p, -1e-15, 1e-15},
      {Op::Sin, -1e5, 1e5},       {Op::Sin, -0.01, 0.01},     {Op::Cos, -1e5, 1e5},       {Op::Cos, 1.5, 1.65},
      {Op::Tan, -1.5, 1.5},       {Op::Asin, -0.999, 0.999},  {Op::Acos, -0.999, 0.999},  {Op::Acos, 0.999999, 0.99999999},
      {Op::Atan, -50, 50},        {Op::Atan, -1e-8, 1e-8},    {Op::Pow, 1e-3, 1e3, -30, 30},
      {Op::Hypot, -1e150, 1e150, -1e150, 1e150},
  };
  std::size_t points = 0, tight = 0;
  std::string summary;
  for (const Range& r : ranges) {
    Tally t;
    for (int i = 0; i < kRandomPoints; ++i) {
      const double a = draw(rng, r.lo, r.hi);
      const double b = r.bhi > r.blo ? draw(rng, r.blo, r.bhi) : 0.0;
      check_point(r.op, a, 0, 0, b, 0, 0, t);
      // perturbed: the input is a + d with |d| <= 2^-60 |a|, stated as the input's bound
      std::uniform_int_distribution<long> k(-(1L << 20), 1L << 20);
      const numeric da = dc::num::exact_rational(std::ldexp(a, -60)) * numeric(k(rng), 1L << 20);
      check_point(r.op, a, da, std::fabs(std::ldexp(a, -60)), b, 0, 0, t);
      // a double-double input (a low part of up to half an ulp) known to 2^-30: the series
      // tails are evaluated at the high part, and their bounds must cover the rest
      const double al = std::ldexp(a, -53) * std::uniform_real_distribution<double>(-0.5, 0.5)(rng);
      const numeric da30 = dc::num::exact_rational(std::ldexp(a, -30)) * numeric(k(rng), 1L << 20);
      check_point(r.op, a, da30, std::fabs(std::ldexp(a, -30)), b, 0, 0, t, al);
    }
    summary += std::string(dc::num::op_name(r.op)) + " " + std::to_string(t.tight) + "/" + std::to_string(t.exact) + "; ";
    points += t.exact;
    tight += t.tight;
  }
  INFO(summary);
  // exact inputs: the kernels answer to 2^-70 (the few exceptions: values next to a zero of
  // the function that the reduction cannot reach, e.g. tan(x) next to pi/2)
  CHECK(tight >= points * 97 / 100);
}

TEST_CASE("double-double functions at the hard places", "[numeric][certified][dd]") {
  Tally t;
  const double pi = 3.14159265358979323846;
  // arguments next to multiples of pi/2 (the nearest doubles to k pi/2 and their neighbours)
  for (int k = -40; k <= 40; ++k) {
    const double x = k * (pi / 2);
    for (double y : {x, std::nextafter(x, 1e9), std::nextafter(x, -1e9)}) {
      check_point(Op::Sin, y, 0, 0, 0, 0, 0, t);
      check_point(Op::Cos, y, 0, 0, 0, 0, 0, t);
    }
  }
  // the nearest doubles to 1 for log, to 0 for log1p, expm1, asin, atan; subnormal and huge
  for (double x : {1.0, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0), 1 + 0x1p-30, 1 - 0x1p-30, 0x1p-1022,
                   0x1p1000, 2.0, 0.5, 1.5, 0.75, std::nextafter(1.5, 0.0)})
    check_point(Op::Log, x, 0, 0, 0, 0, 0, t);
  for (double x : {0x1p-1074, 1e-300, 1e-20, -1e-20, 1e-8, 0.0, 0.5, -0.5, 0x1p-9, -0x1p-9, 0x1.1p-9}) {
    check_point(Op::Log1p, x, 0, 0, 0, 0, 0, t);
    check_point(Op::Expm1, x, 0, 0, 0, 0, 0, t);
    check_point(Op::Asin, x, 0, 0, 0, 0, 0, t);
    check_point(Op::Atan, x, 0, 0, 0, 0, 0, t);
    check_point(Op::Sin, x, 0, 0, 0, 0, 0, t);
    check_point(Op::Tan, x, 0, 0, 0, 0, 0, t);
  }
  for (double x : {-708.0, 708.0, -707.5, 0.0, 1e-300, 0x1p-7, -0x1p-7, 0.34657359027997264})
    check_point(Op::Exp, x, 0, 0, 0, 0, 0, t);
  for (double x : {1.0, -1.0, 0.0, 1 - 0x1p-20, -1 + 0x1p-20, 0.5, -0.5}) {
    check_point(Op::Acos, x, 0, 0, 0, 0, 0, t);
    check_point(Op::Asin, x, 0, 0, 0, 0, 0, t);
  }
  for (double x : {1e300, -1e300, 1e16, 1e8}) check_point(Op::Atan, x, 0, 0, 0, 0, 0, t);
  INFO(t.answered << " of " << t.points << " answered, " << t.tight << " to 2^-70");
  CHECK(t.answered >= t.points * 95 / 100);   // 584 of 590 when written (the rest: +-1, huge, subnormal)
}

TEST_CASE("double-double functions give up outside their ranges", "[numeric][certified][dd]") {
  auto gives_up = [](Op op, double a, double b = 0) {
    const DDE r = dc::num::dde::apply(op, DDE{a, 0.0, 0.0}, DDE{b, 0.0, 0.0});
    return !std::isfinite(r.e);
  };
  CHECK(gives_up(Op::Exp, 710));
  CHECK(gives_up(Op::Exp, -745));
  CHECK(gives_up(Op::Log, 0));
  CHECK(gives_up(Op::Log, -1));
  CHECK(gives_up(Op::Log, 0x1p-1060));   // subnormal: the long double step
  CHECK(gives_up(Op::Log1p, -1));
  CHECK(gives_up(Op::Sin, 1e7));
  CHECK(gives_up(Op::Acos, 1));
  CHECK(gives_up(Op::Acos, 1.5));
  CHECK(gives_up(Op::Pow, -2, 0.5));
  CHECK(gives_up(Op::Exp, std::numeric_limits<double>::quiet_NaN()));
  // an input interval wider than a kernel's reduced range gives up too
  CHECK(!std::isfinite(dc::num::dde::apply(Op::Exp, DDE{1.0, 0.0, 0.5}).e));
  CHECK(!std::isfinite(dc::num::dde::apply(Op::Log, DDE{1.0, 0.0, 0.5}).e));
}

TEST_CASE("compensated evaluation takes the double-double kernels: cancellations after sin, cos, acos", "[numeric][compensated][dd]") {
  // 1 - cos(x), x - sin(x), acos(x) - pi/2 + x next to the points where they cancel: with the
  // functions in long double (2^-64) the first lost 8 digits at x = 1e-5; with the kernels each
  // stays within 2 ulps (the kernels' 2^-70 and cos's absolute 2^-100 near 1)
  GiNaC::symbol x("x");
  const std::vector<ex> fs = {1 - GiNaC::cos(x), x - GiNaC::sin(x), GiNaC::acos(x) - GiNaC::Pi / 2 + x};
  for (const ex& f : fs) {
    const dc::num::CompensatedEvaluator ev(dc::num::compile(f, {x}));
    for (double v : {1e-5, 3e-4, 1e-2, 0.2}) {
      const numeric truth = dc::num::reference_value(f, {{x, dc::num::exact_rational(v)}}, 60);
      const double got = ev({v});
      INFO(f << " at " << v << ": " << got << " vs " << truth.to_double());
      CHECK(dc::num::error_in_ulps(got, truth) <= 2);
    }
  }
}
