#include "apps/checked_files.hpp"

namespace dc::cli {

CheckedFiles check_for_document(const std::vector<std::string>& files, const BudgetFlags& budget) {
  exec::RunOptions run = budget.resolve();
  run.read_once = true;   // each file read once (read_once.hpp)
  CheckedFiles c;
  c.reports = exec::check_files(files, run);
  for (const auto& r : c.reports) {
    if (r.input_error) throw *r.input_error;
    c.derivations.push_back(&*r.derivation);
    c.checks.push_back(&r.summary);
  }
  return c;
}

}  // namespace dc::cli
