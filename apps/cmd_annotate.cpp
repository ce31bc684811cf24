// derivcheck annotate FILE -o OUT — the author's LaTeX or Markdown document with the verdict of
// each displayed row after its display (docs/documents.md). Checked as `check` does (workers,
// budgets); OUT is written atomically and only when the document could be read. Exit code as
// for `check`.
#include <iostream>

#include "apps/budget_flags.hpp"
#include "apps/commands.hpp"
#include "derivations/exec/batch.hpp"
#include "derivations/report/annotate.hpp"
#include "derivations/report/report.hpp"
#include "derivations/syntax/document.hpp"
#include "derivations/syntax/io.hpp"

namespace dc::cli {
namespace {

struct AnnotateOptions {
  std::string input;
  std::string output;
  BudgetFlags budget;
};

int run(const AnnotateOptions& o) {
  if (!is_document_path(o.input))
    throw InputError({o.input, 0, 0}, "annotate reads a LaTeX (.tex) or Markdown (.md) document; for a .dc file "
                                      "use `derivcheck latex --annotate`");
  const bool to_stdout = o.output.empty() || o.output == "-";
  if (!to_stdout) refuse_output_over_inputs(o.output, {o.input});
  exec::RunOptions run = o.budget.resolve();
  run.read_once = true;
  std::vector<FileReport> reports = exec::check_files({o.input}, run);
  if (reports.front().input_error) throw *reports.front().input_error;
  const std::string text = annotate_document(*reports.front().derivation, reports.front().summary);
  if (to_stdout) std::cout << text;
  else write_file_atomic(o.output, text);
  return totals(reports).exit_code(false);
}

const CommandRegistrar registrar(
    "annotate", "write a LaTeX or Markdown document with each displayed row's verdict beside it",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<AnnotateOptions>();
      sub.add_option("input", o->input, "the document (.tex or .md)")->required();
      sub.add_option("-o,--output", o->output, "output file (written atomically; '-' or none: stdout)");
      o->budget.add_to(sub, true);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
