#include "derivations/report/annotate.hpp"

#include <map>

#include "derivations/report/report.hpp"
#include "derivations/syntax/document.hpp"

namespace dc {
namespace {

std::string tex_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '\\': out += "\\textbackslash{}"; break;
      case '{': case '}': case '_': case '#': case '$': case '%': case '&':
        out += '\\';
        out += c;
        break;
      case '^': out += "\\^{}"; break;
      case '~': out += "\\~{}"; break;
      default: out += c;
    }
  }
  return out;
}

// One row's note: "line 126: derived (follows from (9.6), (9.7))".
std::string note_of(const Derivation& d, const StepResult& r) {
  const Step& s = *r.step;
  std::string where = "line " + std::to_string(s.pos.line);
  if (s.document_row->link > 0) where += ", relation " + std::to_string(s.document_row->link);
  std::string what;
  if (r.premise && r.verdict.holds()) {
    what = "given";
  } else if (r.verdict.holds()) {
    what = "derived";
    const std::string rows = justification_rows(&d, r);
    what += r.found_rule == "identity" ? " (an identity)" : rows.empty() ? "" : " (follows from " + rows + ")";
  } else if (r.verdict.kind == VerdictKind::Refuted) {
    what = "REFUTED";
    const std::string rows = justification_rows(&d, r);
    if (!rows.empty()) what += " against " + rows;
    std::string point;
    for (const auto& [name, value] : r.verdict.point) point += (point.empty() ? "" : ", ") + name + " = " + value;
    if (!point.empty()) what += ": fails at " + point;
  } else {
    what = "undecided";
    if (!r.verdict.reason.empty()) what += ": " + r.verdict.reason;
  }
  return where + ": " + what;
}

}  // namespace

std::string annotate_document(const Derivation& d, const CheckSummary& summary) {
  const Document doc = split_document(d.source);
  std::map<int, std::vector<std::string>> notes;   // display -> notes of its rows
  for (const auto& r : summary.results) {
    const Step& s = *r.step;
    if (!s.document_row || s.document_row->relation == "inline") continue;
    notes[s.document_row->display].push_back(note_of(d, r));
  }
  const bool latex = doc.kind == Document::Kind::Latex;
  std::string out;
  std::size_t copied = 0;
  for (std::size_t k = 0; k < doc.displays.size(); ++k) {
    auto it = notes.find(static_cast<int>(k));
    if (it == notes.end()) continue;
    const std::size_t at = doc.displays[k].end;
    out.append(d.source.text, copied, at - copied);
    copied = at;
    if (latex) {
      out += "\n\\par\\noindent{\\footnotesize\\textsf{derivcheck:}";
      for (const auto& n : it->second) out += " " + tex_escape(n) + ";";
      out += "}\\par";   // on a line of its own: the author's line break follows
    } else {
      out += "\n\n> **derivcheck:**\n";
      for (const auto& n : it->second) out += "> - " + n + "\n";
      out += "\n";
    }
  }
  out.append(d.source.text, copied, std::string::npos);
  return out;
}

}  // namespace dc
