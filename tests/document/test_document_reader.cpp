// The document reader and the justification search (derivations/document/): LaTeX and
// Markdown read as written, every displayed relation a step with a verdict at its line.
#include <catch2/catch.hpp>

#include <map>
#include <string>

#include "derivations/document/document.hpp"
#include "document/document_rows.hpp"
#include "derivations/syntax/document.hpp"

using document_test::at;
using document_test::check;
using document_test::Row;

TEST_CASE("document split: Markdown displays, rows of aligned, inline math, code skipped") {
  const std::string md =
      "# Notes\n"                                     // 1
      "Let $x = 2$ here.\n"                           // 2
      "\n"                                            // 3
      "$$a = b \\quad (1.1)$$\n"                      // 4
      "```\n$$not = math$$\n```\n"                    // 5-7
      "$$\\begin{aligned} p &= q \\\\\n"              // 8
      "  &= r\\end{aligned}$$\n"                      // 9
      "Costs \\$5 and $5.\n";                         // 10
  dc::Document doc = dc::split_document(dc::SourceText{"n.md", md});
  REQUIRE(doc.displays.size() == 2);
  CHECK(doc.displays[0].rows.size() == 1);
  CHECK(doc.displays[0].rows[0].origin.line == 4);
  CHECK(doc.displays[0].rows[0].origin.col == 3);
  REQUIRE(doc.displays[1].rows.size() == 2);
  CHECK(doc.displays[1].rows[0].text == "p &= q");
  CHECK(doc.displays[1].rows[1].origin.line == 9);
  CHECK(doc.displays[1].rows[1].text.rfind("&= r", 0) == 0);
  REQUIRE(doc.inlines.size() == 1);   // "$5." is no math: no closing '$'
  CHECK(doc.inlines[0].text == "x = 2");
  CHECK(doc.inlines[0].displays_before == 0);
}

TEST_CASE("document split: LaTeX environments, comments, directives, sectioning") {
  const std::string tex =
      "\\documentclass{article}\n"                                  // 1
      "\\newcommand{\\half}{\\frac{1}{2}}\n"                        // 2
      "% derivcheck: symbol m : positive [kg]\n"                    // 3
      "\\begin{document}\n"                                         // 4
      "\\section{One}\n"                                            // 5
      "% $$ignored = comment$$\n"                                   // 6
      "\\begin{eqnarray}\n"                                         // 7
      "  T &=& \\half m v^2 \\nonumber \\\\\n"                     // 8
      "  E &=& T + V\n"                                             // 9
      "\\end{eqnarray}\n"                                           // 10
      "\\begin{equation} y = \\begin{split} a \\\\ b\\end{split}\\end{equation}\n"   // 11
      "\\end{document}\n";
  dc::Document doc = dc::split_document(dc::SourceText{"n.tex", tex});
  CHECK(doc.kind == dc::Document::Kind::Latex);
  REQUIRE(doc.directives.size() == 1);
  CHECK(doc.directives[0].text == "symbol m : positive [kg]");
  CHECK(doc.directives[0].origin.line == 3);
  REQUIRE(doc.displays.size() == 2);
  REQUIRE(doc.displays[0].rows.size() == 2);
  CHECK(doc.displays[0].rows[0].origin.line == 8);
  CHECK(doc.displays[0].rows[1].origin.line == 9);
  CHECK(doc.displays[0].section == 1);
  CHECK(doc.displays[1].rows.size() == 2);   // split unwrapped: its rows are the display's
}

TEST_CASE("document split: an unclosed display is a warning and the rest is still read") {
  dc::Document doc = dc::split_document(dc::SourceText{"bad.md", "$$a = b$$\n\ntext\n$$ c = d\n"});
  REQUIRE(doc.warnings.size() == 1);
  CHECK(doc.warnings[0].pos().line == 4);
  CHECK(doc.warnings[0].pos().col == 1);
  CHECK(doc.warnings[0].message().find("'$$' is not closed") != std::string::npos);
  CHECK(doc.displays.size() == 1);
  // and in a check, the rows before it are still checked
  dc::Derivation d = dc::read_document(dc::SourceText{"bad.md", "$$y = 2 x$$\n\n$$ y = \n"});
  REQUIRE(d.diagnostics.size() == 1);
  CHECK(d.steps.size() == 1);
}

TEST_CASE("document check: givens, derived rows, a chain, and a slip refuted at its row") {
  const std::string md =
      "Momentum before and after, and the restitution law:\n"                 // 1
      "\n"                                                                    // 2
      "$$m_1 u_1 + m_2 u_2 = m_1 w_1 + m_2 w_2$$\n"                           // 3
      "\n"                                                                    // 4
      "$$w_2 - w_1 = c (u_1 - u_2)$$\n"                                       // 5
      "\n"                                                                    // 6
      "Solving the two for the velocities after the collision:\n"             // 7
      "\n"                                                                    // 8
      "$$w_1 = \\frac{m_1 u_1 + m_2 u_2 - c m_2 (u_1 - u_2)}{m_1 + m_2}$$\n"  // 9
      "\n"                                                                    // 10
      "$$w_2 = \\frac{m_1 u_1 + m_2 u_2 + c m_1 (u_1 - u_2)}{m_1 + m_1}$$\n"  // 11 (slip: m_1 + m_1)
      "\n"                                                                    // 12
      "$$(m_1 + m_2)^2 = m_1^2 + 2 m_1 m_2 + m_2^2 = m_1^2 + m_2^2$$\n";     // 13 (second link wrong)
  auto rows = check("impact.md", md);
  CHECK(at(rows, 3).verdict == "premise");
  CHECK(at(rows, 5).verdict == "premise");   // introduces c
  const Row& w1 = at(rows, 9);
  CHECK(w1.verdict == "proved");
  CHECK(w1.rule == "rewrite");
  CHECK(at(rows, 11).verdict == "refuted");
  CHECK(at(rows, 13, 1).verdict == "proved");
  CHECK(at(rows, 13, 1).rule == "identity");
  CHECK(at(rows, 13, 2).verdict == "refuted");
}

TEST_CASE("document check: an inline given is in force for the display after it only") {
  const std::string md =
      "$$y = a x + b$$\n"                                   // 1
      "\n"                                                  // 2
      "For the special case $b = 0$ this is\n"              // 3
      "\n"                                                  // 4
      "$$y = a x$$\n"                                       // 5
      "\n"                                                  // 6
      "and in general again\n"                              // 7
      "\n"                                                  // 8
      "$$y - b = a x$$\n"                                   // 9
      "\n"                                                  // 10
      "$$y - b = 2 a x$$\n";                               // 11 (wrong in general)
  auto rows = check("case.md", md);
  CHECK(at(rows, 1).verdict == "premise");
  CHECK(at(rows, 5).verdict == "proved");
  CHECK(at(rows, 9).verdict == "proved");
  // b = 0 is not in force here: the slip is refuted, not derived from the special case
  CHECK(at(rows, 11).verdict == "refuted");
}

TEST_CASE("document check: a name set again by a later display is not refuted against the earlier one") {
  // documents reuse a name for the next case's quantity; a counterexample against the earlier
  // meaning is no evidence, so the row is undecided with that reason
  const std::string md =
      "$$y = a x + b$$\n"          // 1
      "\n"                         // 2
      "$$y = a x + 2 b$$\n";       // 3
  auto rows = check("reuse.md", md);
  CHECK(at(rows, 3).verdict == "undecided");
  CHECK(at(rows, 3).reason.find("'y' is set by L1") != std::string::npos);
}

TEST_CASE("document check: what is not read is undecided with the reason, the rest goes on") {
  const std::string md =
      "$$F = \\int f\\,dx$$\n"                              // 1
      "\n"                                                  // 2
      "$$s = v t$$\n"                                       // 3
      "\n"                                                  // 4
      "$$s \\approx 3 t$$\n"                                // 5
      "\n"                                                  // 6
      "$$s < 2 v t$$\n";                                    // 7
  auto rows = check("unread.md", md);
  CHECK(at(rows, 1).verdict == "undecided");
  CHECK(at(rows, 1).reason.find("not read") != std::string::npos);
  CHECK(at(rows, 3).verdict == "premise");
  CHECK(at(rows, 5).verdict == "undecided");   // an approximation is never refuted
  CHECK(at(rows, 7).verdict == "undecided");
}

TEST_CASE("document check: LaTeX align rows continue with &=, labels are cited") {
  const std::string tex =
      "\\documentclass{article}\n"                                                   // 1
      "\\newcommand{\\half}{\\frac{1}{2}}\n"                                         // 2
      "\\begin{document}\n"                                                          // 3
      "\\begin{equation} K = \\half M V^2 \\label{eq:k}\\end{equation}\n"            // 4
      "With $V = 2 U$, from \\eqref{eq:k}:\n"                                        // 5
      "\\begin{align}\n"                                                             // 6
      "  K &= \\half M (2 U)^2 \\\\\n"                                               // 7
      "    &= 2 M U^2 \\\\\n"                                                        // 8
      "    &= 4 M U^2\n"                                                             // 9 (slip)
      "\\end{align}\n"                                                               // 10
      "\\end{document}\n";
  auto rows = check("energy.tex", tex);
  CHECK(at(rows, 4).verdict == "premise");
  CHECK(at(rows, 7).verdict == "proved");
  CHECK(at(rows, 8).verdict == "proved");
  CHECK(at(rows, 9).verdict == "refuted");
}

TEST_CASE("document reader: a row after `= 0` continues the quantity, not the 0") {
  // `A &= B = 0 \\ &= C = 0`: the second row says B = C (and C = 0), not 0 = C
  dc::Derivation d = dc::read_document(dc::SourceText{
      "z.md", "$$\\begin{aligned} p &= m u - M w = 0 \\\\\n &= m a - M b = 0 \\end{aligned}$$\n"});
  const dc::Step* first = nullptr;
  for (const auto& s : d.steps)
    if (s.pos.line == 2 && s.document_row && s.document_row->link == 1) first = &s;
  REQUIRE(first);
  CHECK(first->claim_text == "m*u - M*w = m*a - M*b");
}

TEST_CASE("document vectors: declared vectors are read as vectors, undeclared bold names are not", "[document]") {
  const std::string declared =
      "---\n"                                                               // 1
      "derivcheck: symbol m : positive [kg]\n"                             // 2
      "derivcheck: vector r : 3 [m]\n"                                     // 3
      "derivcheck: vector p, v : 3 [kg*m/s]\n"                             // 4
      "derivcheck: vector L : 3 [kg*m^2/s]\n"                              // 5
      "---\n"                                                               // 6
      "$$\\mathbf{L} = \\mathbf{r} \\times \\mathbf{p}$$\n"        // 7
      "$$\\mathbf{r} \\cdot \\mathbf{L} = 0$$\n"                     // 8
      "$$\\mathbf{p} \\cdot \\mathbf{L} = 1$$\n"                     // 9
      "$$|\\mathbf{L}|^2 = |\\mathbf{r}|^2 |\\mathbf{p}|^2 - (\\mathbf{r} \\cdot \\mathbf{p})^2$$\n";   // 10
  auto rows = check("v.md", declared, true);
  CHECK(at(rows, 7).verdict == "premise");
  CHECK(at(rows, 8).verdict == "proved");
  CHECK(at(rows, 9).verdict != "proved");
  CHECK(at(rows, 10).verdict == "proved");
  const std::string undeclared = "$$\\mathbf{L} = \\mathbf{r} \\times \\mathbf{p}$$\n";
  auto plain = check("u.md", undeclared, true);
  CHECK(at(plain, 1).verdict == "undecided");
  CHECK(at(plain, 1).reason.find("not linear in the vectors") != std::string::npos);
}
