// derivcheck latex FILE|DIR... -o out.tex [--fragment] [--annotate] [--title T]
// Writes the derivations as LaTeX (docs/latex.md). The output file is written atomically and
// only when every input loaded: an input error leaves no (partial) output and exits 2.
#include <algorithm>
#include <filesystem>
#include <iostream>

#include "apps/commands.hpp"
#include "derivations/core/derivation.hpp"
#include "derivations/core/io.hpp"
#include "derivations/core/latex.hpp"
#include "derivations/core/rules.hpp"

namespace dc::cli {
namespace {

struct LatexCliOptions {
  std::vector<std::string> inputs;
  std::string output;
  std::string title;
  std::string subtitle;
  bool fragment = false, annotate = false;
};

int run(const LatexCliOptions& o) {
  const std::vector<std::string> files = dc::derivation_files(o.inputs);
  const bool to_stdout = o.output.empty() || o.output == "-";
  if (!to_stdout) refuse_output_over_inputs(o.output, files);   // before any work
  std::vector<Derivation> ds;
  for (const auto& f : files) ds.push_back(load_derivation(f));  // InputError -> exit 2
  std::vector<const Derivation*> ptrs;
  for (const auto& d : ds) ptrs.push_back(&d);
  std::vector<CheckSummary> summaries;
  std::vector<const CheckSummary*> checks;
  LatexOptions lo;
  lo.fragment = o.fragment;
  lo.annotate = o.annotate;
  lo.title = o.title;
  lo.subtitle = o.subtitle;
  if (o.annotate) {
    summaries.reserve(ds.size());
    for (const auto& d : ds) summaries.push_back(check_derivation(d));
    for (const auto& s : summaries) checks.push_back(&s);
    lo.checks = &checks;
  }
  std::string tex = write_latex(ptrs, lo);
  if (to_stdout) {
    std::cout << tex;
    return kExitOk;
  }
  write_file_atomic(o.output, tex);   // InputError (cannot write) -> exit 2, target untouched
  return kExitOk;
}

const CommandRegistrar registrar(
    "latex", "write derivations as LaTeX (a standalone document, or --fragment to \\input)",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<LatexCliOptions>();
      sub.add_option("inputs", o->inputs, "derivation files or directories (a directory means its *.dc files)")
          ->required();
      sub.add_option("-o,--output", o->output, "output .tex file (written atomically; '-' or none: stdout)");
      sub.add_flag("--fragment", o->fragment, "no preamble: sections to \\input into a document with amsmath, amssymb");
      sub.add_flag("--annotate", o->annotate, "each step's rule and verdict as a margin note, and its notes");
      sub.add_option("--title", o->title, "document title (default: the derivation's title)");
      sub.add_option("--subtitle", o->subtitle, "a line under the title");
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
