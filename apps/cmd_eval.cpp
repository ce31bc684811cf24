// derivcheck eval FILE LABEL --at NAME=VALUE,... [--digits N]
// Prints the value of formula LABEL of a derivation file at an exact-rational point, computed
// with CLN (numeric/reference.hpp) and printed with N significant digits (deterministic).
// Unknown label or parameter, a missing parameter or a value outside its symbol's declared
// domain is an input error (exit 2) naming it.
#include <iostream>
#include <memory>

#include "apps/budget_flags.hpp"
#include "apps/commands.hpp"
#include "derivations/core/derivation.hpp"
#include "numeric/reference.hpp"

namespace dc::cli {
namespace {

struct EvalOptions {
  std::string file, label, at;
  int digits = 50;
  BudgetFlags budget;
};

int run(const EvalOptions& o) {
  return run_supervised(
      o.budget.resolve(),
      [&o](std::ostream& out) {
        const Derivation d = load_derivation(o.file);
        try {
          out << num::eval_formula(d, o.label, o.at, o.digits) << "\n";
        } catch (const std::range_error& e) {
          out << "undecided: " << e.what() << "\n";
          return kExitUndecided;
        }
        return kExitOk;
      },
      [](const std::string& reason) {
        std::cerr << "derivcheck: undecided: the value was not computed: " << reason << "\n";
        return kExitUndecided;
      });
}

const CommandRegistrar registrar(
    "eval", "evaluate a formula of a derivation file exactly (CLN) at a point of exact rationals",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<EvalOptions>();
      sub.add_option("file", o->file, "derivation file")->required();
      sub.add_option("label", o->label, "label of a step 'y = expr'")->required();
      sub.add_option("--at", o->at, "the point: NAME=VALUE,... with exact values (5/2, -0.125, 1e-9)");
      sub.add_option("--digits", o->digits, "significant digits of the result (1..1000)")->capture_default_str();
      o->budget.add_to(sub, false);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
