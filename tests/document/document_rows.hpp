// The rows of a document as the document tests see them: each relation's line, link, verdict,
// the rule the search found and the reason, read and checked in this process.
#pragma once
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "derivations/document/document.hpp"

namespace document_test {

struct Row {
  std::string label;
  int line = 0;
  int link = 0;
  std::string verdict;   // premise, proved, holds_numerically, refuted, undecided
  std::string rule;
  std::string reason;
};

// Every step of the document (the equations of the text too, unless `displayed_only`).
inline std::vector<Row> check(const std::string& name, const std::string& text, bool displayed_only = false) {
  dc::Derivation d = dc::read_document(dc::SourceText{name, text});
  std::vector<Row> out;
  for (const auto& s : d.steps) {
    if (displayed_only && s.document_row && s.document_row->relation == "inline") continue;
    dc::StepResult r = dc::check_any_step(d, s);
    out.push_back({s.label, s.pos.line, s.document_row ? s.document_row->link : 0,
                   r.premise && r.verdict.holds() ? "premise" : dc::to_string(r.verdict.kind), r.found_rule,
                   r.verdict.reason});
  }
  return out;
}

inline const Row& at(const std::vector<Row>& rows, int line, int link = 0) {
  for (const auto& r : rows)
    if (r.line == line && r.link == link) return r;
  FAIL("no row at line " << line << " link " << link);
  return rows.front();
}

}  // namespace document_test
