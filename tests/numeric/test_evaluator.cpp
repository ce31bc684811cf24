// The tape evaluator against the CLN reference: random points, fused primitives, CSE,
// determinism, bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "derivations/decide/prove.hpp"
#include "numeric/evaluator.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"

using namespace dc::num;
using GiNaC::ex;
using GiNaC::symbol;

namespace {

// Max error in double ulps of Evaluator<T> over `n` random points with coordinates drawn by
// `draw`; the reference is evaluated at the exact (rounded) inputs.
template <class T, class Draw>
double max_ulps(const ex& f, const std::vector<symbol>& vars, Draw draw, int n, std::uint64_t seed) {
  Evaluator<T> ev(compile(f, vars));
  std::mt19937_64 rng(seed);
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    std::vector<T> x;
    GiNaC::exmap point;
    for (std::size_t i = 0; i < vars.size(); ++i) {
      const double v = draw(rng, i);
      x.push_back(static_cast<T>(v));
      point[vars[i]] = exact_rational(v);
    }
    const GiNaC::numeric ref = reference_value(f, point, 40);
    worst = std::max(worst, error_in_ulps(static_cast<long double>(ev(x)), ref));
  }
  return worst;
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

}  // namespace

TEST_CASE("evaluator matches the CLN reference on v'1 of the general impact", "[numeric][evaluator]") {
  symbol m1("m1"), m2("m2"), v1("v1"), v2("v2"), e("e");
  const ex v1p = (m1 * v1 + m2 * v2 - e * m2 * (v1 - v2)) / (m1 + m2);
  const std::vector<symbol> vars{m1, m2, v1, v2, e};
  // same-sign velocities, v1 > v2: no cancellation in the numerator, so a few ulps suffice
  auto draw = [](std::mt19937_64& rng, std::size_t i) {
    switch (i) {
      case 0: case 1: return uniform(rng, 0.1, 10);
      case 2: return uniform(rng, 5, 10);
      case 3: return uniform(rng, 1, 4);
      default: return uniform(rng, 0, 0.5);
    }
  };
  const std::uint64_t seed = 42;
  CAPTURE(seed);
  CHECK(max_ulps<double>(v1p, vars, draw, 300, seed) <= 4);
  // long double results measured in double ulps: far below one ulp
  CHECK(max_ulps<long double>(v1p, vars, draw, 300, seed) <= 0.01);
}

TEST_CASE("integer powers become multiplications, half powers square roots", "[numeric][evaluator]") {
  symbol x("x"), y("y");
  const Program p = compile(GiNaC::pow(x, 5) + GiNaC::pow(y, GiNaC::numeric(3, 2)), {x, y});
  CHECK(p.count(Op::Pow) == 0);
  CHECK(p.count(Op::Mul) == 5);  // x^5: x^2, x^4, x^4*x; y^(3/2) = sqrt(y)^3: s^2, s^2*s
  CHECK(p.count(Op::Sqrt) == 1);
  Evaluator<double> ev(p);
  CHECK(ev({1.5, 2.25}) == Approx(std::pow(1.5, 5) + std::pow(2.25, 1.5)).epsilon(1e-15));
  // negative powers divide
  const Program q = compile(GiNaC::pow(x, -3), {x});
  CHECK(q.count(Op::Div) == 1);
  CHECK(Evaluator<double>(q)({2.0}) == 0.125);
}

TEST_CASE("common subexpressions are computed once", "[numeric][evaluator]") {
  symbol m1("m1"), m2("m2"), v1("v1"), v2("v2");
  const ex a = m1 * v1 / (m1 + m2) + m2 * v2 / (m1 + m2) + GiNaC::sin(m1 + m2);
  const Program p = compile(a, {m1, m2, v1, v2});
  CHECK(p.count(Op::Add) == 3);  // m1+m2 once, then two additions of the three terms
  CHECK(p.count(Op::Sin) == 1);
}

TEST_CASE("log(1+x), exp(x)-1 and sqrt(x^2+y^2) compile to log1p, expm1 and hypot", "[numeric][evaluator]") {
  symbol x("x"), y("y");
  const Program p = compile(GiNaC::log(1 + x), {x});
  REQUIRE(p.count(Op::Log1p) == 1);
  CHECK(p.count(Op::Log) == 0);
  CHECK(Evaluator<double>(p)({1e-12}) == std::log1p(1e-12));
  const Program q = compile(GiNaC::exp(x) - 1, {x});
  REQUIRE(q.count(Op::Expm1) == 1);
  CHECK(Evaluator<double>(q)({1e-12}) == std::expm1(1e-12));
  const Program h = compile(GiNaC::sqrt(GiNaC::pow(x, 2) + GiNaC::pow(y, 2)), {x, y});
  REQUIRE(h.count(Op::Hypot) == 1);
  CHECK(Evaluator<double>(h)({3e200, 4e200}) == Approx(5e200));
  // with fusion off, the naive form overflows: the fused op is what saves it
  CompileOptions off;
  off.fuse_hypot = false;
  CHECK(std::isinf(Evaluator<double>(compile(GiNaC::sqrt(GiNaC::pow(x, 2) + GiNaC::pow(y, 2)), {x, y}, off))({3e200, 4e200})));
}

TEST_CASE("a ratio sharing symbols with its denominator is divided first", "[numeric][evaluator]") {
  symbol m1("m1"), m2("m2");
  const ex mu = m1 * m2 / (m1 + m2);
  Evaluator<double> ev(compile(mu, {m1, m2}));
  CHECK(ev({1e160, 1e160}) == Approx(5e159).epsilon(1e-15));
  CompileOptions off;
  off.ratio_first = false;
  CHECK(std::isinf(Evaluator<double>(compile(mu, {m1, m2}, off))({1e160, 1e160})));
}

TEST_CASE("constants are folded exactly rounded, rationals are not pre-rounded", "[numeric][evaluator]") {
  symbol x("x");
  // x/3 is a division by 3, so 3/3 == 1 exactly
  CHECK(Evaluator<double>(compile(x / 3, {x}))({3.0}) == 1.0);
  const Program p = compile(GiNaC::Pi * x + GiNaC::sqrt(ex(2)), {x});
  CHECK(p.count(Op::Sqrt) == 0);
  Evaluator<double> ev(p);
  CHECK(ev({1.0}) == Approx(M_PI + std::sqrt(2.0)).epsilon(1e-16));
  Evaluator<long double> evl(p);
  CHECK(std::fabs(evl({1.0L}) - (3.14159265358979323846264338327950288L + 1.41421356237309504880168872420969808L)) < 1e-18L);
}

TEST_CASE("batch evaluation through the tape equals scalar evaluation bit for bit", "[numeric][evaluator]") {
  symbol m1("m1"), m2("m2"), v1("v1"), v2("v2"), e("e");
  const ex v1p = (m1 * v1 + m2 * v2 - e * m2 * (v1 - v2)) / (m1 + m2) + GiNaC::log(1 + e * v2 * v2);
  const std::vector<symbol> vars{m1, m2, v1, v2, e};
  Evaluator<double> ev(compile(v1p, vars));
  const Eigen::Index n = 1000;  // not a multiple of the block size
  std::mt19937_64 rng(7);
  Eigen::ArrayXXd in(n, 5);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < 5; ++j) in(i, j) = uniform(rng, 0.1, 3);
  // the tape's batch loop; eval_batch (the JIT where available: SLEEF's log, not libm's) is
  // compared with the tape in test_jit.cpp
  std::vector<const double*> cols;
  for (Eigen::Index j = 0; j < 5; ++j) cols.push_back(in.col(j).data());
  Eigen::ArrayXd out(n), fast;
  ev.eval_batch_tape(cols.data(), out.data(), static_cast<std::size_t>(n));
  ev.eval_batch(in, fast);
  REQUIRE(fast.size() == n);
  for (Eigen::Index i = 0; i < n; ++i) {
    std::vector<double> x(5);
    for (Eigen::Index j = 0; j < 5; ++j) x[static_cast<std::size_t>(j)] = in(i, j);
    REQUIRE(out(i) == ev(x));
    // the log term (at most 3.4 here) differs by at most 2 ulp, then one rounding of the sum
    REQUIRE(std::fabs(fast(i) - out(i)) <= 4 * 0x1p-52 * std::max(4.0, std::fabs(out(i))));
  }
}

TEST_CASE("compiled programs do not depend on GiNaC's term order", "[numeric][evaluator]") {
  // the same expression built in two different orders compiles to the same listing
  symbol a("a"), b("b"), c("c");
  const Program p = compile(a * b + c - a / (b + c), {a, b, c});
  const Program q = compile(-a / (c + b) + c + b * a, {a, b, c});
  CHECK(p.listing() == q.listing());
}

TEST_CASE("evaluator bad input", "[numeric][evaluator]") {
  symbol x("x"), y("y");
  CHECK_THROWS_WITH(compile(x + y, {x}), Catch::Contains("'y'"));
  CHECK_THROWS_AS(compile(GiNaC::zeta(x), {x}), std::invalid_argument);
  Evaluator<double> ev(compile(x, {x}));
  CHECK_THROWS_AS(ev(std::vector<double>{1.0, 2.0}), std::invalid_argument);
}

TEST_CASE("a constant sum raised to an integer power is a constant (no endless recursion)", "[numeric][evaluator]") {
  // x - 7 atan(3)/(1 + 7 atan(3)): the product's factor (1 + 7 atan(3))^-1 used to be handed back
  // and forth between the product and the power of a sum until the stack ran out (found by the
  // random formulas of test_certified_batch.cpp)
  GiNaC::symbol x("x");
  const GiNaC::ex c = 7 * GiNaC::atan(GiNaC::ex(3));
  for (const GiNaC::ex& f : {x - c / (1 + c), x * GiNaC::pow(1 + c, -2), x + GiNaC::pow(2 + GiNaC::sqrt(GiNaC::ex(2)), 3)}) {
    INFO(f);
    const dc::num::Program p = dc::num::compile(f, {x});
    const dc::num::Evaluator<double> ev(p);
    const double at = 0.5;
    GiNaC::exmap m;
    m[x] = dc::num::exact_rational(at);
    const GiNaC::numeric ref = dc::num::reference_value(f, m, 40);
    CHECK(dc::num::error_in_ulps(ev(&at), ref) <= 4);
  }
}
