// Domains, the symbol table and constraints.
#include <catch2/catch.hpp>

#include "derivations/kernel/sample.hpp"
#include "derivations/decide/prove.hpp"
#include "derivations/syntax/source.hpp"
#include "support.hpp"

using namespace dc;
using GiNaC::ex;
using GiNaC::numeric;

TEST_CASE("Domain: membership is exact, including pi bounds", "[symbols][domain]") {
  Domain unit = Domain::interval(0, false, 1, false);
  REQUIRE(unit.contains(0));
  REQUIRE(unit.contains(1));
  REQUIRE(unit.contains(numeric(1, 2)));
  REQUIRE_FALSE(unit.contains(numeric(-1, 1000000)));
  REQUIRE_FALSE(unit.contains(numeric(1000001, 1000000)));
  Domain open = Domain::interval(0, true, GiNaC::Pi, true);
  REQUIRE_FALSE(open.contains(0));
  REQUIRE(open.contains(numeric(314159, 100000)));   // 3.14159 < pi
  REQUIRE_FALSE(open.contains(numeric(314160, 100000)));  // 3.14160 > pi
  REQUIRE(Domain::positive().contains(numeric(1, 10)));
  REQUIRE_FALSE(Domain::positive().contains(0));
  REQUIRE(Domain::nonnegative().contains(0));
  REQUIRE_FALSE(Domain::negative().contains(0));
  REQUIRE(Domain::real().contains(-7));
}

TEST_CASE("Domain: positivity, emptiness and text", "[symbols][domain]") {
  REQUIRE(Domain::positive().strictly_positive());
  REQUIRE_FALSE(Domain::nonnegative().strictly_positive());
  REQUIRE(Domain::nonnegative().nonnegative_values());
  REQUIRE(Domain::interval(0, true, 1, false).strictly_positive());
  REQUIRE_FALSE(Domain::interval(0, false, 1, false).strictly_positive());
  REQUIRE(Domain::interval(1, true, 1, false).empty());
  REQUIRE(Domain::interval(2, false, 1, false).empty());
  REQUIRE_FALSE(Domain::interval(1, false, 1, false).empty());
  REQUIRE(Domain::interval(0, false, 1, false).to_string() == "in [0, 1]");
  REQUIRE(Domain::interval(0, true, GiNaC::Pi, true).to_string() == "in (0, pi)");
  REQUIRE(Domain::interval(-GiNaC::Pi / 2, false, 3 * GiNaC::Pi / 4, true).to_string() == "in [-pi/2, 3*pi/4)");
  REQUIRE(Domain::interval(numeric(-1, 2), true, 2, false).to_string() == "in (-1/2, 2]");
  REQUIRE(Domain::positive().to_string() == "positive");
  REQUIRE(Domain::real().to_string() == "real");
}

TEST_CASE("SymbolTable: symbol kinds, lookup, errors", "[symbols][table]") {
  test::Table T;
  T.add("m1", Domain::positive()).add("v1", Domain::real()).add("theta", Domain::interval(0, true, GiNaC::Pi / 2, true));
  ex m1 = T["m1"], v1 = T["v1"], th = T["theta"];
  // possymbol for strictly positive domains: GiNaC simplifies sqrt(m1^2) itself
  REQUIRE(GiNaC::sqrt(GiNaC::pow(m1, 2)).is_equal(m1));
  REQUIRE(GiNaC::sqrt(GiNaC::pow(th, 2)).is_equal(th));
  REQUIRE_FALSE(GiNaC::sqrt(GiNaC::pow(v1, 2)).is_equal(v1));
  REQUIRE(v1.info(GiNaC::info_flags::real));
  REQUIRE(T.t.find("m1")->name == "m1");
  REQUIRE(T.t.find("m1")->tex == "m_1");
  REQUIRE(T.t.find("theta")->tex == "\\theta");
  REQUIRE(T.t.find("nope") == nullptr);
  REQUIRE(T.t.find(GiNaC::ex_to<GiNaC::symbol>(v1))->name == "v1");
  GiNaC::symbol stranger("v1");  // same name, different symbol
  REQUIRE(T.t.find(stranger) == nullptr);

  SymbolInfo again;
  again.name = "v1";
  again.pos = SourcePos{"f.dc", 7, 3};
  try {
    T.t.declare(again);
    FAIL("redeclaration accepted");
  } catch (const InputError& e) {
    REQUIRE(e.pos().line == 7);
    REQUIRE(e.pos().col == 3);
    REQUIRE(e.message().find("already declared") != std::string::npos);
  }
  SymbolInfo empty;
  empty.name = "w";
  empty.domain = Domain::interval(1, true, 1, true);
  empty.pos = SourcePos{"f.dc", 9, 5};
  try {
    T.t.declare(empty);
    FAIL("empty domain accepted");
  } catch (const InputError& e) {
    REQUIRE(e.pos().line == 9);
    REQUIRE(e.message().find("empty") != std::string::npos);
  }
}

TEST_CASE("SymbolTable: functions are numbered in declaration order, at most 16", "[symbols][table]") {
  SymbolTable t;
  for (int i = 0; i < 16; ++i) {
    SymbolInfo f;
    f.name = "f" + std::to_string(i);
    f.is_function = true;
    t.declare(f);
    SymbolInfo s;
    s.name = "s" + std::to_string(i);
    t.declare(s);
  }
  REQUIRE(t.function_index("f0") == 0);
  REQUIRE(t.function_index("f7") == 7);
  REQUIRE(t.function_index("s3") == -1);
  REQUIRE(t.function_index("zz") == -1);
  SymbolInfo f;
  f.name = "f16";
  f.is_function = true;
  REQUIRE_THROWS_AS(t.declare(f), InputError);
}

TEST_CASE("kernel::holds_at", "[symbols][constraint]") {
  test::Table T;
  T.add("a", Domain::real()).add("b", Domain::real());
  ex a = T["a"], b = T["b"];
  Constraint gt{a, b, Constraint::Op::Gt, "a > b", {}};
  REQUIRE(dc::kernel::holds_at(gt, {{a, numeric(3, 2)}, {b, numeric(1, 2)}}));
  REQUIRE_FALSE(dc::kernel::holds_at(gt, {{a, numeric(1, 2)}, {b, numeric(1, 2)}}));
  Constraint ge{a, b, Constraint::Op::Ge, "a >= b", {}};
  REQUIRE(dc::kernel::holds_at(ge, {{a, numeric(1, 2)}, {b, numeric(1, 2)}}));
  Constraint ne{a * a, 2, Constraint::Op::Ne, "a^2 != 2", {}};
  REQUIRE(dc::kernel::holds_at(ne, {{a, numeric(7, 5)}}));
  Constraint lt_pi{a, GiNaC::Pi, Constraint::Op::Lt, "a < pi", {}};
  REQUIRE(dc::kernel::holds_at(lt_pi, {{a, numeric(314159, 100000)}}));
  REQUIRE_FALSE(dc::kernel::holds_at(lt_pi, {{a, numeric(314160, 100000)}}));
  Constraint div{1 / a, 1, Constraint::Op::Gt, "1/a > 1", {}};
  REQUIRE_FALSE(dc::kernel::holds_at(div, {{a, numeric(0)}}));  // undefined: not admissible
  REQUIRE_FALSE(dc::kernel::holds_at(gt, {{a, numeric(1)}}));   // b has no value
}
