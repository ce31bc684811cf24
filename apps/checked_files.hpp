// The inputs of a command that writes a document of the derivations (`latex`, `html`): every
// file read once and every step checked, as `check` does, under the budget flags.
#pragma once
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

}  // namespace dc::cli
