// derivcheck crosscheck FILE|DIR... [--seed S] [--points N] [--no-stress] [--digits D]
// Every formula of the files evaluated by the fast evaluator (double, long double) and by the
// file's stable form, against the CLN reference at seeded random points of the declared
// domains plus stress points; prints median and max error in ulps per formula and method.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "apps/commands.hpp"
#include "derivations/core/io.hpp"
#include "derivations/core/derivation.hpp"
#include "numeric/crosscheck.hpp"

namespace dc::cli {
namespace {

struct CrossOptions {
  std::vector<std::string> inputs;
  num::CrossCheckOptions opt;
  bool no_stress = false;
  double fail_above = -1;
};

int run(CrossOptions& o) {
  if (o.opt.points < 1 || o.opt.points > 1000000)
    throw std::domain_error("--points " + std::to_string(o.opt.points) + " is outside [1, 1000000]");
  if (o.opt.digits < 20 || o.opt.digits > 1000)
    throw std::domain_error("--digits " + std::to_string(o.opt.digits) + " is outside [20, 1000]");
  o.opt.stress = !o.no_stress;
  std::vector<num::FormulaReport> all;
  for (const auto& f : dc::derivation_files(o.inputs)) {
    const Derivation d = load_derivation(f);
    auto r = num::crosscheck(d, o.opt);
    all.insert(all.end(), r.begin(), r.end());
  }
  std::cout << num::format_crosscheck(all, o.opt);
  if (o.fail_above >= 0) {
    for (const auto& r : all)
      for (const auto& m : r.methods)
        if (m.method == "stable" && !(m.max_ulps <= o.fail_above)) return kExitRefuted;
  }
  return kExitOk;
}

const CommandRegistrar registrar(
    "crosscheck",
    "evaluate every formula (double, long double, stable form, compensated) against the CLN reference",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<CrossOptions>();
      sub.add_option("inputs", o->inputs, "derivation files or directories")->required();
      sub.add_option("--seed", o->opt.seed, "seed of the random points (printed)")->capture_default_str();
      sub.add_option("--points", o->opt.points, "random points per formula")->capture_default_str();
      sub.add_option("--digits", o->opt.digits, "precision of the CLN reference")->capture_default_str();
      sub.add_flag("--no-stress", o->no_stress, "random points only");
      sub.add_option("--fail-above", o->fail_above,
                     "exit 1 if a stable form's max error exceeds this many ulps");
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
