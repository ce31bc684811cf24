// Angles and units (issue 24, item 9): deg = pi/180 and the degree sign in expressions, rad and
// sr as dimensionless units, the unit as the author wrote it in `latex --units`, and fractional
// powers of units.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/calculus/install.hpp"
#include "derivations/claims/claims.hpp"
#include "derivations/reader/derivation.hpp"
#include "derivations/report/latex.hpp"
#include "derivations/report/latex_read.hpp"
#include "derivations/rules/check.hpp"
#include "derivations/syntax/units.hpp"

namespace {

dc::Verdict equal(const std::string& l, const std::string& r, const std::string& assume = "") {
  dc::calculus::install();
  return dc::check_equal(l, r, assume);
}

dc::CheckSummary check(const std::string& name, const std::string& text) {
  dc::calculus::install();
  return dc::check_derivation(dc::parse_derivation(dc::SourceText{name, text}));
}

// The first error of a file's steps (dimension errors are the step's, reported by check).
std::string step_error(const std::string& name, const std::string& text) {
  auto s = check(name, text);
  for (const auto& r : s.results)
    if (!r.errors.empty()) return r.errors.front().message();
  FAIL("no step error for " << text);
  return "";
}

dc::InputError parse_error(const std::string& name, const std::string& text) {
  try {
    dc::parse_derivation(dc::SourceText{name, text});
  } catch (const dc::InputError& e) {
    return e;
  }
  FAIL("no error for " << text);
  throw std::logic_error("unreachable");
}

dc::Dimension unit(const std::string& s) {
  return dc::parse_dimension(dc::parse_expression(s, dc::SourcePos{"u", 1, 1}));
}

}  // namespace

TEST_CASE("deg is pi/180 in claims: sin(30*deg) = 1/2 is proved, a wrong value refuted", "[angles]") {
  dc::Verdict v = equal("sin(30*deg)", "1/2");
  CAPTURE(v.detail);
  CHECK(v.kind == dc::VerdictKind::Proved);
  CHECK(equal("cos(60*deg)", "1/2").kind == dc::VerdictKind::Proved);
  CHECK(equal("tan(45*deg)", "1").kind == dc::VerdictKind::Proved);
  CHECK(equal("180*deg", "pi").kind == dc::VerdictKind::Proved);
  dc::Verdict w = equal("sin(30*deg)", "sqrt(3)/2");
  CHECK(w.kind == dc::VerdictKind::Refuted);
  // a symbol times deg: the angle theta in degrees
  CHECK(equal("sin(theta*deg)", "sin(pi*theta/180)").kind == dc::VerdictKind::Proved);
}

TEST_CASE("the degree sign: 30° is 30*deg", "[angles][parser]") {
  dc::Node n = dc::parse_expression("sin(30°) + cos(2*x°)", dc::SourcePos{"e", 1, 1});
  // the degree sign binds to the atom before it: 2*x° is 2*(x°)
  CHECK(dc::to_text(n) == "sin(30*deg) + cos(2*(x*deg))");
  CHECK(equal("sin(30°)", "1/2").kind == dc::VerdictKind::Proved);
  CHECK(equal("cos(90°)", "0").kind == dc::VerdictKind::Proved);
  CHECK(equal("(45°)^2", "pi^2/16").kind == dc::VerdictKind::Proved);
  CHECK(equal("sin(30°)", "1").kind == dc::VerdictKind::Refuted);
  // the degree sign counts as one column: the error after it is positioned on the character
  try {
    dc::parse_expression("30° 2", dc::SourcePos{"e", 1, 1});
    FAIL("no error");
  } catch (const dc::InputError& e) {
    CHECK(e.pos().col == 5);
  }
  try {
    dc::parse_expression("30°°", dc::SourcePos{"e", 1, 1});
    FAIL("no error");
  } catch (const dc::InputError& e) {
    CHECK(e.message() == "unexpected second '°'");
  }
}

TEST_CASE(".dc files: deg is predefined, declaring it is a positioned error", "[angles][format]") {
  auto s = check("deg.dc",
                 "symbol theta : in (0, pi/2) [rad]\n"
                 "symbol g : positive [m/s^2]\n"
                 "symbol v, R : positive [m/s]\n"
                 "a: sin(30*deg) = 1/2\n"
                 "    by rewrite\n"
                 "b: sin(2*45°) = 1\n"
                 "    by rewrite\n"
                 "c: cos(60°) = sqrt(3)/2\n"
                 "    by rewrite\n");
  REQUIRE(s.results.size() == 3);
  CHECK(s.results[0].verdict.kind == dc::VerdictKind::Proved);
  CHECK(s.results[1].verdict.kind == dc::VerdictKind::Proved);
  CHECK(s.results[2].verdict.kind == dc::VerdictKind::Refuted);

  dc::InputError e = parse_error("mine.dc", "symbol x : real [1]\nsymbol deg : positive [1]\n");
  CHECK(e.pos().line == 2);
  CHECK(e.pos().col == 8);
  CHECK(e.message() == "'deg' is predefined as pi/180 (degrees: 30*deg, or 30°) and cannot be declared as a symbol; "
                       "choose another name");
  // nor defined by a step
  dc::InputError d = parse_error("def.dc", "d: deg = pi/180\n    by definition\n");
  CHECK(d.message() == "'deg' is a reserved name and cannot be defined");
  // in claims, 'deg' is no symbol either: an assumption about it is refused
  CHECK_THROWS_AS(equal("deg", "pi/180", "deg > 0"), dc::InputError);
}

TEST_CASE("rad and sr are dimensionless units, dimensions are still checked", "[units]") {
  CHECK(unit("rad").dimensionless());
  CHECK(unit("sr").dimensionless());
  CHECK(unit("rad/s") == unit("1/s"));
  CHECK(unit("rad/s^2") == unit("Hz^2"));
  CHECK(unit("W/sr") == unit("W"));
  auto s = check("omega.dc",
                 "symbol omega : real [rad/s]\n"
                 "symbol t : positive [s]\n"
                 "symbol theta, theta0 : real [rad]\n"
                 "symbol r : positive [m]\n"
                 "a: theta = theta0 + omega*t\n"
                 "    by given\n"
                 "v: r*omega = r*omega\n"
                 "    by rewrite\n");
  REQUIRE(s.results.size() == 2);
  CHECK(s.results[0].verdict.holds());
  // a mismatch is still one: an angular velocity is no angle
  const std::string e = step_error("bad.dc",
                                   "symbol omega : real [rad/s]\n"
                                   "symbol theta : real [rad]\n"
                                   "a: theta = omega\n"
                                   "    by given\n");
  CAPTURE(e);
  CHECK(e.find("1/s") != std::string::npos);
}

TEST_CASE("fractional unit powers: m^(-1/2) for a wave function", "[units]") {
  CHECK(unit("m^(-1/2)").to_string() == "1/m^(1/2)");
  CHECK(unit("m^(1/3)").to_ascii() == "m^(1/3)");
  CHECK(unit("m^(-1/2)") * unit("m^(-1/2)") == unit("1/m"));
  CHECK(unit("kg^(3/2)/kg^(1/2)") == unit("kg"));
  CHECK(unit("m^(2/4)") == unit("m^(1/2)"));
  // the probability density psi^2 of a wave function in 1/sqrt(m) integrates to a number
  auto s = check("psi.dc",
                 "symbol L : positive [m]\n"
                 "symbol x : in (0, 1) [m]\n"
                 "symbol psi, A : real [m^(-1/2)]\n"
                 "symbol P : real [1]\n"
                 "a: A = sqrt(2/L)\n"
                 "    by given\n"
                 "b: P = A^2*L/2\n"
                 "    by given\n"
                 "c: P = 1\n"
                 "    by substitute a into b\n");
  REQUIRE(s.results.size() == 3);
  CHECK(s.results[2].verdict.holds());
  // a dimension mismatch with a fractional power is reported
  const std::string e = step_error("psi_bad.dc",
                                   "symbol L : positive [m]\n"
                                   "symbol A : real [m^(-1/2)]\n"
                                   "a: A = 2/L\n"
                                   "    by given\n");
  CAPTURE(e);
  CHECK(e.find("1/m^(1/2)") != std::string::npos);
  // cube roots of a length are lengths to the 1/3
  CHECK_NOTHROW(check("cube.dc", "symbol V : positive [m^3]\nsymbol a : positive [m]\nq: a = V^(1/3)\n    by given\n"));
  // exponents are exact fractions of integers: decimals stay refused in a unit
  dc::InputError d = parse_error("dec.dc", "symbol m : positive [kg^2.5]\n");
  CHECK(d.message() == "a unit exponent must be an integer such as 2 or -1, or a fraction such as (-1/2)");
}

TEST_CASE("latex --units prints the unit as the author wrote it", "[units][latex]") {
  dc::Derivation d = dc::parse_derivation(dc::SourceText{"am.dc",
                                                         "symbol J_imp : real [N*s]\n"
                                                         "symbol L_ang : real [kg*m^2/s]\n"
                                                         "symbol tau : real [N*m]\n"
                                                         "symbol I_rot : positive [kg*m^2]\n"
                                                         "symbol omega : real [rad/s]\n"
                                                         "symbol p : real [momentum]\n"
                                                         "symbol psi : real [m^(-1/2)]\n"
                                                         "a: L_ang = I_rot*omega\n"
                                                         "    by given\n"
                                                         "b: theta = 30°\n"
                                                         "    by definition\n"});
  dc::LatexOptions opt;
  opt.units = true;
  const std::string tex = dc::write_latex(d, opt);
  CAPTURE(tex);
  CHECK(tex.find("\\si{N.s}") != std::string::npos);
  CHECK(tex.find("\\si{kg.m^{2}/s}") != std::string::npos);
  CHECK(tex.find("\\si{N.m}") != std::string::npos);
  CHECK(tex.find("\\si{rad/s}") != std::string::npos);
  CHECK(tex.find("\\si{m^{-0.5}}") != std::string::npos);
  // a dimension name is printed in base units
  CHECK(tex.find("\\si{kg.m/s}") != std::string::npos);
  // 30° prints with the degree sign
  CHECK(tex.find("30^{\\circ}") != std::string::npos);
}

TEST_CASE("the degree sign round-trips through our LaTeX", "[angles][latex]") {
  dc::SymbolTable t;
  dc::SymbolInfo x;
  x.name = "x";
  t.declare(x);
  const dc::SourcePos at{"e", 1, 1};
  const std::string tex = dc::latex_expression(dc::parse_expression("sin(30°) + x^2*deg", at), t);
  CHECK(tex.find("30^{\\circ}") != std::string::npos);
  CHECK(tex.find("x^{2}{}^{\\circ}") != std::string::npos);
  CHECK(dc::to_text(dc::read_latex_expression(tex, t, at)) == "sin(30*deg) + x^2*deg");
}
