// Budgets, worker processes, --jobs, --shard and merge (issue: never hang, never eat the
// machine). Runaway inputs from tests/data/runaway end with a verdict inside the budget, every
// other line of the run is still answered, and the output does not depend on the number of
// workers. The wall-clock `timeout` around each run only keeps a regression from hanging the
// suite; no test asserts a duration.
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"

using cli_test::run;
using cli_test::Run;
using cli_test::src;

namespace {

// The address-space limit the reproductions run under (3 GiB).
const std::string kUlimit = "ulimit -v 3145728; ";

std::vector<nlohmann::json> json_lines(const std::string& out) {
  std::vector<nlohmann::json> v;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) v.push_back(nlohmann::json::parse(line));
  return v;
}

std::string temp_path(const std::string& stem) {
  return "derivcheck_budget_" + stem + "_" + std::to_string(::getpid());
}

}  // namespace

#ifndef DERIVCHECK_SANITIZER   // RLIMIT_AS cannot work under AddressSanitizer
TEST_CASE("claims: runaway lines end inside their budget and every line is answered, in order",
          "[cli][budgets]") {
  Run r = run({"claims", src("tests/data/runaway/bank.jsonl"), "--no-timings"}, 300, kUlimit);
  CAPTURE(r.out, r.err);
  CHECK(r.err.find("internal error") == std::string::npos);
  CHECK((r.exit_code == 1 || r.exit_code == 3));
  auto results = json_lines(r.out);
  std::ifstream bank(src("tests/data/runaway/bank.jsonl"));
  std::vector<nlohmann::json> claims;
  for (std::string line; std::getline(bank, line);) claims.push_back(nlohmann::json::parse(line));
  REQUIRE(results.size() == claims.size());
  for (std::size_t i = 0; i < claims.size(); ++i) {
    CAPTURE(claims[i].dump(), results[i].dump());
    CHECK(results[i].at("id") == claims[i].at("id"));
    CHECK(results[i].at("line") == static_cast<int>(i + 1));
    std::string verdict = results[i].at("verdict");
    CHECK(verdict != "error");
    if (claims[i].value("false", false)) CHECK((verdict == "refuted" || verdict == "undecided"));
    if (verdict == "undecided" && results[i].at("method") == "budget")
      CHECK_THAT(results[i].at("reason").get<std::string>(), Catch::Matches("(time|memory) budget .* exceeded"));
  }
  // the plain claims around the runaway ones are decided as usual
  CHECK(results.front().at("verdict") == "proved");
  CHECK(results.back().at("verdict") == "proved");
}

TEST_CASE("equal and eval: runaways end with a verdict or a budget, never an internal error", "[cli][budgets]") {
  struct Case {
    std::vector<std::string> args;
    std::set<int> codes;
  };
  std::vector<Case> cases = {
      {{"equal", "exp(exp(exp(exp(x))))", "exp(exp(exp(exp(y))))", "--assume", "x>0, y>0"}, {1}},
      {{"equal", "exp(10^7)", "1"}, {1}},
      {{"equal", "exp(exp(20))", "1"}, {1}},
      {{"equal", "x^(10^30)", "x^(10^30)"}, {0}},
      {{"equal", "(a+b)^100000", "a^100000 + 100000*a^99999*b", "--assume", "a>0, b>0"}, {1}},
      {{"eval", src("tests/data/runaway/stress.dc"), "k", "--at", "x=30000000000000000000"}, {0, 3}},
  };
  for (const auto& c : cases) {
    Run r = run(c.args, 120, kUlimit);
    CAPTURE(c.args, r.out, r.err);
    CHECK(c.codes.count(r.exit_code) == 1);
    CHECK(r.err.find("internal error") == std::string::npos);
  }
}

TEST_CASE("memory budget: an allocation beyond it ends that computation as undecided, saying so",
          "[cli][budgets]") {
  // Expanding the nested definitions needs far more than 256 MiB long before 20 s of CPU. A
  // failed allocation ends the step as "memory budget exceeded" even where the code that
  // asked for the memory catches the failure.
  Run r = run({"check", src("tests/data/runaway/doubling.dc"), "--memory", "256M", "--step-timeout", "20s"}, 600);
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 3);
  CHECK(r.out.find("last rewrite \u2014 undecided (budget): memory budget 256 MiB exceeded") != std::string::npos);
  CHECK(r.out.find("failed") == std::string::npos);
}

TEST_CASE("eval: values far outside double's range are certified, never a wrong finite number", "[cli][eval]") {
  struct Case {
    std::string at, expect;
  };
  for (const auto& c : std::vector<Case>{{"x=3", "20.085536923187667741"},
                                         {"x=1e200", "10^(4.34294481903e+199)"},
                                         {"x=-1e200", "10^(-4.34294481903e+199)"},
                                         {"x=30000000000000000000", "10^(1.30288344571e+19)"},
                                         {"x=1e-300", "1.0000000000000000000"}}) {
    Run r = run({"eval", src("tests/data/runaway/stress.dc"), "k", "--at", c.at, "--digits", "20"}, 120);
    CAPTURE(c.at, r.out, r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.out == c.expect + "\n");
  }
}
TEST_CASE("eval --points: a row whose checks run away ends in its budget, the others are answered",
          "[cli][budgets]") {
  // the rows' first stage runs in chunks under the budget; a chunk that runs out hands each of
  // its rows to a task of its own, so only the runaway row is left without a value
  const std::string in = temp_path("points") + ".csv";
  {
    std::ofstream f(in);
    f << "x,y\n1.5,2\n1e99999,3\n0.1,0.3\n";
  }
  Run r = run({"eval", src("tests/data/runaway/points_assumption.dc"), "f", "--points", in, "--memory", "256M",
               "--step-timeout", "20"},
              300, kUlimit);
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("internal error") == std::string::npos);
  std::istringstream out(r.out);
  std::vector<std::string> l;
  for (std::string line; std::getline(out, line);) l.push_back(line);
  REQUIRE(l.size() == 4);
  CHECK(l[1].rfind("1.5,2,1.75,\"auto (correctly rounded: double-double", 0) == 0);
  CHECK(l[2].rfind("1e99999,3,,,,undecided: ", 0) == 0);
  CHECK(l[3].rfind("0.1,0.3,1.3333333333333333,\"auto (correctly rounded: double-double", 0) == 0);
  std::remove(in.c_str());
}
#endif

TEST_CASE("time budget: a step over it is undecided with the budget as the reason, the others are checked",
          "[cli][budgets]") {
  Run r = run({"check", src("tests/data/runaway/doubling.dc"), "--step-timeout", "300ms"}, 300);
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 3);
  CHECK(r.out.find("d0 definition \u2014 premise") != std::string::npos);
  CHECK(r.out.find("last rewrite \u2014 undecided (budget)") != std::string::npos);
  CHECK(r.out.find("time budget 0.3 s exceeded") != std::string::npos);
  CHECK(r.out.find("24 steps:") != std::string::npos);
}

TEST_CASE("crosscheck: a formula whose reference cannot be computed in budget is reported, not waited for",
          "[cli][budgets]") {
  Run r = run({"crosscheck", src("tests/data/runaway/stress.dc"), "--step-timeout", "500ms"}, 300);
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("p: not evaluated: ") != std::string::npos);
  CHECK(r.out.find("budget") != std::string::npos);
  // exp(2*1e160) is not a double: Arb says so at once, and those points are left out (the CLN
  // reference used to run out of budget there, or wrap its exponent silently)
  CHECK(r.out.find("f: not evaluated") == std::string::npos);
  CHECK(r.out.find("left out: the true value is not a finite double there") != std::string::npos);
}

TEST_CASE("budget flags: malformed values are input errors", "[cli][budgets][errors]") {
  for (const auto& bad : std::vector<std::vector<std::string>>{{"--step-timeout", "0"},
                                                               {"--step-timeout", "fast"},
                                                               {"--memory", "1k"},
                                                               {"--memory", "lots"},
                                                               {"--jobs", "-3"}}) {
    std::vector<std::string> args{"check", src("derivations/handout9/02_cannon.dc")};
    args.insert(args.end(), bad.begin(), bad.end());
    Run r = run(args, 60);
    CAPTURE(bad, r.out, r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("error") != std::string::npos);
  }
}

TEST_CASE("jobs: the report is byte-identical for any number of workers", "[cli][jobs]") {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"check", src("derivations/handout9")},
           {"check", src("derivations/handout9"), "--json"},
           {"check", src("tests/data/rules")},
           {"claims", src("tests/data/corpus.jsonl"), "--no-timings"},
           {"claims", src("tests/data/adversarial.jsonl"), "--no-timings"}}) {
    std::vector<std::string> one = args, three = args;
    one.insert(one.end(), {"--jobs", "1"});
    three.insert(three.end(), {"--jobs", "3"});
    Run a = run(one, 600), b = run(three, 600);
    CAPTURE(args);
    CHECK(a.exit_code == b.exit_code);
    CHECK(a.out == b.out);
    CHECK(!a.out.empty());
    CHECK(b.err.empty());   // no progress line when stderr is not a terminal
  }
}

TEST_CASE("shard and merge: the merged shards are byte-identical to one run", "[cli][shard]") {
  const std::string bank = src("tests/data/corpus.jsonl");
  Run whole = run({"claims", bank, "--no-timings"}, 600);
  std::vector<std::string> parts;
  for (int k = 1; k <= 4; ++k) {
    Run part = run({"claims", bank, "--no-timings", "--shard", std::to_string(k) + "/4"}, 600);
    CHECK(part.exit_code <= 3);
    parts.push_back(temp_path("shard" + std::to_string(k)));
    std::ofstream(parts.back()) << part.out;
  }
  Run merged = run({"merge", parts[2], parts[0], parts[3], parts[1]}, 60);
  CHECK(merged.out == whole.out);
  CHECK(merged.exit_code == whole.exit_code);
  // the same shard twice is an error, not a silently doubled line
  Run twice = run({"merge", parts[0], parts[0]}, 60);
  CHECK(twice.exit_code == 2);
  CHECK(twice.err.find("appears in more than one shard") != std::string::npos);
  for (const auto& p : parts) std::remove(p.c_str());
  for (const std::string bad : {"0/4", "5/4", "1/0", "2", "a/b"}) {
    Run r = run({"claims", bank, "--shard", bad}, 60);
    CAPTURE(bad);
    CHECK(r.exit_code == 2);
  }
}

TEST_CASE("GNU parallel recipe: sharded on localhost and merged equals one run", "[cli][shard][parallel]") {
  if (std::system("command -v parallel >/dev/null 2>&1") != 0) {
    WARN("GNU parallel is not installed (tools/install-deps.sh installs it); recipe not run");
    return;
  }
  const std::string bank = src("tests/data/adversarial.jsonl");
  Run whole = run({"claims", bank, "--no-timings"}, 600);
  std::string out = temp_path("parallel") + ".jsonl";
  std::string cmd = "DERIVCHECK=" + cli_test::quote(DERIVCHECK_CLI) + " bash " +
                    cli_test::quote(src("tools/cluster/claims-parallel.sh")) + " " + cli_test::quote(bank) + " 3 " +
                    out + " --jobs 2 > /dev/null 2>&1";
  int status = std::system(cmd.c_str());
  CHECK(WEXITSTATUS(status) == whole.exit_code);
  std::ifstream in(out);
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK(ss.str() == whole.out);
  std::remove(out.c_str());
}

TEST_CASE("Slurm array script: its shards, merged, equal one run", "[cli][shard][slurm]") {
  // No Slurm here: the array tasks are run one after another with the variables Slurm sets.
  const std::string bank = src("tests/data/corpus.jsonl");
  Run whole = run({"claims", bank, "--no-timings"}, 600);
  std::string dir = temp_path("slurm");
  for (int k = 1; k <= 3; ++k) {
    std::string cmd = "SLURM_ARRAY_TASK_ID=" + std::to_string(k) + " SLURM_ARRAY_TASK_COUNT=3 DERIVCHECK=" +
                      cli_test::quote(DERIVCHECK_CLI) + " bash " + cli_test::quote(src("tools/cluster/claims-slurm.sbatch")) +
                      " " + cli_test::quote(bank) + " " + dir;
    CHECK(std::system(cmd.c_str()) == 0);
  }
  Run merged = run({"merge", dir + "/shard-1.jsonl", dir + "/shard-2.jsonl", dir + "/shard-3.jsonl"}, 60);
  CHECK(merged.out == whole.out);
  CHECK(merged.exit_code == whole.exit_code);
  std::system(("rm -rf " + dir).c_str());
}

TEST_CASE("progress: shown on a terminal for a run longer than a second, erased at the end", "[cli][progress]") {
  // `script` needs a pseudo-terminal (/dev/pts); containers without one cannot run this test.
  if (std::system("script -qec true /dev/null >/dev/null 2>&1") != 0) {
    WARN("no pseudo-terminal available ('script' cannot run here); progress on a terminal not tested");
    return;
  }
  // `script` gives the command a terminal; its stdout goes to a file, so what `script` shows
  // is what the terminal would: stderr, the progress line.
  std::string out = temp_path("progress");
  std::string cmd = "script -qec " +
                    cli_test::quote(cli_test::quote(DERIVCHECK_CLI) + " check " +
                                    cli_test::quote(src("tests/data/runaway/doubling.dc")) +
                                    " --step-timeout 300ms --jobs 1 > " + out) +
                    " /dev/null";
  std::string shown;
  {
    FILE* p = popen(cmd.c_str(), "r");
    REQUIRE(p != nullptr);
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) shown.append(buf, n);
    pclose(p);
  }
  CAPTURE(shown);
  CHECK(shown.find("derivcheck: ") != std::string::npos);
  CHECK(shown.find(" steps, ") != std::string::npos);
  CHECK(shown.find("ETA") != std::string::npos);
  CHECK(shown.find("\r\033[K") != std::string::npos);   // erased line by line, and at the end
  std::ifstream report(out);
  std::stringstream ss;
  ss << report.rdbuf();
  CHECK(ss.str().find("24 steps:") != std::string::npos);
  CHECK(ss.str().find("ETA") == std::string::npos);   // the report itself has no progress
  std::remove(out.c_str());
}

// A file is read once, in a child process that then checks and reports (exec/read_once.hpp);
// a reading that runs away costs that file only: the supervisor starts a new reader that skips
// it, and every other file, before and after it, is still read and checked.
TEST_CASE("time budget: a file whose reading runs away is an input error, the files around it are checked",
          "[cli][budgets]") {
  const std::string slow = src("tests/data/runaway/slow_read.dc");
  const std::string before = src("derivations/handout9/01_momentum_particle.dc");
  const std::string after = src("derivations/handout9/02_cannon.dc");
  Run r = run({"check", before, slow, after, "--step-timeout", "300ms"}, 300);
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 2);
  const std::string all = r.out + r.err;
  CHECK(all.find("slow_read.dc: error: reading this file did not finish: time budget 0.3 s exceeded; it was not "
                 "checked") != std::string::npos);
  CHECK(all.find("01_momentum_particle.dc:") != std::string::npos);
  CHECK(all.find("02_cannon.dc:") != std::string::npos);
  CHECK(all.find("1 file with input errors") != std::string::npos);
  CHECK(all.find(" 0 refuted") != std::string::npos);
  // every step line of the two readable files is what they give without the slow one
  Run two = run({"check", before, after, "--step-timeout", "300ms"}, 300);
  REQUIRE(two.exit_code == 0);
  const auto lines = cli_test::lines_of(two.out);
  REQUIRE(lines.size() > 10);
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    CAPTURE(lines[i]);
    CHECK(r.out.find(lines[i] + "\n") != std::string::npos);
  }
}
