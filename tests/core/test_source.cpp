// InputError formatting: GCC-style header, the quoted line and a caret under the column.
#include <catch2/catch.hpp>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/source.hpp"

using namespace dc;

TEST_CASE("InputError::format quotes the line and underlines the node", "[source]") {
  InputError e(SourcePos{"f.dc", 3, 5}, "undefined symbol 'v_e'", 3, "(v_e + g*t)/u_e");
  CHECK(e.format() == "f.dc:3:5: error: undefined symbol 'v_e'\n    (v_e + g*t)/u_e\n        ^~~\n");
  CHECK(std::string(e.what()) == "f.dc:3:5: error: undefined symbol 'v_e'");
  InputError bare(SourcePos{"f.dc", 1, 1}, "m");
  CHECK(bare.format() == "f.dc:1:1: error: m\n");
}

TEST_CASE("InputError::format counts UTF-8 characters for the caret", "[source]") {
  // Columns count bytes: '+' is byte 4 of "μ + x" (μ is two bytes) but the third character.
  InputError e(SourcePos{"f.dc", 1, 4}, "msg", 1, "μ + x");
  CHECK(e.format() == "f.dc:1:4: error: msg\n    μ + x\n      ^\n");
}

TEST_CASE("a parse error formats with its line", "[source]") {
  const std::string line = "x + + y";
  try {
    parse_expression(line, SourcePos{"<arg>", 1, 1});
    FAIL("no error");
  } catch (const InputError& err) {
    CHECK(err.with_line_text(line).format() ==
          "<arg>:1:5: error: expected an expression after '+', found '+'\n    x + + y\n        ^\n");
  }
}
