// Differentials d(x) and the separation of variables (symbolic/differential.hpp,
// rules/integrate_differential.cpp): the derivative form of a law and its differential form are
// related by rewrite; a separated differential equation is integrated from a stated start.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/report/latex.hpp"
#include "support/checked.hpp"

namespace {

using test_support::Checked;
using K = dc::VerdictKind;

Checked check_text(const std::string& body) { return test_support::check_text(body, "differentials.dc"); }

const std::string kRocket =
    "symbol m_r, m0 : positive [kg]\n"
    "symbol v : real [m/s]\n"
    "symbol u_e : positive [m/s]\n"
    "symbol g : positive [m/s^2]\n"
    "symbol t : nonnegative [s]\n"
    "function mr(t) : positive [kg]\n"
    "function vr(t) : real [m/s]\n"
    "assume m_r <= m0\n"
    "ode: diff(vr(t), t) = -u_e*diff(mr(t), t)/mr(t) - g\n    by given\n";

}  // namespace

TEST_CASE("differentials: the derivative form and the differential form of a law", "[differential]") {
  Checked c = check_text(kRocket +
                         "in_functions: d(vr(t)) = -u_e*d(mr(t))/mr(t) - g*d(t)\n    by rewrite ode\n"
                         "separated: d(v) = -u_e*d(m_r)/m_r - g*d(t)\n    by rewrite ode with vr(t) = v, mr(t) = m_r\n"
                         "gravity_slip: d(v) = -u_e*d(m_r)/m_r + g*d(t)\n    by rewrite ode with vr(t) = v, mr(t) = m_r\n"
                         "multiplied: m_r*d(v) = -u_e*d(m_r) - m_r*g*d(t)\n    by rewrite separated\n"
                         "no_dt: d(v) = -u_e*d(m_r)/m_r - g\n    by rewrite separated\n");
  CHECK(c.kind("in_functions") == K::Proved);
  CHECK(c.kind("separated") == K::Proved);
  CHECK(c.kind("gravity_slip") == K::Refuted);
  CHECK(c.kind("multiplied") == K::Proved);
  // a term without a differential is a different equation (g against g*d(t)): refuted
  CHECK(c.kind("no_dt") == K::Refuted);
}

TEST_CASE("differentials: the rocket equation by separation of variables", "[differential]") {
  Checked c = check_text(kRocket +
                         "separated: d(v) = -u_e*d(m_r)/m_r - g*d(t)\n    by given\n"
                         "multiplied: m_r*d(v) = -u_e*d(m_r) - m_r*g*d(t)\n    by given\n"
                         "velocity: v = -u_e*log(m_r/m0) - g*t\n    by integrate separated with v = 0, m_r = m0, t = 0\n"
                         "from_multiplied: v = -u_e*log(m_r/m0) - g*t\n"
                         "    by integrate multiplied with v = 0, m_r = m0, t = 0\n"
                         "ratio: m0/m_r = exp((v + g*t)/u_e)\n    by integrate separated with v = 0, m_r = m0, t = 0\n"
                         "inverted: v = -u_e*log(m0/m_r) - g*t\n    by integrate separated with v = 0, m_r = m0, t = 0\n"
                         "other_start: v = -u_e*log(m_r/m0) - g*t\n"
                         "    by integrate separated with v = 0, m_r = m0, t = 1\n");
  CHECK(c.kind("velocity") == K::Proved);
  // divided by its coefficient m_r (positive on the declared domain), the equation separates
  CHECK(c.kind("from_multiplied") == K::Proved);
  CHECK(c.kind("ratio") == K::Proved);
  CHECK(c.kind("inverted") == K::Refuted);
  CHECK(c.at("inverted").derived.find("constant along the path: g, u_e") != std::string::npos);
  CHECK(c.kind("other_start") == K::Refuted);
}

TEST_CASE("differentials: v dv = a dx, and what is constant along the path", "[differential]") {
  Checked c = check_text(
      "symbol v, v0 : real [m/s]\n"
      "symbol x, x0 : real [m]\n"
      "symbol a : real [m/s^2]\n"
      "symbol k : positive [1/m]\n"
      "vdv: v*d(v) = a*d(x)\n    by given\n"
      "energy: v^2 = v0^2 + 2*a*(x - x0)\n    by integrate vdv with v = v0, x = x0\n"
      "half: v^2 = v0^2 + a*(x - x0)\n    by integrate vdv with v = v0, x = x0\n"
      // the path may pass through v = 0 and go on with v < 0: one root is not implied
      "root: v = sqrt(v0^2 + 2*a*(x - x0))\n    by integrate vdv with v = v0, x = x0\n"
      "drag: a = -k*v^2\n    by given\n"
      "after_drag: v^2 = v0^2 + 2*a*(x - x0)\n    by integrate vdv with v = v0, x = x0\n");
  CHECK(c.kind("energy") == K::Proved);
  CHECK(c.kind("half") == K::Refuted);
  CHECK(c.kind("root") == K::Refuted);
  // once a premise gives a through v, a is no constant of the integration
  CHECK(c.kind("after_drag") == K::Undecided);
  CHECK(c.at("after_drag").verdict.reason.find("a is treated as constant") != std::string::npos);
}

TEST_CASE("differentials: what is not integrated is undecided, never proved", "[differential]") {
  Checked c = check_text(
      "symbol x, y : real [1]\n"
      "symbol p : positive [1]\n"
      "mixed: d(y) = (x + y)*d(x)\n    by given\n"
      "mixed_claim: y = exp(x) - x - 1\n    by integrate mixed with y = 0, x = 0\n"
      // 1/x is not continuous on a path from x = -1 that may cross 0
      "pole: d(y) = d(x)/x\n    by given\n"
      "through_pole: y = log(abs(x))\n    by integrate pole with y = 0, x = -1\n"
      // on a positive quantity it is
      "pos: d(y) = d(p)/p\n    by given\n"
      "log_p: y = log(p)\n    by integrate pos with y = 0, p = 1\n");
  CHECK(c.kind("mixed_claim") == K::Undecided);
  CHECK(c.at("mixed_claim").verdict.reason.find("not separated") != std::string::npos);
  CHECK(c.kind("through_pole") == K::Undecided);
  CHECK(c.kind("log_p") == K::Proved);
}

TEST_CASE("differentials: input errors are positioned", "[differential]") {
  Checked c = check_text(
      "symbol x, y, t : real [1]\n"
      "lin: d(y) = 2*x*d(x)\n    by given\n"
      "no_start: y = x^2\n    by integrate lin with y = 0\n"
      "stray: y = x^2\n    by integrate lin with y = 0, x = 0, t = 0\n"
      "nonlinear: d(y)*d(x) = d(t)\n    by given\n"
      "nl: y = x\n    by integrate nonlinear with y = 0, x = 0, t = 0\n");
  CHECK(c.has_error("no_start", "say where the integration starts"));
  CHECK(c.has_error("stray", "expected 'x = start'"));
  CHECK(c.has_error("nl", "each of its terms must hold exactly one differential"));
  // the differential of an expression is written out by the chain rule
  CHECK_THROWS_WITH(dc::parse_derivation(dc::SourceText{"e.dc", "symbol x, y : real [1]\n"
                                                                "bad: d(x^2) = 2*x*d(x)\n    by rewrite\n"}),
                    Catch::Contains("differential of an expression out by the chain rule"));
}

TEST_CASE("differentials: LaTeX writes d(v) as an upright d", "[differential]") {
  const dc::Derivation d = dc::parse_derivation(dc::SourceText{
      "l.dc", "symbol v : real [m/s]\nsymbol t : real [s]\nsymbol g : positive [m/s^2]\n"
              "s: d(v) = -g*d(t)\n    by given\n"});
  const std::string tex = dc::latex_relation(d.steps[0].claim, d.symbols);
  CHECK(tex.find("\\mathrm{d}v") != std::string::npos);
  CHECK(tex.find("\\mathrm{d}t") != std::string::npos);
}

TEST_CASE("differentials: a relation that holds along the path holds for the changes too", "[differential]") {
  // y = x^2 along the path gives d(y) = 2*x*d(x); a quantity whose change the file never writes
  // is not assumed constant (g varies unless d(g) = 0 is stated)
  Checked c = check_text(
      "symbol x, y, t : real [1]\n"
      "symbol g : positive [1]\n"
      "yx: y = x^2\n    by given\n"
      "dy: d(y) = 2*x*d(x)\n    by rewrite yx\n"
      "dy_slip: d(y) = x*d(x)\n    by rewrite yx\n"
      "yg: y = g*t\n    by given\n"
      "g_may_vary: d(y) = g*d(t)\n    by rewrite yg\n"
      "constant: d(g) = 0\n    by given\n"
      "g_constant: d(y) = g*d(t)\n    by rewrite yg, constant\n"
      "g_constant_slip: d(y) = 2*g*d(t)\n    by rewrite yg, constant\n");
  CHECK(c.kind("dy") == K::Proved);
  CHECK(c.kind("dy_slip") == K::Refuted);
  CHECK(c.kind("g_may_vary") == K::Undecided);
  CHECK(c.at("g_may_vary").verdict.reason.find("if g is constant, cite a step d(g) = 0") != std::string::npos);
  CHECK(c.kind("g_constant") == K::Proved);
  CHECK(c.kind("g_constant_slip") == K::Refuted);
}
