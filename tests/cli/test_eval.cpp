// derivcheck eval: the double methods print the double in round-trip form, the method and a
// certified bound; reference prints N certified digits; --points evaluates a CSV of points,
// each row on its own (a bad row says so and the others are answered).
#include <cstdio>
#include <fstream>
#include <sstream>

#include "cli/cli_run.hpp"

using cli_test::run;
using cli_test::Run;
using cli_test::src;

namespace {

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

const std::string kHard = "tests/data/numeric/hard.dc";

}  // namespace

TEST_CASE("eval --method: a double, the method, a certified bound", "[cli][eval]") {
  SECTION("auto is the default without --digits: the correctly rounded double") {
    Run r = run({"eval", src(kHard), "one_minus_cos", "--at", "theta=1e-8"}, 120);
    CAPTURE(r.out, r.err);
    CHECK(r.exit_code == 0);
    auto l = lines_of(r.out);
    REQUIRE(l.size() == 3);
    CHECK(l[0] == "5e-17");
    CHECK(l[1].rfind("method: auto (correctly rounded", 0) == 0);
    CHECK(l[2] == "error: <= 0.5 ulp");
  }
  SECTION("double: the plain tape loses every digit here, and its certificate says so") {
    Run r = run({"eval", src(kHard), "one_minus_cos", "--at", "theta=1e-8", "--method", "double"}, 120);
    CAPTURE(r.out, r.err);
    CHECK(r.exit_code == 0);
    auto l = lines_of(r.out);
    REQUIRE(l.size() >= 3);
    CHECK(l[0] == "0");
    CHECK(l[1] == "method: double (the formula's tape)");
    CHECK(l[2].rfind("error: <= 8", 0) == 0);   // about 8.5e+15 ulps: all digits lost
  }
  SECTION("not representable: inf with the reason, exit 0") {
    Run r = run({"eval", src(kHard), "exp_big", "--at", "x=1e200"}, 120);
    CAPTURE(r.out, r.err);
    CHECK(r.exit_code == 0);
    auto l = lines_of(r.out);
    REQUIRE(l.size() == 4);
    CHECK(l[0] == "inf");
    CHECK(l[2] == "error: none (the value is not a finite double)");
    CHECK(l[3] == "note: the true value, about 10^(4.34294481903e+199), overflows double");
  }
  SECTION("an intermediate overflow does not spoil a representable result") {
    Run r = run({"eval", src(kHard), "momentum_norm", "--at", "m1=1e160,m2=1e160,v1=3,v2=4"}, 120);
    CAPTURE(r.out, r.err);
    CHECK(lines_of(r.out).at(0) == "2.5");
    Run d = run({"eval", src(kHard), "momentum_norm", "--at", "m1=1e160,m2=1e160,v1=3,v2=4", "--method", "double"}, 120);
    CAPTURE(d.out);
    CHECK(lines_of(d.out).at(0) == "inf");
    CHECK(d.out.find("finite: this method overflowed") != std::string::npos);
  }
  SECTION("a declared symbol that cancelled is accepted") {
    Run r = run({"eval", src(kHard), "cancelled", "--at", "m=2,v=3"}, 120);
    CAPTURE(r.out, r.err);
    CHECK(r.exit_code == 0);
    CHECK(lines_of(r.out).at(0) == "3");
    Run bad = run({"eval", src(kHard), "cancelled", "--at", "m=-2,v=3"}, 120);
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("outside its declared domain") != std::string::npos);
  }
  SECTION("--digits keeps the reference output; --method reference too") {
    Run a = run({"eval", src(kHard), "restitution_loss", "--at", "e=1/2", "--digits", "10"}, 120);
    Run b = run({"eval", src(kHard), "restitution_loss", "--at", "e=1/2", "--method", "reference", "--digits", "10"}, 120);
    CHECK(a.out == "0.7500000000\n");
    CHECK(b.out == a.out);
  }
  SECTION("bad flags are input errors") {
    CHECK(run({"eval", src(kHard), "restitution_loss", "--at", "e=1/2", "--method", "quad"}, 120).exit_code == 2);
    CHECK(run({"eval", src(kHard), "restitution_loss", "--at", "e=1/2", "--method", "double", "--digits", "5"}, 120)
              .exit_code == 2);
  }
}

TEST_CASE("eval --points: one CSV row per point, a bad row does not stop the others", "[cli][eval]") {
  const std::string in = "derivcheck_eval_points_" + std::to_string(::getpid()) + ".csv";
  const std::string out = "derivcheck_eval_points_" + std::to_string(::getpid()) + ".out.csv";
  {
    std::ofstream f(in);
    f << "theta\n1e-8\n1/2\n-1\n3.1\n";
  }
  Run r = run({"eval", src(kHard), "one_minus_cos", "--points", in, "-o", out, "--method", "double"}, 300);
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 1);   // one row without a value
  std::ifstream f(out);
  std::stringstream ss;
  ss << f.rdbuf();
  auto l = lines_of(ss.str());
  CAPTURE(ss.str());
  REQUIRE(l.size() == 5);
  CHECK(l[0] == "theta,value,method,error_bound,note");
  CHECK(l[1].rfind("1e-8,0,double (the formula's tape),<= 8", 0) == 0);
  CHECK(l[2].rfind("1/2,0.1224174381096272", 0) == 0);   // ...24, within its bound of ...28
  CHECK(l[2].find(",double (the formula's tape),<= 3.1 ulps,") != std::string::npos);
  CHECK(l[3].rfind("-1,,,,\"error: parameter 'theta' = -1 is outside its declared domain", 0) == 0);
  CHECK(l[4].rfind("3.1,", 0) == 0);
  // refuses to overwrite its input
  Run same = run({"eval", src(kHard), "one_minus_cos", "--points", in, "-o", in}, 120);
  CHECK(same.exit_code == 2);
  std::remove(in.c_str());
  std::remove(out.c_str());
}
