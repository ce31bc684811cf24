// derivcheck eval FILE LABEL [--for NAME] (--at NAME=VALUE,... | --points IN.csv [-o OUT.csv])
//                 [--method auto|double|long-double|compensated|stable|reference] [--digits N]
//
// reference: the value with N certified significant digits (Arb; numeric/reference/bind.cpp).
// The double methods (numeric/certified/certified.hpp) print the double in round-trip form, then the
// method and a certified bound on its error:
//     -1.2857142857142858
//     method: auto (correctly rounded: Arb enclosure at 96 bits)
//     error: <= 0.5 ulp
// Without --method: reference when --digits is given (as before), otherwise auto.
// --points: one row per point, the header names the parameters; every row runs in a worker
// under the budget, and a row that fails or runs out of budget says so in its own row.
// Unknown label or parameter, a missing parameter or a value outside its symbol's declared
// domain is an input error (exit 2) naming it.
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "apps/budget_flags.hpp"
#include "apps/commands.hpp"
#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/io.hpp"
#include "derivations/exec/pool.hpp"
#include "numeric/certified/certified.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"

namespace dc::cli {
namespace {

struct EvalOptions {
  std::string file, label, at, method, points, output;
  std::string for_name;   // --for NAME: solve a step that is not 'y = expression' for NAME
  int digits = 50;
  bool digits_given = false;
  BudgetFlags budget;
};

std::string bound_text(double ulps) {
  if (ulps < 0) return "none (the value is not a finite double)";
  if (ulps == 0) return "0 (exact)";
  if (ulps == 0.5) return "<= 0.5 ulp";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", ulps);
  double shown = std::strtod(buf, nullptr);
  if (shown < ulps) std::snprintf(buf, sizeof buf, "%.2g", std::nextafter(shown * 1.05, 1e308));   // never below the bound
  return std::string("<= ") + buf + (ulps == 1 ? " ulp" : " ulps");
}

// One point: the text `eval` prints (three or four lines) or, for CSV, the row's fields.
struct Answer {
  std::string value, method, bound, note;
};

Answer evaluate(const Derivation& d, const EvalOptions& o, const std::string& at) {
  Answer a;
  if (o.method == "reference") {
    a.value = num::eval_formula(d, o.label, at, o.digits);
    a.method = "reference (Arb, " + std::to_string(o.digits) + " certified digits)";
    return a;
  }
  num::CertifiedDouble r = num::certified_eval(d, o.label, num::parse_assignments(at), *num::parse_double_method(o.method));
  a.value = num::shortest_text(r.value);
  a.method = r.method;
  a.bound = bound_text(r.error_ulps);
  a.note = r.note;
  return a;
}

// The file, with step LABEL solved for --for (or for the one quantity `given` leaves open)
// when it is not 'y = expression' (solve_step_for).
Derivation load_for_eval(const EvalOptions& o, const std::vector<std::string>& given) {
  Derivation d = load_derivation(o.file);
  solve_step_for(d, o.label, o.for_name, given);
  return d;
}

std::vector<std::string> names_in_at(const std::string& at) {
  std::vector<std::string> out;
  std::size_t from = 0;
  while (from <= at.size()) {
    std::size_t to = at.find(',', from);
    if (to == std::string::npos) to = at.size();
    std::string item = at.substr(from, to - from);
    std::size_t eq = item.find('=');
    std::string n = item.substr(0, eq);
    n.erase(0, n.find_first_not_of(" \t"));
    if (auto e = n.find_last_not_of(" \t"); e != std::string::npos) n.erase(e + 1);
    if (!n.empty()) out.push_back(n);
    from = to + 1;
  }
  return out;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') out.emplace_back();
    else if (c != '\r' && c != ' ' && c != '\t') out.back() += c;
  }
  return out;
}

int run_points(const EvalOptions& o) {
  const std::string text = read_file(o.points);
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (l.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(l);
  if (lines.empty()) throw InputError({o.points, 1, 1}, "empty points file: expected a header row naming the parameters");
  const std::vector<std::string> header = split_csv_line(lines[0]);
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i].empty()) throw InputError({o.points, 1, 1}, "empty column name in the header (column " + std::to_string(i + 1) + ")");
  const Derivation d = load_for_eval(o, header);
  (void)formula(d, o.label);   // an unknown label is an input error before any row runs

  // each row's text as --at takes it ("" when the row has the wrong number of cells)
  std::vector<std::string> ats(lines.size());
  for (std::size_t row = 1; row < lines.size(); ++row) {
    const std::vector<std::string> cells = split_csv_line(lines[row]);
    if (cells.size() != header.size()) continue;
    for (std::size_t i = 0; i < header.size(); ++i) ats[row] += (i ? "," : "") + header[i] + "=" + cells[i];
  }
  auto answer_fields = [](const Answer& a) {
    return csv_field(a.value) + "," + csv_field(a.method) + "," + csv_field(a.bound) + "," + csv_field(a.note);
  };
  // Tasks, each in a supervised worker: "row R" evaluates row R as `--at` would; "rows A B"
  // runs the double-double stage of auto for rows [A, B) at once (no loop, but the exact
  // parsing and the domain checks of a hostile row are work too, so it runs under the budget)
  // and answers, one record per row, the row's fields or nothing (the row then gets a task of
  // its own). Each row's answer is exactly what its own task would give.
  constexpr char kRecord = '\x1e';
  exec::RunOptions run = o.budget.resolve();
  exec::Pool pool(run.jobs, run.budget, [&](const std::string& task) -> std::string {
    std::istringstream t(task);
    std::string kind;
    std::size_t first = 0, last = 0;
    t >> kind >> first;
    if (kind == "rows") {
      t >> last;
      std::vector<std::size_t> rows;
      std::vector<std::vector<std::pair<std::string, GiNaC::numeric>>> points;
      for (std::size_t row = first; row < last; ++row) {
        if (ats[row].empty()) continue;
        try {
          points.push_back(num::parse_assignments(ats[row]));
          rows.push_back(row);
        } catch (const std::exception&) {
          // malformed value: the row's own task reports it
        }
      }
      const auto answers = num::certified_auto_first_stage(d, o.label, points);
      std::vector<std::string> records(last - first);
      for (std::size_t j = 0; j < rows.size(); ++j) {
        if (!answers[j]) continue;
        Answer a;
        a.value = num::shortest_text(answers[j]->value);
        a.method = answers[j]->method;
        a.bound = bound_text(answers[j]->error_ulps);
        a.note = answers[j]->note;
        records[rows[j] - first] = answer_fields(a);
      }
      std::string out;
      for (const auto& r : records) out += r + kRecord;
      return out;
    }
    const std::vector<std::string> cells = split_csv_line(lines[first]);
    try {
      if (cells.size() != header.size())
        throw std::invalid_argument(std::to_string(cells.size()) + " values for " + std::to_string(header.size()) + " columns");
      return answer_fields(evaluate(d, o, ats[first]));
    } catch (const std::exception& e) {
      return ",,," + csv_field(std::string("error: ") + e.what());
    }
  });
  std::vector<std::string> payload(lines.size());
  std::vector<bool> answered(lines.size(), false);
  if (o.method == "auto") {
    constexpr std::size_t kChunk = 256;
    std::size_t next = 1;
    std::vector<std::size_t> sent;
    std::size_t back = 0;
    pool.run(
        [&](std::string& task) {
          if (next >= lines.size()) return false;
          const std::size_t last = std::min(lines.size(), next + kChunk);
          task = "rows " + std::to_string(next) + " " + std::to_string(last);
          sent.push_back(next);
          next = last;
          return true;
        },
        [&](exec::TaskOutcome&& r) {
          std::size_t row = sent[back++];
          if (!r.done()) return;   // over its budget: every row of the chunk gets its own task
          std::size_t from = 0;
          for (std::size_t to; (to = r.payload.find(kRecord, from)) != std::string::npos; from = to + 1, ++row)
            if (to > from) {
              payload[row] = r.payload.substr(from, to - from);
              answered[row] = true;
            }
        });
  }
  std::size_t next = 1;
  std::vector<std::size_t> sent;   // rows in the order their tasks went out (outcomes come back in it)
  std::size_t back = 0;
  pool.run(
      [&](std::string& task) {
        while (next < lines.size() && answered[next]) ++next;
        if (next >= lines.size()) return false;
        sent.push_back(next);
        task = "row " + std::to_string(next++);
        return true;
      },
      [&](exec::TaskOutcome&& r) {
        payload[sent[back++]] = r.done() ? r.payload : ",,," + csv_field("undecided: " + r.reason);
      });
  std::string out;
  for (const auto& h : header) out += csv_field(h) + ",";
  out += "value,method,error_bound,note\n";
  int failed = 0;
  for (std::size_t row = 1; row < lines.size(); ++row) {
    std::string cells;
    for (const auto& c : split_csv_line(lines[row])) cells += csv_field(c) + ",";
    if (payload[row].rfind(",,,", 0) == 0) ++failed;
    out += cells + payload[row] + "\n";
  }
  if (o.output.empty() || o.output == "-") std::cout << out;
  else write_file_atomic(o.output, out);
  std::cerr << "eval: " << lines.size() - 1 << " points, " << failed << " without a value\n";
  return failed ? kExitRefuted : kExitOk;
}

int run(EvalOptions o) {
  if (o.method.empty()) o.method = o.digits_given ? "reference" : "auto";
  if (o.method != "reference" && !num::parse_double_method(o.method))
    throw std::invalid_argument("--method '" + o.method +
                                "': expected auto, double, long-double, compensated, stable or reference");
  if (o.digits_given && o.method != "reference")
    throw std::invalid_argument("--digits applies to --method reference (the double methods print a double)");
  if (!o.points.empty()) {
    if (!o.at.empty()) throw std::invalid_argument("give either --at or --points, not both");
    if (!o.output.empty() && o.output != "-") refuse_output_over_inputs(o.output, {o.file, o.points});
    return run_points(o);
  }
  if (!o.output.empty()) throw std::invalid_argument("-o is for --points (the results as CSV)");
  return run_supervised(
      o.budget.resolve(),
      [&o](std::ostream& out) {
        const Derivation d = load_for_eval(o, names_in_at(o.at));
        Answer a;
        try {
          a = evaluate(d, o, o.at);
        } catch (const std::range_error& e) {
          out << "undecided: " << e.what() << "\n";
          return kExitUndecided;
        }
        out << a.value << "\n";
        if (o.method != "reference") {
          out << "method: " << a.method << "\n";
          out << "error: " << a.bound << "\n";
          if (!a.note.empty()) out << "note: " << a.note << "\n";
        }
        return kExitOk;
      },
      [](const std::string& reason) {
        std::cerr << "derivcheck: undecided: the value was not computed: " << reason << "\n";
        return kExitUndecided;
      });
}

const CommandRegistrar registrar(
    "eval", "evaluate a formula of a derivation file: a certified double, or N certified digits",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<EvalOptions>();
      sub.add_option("file", o->file, "derivation file")->required();
      sub.add_option("label", o->label, "label of a step 'y = expr' (or any equation, with --for)")->required();
      sub.add_option("--for", o->for_name,
                     "solve the step for this quantity first (cos(theta) = expr gives theta = acos(expr)); "
                     "without it, a step that is not 'y = expr' is solved for the one quantity --at leaves out");
      sub.add_option("--at", o->at, "the point: NAME=VALUE,... with exact values (5/2, -0.125, 1e-9, 1e+200)");
      sub.add_option("--method", o->method,
                     "auto (correctly rounded double, default), double, long-double, compensated, stable, or "
                     "reference (N digits; the default with --digits)");
      sub.add_option("--digits", o->digits, "significant digits of --method reference (1..1000; default 50)")
          ->each([o](const std::string&) { o->digits_given = true; });
      sub.add_option("--points", o->points, "CSV file: a header naming the parameters, one point per row");
      sub.add_option("-o", o->output, "with --points: write the results as CSV here (default stdout)");
      o->budget.add_to(sub, true);
      return [o] { return run(*o); };
    });

}  // namespace
}  // namespace dc::cli
