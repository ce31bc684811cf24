// Deterministic printing of GiNaC expressions (derivations/symbolic/printer.hpp).
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/functions.hpp"
#include "derivations/report/latex.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/symbols.hpp"

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// A table with the impact symbols, declared in the given order (GiNaC's internal order of sums
// and products follows symbol serials and hashes, so the declaration order changes it).
struct Impact {
  dc::SymbolTable t;
  ex m1, m2, v1, v2, e, mu, theta, t_;
  explicit Impact(bool reversed) {
    std::vector<std::tuple<std::string, std::string, dc::Domain>> decl = {
        {"m1", "m_1", dc::Domain::positive()},   {"m2", "m_2", dc::Domain::positive()},
        {"v1", "v_1", dc::Domain::real()},       {"v2", "v_2", dc::Domain::real()},
        {"e", "e", dc::Domain::real()},          {"mu", "\\mu", dc::Domain::positive()},
        {"theta", "\\theta", dc::Domain::real()}, {"t", "t", dc::Domain::real()}};
    if (reversed) std::reverse(decl.begin(), decl.end());
    for (auto& [n, tex, dom] : decl) {
      dc::SymbolInfo s;
      s.name = n;
      s.tex = tex;
      s.domain = dom;
      t.declare(s);
    }
    dc::SymbolInfo f;
    f.name = "mr";
    f.tex = "m_r";
    f.is_function = true;
    f.params = {"t"};
    t.declare(f);
    m1 = t.find("m1")->sym; m2 = t.find("m2")->sym; v1 = t.find("v1")->sym; v2 = t.find("v2")->sym;
    e = t.find("e")->sym; mu = t.find("mu")->sym; theta = t.find("theta")->sym; t_ = t.find("t")->sym;
  }
  // A fixed list of expressions covering sums, products, fractions, powers, functions.
  std::vector<ex> corpus() const {
    ex mr = dc::apply_pool_function(t.function_index("mr"), t_);
    return {
        (m1 * v1 + m2 * v2 - e * m2 * (v1 - v2)) / (m1 + m2),
        GiNaC::normal((m1 * v1 + m2 * v2 - e * m2 * (v1 - v2)) / (m1 + m2)),
        GiNaC::expand((1 - e * e) / 2 * m1 * m2 / (m1 + m2) * GiNaC::pow(v1 - v2, 2)),
        (m2 - m1) * v1 / (m1 + m2),
        -(m1 - m2) * v1 / (m1 + m2),
        (mu - e - e * (1 + e)) / (mu + 1) * v1,
        GiNaC::acos(1 - GiNaC::pow(m1 / (m1 + m2), 2) * v1 * v1 / (2 * m2)),
        -GiNaC::sqrt(2 * mu * (v2 - v1)),
        GiNaC::log(mr / m1) * (-v2) - mu * t_,
        GiNaC::exp((v1 + mu * t_) / v2),
        GiNaC::diff(mr, GiNaC::ex_to<GiNaC::symbol>(t_)) * v1 / mr,
        numeric(3, 7) * GiNaC::pow(m1, -2) * GiNaC::sin(theta) * GiNaC::pow(GiNaC::cos(theta), 2),
        GiNaC::pow(m1 + m2, -3) * GiNaC::pow(v1 - v2, 3),
        GiNaC::Pi * m1 + 1 - GiNaC::pow(e, 2),
    };
  }
};

std::string corpus_text(bool reversed) {
  Impact s(reversed);
  std::ostringstream os;
  for (const auto& x : s.corpus()) os << dc::print_text(x, s.t) << "\n" << dc::print_latex(x, s.t) << "\n";
  return os.str();
}

std::string self_exe() {
  char buf[4096];
  ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  REQUIRE(n > 0);
  buf[n] = 0;
  return buf;
}

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("printer: textbook forms of impact results", "[latex][printer]") {
  Impact s(false);
  const auto& t = s.t;
  CHECK(dc::print_text((s.m1 - s.m2) * s.v1 / (s.m1 + s.m2), t) == "v1*(m1 - m2)/(m1 + m2)");
  CHECK(dc::print_latex((s.m1 - s.m2) * s.v1 / (s.m1 + s.m2), t) ==
        "\\frac{v_1 \\left(m_1 - m_2\\right)}{m_1 + m_2}");
  // canonical sign of a sub-sum: (m2 - m1) is printed as -(m1 - m2)
  CHECK(dc::print_text((s.m2 - s.m1) * s.v1 / (s.m1 + s.m2), t) == "-v1*(m1 - m2)/(m1 + m2)");
  CHECK(dc::print_text(1 - s.e * s.e, t) == "1 - e^2");
  CHECK(dc::print_text(s.m1 * s.v1 + s.m2 * s.v2, t) == "m1*v1 + m2*v2");
  CHECK(dc::print_text(-s.v1 + s.v2, t) == "v2 - v1");
  CHECK(dc::print_latex(numeric(1, 2) * s.m1 * s.v1 * s.v1, t) == "\\frac{m_1 v_1^{2}}{2}");
  CHECK(dc::print_latex(GiNaC::sqrt(2 * s.mu * s.t_), t) == "\\sqrt{2 \\mu t}");
  CHECK(dc::print_latex(GiNaC::acos(1 - s.e), t) == "\\arccos\\left(1 - e\\right)");
  CHECK(dc::print_latex(GiNaC::cos(s.theta), t) == "\\cos \\theta");
  CHECK(dc::print_latex(GiNaC::pow(GiNaC::cos(s.theta), 2), t) == "\\cos^{2} \\theta");
  // a sum under a square root keeps its own sign
  CHECK(dc::print_text(GiNaC::sqrt(2 * s.mu * (s.v2 - s.v1)), t) == "sqrt(2*mu*(v2 - v1))");
  CHECK(dc::print_text(-s.m1 / (s.m1 + s.m2), t) == "-m1/(m1 + m2)");
  ex mr = dc::apply_pool_function(t.function_index("mr"), s.t_);
  CHECK(dc::print_text(mr, t) == "mr(t)");
  CHECK(dc::print_latex(GiNaC::diff(mr, GiNaC::ex_to<GiNaC::symbol>(s.t_)), t) ==
        "\\frac{\\mathrm{d} m_r}{\\mathrm{d} t}");
  CHECK(dc::print_text(GiNaC::diff(mr, GiNaC::ex_to<GiNaC::symbol>(s.t_)), t) == "diff(mr(t), t)");
}

TEST_CASE("printer: numbers", "[latex][printer]") {
  CHECK(dc::print_number(numeric(5, 2)) == "5/2");
  CHECK(dc::print_number(numeric(-7)) == "-7");
  CHECK(dc::print_number(GiNaC::Pi, 10) == "3.141592654");
  CHECK(dc::print_number(GiNaC::sqrt(ex(2)) * numeric(1, 1000000), 5) == "1.4142e-6");
  CHECK(dc::print_number(ex(numeric(1, 3)).evalf(), 4) == "0.3333");
  CHECK(dc::print_number(ex(numeric(999996, 1000000)).evalf(), 4) == "1");
  CHECK(dc::print_number(GiNaC::pow(ex(10), 30) * 3 + numeric(1, 2), 3) == "6000000000000000000000000000001/2");
  CHECK(dc::print_number(GiNaC::evalf(GiNaC::pow(ex(10), 30) * GiNaC::Pi), 3) == "3.14e30");
  CHECK_THROWS_AS(dc::print_number(GiNaC::symbol("x")), std::invalid_argument);
}

TEST_CASE("printer: independent of GiNaC's internal order (declaration order changes it)", "[latex][printer]") {
  // The two tables create their symbols in opposite orders, so GiNaC sorts the operands of the
  // same sums and products differently; the printed text must not change.
  CHECK(corpus_text(false) == corpus_text(true));
}

// Child of the cross-process test below: prints the corpus to $DC_PRINTER_OUT.
TEST_CASE("printer child process", "[.][printer-child]") {
  const char* out = std::getenv("DC_PRINTER_OUT");
  REQUIRE(out != nullptr);
  const char* rev = std::getenv("DC_PRINTER_REVERSED");
  std::ofstream(out, std::ios::binary) << corpus_text(rev && std::string(rev) == "1");
}

TEST_CASE("printer: byte-identical output in separate processes", "[latex][printer]") {
  std::string exe = self_exe();
  std::string base = "/tmp/dc_printer_" + std::to_string(::getpid());
  std::vector<std::string> outputs;
  for (int k = 0; k < 3; ++k) {
    std::string file = base + "_" + std::to_string(k) + ".txt";
    std::string cmd = "DC_PRINTER_OUT='" + file + "' DC_PRINTER_REVERSED=" + (k == 2 ? "1" : "0") + " '" + exe +
                      "' '[printer-child]' > /dev/null 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
    outputs.push_back(slurp(file));
    std::remove(file.c_str());
  }
  REQUIRE(!outputs[0].empty());
  CHECK(outputs[0] == outputs[1]);
  CHECK(outputs[0] == outputs[2]);
  CHECK(outputs[0] == corpus_text(false));
}

TEST_CASE("latex writer: the author's tree typeset as a lecturer would", "[latex][printer]") {
  dc::SymbolTable t;
  for (const char* n : {"k", "m", "x", "theta", "L", "m1", "v1", "m2", "A"}) {
    dc::SymbolInfo info;
    info.name = n;
    info.sym = GiNaC::realsymbol(n);
    t.declare(info);
  }
  auto tex = [&](const char* e) { return dc::latex_expression(dc::parse_expression(e, dc::SourcePos{"<t>", 1, 1}), t); };
  // a leading minus stands before the fraction
  CHECK(tex("-k/m*x") == "-\\frac{k}{m} x");
  CHECK(tex("-1/2*k*A^2") == "-\\frac{1}{2} k A^{2}");
  CHECK(tex("-m1*v1/m2") == "-\\frac{m_1 v_1}{m_2}");
  CHECK(tex("(-k)/m") == "\\frac{-k}{m}");   // the author's own parentheses: kept as written
  CHECK(tex("exp(-x/k)") == "\\mathrm{e}^{-x/k}");
  // powers of trigonometric functions
  CHECK(tex("sin(theta/2)^2") == "\\sin^{2} \\frac{\\theta}{2}");
  CHECK(tex("2*L*sin(theta)^2") == "2 L \\sin^{2} \\theta");
  CHECK(tex("cos(theta + x)^2") == "\\cos^{2}\\left(\\theta + x\\right)");
  CHECK(tex("sin(theta)^(1/2)") == "\\left(\\sin \\theta\\right)^{\\frac{1}{2}}");
}
