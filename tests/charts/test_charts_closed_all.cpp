// Claims of the summary work-precision chart docs/charts/wp_closed_all.png (every formula of
// derivations/handout9 that the numeric module evaluates; docs/charts.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "numeric/charts/chart_data.hpp"

using namespace dc::chart;

namespace {
const std::string kRoot = DERIVCHECK_SOURCE_DIR;

const ClosedAllResult& all_rows() {
  static const ClosedAllResult res = [] {
    std::vector<std::string> paths;
    for (const char* f : {"01_momentum_particle", "02_cannon", "03_ladder", "04_system_of_particles",
                          "05_direct_impact", "06_ballistic_pendulum", "07_two_ball_bounce", "08_oblique_impact",
                          "09_rocket", "10_falling_chain"})
      paths.push_back(kRoot + "/derivations/handout9/" + f + ".dc");
    ClosedAllOptions o;
    o.points = 6, o.repeats = 1, o.batch = 256;
    return closed_forms_wp_all(paths, o);
  }();
  return res;
}

std::map<std::string, std::map<std::string, WpRow>> by_formula() {
  std::map<std::string, std::map<std::string, WpRow>> m;
  for (const auto& r : all_rows().rows) m[r.formula][method_family(r.method)] = r;
  return m;
}
}  // namespace

TEST_CASE("closed forms, all formulas: every compilable handout formula is charted, only abstract ones skipped",
          "[charts][closed_all]") {
  const auto m = by_formula();
  CHECK(m.size() >= 100);
  for (const auto& s : all_rows().skipped) {
    INFO(s);
    CHECK(s.find("unsupported function") != std::string::npos);
  }
  for (const auto& [f, methods] : m) {
    INFO(f);
    for (const char* want : {"CLN 15 digits", "CLN 30 digits", "CLN 50 digits", "CLN 100 digits", "double (evaluator)",
                             "long double (evaluator)", "compensated (double-double)", "certified auto"})
      CHECK(methods.count(want) == 1);
  }
  // the file's stable forms and the hand-written speed limit appear where they exist
  CHECK(m.at("05_direct_impact.dc:energy_loss_general").count("stable form") == 1);
  CHECK(m.at("09_rocket.dc:velocity_symbols").count("stable form") == 1);
  for (const char* f : {"05_direct_impact.dc:v1p_general", "05_direct_impact.dc:energy_loss_general",
                        "06_ballistic_pendulum.dc:deflection", "07_two_ball_bounce.dc:v1p_bounce", "03_ladder.dc:wall_impulse"})
    CHECK(m.at(f).count("hand-written C++") == 1);
}

TEST_CASE("closed forms, all formulas: compensated is never worse than double by more than 1 ulp", "[charts][closed_all]") {
  for (const auto& [f, methods] : by_formula()) {
    INFO(f);
    const double d = methods.at("double (evaluator)").ulps_max;
    const double c = methods.at("compensated (double-double)").ulps_max;
    CHECK(c <= d + 1);
  }
}

TEST_CASE("closed forms, all formulas: CLN at 50 digits is within 1e-40 relative on the random points, "
          "but not at every stress point",
          "[charts][closed_all]") {
  int stress_failures = 0;
  for (const auto& [f, methods] : by_formula()) {
    INFO(f);
    const WpRow& r = methods.at("CLN 50 digits");
    CHECK(r.rel_err_max_random <= 1e-40);
    const WpRow& r100 = methods.at("CLN 100 digits");
    CHECK(r100.rel_err_max_random <= 1e-90);
    if (!(r.rel_err_max <= 1e-40)) ++stress_failures;
  }
  // inputs rounded to 50 digits cancel in the naive forms at stress points (e.g. the energy
  // loss as T_before - T_after with masses near 1e300): the chart shows those outliers
  CHECK(stress_failures >= 1);
}

TEST_CASE("closed forms, all formulas: the certified mode is correctly rounded at every point", "[charts][closed_all]") {
  // crosscheck's random and stress points, exact doubles: `eval --method auto` (double-double,
  // long double, Arb) is within half an ulp of the reference wherever that is a finite double
  std::size_t formulas = 0, worse_double = 0;
  for (const auto& [f, methods] : by_formula()) {
    INFO(f);
    const WpRow& c = methods.at("certified auto");
    const WpRow& d = methods.at("double (evaluator)");
    if (!std::isfinite(c.ulps_max)) continue;   // a point whose true value is not a finite double
    ++formulas;
    CHECK(c.ulps_max <= 0.5 + 1e-9);
    worse_double += d.ulps_max > 0.5 + 1e-9 ? 1 : 0;
  }
  INFO(formulas << " formulas; plain double misses half an ulp on " << worse_double);
  CHECK(formulas >= 90);
  CHECK(worse_double >= 30);
}
