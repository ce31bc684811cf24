#include "apps/checked_files.hpp"

#include "derivations/syntax/document.hpp"

namespace dc::cli {

CheckedFiles check_for_document(const std::vector<std::string>& files, const BudgetFlags& budget) {
  // A LaTeX or Markdown document is already the author's document: it is checked with
  // `check` and written back with its verdicts by `annotate`, not typeset again.
  for (const auto& f : files)
    if (is_document_path(f))
      throw InputError({f, 0, 0}, "this command typesets .dc derivations; '" + f +
                                      "' is a document: check it with `derivcheck check`, or write it with its "
                                      "verdicts by `derivcheck annotate`");
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
