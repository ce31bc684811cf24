// `derivcheck simulate` end to end: exit codes, the comparison table, CSV written.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include <catch2/catch.hpp>

#include <unistd.h>

using Catch::Matchers::Contains;

namespace {

struct Run {
  int code;
  std::string out, err;
};

Run simulate(const std::string& args) {
  REQUIRE(std::filesystem::exists(DERIVCHECK_CLI));  // build the derivcheck target first
  const auto dir = std::filesystem::temp_directory_path();
  // ctest runs test cases as parallel processes: the pid keeps their files apart.
  const std::string tag = std::to_string(::getpid());
  const std::string out = (dir / ("dc_sim_out_" + tag + ".txt")).string(), err = (dir / ("dc_sim_err_" + tag + ".txt")).string();
  const std::string cmd = std::string("cd ") + DERIVCHECK_SOURCE_DIR + " && " + DERIVCHECK_CLI + " simulate " + args +
                          " >" + out + " 2>" + err;
  const int status = std::system(cmd.c_str());
  auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

}  // namespace

TEST_CASE("simulate: every scene runs from the command line and agrees with its closed forms", "[scenes][cli]") {
  for (const char* s : {"spring", "pendulum", "rocket", "chain", "ladder", "cradle", "cannon", "impact", "oblique"}) {
    CAPTURE(s);
    const Run r = simulate(std::string(s) + " --max-rel-error 1e-8");
    CHECK(r.code == 0);
    CHECK_THAT(r.out, Contains("rel.error"));
  }
  // the bounce's default 1 mm separation is physics, not error: it fails a tight bound ...
  CHECK(simulate("bounce --max-rel-error 1e-8").code == 1);
  // ... and passes at zero separation
  CHECK(simulate("bounce --set s=0 --max-rel-error 1e-13").code == 0);
  const Run derived = simulate("pendulum");
  CHECK_THAT(derived.out, Contains("[06_ballistic_pendulum.dc:deflection]"));
}

TEST_CASE("simulate: bad input exits 2 naming the parameter, value and bound", "[scenes][cli]") {
  Run r = simulate("spring --set m1=-1");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("m1 = -1 kg") && Contains("m1 > 0"));
  r = simulate("spring --step 0");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("step h = 0 s"));
  r = simulate("spring --method dopri5 --tol -1");
  CHECK(r.code == 2);
  r = simulate("nosuchscene");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("unknown scene"));
  r = simulate("ladder --method verlet");
  CHECK(r.code == 2);
  r = simulate("spring --set k=abc");
  CHECK(r.code == 2);
}

TEST_CASE("simulate: --list, --describe and --csv", "[scenes][cli]") {
  CHECK_THAT(simulate("--list").out, Contains("spring") && Contains("ladder") && Contains("cannon"));
  const Run d = simulate("chain --describe");
  CHECK_THAT(d.out, Contains("x'' = g") && Contains("[kg]") && Contains("0 <= x <= L"));
  const auto csv = (std::filesystem::temp_directory_path() / ("dc_sim_chain_" + std::to_string(::getpid()) + ".csv")).string();
  std::filesystem::remove(csv);
  REQUIRE(simulate("chain --csv " + csv).code == 0);
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  CHECK(header == "t,x,v,N,N_closed_form");
}
