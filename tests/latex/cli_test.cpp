// `derivcheck latex`: deterministic across processes, atomic output, exit 2 on bad input.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
int run(const std::string& args) {
  std::string cmd = std::string("'") + DERIVCHECK_CLI + "' latex " + args + " > /dev/null 2>&1";
  int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}
}  // namespace

TEST_CASE("derivcheck latex: byte-identical across runs, errors leave no output", "[latex][cli]") {
  REQUIRE(fs::exists(DERIVCHECK_CLI));
  fs::path dir = fs::temp_directory_path() / ("dc_latex_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string h9 = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9";

  SECTION("two processes, same bytes (plain and annotated)") {
    // the same name in two folders: the drawn figures' data files are named after the .tex
    fs::create_directories(dir / "a");
    fs::create_directories(dir / "b");
    for (std::string flags : {"", "--annotate", "--fragment"}) {
      REQUIRE(run("'" + h9 + "' " + flags + " -o '" + (dir / "a/h.tex").string() + "'") == 0);
      REQUIRE(run("'" + h9 + "' " + flags + " -o '" + (dir / "b/h.tex").string() + "'") == 0);
      CAPTURE(flags);
      std::string a = slurp(dir / "a/h.tex");
      CHECK(a.size() > 10000);
      CHECK(a == slurp(dir / "b/h.tex"));
    }
  }
  SECTION("an input error exits 2 and writes nothing") {
    fs::path bad = dir / "bad.dc";
    std::ofstream(bad) << "title \"bad\"\nsymbol x : real\nstep1: x = y\n    by given\n";
    fs::path out = dir / "out.tex";
    CHECK(run("'" + bad.string() + "' -o '" + out.string() + "'") == 2);
    CHECK_FALSE(fs::exists(out));
    // an existing output stays untouched
    std::ofstream(out) << "previous";
    CHECK(run("'" + h9 + "' '" + bad.string() + "' -o '" + out.string() + "'") == 2);
    CHECK(slurp(out) == "previous");
    CHECK(run("'" + (dir / "missing.dc").string() + "' -o '" + out.string() + "'") == 2);
    CHECK(slurp(out) == "previous");
  }
  SECTION("an unwritable output path exits 2") {
    CHECK(run("'" + h9 + "' -o '" + (dir / "no/such/dir/x.tex").string() + "'") == 2);
  }
  fs::remove_all(dir);
}
