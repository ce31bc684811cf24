// CLI behaviour of `derivcheck check | equal | claims`: exit codes, GCC-style errors on bad
// input, and byte-identical output across two processes (GiNaC's print order changes per
// process, so this catches any leak of it). Runs the built binary DERIVCHECK_CLI.
#include "cli/cli_run.hpp"

#include <filesystem>

using cli_test::run;
using cli_test::Run;
using cli_test::src;

TEST_CASE("check: exit codes", "[cli][check]") {
  struct Case {
    const char* file;
    int exit_code;
  };
  auto c = GENERATE(values<Case>({
      {"tests/data/cli/all_hold.dc", 0},
      {"tests/data/cli/refuted.dc", 1},
      {"tests/data/cli/dimension.dc", 1},
      {"tests/data/cli/undecided.dc", 3},
      {"tests/data/cli/erratum.dc", 0},
      {"tests/data/errors/unknown_rule.dc", 2},
      {"tests/data/errors/does_not_exist.dc", 2},
  }));
  CAPTURE(c.file);
  Run r = run({"check", src(c.file)});
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == c.exit_code);
  CHECK(r.out.find(" steps: ") != std::string::npos);
}

TEST_CASE("check --strict fails on reported errata", "[cli][check]") {
  CHECK(run({"check", "--strict", src("tests/data/cli/erratum.dc")}).exit_code == 1);
}

TEST_CASE("check prints one line per step with position, mark, label, tag, rule and verdict", "[cli][check]") {
  Run r = run({"check", src("tests/data/cli/refuted.dc")});
  std::string f = src("tests/data/cli/refuted.dc");
  CAPTURE(r.out);
  CHECK(r.out.find(f + ":5:7: \u2022 momentum (9.6) given \u2014 premise (symbols and dimensions checked)\n") != std::string::npos);
  CHECK(r.out.find(f + ":9:1: \u2717 v1p_wrong solve \u2014 refuted") != std::string::npos);
  CHECK(r.out.find("    counterexample: m1 = ") != std::string::npos);
  CHECK(r.out.find("    left side = ") != std::string::npos);
  CHECK(r.out.find("3 steps: 2 premises, 0 proved, 0 hold numerically, 1 refuted, 0 undecided, 0 errors (0 errata reported)\n") !=
        std::string::npos);
  CHECK(r.out.find(" ms]") == std::string::npos);   // no times without --timings
  Run t = run({"check", "--timings", f});
  CHECK(t.out.find(" ms]") != std::string::npos);
}

TEST_CASE("check: an input error is GCC style with the line and a caret", "[cli][check][errors]") {
  std::string f = src("tests/data/errors/undefined_symbol.dc");
  Run r = run({"check", f});
  CHECK(r.exit_code == 2);
  CHECK(r.out.find(f + ":2:8: error: undefined symbol 'y'") != std::string::npos);
  CHECK(r.out.find("    a: x = y + 1\n           ^\n") != std::string::npos);
}

TEST_CASE("check: runaway input is refused quickly with a positioned error", "[cli][check][errors]") {
  auto f = GENERATE(as<std::string>{}, "huge_power", "expand_call");
  Run r = run({"check", src("tests/data/errors/" + f + ".dc")});
  CHECK(r.exit_code == 2);
  CHECK(r.out.find(":2:") != std::string::npos);
  CHECK(r.out.find("error: ") != std::string::npos);
}

TEST_CASE("check: a directory means its .dc files in sorted order", "[cli][check]") {
  Run r = run({"check", src("tests/data/rules")});
  CAPTURE(r.out);
  auto a = r.out.find("rules/definition.dc:");
  auto b = r.out.find("rules/differentiate.dc:");
  auto c = r.out.find("rules/solves_ode.dc:");
  REQUIRE(a != std::string::npos);
  REQUIRE(b != std::string::npos);
  REQUIRE(c != std::string::npos);
  CHECK(a < b);
  CHECK(b < c);
  CHECK(r.exit_code == 1);   // the fixtures contain refuted bad_* steps
}

TEST_CASE("check --json carries the same content with a stable key order", "[cli][check][json]") {
  Run r = run({"check", "--json", src("tests/data/cli/refuted.dc")});
  CHECK(r.exit_code == 1);
  CHECK(r.out.rfind("{\n  \"files\": [\n    {\n      \"file\": ", 0) == 0);
  CHECK(r.out.find("\"verdict\": \"refuted\"") != std::string::npos);
  CHECK(r.out.find("\"counterexample\": {") != std::string::npos);
  CHECK(r.out.find("\"exit_code\": 1") != std::string::npos);
  CHECK(r.out.find("\"seconds\"") == std::string::npos);
}

TEST_CASE("output is byte-identical across two processes", "[cli][determinism]") {
  std::vector<std::vector<std::string>> commands = {
      {"check", src("tests/data/rules"), src("tests/data/cli")},
      {"check", "--json", src("tests/data/rules"), src("tests/data/cli")},
      {"claims", "--no-timings", src("tests/data/corpus.jsonl")},
      {"equal", "sqrt(x^2)", "x", "--assume", "x real"},
  };
  if (std::ifstream(src("derivations/handout9/05_direct_impact.dc"))) {
    commands.push_back({"check", src("derivations/handout9")});
    commands.push_back({"check", "--json", src("derivations/handout9")});
  }
  for (const auto& cmd : commands) {
    CAPTURE(cmd);
    Run a = run(cmd), b = run(cmd);
    CHECK(a.out.size() > 0);
    CHECK(a.out == b.out);
    CHECK(a.exit_code == b.exit_code);
  }
}

TEST_CASE("equal: verdicts and exit codes", "[cli][equal]") {
  CHECK(run({"equal", "sqrt(x^2)", "x", "--assume", "x>0"}).exit_code == 0);
  Run r = run({"equal", "sqrt(x^2)", "x", "--assume", "x real"});
  CHECK(r.exit_code == 1);
  CHECK(r.out.rfind("refuted", 0) == 0);
  CHECK(r.out.find("counterexample: x = -") != std::string::npos);
  CHECK(run({"equal", "log(a*b)", "log(a)+log(b)", "--assume", "a>0, b>0"}).exit_code == 0);
  CHECK(run({"equal", "exp(pi*sqrt(163))", "640320^3+744"}).exit_code == 1);
}

TEST_CASE("equal: a limit the helper cannot evaluate is undecided, not a crash", "[cli][equal]") {
  Run r = run({"equal", "limit(sin(1/x), x, 0)", "0"});
  CHECK(r.exit_code == 3);
  CHECK(r.out.rfind("undecided (limit)", 0) == 0);
  CHECK(r.out.find("::") == std::string::npos);   // no GiNaC-internal names such as power::eval()
  CHECK(r.err.empty());
  CHECK(run({"equal", "limit(sin(x)/x, x, 0)", "1"}).exit_code == 0);
}

TEST_CASE("equal: malformed input is an error on stderr with exit 2", "[cli][equal][errors]") {
  Run a = run({"equal", "x +", "x"});
  CHECK(a.exit_code == 2);
  CHECK(a.err.rfind("<lhs>:1:4: error: ", 0) == 0);
  Run b = run({"equal", "x", "x", "--assume", "x > 0, x < 0"});
  CHECK(b.exit_code == 2);
  CHECK(b.err.rfind("<assume>:1:8: error: conflicting assumptions for 'x'", 0) == 0);
  Run c = run({"equal", "x", "x", "--assume", "x > y, y > x"});
  CHECK(c.exit_code == 2);
  CHECK(c.err.find("cannot all hold") != std::string::npos);
  Run d = run({"equal", "2^(10^10)", "1"});
  CHECK(d.exit_code == 2);
  CHECK(d.err.rfind("<lhs>:1:", 0) == 0);
  // one argument may hold at most 128 KiB (MAX_ARG_STRLEN); 10^5 deep is tested on the library
  std::string deep = std::string(30000, '(') + "x" + std::string(30000, ')');
  Run e = run({"equal", deep, "x"});
  CHECK(e.exit_code == 2);
  CHECK(e.err.rfind("<lhs>:1:", 0) == 0);
  CHECK(e.err.size() < 2000);
}

TEST_CASE("claims: one JSON result per line, a malformed line does not stop the rest", "[cli][claims]") {
  Run r = run({"claims", "--no-timings", src("tests/data/cli/bank.jsonl")});
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 2);
  std::istringstream in(r.out);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  REQUIRE(lines.size() == 4);
  CHECK(lines[0] == "{\"id\":\"c7\",\"line\":1,\"kind\":\"equal\",\"verdict\":\"proved\",\"method\":\"identity + normal\","
                    "\"detail\":\"normal(lhs - rhs) = 0\",\"side_conditions\":[{\"condition\":\"m1 + m2 != 0\","
                    "\"reason\":\"divisor\",\"status\":\"guaranteed\",\"evidence\":\"follows from the domains: m1 "
                    "positive, m2 positive\"}]}");
  CHECK(lines[1].find("\"line\":2,\"verdict\":\"error\"") != std::string::npos);
  CHECK(lines[1].find("bank.jsonl:2: error: malformed JSON") != std::string::npos);
  CHECK(lines[2].find("\"id\":\"c9\"") != std::string::npos);
  CHECK(lines[2].find("\"verdict\":\"refuted\"") != std::string::npos);
  CHECK(lines[3].find("\"id\":\"c10\"") != std::string::npos);
  CHECK(lines[3].find("\"verdict\":\"proved\"") != std::string::npos);
  Run t = run({"claims", src("tests/data/cli/bank.jsonl")});
  CHECK(t.out.find("\"seconds\":") != std::string::npos);
}

TEST_CASE("claims: a missing file is an input error", "[cli][claims][errors]") {
  Run r = run({"claims", src("tests/data/cli/nope.jsonl")});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("cannot read") != std::string::npos);
}

TEST_CASE("equal: expressions may start with a minus", "[cli][equal]") {
  Run a = run({"equal", "x", "-x"});
  CHECK(a.exit_code == 1);
  CHECK(a.out.rfind("refuted", 0) == 0);
  Run b = run({"equal", "-a", "-a", "--json"});
  CHECK(b.exit_code == 0);
  CHECK(b.out.find("\"verdict\": \"proved\"") != std::string::npos);
  Run c = run({"equal", "-(x-1)", "1-x", "--assume", "-x > 0"});
  CHECK(c.exit_code == 0);
  Run d = run({"equal", "x", "-y", "--bogus"});
  CHECK(d.exit_code == 2);
  CHECK(d.err.find("--bogus") != std::string::npos);
}

TEST_CASE("latex: a derivation with a step that does not hold is not emitted unless asked", "[cli][latex]") {
  std::string out = "derivcheck_latex_refused_" + std::to_string(::getpid()) + ".tex";
  Run r = run({"latex", src("tests/data/cli/refuted.dc"), "-o", out});
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("refuted.dc:9:1: step 'v1p_wrong' is refuted") != std::string::npos);
  CHECK(!std::ifstream(out).good());
  Run a = run({"latex", src("tests/data/cli/refuted.dc"), "-o", out, "--allow-unchecked"});
  CHECK(a.exit_code == 0);
  std::ifstream in(out);
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK(ss.str().find("NOT CHECKED: refuted") != std::string::npos);
  std::remove(out.c_str());
  // the handout's reported erratum does not block it
  Run h = run({"latex", src("derivations/handout9"), "-o", "-"});
  CHECK(h.exit_code == 0);
  CHECK(h.out.find("NOT CHECKED") == std::string::npos);
}

TEST_CASE("map: a user's files are mapped under their own name, with no invented tests", "[cli][map]") {
  Run r = run({"map", src("tests/data/cli/refuted.dc")});
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("Handout 9") == std::string::npos);
  CHECK(r.out.find("ctest") == std::string::npos);
  CHECK(r.out.find("# Derivation map: ") == 0);
  CHECK(r.out.find("3 steps in 1 file.") != std::string::npos);
}

TEST_CASE("chart: without -o the charts go to a new directory, never over earlier ones", "[cli][chart]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("dc_chart_out_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string cd = "cd " + cli_test::quote(dir.string()) + " && ";
  const auto first = cli_test::run({"chart", "checker", "--root", cli_test::src(""), "--repeats", "1"}, 120, cd);
  REQUIRE(first.exit_code == 0);
  CHECK(first.out.find("wrote derivcheck-charts/wp_checker.csv") != std::string::npos);
  CHECK(fs::exists(dir / "derivcheck-charts" / "wp_checker.csv"));
  const auto before = fs::last_write_time(dir / "derivcheck-charts" / "wp_checker.csv");
  const auto second = cli_test::run({"chart", "checker", "--root", cli_test::src(""), "--repeats", "1"}, 120, cd);
  REQUIRE(second.exit_code == 0);
  CHECK(fs::exists(dir / "derivcheck-charts-2" / "wp_checker.csv"));
  CHECK(fs::last_write_time(dir / "derivcheck-charts" / "wp_checker.csv") == before);
  // -o names the directory (created with its parents)
  const auto named = cli_test::run({"chart", "checker", "--root", cli_test::src(""), "--repeats", "1", "-o", "a/b"}, 120, cd);
  REQUIRE(named.exit_code == 0);
  CHECK(fs::exists(dir / "a" / "b" / "wp_checker.csv"));
  CHECK_FALSE(fs::exists(dir / "derivcheck-charts-3"));
  fs::remove_all(dir);
}
