// Typesetting a lecturer would otherwise fix by hand (issue 26): each item as the LaTeX
// fragment the literate fixture tests/data/latex/typesetting.dc must produce.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/report/latex.hpp"
#include "derivations/syntax/source.hpp"

namespace {

dc::Derivation fixture() {
  return dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/latex/typesetting.dc");
}

bool has(const std::string& tex, const std::string& piece) { return tex.find(piece) != std::string::npos; }

dc::Derivation from_text(const std::string& text) { return dc::parse_derivation(dc::SourceText{"<t>.dc", text}); }

}  // namespace

TEST_CASE("typesetting: prose characters print as LaTeX, never as U+", "[latex][typesetting]") {
  const std::string tex = dc::write_latex(fixture(), {});
  CAPTURE(tex);
  CHECK(has(tex, "See \\S{}10.3"));
  CHECK(has(tex, "20$^\\circ$"));
  CHECK(has(tex, "small -- so ``sin $\\theta$ $\\approx$ $\\theta$'' --- and"));
  CHECK(has(tex, "$\\times$2\\ldots{}"));
  CHECK(has(tex, "in $\\mu$m, $\\alpha$ and $\\omega$"));
  CHECK_FALSE(has(tex, "U+"));
  CHECK(dc::latex_escape_text("\xC3\xA9t\xC3\xA9 \xC3\xB1") == "\\'et\\'e \\~{n}");
}

TEST_CASE("typesetting: ASCII quotes pair up, apostrophes stay", "[latex][typesetting]") {
  const std::string tex = dc::write_latex(fixture(), {});
  CHECK(has(tex, "The ``sweet spot'' is where the bat's `centre' of percussion"));
  CHECK(dc::latex_escape_text("\"a\" (\"b\") don't") == "``a'' (``b'') don't");
}

TEST_CASE("typesetting: emphasis holds math and expressions, captions take markup", "[latex][typesetting]") {
  const std::string tex = dc::write_latex(fixture(), {});
  CHECK(has(tex, "\\emph{the moment $m g d$ does not change}"));
  CHECK(has(tex, "\\emph{the ratio $r^2$ is kept}"));
  CHECK_FALSE(has(tex, "*the"));
  CHECK(has(tex, "\\textit{Figure:} The period $T$ against $d/g$, \\emph{measured}"));
}

TEST_CASE("typesetting: inline expressions keep quotients on the line", "[latex][typesetting]") {
  const std::string tex = dc::write_latex(fixture(), {});
  CHECK(has(tex, "$m \\left(r_1 v_1/s\\right)^{2}/s$"));
  CHECK(has(tex, "$\\left(1/2\\right) m v_1^{2}$"));
}

TEST_CASE("typesetting: Greek names with subscripts, and a definition's tex", "[latex][typesetting]") {
  const dc::Derivation d = fixture();
  const std::string tex = dc::write_latex(d, {});
  CHECK(d.symbols.find("omega_n")->tex == "\\omega_n");
  CHECK(d.symbols.find("theta_max")->tex == "\\theta_{\\mathrm{max}}");
  CHECK(d.symbols.find("k_G")->tex == "k_G");
  CHECK(d.symbols.find("Om")->tex == "\\Omega");          // tex "..." on the definition
  CHECK(d.symbols.find("omega_d")->tex == "\\omega_d");   // a definition's default
  CHECK(has(tex, "\\omega_n &= \\sqrt{\\frac{g}{d}}"));
  CHECK(has(tex, "\\Omega &= 2 \\omega_n"));
  CHECK(has(tex, "\\theta_{\\mathrm{max}} &= \\frac{1}{2}"));
  // a tex line on a step that introduces no name is a positioned error
  try {
    from_text("symbol x, y : real [1]\ns1: x = y\n    by given\n    tex \"\\xi\"\n");
    FAIL("no error");
  } catch (const dc::InputError& e) {
    CHECK(e.pos().line == 4);
    CHECK(has(e.message(), "introduces none"));
  }
}

TEST_CASE("typesetting: a declared function of t is an argument like a symbol", "[latex][typesetting]") {
  const std::string tex = dc::write_latex(fixture(), {});
  CHECK(has(tex, "\\tau &= m g d \\sin \\theta"));
  CHECK_FALSE(has(tex, "\\sin\\left(\\theta\\right)"));
}

TEST_CASE("typesetting: a limit step shows its limit", "[latex][typesetting]") {
  const std::string tex = dc::write_latex(fixture(), {});
  CHECK(has(tex, "T &= 2 \\pi \\sqrt{\\frac{d}{g}}\\qquad\\text{(as $k_G \\to 0$)}"));
  // first_order and a limit with substitutions (Handout 9)
  const dc::Derivation rocket =
      dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/09_rocket.dc");
  CHECK(has(dc::write_latex(rocket, {}), "\\qquad\\text{(to first order in $\\Delta m$, $\\Delta v$)}"));
  const dc::Derivation impact =
      dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/05_direct_impact.dc");
  // its chain already shows lim_{m_2 -> oo}: only the substitution is added
  CHECK(has(dc::write_latex(impact, {}), "= -v_1\\qquad\\text{(with $v_2 = 0$)}"));
  const dc::Derivation oblique =
      dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/08_oblique_impact.dc");
  CHECK(has(dc::write_latex(oblique, {}), "\\qquad\\text{(as $m_2 \\to \\infty$, with $v_{1n} = v_1 \\cos \\theta_1$, $v_{2n} = 0$)}"));
}

TEST_CASE("typesetting: the handout's title from the file", "[latex][typesetting]") {
  const dc::Derivation d = fixture();
  CHECK(has(dc::write_latex(d, {}), "\\title{Handout 10 -- Angular momentum}"));
  // several files: the first handout line wins over "Derivations"; --title over both
  const dc::Derivation other = from_text("title \"Other\"\nsymbol x : real [1]\ns1: x = x\n    by given\n");
  std::vector<const dc::Derivation*> both{&other, &d};
  CHECK(has(dc::write_latex(both, {}), "\\title{Handout 10 -- Angular momentum}"));
  dc::LatexOptions o;
  o.title = "Given";
  CHECK(has(dc::write_latex(both, o), "\\title{Given}"));
  std::vector<const dc::Derivation*> plain{&other, &other};
  CHECK(has(dc::write_latex(plain, {}), "\\title{Derivations}"));
}

TEST_CASE("typesetting: --units lists the defined quantities too", "[latex][typesetting]") {
  dc::LatexOptions o;
  o.units = true;
  const std::string tex = dc::write_latex(fixture(), o);
  CAPTURE(tex.substr(tex.find("Quantities"), 400));
  CHECK(has(tex, "$\\omega_n$, $\\Omega$, $\\omega_d$ in \\si{"));
  CHECK(has(tex, "$\\tau$ in \\si{J}"));
}

TEST_CASE("typesetting: first_order of a declared function names the function", "[latex][typesetting]") {
  // the small quantity is the function itself (its applications are found by the rule): the
  // condition prints its TeX name, as for a symbol
  const dc::Derivation d = from_text(
      "symbol g : positive [1]\n"
      "symbol t : real [1]\n"
      "function theta(t) : real [1] tex \"\\theta\"\n"
      "eom: diff(theta(t), t, 2) = -g*sin(theta(t))\n"
      "    by given\n"
      "lin: diff(theta(t), t, 2) = -g*theta(t)\n"
      "    by first_order theta of eom\n"
      "lin2: diff(theta(t), t, 2) = -g*theta(t)\n"
      "    by first_order theta(t) of eom\n");
  const std::string tex = dc::write_latex(d, {});
  CAPTURE(tex);
  CHECK(has(tex, "\\text{(to first order in $\\theta$)}"));
  CHECK_FALSE(has(tex, "to first order in $$"));
}
