// Literate text in .dc files (docs/format.md, "Text"): headings, paragraphs with inline math
// and expressions, remarks, figure placeholders and hidden helper steps are read in file order
// with their places among the steps; malformed text is a positioned input error; the checker
// ignores the text (verdicts do not change).
#include <catch2/catch.hpp>

#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/report/latex.hpp"
#include "derivations/syntax/prose.hpp"
#include "derivations/rules/check.hpp"

namespace {

const char* kDecl = "symbol m1, v1 : positive [1] tex \"m_1\", \"v_1\"\nsymbol p1 : real [1]\n";

dc::Derivation parse(const std::string& body) { return dc::parse_derivation(dc::SourceText{"p.dc", kDecl + body}); }

dc::InputError error_of(const std::string& body) {
  try {
    parse(body);
  } catch (const dc::InputError& e) {
    return e;
  }
  FAIL("no error for: " << body);
  throw;
}

}  // namespace

TEST_CASE("text, headings, remarks and figures are read in place", "[format][prose]") {
  dc::Derivation d = parse(
      "heading \"Momentum\"\n"
      "text\n"
      "    The momentum `m1*v1` of the\n"
      "    first particle, and $\\Delta p$ *changes* \\# 3. # a comment\n"
      "a: p1 = m1*v1\n"
      "    by given\n"
      "figure \"Two balls\"\n"
      "remark Nothing is lost.\n"
      "b: p1 = v1*m1\n"
      "    by rewrite a\n"
      "    hide\n"
      "text After the last step.\n");
  REQUIRE(d.steps.size() == 2);
  REQUIRE(d.prose.size() == 5);
  CHECK(d.prose[0].kind == dc::Prose::Kind::Heading);
  CHECK(d.prose[0].before_step == 0);
  CHECK(d.prose[1].kind == dc::Prose::Kind::Paragraph);
  CHECK(dc::prose_plain_text(d.prose[1].pieces) == "The momentum `m1*v1` of the first particle, and $\\Delta p$ changes # 3.");
  REQUIRE(d.prose[1].pieces.size() == 7);   // text, expr, text, math, text, emph, text
  CHECK(d.prose[1].pieces[1].kind == dc::ProsePiece::Kind::Expr);
  CHECK(d.prose[1].pieces[3].kind == dc::ProsePiece::Kind::Math);
  CHECK(d.prose[1].pieces[5].kind == dc::ProsePiece::Kind::Emph);
  CHECK(d.prose[2].kind == dc::Prose::Kind::Figure);
  CHECK(d.prose[2].before_step == 1);
  CHECK(d.prose[3].kind == dc::Prose::Kind::Remark);
  CHECK(d.prose[4].before_step == 2);
  CHECK_FALSE(d.steps[0].hidden);
  CHECK(d.steps[1].hidden);

  // the text is printed in place, the expression with the file's TeX names, the hidden step not
  std::string tex = dc::write_latex(d, dc::LatexOptions{});
  auto at = [&](const std::string& s) { return tex.find(s); };
  CHECK(at("\\subsection*{Momentum}") < at("The momentum $m_1 v_1$ of the first particle, and $\\Delta p$ \\emph{changes} \\# 3."));
  CHECK(at("\\# 3.") < at("% a (p.dc:"));
  CHECK(at("% a (p.dc:") < at("\\textit{Figure:} Two balls"));
  CHECK(at("\\paragraph*{Remark.} Nothing is lost.") < at("After the last step."));
  CHECK(at("% b (p.dc:") == std::string::npos);
  // --annotate shows the hidden step, and says so
  dc::LatexOptions annotated;
  annotated.annotate = true;
  std::string atex = dc::write_latex(d, annotated);
  CHECK(atex.find("% b (p.dc:") != std::string::npos);
  CHECK(atex.find("(hidden in the handout)") != std::string::npos);

  // text changes no verdict
  dc::Derivation plain = parse("a: p1 = m1*v1\n    by given\nb: p1 = v1*m1\n    by rewrite a\n");
  CHECK(dc::check_derivation(d).results[1].verdict.kind == dc::check_derivation(plain).results[1].verdict.kind);
}

TEST_CASE("malformed text is a positioned input error", "[format][prose][errors]") {
  struct Case {
    const char* body;
    int line, col;
    const char* message;
  };
  auto c = GENERATE(values<Case>({
      {"text\n    a $x + 1 and more\na: m1 = m1\n    by given\n", 4, 7, "unterminated math"},
      {"text see `m1*w` here\na: m1 = m1\n    by given\n", 3, 14, "'w'"},
      {"text see `m1*` here\na: m1 = m1\n    by given\n", 3, 0, ""},
      {"text\na: m1 = m1\n    by given\n", 3, 1, "empty text"},
      {"heading\na: m1 = m1\n    by given\n", 3, 0, "expected a quoted heading"},
      {"text a $\\frac{1}{2$ b\na: m1 = m1\n    by given\n", 3, 8, "unbalanced '{'"},
      {"a: m1 = m1\n    by given\n    hide now\n", 5, 10, "unexpected text 'now'"},
      {"figure \"\"\na: m1 = m1\n    by given\n", 3, 0, "empty figure"},
  }));
  CAPTURE(c.body);
  dc::InputError e = error_of(c.body);
  CAPTURE(e.what());
  CHECK(e.pos().line == c.line);
  if (c.col) CHECK(e.pos().col == c.col);
  CHECK(std::string(e.what()).find(c.message) != std::string::npos);
}

TEST_CASE("a file with only text and no step is still 'no steps'", "[format][prose][errors]") {
  dc::InputError e = error_of("text Just words.\n");
  CHECK(std::string(e.what()).find("no steps") != std::string::npos);
}

TEST_CASE("an inline expression may be an equation whose sides are checked symbols", "[format][prose]") {
  dc::Derivation d = parse("text\n    with `p1 = m1*v1` the momentum is known\ns: p1 = m1*v1\n    by given\n");
  REQUIRE(d.prose.size() == 1);
  bool found = false;
  for (const auto& p : d.prose[0].pieces)
    if (p.kind == dc::ProsePiece::Kind::Expr) found = p.more.size() == 1;
  CHECK(found);
  const dc::InputError e = error_of("text\n    with `p1 = m1*w` it is slow\ns: p1 = m1*v1\n    by given\n");
  CHECK(std::string(e.what()).find("'w'") != std::string::npos);
}
