// Smaller tool points of issue 26: crosscheck names the user's functions and explains a file
// it cannot evaluate, keeps physical quantities at physical magnitudes and calls an overflow an
// overflow; misspelt names get a suggestion; `eval --for` solves a step for a quantity.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "derivations/reader/derivation.hpp"
#include "numeric/crosscheck.hpp"

namespace {

struct Run {
  int code;
  std::string out;
};

Run run_cli(const std::string& args) {
  const std::string cmd = std::string(DERIVCHECK_CLI) + " " + args + " 2>&1";
  Run r{-1, {}};
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string data(const std::string& name) { return std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/numeric/" + name; }

bool has(const std::string& s, const std::string& piece) { return s.find(piece) != std::string::npos; }

std::string error_of(const std::string& text) {
  try {
    dc::parse_derivation(dc::SourceText{"<t>.dc", text});
  } catch (const dc::InputError& e) {
    return e.message();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("crosscheck: functions of t are named as the user wrote them, and a file of them says why",
          "[numeric][crosscheck][tool-points]") {
  // a formula through a declared function: the user's name, never GiNaC's pool name
  dc::Derivation d = dc::parse_derivation(dc::SourceText{
      "<t>.dc",
      "symbol t : real [s]\nsymbol v : real [m/s]\nfunction x(t) : real [m]\n"
      "pos: x(t) = 2*t\n    by given\nvel: v = diff(x(t), t)\n    by given\n"});
  dc::num::CrossCheckOptions opt;
  opt.points = 5;
  const auto reports = dc::num::crosscheck(d, opt);
  REQUIRE(reports.size() == 1);
  CHECK(has(reports[0].skipped, "the function x(t)"));
  const std::string table = dc::num::format_crosscheck(reports, opt);
  CHECK_FALSE(has(table, "dcfn"));
  // a file whose results are all functions of t is listed with the reason
  const Run r = run_cli("crosscheck '" + data("functions_of_t.dc") + "' --points 5");
  CAPTURE(r.out);
  CHECK(r.code == 0);
  CHECK(has(r.out, "functions_of_t.dc\n"));
  CHECK(has(r.out, "no formula evaluated: its results are functions (x(t), v(t))"));
}

TEST_CASE("crosscheck: stress points stay physical for quantities with a unit, overflow is named",
          "[numeric][crosscheck][tool-points]") {
  const dc::Derivation d = dc::load_derivation(data("stress_range.dc"));
  dc::num::CrossCheckOptions opt;
  opt.points = 10;
  const dc::Formula area = dc::formula(d, "area");
  double max_L = 0, max_q = 0;
  for (const auto& p : dc::num::crosscheck_points(d, area, opt)) {
    for (std::size_t i = 0; i < area.params.size(); ++i) {
      const double v = std::fabs(p.x[i]);
      (area.params[i].get_name() == "L" ? max_L : max_q) = std::max(area.params[i].get_name() == "L" ? max_L : max_q, v);
    }
  }
  CHECK(max_L <= 1e60);    // a length: no 1e160 m
  CHECK(max_L >= 1e59);    // but still far beyond any physical length
  CHECK(max_q >= 1e159);   // a pure number is still stressed at huge magnitudes
  const std::string table = dc::num::format_crosscheck(dc::num::crosscheck(d, opt), opt);
  CAPTURE(table);
  CHECK(has(table, "over 4 ulps: overflow (double overflows: a non-finite result at"));
  CHECK_FALSE(has(table, "(double inf)"));
}

TEST_CASE("unknown names: a suggestion by edit distance in the positioned error", "[tool-points][reader]") {
  const std::string head = "symbol x, theta : real [1]\ns1: x = theta\n    by given\n";
  CHECK(has(error_of(head + "s2: x = thetaa\n    by given\n"), "undefined symbol 'thetaa' (did you mean 'theta'?)"));
  CHECK(has(error_of(head + "s2: x = theta\n    by givn\n"), "unknown rule 'givn' (did you mean 'given'?)"));
  CHECK(has(error_of(head + "s2: x = theta\n    by simplfy s1\n"), "(did you mean 'simplify'?)"));
  CHECK(has(error_of(head + "s2: x = theta\n    by rewrite s11\n"), "unknown label 's11' (did you mean 's1'?)"));
  CHECK(has(error_of(head + "s2: x = sni(theta)\n    by given\n"), "unknown function 'sni' (did you mean 'sin'?)"));
  // nothing near: no suggestion
  const std::string far = error_of(head + "s2: x = zzzzzz\n    by given\n");
  CHECK(has(far, "undefined symbol 'zzzzzz'"));
  CHECK_FALSE(has(far, "did you mean"));
  // the suggestion goes with the position
  try {
    dc::parse_derivation(dc::SourceText{"<t>.dc", head + "s2: x = thetaa\n    by given\n"});
  } catch (const dc::InputError& e) {
    CHECK(e.pos().line == 4);
    CHECK(e.pos().col == 9);
  }
}

TEST_CASE("eval --for: a step that is not 'y = expression' solved for a quantity", "[numeric][eval][tool-points]") {
  const std::string f = "'" + data("solve_for.dc") + "'";
  // cos(theta) = 1 - dh/L at dh = L/2: theta = acos(1/2) = pi/3
  Run r = run_cli("eval " + f + " swing --for theta --at dh=1/2,L=1");
  CAPTURE(r.out);
  CHECK(r.code == 0);
  CHECK(r.out.rfind("1.0471975511965979\n", 0) == 0);
  // without --for: the one quantity --at leaves open
  r = run_cli("eval " + f + " swing --at dh=1/2,L=1");
  CHECK(r.code == 0);
  CHECK(r.out.rfind("1.0471975511965979\n", 0) == 0);
  // reference digits too
  r = run_cli("eval " + f + " swing --at dh=1/2,L=1 --digits 20");
  CHECK(r.out.rfind("1.04719755119659774", 0) == 0);
  // the handout's own step dh = L*(1 - cos(theta)), solved for theta
  r = run_cli("eval '" + std::string(DERIVCHECK_SOURCE_DIR) +
              "/derivations/handout9/06_ballistic_pendulum.dc' height --for theta --at dh=1/2,L=1");
  CHECK(r.code == 0);
  CHECK(r.out.rfind("1.0471975511965979\n", 0) == 0);
  // sqrt(x) = y with y positive: x = y^2
  r = run_cli("eval " + f + " root --for x --at y=3");
  CHECK(r.out.rfind("9\n", 0) == 0);
  // refused where the inverse is not the one solution, or the quantity occurs twice
  r = run_cli("eval " + f + " unbounded --for phi --at dh=1/2,L=1");
  CHECK(r.code == 2);
  CHECK(has(r.out, "declared within [0, pi]"));
  r = run_cli("eval " + f + " twice --for x --at y=2");
  CHECK(r.code == 2);
  CHECK(has(r.out, "occurs 3 times"));
  r = run_cli("eval " + f + " swing --at L=1");
  CHECK(r.code == 2);
  CHECK(has(r.out, "name the quantity to solve it for with --for (not given: theta, dh)"));
}
