#include "apps/checked_files.hpp"

#include <iostream>

#include "derivations/syntax/document.hpp"
#include "derivations/syntax/io.hpp"

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

int write_checked_document(const std::string& input, const std::string& output, const BudgetFlags& budget,
                           const std::string& not_a_document,
                           const std::function<std::string(const Derivation&, const CheckSummary&)>& render) {
  if (!is_document_path(input)) throw InputError({input, 0, 0}, not_a_document);
  const bool to_stdout = output.empty() || output == "-";
  if (!to_stdout) refuse_output_over_inputs(output, {input});
  exec::RunOptions run = budget.resolve();
  run.read_once = true;
  std::vector<FileReport> reports = exec::check_files({input}, run);
  if (reports.front().input_error) throw *reports.front().input_error;
  const std::string text = render(*reports.front().derivation, reports.front().summary);
  if (to_stdout) std::cout << text;
  else write_file_atomic(output, text);
  return totals(reports).exit_code(false);
}

}  // namespace dc::cli
