// Claims of the checker work-precision chart and of the chain / bounce event maps
// (docs/charts.md), as tests. Small sweeps; the charts themselves use more.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <catch2/catch.hpp>

#include "numeric/charts/chart_checker.hpp"
#include "numeric/charts/chart_ode_maps.hpp"

using namespace dc::chart;

namespace {
const std::string kCorpus = std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/corpus.jsonl";
}

TEST_CASE("checker chart: the cascade judges every labelled claim right, symbolic only leaves true claims undecided",
          "[charts][checker]") {
  const auto corpus = read_corpus(kCorpus);
  REQUIRE(corpus.size() >= 40);
  const auto strategies = checker_strategies({1}, {20});
  REQUIRE(strategies.size() == 3);
  REQUIRE(strategies.front().name == "symbolic only");
  REQUIRE(strategies.back().name == "full cascade");
  std::map<std::string, CheckerRow> by;
  for (const auto& s : strategies) by[s.name] = run_strategy(corpus, s, 1);
  const auto& cascade = by.at("full cascade");
  const auto& sym = by.at("symbolic only");
  const auto& probe = by.at("probe k=1, 20 digits");
  CAPTURE(cascade.wrong, sym.wrong, probe.wrong);
  CHECK(cascade.accuracy == 1.0);
  CHECK(cascade.false_accepts == 0);
  CHECK(cascade.false_rejects == 0);
  CHECK(cascade.undecided == 0);
  // symbolic stages cannot refute a claim nor settle every true one
  CHECK(sym.true_undecided > 0);
  CHECK(sym.accuracy < 1.0);
  CHECK(sym.false_accepts == 0);
  // no strategy ever refutes a true claim
  CHECK(sym.false_rejects == 0);
  CHECK(probe.false_rejects == 0);
}

TEST_CASE("checker chart: the probe judges every claim right at 20 digits and more, the near-integer trap included",
          "[charts][checker]") {
  // exp(pi sqrt(163)) differs from 640320^3 + 744 by 7.5e-13 (~4e-30 relative): below the 20-digit
  // agreement tolerance, but the probe's Arb balls certify the difference, so the claim is refuted
  const auto corpus = read_corpus(kCorpus);
  for (const auto& s : checker_strategies({1, 8}, {20, 30, 100})) {
    if (s.family.rfind("probe", 0) != 0) continue;
    const auto r = run_strategy(corpus, s, 1);
    CAPTURE(s.name, r.wrong);
    CHECK(r.false_rejects == 0);
    CHECK(r.undecided == 0);
    CHECK(r.accuracy == 1.0);
    CHECK(r.false_accepts == 0);
  }
}

TEST_CASE("checker chart: bad options and corpora are errors", "[charts][checker]") {
  CHECK_THROWS_AS(checker_strategies({0}, {30}), std::invalid_argument);
  CHECK_THROWS_AS(checker_strategies({1}, {15}), std::invalid_argument);
  CHECK_THROWS_AS(read_corpus(kCorpus + ".missing"), std::invalid_argument);
}

TEST_CASE("chain map: x' = sqrt(2gx) from rest stays at x = 0 with every integrator, x'' = g follows the fall",
          "[charts][maps]") {
  const double h = 1e-3;
  const auto rows = chain_from_rest_map(h, 12);
  int first = 0, second = 0;
  for (const auto& r : rows) {
    CAPTURE(r.model, r.method, r.t, r.x, r.x_exact);
    if (r.model.rfind("first", 0) == 0) {
      ++first;
      CHECK(r.x == 0.0);   // exactly: the error is the whole fall g t^2/2
      CHECK(r.abs_error == r.x_exact);
    } else {
      ++second;
      if (r.method == "euler") {
        // explicit Euler on x'' = g lags by exactly g t h / 2 (first order)
        if (r.t > 0) CHECK(std::abs(r.abs_error - 9.81 * r.t * h / 2) <= 1e-9 * r.x_exact + 1e-15);
      } else {
        CHECK(r.abs_error <= 1e-12 * std::max(r.x_exact, 1e-6));
      }
    }
  }
  CHECK(first == 4 * 12);
  CHECK(second >= 5 * 10);
}

TEST_CASE("bounce map: located events reproduce the exact rebound velocity, events at the step end err first order in h",
          "[charts][maps]") {
  for (const char* m : {"rk4", "verlet", "dopri5", "rosenbrock"})
    for (double h : {1e-4, 1e-2}) {
      const auto r = bounce_event_run(m, true, h);
      CAPTURE(m, h, r.v1p, r.v1p_exact);
      CHECK(r.rel_error < 1e-9);
    }
  for (const char* m : {"euler", "rk4", "dopri5", "verlet", "rosenbrock"}) {
    // the error depends on where in its step each event falls, so compare decades: at most h
    // (overshoot of the ground) and at least 1e-4 relative at h = 1e-3, and >= 10x smaller at 1e-5
    const auto a = bounce_event_run(m, false, 1e-3), b = bounce_event_run(m, false, 1e-5);
    const auto located = bounce_event_run(m, true, 1e-3);
    CAPTURE(m, a.rel_error, b.rel_error, located.rel_error);
    CHECK(a.rel_error > 1e-4);
    CHECK(a.rel_error > 10 * b.rel_error);
    if (std::string(m) != "euler") CHECK(a.rel_error > 100 * located.rel_error);   // euler: see below
  }
  // explicit Euler's trajectory error is first order even with located events
  const auto e1 = bounce_event_run("euler", true, 1e-3), e2 = bounce_event_run("euler", true, 1e-4);
  CAPTURE(e1.rel_error, e2.rel_error);
  CHECK(e1.rel_error / e2.rel_error > 5);
  CHECK(e1.rel_error / e2.rel_error < 20);
}
