// derivcheck annotate FILE -o OUT — the author's LaTeX or Markdown document with the verdict of
// each displayed row after its display (docs/documents.md). Checked as `check` does (workers,
// budgets); OUT is written atomically and only when the document could be read. Exit code as
// for `check`.
#include "apps/budget_flags.hpp"
#include "apps/checked_files.hpp"
#include "apps/commands.hpp"
#include "derivations/report/annotate.hpp"
#include "derivations/report/report.hpp"

namespace dc::cli {
namespace {

struct AnnotateOptions {
  std::string input;
  std::string output;
  BudgetFlags budget;
};

int run(const AnnotateOptions& o) {
  return write_checked_document(o.input, o.output, o.budget,
                                "annotate reads a LaTeX (.tex) or Markdown (.md) document; for a .dc file "
                                "use `derivcheck latex --annotate`",
                                annotate_document);
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
