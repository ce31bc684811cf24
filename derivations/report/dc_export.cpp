#include "derivations/report/dc_export.hpp"

#include <cctype>
#include <map>
#include <set>

namespace dc {
namespace {

std::string dc_label(const std::string& label) {
  std::string out = label;
  for (char& c : out)
    if (c == '.') c = '_';
  return out;
}

// The labels of `line` (tokens that are step labels) in their .dc spelling.
std::string relabel(const std::string& line, const std::map<std::string, std::string>& labels) {
  std::string out;
  for (std::size_t i = 0; i < line.size();) {
    const char c = line[i];
    if (std::isalpha(static_cast<unsigned char>(c)) && (i == 0 || !std::isalnum(static_cast<unsigned char>(line[i - 1])))) {
      std::size_t e = i;
      while (e < line.size() && (std::isalnum(static_cast<unsigned char>(line[e])) || line[e] == '_' || line[e] == '.')) ++e;
      std::string word = line.substr(i, e - i);
      while (!word.empty() && word.back() == '.') word.pop_back();   // a full stop after a label
      auto it = labels.find(word);
      out += it != labels.end() ? it->second : word;
      i += word.size();
      continue;
    }
    out += c;
    ++i;
  }
  return out;
}

std::string quoted(std::string s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += "'";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out + "\"";
}

std::string domain_text(const SymbolInfo& info) { return info.domain.to_string(); }

std::string unit_text(const SymbolInfo& info) { return info.unit.empty() ? "1" : info.unit; }

}  // namespace

std::string document_as_dc(const Derivation& d, const CheckSummary& summary) {
  std::map<std::string, std::string> labels;
  std::set<std::string> used;
  for (const auto& s : d.steps) {
    std::string l = dc_label(s.label);
    while (!used.insert(l).second) l += "_";
    labels[s.label] = l;
  }
  std::map<const Step*, const StepResult*> result_of;
  for (const auto& r : summary.results) result_of[r.step] = &r;

  std::string out;
  out += "# " + d.source.name + " as a .dc file: written by `derivcheck dc` from the rules its check found.\n";
  out += "# Rows with no justification found are premises here (`by given`, note \"TODO …\"): give their rule.\n";
  out += "title " + quoted(d.title) + "\n\n";
  for (const auto& info : d.symbols.all()) {
    if (info.defined_by_step || info.is_differential) continue;
    if (info.is_function) {
      std::string params;
      for (const auto& p : info.params) params += (params.empty() ? "" : ", ") + p;
      out += "function " + info.name + "(" + params + ") : " + domain_text(info) + " [" + unit_text(info) + "]\n";
    } else {
      out += "symbol " + info.name + " : " + domain_text(info) + " [" + unit_text(info) + "]\n";
    }
  }
  for (const auto& c : d.symbols.constraints()) out += "assume " + c.text + "\n";
  out += "\n";
  int todo = 0;
  std::set<std::string> tags_written;
  for (const auto& s : d.steps) {
    auto rit = result_of.find(&s);
    const StepResult* r = rit == result_of.end() ? nullptr : rit->second;
    const DocumentRow* row = s.document_row ? &*s.document_row : nullptr;
    const std::string where = "line " + std::to_string(s.pos.line) + (row && row->link > 0 ? ", relation " + std::to_string(row->link) : "");
    if (!r || (row && (!row->not_read.empty() || (row->relation != "=" && row->relation != "inline")))) {
      out += "# " + where + ": " + s.claim_text + (row && row->relation != "=" ? "  (" + row->relation + ")" : "") +
             " — not a .dc step" + (row && !row->not_read.empty() ? " (not read: " + row->not_read + ")" : "") + "\n";
      continue;
    }
    std::string claim = s.claim_text;
    std::vector<std::string> notes;
    std::string rule;
    const bool holds = r->verdict.holds();
    const bool refuted = r->verdict.kind == VerdictKind::Refuted;
    if (r->premise && holds) {
      rule = "by given";
    } else if ((holds || refuted) && r->found_rule == "identity") {
      rule = "by rewrite";
    } else if ((holds || refuted) && !r->found_line.empty()) {
      rule = relabel(r->found_line, labels);
      if (!r->found_claim.empty() && r->found_claim != s.claim_text) {
        notes.push_back("as written: " + s.claim_text);
        claim = r->found_claim;
      }
    } else if (holds) {
      rule = "by given";
      notes.push_back("derived in the document by " + r->found_rule + ", which a .dc rule line does not state here");
    } else if (refuted) {
      rule = "by given";
      ++todo;
      notes.push_back("TODO: REFUTED in the document by " + r->found_rule + " (" + r->verdict.method +
                      "), which a .dc rule line does not state here");
    } else {
      rule = "by given";
      ++todo;
      notes.push_back("TODO: no justification found in the document (" + r->verdict.reason + ")");
    }
    if (row && row->relation == "inline") notes.push_back("an equation of the text (" + where + ")");
    std::string head;
    if (!s.tag.empty() && tags_written.insert(s.tag).second) head = "(" + s.tag + ") ";
    out += head + labels[s.label] + ": " + claim + "\n    " + rule + "\n";
    for (const auto& n : notes) out += "    note " + quoted(n) + "\n";
  }
  out += "# " + std::to_string(todo) + (todo == 1 ? " row" : " rows") + " marked TODO\n";
  return out;
}

}  // namespace dc
