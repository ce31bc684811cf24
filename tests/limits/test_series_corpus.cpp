// The series corpus (tests/data/series.jsonl): truncated expansions as textbooks write them
// (Taylor, Laurent, Puiseux, log terms, at infinity, physical approximations) and realistic
// wrong variants (a sign, a coefficient, an order claimed one too high). Each line is a
// `derivcheck claims` line of kind "series" (or "series_first_order": agreement to first
// order, the same test with order 2) with the verdict it must get: "proved", "refuted",
// or "undecided" where boundedness holds without a limit (not decidable by the method, and
// never guessed).
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "derivations/claims/claims.hpp"

namespace {
std::string data(const std::string& rel) { return std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/" + rel; }
}  // namespace

TEST_CASE("the series corpus: every line gets its verdict", "[limits][series][corpus]") {
  std::ifstream in(data("series.jsonl"));
  REQUIRE(in);
  std::string line;
  int n = 0, proved = 0, refuted = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    ++n;
    nlohmann::json claim = nlohmann::json::parse(line);
    const std::string expected = claim.at("expected");
    nlohmann::ordered_json r = dc::check_claim_line(line, n, "series.jsonl");
    CAPTURE(n, claim.at("id").get<std::string>(), r.dump());
    CHECK(r.value("verdict", "") == expected);
    proved += expected == "proved";
    refuted += expected == "refuted";
    if (expected == "proved") CHECK(r.value("detail", "").find("->") != std::string::npos);   // the quotient's limit
  }
  CHECK(n >= 40);
  CHECK(proved >= 20);
  CHECK(refuted >= 12);
}

TEST_CASE("series claims: malformed order and direction are line errors", "[limits][series][claims]") {
  auto r = dc::check_claim_line(R"J({"kind":"series","lhs":"sin(x)","rhs":"x","var":"x","point":"0"})J", 1, "b.jsonl");
  CHECK(r.at("verdict") == "error");
  CHECK(r.at("error").get<std::string>().find("integer field 'order'") != std::string::npos);
  r = dc::check_claim_line(R"J({"kind":"series","lhs":"sin(x)","rhs":"x","var":"x","point":"0","order":2.5})J", 1, "b.jsonl");
  CHECK(r.at("verdict") == "error");
  r = dc::check_claim_line(R"J({"kind":"series","lhs":"exp(1/x)","rhs":"1","var":"x","point":"oo","order":1,"dir":"+"})J", 1,
                           "b.jsonl");
  CHECK(r.at("verdict") == "error");
  CHECK(r.at("error").get<std::string>().find("'dir' goes with a finite point") != std::string::npos);
  // an order term and a different "order"; an order term that is not a power of (var - point)
  r = dc::check_claim_line(R"J({"kind":"series","lhs":"sin(x)","rhs":"x + O(x^3)","var":"x","point":"0","order":5})J", 1,
                           "b.jsonl");
  CHECK(r.at("verdict") == "error");
  CHECK(r.at("error").get<std::string>().find("but the rhs ends in O(x^3), order 3") != std::string::npos);
  r = dc::check_claim_line(R"J({"kind":"series","lhs":"sin(x)","rhs":"x + O(sin(x))","var":"x","point":"0"})J", 1, "b.jsonl");
  CHECK(r.at("verdict") == "error");
  CHECK(r.at("error").get<std::string>().find("the order term must be") != std::string::npos);
}
