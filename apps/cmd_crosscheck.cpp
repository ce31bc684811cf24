// derivcheck crosscheck FILE|DIR... [--seed S] [--points N] [--no-stress] [--digits D]
// Every formula of the files evaluated by the fast evaluator (double, long double) and by the
// file's stable form, against the CLN reference at seeded random points of the declared
// domains plus stress points; prints median and max error in ulps per formula and method.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "apps/budget_flags.hpp"
#include "apps/commands.hpp"
#include "derivations/exec/pool.hpp"
#include "derivations/exec/wire.hpp"
#include "derivations/syntax/io.hpp"
#include "derivations/reader/derivation.hpp"
#include "numeric/crosscheck.hpp"

namespace dc::cli {
namespace {

struct CrossOptions {
  std::vector<std::string> inputs;
  num::CrossCheckOptions opt;
  bool no_stress = false;
  double fail_above = -1;
  BudgetFlags budget;
};

std::string encode(const std::vector<num::FormulaReport>& reports) {
  exec::Writer w;
  w.u64(reports.size());
  for (const auto& r : reports) {
    for (const auto* s : {&r.file, &r.label, &r.target, &r.stable_label, &r.stable_regime, &r.stable_of, &r.skipped})
      w.str(*s);
    w.u64(r.in_regime);
    w.u64(r.rejected);
    w.u64(r.reference_not_double);
    w.u64(r.methods.size());
    for (const auto& m : r.methods) {
      w.str(m.method);
      w.u64(m.points);
      w.u64(m.stress_points);
      for (double d : {m.median_ulps, m.max_ulps, m.max_ulps_random, m.max_ulps_stress}) w.f64(d);
      w.u64(m.non_finite);
      w.pairs(m.worst_point);
      w.str(m.worst_kind);
    }
  }
  return w.take();
}

std::vector<num::FormulaReport> decode(const std::string& bytes) {
  exec::WireReader rd(bytes);
  std::vector<num::FormulaReport> out(rd.u64());
  for (auto& r : out) {
    for (auto* s : {&r.file, &r.label, &r.target, &r.stable_label, &r.stable_regime, &r.stable_of, &r.skipped}) *s = rd.str();
    r.in_regime = rd.u64();
    r.rejected = rd.u64();
    r.reference_not_double = rd.u64();
    r.methods.resize(rd.u64());
    for (auto& m : r.methods) {
      m.method = rd.str();
      m.points = rd.u64();
      m.stress_points = rd.u64();
      for (double* d : {&m.median_ulps, &m.max_ulps, &m.max_ulps_random, &m.max_ulps_stress}) *d = rd.f64();
      m.non_finite = rd.u64();
      m.worst_point = rd.pairs();
      m.worst_kind = rd.str();
    }
  }
  return out;
}

int run(CrossOptions& o) {
  if (o.opt.points < 1 || o.opt.points > 1000000)
    throw std::domain_error("--points " + std::to_string(o.opt.points) + " is outside [1, 1000000]");
  if (o.opt.digits < 20 || o.opt.digits > 1000)
    throw std::domain_error("--digits " + std::to_string(o.opt.digits) + " is outside [20, 1000]");
  o.opt.stress = !o.no_stress;
  // One worker task per formula, under the budget: a formula whose reference values cannot
  // be computed in time is reported as not evaluated, with the budget as the reason.
  struct Task {
    std::size_t file;
    int formula;
    std::string label;
  };
  std::vector<Derivation> derivations;
  std::vector<Task> tasks;
  for (const auto& f : dc::derivation_files(o.inputs)) {
    derivations.push_back(load_derivation(f));
    int i = 0;
    for (const auto& formula : formulas(derivations.back())) tasks.push_back({derivations.size() - 1, i++, formula.label});
  }
  exec::RunOptions run = o.budget.resolve();
  const num::CrossCheckOptions base = o.opt;
  exec::Pool pool(run.jobs, run.budget, [&](const std::string& task) {
    const Task& t = tasks[std::stoul(task)];
    num::CrossCheckOptions one = base;
    one.only_formula = t.formula;
    return encode(num::crosscheck(derivations[t.file], one));
  });
  std::vector<num::FormulaReport> all;
  std::size_t next = 0, done = 0;
  pool.run([&](std::string& task) {
    if (next >= tasks.size()) return false;
    task = std::to_string(next++);
    return true;
  }, [&](exec::TaskOutcome&& out) {
    const Task& t = tasks[done++];
    if (out.done()) {
      for (auto& r : decode(out.payload)) all.push_back(std::move(r));
      return;
    }
    num::FormulaReport r;
    r.file = derivations[t.file].source.name;
    r.label = t.label;
    r.skipped = out.reason;
    all.push_back(std::move(r));
  });
  // a file with no formula is named with the reason, in file order, not skipped in silence
  for (std::size_t i = 0; i < derivations.size(); ++i) {
    if (!formulas(derivations[i]).empty()) continue;
    num::FormulaReport r;
    r.file = derivations[i].source.name;
    r.skipped = num::no_formula_reason(derivations[i]);
    auto at = std::find_if(all.begin(), all.end(), [&](const num::FormulaReport& x) {
      for (std::size_t j = i + 1; j < derivations.size(); ++j)
        if (x.file == derivations[j].source.name) return true;
      return false;
    });
    all.insert(at, std::move(r));
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
      o->budget.add_to(sub, true);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
