// The antiderivative rules and definite / improper integrals (derivations/integrals/).
//   - every textbook integrand of the table gets an antiderivative, proved by differentiation;
//   - each definite integral's value agrees with Arb's rigorous quadrature (an independent
//     method: adaptive Gauss-Legendre with certified error bounds);
//   - improper integrals get their textbook values; divergent ones and oscillating ones are
//     reported as such;
//   - a singularity inside the interval, a range outside the domain or an unknown order of the
//     limits never produces a value.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/calculus/antiderivative.hpp"
#include "derivations/calculus/definite.hpp"
#include "derivations/kernel/quadrature.hpp"

namespace {

using GiNaC::ex;
using dc::integrals::Definite;

struct Env {
  dc::SymbolTable table;
  ex xe;   // the declared symbol (a realsymbol: never copy it into a GiNaC::symbol, that slices it)
  const GiNaC::symbol& x() const { return GiNaC::ex_to<GiNaC::symbol>(xe); }
  Env() {
    dc::SymbolInfo si;
    si.name = "x";
    xe = table.declare(si).sym;   // declare() makes the symbol
    dc::SymbolInfo a;
    a.name = "a";
    a.domain = dc::Domain::positive();
    table.declare(a);
  }
  ex parse(const std::string& text) const { return dc::to_ginac(dc::parse_expression(text, dc::SourcePos{}), table); }
};

const Env& env() {
  static const Env e;
  return e;
}

}  // namespace

TEST_CASE("textbook integrands: antiderivative proved, definite value = rigorous quadrature", "[integrals]") {
  struct Case {
    const char* f;
    const char* a;
    const char* b;
  };
  const Case cases[] = {
      {"x^3 - 2*x + 1", "0", "2"},         {"exp(3*x)", "0", "1"},             {"sin(2*x + 1)", "0", "1"},
      {"cos(x/3)", "-1", "2"},             {"1/(2*x + 3)", "0", "1"},          {"(2*x + 1)^(-3)", "0", "1"},
      {"sqrt(4*x + 1)", "0", "2"},         {"1/sqrt(x + 1)", "0", "3"},        {"tan(x)", "0", "1"},
      {"log(x)", "1", "3"},                {"atan(x)", "0", "1"},              {"asin(x/2)", "0", "1"},
      {"acos(x)", "0", "1/2"},             {"2^x", "0", "3"},                  {"1/(1 + x^2)", "-1", "2"},
      {"1/sqrt(1 - x^2)", "0", "1/2"},     {"1/sqrt(x^2 + 1)", "0", "1"},      {"x*exp(x)", "0", "1"},
      {"x^2*sin(x)", "0", "2"},            {"x^3*cos(2*x)", "0", "1"},         {"x*log(x)", "1", "2"},
      {"x^2*log(x + 1)", "0", "1"},        {"exp(x)*sin(x)", "0", "1"},        {"exp(-2*x)*cos(3*x)", "0", "2"},
      {"1/(x*(x + 1))", "1", "2"},         {"(3*x + 2)/(x^2 + 4*x + 3)", "0", "1"},
      {"1/(x^2 - 4)", "3", "5"},           {"(x^3 + 1)/(x - 2)", "3", "4"},    {"1/(x^2 + 2*x + 5)", "0", "1"},
      {"x/(x^2 + 1)", "0", "2"},           {"1/(x - 1)^2", "2", "3"},          {"(x + 1)/(x^2 + 1)", "0", "1"},
      {"1/(x^3 + 1)", "0", "1"},           {"x*exp(x^2)", "0", "1"},           {"x*sin(x^2)", "0", "1"},
      {"sin(x)*cos(x)", "0", "1"},         {"log(x)/x", "1", "2"},             {"exp(x)/(1 + exp(x))", "0", "1"},
      {"x^3*exp(-x^2)", "0", "1"},         {"sin(x)^2", "0", "2"},             {"cos(x)^3", "0", "1"},
      {"cos(x)*exp(sin(x))", "0", "1"},    {"sin(3*x)*cos(x)", "0", "1"},      {"sin(x)^2*cos(x)", "0", "1"},    {"1/(x*log(x))", "2", "3"},         {"(x + 1)^5*x", "0", "1"},
      {"exp(-x/a)", "0", "1"},
  };
  const Env& E = env();
  for (const Case& c : cases) {
    const ex f = E.parse(c.f);
    CAPTURE(c.f);
    const auto F = dc::integrals::antiderivative(f, E.x(), E.table);
    REQUIRE(F);
    const ex a = E.parse(c.a), b = E.parse(c.b);
    const Definite d = dc::integrals::definite_integral(f, E.x(), a, 0, b, 0, E.table);
    CAPTURE(d.why, d.evidence);
    REQUIRE(d.kind == Definite::Kind::Value);
    if (f.has(E.table.find("a")->sym)) continue;   // a parameter: no quadrature
    const dc::kernel::Ball q = dc::kernel::integrate_constant(f, E.x(), a, b, 128);
    GiNaC::numeric lo, hi;
    REQUIRE(q.exact_bounds(lo, hi));
    GiNaC::Digits = 40;
    const ex v = d.value.evalf();
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(v));
    const GiNaC::numeric tol("1e-30");
    CHECK(GiNaC::ex_to<GiNaC::numeric>(v) >= lo - tol);
    CHECK(GiNaC::ex_to<GiNaC::numeric>(v) <= hi + tol);
  }
}

TEST_CASE("improper integrals: textbook values, divergence, non-existence", "[integrals][improper]") {
  struct Case {
    const char* f;
    const char* a;   // "-oo" allowed
    const char* b;   // "oo" allowed
    Definite::Kind kind;
    const char* value;   // exact value for Kind::Value
  };
  using K = Definite::Kind;
  const Case cases[] = {
      {"exp(-x)", "0", "oo", K::Value, "1"},
      {"x^4*exp(-x)", "0", "oo", K::Value, "24"},
      {"exp(-a*x)", "0", "oo", K::Value, "1/a"},
      {"1/(1 + x^2)", "-oo", "oo", K::Value, "pi"},
      {"1/(x^2 + a^2)", "0", "oo", K::Value, "pi/(2*a)"},
      {"1/x^2", "1", "oo", K::Value, "1"},
      {"1/sqrt(x)", "0", "1", K::Value, "2"},
      {"log(x)", "0", "1", K::Value, "-1"},
      {"1/sqrt(1 - x^2)", "-1", "1", K::Value, "pi"},
      {"x*exp(-x^2)", "-oo", "oo", K::Value, "0"},
      {"exp(-x)*sin(x)", "0", "oo", K::Value, "1/2"},
      {"1/(x*(x + 1))", "1", "oo", K::Value, "log(2)"},
      {"1/(x*log(x)^2)", "2", "oo", K::Value, "1/log(2)"},
      {"exp(x)", "-oo", "0", K::Value, "1"},
      {"exp(x)", "0", "a - 1", K::Value, "exp(a - 1) - 1"},   // either order: exp is continuous everywhere
      {"1/x", "1", "oo", K::Diverges, ""},
      {"1/x", "0", "1", K::Diverges, ""},
      {"1/x^2", "0", "1", K::Diverges, ""},
      {"1/(x*log(x))", "2", "oo", K::Diverges, ""},
      {"sqrt(x)", "0", "oo", K::Diverges, ""},
      {"sin(x)", "0", "oo", K::DoesNotExist, ""},
      {"cos(2*x)", "-oo", "0", K::DoesNotExist, ""},
  };
  const Env& E = env();
  for (const Case& c : cases) {
    CAPTURE(c.f, c.a, c.b);
    const int a_inf = std::string(c.a) == "-oo" ? -1 : 0, b_inf = std::string(c.b) == "oo" ? 1 : 0;
    const Definite d = dc::integrals::definite_integral(E.parse(c.f), E.x(), a_inf ? ex(0) : E.parse(c.a), a_inf,
                                                        b_inf ? ex(0) : E.parse(c.b), b_inf, E.table);
    CAPTURE(d.why, d.evidence);
    REQUIRE(d.kind == c.kind);
    if (c.kind == K::Value) CHECK((d.value - E.parse(c.value)).evalf().is_zero());
  }
}

TEST_CASE("integrals: no value across a singularity, outside a domain or with limits of unknown order",
          "[integrals][soundness]") {
  struct Case {
    const char* f;
    const char* a;
    const char* b;
  };
  const Case cases[] = {
      {"1/x", "-1", "1"},            // a pole inside: the integral diverges
      {"1/x^3", "-1", "2"},          // ditto (log(b^2)/2 style answers would be wrong)
      {"1/(x^2 - 1)", "0", "2"},     // a pole at 1
      {"tan(x)", "0", "2"},          // a pole at pi/2
      {"sqrt(x - 1)", "0", "2"},     // not real on (0, 1)
      {"log(x)", "-1", "1"},         // not real on (-1, 0]
      {"1/(x - a)", "0", "1"},       // a in (0, 1) for some values of a
      {"1/(1 + x)", "0", "a - 2"},   // a - 2 may be below 0, even below -1: unknown order, a pole
      {"exp(-x^2)", "0", "1"},       // no elementary antiderivative: no value from this method
  };
  const Env& E = env();
  for (const Case& c : cases) {
    CAPTURE(c.f, c.a, c.b);
    const Definite d = dc::integrals::definite_integral(E.parse(c.f), E.x(), E.parse(c.a), 0, E.parse(c.b), 0, E.table);
    CAPTURE(d.evidence);
    CHECK(d.kind == Definite::Kind::Unknown);
    CHECK_FALSE(d.why.empty());
  }
}
