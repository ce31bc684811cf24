// derivcheck equal LHS RHS [--assume "m1>0, v1 real, e in [0,1]"] — one claim (docs/cli.md).
#include <iostream>

#include "apps/budget_flags.hpp"
#include "apps/commands.hpp"
#include "derivations/claims/claims.hpp"
#include "derivations/syntax/io.hpp"
#include "derivations/report/report.hpp"

namespace dc::cli {
namespace {

struct EqualOptions {
  std::string lhs, rhs, assume;
  bool json = false;
  BudgetFlags budget;
};

void print(const Verdict& v, bool json, std::ostream& out) {
  if (json) {
    out << dc::json_text(verdict_json(v), 2) << "\n";
  } else {
    out << verdict_phrase(v) << "\n" << verdict_evidence(v, "    ");
    for (const auto& sc : v.side_conditions)
      if (sc.status != SideCondition::Status::Guaranteed)
        out << "    side condition: " << sc.what << " (" << sc.reason << ") "
                  << (sc.status == SideCondition::Status::Violated ? "violated" : "not guaranteed by the assumptions")
                  << (sc.evidence.empty() ? "" : ": " + sc.evidence) << "\n";
  }
}


int run(const EqualOptions& o) {
  // Parsing, the cascade and the probe all run in a worker under the budget.
  return run_supervised(
      o.budget.resolve(),
      [&o](std::ostream& out) {
        Verdict v = check_equal(o.lhs, o.rhs, o.assume);
        print(v, o.json, out);
        return exit_code_of(v.kind);
      },
      [&o](const std::string& reason) {
        Verdict v;
        v.method = "budget";
        v.reason = reason;
        print(v, o.json, std::cout);
        return exit_code_of(v.kind);
      });
}

const CommandRegistrar registrar(
    "equal", "decide whether two expressions are equal under assumptions",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<EqualOptions>();
      sub.add_option("lhs", o->lhs, "left-hand side")->required();
      sub.add_option("rhs", o->rhs, "right-hand side")->required();
      sub.add_option("--assume", o->assume,
                     "comma-separated assumptions: x>0, x>=0, x<0, x real, x in (a,b) / [a,b], or relations "
                     "such as v1 > v2; other symbols are real");
      sub.add_flag("--json", o->json, "print the verdict as JSON");
      o->budget.add_to(sub, false);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
