// The fast first try of the certified automatic mode (numeric/certified/certified_fast.hpp): the tape in
// long double with a running error bound. Checked against the CLN reference at 60 digits
// (numeric/reference/reference.hpp), which shares no code with the running-error bound:
//   - every operation: the true value at an exact input lies within the stated bound, for input
//     errors of the size of a double rounding up to 2^-20 relative (so propagation matters);
//   - whenever the try says "decided", its double is the nearest double to the true value;
//   - where no bound can be had (singularities, domain edges) it gives up instead of guessing.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "numeric/certified/certified.hpp"
#include "numeric/certified/certified_fast.hpp"
#include "numeric/evaluator.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"
#include "tests/numeric/handout.hpp"

namespace {

using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::symbol;

numeric abs_num(const numeric& x) { return x < 0 ? -x : x; }

// x = xd + delta exactly (delta a random fraction of 2^-20 |xd|), with the bound |delta|.
struct Input {
  numeric exact;
  double xd, err;
};

Input perturbed(double xd, std::mt19937_64& rng, bool perturb) {
  Input in{dc::num::exact_rational(xd), xd, 0};
  if (!perturb || xd == 0) return in;
  std::uniform_int_distribution<long> k(-(1L << 20), 1L << 20);
  const numeric delta = dc::num::exact_rational(std::ldexp(xd, -20)) * numeric(k(rng), 1L << 20);
  in.exact += delta;
  in.err = std::fabs(abs_num(delta).to_double()) * (1 + 1e-12);
  return in;
}

// Checks the bound at one point; returns whether the try decided the rounding.
bool check_point(const ex& f, const std::vector<symbol>& xs, const std::vector<Input>& in) {
  const dc::num::CertifiedTape tape(dc::num::compile(f, xs));
  std::vector<double> x, e;
  GiNaC::exmap point;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    x.push_back(in[i].xd);
    e.push_back(in[i].err);
    point[xs[i]] = in[i].exact;
  }
  const dc::num::FastCertified r = tape(x.data(), e.data());
  if (!r.why_not.empty() && !r.decided && r.bound == 0) return false;   // gave up: nothing claimed
  const numeric truth = dc::num::reference_value(f, point, 60);
  const numeric approx = dc::num::exact_rational(r.approx);
  const numeric bound = dc::num::exact_rational(r.bound);
  INFO("f = " << f << " at " << point << ": approx " << static_cast<double>(r.approx) << " bound "
              << static_cast<double>(r.bound) << " truth " << truth.to_double());
  CHECK(abs_num(truth - approx) <= bound);
  if (r.decided) CHECK(r.value == dc::num::nearest_double(truth));
  return r.decided;
}

}  // namespace

TEST_CASE("the running error bound holds for every operation", "[numeric][certified][fast]") {
  symbol a("a"), b("b");
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> unit(0, 1);
  struct OpCase {
    ex f;
    double lo, hi;     // range of a (log-uniform when both positive)
    double blo, bhi;   // range of b
  };
  const std::vector<OpCase> cases = {
      {a + b, -1e3, 1e3, -1e3, 1e3},        {a - b, 0.5, 2, 0.5, 2},
      {a * b, -1e5, 1e5, 1e-5, 1e5},         {a / b, 1e-200, 1e200, 1e-100, 1e100},
      {GiNaC::sqrt(a), 1e-300, 1e300, 0, 0}, {GiNaC::exp(a), -700, 700, 0, 0},
      {GiNaC::exp(a) - 1, -1e-3, 1e-3, 0, 0}, {GiNaC::log(a), 1e-300, 1e300, 0, 0},
      {GiNaC::log(1 + a), -0.5, 1e3, 0, 0},  {GiNaC::sin(a), -1e4, 1e4, 0, 0},
      {GiNaC::cos(a), -1e4, 1e4, 0, 0},      {GiNaC::tan(a), -1.5, 1.5, 0, 0},
      {GiNaC::atan(a), -1e10, 1e10, 0, 0},   {GiNaC::asin(a), -0.999, 0.999, 0, 0},
      {GiNaC::acos(a), -0.999, 0.999, 0, 0}, {GiNaC::abs(a), -5, 5, 0, 0},
      {GiNaC::pow(a, b), 1e-3, 1e3, -30, 30}, {GiNaC::sqrt(a * a + b * b), -1e150, 1e150, -1e150, 1e150},
      {GiNaC::pow(a, ex(1) / 3), 1e-100, 1e100, 0, 0},
  };
  int decided = 0, total = 0;
  for (const OpCase& c : cases) {
    const bool binary = c.f.has(b);
    for (int i = 0; i < 40; ++i) {
      auto draw = [&](double lo, double hi) {
        if (lo > 0) return std::exp(std::log(lo) + unit(rng) * (std::log(hi) - std::log(lo)));
        return lo + unit(rng) * (hi - lo);
      };
      const bool perturb = i % 2 == 1;
      std::vector<Input> in = {perturbed(draw(c.lo, c.hi), rng, perturb)};
      std::vector<symbol> xs = {a};
      if (binary) {
        in.push_back(perturbed(draw(c.blo, c.bhi), rng, perturb));
        xs.push_back(b);
      }
      decided += check_point(c.f, xs, in) ? 1 : 0;
      ++total;
    }
  }
  // exact double inputs decide almost always; 2^-20 input errors never (they exceed an ulp)
  CHECK(decided >= total * 2 / 5);
}

TEST_CASE("the fast try near hard spots: bound holds or it gives up", "[numeric][certified][fast]") {
  symbol a("a");
  std::mt19937_64 rng(7);
  // sin and cos near multiples of pi (argument reduction), 1 - cos near 0, log near 1,
  // asin near 1, tan near its pole
  const std::vector<std::pair<ex, double>> spots = {
      {GiNaC::sin(a), 3.141592653589793}, {GiNaC::sin(a), 355.0},       {GiNaC::cos(a), 1.5707963267948966},
      {GiNaC::sin(a), 1e22},              {1 - GiNaC::cos(a), 1e-8},    {GiNaC::log(a), 1.0000000001},
      {GiNaC::asin(a), 0.9999999999},     {GiNaC::tan(a), 1.5707963267948966}, {GiNaC::exp(a), 709.78},
  };
  for (const auto& [f, x] : spots)
    for (bool perturb : {false, true}) check_point(f, {a}, {perturbed(x, rng, perturb)});
}

TEST_CASE("the fast try gives up at singularities instead of guessing", "[numeric][certified][fast]") {
  symbol a("a");
  auto give_up = [&](const ex& f, double x, double err) {
    const dc::num::CertifiedTape tape(dc::num::compile(f, {a}));
    const dc::num::FastCertified r = tape(&x, &err);
    INFO(f << " at " << x << " +- " << err);
    CHECK_FALSE(r.decided);
    CHECK_FALSE(r.why_not.empty());
  };
  give_up(1 / a, 1e-20, 1e-20);
  give_up(GiNaC::log(a), 1e-20, 1e-19);
  give_up(GiNaC::sqrt(a), 1e-30, 1e-29);
  give_up(GiNaC::asin(a), 1.0, 1e-17);
  give_up(GiNaC::tan(a), 1.5707963267948966, 1e-3);
}

TEST_CASE("decided results of handout formulas are the correctly rounded doubles", "[numeric][certified][fast]") {
  // every formula of three handout files at random points of their declared domains
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(0, 1);
  int decided = 0, total = 0;
  for (const char* file : {"05_direct_impact.dc", "07_two_ball_bounce.dc", "09_rocket.dc"}) {
    const dc::Derivation& d = dc::test::handout(file);
    for (const dc::Formula& f : dc::formulas(d)) {
      const auto plain = dc::test::compilable_plain(d, f);
      if (!plain) continue;
      const ex& expr = plain->expr;
      const std::vector<symbol>& xs = plain->xs;
      for (int i = 0; i < 5; ++i) {
        std::vector<Input> in;
        for (std::size_t k = 0; k < xs.size(); ++k) in.push_back({{}, 0.25 + 4 * unit(rng), 0});
        for (auto& v : in) v.exact = dc::num::exact_rational(v.xd);
        GiNaC::exmap pt;
        for (std::size_t k = 0; k < xs.size(); ++k) pt[xs[k]] = in[k].exact;
        const ex val = expr.subs(pt).evalf();
        if (!GiNaC::is_a<numeric>(val) || !GiNaC::ex_to<numeric>(val).is_real()) continue;
        decided += check_point(expr, xs, in) ? 1 : 0;
        ++total;
      }
    }
  }
  INFO(decided << " of " << total << " decided");
  CHECK(total >= 50);
  CHECK(decided >= total * 9 / 10);
}
