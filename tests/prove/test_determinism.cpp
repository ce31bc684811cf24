// The same claims give byte-identical verdict text in one process and across processes
// (GiNaC's internal order changes between processes with the address layout).
#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

#include "derivations/decide/prove.hpp"
#include "support.hpp"

using namespace dc;
using GiNaC::ex;

namespace {

std::string all_verdicts() {
  test::Table T;
  T.add("m1", Domain::positive()).add("m2", Domain::positive()).add("v1", Domain::real()).add("v2", Domain::real())
      .add("e", test::unit_interval()).add("x", Domain::real()).add("z", Domain::interval(-1, false, 0, true));
  ex m1 = T["m1"], m2 = T["m2"], v1 = T["v1"], v2 = T["v2"], e = T["e"], x = T["x"], z = T["z"];
  std::vector<std::pair<ex, ex>> claims = {
      {((m1 - e * m2) * v1 + (1 + e) * m2 * v2) / (m1 + m2), ((m1 + e * m2) * v1 + (1 + e) * m2 * v2) / (m1 + m2)},
      {GiNaC::sqrt(x * x), x},
      {GiNaC::acos(1 - 2 * z * z), 2 * GiNaC::asin(z)},
      {GiNaC::atan(x) + GiNaC::atan(1 / x), GiNaC::Pi / 2},
      {GiNaC::exp(GiNaC::Pi * GiNaC::sqrt(ex(163))), GiNaC::pow(ex(640320), 3) + 744},
      {GiNaC::sin(2 * x), 2 * GiNaC::sin(x) * GiNaC::cos(x)},
      {GiNaC::pow(m1 - m2, 3) / (m2 - m1), 0},
  };
  std::string out;
  ProveOptions sym_only;
  sym_only.numeric = false;
  for (const auto& [l, r] : claims) {
    out += test::describe(prove_equal(l, r, T.t)) + "\n";
    out += test::describe(prove_equal(l, r, T.t, sym_only)) + "\n";
  }
  for (const auto& c : side_conditions(GiNaC::log(m1 - m2) / (v1 - v2) + GiNaC::sqrt(x), T.t))
    out += c.what + " " + c.reason + " " + c.evidence + "\n";
  return out;
}

std::string run_self() {
  char path[4096];
  ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) return "";
  path[n] = 0;
  std::string cmd = std::string("'") + path + "' '[.print-verdicts]' 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
  if (!p) return "";
  std::string out;
  std::array<char, 4096> buf;
  std::size_t k;
  while ((k = fread(buf.data(), 1, buf.size(), p.get())) > 0) out.append(buf.data(), k);
  // keep only our block (Catch2 adds its summary)
  auto b = out.find("<<<"), e = out.find(">>>");
  return (b == std::string::npos || e == std::string::npos) ? out : out.substr(b, e - b);
}

}  // namespace

TEST_CASE("print verdicts (helper for the cross-process test)", "[.print-verdicts]") {
  std::cout << "<<<" << all_verdicts() << ">>>" << std::endl;
}

TEST_CASE("verdict text is identical within a process", "[prove][determinism]") {
  std::string a = all_verdicts();
  std::string b = all_verdicts();
  REQUIRE(a == b);
  REQUIRE(a.find("refuted") != std::string::npos);
}

TEST_CASE("verdict text is identical across processes", "[prove][determinism]") {
  std::string a = run_self();
  std::string b = run_self();
  REQUIRE(a.size() > 100);
  REQUIRE(a == b);
  // and equal to this process's text
  REQUIRE(a == "<<<" + all_verdicts());
}
