// Compensated (double-double) evaluation for the formulas whose value crosses zero inside the
// domain: v'1, v'2 (general impact), T' after a plastic impact, the rocket's v. Near the zero
// their terms cancel in any fixed double formula; the compensated tape stays within 4 ulps of
// the CLN reference there and over the domain. Formulas are loaded by label, never typed here.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "derivations/reader/derivation.hpp"
#include "numeric/compensated.hpp"
#include "numeric/crosscheck.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/formula_evaluator.hpp"
#include "numeric/reference/reference.hpp"
#include "handout.hpp"

using namespace dc::num;

namespace {

using dc::test::handout;

struct Errs {
  double naive, fast, comp;  // formula's tape in double; stable-in-regime in double; compensated
  double naive_digits_lost() const {
    return std::isfinite(naive) ? std::log10(std::max(naive, 1.0)) : 16.0;
  }
  double fast_digits_lost() const { return std::isfinite(fast) ? std::log10(std::max(fast, 1.0)) : 16.0; }
};

Errs errs_at(const std::string& file, const std::string& label, const std::map<std::string, double>& at) {
  const dc::Derivation& d = handout(file);
  FormulaEvaluator fe(d, label, EvalMode::Compensated);
  std::vector<double> x;
  GiNaC::exmap point;
  for (const auto& s : fe.params()) {
    const double v = at.at(s.get_name());
    x.push_back(v);
    point[d.symbols.find(s.get_name())->sym] = exact_rational(v);
  }
  const GiNaC::numeric ref = reference_value(fe.formula().expr, point, 50);
  return {error_in_ulps(fe.naive(x), ref), error_in_ulps(fe.fast(x), ref),
          error_in_ulps(fe.compensated_value(x), ref)};
}

}  // namespace

TEST_CASE("double-double primitives are error-free where they must be", "[numeric][compensated]") {
  // TwoSum / TwoProd: hi + lo is the exact sum / product
  const dc::num::DD s = dd::two_sum(1.0, 1e-20);
  CHECK(s.hi == 1.0);
  CHECK(s.lo == 1e-20);
  const double a = 1.0 + std::ldexp(1.0, -30), b = 1.0 - std::ldexp(1.0, -30);
  const dc::num::DD p = dd::two_prod(a, b);  // 1 - 2^-60 exactly
  CHECK(p.hi == 1.0);
  CHECK(p.lo == -std::ldexp(1.0, -60));
  // division and square root: residuals at double-double level
  const dc::num::DD q = dd::div({1.0, 0.0}, {3.0, 0.0});
  CHECK(std::fabs(dd::sub(dd::mul(q, {3.0, 0.0}), {1.0, 0.0}).hi) < 1e-31);
  const dc::num::DD r = dd::sqrt({2.0, 0.0});
  CHECK(std::fabs(dd::sub(dd::mul(r, r), {2.0, 0.0}).hi) < 1e-30);
  // exp and log are inverse to double-double accuracy (not just long double's 2^-64)
  for (double x : {3.0, 0.7, 1e-10, 1e5, 2.5e-5}) {
    const dc::num::DD y = dd::transcendental(Op::Log, {x, 0.0}, {});
    const dc::num::DD back = dd::transcendental(Op::Exp, y, {});
    CAPTURE(x);
    CHECK(std::fabs(dd::sub(back, {x, 0.0}).hi / x) < 1e-28);
  }
  // overflow gives inf, not NaN from inf - inf in the error terms
  const dc::num::DD big = dd::mul({1e300, 0.0}, {1e10, 0.0});
  CHECK(std::isinf(big.hi));
  CHECK(std::isinf(dd::add({1.7e308, 0.0}, {1.7e308, 0.0}).hi));
}

TEST_CASE("compensated batch and scalar evaluation agree bit for bit", "[numeric][compensated]") {
  const dc::Derivation& d = handout("05_direct_impact.dc");
  FormulaEvaluator fe(d, "v1p_general", EvalMode::Compensated);
  const int n = 600;  // more than two blocks of 256
  Eigen::ArrayXXd in(n, 5);
  for (int i = 0; i < n; ++i) {
    const double t = 0.37 + i * 0.013;
    for (int j = 0; j < 5; ++j) {
      const std::string& name = fe.params()[static_cast<std::size_t>(j)].get_name();
      in(i, j) = name == "e" ? std::fmod(t, 1.0) : (name[0] == 'v' ? std::sin(t * (j + 1)) * 3 : 1 + t * j);
    }
  }
  Eigen::ArrayXd out;
  fe.eval_batch(in, out);
  REQUIRE(out.size() == n);
  for (int i = 0; i < n; ++i) {
    std::vector<double> x(5);
    for (int j = 0; j < 5; ++j) x[static_cast<std::size_t>(j)] = in(i, j);
    REQUIRE(out(i) == fe(x));
  }
}

TEST_CASE("Auto mode: compensated exactly where the tape can cancel", "[numeric][compensated]") {
  const dc::Derivation& impact = handout("05_direct_impact.dc");
  CHECK(FormulaEvaluator(impact, "v1p_general").compensated());
  CHECK(FormulaEvaluator(impact, "v2p_general").compensated());
  CHECK(FormulaEvaluator(impact, "energy_after_plastic").compensated());
  CHECK(FormulaEvaluator(handout("09_rocket.dc"), "velocity_symbols").compensated());
  // sign-definite stable forms stay in fast double
  CHECK_FALSE(FormulaEvaluator(impact, "energy_loss_general").compensated());
  CHECK_FALSE(FormulaEvaluator(impact, "energy_loss_plastic_naive").compensated());
  CHECK_FALSE(FormulaEvaluator(handout("06_ballistic_pendulum.dc"), "height").compensated());
  CHECK_FALSE(FormulaEvaluator(impact, "v1p_general", EvalMode::Fast).compensated());
}

TEST_CASE("v'1 and v'2 near their zero: the double forms lose digits, compensated does not", "[numeric][compensated]") {
  const double m1 = 2.0, m2 = 3.0, v1 = 1.5, e = 0.5;
  for (double rel : {1e-6, 1e-9, 1e-12}) {
    // v'1 = 0 at v2 = v1 (e m2 - m1)/(m2 (1 + e)); v'2 = 0 at v2 = -m1 v1 (1 + e)/(m2 - e m1)
    const double v2a = v1 * (e * m2 - m1) / (m2 * (1 + e)) * (1 + rel);
    const Errs a = errs_at("05_direct_impact.dc", "v1p_general", {{"m1", m1}, {"m2", m2}, {"v1", v1}, {"v2", v2a}, {"e", e}});
    const double v2b = -m1 * v1 * (1 + e) / (m2 - e * m1) * (1 + rel);
    const Errs b = errs_at("05_direct_impact.dc", "v2p_general", {{"m1", m1}, {"m2", m2}, {"v1", v1}, {"v2", v2b}, {"e", e}});
    CAPTURE(rel, a.naive, a.fast, a.comp, b.naive, b.fast, b.comp);
    CHECK(a.comp <= 4);
    CHECK(b.comp <= 4);
    // the double forms lose about -log10(rel) - 1 digits (the result is ~rel times the terms)
    CHECK(std::max(a.naive_digits_lost(), a.fast_digits_lost()) >= -std::log10(rel) - 3);
    CHECK(std::max(b.naive_digits_lost(), b.fast_digits_lost()) >= -std::log10(rel) - 3);
  }
  const Errs huge = errs_at("05_direct_impact.dc", "v1p_general",
                            {{"m1", 1e300}, {"m2", 3e305}, {"v1", 2e10}, {"v2", -1e9}, {"e", 0.5}});
  CAPTURE(huge.naive, huge.comp);
  CHECK(huge.comp <= 4);  // the stable form's mass fractions, in double-double: no overflow
}

TEST_CASE("T' after a plastic impact near v2 = -m1 v1/m2 (all energy lost)", "[numeric][compensated]") {
  const double m1 = 2.0, m2 = 3.0, v1 = 1.5;
  for (double rel : {1e-6, 1e-10}) {
    const Errs r = errs_at("05_direct_impact.dc", "energy_after_plastic",
                           {{"m1", m1}, {"m2", m2}, {"v1", v1}, {"v2", -m1 * v1 / m2 * (1 + rel)}});
    CAPTURE(rel, r.naive, r.fast, r.comp);
    CHECK(r.comp <= 4);
    CHECK(std::max(r.naive_digits_lost(), r.fast_digits_lost()) >= -std::log10(rel) - 3);
  }
}

TEST_CASE("rocket v = -u_e ln(m_r/m0) - g t near its zero (thrust just balancing gravity)", "[numeric][compensated]") {
  const double m0 = 1234.5, u_e = 2500.0, g = 9.81;
  for (double frac : {0.3, 1e-4}) {       // burnt fraction: naive log form and log1p regime
    for (double rel : {1e-6, 1e-11}) {
      const double m_r = m0 * (1 - frac);
      const double t = u_e * std::log(m0 / m_r) / g * (1 + rel);
      const Errs r = errs_at("09_rocket.dc", "velocity_symbols",
                             {{"m_r", m_r}, {"m0", m0}, {"u_e", u_e}, {"g", g}, {"t", t}});
      CAPTURE(frac, rel, r.naive, r.fast, r.comp);
      CHECK(r.comp <= 4);
      CHECK(std::max(r.naive_digits_lost(), r.fast_digits_lost()) >= -std::log10(rel) - 3);
    }
  }
}

TEST_CASE("compensated forms stay within 4 ulps over the domain and the stress points", "[numeric][compensated]") {
  CrossCheckOptions opt;
  opt.points = 150;
  CAPTURE(opt.seed);
  const std::map<std::string, std::vector<std::string>> files = {
      {"05_direct_impact.dc", {"v1p_general", "v2p_general", "energy_after_plastic"}},
      {"09_rocket.dc", {"velocity_symbols"}},
  };
  for (const auto& [file, labels] : files) {
    const auto reports = crosscheck(handout(file), opt);
    for (const auto& label : labels) {
      auto rep = std::find_if(reports.begin(), reports.end(), [&](const FormulaReport& r) { return r.label == label; });
      REQUIRE(rep != reports.end());
      auto comp = std::find_if(rep->methods.begin(), rep->methods.end(),
                               [](const MethodStats& m) { return m.method == "compensated"; });
      REQUIRE(comp != rep->methods.end());
      CAPTURE(file, label, comp->points, comp->max_ulps_random, comp->max_ulps_stress, comp->worst_kind);
      CHECK(comp->points >= 150);
      CHECK(comp->max_ulps <= 4);
      CHECK(comp->non_finite == 0);
    }
  }
}
