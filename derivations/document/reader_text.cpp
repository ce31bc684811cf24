// What the prose around the displays of a document says (reader.hpp): the equations of the
// text and which of them are in force for a display, the "where" clause after a display,
// names the text says to neglect, values at a point ("$v = 0$ at $t = 0$"), and names written
// once and never used.
#include <algorithm>
#include <cctype>

#include "derivations/document/reader.hpp"

namespace dc::document_detail {

std::string DocumentReader::read_values_at(Node& n, const std::map<std::string, std::string>& here) {
  std::string why;
  walk(n, [&](Node& x) {
    if (x.kind != NodeKind::Call || x.text != "value_at" || x.args.size() != 2 ||
        x.args[0].kind != NodeKind::Symbol)
      return;
    const std::string name = x.args[0].text;
    std::string var;
    if (auto it = here.find(name); it != here.end()) var = it->second;
    for (const auto& [id, v] : function_vars_)
      if (var.empty() && id == function_id(name, v)) var = v;
    if (var.empty() && x.args[1].kind == NodeKind::Symbol) var = x.args[1].text;   // x(t): the row says so
    if (var.empty() || var == name) {
      if (why.empty())
        why = name + "(" + to_text(x.args[1]) + ") is the value of " + name + " at " + to_text(x.args[1]) +
              ", but no row makes " + name + " a function of a variable (dv/dt, v(t))";
      return;
    }
    Node arg = x.args[1];
    x.text = function_id(name, var);
    x.args = {arg};
    function_vars_[x.text] = var;
  });
  return why;
}

// An inline equation of the prose (`$e = 1$`) is a given for the display that follows it.
void DocumentReader::inline_givens() {
  // `taking $v = 0$ at $t = 0$`: a value at a point (an initial condition), not a condition
  // of the display: neither equation is read as a given
  std::set<std::size_t> at_point;
  const std::string& src = doc_.source.text;
  for (std::size_t i = 0; i + 1 < doc_.inlines.size(); ++i) {
    std::size_t p = offset_of(doc_.inlines[i].origin) + doc_.inlines[i].text.size();
    if (src.compare(p, 1, "$") == 0) ++p;
    else if (src.compare(p, 2, "\\)") == 0) p += 2;
    else continue;
    while (p < src.size() && src[p] == ' ') ++p;
    if (src.compare(p, 3, "at ") != 0) continue;
    p += 3;
    while (p < src.size() && src[p] == ' ') ++p;
    if (p == offset_of(doc_.inlines[i + 1].origin) - 1 || p == offset_of(doc_.inlines[i + 1].origin) - 2) {
      at_point.insert(i);
      at_point.insert(i + 1);
    }
  }
  // `in equilibrium at $x = 0$`: the same, an equation right after the word "at"
  for (std::size_t i = 0; i < doc_.inlines.size(); ++i) {
    std::size_t p = offset_of(doc_.inlines[i].origin);
    if (p > 0 && (src[p - 1] == '$' || src[p - 1] == '(')) --p;   // the opening $ or \(
    if (p > 0 && src[p - 1] == '\\') --p;
    std::size_t e = p;
    while (e > 0 && src[e - 1] == ' ') --e;
    if (e >= 3 && src.compare(e - 2, 2, "at") == 0 && !std::isalpha(static_cast<unsigned char>(src[e - 3])))
      at_point.insert(i);
  }
  // `Discarding the root $T = 0$`, `other than $x = 0$`: an equation the words set aside is no
  // given (the words before it in its sentence, up to a few of them)
  for (std::size_t i = 0; i < doc_.inlines.size(); ++i) {
    std::size_t p = offset_of(doc_.inlines[i].origin);
    std::size_t b = p > 48 ? p - 48 : 0;
    for (std::size_t k = p; k > b; --k)
      if (src[k - 1] == '.' || src[k - 1] == '\n' || (k + 2 < p && src[k - 1] == '$')) {
        b = k;
        break;
      }
    std::string before = src.substr(b, p - b);
    for (auto& ch : before) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    // ("not" is no such word: "the pin cannot take a moment, $M(0) = 0$" asserts it)
    for (const char* w : {"discard", "exclud", "except", "other than", "apart from", "rather than", "instead of",
                          "reject"})
      if (before.find(w) != std::string::npos) at_point.insert(i);
  }
  for (std::size_t mi = 0; mi < doc_.inlines.size(); ++mi) {
    const auto& m = doc_.inlines[mi];
    if (at_point.count(mi)) continue;
    TexRow row;
    try {
      row = parse_tex_row(m.text, m.origin, ctx_);
    } catch (const InputError&) {
      continue;   // prose math that is not an equation we read: symbols only
    }
    note_lone_names(row);
    // `$\mu = dm/dt$`: a name differentiated on its own is a function of that variable here, as
    // in a display (read plain, dm/dt would be 0)
    {
      std::map<std::string, std::string> functions;
      for (const auto& ch : row.chains)
        for (const auto& side : ch.sides)
          walk(side, [&](const Node& x) {
            if (x.kind == NodeKind::Call && x.text == "diff" && x.args.size() >= 2 &&
                x.args[0].kind == NodeKind::Symbol && x.args[1].kind == NodeKind::Symbol)
              functions[x.args[0].text] = x.args[1].text;
          });
      std::string unread;
      for (auto& ch : row.chains)
        for (auto& side : ch.sides)
          if (std::string why = read_values_at(side, functions); unread.empty()) unread = why;
      if (!unread.empty()) continue;   // `$v(0) = 0$` with v a function of nothing: symbols only
      for (auto& ch : row.chains)
        for (auto& side : ch.sides) to_functions(side, functions);
      for (const auto& [name, var] : functions) function_vars_[function_id(name, var)] = var;
    }
    for (const auto& ch : row.chains) {
      // `$\mu = m_1/m_2$`, and the substitutions the text makes (`substitute $v_2 \approx v_0$`)
      if (ch.continues || ch.sides.size() < 2) continue;
      bool relations_ok = true;
      for (TexRel rel : ch.rels) relations_ok = relations_ok && (rel == TexRel::Eq || rel == TexRel::Approx);
      if (!relations_ok) {   // `$0 < e < 1$`: bounds the names it mentions from here on
        std::set<std::string> names;
        for (const auto& side : ch.sides) symbol_names(side, names);
        for (const auto& n : names) bounded_.push_back({m.displays_before, m.origin, n});
        continue;
      }
      if (!row.vector_names.empty()) continue;
      bool has_unit = false;
      for (const auto& u : ch.side_units) has_unit = has_unit || !u.empty();
      if (has_unit) continue;   // a value with a unit, `$m_1 = 1 \text{ kg}$`: not read yet
      Step s;
      s.label = "I" + std::to_string(m.origin.line) + "." + std::to_string(m.origin.col);
      s.claim.sides = ch.sides;
      s.claim_text = to_text(s.claim);
      s.pos = s.claim_pos = m.origin;
      s.rule.name = s.rule.written_name = "given";
      DocumentRow dr;
      dr.relation = "inline";
      dr.display = static_cast<int>(m.displays_before);   // the display it leads into
      s.document_row = dr;
      std::string subject = ch.sides[0].kind == NodeKind::Symbol ? ch.sides[0].text : std::string();
      const bool where = m.displays_before > 0 && in_where_clause(m.displays_before - 1, m.origin);
      inline_steps_.push_back({m.displays_before, static_cast<std::size_t>(m.section), std::move(s), subject, where});
    }
  }
}

// Which inline givens define a fresh name: their subject appears in no display of their
// section before them and in no equation of the text there before them, and its value is an
// expression of other names.
void DocumentReader::mark_definitions() {
  auto before = [](const SourcePos& a, const SourcePos& b) {
    return a.line < b.line || (a.line == b.line && a.col < b.col);
  };
  for (auto& is : inline_steps_) {
    if (is.subject.empty()) continue;
    bool seen = false;
    for (const auto& r : rows_) {
      if (seen || r.display >= is.displays_before ||
          static_cast<std::size_t>(doc_.displays[r.display].section) != is.section)
        continue;
      for (const auto& ch : r.tex.chains)
        for (const auto& side : ch.sides) {
          std::set<std::string> names;
          symbol_names(side, names);
          seen = seen || names.count(is.subject) > 0;
        }
    }
    for (const auto& o : inline_steps_) {
      if (seen || o.section != is.section || !before(o.step.pos, is.step.pos)) continue;
      for (const auto& side : o.step.claim.sides) {
        std::set<std::string> names;
        symbol_names(side, names);
        seen = seen || names.count(is.subject) > 0;
      }
    }
    // a value (`$v_2 = 0$`) or another name (`$m_1 = m_2$`, `$T_2 = T_1$`) is a case of the
    // section, however fresh: only an expression defines (`$\mu = dm/dt$`, `$\rho = m/L$`)
    const Node* value = &is.step.claim.sides.back();
    while (value->kind == NodeKind::Neg && !value->args.empty()) value = &value->args[0];
    is.defines = !seen && is.step.claim.sides.size() == 2 && value->kind != NodeKind::Number &&
                 value->kind != NodeKind::Symbol;
  }
}

std::vector<std::string> DocumentReader::definitions_for(std::size_t k, std::size_t section) const {
  std::vector<std::string> out;
  auto after = [](const SourcePos& a, const SourcePos& b) {
    return a.line > b.line || (a.line == b.line && a.col > b.col);
  };
  for (const auto& is : inline_steps_) {
    if (!is.defines || is.section != section || is.displays_before > k) continue;
    bool superseded = false;
    for (const auto& o : inline_steps_)
      superseded = superseded || (&o != &is && o.subject == is.subject && o.displays_before <= k &&
                                  after(o.step.pos, is.step.pos));
    for (const auto& b : bounded_)
      superseded = superseded || (b.name == is.subject && b.displays_before <= k && after(b.pos, is.step.pos));
    // a display row between the definition and display k that gives the name a value
    for (const auto& r : rows_) {
      if (superseded || r.display < is.displays_before || r.display >= k) continue;
      for (const auto& ch : r.tex.chains)
        superseded = superseded || (!ch.continues && !ch.sides.empty() && ch.sides[0].kind == NodeKind::Symbol &&
                                    ch.sides[0].text == is.subject);
    }
    if (!superseded) out.push_back(is.step.label);
  }
  return out;
}

// A name written once in the whole document, in the text, is used for nothing and defined
// nowhere: most often a slip for another name (the seed handout's v_e for u_e).
void DocumentReader::note_lone_names(const TexRow& row) {
  for (const auto& ch : row.chains)
    for (std::size_t i = 0; i < ch.sides.size(); ++i) {
      const Node& side = ch.sides[i];
      // the left side of an equation in the text is defined there (`$L_0 = 1$ m`)
      if (i == 0 && ch.sides.size() > 1 && side.kind == NodeKind::Symbol) continue;
      walk(side, [&](const Node& x) {
        if (x.kind != NodeKind::Symbol || is_reserved_name(x.text) || x.text.size() < 2) return;
        auto tex = row.tex_of.find(x.text);
        if (tex == row.tex_of.end() || tex->second.empty()) return;
        const std::string& src = doc_.source.text;
        std::size_t count = 0;
        for (std::size_t p = src.find(tex->second); p != std::string::npos && count < 2;
             p = src.find(tex->second, p + 1))
          ++count;
        if (count != 1 || !lone_.insert(x.text).second) return;
        std::vector<std::string> candidates;
        for (const auto& r : rows_)
          for (const auto& c : r.tex.chains)
            for (const auto& sd : c.sides) {
              std::set<std::string> names;
              symbol_names(sd, names);
              for (const auto& n : names)
                if (std::find(candidates.begin(), candidates.end(), n) == candidates.end()) candidates.push_back(n);
            }
        d_.diagnostics.push_back(InputError::warning(
            x.pos, "'" + tex->second + "' appears only here: no equation uses or defines it" +
                       did_you_mean(x.text, candidates),
            std::max(1, x.length), doc_.source.line(x.pos.line)));
      });
    }
}

// Offsets and positions in the document's text.
std::size_t DocumentReader::offset_of(const SourcePos& p) const {
  const std::string& t = doc_.source.text;
  std::size_t off = 0;
  for (int line = 1; line < p.line && off < t.size(); ++line) {
    const std::size_t nl = t.find('\n', off);
    if (nl == std::string::npos) return t.size();
    off = nl + 1;
  }
  return std::min(t.size(), off + static_cast<std::size_t>(std::max(0, p.col - 1)));
}

// The "where …" clause right after display k: the text from its end to the first full stop,
// blank line or next display, when that text begins with "where", "with", "here" or "in
// which". Its equations define the display's names (`where $\mu = m_1/m_2$`).
bool DocumentReader::in_where_clause(std::size_t k, const SourcePos& at) const {
  if (k >= doc_.displays.size()) return false;
  const std::string& t = doc_.source.text;
  std::size_t b = doc_.displays[k].end;
  while (b < t.size() && std::isspace(static_cast<unsigned char>(t[b]))) ++b;
  std::string head = t.substr(b, 9);
  for (char& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  auto starts = [&](const char* w) {
    const std::size_t n = std::char_traits<char>::length(w);
    return head.compare(0, n, w) == 0 && (head.size() == n || !std::isalpha(static_cast<unsigned char>(head[n])));
  };
  if (!(starts("where") || starts("with") || starts("here") || starts("in which"))) return false;
  std::size_t e = k + 1 < doc_.displays.size() ? offset_of(doc_.displays[k + 1].pos) : t.size();
  e = std::min(e, t.find("\n\n", b));
  bool in_math = false;
  for (std::size_t i = b; i + 1 < e; ++i) {
    if (t[i] == '$') in_math = !in_math;
    if (!in_math && t[i] == '.' && std::isspace(static_cast<unsigned char>(t[i + 1]))) {
      e = i;
      break;
    }
  }
  const std::size_t o = offset_of(at);
  return o >= b && o < e;
}

// "neglect D", "neglecting $D$", "ignoring D" in the text before a display, where D is a
// name of that display: D = 0 is a condition of the display, listed as a given of the text
// (the words are the author's; the search may use them to derive a row, never to refute one).
void DocumentReader::neglected_names() {
  const std::string& t = doc_.source.text;
  for (std::size_t k = 0; k < doc_.displays.size(); ++k) {
    const std::size_t b = k == 0 ? 0 : doc_.displays[k - 1].end;
    const std::size_t e = offset_of(doc_.displays[k].pos);
    if (e <= b) continue;
    std::set<std::string> names;   // the names of this display's rows and the rows before it
    for (const auto& r : rows_)
      if (r.display <= k)
        for (const auto& ch : r.tex.chains)
          for (const auto& side : ch.sides) symbol_names(side, names);
    for (const char* verb : {"neglect", "ignor"}) {
      for (std::size_t p = t.find(verb, b); p != std::string::npos && p < e; p = t.find(verb, p + 1)) {
        std::size_t q = p;
        while (q < e && std::isalpha(static_cast<unsigned char>(t[q]))) ++q;   // neglect|ing|ed
        while (q < e && t[q] == ' ') ++q;
        if (t.compare(q, 4, "the ") == 0) q += 4;
        std::size_t tb = q, te = q;
        if (q < e && t[q] == '$') {
          tb = q + 1;
          te = t.find('$', tb);
          if (te == std::string::npos || te >= e) continue;
        } else {
          while (te < e && !std::isspace(static_cast<unsigned char>(t[te])) && t[te] != ',' && t[te] != '.' &&
                 t[te] != ';' && t[te] != ')')
            ++te;
        }
        if (te <= tb || te - tb > 24) continue;
        const SourcePos at = position_in(t, {doc_.source.name, 1, 1}, tb);
        TexRow row;
        try {
          row = parse_tex_row(t.substr(tb, te - tb), at, ctx_);
        } catch (const InputError&) {
          continue;
        }
        if (row.chains.size() != 1 || row.chains[0].sides.size() != 1) continue;
        const Node& x = row.chains[0].sides[0];
        if (x.kind != NodeKind::Symbol || !names.count(x.text)) continue;
        Step s;
        s.label = "N" + std::to_string(at.line) + "." + std::to_string(at.col);
        Node zero;
        zero.kind = NodeKind::Number;
        zero.text = "0";
        zero.pos = at;
        s.claim.sides = {x, zero};
        s.claim_text = to_text(s.claim);
        s.pos = s.claim_pos = at;
        s.rule.name = s.rule.written_name = "given";
        s.notes.push_back("read from the words '" + t.substr(p, te - p + (t[te] == '$' ? 1 : 0)) + "' in the text");
        DocumentRow dr;
        dr.relation = "inline";
        dr.display = static_cast<int>(k);
        s.document_row = dr;
        InlineStep is{k, static_cast<std::size_t>(doc_.displays[k].section), std::move(s), x.text};
        auto it = std::find_if(inline_steps_.begin(), inline_steps_.end(), [&](const InlineStep& o) {
          return o.displays_before > k || (o.displays_before == k && (o.step.pos.line > at.line ||
                                                                      (o.step.pos.line == at.line && o.step.pos.col > at.col)));
        });
        inline_steps_.insert(it, std::move(is));
      }
    }
  }
}

// The conditions in force for a display: the inline givens of the text just before it
// (`For equal masses, $m_1 = m_2$, this becomes:`). A display that follows the previous one
// with no text between, or whose text adds givens of its own (a special case of the case at
// hand), keeps the conditions of the previous display; a given for a name already given
// (`$e = 0$` after `$e = 1$`) starts a new case; text without givens ends the case.
std::vector<std::string> DocumentReader::conditions_for(std::size_t k, const std::vector<std::string>& own, const std::vector<std::string>& previous, bool same_section) const {
  const DocDisplay& disp = doc_.displays[k];
  const bool has_prose = disp.prose_before.find_first_not_of(" \t\n$") != std::string::npos;
  if (!same_section) return own;
  if (has_prose && own.empty()) return {};
  std::vector<std::string> out = previous;
  for (const auto& g : own) {
    const std::string& subject = subject_of_.at(g);
    for (const auto& p : previous)
      if (!subject.empty() && subject_of_.at(p) == subject && !restates(g, p)) return own;   // a new case
    out.push_back(g);
  }
  return out;
}

// The inline givens of the section before display k that are not in force there, unless a
// later given for the same name or an inequality of the text about it (`$0 < e < 1$`)
// supersedes them before the display.
std::vector<std::string> DocumentReader::stated_earlier(std::size_t k, std::size_t section, const std::vector<std::string>& in_force) const {
  std::vector<std::string> out;
  auto after = [](const SourcePos& a, const SourcePos& b) {   // a after b
    return a.line > b.line || (a.line == b.line && a.col > b.col);
  };
  for (const auto& is : inline_steps_) {
    if (is.section != section || is.displays_before > k || is.subject.empty()) continue;
    if (std::find(in_force.begin(), in_force.end(), is.step.label) != in_force.end()) continue;
    bool superseded = false;
    for (const auto& o : inline_steps_)
      superseded = superseded || (o.subject == is.subject && o.displays_before <= k && after(o.step.pos, is.step.pos));
    for (const auto& b : bounded_)
      superseded = superseded || (b.name == is.subject && b.displays_before <= k && after(b.pos, is.step.pos));
    if (!superseded) out.push_back(is.step.label);
  }
  return out;
}

// Does inline given g restate p's value (`$\mu = m_1/m_2 \approx 0$` after `$\mu = m_1/m_2$`):
// a regime of the same quantity, not a new case.
bool DocumentReader::restates(const std::string& g, const std::string& p) const {
  const InlineStep* a = nullptr;
  const InlineStep* b = nullptr;
  for (const auto& is : inline_steps_) {
    if (is.step.label == g) a = &is;
    if (is.step.label == p) b = &is;
  }
  if (!a || !b || b->step.claim.sides.size() < 2) return false;
  const std::string value = to_text(b->step.claim.sides.back());
  for (std::size_t i = 1; i < a->step.claim.sides.size(); ++i)
    if (to_text(a->step.claim.sides[i]) == value) return true;
  return false;
}

// "(9.6)", "Eq. 9.6", "\eqref{x}" in prose: the tags and labels it names.
std::vector<std::string> DocumentReader::tags_in(const std::string& prose) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < prose.size(); ++i) {
    if (prose[i] != '(') continue;
    std::size_t j = i + 1;
    while (j < prose.size() && (std::isdigit(static_cast<unsigned char>(prose[j])) || prose[j] == '.' ||
                                std::isalpha(static_cast<unsigned char>(prose[j]))))
      ++j;
    if (j < prose.size() && prose[j] == ')' && j > i + 1 && std::isdigit(static_cast<unsigned char>(prose[i + 1])))
      out.push_back(prose.substr(i + 1, j - i - 1));
  }
  return out;
}

// The labels the text cites with \eqref{…} or \ref{…}.
std::vector<std::string> DocumentReader::refs_in(const std::string& prose) {
  std::vector<std::string> out;
  for (const char* cs : {"\\eqref{", "\\ref{"})
    for (std::size_t p = prose.find(cs); p != std::string::npos; p = prose.find(cs, p + 1)) {
      const std::size_t b = p + std::char_traits<char>::length(cs);
      const std::size_t e = prose.find('}', b);
      if (e != std::string::npos) out.push_back(prose.substr(b, e - b));
    }
  return out;
}

std::string DocumentReader::hint_of(const std::string& prose) {
  // the last two sentences of the last paragraph ("m_2 can be considered infinite. This gives:")
  std::size_t from = 0;
  const std::size_t para = prose.rfind("\n\n", prose.find_last_not_of(" \t\n"));
  if (para != std::string::npos) from = para + 2;
  int stops = 0;
  for (std::size_t i = prose.size(); i-- > from + 1;) {
    const char c = prose[i - 1];
    if ((c == '.' || c == '!' || c == '?') && std::isspace(static_cast<unsigned char>(prose[i])) &&
        prose.find_first_not_of(" \t\n", i) != std::string::npos && ++stops == 2) {
      from = i;
      break;
    }
  }
  std::string tail = prose.substr(from);
  if (tail.size() > 400) tail = tail.substr(tail.size() - 400);
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail;
}

// The text after a display when it continues the display's sentence ("where the higher-order
// term was neglected"): up to its first full stop. A new sentence or paragraph is the next
// display's business.
std::string DocumentReader::continuation_of(const std::string& prose) {
  const std::size_t b = prose.find_first_not_of(" \t\n");
  if (b == std::string::npos || !std::islower(static_cast<unsigned char>(prose[b]))) return "";
  std::size_t e = prose.size();
  for (std::size_t i = b; i + 1 < prose.size(); ++i)
    if ((prose[i] == '.' && std::isspace(static_cast<unsigned char>(prose[i + 1]))) ||
        (prose[i] == '\n' && prose[i + 1] == '\n')) {
      e = i;
      break;
    }
  std::string out = prose.substr(b, std::min<std::size_t>(e - b, 400));
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace dc::document_detail
