// Integer-valued symbols (issue 24, item 4): `symbol n : positive integer`, `--assume 'n integer'`
// and the claim bank's assume field. True identities in integer n are proved (sin(n*pi) = 0),
// false ones are refuted at an integer witness, and a real n is unaffected.
#include <catch2/catch.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include "derivations/calculus/install.hpp"
#include "derivations/claims/claims.hpp"
#include "derivations/decide/integer.hpp"
#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace {

dc::Verdict equal(const std::string& l, const std::string& r, const std::string& assume = "") {
  dc::calculus::install();
  return dc::check_equal(l, r, assume);
}

dc::CheckSummary check(const std::string& name, const std::string& text) {
  dc::calculus::install();
  return dc::check_derivation(dc::parse_derivation(dc::SourceText{name, text}));
}

// The value of `name` at a counterexample, as written there.
std::string at(const dc::Verdict& v, const std::string& name) {
  for (const auto& [k, val] : v.point)
    if (k == name) return val;
  return "";
}

bool is_integer_text(const std::string& s) {
  if (s.empty()) return false;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!(std::isdigit(static_cast<unsigned char>(s[i])) || (i == 0 && s[i] == '-'))) return false;
  return true;
}

}  // namespace

TEST_CASE("parse_domain: integer, with a sign, and integer intervals", "[integer][domain]") {
  const dc::SourcePos at{"d.dc", 1, 1};
  dc::Domain d = dc::parse_domain("integer", at);
  CHECK(d.integer);
  CHECK(d.kind == dc::Domain::Kind::Real);
  CHECK(d.to_string() == "integer");
  dc::Domain p = dc::parse_domain("positive integer", at);
  CHECK(p.integer);
  CHECK(p.kind == dc::Domain::Kind::Positive);
  CHECK(p.to_string() == "positive integer");
  CHECK(dc::parse_domain("nonnegative integer", at).to_string() == "nonnegative integer");
  dc::Domain i = dc::parse_domain("integer in [1, 10]", at);
  CHECK(i.integer);
  CHECK(i.to_string() == "integer in [1, 10]");
  CHECK(i.contains(3));
  CHECK_FALSE(i.contains(GiNaC::numeric(5, 2)));
  CHECK_FALSE(i.contains(11));
  CHECK_FALSE(p.contains(0));
  CHECK(dc::parse_domain("integer in (0, 1)", at).empty());
  CHECK_FALSE(dc::parse_domain("integer in (0, 1]", at).empty());
  CHECK_FALSE(dc::parse_domain("in (0, 1)", at).empty());
  CHECK_THROWS_AS(dc::parse_domain("integer positive", at), dc::InputError);
}

TEST_CASE("integer_valued and the reduction of integer periods", "[integer]") {
  dc::calculus::install();
  dc::SymbolTable t;
  dc::SymbolInfo n;
  n.name = "n";
  n.domain = dc::parse_domain("integer", {"d", 1, 1});
  t.declare(n);
  dc::SymbolInfo x;
  x.name = "x";
  t.declare(x);
  const GiNaC::ex N = t.find("n")->sym, X = t.find("x")->sym;
  CHECK(dc::integer_valued(2 * N + 3, t));
  CHECK(dc::integer_valued(N * N - N, t));
  CHECK_FALSE(dc::integer_valued(N / 2, t));
  CHECK_FALSE(dc::integer_valued(X, t));
  CHECK(dc::reduce_integer_periods(GiNaC::sin(N * GiNaC::Pi), t).is_zero());
  CHECK(dc::reduce_integer_periods(GiNaC::cos(2 * N * GiNaC::Pi), t).is_equal(1));
  CHECK(dc::reduce_integer_periods(GiNaC::pow(-1, 2 * N), t).is_equal(1));
  CHECK(dc::reduce_integer_periods(GiNaC::pow(-1, N * N + N), t).is_equal(1));
  CHECK(dc::reduce_integer_periods(GiNaC::exp(2 * GiNaC::Pi * GiNaC::I * N), t).is_equal(1));
  CHECK(dc::reduce_integer_periods(GiNaC::exp(GiNaC::Pi * GiNaC::I * N), t).is_equal(GiNaC::pow(-1, N)));
  // half periods and real symbols are left alone
  CHECK(dc::reduce_integer_periods(GiNaC::sin(N * GiNaC::Pi / 2), t).is_equal(GiNaC::sin(N * GiNaC::Pi / 2)));
  CHECK(dc::reduce_integer_periods(GiNaC::sin(X * GiNaC::Pi), t).is_equal(GiNaC::sin(X * GiNaC::Pi)));
  // exp(2*pi*I*n) = 1 is proved by the cascade for an integer n
  dc::Verdict v = dc::prove_equal(GiNaC::exp(2 * GiNaC::Pi * GiNaC::I * N), 1, t);
  CAPTURE(v.detail, v.reason);
  CHECK(v.kind == dc::VerdictKind::Proved);
  CHECK(v.method.rfind("integer periods", 0) == 0);
}

TEST_CASE("equal --assume 'n integer': true identities proved, false ones refuted at an integer", "[integer][claims]") {
  for (const char* lhs : {"sin(n*pi)", "sin(x + 2*n*pi) - sin(x)", "tan(n*pi)"}) {
    dc::Verdict v = equal(lhs, "0", "n integer");
    CAPTURE(lhs, v.detail, v.reason);
    CHECK(v.kind == dc::VerdictKind::Proved);
  }
  for (auto [l, r] : {std::pair<const char*, const char*>{"cos(2*n*pi)", "1"},
                      {"(-1)^(2*n)", "1"},
                      {"cos(n*pi)", "(-1)^n"},
                      {"(-1)^(n^2 + n)", "1"},
                      {"cos(x + n*pi)", "(-1)^n*cos(x)"}}) {
    dc::Verdict v = equal(l, r, "n integer");
    CAPTURE(l, r, v.detail, v.reason);
    CHECK(v.kind == dc::VerdictKind::Proved);
  }
  // false in integer n: refuted, the witness an integer
  for (auto [l, r] : {std::pair<const char*, const char*>{"sin(n*pi/2)", "0"},
                      {"cos(n*pi)", "1"},
                      {"(-1)^n", "1"},
                      {"cos(n*pi)", "(-1)^(n + 2*n)*(-1)"}}) {
    dc::Verdict v = equal(l, r, "n integer");
    CAPTURE(l, r, v.detail);
    CHECK(v.kind == dc::VerdictKind::Refuted);
    CHECK(is_integer_text(at(v, "n")));
  }
  // a real n is unaffected: sin(n*pi) = 0 is refuted as before, at a non-integer
  dc::Verdict real = equal("sin(n*pi)", "0");
  CHECK(real.kind == dc::VerdictKind::Refuted);
  CHECK_FALSE(is_integer_text(at(real, "n")));
  CHECK(equal("sin(n*pi)", "0", "n > 0").kind == dc::VerdictKind::Refuted);
  // `n integer, n > 0` together: a positive integer
  dc::Verdict pos = equal("sqrt(n^2)", "n", "n integer, n > 0");
  CHECK(pos.holds());
  dc::Verdict f = equal("sin(n*pi/2)", "1", "n > 0, n integer");
  CHECK(f.kind == dc::VerdictKind::Refuted);
  CHECK(is_integer_text(at(f, "n")));
  CHECK_THROWS_AS(equal("n", "n", "n integer, n in (0, 1)"), dc::InputError);
}

TEST_CASE("integer symbols in powers: x^n needs no positive base", "[integer][claims]") {
  dc::Verdict v = equal("x^n*x", "x^(n + 1)", "n nonnegative integer");
  CAPTURE(v.detail, v.reason);
  CHECK(v.holds());
  dc::Verdict w = equal("x^n*x", "x^(n + 2)", "n nonnegative integer");
  CHECK(w.kind == dc::VerdictKind::Refuted);
}

TEST_CASE("a claims line: assume 'n integer' and the assumptions object", "[integer][claims]") {
  dc::calculus::install();
  auto r = dc::check_claim_line(R"J({"id":"a","kind":"equal","lhs":"cos(2*n*pi)","rhs":"1","assume":"n integer"})J", 1,
                                "bank.jsonl");
  CAPTURE(r.dump());
  CHECK(r.at("verdict") == "proved");
  auto o = dc::check_claim_line(
      R"J({"id":"b","kind":"equal","lhs":"sin(n*pi)","rhs":"0","assumptions":{"n":"positive integer"}})J", 2,
      "bank.jsonl");
  CHECK(o.at("verdict") == "proved");
  auto m = dc::check_claim_line(
      R"J({"id":"c","kind":"equal","lhs":"cos(n*pi)","rhs":"1","assumptions":{"n":"integer"},"assume":"n > 0"})J", 3,
      "bank.jsonl");
  CAPTURE(m.dump());
  CHECK(m.at("verdict") == "refuted");
}

TEST_CASE(".dc: the particle in a box, sin(n*pi*x/L) vanishes at x = L", "[integer][format]") {
  auto s = check("box.dc",
                 "symbol n : positive integer [1]\n"
                 "symbol L : positive [m]\n"
                 "symbol x : real [m]\n"
                 "symbol psi, A : real [m^(-1/2)]\n"
                 "wave: psi = A*sin(n*pi*x/L)\n"
                 "    by given\n"
                 "edge: psi = 0\n"
                 "    by substitute x = L into wave\n"
                 "half: psi = A*(-1)^n\n"
                 "    by substitute x = L/2 into wave\n"
                 "two: psi = 0\n"
                 "    by substitute x = 2*L into wave\n");
  REQUIRE(s.results.size() == 4);
  CAPTURE(s.results[1].verdict.detail, s.results[1].verdict.reason);
  CHECK(s.results[1].verdict.kind == dc::VerdictKind::Proved);
  CHECK(s.results[3].verdict.kind == dc::VerdictKind::Proved);
  // sin(n*pi/2) is not (-1)^n: refuted at an integer n
  CHECK(s.results[2].verdict.kind == dc::VerdictKind::Refuted);
  CHECK(is_integer_text(at(s.results[2].verdict, "n")));

  // the same file with a real n: the edge step is refuted
  auto r = check("box_real.dc",
                 "symbol n : positive [1]\n"
                 "symbol L : positive [m]\n"
                 "symbol x : real [m]\n"
                 "symbol psi, A : real [m^(-1/2)]\n"
                 "wave: psi = A*sin(n*pi*x/L)\n"
                 "    by given\n"
                 "edge: psi = 0\n"
                 "    by substitute x = L into wave\n");
  REQUIRE(r.results.size() == 2);
  CHECK(r.results[1].verdict.kind == dc::VerdictKind::Refuted);
}

TEST_CASE(".dc: a value named for an integer symbol must be an integer", "[integer][format]") {
  auto s = check("val.dc",
                 "symbol n, m : integer [1]\n"
                 "symbol k : integer [1]\n"
                 "a: k = n + 2*m\n"
                 "    by definition\n");
  REQUIRE(s.results.size() == 1);
  CAPTURE(s.results[0].verdict.detail, s.results[0].verdict.reason);
  CHECK(s.results[0].verdict.kind != dc::VerdictKind::Refuted);
  auto bad = check("val2.dc",
                   "symbol k : positive integer [1]\n"
                   "a: k = 1/2\n"
                   "    by definition\n");
  REQUIRE(bad.results.size() == 1);
  CAPTURE(bad.results[0].verdict.detail);
  CHECK(bad.results[0].verdict.kind == dc::VerdictKind::Refuted);
  // a half of an integer is not known to be one: undecided, never accepted
  auto half = check("val3.dc",
                    "symbol n : integer [1]\n"
                    "symbol k : integer [1]\n"
                    "a: k = n/2\n"
                    "    by definition\n");
  REQUIRE(half.results.size() == 1);
  CHECK(half.results[0].verdict.kind != dc::VerdictKind::Refuted);
  bool noted = false;
  for (const auto& sc : half.results[0].verdict.side_conditions)
    noted = noted || (sc.what.find(" is integer") != std::string::npos && sc.status == dc::SideCondition::Status::Unknown);
  CHECK(noted);
}

TEST_CASE("integer symbols: no derivative with respect to them, limits only at infinity", "[integer][calculus]") {
  CHECK_THROWS_AS(equal("diff(sin(n*pi*x), n)", "pi*x*cos(n*pi*x)", "n integer"), dc::InputError);
  // a limit over the reals is also the sequence's
  dc::Verdict v = equal("limit(1/n, n, oo)", "0", "n positive integer");
  CAPTURE(v.detail, v.reason);
  CHECK(v.holds());
  // sin(n*pi) has no limit over the reals, but the sequence is 0: never refuted
  dc::Verdict w = equal("limit(sin(n*pi), n, oo)", "0", "n positive integer");
  CAPTURE(w.detail, w.reason);
  CHECK(w.kind != dc::VerdictKind::Refuted);
}
