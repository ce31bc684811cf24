// The inputs of a command that writes a document of the derivations (`latex`, `html`): every
// file read once and every step checked, as `check` does, under the budget flags.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "apps/budget_flags.hpp"
#include "derivations/report/report.hpp"

namespace dc::cli {

struct CheckedFiles {
  std::vector<FileReport> reports;                 // one per file, in input order
  std::vector<const Derivation*> derivations;      // into reports
  std::vector<const CheckSummary*> checks;         // into reports, same order
};

// Throws the first file's input error (a positioned InputError: exit 2, nothing written).
CheckedFiles check_for_document(const std::vector<std::string>& files, const BudgetFlags& budget);

// `annotate` and `dc`: one author's LaTeX or Markdown document (anything else is an input
// error saying `not_a_document`), checked as `check` does, and what `render` makes of it
// written atomically to `output` (stdout when it is empty or "-"), only when the document
// could be read. Returns the exit code of `check`.
int write_checked_document(const std::string& input, const std::string& output, const BudgetFlags& budget,
                           const std::string& not_a_document,
                           const std::function<std::string(const Derivation&, const CheckSummary&)>& render);

}  // namespace dc::cli
