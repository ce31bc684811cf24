// Runs the built derivcheck binary (DERIVCHECK_CLI) for the tests of tests/cli: its exit code,
// stdout and stderr. ctest runs test cases as parallel processes, so every temporary name
// carries the pid.
#pragma once
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cli_test {

inline std::string src(const std::string& rel) { return std::string(DERIVCHECK_SOURCE_DIR) + "/" + rel; }

inline std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

struct Run {
  int exit_code = -1;
  std::string out;   // stdout
  std::string err;   // stderr
};

// `timeout_s` > 0 runs the binary under coreutils timeout (exit 124 if it had to stop it), so
// a test of something that must not block cannot hang the suite.
// `shell_prefix` runs before the binary in the same shell (e.g. "ulimit -v 3145728;").
inline Run run(const std::vector<std::string>& args, int timeout_s = 0, const std::string& shell_prefix = "") {
  static int counter = 0;
  std::string errfile = "derivcheck_cli_test_stderr_";
  errfile.append(std::to_string(::getpid())).append("_").append(std::to_string(++counter)).append(".txt");
  std::string cmd = shell_prefix;
  if (timeout_s > 0) cmd.append("timeout ").append(std::to_string(timeout_s)).append(" ");
  cmd += quote(DERIVCHECK_CLI);
  for (const auto& a : args) cmd.append(" ").append(quote(a));
  cmd += " 2>" + errfile;
  Run r;
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(errfile);
  std::stringstream ss;
  ss << e.rdbuf();
  r.err = ss.str();
  std::remove(errfile.c_str());
  return r;
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace cli_test
