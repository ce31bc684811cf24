// derivcheck dc FILE -o OUT.dc — the author's LaTeX or Markdown document as the equivalent .dc
// file, each row with the rule its check found (docs/documents.md). Checked as `check` does
// (workers, budgets); OUT is written atomically and only when the document could be read.
// Exit code as for `check`.
#include <iostream>

#include "apps/budget_flags.hpp"
#include "apps/commands.hpp"
#include "derivations/exec/batch.hpp"
#include "derivations/report/dc_export.hpp"
#include "derivations/report/report.hpp"
#include "derivations/syntax/document.hpp"
#include "derivations/syntax/io.hpp"

namespace dc::cli {
namespace {

struct DcOptions {
  std::string input;
  std::string output;
  BudgetFlags budget;
};

int run(const DcOptions& o) {
  if (!is_document_path(o.input))
    throw InputError({o.input, 0, 0}, "dc reads a LaTeX (.tex) or Markdown (.md) document and writes its .dc file");
  const bool to_stdout = o.output.empty() || o.output == "-";
  if (!to_stdout) refuse_output_over_inputs(o.output, {o.input});
  exec::RunOptions run = o.budget.resolve();
  run.read_once = true;
  std::vector<FileReport> reports = exec::check_files({o.input}, run);
  if (reports.front().input_error) throw *reports.front().input_error;
  const std::string text = document_as_dc(*reports.front().derivation, reports.front().summary);
  if (to_stdout) std::cout << text;
  else write_file_atomic(o.output, text);
  return totals(reports).exit_code(false);
}

const CommandRegistrar registrar(
    "dc", "write a LaTeX or Markdown document as the equivalent .dc file, with the rules its check found",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<DcOptions>();
      sub.add_option("input", o->input, "the document (.tex or .md)")->required();
      sub.add_option("-o,--output", o->output, "output .dc file (written atomically; '-' or none: stdout)");
      o->budget.add_to(sub, true);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
