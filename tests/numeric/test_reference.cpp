// The CLN reference, exact conversions, and the `eval` / `crosscheck` commands' bad input.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"

using namespace dc::num;

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

const std::string kImpact = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/05_direct_impact.dc";

}  // namespace

TEST_CASE("exact conversions round-trip and format deterministically", "[numeric][reference]") {
  CHECK(format_significant(GiNaC::numeric(1, 3), 5) == "0.33333");
  CHECK(format_significant(GiNaC::numeric(-2, 3), 3) == "-0.667");
  CHECK(format_significant(GiNaC::numeric(12345678), 3) == "1.23e+07");
  CHECK(format_significant(GiNaC::numeric(1, 100000000), 2) == "1.0e-08");
  CHECK(format_significant(GiNaC::numeric(999999, 1000000), 3) == "1.00");
  CHECK(format_significant(GiNaC::numeric(5, 2), 1) == "2");  // ties to even
  CHECK(format_significant(GiNaC::numeric(0), 10) == "0");
  for (double x : {0.1, -3.5e-300, 1e308, 4.9e-324, 2.0 / 3.0})
    CHECK(round_to_double(exact_rational(x)) == x);
  CHECK(round_to_long_double(exact_rational(0.1L)) == 0.1L);
  GiNaC::numeric v;
  REQUIRE(parse_rational("5/2", v));
  CHECK(v == GiNaC::numeric(5, 2));
  REQUIRE(parse_rational("-0.125", v));
  CHECK(v == GiNaC::numeric(-1, 8));
  REQUIRE(parse_rational("1e-9", v));
  CHECK(v == GiNaC::numeric(1, 1000000000));
  CHECK_FALSE(parse_rational("1/0", v));
  CHECK_FALSE(parse_rational("abc", v));
  CHECK_FALSE(parse_rational("0.5.2", v));
  CHECK(double_ulp(GiNaC::numeric(1)) == GiNaC::pow(GiNaC::numeric(2), GiNaC::numeric(-52)));
  CHECK(error_in_ulps(1.0 + 0x1p-52, GiNaC::numeric(1)) == 1.0);
}

TEST_CASE("reference values to N digits", "[numeric][reference]") {
  GiNaC::symbol x("x");
  // exp(pi sqrt(163)) is within 1e-12 of an integer: 50 digits tell them apart
  const GiNaC::numeric r = reference_value(GiNaC::exp(GiNaC::Pi * GiNaC::sqrt(GiNaC::ex(163))), {}, 50);
  CHECK(format_significant(r, 30) == "262537412640768743.999999999999");
  // rational at a rational point: exact
  CHECK(reference_value(x / 3 + 1, {{x, GiNaC::numeric(1, 2)}}, 20) == GiNaC::numeric(7, 6));
  // a float zero that is not zero: acos(1 - 1e-162) needs more than 100 digits
  const GiNaC::ex tiny = GiNaC::pow(GiNaC::numeric(10), -162);
  const GiNaC::numeric a = reference_value(GiNaC::acos(1 - x), {{x, tiny}}, 30);
  CHECK(format_significant(a, 20) == "1.4142135623730950488e-81");
  CHECK_THROWS_AS(reference_value(GiNaC::log(x), {{x, GiNaC::numeric(-1)}}, 30), std::domain_error);
  CHECK_THROWS_AS(reference_value(1 / x, {{x, GiNaC::numeric(0)}}, 30), std::domain_error);
  CHECK_THROWS_WITH(reference_value(x + GiNaC::symbol("y"), {{x, GiNaC::numeric(1)}}, 30), Catch::Contains("y"));
}

TEST_CASE("derivcheck eval prints N significant digits", "[numeric][reference][cli]") {
  const Run r = run_cli("eval " + kImpact + " v1p_general --at m1=1,m2=5/2,v1=3,v2=-1,e=1/2 --digits 30");
  CHECK(r.code == 0);
  CHECK(r.out == "-1.28571428571428571428571428571\n");
}

TEST_CASE("derivcheck eval: bad input is exit 2 naming the problem", "[numeric][reference][cli]") {
  const std::string base = "eval " + kImpact + " v1p_general --at ";
  Run r = run_cli(base + "m1=1,m2=5/2,v1=3,v2=-1,e=3/2");
  CHECK(r.code == 2);
  CHECK_THAT(r.out, Catch::Contains("'e'") && Catch::Contains("3/2") && Catch::Contains("[0, 1]"));
  r = run_cli(base + "m1=1,m2=5/2,v1=3,v2=-1");
  CHECK(r.code == 2);
  CHECK_THAT(r.out, Catch::Contains("missing") && Catch::Contains("e"));
  r = run_cli(base + "m1=1,m2=5/2,v1=3,v2=-1,e=1/2,q=1");
  CHECK(r.code == 2);
  CHECK_THAT(r.out, Catch::Contains("unknown parameter 'q'"));
  r = run_cli(base + "m1=-1,m2=5/2,v1=3,v2=-1,e=1/2");
  CHECK(r.code == 2);
  CHECK_THAT(r.out, Catch::Contains("'m1'") && Catch::Contains("positive"));
  r = run_cli(base + "m1=1,m2=5/2,v1=-3,v2=1,e=1/2");
  CHECK(r.code == 2);
  CHECK_THAT(r.out, Catch::Contains("v1 > v2"));
  r = run_cli(base + "m1=x");
  CHECK(r.code == 2);
  CHECK_THAT(r.out, Catch::Contains("m1"));
  r = run_cli("eval " + kImpact + " no_such_label --at m1=1");
  CHECK(r.code == 2);
  CHECK_THAT(r.out, Catch::Contains("no_such_label"));
}

TEST_CASE("derivcheck crosscheck prints its seed and is deterministic", "[numeric][crosscheck][cli]") {
  const std::string args = "crosscheck " + kImpact + " --points 20 --seed 7";
  const Run a = run_cli(args), b = run_cli(args);
  CHECK(a.code == 0);
  CHECK_THAT(a.out, Catch::Contains("seed 7") && Catch::Contains("energy_loss_general") && Catch::Contains("stable("));
  CHECK(a.out == b.out);
  CHECK(run_cli("crosscheck " + kImpact + " --points 0").code == 2);
}
