// The author's own rule for a row: a comment `% by solve (9.6), (9.7) for v_1', v_2'` (LaTeX),
// `<!-- by … -->` (Markdown) or `% derivcheck: by …`, inside a display or on the line right
// after it. It names the rule of the row it follows, in .dc rule syntax with the document's
// own references and names: tags `(9.6)`, `\eqref{eq:x}` / `\ref{x}` / a bare label `eq:x`,
// and TeX names and values (`v'_1`, `\theta = 0`). Those are written as step labels and .dc
// names, and the .dc reader reads the rule line (read_rule_line), so the row is checked
// exactly as the same step of a .dc file would be, with no search.
#include <cctype>

#include "derivations/document/reader.hpp"
#include "derivations/reader/derivation.hpp"

namespace dc::document_detail {

namespace {

bool is_keyword(const std::string& w) {
  for (const char* k : {"for", "into", "of", "with", "wrt", "from", "to", "order"})
    if (w == k) return true;
  return false;
}

std::string trimmed(const std::string& t) {
  const std::size_t b = t.find_first_not_of(" \t\n");
  if (b == std::string::npos) return "";
  return t.substr(b, t.find_last_not_of(" \t\n") - b + 1);
}

}  // namespace

// One argument group's items, each written in .dc notation: a reference becomes the labels of
// its rows, anything else is read as TeX (an equation or an expression).
std::string DocumentReader::as_dc_rule(const DocDirective& c, const std::string& rest) const {
  // split at top-level commas, keywords and arrows, keeping the separators
  std::vector<std::string> pieces;   // item, separator, item, ...
  std::string item;
  int depth = 0;
  auto flush = [&](const std::string& sep) {
    pieces.push_back(trimmed(item));
    pieces.push_back(sep);
    item.clear();
  };
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const char ch = rest[i];
    if (ch == '(' || ch == '{' || ch == '[') ++depth;
    if (ch == ')' || ch == '}' || ch == ']') --depth;
    if (depth == 0 && ch == ',') {
      flush(", ");
      continue;
    }
    if (depth == 0 && rest.compare(i, 2, "->") == 0) {
      flush(" -> ");
      ++i;
      continue;
    }
    if (depth == 0 && rest.compare(i, 3, "\\to") == 0 && (i + 3 >= rest.size() || !std::isalpha(static_cast<unsigned char>(rest[i + 3])))) {
      flush(" -> ");
      i += 2;
      continue;
    }
    if (depth == 0 && std::isalpha(static_cast<unsigned char>(ch)) &&
        (i == 0 || rest[i - 1] == ' ')) {
      std::size_t e = i;
      while (e < rest.size() && std::isalpha(static_cast<unsigned char>(rest[e]))) ++e;
      const std::string w = rest.substr(i, e - i);
      if (is_keyword(w) && (e >= rest.size() || rest[e] == ' ')) {
        flush(" " + w + " ");
        i = e - 1;
        continue;
      }
    }
    item += ch;
  }
  pieces.push_back(trimmed(item));
  std::string out;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (k % 2 == 1) {
      out += pieces[k];
      continue;
    }
    const std::string& it = pieces[k];
    if (it.empty()) continue;
    // a reference: (9.6), \eqref{x}, \ref{x}, a label, a step's own label
    std::string key = it;
    if (key.size() > 2 && key.front() == '(' && key.back() == ')') key = key.substr(1, key.size() - 2);
    for (const char* cmd : {"\\eqref{", "\\ref{"}) {
      const std::string c2 = cmd;
      if (key.rfind(c2, 0) == 0 && key.back() == '}') key = key.substr(c2.size(), key.size() - c2.size() - 1);
    }
    const std::vector<std::string>* rows = nullptr;
    if (auto t = tag_rows_.find(key); t != tag_rows_.end()) rows = &t->second;
    else if (auto l = label_rows_.find(key); l != label_rows_.end()) rows = &l->second;
    if (rows) {
      for (std::size_t j = 0; j < rows->size(); ++j) out += (j ? ", " : "") + (*rows)[j];
      continue;
    }
    if (d_.find(it)) {
      out += it;
      continue;
    }
    // a number of `to order N`, a TeX name, value or equation
    try {
      TexRow row = parse_tex_row(it, c.origin, ctx_);
      if (row.chains.size() == 1 && row.chains[0].sides.size() == 2 && row.chains[0].rels[0] == TexRel::Eq)
        out += to_text(row.chains[0].sides[0]) + " = " + to_text(row.chains[0].sides[1]);
      else if (row.chains.size() == 1 && row.chains[0].sides.size() == 1)
        out += to_text(row.chains[0].sides[0]);
      else
        out += it;
    } catch (const InputError&) {
      out += it;   // left as written: the .dc reader reports it
    }
  }
  return out;
}

void DocumentReader::authors_rules() {
  const std::string& src = doc_.source.text;
  for (const auto& c : doc_.rule_comments) {
    std::size_t e = 0;
    while (e < c.text.size() && (std::isalnum(static_cast<unsigned char>(c.text[e])) || c.text[e] == '_')) ++e;
    const std::string word = c.text.substr(0, e);
    if (!is_rule_name(word)) {
      if (c.addressed)
        throw InputError(c.origin, "unknown rule '" + word + "' after 'derivcheck: by'", static_cast<int>(std::max<std::size_t>(1, e)),
                         doc_.source.line(c.origin.line));
      continue;   // `% by the way`: a comment of the author's
    }
    // the display the comment is in, or the one that ends right before it
    const std::size_t at = offset_of(c.origin);
    const DocDisplay* disp = nullptr;
    std::size_t k = 0;
    for (std::size_t i = 0; i < doc_.displays.size(); ++i) {
      const DocDisplay& dd = doc_.displays[i];
      const std::size_t from = offset_of(dd.pos);
      if (from > at) break;
      std::string between = at > dd.end ? src.substr(dd.end, at - dd.end) : "";
      std::size_t newlines = 0;
      std::string marks;
      for (char ch : between) {
        if (ch == '\n') ++newlines;
        else if (ch != ' ' && ch != '\t' && ch != '\r') marks += ch;
      }
      for (const char* m : {"<!--", "%"})
        if (marks.rfind(m, 0) == 0) marks = marks.substr(std::string(m).size());
      if (marks.rfind("derivcheck:", 0) == 0) marks = marks.substr(11);
      if (marks == "by") marks.clear();
      if (at <= dd.end || (newlines <= 1 && marks.empty())) {
        disp = &dd;
        k = i;
      }
    }
    if (!disp) {
      d_.diagnostics.push_back(InputError::warning(c.origin, "a 'by " + word + "' comment that follows no displayed row is ignored; write it inside the display or on the line right after it",
                                                   static_cast<int>(e), doc_.source.line(c.origin.line)));
      continue;
    }
    // the last row of that display that starts before the comment
    const ReadRow* row = nullptr;
    for (const auto& r : rows_)
      if (r.display == k && offset_of(r.row->origin) < at) row = &r;
    if (!row) continue;
    const std::string rule = word + " " + as_dc_rule(c, c.text.substr(e));
    std::vector<std::size_t> links;
    for (std::size_t i = 0; i < d_.steps.size(); ++i) {
      const Step& s = d_.steps[i];
      if (s.document_row && s.document_row->relation != "inline" && s.pos.line == row->row->origin.line &&
          s.pos.col == row->row->origin.col)
        links.push_back(i);
    }
    // a comment that only looks like a rule (`% by definition of the momentum`) is the author's
    // prose: a warning, unless it was addressed to the checker (`% derivcheck: by …`)
    if (!c.addressed && !links.empty()) {
      try {
        (void)read_rule_line(d_, links.front(), rule, c.origin);
      } catch (const InputError& err) {
        d_.diagnostics.push_back(InputError::warning(c.origin, "a comment 'by " + word + " …' after a row is not read as its rule: " +
                                                                   err.message() + " (write `derivcheck: by …` to make it one)",
                                                     static_cast<int>(e), doc_.source.line(c.origin.line)));
        continue;
      }
    }
    for (std::size_t i : links) {
      Step& s = d_.steps[i];
      s.rule = read_rule_line(d_, i, rule, c.origin);
      s.rule.written_name = word;
      s.document_row->authors_rule = true;
      s.notes.push_back("the rule is the author's: 'by " + trimmed(c.text) + "' (line " + std::to_string(c.origin.line) +
                        "), read as 'by " + rule + "'");
    }
  }
}

}  // namespace dc::document_detail
