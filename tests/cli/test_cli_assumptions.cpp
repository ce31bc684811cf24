// CLI behaviour of assumptions (issue 8, item 7): a constant-false assumption is an input error
// at its position (exit 2) in `equal --assume`, in .dc files and in claims lines; satisfiable
// assumptions with large values are accepted. Runs the built binary DERIVCHECK_CLI.
#include <catch2/catch.hpp>

#include <cmath>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"

using namespace cli_test;

TEST_CASE("equal --assume: a constant-false assumption is exit 2 at its position", "[cli][assumptions]") {
  struct Case {
    const char* assume;
    const char* prefix;
  };
  auto c = GENERATE(values<Case>({
      {"x > x", "<assume>:1:1: error: the assumption 'x > x' can never hold"},
      {"1 > 2", "<assume>:1:1: error: the assumption '1 > 2' can never hold"},
      {"x != x", "<assume>:1:1: error: the assumption 'x != x' can never hold"},
      {"y > 0, x < x - 1", "<assume>:1:8: error: the assumption 'x < x - 1' can never hold"},
  }));
  Run r = run({"equal", "x", "x", "--assume", c.assume});
  CAPTURE(c.assume, r.out, r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.rfind(c.prefix, 0) == 0);
  CHECK(r.err.find('^') != std::string::npos);
}

TEST_CASE("equal --assume: constant-true and large-value assumptions are accepted", "[cli][assumptions]") {
  CHECK(run({"equal", "x", "x", "--assume", "x >= x"}).exit_code == 0);
  Run big = run({"equal", "sqrt(x^2)", "x", "--assume", "x > 1000000"});
  CAPTURE(big.out, big.err);
  CHECK(big.exit_code != 2);   // satisfiable: never "never holds"
  CHECK(big.exit_code != 1);   // true: never refuted
  Run imp = run({"equal", "x", "x", "--assume", "x > 5, x < 3"});
  CHECK(imp.exit_code == 2);
  CHECK(imp.err.find("cannot all hold") != std::string::npos);
}

TEST_CASE("check: a constant-false assume in a .dc file is exit 2 at its position", "[cli][assumptions]") {
  Run r = run({"check", src("tests/data/errors/assume_never.dc")});
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 2);
  std::string all = r.out + r.err;
  CHECK(all.find("assume_never.dc:3:8: error: the assumption 'x > x' can never hold") != std::string::npos);
}

TEST_CASE("claims: a constant-false assume gives that line an error verdict, the others are checked",
          "[cli][assumptions]") {
  std::string file = "derivcheck_cli_assume_" + std::to_string(::getpid()) + ".jsonl";
  {
    std::ofstream f(file);
    f << R"J({"id":"never","kind":"equal","lhs":"x","rhs":"x","assume":"x > x"})J" << "\n";
    f << R"J({"id":"fine","kind":"equal","lhs":"abs(x - y)","rhs":"x - y","assume":"x > y"})J" << "\n";
  }
  Run r = run({"claims", file, "--no-timings"});
  std::remove(file.c_str());
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 2);
  std::istringstream lines(r.out);
  std::string never, fine;
  std::getline(lines, never);
  std::getline(lines, fine);
  CHECK(never.rfind(R"({"id":"never",)", 0) == 0);
  CHECK(never.find(R"("verdict":"error")") != std::string::npos);
  CHECK(never.find("in field 'assume' (column 1): the assumption 'x > x' can never hold") != std::string::npos);
  CHECK(fine.rfind(R"({"id":"fine",)", 0) == 0);
  CHECK((fine.find(R"("verdict":"proved")") != std::string::npos ||
         fine.find(R"("verdict":"holds_numerically")") != std::string::npos));
}

TEST_CASE("a malformed assumption is exit 2 at its bracket, never dropped", "[cli][assumptions]") {
  // Dropping `x in [0,1` would check the claim for every real x and refute it outside [0, 1].
  struct Case {
    const char* assume;
    const char* prefix;
  };
  auto c = GENERATE(values<Case>({
      {"x in [0,1", "<assume>:1:6: error: unclosed '['"},
      {"x > 0, y in (0, 2", "<assume>:1:13: error: unclosed '('"},
      {"x in 0, 1]", "<assume>:1:10: error: unmatched ']'"},
      {"x > 0)", "<assume>:1:6: error: unmatched ')'"},
  }));
  Run r = run({"equal", "sqrt(x^2)", "x", "--assume", c.assume});
  CAPTURE(c.assume, r.out, r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.out.empty());
  CHECK(r.err.rfind(c.prefix, 0) == 0);
  CHECK(r.err.find('^') != std::string::npos);
}

TEST_CASE("a malformed assumption in a claim line is that line's error, the other lines are checked",
          "[cli][assumptions]") {
  std::string file = "derivcheck_cli_malformed_assume_" + std::to_string(::getpid()) + ".jsonl";
  {
    std::ofstream f(file);
    f << R"J({"kind":"equal","lhs":"sqrt(x^2)","rhs":"x","assume":"x in [0,1"})J" << "\n";
    f << R"J({"kind":"equal","lhs":"sqrt(x^2)","rhs":"x","assume":"x in [0,1]"})J" << "\n";
  }
  Run r = run({"claims", file, "--no-timings"});
  std::remove(file.c_str());
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 2);
  const auto lines = lines_of(r.out);
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].find("\"verdict\":\"error\"") != std::string::npos);
  CHECK(lines[0].find("unclosed '['") != std::string::npos);
  CHECK((lines[1].find("\"verdict\":\"proved\"") != std::string::npos ||
         lines[1].find("\"verdict\":\"holds_numerically\"") != std::string::npos));
}

TEST_CASE("a refutation reports a point of ordinary size when one refutes", "[cli][assumptions][evidence]") {
  // Without a preference the first certified point had m ~ 1e-10, where both sides agree to
  // fourteen digits: true evidence that tells the reader nothing.
  auto c = GENERATE(values<std::vector<std::string>>({
      {"3*m*v0*b/(M*L^2)", "3*m*v0*b/(M*L^2 + 3*m*b^2)", "m>0, M>0, L>0, b>0, v0>0, b <= L"},
      {"x/(x + y)", "x/(x + 2*y)", "x > 0, y > 0, y < x"},
      {"sqrt(a^2 + b^2)", "a + b", "a > 0, b > 0, a <= 2*b"},
  }));
  Run r = run({"equal", c[0], c[1], "--assume", c[2], "--json"});
  CAPTURE(c[0], c[1], c[2], r.out, r.err);
  REQUIRE(r.exit_code == 1);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j.contains("counterexample"));
  for (const auto& [name, value] : j["counterexample"].items()) {
    const std::string t = value.get<std::string>();
    const auto slash = t.find('/');
    const double x = slash == std::string::npos ? std::stod(t) : std::stod(t.substr(0, slash)) / std::stod(t.substr(slash + 1));
    CAPTURE(name, t);
    CHECK((x == 0 || (std::abs(x) >= 1e-2 && std::abs(x) <= 1e2)));
  }
}

TEST_CASE("claims: units on a line make a dimension mismatch the first evidence", "[cli][claims][units]") {
  std::string file = "derivcheck_cli_units_" + std::to_string(::getpid()) + ".jsonl";
  {
    std::ofstream f(file);
    // a student's answer with a stray h: m/s against m^2/s
    f << R"J({"id":"wrong","kind":"equal","lhs":"v","rhs":"sqrt(2*g*h)*h","assume":"g > 0, h > 0","units":{"v":"m/s","g":"m/s^2","h":"m"}})J" << "\n";
    f << R"J({"id":"right","kind":"equal","lhs":"sqrt(2*g*h)^2","rhs":"2*g*h","assume":"g > 0, h > 0","units":{"g":"m/s^2","h":"m"}})J" << "\n";
    f << R"J({"id":"partial","kind":"equal","lhs":"v","rhs":"2*v","units":{"g":"m/s^2"}})J" << "\n";
    f << R"J({"id":"anti","kind":"antiderivative","lhs":"F0*t","rhs":"F0*t^2/2","var":"t","units":{"F0":"N/s","t":"s"}})J" << "\n";
    f << R"J({"id":"anti_wrong","kind":"antiderivative","lhs":"F0*t","rhs":"F0*t","var":"t","units":{"F0":"N/s","t":"s"}})J" << "\n";
    f << R"J({"id":"bad_unit","kind":"equal","lhs":"v","rhs":"v","units":{"v":"furlong"}})J" << "\n";
    f << R"J({"id":"no_units","kind":"equal","lhs":"v","rhs":"2*v"})J" << "\n";
  }
  Run r = run({"claims", file, "--no-timings"});
  std::remove(file.c_str());
  CAPTURE(r.out, r.err);
  const auto lines = lines_of(r.out);
  REQUIRE(lines.size() == 7);
  std::vector<nlohmann::json> j;
  for (const auto& l : lines) j.push_back(nlohmann::json::parse(l));
  CHECK(j[0]["verdict"] == "refuted");
  CHECK(j[0]["dimensions"] == "dimensions differ: lhs is m/s, rhs is m²/s");
  CHECK(j[0]["detail"].get<std::string>().rfind("dimensions differ", 0) == 0);
  CHECK(j[1]["verdict"] == "proved");
  CHECK_FALSE(j[1].contains("dimensions"));
  CHECK(j[2]["dimensions"] == "dimensions not checked: no unit for v");
  CHECK(j[3]["verdict"] == "proved");
  CHECK_FALSE(j[3].contains("dimensions"));
  CHECK(j[4]["verdict"] == "refuted");
  CHECK(j[4]["dimensions"].get<std::string>().find("dimensions differ: rhs is") == 0);
  CHECK(j[5]["verdict"] == "error");
  CHECK(j[5]["error"].get<std::string>().find("unit of 'v'") != std::string::npos);
  CHECK_FALSE(j[6].contains("dimensions"));
}

TEST_CASE("equal --assume 'n integer' and degrees: the CLI path", "[cli][assumptions][integer][angles]") {
  Run p = run({"equal", "sin(n*pi)", "0", "--assume", "n integer"});
  CAPTURE(p.out, p.err);
  CHECK(p.exit_code == 0);
  CHECK(p.out.rfind("proved (identity + integer periods + normal)", 0) == 0);
  Run f = run({"equal", "cos(n*pi)", "1", "--assume", "n positive integer"});
  CAPTURE(f.out);
  CHECK(f.exit_code == 1);
  CHECK(f.out.rfind("refuted", 0) == 0);
  Run real = run({"equal", "sin(n*pi)", "0"});
  CHECK(real.exit_code == 1);
  Run merged = run({"equal", "cos(2*n*pi)", "1", "--assume", "n > 0, n integer"});
  CHECK(merged.exit_code == 0);
  Run none = run({"equal", "n", "n", "--assume", "n integer, n in (0, 1)"});
  CAPTURE(none.err);
  CHECK(none.exit_code == 2);
  CHECK(none.err.find("leave no integer") != std::string::npos);
  Run deg = run({"equal", "sin(30°)", "1/2"});
  CAPTURE(deg.out, deg.err);
  CHECK(deg.exit_code == 0);
  Run deg2 = run({"equal", "sin(30*deg)", "1/2"});
  CHECK(deg2.exit_code == 0);
}
