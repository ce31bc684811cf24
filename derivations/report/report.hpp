// Reports of `derivcheck check`: one line per step (GCC-style position, ✓/✗/?, label, tag,
// rule, verdict and method), evidence lines, errors with the offending line and a caret, and a
// summary. Text and JSON carry the same content; both are byte-identical across runs except
// for measured times (only printed with `timings`).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace dc {

// The outcome for one input file: either an input error (the file could not be read or
// parsed), or the derivation and the results of its steps.
struct FileReport {
  std::string file;
  std::optional<InputError> input_error;
  std::optional<Derivation> derivation;
  CheckSummary summary;
  double seconds = 0;
};

struct ReportOptions {
  bool timings = false;   // print measured times (the only non-deterministic output)
  bool quiet = false;     // only steps that did not hold, errors and the summary
  bool strict = false;    // errata count as failures (exit code 1)
};

// Read, parse and check one file (never throws for bad input: it becomes input_error).
FileReport check_file(const std::string& path, const ProveOptions& opt = {});

// Totals over files, and the exit code: 2 if any input error, else CheckSummary::exit_code.
struct Totals {
  int steps = 0, premises = 0, proved = 0, holds_numerically = 0, refuted = 0, undecided = 0, errors = 0, errata = 0;
  int input_errors = 0;
  double seconds = 0;
  int exit_code(bool strict) const;
};
Totals totals(const std::vector<FileReport>& files);

std::string format_text(const std::vector<FileReport>& files, const ReportOptions& opt);
// What format_text prints for one step: its line, the evidence, side conditions that are not
// guaranteed, notes, errors ("" for a step that holds under `quiet`). `d`, when given, names a
// document step's justification rows by their tags.
// The rows a document step's justification used, as the report names them: "(9.6)" for a
// tagged row (once for all its links), else the step's label; "" when none.
std::string justification_rows(const Derivation* d, const StepResult& r);
std::string format_step_text(const Step& s, const StepResult& r, const ReportOptions& opt,
                             const Derivation* d = nullptr);
// The summary line format_text ends with ("64 steps: 12 premises, ..."), without the newline.
std::string summary_text(const Totals& t, const ReportOptions& opt);
nlohmann::ordered_json to_json(const std::vector<FileReport>& files, const ReportOptions& opt);
// The verdict alone as JSON (used by `equal` and `claims` too).
nlohmann::ordered_json verdict_json(const Verdict& v);
// "proved (normal)", "refuted (numeric probe)", ... one line.
std::string verdict_phrase(const Verdict& v);
// Evidence lines (counterexample, values, residual, reason), each prefixed by `indent`.
std::string verdict_evidence(const Verdict& v, const std::string& indent);

}  // namespace dc
