#include "derivations/report/report.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "derivations/document/document.hpp"
#include "derivations/syntax/io.hpp"

namespace dc {

namespace {

const char* mark(const StepResult& r) {
  std::size_t own = r.errors.size() - (r.erratum_reported ? 1 : 0);
  if (own > 0 || r.verdict.kind == VerdictKind::Refuted) return "\u2717";   // ✗
  if (r.verdict.kind == VerdictKind::Undecided) return "?";
  if (r.premise) return "\u2022";                                          // •
  return "\u2713";                                                           // ✓
}

std::string pos_text(const SourcePos& p) {
  return p.file + ":" + std::to_string(p.line) + ":" + std::to_string(p.col);
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f ms", s * 1e3);
  return buf;
}

std::string side_condition_status(SideCondition::Status s) {
  switch (s) {
    case SideCondition::Status::Guaranteed: return "guaranteed";
    case SideCondition::Status::Violated: return "violated";
    case SideCondition::Status::Unknown: return "not guaranteed by the declarations";
  }
  return "unknown";
}

nlohmann::ordered_json error_json(const InputError& e) {
  nlohmann::ordered_json j;
  j["file"] = e.pos().file;
  j["line"] = e.pos().line;
  j["col"] = e.pos().col;
  j["message"] = e.message();
  return j;
}

// Warnings and notes, each as error_json with its severity.
nlohmann::ordered_json diagnostics_json(const std::vector<InputError>& ds) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& w : ds) {
    nlohmann::ordered_json wj = error_json(w);
    wj["severity"] = w.severity_word();
    out.push_back(wj);
  }
  return out;
}

}  // namespace

std::string verdict_phrase(const Verdict& v) {
  std::string s;
  s = verdict_words(v.kind);
  if (!v.method.empty()) s += " (" + v.method + ")";
  if (v.kind == VerdictKind::HoldsNumerically) {
    s += ": " + std::to_string(v.points) + " points at " + std::to_string(v.digits) + " digits";
    if (!v.false_accept.empty()) s += ", false accept " + v.false_accept;
  }
  if (v.kind == VerdictKind::Undecided && !v.reason.empty()) s += ": " + v.reason;
  return s;
}

std::string verdict_evidence(const Verdict& v, const std::string& indent) {
  std::string out;
  if (v.kind == VerdictKind::Refuted) {
    if (!v.point.empty()) {
      std::string pt;
      for (const auto& [name, value] : v.point) pt += (pt.empty() ? "" : ", ") + name + " = " + value;
      out += indent + "counterexample: " + pt + "\n";
    }
    if (!v.function_values.empty()) out += indent + "function values drawn there: " + v.function_values + "\n";
    if (!v.lhs_value.empty() || !v.rhs_value.empty())
      out += indent + (v.lhs_label.empty() ? std::string("left side") : v.lhs_label) + " = " + v.lhs_value + ", " +
             (v.rhs_label.empty() ? std::string("right side") : v.rhs_label) + " = " + v.rhs_value + "\n";
    if (!v.hint.empty()) out += indent + "hint: " + v.hint + "\n";
  }
  // a claim that holds on the common domain of its sides says which assumption makes it hold
  // everywhere (decide/common_domain.hpp)
  if (v.holds() && !v.hint.empty()) out += indent + "hint: " + v.hint + "\n";
  if (v.kind == VerdictKind::Undecided && !v.residual.empty()) out += indent + "residual: " + v.residual + "\n";
  // The prover's own "differs at ..." repeats the counterexample above; rule details (which
  // link, what was eliminated) are kept.
  if (!v.holds() && !v.detail.empty() && v.detail.rfind("differs at", 0) != 0) out += indent + v.detail + "\n";
  return out;
}

nlohmann::ordered_json verdict_json(const Verdict& v) {
  nlohmann::ordered_json j;
  j["verdict"] = to_string(v.kind);
  j["method"] = v.method;
  if (!v.detail.empty()) j["detail"] = v.detail;
  if (v.kind == VerdictKind::HoldsNumerically || v.kind == VerdictKind::Refuted) {
    j["points"] = v.points;
    j["digits"] = v.digits;
    if (!v.false_accept.empty()) j["false_accept"] = v.false_accept;
  }
  if (v.kind == VerdictKind::Refuted) {
    nlohmann::ordered_json pt = nlohmann::ordered_json::object();
    for (const auto& [name, value] : v.point) pt[name] = value;
    j["counterexample"] = pt;
    j["lhs_value"] = v.lhs_value;
    j["rhs_value"] = v.rhs_value;
    if (!v.lhs_label.empty()) j["lhs_label"] = v.lhs_label;
    if (!v.rhs_label.empty()) j["rhs_label"] = v.rhs_label;
    if (!v.function_values.empty()) j["function_values"] = v.function_values;
    if (!v.hint.empty()) j["hint"] = v.hint;
  }
  if (v.holds() && !v.hint.empty()) j["hint"] = v.hint;
  if (v.kind == VerdictKind::Undecided) {
    if (!v.residual.empty()) j["residual"] = v.residual;
    j["reason"] = v.reason;
  }
  if (!v.side_conditions.empty()) {
    nlohmann::ordered_json sc = nlohmann::ordered_json::array();
    for (const auto& c : v.side_conditions) {
      nlohmann::ordered_json o;
      o["condition"] = c.what;
      o["reason"] = c.reason;
      o["status"] = c.status == SideCondition::Status::Guaranteed ? "guaranteed"
                    : c.status == SideCondition::Status::Violated ? "violated"
                                                                   : "unknown";
      if (!c.evidence.empty()) o["evidence"] = c.evidence;
      sc.push_back(o);
    }
    j["side_conditions"] = sc;
  }
  return j;
}

FileReport check_file(const std::string& path, const ProveOptions& opt) {
  FileReport fr;
  fr.file = path;
  auto t0 = std::chrono::steady_clock::now();
  try {
    fr.derivation.emplace(load_any(path));
  } catch (const InputError& e) {
    fr.input_error = e;
  }
  if (fr.derivation)
    for (const auto& s : fr.derivation->steps) fr.summary.add(check_any_step(*fr.derivation, s, opt));
  fr.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return fr;
}

int Totals::exit_code(bool strict) const {
  if (input_errors > 0) return kExitInputError;
  CheckSummary s;
  s.refuted = refuted;
  s.errors = errors;
  s.undecided = undecided;
  s.errata = errata;
  return s.exit_code(strict);
}

Totals totals(const std::vector<FileReport>& files) {
  Totals t;
  for (const auto& f : files) {
    if (f.input_error || f.summary.input_errors > 0) ++t.input_errors;
    t.steps += static_cast<int>(f.summary.results.size());
    t.premises += f.summary.premises;
    t.proved += f.summary.proved;
    t.holds_numerically += f.summary.holds_numerically;
    t.refuted += f.summary.refuted;
    t.undecided += f.summary.undecided;
    t.errors += f.summary.errors;
    t.errata += f.summary.errata;
    t.seconds += f.seconds;
  }
  return t;
}

// The rule of a step as the report names it: the rule the author wrote, or for a document step
// the justification the search found ("follows from (9.6), L120", "identity", "given").
std::string justification_rows(const Derivation* d, const StepResult& r) {
  std::string rows;
  std::vector<std::string> named;
  for (const auto& label : r.found_rows) {
    const Step* st = d ? d->find(label) : nullptr;
    const std::string name = st && !st->tag.empty() ? "(" + st->tag + ")" : label;
    if (std::find(named.begin(), named.end(), name) != named.end()) continue;   // links of one tagged row
    named.push_back(name);
    rows += (rows.empty() ? "" : ", ") + name;
  }
  return rows;
}

std::string rule_text(const Derivation* d, const Step& s, const StepResult& r) {
  if (!s.document_row) return s.rule.written_name;
  if (r.found_rule.empty()) return "(no justification found)";
  if (r.found_rows.empty()) return r.found_rule;
  return (r.verdict.kind == VerdictKind::Refuted ? "against " : "follows from ") + justification_rows(d, r);
}

std::string summary_text(const Totals& t, const ReportOptions& opt) {
  std::string out = std::to_string(t.steps) + " steps: " + std::to_string(t.premises) + " premises, " +
                    std::to_string(t.proved) + " proved, " + std::to_string(t.holds_numerically) +
                    " hold numerically, " + std::to_string(t.refuted) + " refuted, " + std::to_string(t.undecided) +
                    " undecided, " + std::to_string(t.errors) + " errors (" + std::to_string(t.errata) +
                    " errata reported)";
  if (t.input_errors > 0)
    out += "; " + std::to_string(t.input_errors) + (t.input_errors == 1 ? " file" : " files") + " with input errors";
  if (opt.timings) out += " [" + seconds_text(t.seconds) + "]";
  return out;
}

std::string format_step_text(const Step& s, const StepResult& r, const ReportOptions& opt, const Derivation* d) {
  std::string out;
  std::size_t own = r.errors.size() - (r.erratum_reported ? 1 : 0);
  bool ok = own == 0 && r.verdict.holds();
  if (opt.quiet && ok && !r.erratum_reported && s.diagnostics.empty()) return {};
  std::string line = pos_text(s.pos) + ": " + mark(r) + " " + s.label;
  if (!s.tag.empty()) line += " (" + s.tag + ")";
  // A step whose own error stopped its rule is "not checked" (the error follows), never ✗
  // beside "undecided".
  line += " " + rule_text(d, s, r) + " \u2014 " +
          (r.premise && r.verdict.holds() && s.document_row ? "given: " + r.verdict.detail
           : r.premise && r.verdict.holds() ? std::string("premise (symbols and dimensions checked)")
           : own > 0 && r.verdict.kind == VerdictKind::Undecided ? std::string("not checked")
                                                                 : verdict_phrase(r.verdict));
  if (own > 0) line += "; " + std::to_string(own) + (own == 1 ? " error" : " errors");
  if (r.erratum_reported) line += "; erratum reported";
  if (opt.timings) line += " [" + seconds_text(r.seconds) + "]";
  out += line + "\n";
  out += verdict_evidence(r.verdict, "    ");
  if (!ok && !r.derived.empty()) out += "    derived: " + r.derived + "\n";
  if (!opt.quiet) {
    if (introduces_name(s))
      out += "    introduces: " + to_text(s.claim.sides[0]) + " = " + to_text(s.claim.sides[1]) +
             ", for the steps after it\n";
    for (const auto& sc : r.verdict.side_conditions)
      if (sc.status != SideCondition::Status::Guaranteed)
        out += "    side condition: " + sc.what + " (" + sc.reason + ") " + side_condition_status(sc.status) +
               (sc.evidence.empty() ? "" : ": " + sc.evidence) + "\n";
    for (const auto& n : s.notes) out += "    note: " + n + "\n";
  }
  for (const auto& e : r.errors) out += e.format();
  for (const auto& w : s.diagnostics) out += w.format();
  return out;
}

std::string format_text(const std::vector<FileReport>& files, const ReportOptions& opt) {
  std::string out;
  for (const auto& f : files) {
    if (f.input_error) {
      out += f.input_error->format();
      continue;
    }
    const Derivation& d = *f.derivation;
    for (const auto& w : d.diagnostics) out += w.format();
    for (std::size_t i = 0; i < f.summary.results.size(); ++i)
      out += format_step_text(d.steps[i], f.summary.results[i], opt, &d);
  }
  return out + summary_text(totals(files), opt) + "\n";
}

nlohmann::ordered_json to_json(const std::vector<FileReport>& files, const ReportOptions& opt) {
  nlohmann::ordered_json root;
  nlohmann::ordered_json jf = nlohmann::ordered_json::array();
  for (const auto& f : files) {
    nlohmann::ordered_json o;
    o["file"] = f.file;
    if (f.input_error) {
      o["input_error"] = error_json(*f.input_error);
      jf.push_back(o);
      continue;
    }
    const Derivation& d = *f.derivation;
    o["title"] = d.title;
    o["section"] = d.section;
    if (!d.diagnostics.empty()) o["diagnostics"] = diagnostics_json(d.diagnostics);
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < f.summary.results.size(); ++i) {
      const StepResult& r = f.summary.results[i];
      const Step& s = d.steps[i];
      nlohmann::ordered_json j;
      j["label"] = s.label;
      j["tag"] = s.tag;
      j["line"] = s.pos.line;
      j["col"] = s.pos.col;
      j["rule"] = s.document_row ? r.found_rule : s.rule.written_name;
      if (s.document_row) {
        j["link"] = s.document_row->link;
        j["justification"] = {{"rule", r.found_rule}, {"rows", r.found_rows}};
      }
      j["claim"] = s.claim_text;
      if (s.erratum) {
        j["erratum"] = {{"why", s.erratum->why}, {"corrected", s.erratum->corrected_text}};
      }
      nlohmann::ordered_json vj = verdict_json(r.verdict);
      for (auto& [k, v] : vj.items()) j[k] = v;
      if (r.premise && r.verdict.holds()) j["verdict"] = "premise";
      j["derived"] = r.derived;
      j["dimension"] = r.dimension;
      if (introduces_name(s))
        j["introduces"] = {{"name", to_text(s.claim.sides[0])}, {"value", to_text(s.claim.sides[1])}};
      nlohmann::ordered_json errs = nlohmann::ordered_json::array();
      for (const auto& e : r.errors) errs.push_back(error_json(e));
      j["errors"] = errs;
      j["erratum_reported"] = r.erratum_reported;
      if (!s.diagnostics.empty()) j["diagnostics"] = diagnostics_json(s.diagnostics);
      if (!s.notes.empty()) j["notes"] = s.notes;
      if (opt.timings) j["seconds"] = r.seconds;
      steps.push_back(j);
    }
    o["steps"] = steps;
    jf.push_back(o);
  }
  root["files"] = jf;
  Totals t = totals(files);
  nlohmann::ordered_json sum;
  sum["steps"] = t.steps;
  sum["premises"] = t.premises;
  sum["proved"] = t.proved;
  sum["holds_numerically"] = t.holds_numerically;
  sum["refuted"] = t.refuted;
  sum["undecided"] = t.undecided;
  sum["errors"] = t.errors;
  sum["errata"] = t.errata;
  sum["input_errors"] = t.input_errors;
  if (opt.timings) sum["seconds"] = t.seconds;
  root["summary"] = sum;
  root["exit_code"] = t.exit_code(opt.strict);
  return root;
}

}  // namespace dc
