// derivcheck html FILE|DIR... -o DIR [--title T] [--subtitle S] [--katex DIR]
// Writes the checked web page of the derivations (docs/html.md): DIR/index.html with every
// step's verdict beside it, and the KaTeX it needs. Nothing is written when an input has an
// error (exit 2); the site is put in place whole, and a folder html did not write is refused.
// The exit code is `check`'s: the page is written whatever the verdicts, since it shows them.
#include <iostream>

#include "apps/budget_flags.hpp"
#include "apps/checked_files.hpp"
#include "apps/commands.hpp"
#include "numeric/charts/figure_data.hpp"
#include "derivations/report/html.hpp"
#include "derivations/syntax/io.hpp"

namespace dc::cli {
namespace {

// Where Debian's libjs-katex installs KaTeX (its fonts are a link into fonts-katex).
constexpr const char* kDebianKatex = "/usr/share/javascript/katex";

struct HtmlCliOptions {
  std::vector<std::string> inputs;
  std::string output;
  std::string title;
  std::string subtitle;
  std::string katex = kDebianKatex;
  BudgetFlags budget;
};

int run(const HtmlCliOptions& o) {
  const std::vector<std::string> files = dc::derivation_files(o.inputs);
  check_html_site_target(o.output);   // before any work: a folder html did not write is refused,
  check_html_katex(o.katex);          // and so is a missing KaTeX
  const CheckedFiles checked = check_for_document(files, o.budget);
  const Totals t = totals(checked.reports);
  if (t.input_errors > 0) {   // a step whose references contradict each other: bad input, nothing written
    ReportOptions quiet;
    quiet.quiet = true;
    std::cerr << format_text(checked.reports, quiet);
    return kExitInputError;
  }
  HtmlOptions ho;
  ho.title = o.title;
  ho.subtitle = o.subtitle;
  ho.summary = summary_text(t, ReportOptions{});
  const std::map<const Prose*, std::string> figures = chart::svg_figures(checked.derivations);
  ho.figures = &figures;
  write_html_site(o.output, write_html(checked.derivations, checked.checks, ho), o.katex);
  std::cerr << "derivcheck html: wrote " << o.output << "/index.html (" << summary_text(t, ReportOptions{}) << ")\n";
  return t.exit_code(false);
}

const CommandRegistrar registrar(
    "html", "write the checked web page of derivations: DIR/index.html with every step's verdict",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<HtmlCliOptions>();
      sub.add_option("inputs", o->inputs, "derivation files or directories (a directory means its *.dc files)")
          ->required();
      sub.add_option("-o,--output", o->output,
                     "the site's folder (new, empty, or a site html wrote before; replaced whole)")
          ->required();
      sub.add_option("--title", o->title, "page title (default: as for latex)");
      sub.add_option("--subtitle", o->subtitle, "a line under the title");
      sub.add_option("--katex", o->katex, "the folder holding KaTeX (default: Debian's " + std::string(kDebianKatex) + ")");
      o->budget.add_to(sub, true);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
