// Inline markup of literate text (see prose.hpp).
#include "derivations/syntax/prose.hpp"

namespace dc {

std::vector<ProsePiece> parse_prose(const ProseSource& src, const std::function<void(const Node&)>& validate,
                                    const std::function<void(const SourcePos&, const std::string&, int)>& fail) {
  const std::string& t = src.text;
  auto at = [&](std::size_t i) { return i < src.pos.size() ? src.pos[i] : src.end; };
  std::vector<ProsePiece> out;
  std::string plain;
  auto flush = [&] {
    if (plain.empty()) return;
    out.push_back({ProsePiece::Kind::Text, plain, {}});
    plain.clear();
  };
  // The closing delimiter of a piece opened at `open`, on the same paragraph.
  auto closing = [&](std::size_t open, char c, const char* what) {
    std::size_t k = open + 1;
    while (k < t.size() && t[k] != c) {
      if (t[k] == '\\' && k + 1 < t.size()) ++k;
      ++k;
    }
    if (k >= t.size()) fail(at(open), std::string("unterminated ") + what + ": expected a closing '" + c + "' in this paragraph", 1);
    return k;
  };
  for (std::size_t i = 0; i < t.size();) {
    char c = t[i];
    if (c == '\\' && i + 1 < t.size() && (t[i + 1] == '#' || t[i + 1] == '$' || t[i + 1] == '`' || t[i + 1] == '*')) {
      plain += t[i + 1];
      i += 2;
      continue;
    }
    if (c == '\n' || c == '\t' || c == '\r') {
      if (!plain.empty() && plain.back() != ' ') plain += ' ';
      ++i;
      continue;
    }
    if (c == ' ') {
      if (plain.empty() ? out.empty() : plain.back() == ' ') {
        ++i;
        continue;   // runs of spaces (indentation of continuation lines) are one space
      }
      plain += ' ';
      ++i;
      continue;
    }
    if (c == '$') {
      std::size_t k = closing(i, '$', "math '$...$'");
      std::string m = t.substr(i + 1, k - i - 1);
      for (char& ch : m)
        if (ch == '\n') ch = ' ';
      if (m.find_first_not_of(' ') == std::string::npos) fail(at(i), "empty math '$$': write the formula between the dollars", 2);
      int depth = 0;
      for (std::size_t j = 0; j < m.size(); ++j) {
        if (m[j] == '\\' && j + 1 < m.size()) { ++j; continue; }
        if (m[j] == '{') ++depth;
        if (m[j] == '}' && --depth < 0) fail(at(i + 1 + j), "unbalanced '}' in math", 1);
      }
      if (depth != 0) fail(at(i), "unbalanced '{' in math '$...$'", 1);
      flush();
      out.push_back({ProsePiece::Kind::Math, m, {}});
      i = k + 1;
      continue;
    }
    if (c == '`') {
      std::size_t k = closing(i, '`', "expression '`...`'");
      std::size_t b = i + 1, e = k;
      while (b < e && (t[b] == ' ' || t[b] == '\n')) ++b;
      while (e > b && (t[e - 1] == ' ' || t[e - 1] == '\n')) --e;
      if (b >= e) fail(at(i), "empty expression '``': write an expression of the file between the backticks", 2);
      ProsePiece p{ProsePiece::Kind::Expr, t.substr(b, e - b), {}, {}};
      // an expression, or an equation `beta = v/c` as prose writes them inline
      Relation r = parse_relation(std::string_view(t).substr(b, e - b), at(b));
      for (auto& side : r.sides) validate(side);
      p.expr = std::move(r.sides[0]);
      for (std::size_t j = 1; j < r.sides.size(); ++j) p.more.push_back(std::move(r.sides[j]));
      flush();
      out.push_back(std::move(p));
      i = k + 1;
      continue;
    }
    if (c == '*') {
      // *emphasis*: opens before a non-space, closes after one; a lone '*' is text
      // ($...$ and `expr` inside are skipped over and parsed as pieces of the emphasis)
      std::size_t k = i + 1;
      while (k < t.size() && t[k] != '*') {
        if (t[k] == '\\' && k + 1 < t.size()) {
          k += 2;
          continue;
        }
        if (t[k] == '$' || t[k] == '`') {
          std::size_t close = t.find(t[k], k + 1);
          if (close == std::string::npos) break;
          k = close;
        }
        ++k;
      }
      if (k < t.size() && t[k] == '*' && k > i + 1 && t[i + 1] != ' ' && t[k - 1] != ' ') {
        flush();
        std::string w = t.substr(i + 1, k - i - 1);
        std::vector<SourcePos> wpos;
        for (std::size_t j = i + 1; j < k; ++j) wpos.push_back(at(j));
        ProsePiece e{ProsePiece::Kind::Emph, {}, {}, {}};
        e.inner = parse_prose({w, wpos, at(k)}, validate, fail);
        e.text = prose_plain_text(e.inner);
        out.push_back(std::move(e));
        i = k + 1;
        continue;
      }
    }
    plain += c;
    ++i;
  }
  while (!plain.empty() && plain.back() == ' ') plain.pop_back();
  flush();
  return out;
}

std::string prose_plain_text(const std::vector<ProsePiece>& pieces) {
  std::string s;
  for (const auto& p : pieces) {
    switch (p.kind) {
      case ProsePiece::Kind::Text: s += p.text; break;
      case ProsePiece::Kind::Emph: s += p.text; break;
      case ProsePiece::Kind::Math: s += "$" + p.text + "$"; break;
      case ProsePiece::Kind::Expr: s += "`" + p.text + "`"; break;
    }
  }
  return s;
}

}  // namespace dc
