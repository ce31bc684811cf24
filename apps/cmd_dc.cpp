// derivcheck dc FILE -o OUT.dc — the author's LaTeX or Markdown document as the equivalent .dc
// file, each row with the rule its check found (docs/documents.md). Checked as `check` does
// (workers, budgets); OUT is written atomically and only when the document could be read.
// Exit code as for `check`.
#include "apps/budget_flags.hpp"
#include "apps/checked_files.hpp"
#include "apps/commands.hpp"
#include "derivations/report/dc_export.hpp"
#include "derivations/report/report.hpp"

namespace dc::cli {
namespace {

struct DcOptions {
  std::string input;
  std::string output;
  BudgetFlags budget;
};

int run(const DcOptions& o) {
  return write_checked_document(o.input, o.output, o.budget,
                                "dc reads a LaTeX (.tex) or Markdown (.md) document and writes its .dc file",
                                document_as_dc);
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
