// The matchers as a user of the library writes them (docs/library.md): GiNaC::ex against a
// string (names matched to the user's own symbols), ex against ex, strings against strings,
// and the failure message Catch prints (each fact once).
#include <catch2/catch.hpp>

#include <string>

#include "derivations/catch/derivcheck_catch.hpp"

using dc::catch2::EqualsSymbolically;
using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::symbol;

namespace {
// What Catch prints under "with expansion:" for REQUIRE_THAT(arg, matcher).
template <class Arg, class Matcher>
std::string expansion(const Arg& arg, const Matcher& m) {
  Catch::MatchExpr<Arg, Matcher> expr(arg, m, "matcher");
  std::ostringstream os;
  expr.streamReconstructedExpression(os);
  return os.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}
}  // namespace

TEST_CASE("matchers: GiNaC::ex against a string, names matched to the user's symbols", "[matchers][library]") {
  symbol k("k"), A("A");
  ex E = numeric(1, 2) * k * GiNaC::pow(A, 2);
  REQUIRE_THAT(E, EqualsSymbolically("1/2*k*A^2").assuming("k>0"));
  REQUIRE_THAT(E, EqualsSymbolically("k*A^2/2"));
  // the domain comes from the assumptions, by name: |A| = A needs A >= 0
  REQUIRE_THAT(GiNaC::sqrt(GiNaC::pow(A, 2)), EqualsSymbolically("A").assuming("A>=0"));
  auto m = EqualsSymbolically("A");
  CHECK_FALSE(m.match(GiNaC::sqrt(GiNaC::pow(A, 2))));
  REQUIRE(m.verdict() != nullptr);
  CHECK(m.verdict()->kind == dc::VerdictKind::Refuted);
  // a symbol or a number on the left is an expression too
  REQUIRE_THAT(k, EqualsSymbolically("k"));
  REQUIRE_THAT(k - k, EqualsSymbolically(0));
}

TEST_CASE("matchers: a string against a GiNaC::ex, and ex against ex", "[matchers][library]") {
  symbol x("x"), y("y");
  REQUIRE_THAT("x^2 - y^2", EqualsSymbolically((x - y) * (x + y)));
  REQUIRE_THAT(std::string("log(x*y)"), EqualsSymbolically(GiNaC::log(x) + GiNaC::log(y)).assuming("x>0, y>0"));
  REQUIRE_THAT(GiNaC::pow(x + y, 2), EqualsSymbolically(x * x + 2 * x * y + y * y));
  REQUIRE_THAT("(x + y)^2", EqualsSymbolically("x^2 + 2*x*y + y^2"));
}

TEST_CASE("matchers: composition with ! for expressions", "[matchers][library]") {
  symbol x("x");
  REQUIRE_THAT(GiNaC::sqrt(x * x), !EqualsSymbolically(x));
}

TEST_CASE("matchers: the failure message has the counterexample once", "[matchers][library]") {
  symbol k("k"), A("A");
  ex E = k * GiNaC::pow(A, 2);   // the 1/2 forgotten
  auto m = EqualsSymbolically("1/2*k*A^2").assuming("k>0");
  REQUIRE_FALSE(m.match(E));
  REQUIRE(m.verdict() != nullptr);
  REQUIRE(m.verdict()->kind == dc::VerdictKind::Refuted);
  std::string shown = expansion(E, m);
  INFO(shown);
  CHECK_THAT(shown, Catch::StartsWith("A^2*k equals symbolically A^2*k/2 assuming k>0\n  verdict: refuted ("));
  // the text docs/library.md shows for this failure
  CHECK_THAT(shown, Catch::Contains("verdict: refuted (identity + numeric probe)\n"
                                    "  counterexample: A = -467/9870, k = 190358/42577\n"
                                    "  lhs = 0.010009111597434420177\n  rhs = 0.0050045557987172100884"));
  CHECK(count(shown, "counterexample:") == 1);
  CHECK(count(shown, "k = ") == 1);     // the point, once
  CHECK(count(shown, "lhs = ") == 1);   // both values, once
  CHECK(count(shown, "rhs = ") == 1);
  CHECK(count(shown, "differs at") == 0);
  // the same through the string overload
  auto t = EqualsSymbolically("x").assuming("x real");
  REQUIRE_FALSE(t.match("sqrt(x^2)"));
  std::string shown_t = expansion(std::string("sqrt(x^2)"), t);
  INFO(shown_t);
  CHECK(count(shown_t, "counterexample:") == 1);
  CHECK(count(shown_t, "x = ") == 1);
}

TEST_CASE("matchers: undecided states the residual and the reason once", "[matchers][library]") {
  // an undecided verdict as prove_equal makes it with the numeric probe off
  dc::Verdict v;
  v.kind = dc::VerdictKind::Undecided;
  v.method = "normal";
  v.residual = "x - y";
  v.reason = "the symbolic stages leave a nonzero residual and the numeric probe is off";
  v.detail = v.reason + "; residual: " + v.residual;
  std::string d = dc::catch2::detail::verdict_description(v);
  CHECK(count(d, "x - y") == 1);
  CHECK(count(d, "numeric probe is off") == 1);
}

TEST_CASE("matchers: a matcher used twice describes its latest match", "[matchers][library]") {
  auto m = EqualsSymbolically("x");
  CHECK_FALSE(m.match("x + 1"));
  std::string first = m.toString();
  CHECK(m.match("x"));
  CHECK(m.toString() != first);
  CHECK_THAT(m.toString(), Catch::Contains("verdict: proved"));
}

TEST_CASE("matchers: two different symbols with one name are an input error", "[matchers][library]") {
  symbol x1("x"), x2("x");
  auto m = EqualsSymbolically(ex(x2));
  CHECK_FALSE(m.match(x1));
  CHECK(m.verdict() == nullptr);
  CHECK_THAT(m.describe(), Catch::Contains("both named 'x'"));
}
