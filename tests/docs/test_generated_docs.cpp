// Generated documentation must match what the code prints now: the handout map
// (docs/handout9.md) is regenerated and compared byte for byte.
#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {

std::string run(const std::string& cmd, int* status) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  REQUIRE(pipe);
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe.get())) > 0) out.append(buf.data(), n);
  *status = pclose(pipe.release());
  return out;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("docs/handout9.md is what 'derivcheck map' prints now", "[docs]") {
  const std::string src = DERIVCHECK_SOURCE_DIR;
  int status = 0;
  std::string generated = run(std::string("cd '") + src + "' && '" + DERIVCHECK_CLI +
                                  "' map derivations/handout9 --tests tests --title 'Handout 9' --ctest-prefix 'derivation: handout9/'",
                              &status);
  REQUIRE(status == 0);
  std::string committed = slurp(src + "/docs/handout9.md");
  INFO("regenerate with: build/derivcheck map derivations/handout9 --tests tests --title 'Handout 9' "
       "--ctest-prefix 'derivation: handout9/' -o docs/handout9.md");
  REQUIRE(generated == committed);
}

TEST_CASE("the handout map lists every tagged handout equation", "[docs]") {
  const std::string src = DERIVCHECK_SOURCE_DIR;
  std::string committed = slurp(src + "/docs/handout9.md");
  for (const char* tag : {"(9.1)", "(9.2)", "(9.3)", "(9.4)", "(9.5)", "(9.6)", "(9.7)"}) {
    CAPTURE(tag);
    CHECK(committed.find(tag) != std::string::npos);
  }
}

TEST_CASE("README's example output is what 'derivcheck check' prints now", "[docs]") {
  const std::string src = DERIVCHECK_SOURCE_DIR;
  int status = 0;
  std::string out = run(std::string("cd '") + src + "' && '" + DERIVCHECK_CLI + "' check docs/examples/quickstart.dc",
                        &status);
  CHECK(WEXITSTATUS(status) == 1);   // the example contains a refuted step on purpose
  std::string readme = slurp(src + "/README.md");
  std::string block = "```console\n$ derivcheck check docs/examples/quickstart.dc\n" + out + "```";
  INFO("regenerate with: tools/update-readme.sh build/derivcheck");
  REQUIRE(readme.find(block) != std::string::npos);
}
