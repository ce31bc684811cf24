// Each rule on true and false steps: tests/data/rules/*.dc label correct steps ok_* (must be
// proved or hold numerically) and wrong steps bad_* (must be refuted, with a counterexample
// or the two values). Premises (given/definition) must be accepted, and no step may have an
// error: dimensions in the fixtures are consistent.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/report/latex.hpp"
#include "derivations/report/report.hpp"
#include "derivations/rules/check.hpp"

namespace {

std::string data(const std::string& rel) { return std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/" + rel; }

bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }

}  // namespace

TEST_CASE("every rule accepts its true steps and refutes its false ones", "[rules]") {
  std::string file = GENERATE(as<std::string>{}, "rewrite", "substitute", "solve", "solve_roots", "limit", "limit_forms", "series", "series_order",
                              "first_order", "differentiate", "integrate", "solves_ode", "definition", "bound_variables", "functions_at_points", "named_results",
                              "chain_names", "solve_free", "defined_through_t", "stationary", "instance",
                              "eval_between");
  CAPTURE(file);
  dc::Derivation d = dc::load_derivation(data("rules/" + file + ".dc"));
  dc::CheckSummary sum = dc::check_derivation(d);
  int ok = 0, bad = 0;
  for (std::size_t i = 0; i < d.steps.size(); ++i) {
    const dc::Step& s = d.steps[i];
    const dc::StepResult& r = sum.results[i];
    CAPTURE(s.label, dc::verdict_phrase(r.verdict), r.verdict.detail, r.derived);
    std::string errors;
    for (const auto& e : r.errors) errors += e.format();
    CAPTURE(errors);
    CHECK(r.errors.empty());
    if (starts_with(s.label, "ok_")) {
      ++ok;
      CHECK(r.verdict.holds());
    } else if (starts_with(s.label, "bad_")) {
      ++bad;
      CHECK(r.verdict.kind == dc::VerdictKind::Refuted);
      // evidence: a counterexample point or the two differing values
      CHECK((!r.verdict.point.empty() || !r.verdict.lhs_value.empty() || !r.verdict.detail.empty()));
    } else {
      CHECK(r.verdict.holds());
    }
  }
  CHECK(ok >= 1);
  CHECK(bad >= 1);
}

TEST_CASE("a name a step introduces is stated in the report, and a premise using a bound name is warned about",
          "[rules][names]") {
  dc::Derivation d = dc::load_derivation(data("rules/chain_names.dc"));
  dc::CheckSummary sum = dc::check_derivation(d);
  dc::FileReport f;
  f.file = "chain_names.dc";
  f.derivation = d;
  f.summary = sum;
  const std::string text = dc::format_text({f}, {});
  CHECK(text.find("introduces: W = integral(k*s, s, 0, L), for the steps after it") != std::string::npos);
  CHECK(text.find("introduces: I_G = integral(") != std::string::npos);
  // a refuted chain whose first side is fresh says how to define the name
  CHECK(text.find("'K' appears in no earlier step, so nothing determines it: only a definition introduces a name "
                  "(write 'K = a*b + a*b  by definition'") != std::string::npos);
  // the fresh-symbol chains introduce nothing
  CHECK(text.find("introduces: K") == std::string::npos);
  CHECK(text.find("introduces: p2") == std::string::npos);
  // the premise after the rod's named result says which value I_G is, at the name
  const dc::Step* law = d.find("parallel_axis");
  REQUIRE(law);
  REQUIRE(law->diagnostics.size() == 1);
  CHECK(law->diagnostics[0].severity() == dc::InputError::Severity::Note);
  CHECK(law->diagnostics[0].pos().col == law->claim_pos.col + 6);   // `I_O = I_G + ...`
  CHECK(law->diagnostics[0].message().find("step 'ok_rod'") != std::string::npos);
  CHECK(text.find(": note: 'I_G' here is the value that step 'ok_rod'") != std::string::npos);
  // no other step is warned about
  for (const auto& s : d.steps)
    if (s.label != "parallel_axis") CHECK(s.diagnostics.empty());
  const nlohmann::ordered_json j = dc::to_json({f}, {});
  bool named = false, warned = false;
  for (const auto& st : j["files"][0]["steps"]) {
    if (st["label"] == "ok_named_undeclared") {
      named = st.contains("introduces") && st["introduces"]["name"] == "W" &&
              st["introduces"]["value"] == "integral(k*s, s, 0, L)";
    }
    if (st["label"] == "parallel_axis") warned = st.contains("diagnostics") && st["diagnostics"].size() == 1 && st["diagnostics"][0]["severity"] == "note";
    if (st["label"] == "bad_fresh_chain") CHECK(!st.contains("introduces"));
  }
  CHECK(named);
  CHECK(warned);
  // warnings do not change the exit code: the file has refuted steps (exit 1), nothing more
  CHECK(sum.exit_code(false) == dc::kExitRefuted);
}

TEST_CASE("solve reports what lsolve derived, deterministically", "[rules][solve]") {
  dc::Derivation d = dc::load_derivation(data("rules/solve.dc"));
  const dc::Step* s = d.find("ok_solve");
  REQUIRE(s);
  dc::StepResult a = dc::check_step(d, *s);
  dc::StepResult b = dc::check_step(d, *s);
  CHECK(a.verdict.kind == dc::VerdictKind::Proved);
  CHECK(a.verdict.method.find("lsolve") != std::string::npos);
  CHECK(a.derived.find("v2p = ") != std::string::npos);
  CHECK(a.derived == b.derived);
  // dividing by m1 + m2 is recorded as a side condition
  bool divisor = false;
  for (const auto& c : a.verdict.side_conditions) divisor = divisor || c.reason == "divisor";
  CHECK(divisor);
}

TEST_CASE("a nonlinear solve substitutes the claim back", "[rules][solve]") {
  dc::Derivation d = dc::load_derivation(data("rules/solve.dc"));
  dc::StepResult r = dc::check_step(d, *d.find("ok_nonlinear"));
  CHECK(r.verdict.holds());
  CHECK(r.verdict.method.find("substituted back") != std::string::npos);
}

TEST_CASE("definitions are abbreviations: their dimension is inferred", "[rules][definition]") {
  dc::Derivation d = dc::load_derivation(data("rules/definition.dc"));
  const dc::SymbolInfo* p = d.symbols.find("p");
  REQUIRE(p);
  CHECK(p->defined_by_step);
  CHECK(p->dimension.to_string() == "kg·m/s");
  dc::StepResult r = dc::check_step(d, *d.find("ok_energy"));
  CHECK(r.dimension == "kg·m²/s²");
}

TEST_CASE("a dimension mismatch is reported at the step with both dimensions", "[rules][dimensions]") {
  dc::SourceText src{"dim.dc",
                     "symbol m : positive [kg]\n"
                     "symbol v : real [m/s]\n"
                     "symbol p : real [kg*m/s]\n"
                     "wrong: p = m*v^2\n"
                     "    by given\n"};
  dc::Derivation d = dc::parse_derivation(src);
  dc::CheckSummary sum = dc::check_derivation(d);
  REQUIRE(sum.results.size() == 1);
  REQUIRE(sum.results[0].errors.size() == 1);
  const dc::InputError& e = sum.results[0].errors[0];
  CHECK(e.pos().line == 4);
  CHECK(e.pos().col == 12);
  CHECK(e.message().find("kg·m/s") != std::string::npos);
  CHECK(e.message().find("kg·m²/s²") != std::string::npos);
  CHECK(sum.errors == 1);
  CHECK(sum.exit_code(false) == 1);
}

TEST_CASE("an erratum reports the printed claim and checks the corrected one", "[rules][erratum]") {
  dc::SourceText src{"erratum.dc",
                     "symbol v, u_e : positive [m/s]\n"
                     "symbol g : positive [m/s^2]\n"
                     "symbol t : positive [s]\n"
                     "ratio: (v_e + g*t)/u_e\n"
                     "    by given\n"
                     "    erratum \"v_e is never defined; the intended quantity is v\" : (v + g*t)/u_e\n"};
  dc::Derivation d = dc::parse_derivation(src);
  dc::CheckSummary sum = dc::check_derivation(d);
  REQUIRE(sum.results.size() == 1);
  const dc::StepResult& r = sum.results[0];
  CHECK(r.erratum_reported);
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].pos().line == 4);
  CHECK(r.errors[0].pos().col == 9);
  CHECK(r.errors[0].message().find("v_e") != std::string::npos);
  CHECK(sum.errata == 1);
  CHECK(sum.errors == 0);
  CHECK(sum.exit_code(false) == 0);
  CHECK(sum.exit_code(true) == 1);
}

TEST_CASE("a wrong printed claim with an erratum is reported with its refutation", "[rules][erratum]") {
  dc::SourceText src{"erratum2.dc",
                     "symbol a, b : real [1]\n"
                     "sq: (a + b)^2 = a^2 + b^2\n"
                     "    by expand\n"
                     "    erratum \"the cross term is missing\" : (a + b)^2 = a^2 + 2*a*b + b^2\n"};
  dc::Derivation d = dc::parse_derivation(src);
  dc::CheckSummary sum = dc::check_derivation(d);
  const dc::StepResult& r = sum.results[0];
  CHECK(r.erratum_reported);
  CHECK(r.verdict.holds());
  REQUIRE(!r.errors.empty());
  CHECK(r.errors[0].message().find("printed claim is wrong") != std::string::npos);
}

namespace {

const dc::StepResult& result_of(const dc::Derivation& d, const dc::CheckSummary& sum, const std::string& label) {
  for (std::size_t i = 0; i < d.steps.size(); ++i)
    if (d.steps[i].label == label) return sum.results[i];
  FAIL("no step " << label);
  return sum.results[0];
}

}  // namespace

TEST_CASE("stationary points, instances and evaluation bars give their evidence", "[rules][stationary][instance]") {
  dc::Derivation d = dc::load_derivation(data("rules/stationary.dc"));
  dc::CheckSummary sum = dc::check_derivation(d);
  // a maximum: the derivative vanishes and the second derivative's sign is named
  const dc::Verdict& max = result_of(d, sum, "ok_range_max").verdict;
  CHECK(max.detail.find("second derivative at theta = pi/4 is -4*v0^2/g < 0") != std::string::npos);
  // a maximum called a minimum: refuted at a point with the second derivative's value
  const dc::Verdict& min = result_of(d, sum, "bad_range_min").verdict;
  CHECK(min.kind == dc::VerdictKind::Refuted);
  CHECK(!min.point.empty());
  CHECK(min.lhs_label.find("second derivative") != std::string::npos);
  CHECK(min.lhs_value.rfind("-", 0) == 0);
  CHECK(min.rhs_value == "positive");
  // a slope that does not vanish: its value at a certified point
  const dc::Verdict& slope = result_of(d, sum, "bad_range_slope").verdict;
  CHECK(slope.kind == dc::VerdictKind::Refuted);
  CHECK(slope.lhs_label == "derivative (at theta = pi/3)");
  CHECK(slope.rhs_value == "0");
  CHECK(result_of(d, sum, "bad_range_outside").verdict.detail.find("not in the declared domain") != std::string::npos);
  CHECK(result_of(d, sum, "bad_inflection_max").verdict.detail.find("inflection") != std::string::npos);

  dc::Derivation in = dc::load_derivation(data("rules/instance.dc"));
  dc::CheckSummary isum = dc::check_derivation(in);
  CHECK(result_of(in, isum, "ok_first").verdict.detail.find("with v -> v1, KE -> KE1 (m unchanged)") != std::string::npos);
  CHECK(result_of(in, isum, "ok_exchanged").verdict.detail.find("sides exchanged") != std::string::npos);
  const dc::Verdict& half = result_of(in, isum, "bad_half").verdict;
  CHECK(half.detail.find("the closest renaming, v -> v1, KE -> KE1 (m unchanged), gives KE1 = m*v1^2/2") !=
        std::string::npos);
  CHECK(!half.point.empty());
}

TEST_CASE("what cannot be decided about extrema, instances and bars says why", "[rules][stationary][instance]") {
  dc::Derivation d = dc::load_derivation(data("rules/undecided_forms.dc"));
  dc::CheckSummary sum = dc::check_derivation(d);
  const std::vector<std::pair<std::string, std::string>> want = {
      {"und_sign", "a maximum needs a < 0"},
      {"und_domain", "mu is declared real but the law's m is positive"},
      {"und_constraint", "the instance needs 'assume v1 < c'"},
      {"und_bar", "the limit does not exist"}};
  for (const auto& [label, why] : want) {
    const dc::StepResult& r = result_of(d, sum, label);
    CAPTURE(label, r.verdict.reason, r.verdict.detail);
    CHECK(r.errors.empty());
    CHECK(r.verdict.kind == dc::VerdictKind::Undecided);
    CHECK((r.verdict.reason + r.verdict.detail).find(why) != std::string::npos);
  }
}

TEST_CASE("an evaluation bar prints as a bar with its ends", "[rules][latex]") {
  dc::Derivation d = dc::load_derivation(data("rules/eval_between.dc"));
  CHECK(dc::latex_expression(d.steps[0].claim.sides[0], d.symbols) == "\\left[\\frac{k x^{2}}{2}\\right]_{0}^{L}");
  const dc::Step* decay = d.find("ok_decay");
  REQUIRE(decay);
  CHECK(dc::latex_expression(decay->claim.sides[0], d.symbols).find("\\right]_{0}^{\\infty}") != std::string::npos);
}
