// The limit corpus (tests/data/limits.jsonl): textbook and Gruntz-thesis limits, one-sided
// limits, limits that do not exist, physical limits, and realistic wrong claimed values.
// Every line is a `derivcheck claims` line of kind "limit" with the verdict it must get
// ("expected": "proved" for a true claim, "refuted" for a false one).
//
// The bar: no line judged wrong, at least 95% decided, and the undecided lines are exactly
// the ones listed below, each with the reason the engine gives.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "derivations/claims/claims.hpp"

namespace {

std::string data(const std::string& rel) { return std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/" + rel; }

// Known undecided lines and why (the start of the reason the engine gives).
const std::map<std::string, std::string> kKnownUndecided = {
    // a*x -> +oo holds only for a > 0; a is declared real, so the claim is false, but the
    // engine only says that the sign of a is not fixed (it does not search for a witness a < 0)
    {"gap_param_sign", "the sign of a is not determined by the declarations"},
};

}  // namespace

TEST_CASE("the limit corpus: every line decided right or known undecided, none wrong", "[limits][corpus]") {
  std::ifstream in(data("limits.jsonl"));
  REQUIRE(in);
  std::string line;
  int n = 0, decided = 0, wrong = 0, proved = 0, refuted = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    ++n;
    nlohmann::json claim = nlohmann::json::parse(line);
    const std::string id = claim.at("id");
    const std::string expected = claim.at("expected");
    nlohmann::ordered_json r = dc::check_claim_line(line, n, "limits.jsonl");
    const std::string verdict = r.value("verdict", "");
    CAPTURE(n, id, expected, r.dump());
    REQUIRE((expected == "proved" || expected == "refuted"));
    (expected == "proved" ? proved : refuted) += 1;
    auto known = kKnownUndecided.find(id);
    if (verdict == "undecided") {
      CHECK(known != kKnownUndecided.end());
      if (known != kKnownUndecided.end()) CHECK(r.value("reason", "").rfind(known->second, 0) == 0);
      continue;
    }
    CHECK(known == kKnownUndecided.end());   // decided now: take it off the list
    ++decided;
    if (verdict != expected) ++wrong;
    CHECK(verdict == expected);
    // no line may take long (the whole corpus runs in a few seconds)
    CHECK(r.value("seconds", 0.0) < 5.0);
  }
  CHECK(n >= 80);
  CHECK(proved >= 60);
  CHECK(refuted >= 20);
  CHECK(wrong == 0);
  CHECK(decided * 100 >= 95 * n);
}

TEST_CASE("limit claims: dir, undefined and infinite right-hand sides", "[limits][claims]") {
  auto verdict = [](const std::string& line) { return dc::check_claim_line(line, 1, "t.jsonl"); };
  auto r = verdict(R"J({"id":"a","kind":"limit","lhs":"1/x","var":"x","point":"0","dir":"+","rhs":"oo"})J");
  CHECK(r.at("verdict") == "proved");
  r = verdict(R"J({"id":"b","kind":"limit","lhs":"1/x","var":"x","point":"0","dir":"-","rhs":"-oo"})J");
  CHECK(r.at("verdict") == "proved");
  r = verdict(R"J({"id":"c","kind":"limit","lhs":"1/x","var":"x","point":"0","rhs":"undefined"})J");
  CHECK(r.at("verdict") == "proved");
  CHECK(r.at("detail").get<std::string>().find("one-sided limits differ") != std::string::npos);
  r = verdict(R"J({"id":"d","kind":"limit","lhs":"1/x","var":"x","point":"0","rhs":"oo"})J");
  CHECK(r.at("verdict") == "refuted");
  CHECK(r.at("lhs_value") == "undefined");
  r = verdict(R"J({"id":"e","kind":"limit","lhs":"sin(x)/x","var":"x","point":"0","rhs":"undefined"})J");
  CHECK(r.at("verdict") == "refuted");
  CHECK(r.at("lhs_value") == "1");
  r = verdict(R"J({"id":"f","kind":"limit","lhs":"x","var":"x","point":"0","dir":"up","rhs":"0"})J");
  CHECK(r.at("verdict") == "error");
  CHECK(r.at("error").get<std::string>().find("field 'dir'") != std::string::npos);
  // a side outside the declared domain
  r = verdict(R"J({"id":"g","kind":"limit","lhs":"x","var":"x","point":"0","dir":"-","rhs":"0","assumptions":{"x":"positive"}})J");
  CHECK(r.at("verdict") == "undecided");
  CHECK(r.at("reason") == "x cannot approach the point from below within its declared domain");
}
