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

TEST_CASE("eval --points auto: every row as eval --at gives it, in file order, whichever stage answers", "[cli][eval]") {
  // the first stage runs for all rows in the parent, the rest in workers: rows decided by
  // double-double (exact doubles and decimals), rows for long double (momenta of 1e160), for Arb
  // (a cancellation at an inexact decimal), rows outside the domain, malformed values and rows
  // with the wrong number of cells must come out exactly as `eval --at` says, in order
  const std::string in = "derivcheck_eval_auto_" + std::to_string(::getpid()) + ".csv";
  const std::string out = "derivcheck_eval_auto_" + std::to_string(::getpid()) + ".out.csv";
  const std::vector<std::string> rows = {"2,3,0.5,-0.25",  "1e160,1e160,3,4", "2.1,3.3,1.7,-0.3", "-1,2,3,4",
                                         "1,2,x,4",        "1,2,3",           "1e-170,1e-170,3,4", "0.1,0.2,0.3,0.4"};
  {
    std::ofstream f(in);
    f << "m1,m2,v1,v2\n";
    for (const auto& r : rows) f << r << "\n";
  }
  Run r = run({"eval", src(kHard), "momentum_norm", "--points", in, "-o", out, "--jobs", "2"}, 300);
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 1);   // rows without a value
  std::ifstream f(out);
  std::stringstream ss;
  ss << f.rdbuf();
  const auto l = lines_of(ss.str());
  CAPTURE(ss.str());
  REQUIRE(l.size() == rows.size() + 1);
  const char* names[] = {"m1", "m2", "v1", "v2"};
  int first_stage = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    INFO("row " << rows[i]);
    std::vector<std::string> cells;
    std::stringstream rs(rows[i]);
    for (std::string c; std::getline(rs, c, ',');) cells.push_back(c);
    if (cells.size() != 4) {
      CHECK(l[i + 1].find("error: 3 values for 4 columns") != std::string::npos);
      continue;
    }
    std::string at;
    for (std::size_t j = 0; j < 4; ++j) at += (j ? "," : "") + std::string(names[j]) + "=" + cells[j];
    Run one = run({"eval", src(kHard), "momentum_norm", "--at", at}, 120);
    const auto o = lines_of(one.out);
    if (one.exit_code != 0) {
      CHECK(l[i + 1].find(",,,,") != std::string::npos);
      CHECK(l[i + 1].find("error: ") != std::string::npos);
      continue;
    }
    REQUIRE(o.size() >= 3);
    // value, method and bound as the single-point command prints them
    auto field = [](const std::string& t) { return t.find(',') == std::string::npos ? t : "\"" + t + "\""; };
    CHECK(l[i + 1] == rows[i] + "," + o[0] + "," + field(o[1].substr(8)) + "," + field(o[2].substr(7)) + ",");
    first_stage += o[1].find("double-double") != std::string::npos ? 1 : 0;
  }
  CHECK(first_stage >= 3);
  CHECK(ss.str().find("long double with a running error bound") != std::string::npos);
  std::remove(in.c_str());
  std::remove(out.c_str());
}
