// One displayed row: what only typesets is dropped (spacing, \left/\right, sizes), \label,
// \tag, \eqref and a trailing (9.6) are taken out, the row is split at top-level separators
// (, ; : \quad \text{and}) and at "gives" arrows, and each piece is read as a chain.
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "derivations/syntax/tex/internal/parser.hpp"
#include "derivations/syntax/tex_math.hpp"

namespace dc {
namespace tex {
namespace {

bool plain_group(const std::vector<Token>& toks, std::size_t open, std::size_t& close, std::string& text) {
  if (open >= toks.size() || !toks[open].is('{')) return false;
  int depth = 0;
  for (std::size_t i = open; i < toks.size(); ++i) {
    if (toks[i].is('{')) ++depth;
    if (toks[i].is('}') && --depth == 0) {
      close = i;
      return true;
    }
    if (i > open) {
      if (!text.empty() && toks[i].space_before) text += ' ';
      text += (toks[i].kind == TokKind::Cs ? "\\" : "") + toks[i].text;
    }
  }
  return false;
}

Token quad_at(const Token& t) {
  Token q = t;
  q.kind = TokKind::Cs;
  q.text = "quad";
  return q;
}

bool tag_text(const std::string& s) {
  if (s.empty() || s.size() > 12) return false;
  bool digit = false;
  for (char c : s) {
    if (c >= '0' && c <= '9') digit = true;
    else if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '.' || c == '-' || c == '*' || c == '\''))
      return false;
  }
  return digit;
}

// The control sequences clean() and rewrite_physics() act on (all others pass unchanged).
bool cleaned_cs(const std::string& c) {
  static const std::unordered_set<std::string> kCleaned = {
      "Cref", "\\", "abs", "autoref", "boxed", "colon", "color", "cref", "dd", "enspace", "eqref", "hfill",
      "hphantom", "hskip", "hspace", "intertext", "label", "lbrack", "left", "lparen", "mbox", "middle", "norm",
      "overset", "pd", "pdv", "dv", "odv", "phantom", "qquad", "qty", "quad", "rbrack", "ref", "right", "rparen",
      "shortintertext", "stackrel", "tag", "text", "textnormal", "textrm", "vert", "vphantom", "vspace"};
  return kCleaned.count(c) > 0;
}

Token with(const Token& at, TokKind kind, std::string text) {
  Token k = at;
  k.kind = kind;
  k.text = std::move(text);
  return k;
}

// The physics and derivative packages: \dv{f}{x} \dv[2]{x}{t} \dv{t} \pdv{f}{x} \odv{f}{x} as
// \frac{d f}{d x}; \dd{x} \dd x as \mathrm{d}x; \abs{x} \norm{x} as |x|; \qty( as (.
bool rewrite_physics(const std::vector<Token>& in, std::size_t& i, std::vector<Token>& out) {
  const Token& t = in[i];
  const std::string& c = t.text;
  auto group_tokens = [&](std::size_t open, std::size_t& close, std::vector<Token>& inner) {
    std::string ignored;
    if (!plain_group(in, open, close, ignored)) return false;
    inner.assign(in.begin() + static_cast<long>(open + 1), in.begin() + static_cast<long>(close));
    return true;
  };
  if (c == "qty") return true;  // \qty( ... ): the delimiters follow
  if (c == "abs" || c == "norm") {
    std::size_t close = 0;
    std::vector<Token> inner;
    if (!group_tokens(i + 1, close, inner)) return false;
    out.push_back(with(t, TokKind::Char, "|"));
    out.insert(out.end(), inner.begin(), inner.end());
    out.push_back(with(in[close], TokKind::Char, "|"));
    i = close;
    return true;
  }
  if (c == "dd") {
    out.push_back(with(t, TokKind::Cs, "mathrm"));
    out.push_back(with(t, TokKind::Char, "{"));
    out.push_back(with(t, TokKind::Char, "d"));
    out.push_back(with(t, TokKind::Char, "}"));
    std::size_t close = 0;
    std::vector<Token> inner;
    if (group_tokens(i + 1, close, inner)) {
      out.insert(out.end(), inner.begin(), inner.end());
      i = close;
    }
    return true;
  }
  if (c != "dv" && c != "pdv" && c != "odv" && c != "pd") return false;
  std::size_t j = i + 1;
  std::vector<Token> order;
  if (j < in.size() && in[j].is('[')) {
    std::size_t k = j + 1;
    while (k < in.size() && !in[k].is(']')) order.push_back(in[k++]);
    if (k >= in.size()) return false;
    j = k + 1;
  }
  std::size_t close1 = 0, close2 = 0;
  std::vector<Token> a, b;
  if (!group_tokens(j, close1, a)) return false;
  bool two = group_tokens(close1 + 1, close2, b);
  const Token d = c == "pdv" || c == "pd" ? with(t, TokKind::Cs, "partial") : with(t, TokKind::Char, "d");
  auto power = [&](std::vector<Token>& v) {
    if (order.empty()) return;
    v.push_back(with(t, TokKind::Char, "^"));
    v.push_back(with(t, TokKind::Char, "{"));
    v.insert(v.end(), order.begin(), order.end());
    v.push_back(with(t, TokKind::Char, "}"));
  };
  std::vector<Token> num{d}, den{d};
  power(num);
  if (two) num.insert(num.end(), a.begin(), a.end());
  const std::vector<Token>& var = two ? b : a;
  den.insert(den.end(), var.begin(), var.end());
  power(den);
  out.push_back(with(t, TokKind::Cs, "frac"));
  out.push_back(with(t, TokKind::Char, "{"));
  out.insert(out.end(), num.begin(), num.end());
  out.push_back(with(t, TokKind::Char, "}"));
  out.push_back(with(t, TokKind::Char, "{"));
  out.insert(out.end(), den.begin(), den.end());
  out.push_back(with(t, TokKind::Char, "}"));
  i = two ? close2 : close1;
  return true;
}

// Drops what only typesets; takes out labels, tags and references.
std::vector<Token> clean(const std::vector<Token>& in, TexRow& row, bool& starts_continued) {
  std::vector<Token> out;
  out.reserve(in.size());
  bool first = true;
  starts_continued = false;
  bool pending_space = false;
  int depth = 0;  // braces: prose in \text{..} is a separator only outside groups
  std::vector<char> drop(in.size(), 0);
  for (std::size_t i = 0; i + 1 < in.size(); ++i) {
    const Token& t = in[i];
    if (drop[i] == 1) continue;
    if (drop[i] == 2) out.push_back(t);  // the extra '}' of a font switch
    if (t.is('{')) ++depth;
    if (t.is('}')) --depth;
    if (first && (t.is('&') || t.is_cs("quad") || t.is_cs("qquad"))) starts_continued = true;
    if (t.is('&')) continue;
    // {\rm d}, {\bf p}: the old font switches as \mathrm{d}, \mathbf{p}
    if (t.is('{') && i + 1 < in.size() && in[i + 1].kind == TokKind::Cs) {
      static const std::pair<const char*, const char*> kSwitch[] = {
          {"rm", "mathrm"}, {"bf", "mathbf"}, {"it", "mathit"}, {"sf", "mathsf"}, {"cal", "mathcal"}, {"bm", "mathbf"}};
      const char* to = nullptr;
      for (const auto& [from, mapped] : kSwitch)
        if (in[i + 1].text == from) to = mapped;
      if (to) {  // {\rm tot} -> {\mathrm{tot}}: the outer group stays (v_{\rm tot})
        int d = 0;
        std::size_t c = i;
        for (; c + 1 < in.size(); ++c) {
          if (in[c].is('{')) ++d;
          if (in[c].is('}') && --d == 0) break;
        }
        if (c + 1 < in.size()) drop[c] = 2;
        out.push_back(t);
        out.push_back(with(t, TokKind::Cs, to));
        out.push_back(t);
        ++i;
        first = false;
        continue;
      }
    }
    if (t.kind == TokKind::Cs && !cleaned_cs(t.text) && !is_size_cs(t.text) && !is_ignored_cs(t.text)) {
      out.push_back(t);  // the common case (\frac, \theta, \mathbf, ...): nothing to clean
      if (pending_space) out.back().space_before = true;
      pending_space = false;
      first = false;
      continue;
    }
    if (t.kind == TokKind::Cs && rewrite_physics(in, i, out)) {
      first = false;
      continue;
    }
    if (t.kind == TokKind::Cs) {
      const std::string& c = t.text;
      if (c == "left" || c == "right" || c == "middle") {
        if (i + 2 < in.size() && in[i + 1].is('.')) ++i;
        continue;
      }
      if (is_size_cs(c) || is_ignored_cs(c)) {
        if (c.size() == 1 && i + 1 < in.size()) pending_space = true;  // \, is a space (in m\,s too)
        continue;
      }
      if (c == "label" || c == "tag" || c == "eqref" || c == "ref" || c == "cref" || c == "Cref" || c == "autoref") {
        std::size_t j = i + 1, close = 0;
        if (c == "tag" && j < in.size() && in[j].is('*')) ++j;
        std::string s;
        if (!plain_group(in, j, close, s)) continue;  // the brace check reports it
        if (c == "label") row.label = s;
        else if (c == "tag") row.tag = s;
        else row.refs.push_back(s);
        i = close;
        continue;
      }
      if (c == "phantom" || c == "hphantom" || c == "vphantom" || c == "color" || c == "hspace" || c == "vspace" ||
          c == "intertext" || c == "shortintertext") {
        std::size_t j = i + 1, close = 0;
        if (j < in.size() && in[j].is('*')) ++j;
        std::string s;
        if (!plain_group(in, j, close, s)) continue;
        if (c == "hspace" || c == "intertext" || c == "shortintertext") out.push_back(quad_at(t));
        i = close;
        continue;
      }
      if (c == "boxed") {  // \boxed{v = \sqrt{2gh}}: the box only typesets
        std::size_t close = 0;
        std::string s;
        if (plain_group(in, i + 1, close, s)) {
          drop[close] = 1;  // the group's braces go, its inside is cleaned as the rest
          ++i;
          continue;
        }
      }
      if (c == "\\" && i + 2 < in.size() && !in[i + 1].space_before &&
          (in[i + 1].is('!') || in[i + 1].is(',') || in[i + 1].is(';') || in[i + 1].is(':'))) {
        ++i;  // \\! in Markdown sources: an escaped \! (spacing)
        pending_space = true;
        continue;
      }
      if (c == "\\" && i + 1 < in.size() && in[i + 1].is('[')) {  // \\[2pt]
        std::size_t k = i + 1;
        while (k + 1 < in.size() && !in[k].is(']')) ++k;
        out.push_back(quad_at(t));
        i = k;
        continue;
      }
      if (c == "hfill" || c == "qquad" || c == "quad" || c == "\\" || c == "enspace" || c == "hskip") {
        out.push_back(quad_at(t));
        first = false;
        continue;
      }
      bool in_script = i > 0 && (in[i - 1].is('_') || in[i - 1].is('^'));
      if ((c == "text" || c == "mbox" || c == "textrm" || c == "textnormal") && depth == 0 && !in_script) {
        std::size_t close = 0;
        std::string s;
        if (plain_group(in, i + 1, close, s)) {
          std::string trimmed = s;
          while (!trimmed.empty() && trimmed.front() == ' ') trimmed.erase(trimmed.begin());
          while (!trimmed.empty() && trimmed.back() == ' ') trimmed.pop_back();
          if (trimmed.size() > 2 && trimmed.front() == '(' && trimmed.back() == ')' &&
              tag_text(trimmed.substr(1, trimmed.size() - 2))) {
            row.tag = trimmed.substr(1, trimmed.size() - 2);
            i = close;
            continue;
          }
          bool after_number = !out.empty() && out.back().kind == TokKind::Char && !out.back().text.empty() &&
                              out.back().text[0] >= '0' && out.back().text[0] <= '9';
          bool spaced = !s.empty() && (s.front() == ' ' || s.back() == ' ');
          if ((is_separator_word(s) || (spaced && !after_number)) && !(after_number && looks_like_unit(s))) {
            for (std::size_t k = i + 2; k + 1 < close; ++k) {  // references in the prose: by \eqref{..}
              std::size_t c2 = 0;
              std::string ref;
              if ((in[k].is_cs("eqref") || in[k].is_cs("ref")) && plain_group(in, k + 1, c2, ref)) row.refs.push_back(ref);
            }
            out.push_back(quad_at(t));
            i = close;
            continue;
          }
        }
      }
      if ((c == "overset" || c == "stackrel") && i + 1 < in.size()) {
        std::size_t close = 0;
        std::string s;
        if (plain_group(in, i + 1, close, s)) {
          if (s.size() > 2 && s.front() == '(' && s.back() == ')') row.refs.push_back(s.substr(1, s.size() - 2));
          std::size_t close2 = 0;
          std::string rel;
          if (plain_group(in, close + 1, close2, rel)) {
            for (std::size_t k = close + 2; k < close2; ++k) out.push_back(in[k]);
            i = close2;
          } else {
            i = close;
          }
          continue;
        }
      }
      if (c == "colon") {
        Token k = t;
        k.kind = TokKind::Char;
        k.text = ":";
        out.push_back(k);
        continue;
      }
      if (c == "lbrack" || c == "rbrack" || c == "lparen" || c == "rparen" || c == "vert") {
        Token k = t;
        k.kind = TokKind::Char;
        k.text = c == "lbrack" ? "[" : c == "rbrack" ? "]" : c == "lparen" ? "(" : c == "rparen" ? ")" : "|";
        out.push_back(k);
        first = false;
        continue;
      }
    }
    if (t.is(':') && i + 1 < in.size() && in[i + 1].is('=')) continue;  // a := b
    if (t.is('{') && i + 2 < in.size() && in[i + 1].is('}')) {  // {} typesets nothing
      ++i;
      continue;
    }
    out.push_back(t);
    if (pending_space) out.back().space_before = true;
    pending_space = false;
    first = false;
  }
  // a final full stop or comma, and spacing at the end
  while (!out.empty() && (out.back().is('.') || out.back().is(',') || out.back().is(';') || out.back().is_cs("quad")))
    out.pop_back();
  out.push_back(in.back());
  return out;
}

struct Segment {
  std::size_t begin = 0, end = 0;
  bool gives_before = false;
  bool colon_after = false;
  bool has_relation = false;
};

// The row's pieces at top-level separators and gives-arrows.
std::vector<Segment> split(const Parser& p) {
  const std::vector<Token>& toks = p.tokens();
  std::vector<Segment> out;
  Segment cur;
  int depth = 0;
  std::size_t n = toks.size() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    const Token& t = toks[i];
    if (t.is('{')) {
      i = p.match(i);
      continue;
    }
    if (t.is('(') || t.is('[') || t.is_cs("{")) ++depth;
    if ((t.is(')') || t.is(']') || t.is_cs("}")) && depth > 0) --depth;
    if (depth > 0) continue;
    TexRel rel;
    bool is_rel = relation_of(t, rel);
    bool sep = t.is(',') || t.is(';') || t.is(':') || t.is_cs("quad") || (is_rel && rel == TexRel::Gives);
    if (!sep) {
      if (is_rel) cur.has_relation = true;
      continue;
    }
    cur.end = i;
    cur.colon_after = t.is(':');
    out.push_back(cur);
    Segment next;
    next.begin = i + 1;
    next.gives_before = is_rel && rel == TexRel::Gives;
    cur = next;
  }
  cur.end = n;
  out.push_back(cur);
  return out;
}

}  // namespace
}  // namespace tex

using tex::Parser;
using tex::Token;
using tex::TokKind;

TexRow parse_tex_row(std::string_view text, const SourcePos& origin, const TexContext& ctx) {
  if (text.size() > ctx.limits.max_length)
    throw InputError(origin, "row is " + std::to_string(text.size()) + " characters long (limit " +
                                 std::to_string(ctx.limits.max_length) + ")");
  TexRow row;
  bool starts_continued = false;
  std::vector<Token> toks = tex::clean(tex::expand(tex::lex(text, origin), ctx, origin), row, starts_continued);
  // a trailing (9.6) after a \quad, or after a space when it has a dot: the row's tag
  std::size_t n = toks.size() - 1;
  if (n >= 3 && toks[n - 1].is(')')) {
    std::size_t open = n - 1;
    while (open > 0 && !toks[open].is('(') && n - open < 14) --open;
    if (toks[open].is('(')) {
      std::string s;
      for (std::size_t i = open + 1; i + 1 < n; ++i) s += toks[i].text;
      bool quad = open > 0 && toks[open - 1].is_cs("quad");
      if (tex::tag_text(s) && (quad || (toks[open].space_before && s.find('.') != std::string::npos)) && open > 1) {
        row.tag = s;
        std::size_t cut = quad ? open - 1 : open;
        toks.erase(toks.begin() + static_cast<long>(cut), toks.end() - 1);
        // the sentence's stop before the tag (`= n R T \ln\frac{V_2}{V_1} . \qquad (2)`)
        while (toks.size() > 1) {
          const Token& t = toks[toks.size() - 2];
          if (!(t.is('.') || t.is(',') || t.is(';') || t.is_cs("quad"))) break;
          toks.erase(toks.end() - 2);
        }
      }
    }
  }
  Parser p(text, origin, ctx, std::move(toks), row);
  p.check_groups();
  std::vector<tex::Segment> segs = tex::split(p);
  bool gives = false;
  bool first_piece = true;
  for (const tex::Segment& s : segs) {
    gives = gives || s.gives_before;
    if (s.begin >= s.end) continue;
    if (s.colon_after && !s.has_relation) continue;  // a heading such as \sum F_x :
    p.set_range(s.begin, s.end);
    TexChain c;
    c.follows_previous = gives;
    gives = false;
    TexRel rel;
    if (tex::relation_of(p.peek(), rel)) {
      c.continues = true;
      Node empty;
      empty.pos = p.at(p.peek());
      c.sides.push_back(std::move(empty));
      c.side_units.emplace_back();
    } else {
      if (first_piece && starts_continued && (p.peek().is('+') || p.peek().is('-'))) c.continues_side = true;
      c.sides.push_back(p.sum().node);
      c.side_units.push_back(p.take_unit_of_side());
    }
    while (tex::relation_of(p.peek(), rel)) {
      const Token& r = p.next();
      c.rels.push_back(rel);
      c.rel_pos.push_back(p.at(r));
      c.sides.push_back(p.sum().node);
      c.side_units.push_back(p.take_unit_of_side());
    }
    if (p.pos() < p.end())
      p.fail(p.peek(), "expected an operator, a relation or the end of the row, found " + p.describe(p.peek()));
    first_piece = false;
    row.chains.push_back(std::move(c));
  }
  row.text_only = true;
  for (const TexChain& c : row.chains)
    if (c.sides.size() >= 2) row.text_only = false;
  return row;
}

Node parse_tex_expression(std::string_view text, const SourcePos& origin, const TexContext& ctx) {
  if (text.size() > ctx.limits.max_length)
    throw InputError(origin, "expression is " + std::to_string(text.size()) + " characters long (limit " +
                                 std::to_string(ctx.limits.max_length) + ")");
  TexRow row;
  bool starts_continued = false;
  std::vector<Token> toks = tex::clean(tex::expand(tex::lex(text, origin), ctx, origin), row, starts_continued);
  Parser p(text, origin, ctx, std::move(toks), row);
  p.check_groups();
  p.set_range(0, p.tokens().size() - 1);
  if (p.pos() >= p.end()) p.fail(p.peek(), "expected an expression, found end of row");
  Node n = p.sum().node;
  if (p.pos() < p.end()) {
    TexRel rel;
    if (tex::relation_of(p.peek(), rel)) p.fail(p.peek(), "expected an expression here, not a relation");
    p.fail(p.peek(), "expected an operator or the end of the expression, found " + p.describe(p.peek()));
  }
  return n;
}

}  // namespace dc
