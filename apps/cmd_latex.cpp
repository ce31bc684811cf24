// derivcheck latex FILE|DIR... -o out.tex [--fragment] [--annotate] [--title T]
// Writes the derivations as LaTeX (docs/latex.md). The output file is written atomically and
// only when every input loaded: an input error leaves no (partial) output and exits 2.
// A figure that names what draws it (`plot ...`, `simulate ...`) gets its data in a file beside
// out.tex, named out-figN.dat (N: the figure's number in the document), read by pgfplots.
#include <algorithm>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <iostream>

#include "apps/budget_flags.hpp"
#include "apps/checked_files.hpp"
#include "apps/commands.hpp"
#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/io.hpp"
#include "derivations/report/latex.hpp"
#include "derivations/rules/check.hpp"
#include "derivations/exec/batch.hpp"
#include "numeric/charts/figure_data.hpp"

namespace dc::cli {
namespace {

struct LatexCliOptions {
  std::vector<std::string> inputs;
  std::string output;
  std::string title;
  std::string subtitle;
  bool fragment = false, annotate = false, allow_unchecked = false, units = false;
  BudgetFlags budget;
};

std::string step_position(const Derivation& d, const Step& s) {
  return d.source.name + ":" + std::to_string(s.pos.line) + ":" + std::to_string(s.pos.col);
}

// The figures drawn by the code (numeric/charts/figure_data.hpp), their data files beside the
// .tex and never in a folder the derivations are read from; to stdout, the data stand inline.
// Any error is an InputError, raised before anything is written.
chart::DrawnFigures draw_figures(const std::vector<const Derivation*>& ds, const std::string& output,
                                 const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  const bool to_stdout = output.empty() || output == "-";
  const fs::path out_path(output);
  chart::DrawnFigures out = chart::draw_figures(ds, to_stdout ? std::string() : out_path.stem().string());
  for (auto& [name, text] : out.files) {
    const fs::path data = out_path.parent_path() / name;
    for (const auto& in : inputs) {
      std::error_code ec;
      if (fs::equivalent(fs::absolute(fs::path(in)).parent_path(), fs::absolute(out_path).parent_path(), ec))
        throw std::invalid_argument("the figures' data files would be written beside " + in + " (" + data.string() +
                                    "): write the .tex outside the source folder");
    }
    refuse_output_over_inputs(data.string(), inputs);
    name = data.string();
  }
  return out;
}

int run(const LatexCliOptions& o) {
  const std::vector<std::string> files = dc::derivation_files(o.inputs);
  const bool to_stdout = o.output.empty() || o.output == "-";
  if (!to_stdout) refuse_output_over_inputs(o.output, files);   // before any work
  // Every step is checked (as `check` does, under the budgets): a handout with a step that does
  // not hold is not emitted unless --allow-unchecked, and then that step is marked in it.
  const CheckedFiles checked = check_for_document(files, o.budget);
  std::vector<std::string> unchecked;
  for (const auto& r : checked.reports) {
    for (const auto& res : r.summary.results)
      if (!step_checked_ok(res))
        unchecked.push_back(step_position(*r.derivation, *res.step) + ": step '" + res.step->label + "' " +
                            (res.verdict.holds() ? std::string("has errors") : "is " + std::string(to_string(res.verdict.kind))) +
                            " (" + res.verdict.method + ")");
  }
  // figure lines are input: a bad one stops everything (exit 2) before any check verdict counts
  const chart::DrawnFigures figures = draw_figures(checked.derivations, o.output, files);
  if (!unchecked.empty() && !o.allow_unchecked) {
    for (const auto& u : unchecked) std::cerr << u << "\n";
    std::cerr << "derivcheck latex: " << unchecked.size() << (unchecked.size() == 1 ? " step does" : " steps do")
              << " not hold; no LaTeX written (run `derivcheck check` for the evidence, or pass --allow-unchecked "
                 "to emit it with those steps marked)\n";
    return kExitRefuted;
  }
  LatexOptions lo;
  lo.fragment = o.fragment;
  lo.annotate = o.annotate;
  lo.units = o.units;
  lo.title = o.title;
  lo.subtitle = o.subtitle;
  lo.checks = &checked.checks;
  lo.mark_unchecked = o.allow_unchecked;
  lo.drawn_figures = &figures.pictures;
  std::string tex = write_latex(checked.derivations, lo);
  if (to_stdout) {
    std::cout << tex;
    return kExitOk;
  }
  for (const auto& [path, text] : figures.files) write_file_atomic(path, text);   // the data before the .tex
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
      sub.add_flag("--annotate", o->annotate, "each step's rule and verdict on a line under it, and its notes");
      sub.add_flag("--units", o->units, "each section lists its quantities with their units (needs siunitx)");
      sub.add_option("--title", o->title, "document title (default: the derivation's title)");
      sub.add_option("--subtitle", o->subtitle, "a line under the title");
      sub.add_flag("--allow-unchecked", o->allow_unchecked,
                   "emit even if steps are refuted or undecided (they are marked NOT CHECKED)");
      o->budget.add_to(sub, true);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
