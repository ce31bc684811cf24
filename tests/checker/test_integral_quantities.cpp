// A definite integral of a declared function is a quantity that references can determine
// (symbolic/integral_atom.hpp): linear in its integrand, one quantity per integrand and limits,
// differentiated by Leibniz's rule, and never the ground of a refutation that rests on treating
// two such integrals as unrelated.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"
#include "support/checked.hpp"

namespace {

using test_support::Checked;

Checked check_text(const std::string& body) { return test_support::check_text(body, "integrals.dc"); }

const std::string kHeader =
    "symbol x, y, L, A, B : positive [1]\n"
    "function psi(x) : real [1]\n"
    "norm: integral(psi(x)^2, x, 0, L) = 1\n    by given\n";

}  // namespace

TEST_CASE("a normalisation integral is a quantity the references determine", "[integrals][functions]") {
  using K = dc::VerdictKind;
  Checked c = check_text(kHeader +
                         "twice: 2*integral(psi(x)^2, x, 0, L) = 2\n    by rewrite norm\n"
                         "scaled: integral(A^2*psi(x)^2, x, 0, L) = A^2\n    by rewrite norm\n"
                         "renamed: integral(psi(y)^2, y, 0, L) = 1\n    by rewrite norm\n"
                         "split: integral(psi(x)^2 + x, x, 0, L) = 1 + L^2/2\n    by rewrite norm\n"
                         "wrong: integral(A^2*psi(x)^2, x, 0, L) = 2*A^2\n    by rewrite norm\n"
                         "wrong_split: integral(psi(x)^2 + x, x, 0, L) = 1 + L^2\n    by rewrite norm\n");
  CHECK(c.kind("twice") == K::Proved);
  CHECK(c.kind("scaled") == K::Proved);
  CHECK(c.kind("renamed") == K::Proved);
  CHECK(c.kind("split") == K::Proved);
  // with the integral eliminated, what is left is an ordinary false equation
  CHECK(c.kind("wrong") == K::Refuted);
  CHECK(c.kind("wrong_split") == K::Refuted);
}

TEST_CASE("integrals of a declared function are differentiated by Leibniz's rule", "[integrals][functions]") {
  using K = dc::VerdictKind;
  Checked c = check_text(kHeader +
                         "upper: diff(integral(psi(x)^2, x, 0, L), L) = psi(L)^2\n    by rewrite\n"
                         "param: diff(integral(A*x*psi(x), x, 0, L), A) = integral(x*psi(x), x, 0, L)\n    by rewrite\n"
                         "const: diff(integral(psi(x)^2, x, 0, L), A) = 0\n    by rewrite\n"
                         "singular: diff(integral(psi(x)/(x - A), x, 0, L), A) = integral(psi(x)/(x - A)^2, x, 0, L)\n"
                         "    by rewrite\n"
                         "ftc: integral(diff(psi(x), x), x, 0, L) = psi(L) - psi(0)\n    by rewrite\n"
                         "ftc2_wrong: integral(diff(psi(x), x, 2), x, 0, L) = diff(psi(L), L)\n    by rewrite\n"
                         "ftc_wrong: integral(diff(psi(x), x), x, 0, L) = psi(L) + psi(0)\n    by rewrite\n"
                         "square: integral(psi(x)*diff(psi(x), x), x, 0, L) = psi(L)^2/2 - psi(0)^2/2\n    by rewrite\n"
                         "cube: integral(A*(psi(x)^2 + 1)*diff(psi(x), x), x, 0, L) = A*(psi(L)^3/3 + psi(L) - psi(0)^3/3 - psi(0))\n"
                         "    by rewrite\n"
                         "square_wrong: integral(psi(x)*diff(psi(x), x), x, 0, L) = psi(L)^2 - psi(0)^2\n    by rewrite\n");
  CHECK(c.kind("upper") == K::Proved);
  // not under the integral sign where the integrand is singular (A may lie in (0, L))
  CHECK(c.kind("singular") != K::Proved);
  CHECK(c.kind("singular") != K::HoldsNumerically);
  // the fundamental theorem for a derivative of the declared function itself
  CHECK(c.kind("ftc") == K::Proved);
  CHECK(c.kind("ftc2_wrong") == K::Refuted);   // it forgets -psi'(0)
  CHECK(c.kind("ftc_wrong") == K::Refuted);
  // a polynomial of the function times its derivative: the substitution u = psi(x)
  CHECK(c.kind("square") == K::Proved);
  CHECK(c.kind("cube") == K::Proved);
  CHECK(c.kind("square_wrong") == K::Refuted);
  CHECK(c.kind("param") == K::Proved);
  CHECK(c.kind("const") == K::Proved);
}

TEST_CASE("two integrals that are related but written differently are never refuted", "[integrals][functions][soundness]") {
  using K = dc::VerdictKind;
  // Each of these is true for every function psi; the checker knows no change of variable or
  // splitting of intervals, so they must stay undecided (never refuted, never proved by
  // accident).
  Checked c = check_text(kHeader +
                         "mirror: integral(psi(x), x, 0, L) = integral(psi(L - x), x, 0, L)\n    by rewrite\n"
                         "adjacent: integral(psi(x), x, 0, L) = integral(psi(x), x, 0, A) + integral(psi(x), x, A, L)\n"
                         "    by rewrite\n"
                         "parts: integral(x*diff(psi(x), x), x, 0, L) = L*psi(L) - integral(psi(x), x, 0, L)\n"
                         "    by rewrite\n"
                         "named: B = integral(psi(x), x, 0, L)\n    by given\n"
                         "via_ref: B = integral(psi(L - x), x, 0, L)\n    by rewrite named\n");
  for (const char* label : {"mirror", "adjacent", "parts", "via_ref"}) {
    CAPTURE(label);
    CHECK(c.kind(label) == K::Undecided);
    CHECK(c.at(label).verdict.reason.find("relations between such integrals") != std::string::npos);
  }
}

TEST_CASE("a cited antiderivative is instantiated as F(b) - F(a), never used as a value", "[integrals][antiderivative]") {
  using K = dc::VerdictKind;
  // (1 + 2x^2) e^(x^2) has the antiderivative x e^(x^2), which the integral rules do not find:
  // the author's own, checked by differentiation, makes the definite integral usable
  Checked c = check_text(
      "symbol x, L, W : positive [1]\n"
      "anti: integral((1 + 2*x^2)*exp(x^2), x) = x*exp(x^2)\n    by integrate\n"
      "work: W = integral((1 + 2*x^2)*exp(x^2), x, 0, L)\n    by given\n"
      "cited: W = L*exp(L^2)\n    by substitute anti into work\n"
      "cited_wrong: W = L*exp(L^2) + 1\n    by substitute anti into work\n"
      "scaled: 3*integral((1 + 2*x^2)*exp(x^2), x, 0, L) = 3*L*exp(L^2)\n    by rewrite anti\n"
      "uncited: integral((1 + 2*x^2)*exp(x^2), x, 0, L) + 1 = L*exp(L^2) + 1\n    by rewrite\n");
  CHECK(c.kind("cited") == K::Proved);
  CHECK(c.kind("cited_wrong") == K::Refuted);
  CHECK(c.kind("scaled") == K::Proved);
  CHECK(c.kind("uncited") == K::Undecided);   // without the citation: no antiderivative found

  // two true antiderivatives differ by a constant: citing both proves nothing about F itself
  Checked k = check_text(
      "symbol y : real [1]\n"
      "a1: integral(cos(y), y) = sin(y)\n    by integrate\n"
      "a2: integral(cos(y), y) = sin(y) + 1\n    by integrate\n"
      "bogus: sin(y) = sin(y) + 1\n    by rewrite a1, a2\n");
  CHECK(k.kind("a1") == K::Proved);
  CHECK(k.kind("a2") == K::Proved);
  CHECK(k.kind("bogus") == K::Refuted);

  // an antiderivative checked on the declared domain only (x in [0, 1]: x^2/2 for sqrt(x^2)) is
  // not one on the whole line, so it says nothing about the integral from -1 to 1 (which is 1)
  Checked d = check_text(
      "symbol x : in [0, 1] [1]\n"
      "symbol y : real [1]\n"
      "anti: integral(sqrt(x^2), x) = x^2/2\n    by integrate\n"
      "zero: integral(sqrt(y^2), y, -1, 1) = 0\n    by rewrite anti\n");
  CHECK(d.kind("anti") != K::Refuted);
  CHECK(d.kind("zero") != K::Proved);
  CHECK(d.kind("zero") != K::HoldsNumerically);
}

TEST_CASE("integrate: a reference that mentions the upper limit is no licence for the derivative test", "[integrate]") {
  // d/dT of a closed form checked against the integrand at T is valid only for T free: a
  // reference that pins T (a period) or makes the integrand depend on T (F(t) = F0*t/T) made
  // false claims pass. The integral is computed as a function of T instead.
  using K = dc::VerdictKind;
  test_support::Checked c = test_support::check_text(
      "symbol t, T : positive [s]\n"
      "symbol t2 : positive [s]\n"
      "symbol omega : positive [1/s]\n"
      "symbol F0 : positive [N]\n"
      "function F(t) : real [N]\n"
      "function A(t) : real [1]\n"
      "period: T = 2*pi/omega\n    by given\n"
      "over_period: integral(sin(omega*t), t, 0, T) = 0\n    by integrate period wrt t\n"
      "half_period_slip: integral(sin(omega*t/2), t, 0, T) = 0\n    by integrate period wrt t\n"
      "half_period: integral(sin(omega*t/2), t, 0, T) = 4/omega\n    by integrate period wrt t\n"
      "ramp: F(t) = F0*t/T\n    by given\n"
      "impulse: integral(F(t), t, 0, T) = F0*T/2\n    by integrate ramp wrt t\n"
      "impulse_slip: integral(F(t), t, 0, T) = F0*T\n    by integrate ramp wrt t\n"
      "rate: diff(A(t), t) = omega*sin(omega*t/2)\n    by given\n"
      "end: t2 = 2*pi/omega\n    by given\n"
      "change_slip: A(t2) - A(0) = 0\n    by integrate rate, end wrt t from 0\n"
      "change: A(t2) - A(0) = 4\n    by integrate rate, end wrt t from 0\n",
      "limits.dc");
  CHECK(c.kind("over_period") == K::Proved);
  CHECK(c.kind("half_period_slip") == K::Refuted);
  CHECK(c.kind("half_period") == K::Proved);
  CHECK(c.kind("impulse") == K::Proved);
  CHECK(c.kind("impulse_slip") == K::Refuted);
  CHECK(c.kind("change_slip") == K::Refuted);
  CHECK(c.kind("change") == K::Proved);
  for (const char* label : {"over_period", "half_period", "impulse", "change"}) {
    CAPTURE(label);
    CHECK(c.at(label).errors.empty());
  }
}
