// derivcheck equal LHS RHS [--assume "m1>0, v1 real, e in [0,1]"] — one claim (docs/cli.md).
#include <iostream>

#include "apps/commands.hpp"
#include "derivations/core/claims.hpp"
#include "derivations/core/io.hpp"
#include "derivations/core/report.hpp"

namespace dc::cli {
namespace {

struct EqualOptions {
  std::string lhs, rhs, assume;
  bool json = false;
};

int run(const EqualOptions& o) {
  Verdict v = check_equal(o.lhs, o.rhs, o.assume);
  if (o.json) {
    std::cout << dc::json_text(verdict_json(v), 2) << "\n";
  } else {
    std::cout << verdict_phrase(v) << "\n" << verdict_evidence(v, "    ");
    for (const auto& sc : v.side_conditions)
      if (sc.status != SideCondition::Status::Guaranteed)
        std::cout << "    side condition: " << sc.what << " (" << sc.reason << ") "
                  << (sc.status == SideCondition::Status::Violated ? "violated" : "not guaranteed by the assumptions")
                  << (sc.evidence.empty() ? "" : ": " + sc.evidence) << "\n";
  }
  switch (v.kind) {
    case VerdictKind::Proved:
    case VerdictKind::HoldsNumerically: return kExitOk;
    case VerdictKind::Refuted: return kExitRefuted;
    case VerdictKind::Undecided: return kExitUndecided;
  }
  return kExitInternal;
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
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
