// The corpus transcribed from SymPy's published tests (tests/data/published/published.jsonl,
// tools/published-corpus/README.md), run through `derivcheck claims` with its budgets: no false
// claim proved or holding, no true claim refuted, at least 97 % judged right.
#include "cli/labelled_corpus.hpp"

TEST_CASE("published corpus: no false accept, no false refute, >= 97 % right", "[cli][published][soundness]") {
  const cli_test::CorpusScore s = cli_test::score_corpus(cli_test::src("tests/data/published/published.jsonl"));
  REQUIRE(s.claims >= 600);
  CAPTURE(s.false_accepts, s.false_refutes, s.errors, s.right);
  CHECK(s.false_accepts.empty());
  CHECK(s.false_refutes.empty());
  CHECK(s.errors.empty());
  CHECK(s.right >= static_cast<int>(s.claims) * 97 / 100);
}
