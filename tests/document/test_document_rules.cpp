// The author's own rule for a row (derivations/document/rule_comments.cpp): a comment
// `% by solve (9.6), (9.7) for v'_1, v'_2` checks the row as the same .dc step, with the
// document's tags, labels and TeX names, instead of the search.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/document/document.hpp"
#include "document/document_rows.hpp"

using document_test::at;
using document_test::check;

namespace {

const std::string kLaws =
    "\\begin{align}\n"                                                       // 1
    "  m_1 v_1 + m_2 v_2 &= m_1 v'_1 + m_2 v'_2 \\label{eq:mom} \\\\\n"      // 2
    "  v'_2 - v'_1 &= e (v_1 - v_2) \\label{eq:rest}\n"                       // 3
    "\\end{align}\n";                                                        // 4
const std::string kRight = "\\frac{m_1 v_1 + m_2 v_2 - e m_2 (v_1 - v_2)}{m_1 + m_2}";

}  // namespace

TEST_CASE("author's rule: a LaTeX comment in the display or on the line after it names the rule") {
  auto rows = check("a.tex", kLaws +
                                 "\\begin{equation}\n"                                                  // 5
                                 "  v'_1 = " + kRight + " % by solve \\eqref{eq:mom}, \\eqref{eq:rest} for v'_1, v'_2\n"   // 6
                                 "\\end{equation}\n"                                                    // 7
                                 "\\begin{equation}\n"                                                  // 8
                                 "  v'_1 = " + kRight + "\n"                                            // 9
                                 "\\end{equation}\n"                                                    // 10
                                 "% by solve eq:mom, eq:rest for v'_1, v'_2\n");                        // 11
  CHECK(at(rows, 6).verdict == "proved");
  CHECK(at(rows, 6).rule == "solve");
  CHECK(at(rows, 9).verdict == "proved");
  CHECK(at(rows, 9).rule == "solve");
}

TEST_CASE("author's rule: the rule is checked as written, a wrong one refutes, an ordinary comment is prose") {
  // the author's substitution does not give the row: refuted with a counterexample at positive values
  auto wrong = check("b.tex", kLaws +
                                  "\\begin{equation}\n"                                                 // 5
                                  "  v'_1 = " + kRight + " % by rewrite eq:mom\n"                       // 6
                                  "\\end{equation}\n");
  CHECK(at(wrong, 6).verdict == "refuted");
  CHECK(at(wrong, 6).rule == "rewrite");
  // `% by the way`: not a rule; the search finds the justification
  auto prose = check("c.tex", kLaws +
                                  "\\begin{equation}\n"
                                  "  v'_1 = " + kRight + " % by the way, both laws\n"                  // 6
                                  "\\end{equation}\n");
  CHECK(at(prose, 6).verdict == "proved");
  CHECK(at(prose, 6).rule != "solve");
}

TEST_CASE("author's rule: Markdown comment with tags, and positioned errors") {
  const std::string md = "$$F = m a \\quad (1)$$\n"                           // 1
                         "\n"
                         "$$a = g \\quad (2)$$\n"                             // 3
                         "\n"
                         "$$F = m g$$\n"                                      // 5
                         "<!-- by substitute (2) into (1) -->\n";             // 6
  auto rows = check("d.md", md);
  CHECK(at(rows, 5).verdict == "proved");
  CHECK(at(rows, 5).rule == "substitute");
  // addressed to the checker, a reference that names no row and an unknown rule are input
  // errors at the comment's line; the same words in a plain comment are the author's prose
  // (a warning), as is `by definition of …`
  try {
    dc::read_document(dc::SourceText{"e.md", "$$F = m a$$\n\n$$F = m g$$\n<!-- derivcheck: by substitute (7) into (1) -->\n"});
    FAIL("no error");
  } catch (const dc::InputError& e) {
    CHECK(e.pos().line == 4);
  }
  for (const char* prose : {"<!-- by substitute (7) into (1) -->", "<!-- by definition of the force -->"}) {
    const dc::Derivation d =
        dc::read_document(dc::SourceText{"g.md", std::string("$$F = m a$$\n\n$$F = m g$$\n") + prose + "\n"});
    CHECK(d.diagnostics.size() == 1);
  }
  CHECK_THROWS_AS(dc::read_document(dc::SourceText{"f.md", "$$F = m a$$\n<!-- derivcheck: by magic -->\n"}),
                  dc::InputError);
}
