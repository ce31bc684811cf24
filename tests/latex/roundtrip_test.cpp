// Round trip: every equation the LaTeX writer emits for derivations/handout9/*.dc is read back
// (latex_read) and each side proved equal to the source side with dc::prove_equal, so a dropped
// sign or bracket in printing cannot pass.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include "derivations/reader/derivation.hpp"
#include "derivations/report/latex.hpp"
#include "derivations/report/latex_read.hpp"
#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/printer.hpp"

namespace {

std::vector<std::string> handout_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9"))
    if (e.path().extension() == ".dc") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// Do the read-back side and the source side denote the same value? Sides GiNaC cannot hold
// (an integral) are compared part by part.
bool same_structure(const dc::Node& read, const dc::Node& src, const dc::SymbolTable& t, std::string* why,
                    const std::string& cause);

bool same_value(const dc::Node& read, const dc::Node& src, const dc::SymbolTable& t, std::string* why) {
  try {
    GiNaC::ex a = dc::to_ginac(read, t);
    GiNaC::ex b = dc::to_ginac(src, t);
    dc::Verdict v = dc::prove_equal(a, b, t);
    if (!v.holds())
      *why = std::string(dc::to_string(v.kind)) + " " + dc::print_text(a, t) + " vs " + dc::print_text(b, t) +
             " " + v.detail;
    return v.holds();
  } catch (const dc::InputError& e) {
    return same_structure(read, src, t, why, e.message());
  } catch (const dc::UndecidedLimit& e) {   // an integral GiNaC cannot evaluate
    return same_structure(read, src, t, why, e.what());
  }
}

// Sides GiNaC cannot hold are compared part by part.
bool same_structure(const dc::Node& read, const dc::Node& src, const dc::SymbolTable& t, std::string* why,
                    const std::string& cause) {
  if (read.kind != src.kind || read.text != src.text || read.args.size() != src.args.size()) {
    *why = "structure differs where GiNaC cannot compare: " + cause;
    return false;
  }
  for (std::size_t i = 0; i < read.args.size(); ++i)
    if (!same_value(read.args[i], src.args[i], t, why)) return false;
  return true;
}

struct Emitted {
  dc::Derivation d;
  std::string tex;
};

}  // namespace

TEST_CASE("latex round trip: every handout equation reads back equal to its source", "[latex][roundtrip]") {
  bool annotate = GENERATE(false, true);
  int equations = 0, sides = 0;
  auto files = handout_files();
  REQUIRE(files.size() >= 10);
  for (const auto& file : files) {
    dc::Derivation d = dc::load_derivation(file);
    dc::LatexOptions opt;
    opt.annotate = annotate;
    std::string tex = dc::write_latex(d, opt);
    auto displays = dc::extract_latex_displays(tex);
    CAPTURE(file, annotate);
    // every step is displayed, except stable rewrites and hidden steps in the plain handout
    std::vector<const dc::Step*> shown;
    for (const auto& s : d.steps)
      if (annotate || (!s.stable_of && !s.hidden)) shown.push_back(&s);
    REQUIRE(displays.size() == shown.size());
    for (std::size_t i = 0; i < displays.size(); ++i) {
      const dc::Step& s = *shown[i];
      const auto& disp = displays[i];
      CAPTURE(s.label, disp.latex);
      REQUIRE(disp.label == s.label);
      CHECK(disp.tag == s.tag);
      CHECK(disp.footnote == s.erratum.has_value());
      dc::Relation r = dc::read_latex_relation(disp.latex, d.symbols);
      const dc::Relation& src = s.erratum ? s.erratum->corrected : s.claim;
      REQUIRE(r.sides.size() == src.sides.size());
      for (std::size_t k = 0; k < r.sides.size(); ++k) {
        std::string why;
        CAPTURE(k, dc::to_text(src.sides[k]), dc::to_text(r.sides[k]));
        CHECK(same_value(r.sides[k], src.sides[k], d.symbols, &why));
        if (!why.empty()) INFO(why);
        ++sides;
      }
      ++equations;
    }
  }
  INFO(equations << " equations, " << sides << " sides");
  CHECK(equations >= 100);
}

TEST_CASE("latex round trip: a dropped minus or bracket in the emission is caught", "[latex][roundtrip]") {
  std::string file = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9/05_direct_impact.dc";
  dc::Derivation d = dc::load_derivation(file);
  auto displays = dc::extract_latex_displays(dc::write_latex(d, {}));
  auto find = [&](const std::string& label) -> const dc::LatexDisplay& {
    for (const auto& x : displays)
      if (x.label == label) return x;
    FAIL("no display " << label);
    throw 0;
  };
  auto rhs_holds = [&](const std::string& latex) {
    dc::Relation r = dc::read_latex_relation(latex, d.symbols);
    std::string why;
    return same_value(r.sides.back(), d.find("v1p_general")->claim.sides.back(), d.symbols, &why);
  };
  std::string good = find("v1p_general").latex;
  REQUIRE(good.find(" - e m_2") != std::string::npos);
  REQUIRE(rhs_holds(good));
  SECTION("minus to plus") {
    std::string bad = good;
    bad.replace(bad.find(" - e m_2"), 3, " + ");
    CHECK_FALSE(rhs_holds(bad));
  }
  SECTION("minus dropped (juxtaposition)") {
    std::string bad = good;
    bad.replace(bad.find(" - e m_2"), 3, " ");
    CHECK_FALSE(rhs_holds(bad));
  }
  SECTION("bracket dropped") {
    std::string bad = good;
    bad.erase(bad.find("\\left(v_1"), 6);
    bad.erase(bad.find("\\right)"), 7);
    CHECK_FALSE(rhs_holds(bad));
  }
  SECTION("every equation of the handout: flipping its first binary minus is refuted") {
    int flipped = 0;
    for (const auto& f : handout_files()) {
      dc::Derivation dd = dc::load_derivation(f);
      for (const auto& x : dc::extract_latex_displays(dc::write_latex(dd, {}))) {
        auto at = x.latex.find(" - ");
        if (at == std::string::npos) continue;
        const dc::Step* s = dd.find(x.label);
        REQUIRE(s);
        const dc::Relation& src = s->erratum ? s->erratum->corrected : s->claim;
        std::string bad = x.latex;
        bad.replace(at, 3, " + ");
        dc::Relation r = dc::read_latex_relation(bad, dd.symbols);
        REQUIRE(r.sides.size() == src.sides.size());
        bool all_hold = true;
        std::string why;
        for (std::size_t k = 0; k < r.sides.size(); ++k)
          all_hold = all_hold && same_value(r.sides[k], src.sides[k], dd.symbols, &why);
        CAPTURE(f, x.label, bad);
        CHECK_FALSE(all_hold);
        ++flipped;
      }
    }
    CHECK(flipped >= 40);
  }
}

TEST_CASE("latex reader: errors carry positions", "[latex][roundtrip]") {
  dc::SymbolTable t;
  dc::SymbolInfo s;
  s.name = "m1";
  s.tex = "m_1";
  t.declare(s);
  CHECK(dc::to_text(dc::read_latex_expression("\\frac{m_1}{2} m_1^{2}", t)) != "");
  try {
    dc::read_latex_relation("m_1 = \n  \\frac{m_1}{q}", t);
    FAIL("expected an error");
  } catch (const dc::InputError& e) {
    CHECK(e.pos().line == 2);
    CHECK(e.pos().col == 14);
    CHECK_THAT(e.message(), Catch::Contains("unknown symbol"));
  }
  CHECK_THROWS_AS(dc::read_latex_expression("\\left(m_1", t), dc::InputError);
  CHECK_THROWS_AS(dc::read_latex_expression("\\unknown", t), dc::InputError);
}

TEST_CASE("notation dot: derivatives of declared functions print as dots and read back", "[latex][roundtrip]") {
  const std::string body =
      "symbol t : nonnegative [s]\nsymbol k, m : positive [1]\nfunction x(t) : real [1]\n"
      "a: diff(x(t), t, 2) = -k/m*x(t)\n    by given\n"
      "b: m*diff(x(t), t)^2/2 + k*x(t)^2/2 = m*diff(x(t), t)^2/2 + k*x(t)^2/2\n    by rewrite a\n"
      "c: x(0) = diff(x(t), t)\n    by given\n";
  for (bool dot : {true, false}) {
    CAPTURE(dot);
    dc::Derivation d = dc::parse_derivation(dc::SourceText{"n.dc", (dot ? "notation dot\n" : "") + body});
    CHECK(d.dot_derivatives == dot);
    std::string tex = dc::write_latex(d, dc::LatexOptions{});
    CHECK((tex.find("\\ddot{x} &= -\\frac{k}{m} x") != std::string::npos) == dot);
    CHECK((tex.find("\\dot{x}") != std::string::npos) == dot);
    CHECK(tex.find("x(0) &=") != std::string::npos);   // x at another point keeps its argument
    CHECK(tex.find("x(t)") == std::string::npos);      // one notation: x, not x(t)
    auto displays = dc::extract_latex_displays(tex);
    REQUIRE(displays.size() == d.steps.size());
    for (std::size_t i = 0; i < displays.size(); ++i) {
      CAPTURE(displays[i].latex);
      dc::Relation r = dc::read_latex_relation(displays[i].latex, d.symbols);
      REQUIRE(r.sides.size() == d.steps[i].claim.sides.size());
      for (std::size_t k = 0; k < r.sides.size(); ++k)
      {
        std::string why;
        CHECK(same_value(r.sides[k], d.steps[i].claim.sides[k], d.symbols, &why));
        CAPTURE(why);
      }
    }
  }
  CHECK_THROWS_WITH(dc::parse_derivation(dc::SourceText{"n.dc", "notation dots\n" + body}),
                    Catch::Contains("n.dc:1:10: error: unknown notation 'dots'"));
}

TEST_CASE("one-sided limits read back with their side", "[latex][roundtrip]") {
  dc::Derivation d = dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/rules/limit_forms.dc");
  std::string tex = dc::write_latex(d, dc::LatexOptions{});
  auto displays = dc::extract_latex_displays(tex);
  int sided = 0;
  for (const auto& disp : displays) {
    const dc::Step* s = d.find(disp.label);
    REQUIRE(s);
    if (s->rule.name != "limit" || s->rule.dir == 0 || !s->rule.into.empty()) continue;
    CAPTURE(disp.label, disp.latex);
    dc::Relation r = dc::read_latex_relation(disp.latex, d.symbols);
    REQUIRE(r.sides.size() >= 2);
    const dc::Node& lim = r.sides[0];
    REQUIRE(lim.kind == dc::NodeKind::Call);
    CHECK(lim.text == "limit");
    REQUIRE(lim.args.size() == 4);
    CHECK(lim.args[3].text == (s->rule.dir > 0 ? "+" : "-"));
    CHECK(dc::to_text(lim.args[2]) == dc::to_text(s->rule.point->value));
    ++sided;
  }
  CHECK(sided >= 2);
  CHECK_THROWS_AS(dc::read_latex_expression("\\lim_{x \\to 0^{*}} x", d.symbols), dc::InputError);
}

TEST_CASE("integrals read back: definite, improper and indefinite", "[latex][roundtrip]") {
  dc::Derivation d = dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/rules/bound_variables.dc");
  std::string tex = dc::write_latex(d, dc::LatexOptions{});
  int integrals = 0, indefinite = 0;
  for (const auto& disp : dc::extract_latex_displays(tex)) {
    const dc::Step* s = d.find(disp.label);
    REQUIRE(s);
    if (disp.latex.find("\\int") == std::string::npos) continue;
    CAPTURE(disp.label, disp.latex);
    dc::Relation r = dc::read_latex_relation(disp.latex, d.symbols);
    REQUIRE(r.sides.size() == s->claim.sides.size());
    CHECK(dc::to_text(r.sides[0]) == dc::to_text(s->claim.sides[0]));
    ++integrals;
    if (s->claim.sides[0].kind == dc::NodeKind::Call && s->claim.sides[0].args.size() == 2) ++indefinite;
  }
  CHECK(integrals >= 8);
  CHECK(indefinite == 3);
}
