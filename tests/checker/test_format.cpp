// The .dc reader: every bad-input class gives an InputError with an exact position, the
// offending line, and what was expected (issue 2, item 8). Runaway input (10^5-deep
// parentheses, 2^(10^10), (a+b)^100000) is refused as an error, never a hang or a crash.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace {

std::string data(const std::string& rel) { return std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/" + rel; }

struct Expected {
  const char* file;
  int line, col;
  const char* message;   // a substring of the message
};

dc::InputError load_error(const std::string& path) {
  try {
    dc::load_derivation(path);
  } catch (const dc::InputError& e) {
    return e;
  }
  FAIL("no error for " << path);
  throw;
}

}  // namespace

TEST_CASE("malformed files give positioned errors saying what was expected", "[format][errors]") {
  auto x = GENERATE(values<Expected>({
      {"unknown_statement", 2, 1, "unknown statement 'symbl'; expected one of title, handout, section, symbol"},
      {"duplicate_label", 4, 1, "duplicate label 'a' (first defined at 2:1)"},
      {"later_label", 3, 16, "step 'b' is defined later (at 4:1)"},
      {"unknown_label", 3, 16, "unknown label 'nowhere'"},
      {"unknown_rule", 3, 8, "unknown rule 'magic'; known rules: given, definition, rewrite"},
      {"malformed_symbol", 1, 10, "expected ':' and a domain"},
      {"unknown_unit", 1, 18, "unknown unit 'kgs'"},
      {"undefined_symbol", 2, 8, "undefined symbol 'y'"},
      {"contradictory", 2, 1, "the assumptions cannot all hold"},
      {"contradictory_domain", 2, 1, "the assumptions cannot all hold"},
      {"missing_rule", 2, 1, "has no rule: expected an indented line 'by RULE"},
      {"indented_start", 1, 5, "unexpected indented line"},
      {"unterminated_string", 1, 7, "unterminated string"},
      {"unbalanced", 2, 14, "expected ')' to close '(' opened at 2:8"},
      {"huge_power", 2, 10, "too large"},
      {"expand_call", 2, 5, "expand"},
      {"solve_without_refs", 3, 14, "expected the labels of the equations to solve"},
      {"redeclared", 2, 8, "already declared at 1:8"},
      {"empty_domain", 1, 15, "is empty"},
  }));
  std::string path = data(std::string("errors/") + x.file + ".dc");
  dc::InputError e = load_error(path);
  std::string formatted = e.format();
  CAPTURE(x.file, formatted);
  CHECK(e.pos().file == path);
  CHECK(e.pos().line == x.line);
  CHECK(e.pos().col == x.col);
  CHECK(e.message().find(x.message) != std::string::npos);
  // GCC style with the offending line and a caret; no internals
  CHECK(formatted.rfind(path + ":" + std::to_string(x.line) + ":" + std::to_string(x.col) + ": error: ", 0) == 0);
  CHECK(formatted.find('^') != std::string::npos);
  CHECK(formatted.find("GiNaC") == std::string::npos);
  CHECK(formatted.find(".cpp") == std::string::npos);
}

TEST_CASE("a missing file is an input error naming the file", "[format][errors]") {
  dc::InputError e = load_error(data("errors/does_not_exist.dc"));
  CHECK(e.message().find("cannot read") != std::string::npos);
  CHECK(e.message().find("does_not_exist.dc") != std::string::npos);
}

TEST_CASE("10^5-deep parentheses are refused with a position", "[format][limits]") {
  std::string claim = std::string(100000, '(') + "x" + std::string(100000, ')');
  dc::SourceText src{"deep.dc", "symbol x : real [1]\na: x = " + claim + "\n    by given\n"};
  try {
    dc::parse_derivation(src);
    FAIL("accepted 10^5-deep parentheses");
  } catch (const dc::InputError& e) {
    CHECK(e.pos().line == 2);
    CHECK(e.pos().col >= 4);
    CHECK(e.format().size() < 2000);   // the quoted line is cut around the column
  }
}

TEST_CASE("100000 unary minus signs are refused", "[format][limits]") {
  dc::SourceText src{"minus.dc", "symbol x : real [1]\na: x = " + std::string(100000, '-') + "x\n    by given\n"};
  CHECK_THROWS_AS(dc::parse_derivation(src), dc::InputError);
}

TEST_CASE("the reader keeps positions across continuation lines", "[format]") {
  dc::SourceText src{"cont.dc",
                     "symbol m1, m2 : positive [kg]   # masses\n"
                     "symbol v1, v2 : real [m/s]\n"
                     "(9.6) total: m1*v1 +\n"
                     "        m2*v2 = m1*v1 + m2*v2\n"
                     "    by rewrite\n"
                     "    note \"continued # not a comment\"\n"};
  dc::Derivation d = dc::parse_derivation(src);
  REQUIRE(d.steps.size() == 1);
  const dc::Step& s = d.steps[0];
  CHECK(s.tag == "9.6");
  CHECK(s.label == "total");
  CHECK(s.pos.col == 7);
  CHECK(s.claim_pos.line == 3);
  CHECK(s.claim_pos.col == 14);
  CHECK(s.claim_text == "m1*v1 + m2*v2 = m1*v1 + m2*v2");
  REQUIRE(s.claim.sides.size() == 2);
  CHECK(s.claim.sides[1].pos.line == 4);
  CHECK(s.claim.sides[1].pos.col == 17);
  REQUIRE(s.notes.size() == 1);
  CHECK(s.notes[0] == "continued # not a comment");
  CHECK(s.rule.name == "rewrite");
}

TEST_CASE("rule lines are parsed into their argument groups", "[format][rules]") {
  dc::SourceText src{"args.dc",
                     "symbol m1, m2 : positive [kg]\n"
                     "symbol v1, v2, v1p : real [m/s]\n"
                     "a: v1p = (m1 - m2)*v1/(m1 + m2) + v2\n"
                     "    by given\n"
                     "b: v1p = -v1\n"
                     "    by limit m2 -> oo of a with v2 = 0\n"
                     "c: v1p = -v1 + v2\n"
                     "    by simplify a, b with m1 = 0\n"};
  dc::Derivation d = dc::parse_derivation(src);
  const dc::RuleSpec& b = d.find("b")->rule;
  CHECK(b.name == "limit");
  REQUIRE(b.var);
  CHECK(b.var->label == "m2");
  REQUIRE(b.point);
  CHECK(b.point->value.text == "oo");
  REQUIRE(b.into.size() == 1);
  CHECK(b.into[0].label == "a");
  REQUIRE(b.with.size() == 1);
  CHECK(b.with[0].kind == dc::RuleArg::Kind::Equation);
  const dc::RuleSpec& c = d.find("c")->rule;
  CHECK(c.name == "rewrite");
  CHECK(c.written_name == "simplify");
  REQUIRE(c.refs.size() == 2);
  CHECK(c.refs[1].label == "b");
  CHECK(c.refs[1].pos.col == 20);
}

TEST_CASE("formula() hands final formulas to the numeric module", "[format][formula]") {
  dc::Derivation d = dc::load_derivation(data("rules/substitute.dc"));
  dc::Formula f = dc::formula(d, "ok_substitute");
  CHECK(f.target == "v1p");
  CHECK(f.params.size() == 4);   // m1, m2, v1, v2 in declaration order
  CHECK(f.params[0].get_name() == "m1");
  CHECK_THROWS_AS(dc::formula(d, "nowhere"), dc::InputError);
  CHECK(dc::formulas(d).size() >= 3);
}

TEST_CASE("limit points carry a direction, oo, -oo and undefined are limit values only", "[format][rules]") {
  dc::SourceText src{"t.dc",
                     "symbol x : real [1]\n"
                     "a: 1/x = oo\n"
                     "    by limit x -> 0+\n"
                     "b: 1/x = -oo\n"
                     "    by limit x -> 0 -\n"
                     "c: 1/x = undefined\n"
                     "    by limit x -> 0\n"
                     "d: x = -oo\n"
                     "    by limit x -> -oo of a\n"};
  dc::Derivation d = dc::parse_derivation(src);
  CHECK(d.find("a")->rule.dir == 1);
  CHECK(d.find("a")->rule.point->value.text == "0");
  CHECK(d.find("a")->rule.into.empty());
  CHECK(d.find("b")->rule.dir == -1);
  CHECK(d.find("c")->rule.dir == 0);
  CHECK(d.find("d")->rule.dir == 0);
  CHECK(d.find("d")->rule.into.size() == 1);

  auto error_of = [](const std::string& text) -> std::string {
    try {
      dc::parse_derivation(dc::SourceText{"e.dc", "symbol x, y : real [1]\n" + text});
    } catch (const dc::InputError& e) {
      return std::to_string(e.pos().line) + ":" + std::to_string(e.pos().col) + " " + e.message();
    }
    return "no error";
  };
  // A direction goes with a finite point.
  CHECK(error_of("a: x = oo\n    by limit x -> oo+\n").find("3:21 a direction") == 0);
  // oo and undefined outside a limit step are not expressions.
  CHECK(error_of("a: y = oo\n    by given\n").find("2:8 'oo'") == 0);
  CHECK(error_of("a: y = undefined\n    by given\n").find("2:8 undefined symbol 'undefined'") == 0);
  // `to order N` (series only; elsewhere `to` may be a symbol).
  CHECK(error_of("a: sin(x) = x\n    by series x -> 0 to degree 3\n").find("3:25 expected 'order N' after 'to'") == 0);
  CHECK(error_of("a: sin(x) = x\n    by series x -> 0 to order 2.5\n").find("3:31 expected an integer order") == 0);
  CHECK(error_of("symbol to : real [1]\na: x = to\n    by given\nb: x = 2\n    by rewrite a with to = 2\n") == "no error");
  {
    dc::Derivation s = dc::parse_derivation(
        dc::SourceText{"s.dc", "symbol x : real [1]\na: sin(x) = x - x^3/6\n    by series x -> 0- to order -2\n"});
    REQUIRE(s.find("a")->rule.order);
    CHECK(*s.find("a")->rule.order == -2);
    CHECK(s.find("a")->rule.dir == -1);
  }
  // A limit(...) the engine cannot decide is not an input error of the file (fuzz_reader: the
  // whole file was lost with "reading this file did not finish").
  CHECK(error_of("symbol m : positive [1]\na: y = limit((m/x - 1)*y/(m/x), x, oo)\n    by given\n") == "no error");
  CHECK(error_of("assume limit((x - 1)*y, x, oo) > 0\n").find("2:8 this expression cannot be used in a declaration") == 0);
  // y'(T0) = value: a derivative's initial value, for solves_ode only.
  {
    dc::Derivation o = dc::parse_derivation(dc::SourceText{
        "o.dc", "symbol t : real [1]\nfunction x(t) : real [1]\node: diff(x(t), t, 2) = -x(t)\n    by given\n"
                "s: x(t) = sin(t)\n    by solves_ode ode wrt t with x(0) = 0, x''(0) = 0\n"});
    REQUIRE(o.find("s")->rule.with.size() == 2);
    CHECK(o.find("s")->rule.with[0].prime_order == 0);
    CHECK(o.find("s")->rule.with[1].prime_order == 2);
  }
  CHECK(error_of("function f(x) : real [1]\na: f(x) = x\n    by rewrite with f'(0) = 1\n").find("4:21 an initial value of a derivative") == 0);
  // A declared symbol named undefined keeps its meaning.
  CHECK(error_of("symbol undefined : real [1]\na: 1/x = undefined\n    by limit x -> 0\n") == "no error");
}

TEST_CASE("an interval's bounds may contain parentheses", "[format]") {
  dc::Derivation d = dc::parse_derivation(dc::SourceText{
      "i.dc", "symbol x : in (0, 10^(-40)) [1]\nsymbol z : in [(1), 2*(3)] [1]\na: x = x\n    by rewrite\n"});
  CHECK(d.symbols.find("x")->domain.to_string() == "in (0, 1/10000000000000000000000000000000000000000)");
  CHECK(d.symbols.find("z")->domain.to_string() == "in [1, 6]");
  try {
    dc::parse_derivation(dc::SourceText{"j.dc", "symbol x : in (0, (1) \na: x = x\n    by rewrite\n"});
    FAIL("no error");
  } catch (const dc::InputError& e) {
    CHECK(std::string(e.message()).find("expected ']' or ')' to close the interval") != std::string::npos);
    CHECK(e.pos().col == 15);
  }
}
