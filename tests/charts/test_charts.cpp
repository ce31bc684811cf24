// Each claim a chart in docs/charts.md makes, as a test (issue 5: "each claim a map makes is
// also a test"). Small point counts; the charts themselves use more.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "derivations/syntax/io.hpp"
#include "numeric/charts/chart_data.hpp"
#include "numeric/charts/chart_plot.hpp"

using namespace dc::chart;

namespace {

const std::string kRoot = DERIVCHECK_SOURCE_DIR;

// Largest bits lost per method in a map, restricted to stress values where `in_regime` holds.
std::map<std::string, double> worst(const std::vector<MapRow>& rows,
                                    const std::function<bool(double)>& in_regime = [](double) { return true; }) {
  std::map<std::string, double> w;
  for (const auto& r : rows)
    if (in_regime(r.stress)) w[r.method] = std::max(w[r.method], r.bits_lost);
  return w;
}

double for_prefix(const std::map<std::string, double>& w, const std::string& prefix) {
  double best = -1;
  for (const auto& [m, b] : w)
    if (m.rfind(prefix, 0) == 0) best = std::max(best, b);
  return best;
}

}  // namespace

TEST_CASE("map e -> 1: the naive (1 - e^2) form loses over 20 bits, the stable step under 2", "[charts][maps]") {
  const auto rows = closed_form_map(kRoot, "e_to_1", 27);
  const auto w = worst(rows, [](double one_minus_e) { return one_minus_e < 1e-6; });
  CAPTURE(w);
  CHECK(w.at("naive: as written") > 20);
  REQUIRE(for_prefix(w, "stable: ") >= 0);   // the file has a stable step for energy_loss_general
  CHECK(for_prefix(w, "stable: ") < 2);
}

TEST_CASE("map v1 - v2 -> 0: T before - T after loses everything, the factored form nothing", "[charts][maps]") {
  const auto w = worst(closed_form_map(kRoot, "v1_to_v2", 27), [](double rel) { return rel < 1e-12; });
  CAPTURE(w);
  CHECK(w.at("naive: T before - T after") > 40);
  CHECK(w.at("stable: 1/2 m1 m2/(m1+m2) (v1-v2)^2") < 2);
}

TEST_CASE("map mu -> 0: the two-ball rebound formula is well conditioned (no form loses 2 bits)", "[charts][maps]") {
  const auto w = worst(closed_form_map(kRoot, "mu_to_0", 20));
  CAPTURE(w);
  for (const auto& [m, b] : w) CHECK(b < 2);
}

TEST_CASE("map m2 -> oo: m1 m2 overflows in the naive form, the stable step stays accurate", "[charts][maps]") {
  const auto rows = closed_form_map(kRoot, "m2_to_inf", 20);
  const auto w = worst(rows, [](double m2) { return m2 > 1e200; });
  CAPTURE(w);
  CHECK(w.at("naive: as written") >= 52);
  REQUIRE(for_prefix(w, "stable: ") >= 0);
  CHECK(for_prefix(w, "stable: ") < 2);
  // below the overflow the naive form is fine
  const auto low = worst(rows, [](double m2) { return m2 < 1e150; });
  CHECK(low.at("naive: as written") < 2);
}

TEST_CASE("map theta -> 0: acos(1 - x) loses most digits for tiny v0, the half-angle forms do not", "[charts][maps]") {
  const auto w = worst(closed_form_map(kRoot, "theta_to_0", 25), [](double v0) { return v0 < 1e-6; });
  CAPTURE(w);
  CHECK(w.at("naive: as written") > 40);
  CHECK(for_prefix(w, "stable: ") < 2);
}

TEST_CASE("map m_r -> m0: ln(m_r/m0) loses over 30 bits for a tiny burn fraction, log1p does not", "[charts][maps]") {
  const auto w = worst(closed_form_map(kRoot, "mr_to_m0", 15), [](double frac) { return frac < 1e-12; });
  CAPTURE(w);
  CHECK(w.at("naive: -u_e ln(m_r/m0) - g t") > 30);
  CHECK(for_prefix(w, "stable: ") < 2);
}

TEST_CASE("stiff spring: verlet blows up past omega h = 2, rk4 past 2.83, rosenbrock never, euler always grows", "[charts][maps]") {
  const auto rows = stiff_spring_map(5000, 12, 3.2);
  std::map<std::string, double> below, above;
  for (const auto& r : rows) {
    auto& lim = r.method == "verlet" ? (r.omega_h < 1.9 ? below : r.omega_h > 2.1 ? above : below)
              : r.method == "rk4"   ? (r.omega_h < 2.7 ? below : r.omega_h > 2.9 ? above : below)
                                    : (r.omega_h < 2 ? below : above);
    if ((r.method == "verlet" && r.omega_h >= 1.9 && r.omega_h <= 2.1) ||
        (r.method == "rk4" && r.omega_h >= 2.7 && r.omega_h <= 2.9))
      continue;
    lim[r.method] = std::max(lim[r.method], r.max_position_error);
  }
  CAPTURE(below, above);
  // the oscillation amplitude is v0/omega = 0.023 m: a bounded run stays below 0.1 m
  CHECK(below.at("verlet") < 0.1);
  CHECK(above.at("verlet") > 1e3);
  CHECK(below.at("rk4") < 0.1);
  CHECK(above.at("rk4") > 1e3);
  CHECK(below.at("rosenbrock") < 0.1);
  CHECK(above.at("rosenbrock") < 0.1);
  CHECK(below.at("euler") > 1e3);
}

TEST_CASE("closed-form work-precision: CLN at d digits is accurate to about d digits, double to a few ulps", "[charts][closed]") {
  ClosedOptions o;
  o.points = 8;
  o.repeats = 1;
  const auto rows = closed_form_wp(kRoot + "/derivations/handout9/05_direct_impact.dc", "energy_loss_general", o);
  std::map<std::string, WpRow> by;
  for (const auto& r : rows) by[r.method] = r;
  for (int d : {15, 30, 50, 100}) {
    const auto& r = by.at("CLN " + std::to_string(d) + " digits");
    CAPTURE(d, r.rel_err_max);
    CHECK(r.rel_err_max < std::pow(10.0, 1 - d));
  }
  CHECK(by.at("double (evaluator)").rel_err_max < 1e-15);
  CHECK(by.at("hand-written C++").rel_err_max < 1e-15);
  CHECK(by.at("long double (evaluator)").rel_err_max < 1e-18);
  // a CLN evaluation costs far more than a compiled double evaluation
  CHECK(by.at("CLN 15 digits").seconds.median > 20 * by.at("double (evaluator)").seconds.median);
}

TEST_CASE("closed-form work-precision: the acos form of the pendulum loses digits somewhere in its domain", "[charts][closed]") {
  ClosedOptions o;
  o.points = 48;
  o.repeats = 1;
  o.cln_digits = {15};
  const auto rows = closed_form_wp(kRoot + "/derivations/handout9/06_ballistic_pendulum.dc", "deflection", o);
  std::map<std::string, WpRow> by;
  for (const auto& r : rows) by[r.method] = r;
  CHECK(by.at("double (naive: no rewrites)").bits_lost_max > 6);
  for (const auto& [m, r] : by)
    if (m.rfind("double (stable form", 0) == 0) CHECK(r.bits_lost_max < 3);
}

TEST_CASE("plots: log axes drop non-positive points, pgfplots and gnuplot describe the same series", "[charts][plot]") {
  Plot p;
  p.title = "t_1 & 50%";
  p.xlabel = "x [s]";
  p.ylabel = "y [m]";
  p.series.push_back({"a_b", {{1, 2, 1, 3}, {0, 5, 0, 0}, {10, -1, 0, 0}, {100, 4, 3, 5}}, true, true});
  CHECK(plottable(p, {1, 2, 0, 0}));
  CHECK_FALSE(plottable(p, {0, 5, 0, 0}));
  CHECK_FALSE(plottable(p, {10, -1, 0, 0}));
  CHECK_FALSE(plottable(p, {NAN, 1, 0, 0}));
  const std::string tex = pgfplots(p);
  CHECK(tex.find("loglogaxis") != std::string::npos);
  CHECK(tex.find("t\\_1 \\& 50\\%") != std::string::npos);
  CHECK(tex.find("(100, 4) -= (0, 1) += (0, 1)") != std::string::npos);
  CHECK(tex.find("(0, 5)") == std::string::npos);
  const std::string gp = gnuplot_script(p, "svg", "/tmp/x.svg");
  CHECK(gp.find("set logscale x") != std::string::npos);
  CHECK(gp.find("yerrorbars") != std::string::npos);
  p.logx = p.logy = false;
  CHECK(pgfplots(p).find("\\begin{axis}") != std::string::npos);
  CHECK(plottable(p, {0, -1, 0, 0}));
}

TEST_CASE("plots: write_figures leaves complete files and no temporaries", "[charts][plot]") {
  const auto dir = std::filesystem::temp_directory_path() / ("dc_charts_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Plot p;
  p.title = "test";
  p.xlabel = "x";
  p.ylabel = "y";
  p.series.push_back({"s", {{1, 1, 1, 1}, {10, 100, 50, 200}}, true, true});
  const auto files = write_figures(p, (dir / "fig").string());
  CHECK(std::find(files.begin(), files.end(), (dir / "fig.tex").string()) != files.end());
  for (const auto& f : files) CHECK(std::filesystem::file_size(f) > 100);
  for (const auto& e : std::filesystem::directory_iterator(dir)) CHECK(e.path().string().find(".tmp") == std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("tables: CSV cells with commas or quotes are quoted, stats are median/min/max", "[charts]") {
  Table t{{"a", "b"}, {{"x,y", "say \"hi\""}}};
  CHECK(t.to_csv() == "a,b\n\"x,y\",\"say \"\"hi\"\"\"\n");
  const Stat s = stat_of({3, 1, 2, 10});
  CHECK(s.median == 2.5);
  CHECK(s.min == 1);
  CHECK(s.max == 10);
  CHECK_THROWS_AS(stat_of({}), std::invalid_argument);
  CHECK_THROWS_AS(closed_form_map(kRoot, "no_such_map", 5), std::invalid_argument);
  CHECK(fmt(HUGE_VAL) == "inf");
}

TEST_CASE("plots: no series hides under another, known bounds stop the axis, categories get one tick each",
          "[charts][plot]") {
  Plot p;
  p.title = "t";
  p.xlabel = "x";
  p.ylabel = "bits lost";
  p.logy = false;
  p.series.push_back({"naive", {{1, 50, 0, 0}, {10, 3, 0, 0}}, false, true});
  p.series.push_back({"evaluator", {{1, 50, 0, 0}, {10, 3, 0, 0}}, false, true});
  p.series.push_back({"stable", {{1, 0.5, 0, 0}, {10, 0.2, 0, 0}}, false, true});
  const Plot m = merge_identical_series(p);
  REQUIRE(m.series.size() == 2);
  CHECK(m.series[0].name == "naive = evaluator");
  CHECK(m.series[1].name == "stable");
  // a series equal to another only on some points stays apart
  p.series[1].points[1].y = 4;
  CHECK(merge_identical_series(p).series.size() == 3);

  p.ymin = 0;
  std::string gp = gnuplot_script(p, "svg", "/tmp/x.svg");
  CHECK(gp.find("set yrange [0:*]") != std::string::npos);
  CHECK(gp.find("graph 0.06, graph 0\n") != std::string::npos);   // no padding below the bound
  CHECK(pgfplots(p).find("ymin=0") != std::string::npos);

  Plot c;
  c.title = "c";
  c.xcategories = {"symbolic only", "probe 30 digits, k = 1"};
  c.series.push_back({"accuracy 1.000", {{0, 1e-4, 1e-4, 2e-4}, {1, 2e-4, 1e-4, 3e-4}}, true, false});
  gp = gnuplot_script(c, "svg", "/tmp/x.svg");
  CHECK(gp.find("set xtics (\"symbolic only\" 0, \"probe 30 digits, k = 1\" 1)") != std::string::npos);
  CHECK(gp.find("set logscale x") == std::string::npos);
  CHECK(gp.find("set xrange [-0.6:1.6]") != std::string::npos);
  const std::string tex = pgfplots(c);
  CHECK(tex.find("xticklabels={{symbolic only},{probe 30 digits, k = 1}}") != std::string::npos);
  CHECK(tex.find("semilogyaxis") != std::string::npos);
}
