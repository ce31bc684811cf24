// Stable forms from the handout files (loaded by label, never typed here) against their naive
// forms: the naive form loses digits in its regime (the test states how many), the stable form
// stays within 4 ulps of the CLN reference there and over the domain.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "derivations/reader/derivation.hpp"
#include "numeric/crosscheck.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/formula_evaluator.hpp"
#include "numeric/reference/reference.hpp"
#include "handout.hpp"

using namespace dc::num;

namespace {

using dc::test::handout;

struct Errors {
  double naive_ulps, stable_ulps;
  // decimal digits the naive form loses: log10 of its error in ulps (inf result: all 16)
  double naive_digits_lost() const {
    return std::isfinite(naive_ulps) ? std::log10(std::max(naive_ulps, 1.0)) : 16.0;
  }
};

// Error of the formula's own tape (naive) and of the FormulaEvaluator (stable form in its
// regime) at one point given as name -> double.
Errors errors_at(const std::string& file, const std::string& label,
                 const std::map<std::string, double>& at) {
  const dc::Derivation& d = handout(file);
  FormulaEvaluator fe(d, label);
  REQUIRE(fe.has_stable());
  std::vector<double> x;
  GiNaC::exmap point;
  for (const auto& s : fe.params()) {
    const double v = at.at(s.get_name());
    x.push_back(v);
    point[d.symbols.find(s.get_name())->sym] = exact_rational(v);
  }
  const GiNaC::numeric ref = reference_value(fe.formula().expr, point, 40);
  return {error_in_ulps(fe.naive(x), ref), error_in_ulps(fe(x), ref)};
}

}  // namespace

TEST_CASE("general impact energy loss as e -> 1: 1 - e^2 cancels, (1 - e)(1 + e) does not", "[numeric][stable]") {
  const Errors r = errors_at("05_direct_impact.dc", "energy_loss_general",
                             {{"m1", 2.0}, {"m2", 3.0}, {"v1", 1.5}, {"v2", 0.25}, {"e", 1 - 1e-9}});
  CAPTURE(r.naive_ulps, r.stable_ulps);
  REQUIRE(r.naive_digits_lost() >= 5);
  REQUIRE(r.stable_ulps <= 4);
}

TEST_CASE("energy difference T - T' as v1 -> v2 and for masses near 1e160", "[numeric][stable]") {
  const Errors close = errors_at("05_direct_impact.dc", "energy_loss_plastic_naive",
                                 {{"m1", 2.0}, {"m2", 3.0}, {"v1", 1.5}, {"v2", 1.5 * (1 - 1e-7)}});
  CAPTURE(close.naive_ulps, close.stable_ulps);
  REQUIRE(close.naive_digits_lost() >= 10);
  REQUIRE(close.stable_ulps <= 4);
  const Errors heavy = errors_at("05_direct_impact.dc", "energy_loss_plastic_naive",
                                 {{"m1", 1e160}, {"m2", 3e160}, {"v1", 1.5}, {"v2", 0.5}});
  CAPTURE(heavy.naive_ulps, heavy.stable_ulps);
  REQUIRE(heavy.naive_digits_lost() >= 16);  // (m1 v1)^2 overflows: no digit survives
  REQUIRE(heavy.stable_ulps <= 4);
  const Errors general = errors_at("05_direct_impact.dc", "energy_loss_general_naive",
                                   {{"m1", 2.0}, {"m2", 3.0}, {"v1", 1.5}, {"v2", 0.25}, {"e", 1 - 1e-9}});
  CAPTURE(general.naive_ulps, general.stable_ulps);
  REQUIRE(general.naive_digits_lost() >= 8);
  REQUIRE(general.stable_ulps <= 4);
}

TEST_CASE("impact velocities for huge masses: products m*v overflow, mass fractions do not", "[numeric][stable]") {
  const Errors r = errors_at("05_direct_impact.dc", "v1p_general",
                             {{"m1", 1e300}, {"m2", 3e305}, {"v1", 2e10}, {"v2", -1e9}, {"e", 0.5}});
  CAPTURE(r.naive_ulps, r.stable_ulps);
  REQUIRE(r.naive_digits_lost() >= 16);
  REQUIRE(r.stable_ulps <= 4);
}

TEST_CASE("ballistic pendulum for small v0: acos(1 - x) against 2 asin(sqrt(x/2))", "[numeric][stable]") {
  const Errors r = errors_at("06_ballistic_pendulum.dc", "deflection",
                             {{"m", 0.01}, {"M", 5.0}, {"v0", 1e-3}, {"L", 2.0}, {"g", 9.81}});
  CAPTURE(r.naive_ulps, r.stable_ulps);
  REQUIRE(r.naive_digits_lost() >= 8);
  REQUIRE(r.stable_ulps <= 4);
  const Errors h = errors_at("06_ballistic_pendulum.dc", "height", {{"L", 2.0}, {"theta", 1e-6}});
  CAPTURE(h.naive_ulps, h.stable_ulps);
  REQUIRE(h.naive_digits_lost() >= 8);
  REQUIRE(h.stable_ulps <= 4);
}

TEST_CASE("rocket velocity with m_r close to m0: log(m_r/m0) against log1p of the burnt fraction", "[numeric][stable]") {
  const Errors r = errors_at("09_rocket.dc", "velocity_symbols",
                             {{"m_r", 1000 * (1 - 1e-10)}, {"m0", 1000.0}, {"u_e", 2500.0}, {"g", 9.81}, {"t", 0.0}});
  CAPTURE(r.naive_ulps, r.stable_ulps);
  REQUIRE(r.naive_digits_lost() >= 5);
  REQUIRE(r.stable_ulps <= 4);
  // outside the regime (m_r << m0) the evaluator keeps the formula: still accurate
  const Errors late = errors_at("09_rocket.dc", "velocity_symbols",
                                {{"m_r", 1e-3}, {"m0", 1000.0}, {"u_e", 2500.0}, {"g", 9.81}, {"t", 0.0}});
  CHECK(late.naive_ulps <= 4);
  CHECK(late.stable_ulps <= 4);
  // ... where the stable form alone would lose digits: that is why its regime has a condition
  const dc::Derivation& d = handout("09_rocket.dc");
  FormulaEvaluator fe(d, "velocity_symbols");
  REQUIRE(fe.condition().has_value());
  CHECK(fe.condition()->text == "m_r > m0/2");
  const std::vector<double> x{1e-3, 1000.0, 2500.0, 9.81, 0.0};
  CHECK_FALSE(fe.in_regime(x.data()));
}

TEST_CASE("momentum change as v1p -> v1", "[numeric][stable]") {
  const Errors r = errors_at("05_direct_impact.dc", "momentum_change",
                             {{"m1", 3.0}, {"v1", 0.7}, {"v1p", 0.7 * (1 - 1e-12)}});
  CAPTURE(r.naive_ulps, r.stable_ulps);
  REQUIRE(r.naive_digits_lost() >= 3);
  REQUIRE(r.stable_ulps <= 4);
}

// A priori first-order bounds for the stable forms (the inputs are exact doubles): a correctly
// rounded operation adds at most u = 2^-53 of relative error, a libm sin/asin at most 2u (1 ulp),
// sqrt halves the relative error of its argument, a square doubles it, and sums of terms of one
// sign do not amplify; a relative error of r*u is less than r ulps of the result. Counting:
//   momentum_change      m1*(v1p - v1)                                  2 roundings          -> 2
//   energy_loss_plastic  1/2*(v1 - v2)^2/(1/m1 + 1/m2)                  2*1 + 1 + 1+1+1 + 1  -> 7
//   energy_loss_general  (1 - e)*(1 + e)/2*(...plastic...)              1 + 1 + 1 + 7 + 1    -> 11
//   height               2*L*sin(theta/2)^2                             2*2 + 1 + 1          -> 6
// (measured with 3 seeds x 3000 points: 1.3, 3.7, 5.0 and 2.6 ulps). The test used to demand 4 ulps
// of every form; the sanitizer run's different sampling found energy_loss_general at 4.26 ulps,
// and 9000 points found 5.0: 4 was a lucky seed, not a property.
TEST_CASE("stable forms stay within their a priori error bounds over the domain and the stress points",
          "[numeric][stable]") {
  CrossCheckOptions opt;
  opt.points = 150;
  CAPTURE(opt.seed);
  // formulas whose stable form is well-conditioned over the whole declared domain
  const std::map<std::string, std::vector<std::pair<std::string, double>>> files = {
      {"05_direct_impact.dc",
       {{"momentum_change", 2}, {"energy_loss_plastic_naive", 7}, {"energy_loss_general", 11},
        {"energy_loss_general_naive", 11}}},
      {"06_ballistic_pendulum.dc", {{"height", 6}}},
  };
  for (const auto& [file, labels] : files) {
    const auto reports = crosscheck(handout(file), opt);
    for (const auto& [label, bound] : labels) {
      auto rep = std::find_if(reports.begin(), reports.end(), [&](const FormulaReport& r) { return r.label == label; });
      REQUIRE(rep != reports.end());
      auto stable = std::find_if(rep->methods.begin(), rep->methods.end(),
                                 [](const MethodStats& m) { return m.method == "stable"; });
      REQUIRE(stable != rep->methods.end());
      CAPTURE(file, label, bound, stable->points, stable->stress_points, stable->max_ulps_random, stable->max_ulps_stress);
      CHECK(stable->points >= 150);
      CHECK(stable->stress_points >= 5);
      CHECK(stable->max_ulps <= bound);
      CHECK(stable->non_finite == 0);
    }
  }
}

// deflection_stable = 2*asin(y), y = m*v0/(2*(M + m)*sqrt(L*g)), is not well-conditioned on the
// whole domain: asin's condition number y/(sqrt(1 - y^2)*asin(y)) grows without bound as
// theta -> pi (measured: 10.4 ulps there, and no fixed bound holds). For theta <= 60 degrees
// (y <= 1/2) it is at most 1.1; y carries at most 5.5u (m*v0, M + m, L*g halved by sqrt, sqrt,
// the product, the quotient), asin adds 2u: (1.1*5.5 + 2)u -> at most 9 ulps.
TEST_CASE("the pendulum's deflection stays within its bound where asin is well-conditioned", "[numeric][stable]") {
  double worst = 0;
  int n = 0;
  for (double m : {0.003, 0.05, 1.0, 7.3})
    for (double M : {0.7, 4.0, 55.0})
      for (double L : {0.4, 2.5})
        for (double y : {1e-12, 1e-6, 1e-3, 0.01, 0.1, 0.2, 0.3, 0.37, 0.45, 0.5}) {
          const double g = 9.81;
          const double v0 = y * 2 * (M + m) * std::sqrt(L * g) / m;   // a double near the target y
          const Errors r = errors_at("06_ballistic_pendulum.dc", "deflection", {{"m", m}, {"M", M}, {"v0", v0}, {"L", L}, {"g", g}});
          worst = std::max(worst, r.stable_ulps);
          ++n;
        }
  CAPTURE(n, worst);
  CHECK(worst <= 9);
}

TEST_CASE("the rocket's stable form with its regime condition stays within 4 ulps where -g t does not cancel", "[numeric][stable]") {
  // v = -u_e log(m_r/m0) - g t has an interior zero (the two terms cancel when the rocket has
  // not yet gained speed against gravity); with t = 0 the evaluator's error is the log's alone.
  const dc::Derivation& d = handout("09_rocket.dc");
  FormulaEvaluator fe(d, "velocity_symbols");
  double worst = 0;
  for (double frac : {1e-15, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 0.4, 0.6, 0.9, 0.999, 0.999999}) {
    const double m0 = 1234.5, m_r = m0 * (1 - frac);
    const std::vector<double> x{m_r, m0, 2500.0, 9.81, 0.0};
    GiNaC::exmap p;
    for (std::size_t i = 0; i < x.size(); ++i)
      p[d.symbols.find(fe.params()[i].get_name())->sym] = exact_rational(x[i]);
    worst = std::max(worst, error_in_ulps(fe(x), reference_value(fe.formula().expr, p, 40)));
  }
  CHECK(worst <= 4);
}
