// TeX math tokens and author macros: lexing a row, expanding \newcommand and \def macros, and
// collecting their definitions from a preamble.
//
// Expansion is iterative (a stack of pending tokens, no recursion) and bounded: at most
// kMaxExpansions macro calls per row and kMaxPending pending tokens, so a macro that calls
// itself, or one that doubles at every call, is an error at its call in time linear in the limit;
// kMaxWork bounds the tokens moved through arguments and bodies (nested calls \a{\a{\a{..}}}
// would otherwise cost the square of their depth).
#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "derivations/syntax/tex/internal/tokens.hpp"
#include "derivations/syntax/source.hpp"
#include "derivations/syntax/tex_math.hpp"

namespace dc::tex {
namespace {

constexpr int kMaxExpansions = 2000;
constexpr std::size_t kMaxPending = 200000;
constexpr std::size_t kMaxWork = 200000;  // tokens moved through arguments and bodies in one row

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

std::size_t utf8_len(unsigned char c) {
  if (c >= 0xF0) return 4;
  if (c >= 0xE0) return 3;
  if (c >= 0xC0) return 2;
  return 1;
}

}  // namespace

std::vector<Token> lex(std::string_view text, const SourcePos& origin) {
  std::vector<Token> out;
  out.reserve(text.size() / 2 + 2);
  int line = origin.line, col = origin.col;
  std::size_t i = 0, n = text.size();
  bool space = false;
  auto advance = [&](std::size_t to) {
    for (; i < to; ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
  };
  while (i < n) {
    char c = text[i];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '~') {
      space = true;
      advance(i + 1);
      continue;
    }
    if (c == '%') {  // a comment runs to the end of the line
      std::size_t nl = text.find('\n', i);
      advance(nl == std::string_view::npos ? n : nl);
      continue;
    }
    Token t;
    t.off = i;
    t.line = line;
    t.col = col;
    t.space_before = space;
    space = false;
    std::size_t j = i + 1;
    if (c == '\\') {
      t.kind = TokKind::Cs;
      if (j < n && is_letter(text[j])) {
        while (j < n && is_letter(text[j])) ++j;
        t.text = std::string(text.substr(i + 1, j - i - 1));
      } else if (j < n) {
        j += utf8_len(static_cast<unsigned char>(text[j]));
        j = std::min(j, n);
        t.text = std::string(text.substr(i + 1, j - i - 1));
        if (t.text == " " || t.text == "\n") t.text = " ";
      } else {
        t.text = "";
      }
    } else {
      j = std::min(n, i + utf8_len(static_cast<unsigned char>(c)));
      t.kind = TokKind::Char;
      t.text = std::string(text.substr(i, j - i));
      if (t.text == "\xC2\xB0") {  // the degree sign
        t.kind = TokKind::Cs;
        t.text = "degree";
      }
    }
    t.end = j;
    advance(j);
    out.push_back(std::move(t));
  }
  Token e;
  e.kind = TokKind::End;
  e.off = e.end = n;
  e.line = line;
  e.col = col;
  e.space_before = space;
  out.push_back(e);
  return out;
}

std::vector<Token> expand(std::vector<Token> toks, const TexContext& ctx, const SourcePos& origin) {
  if (ctx.macros.empty()) return toks;
  Token end_tok = toks.back();
  toks.pop_back();
  std::vector<Token> pending(toks.rbegin(), toks.rend());  // top of the stack = next token
  std::vector<Token> out;
  out.reserve(toks.size() + 8);
  std::map<std::string, std::vector<Token>> bodies;
  int expansions = 0;
  std::size_t work = 0;
  // buffers kept across calls: a large argument would otherwise be a fresh allocation (and fresh
  // pages) at every call
  std::vector<std::vector<Token>> args(9);
  std::vector<Token> result;
  auto fail = [&](const Token& at, const std::string& msg) -> void {
    throw InputError(SourcePos{origin.file, at.line, at.col}, msg, static_cast<int>(std::max<std::size_t>(1, at.end - at.off)));
  };
  while (!pending.empty()) {
    Token t = std::move(pending.back());
    pending.pop_back();
    auto m = t.kind == TokKind::Cs ? ctx.macros.find(t.text) : ctx.macros.end();
    if (m == ctx.macros.end()) {
      out.push_back(std::move(t));
      continue;
    }
    if (++expansions > kMaxExpansions)
      fail(t, "macro \\" + t.text + " expanded more than " + std::to_string(kMaxExpansions) +
                  " times in one row: does it call itself?");
    // arguments: a {group} or a single token each; an optional first one in [..] when declared
    const TexMacro& mac = m->second;
    std::size_t call_end = t.end;
    for (int a = 0; a < mac.arity; ++a) {
      std::vector<Token>& arg = args[static_cast<std::size_t>(a)];
      arg.clear();
      if (a == 0 && mac.has_default) {
        if (!pending.empty() && pending.back().is('[')) {
          pending.pop_back();
          int depth = 0;
          while (true) {
            if (pending.empty()) fail(t, "expected ']' to close the optional argument of \\" + t.text);
            Token x = std::move(pending.back());
            pending.pop_back();
            if (x.is('{')) ++depth;
            if (x.is('}')) --depth;
            if (depth == 0 && x.is(']')) {
              call_end = x.end;
              break;
            }
            arg.push_back(std::move(x));
          }
        } else {
          arg = lex(mac.default_arg, origin);
          arg.pop_back();
          for (Token& x : arg) x.off = t.off, x.end = t.end, x.line = t.line, x.col = t.col;
        }
        continue;
      }
      if (pending.empty()) fail(t, "expected argument " + std::to_string(a + 1) + " of \\" + t.text);
      Token x = std::move(pending.back());
      pending.pop_back();
      call_end = x.end;
      if (x.is('{')) {
        int depth = 1;
        while (true) {
          if (pending.empty()) fail(x, "expected '}' to close '{' at " + std::to_string(x.line) + ":" + std::to_string(x.col));
          Token y = std::move(pending.back());
          pending.pop_back();
          if (y.is('{')) ++depth;
          if (y.is('}') && --depth == 0) {
            call_end = y.end;
            break;
          }
          arg.push_back(std::move(y));
        }
      } else {
        arg.push_back(std::move(x));
      }
    }
    auto b = bodies.find(t.text);
    if (b == bodies.end()) {
      std::vector<Token> body = lex(mac.body, origin);
      body.pop_back();
      b = bodies.emplace(t.text, std::move(body)).first;
    }
    // the expansion, pushed in reverse; body tokens take the position of the call
    result.clear();
    const std::vector<Token>& body = b->second;
    for (std::size_t k = 0; k < body.size(); ++k) {
      const Token& x = body[k];
      if (x.is('#') && k + 1 < body.size() && body[k + 1].kind == TokKind::Char && body[k + 1].text.size() == 1 &&
          body[k + 1].text[0] >= '1' && body[k + 1].text[0] <= '9') {
        std::size_t idx = static_cast<std::size_t>(body[k + 1].text[0] - '1');
        if (idx < static_cast<std::size_t>(mac.arity)) result.insert(result.end(), args[idx].begin(), args[idx].end());
        ++k;
        continue;
      }
      Token y = x;
      y.off = t.off;
      y.end = call_end;
      y.line = t.line;
      y.col = t.col;
      y.space_before = k == 0 ? t.space_before : x.space_before;
      result.push_back(std::move(y));
    }
    work += result.size();
    for (int a = 0; a < mac.arity; ++a) work += args[static_cast<std::size_t>(a)].size();
    if (work > kMaxWork)
      fail(t, "macro expansion in this row moves more than " + std::to_string(kMaxWork) + " tokens (nested calls of \\" +
                  t.text + "?)");
    if (pending.size() + result.size() > kMaxPending)
      fail(t, "macro \\" + t.text + " expands to more than " + std::to_string(kMaxPending) + " tokens");
    for (auto it = result.rbegin(); it != result.rend(); ++it) pending.push_back(std::move(*it));
  }
  out.push_back(end_tok);
  return out;
}

}  // namespace dc::tex

namespace dc {
namespace {

struct Scan {
  std::string_view s;
  std::size_t i = 0;
  void spaces() {
    while (i < s.size()) {
      if (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r') {
        ++i;
      } else if (s[i] == '%') {
        while (i < s.size() && s[i] != '\n') ++i;
      } else {
        break;
      }
    }
  }
  // {balanced} -> inside; false when not at '{' or unbalanced
  bool group(std::string& out) {
    spaces();
    if (i >= s.size() || s[i] != '{') return false;
    int depth = 0;
    std::size_t start = i + 1;
    for (; i < s.size(); ++i) {
      if (s[i] == '\\') {
        ++i;
        continue;
      }
      if (s[i] == '{') ++depth;
      if (s[i] == '}' && --depth == 0) {
        out = std::string(s.substr(start, i - start));
        ++i;
        return true;
      }
    }
    return false;
  }
  bool cs_name(std::string& out) {
    spaces();
    if (i >= s.size() || s[i] != '\\') return false;
    std::size_t j = i + 1;
    while (j < s.size() && ((s[j] >= 'a' && s[j] <= 'z') || (s[j] >= 'A' && s[j] <= 'Z'))) ++j;
    if (j == i + 1 && j < s.size()) ++j;  // a control symbol
    out = std::string(s.substr(i + 1, j - i - 1));
    i = j;
    return !out.empty();
  }
  bool bracket(std::string& out) {
    spaces();
    if (i >= s.size() || s[i] != '[') return false;
    std::size_t j = s.find(']', i);
    if (j == std::string_view::npos) return false;
    out = std::string(s.substr(i + 1, j - i - 1));
    i = j + 1;
    return true;
  }
};

}  // namespace

void read_tex_macros(std::string_view text, TexContext& ctx) {
  Scan sc{text};
  while (sc.i < text.size()) {
    std::size_t at = text.find_first_of("\\%", sc.i);
    if (at == std::string_view::npos) break;
    sc.i = at;
    if (text[at] == '%') {
      sc.spaces();
      continue;
    }
    std::string cmd;
    sc.cs_name(cmd);
    if (cmd == "newcommand" || cmd == "renewcommand" || cmd == "providecommand" || cmd == "DeclareMathOperator" ||
        cmd == "DeclareRobustCommand") {
      if (sc.i < text.size() && text[sc.i] == '*') ++sc.i;
      std::string name, inner;
      if (sc.group(inner)) {
        Scan in{inner};
        if (!in.cs_name(name)) continue;
      } else if (!sc.cs_name(name)) {
        continue;
      }
      TexMacro mac;
      std::string n, dflt, body;
      if (cmd != "DeclareMathOperator" && sc.bracket(n)) {
        mac.arity = std::clamp(std::atoi(n.c_str()), 0, 9);
        if (sc.bracket(dflt)) {
          mac.has_default = true;
          mac.default_arg = dflt;
        }
      }
      if (!sc.group(body)) continue;
      mac.body = cmd == "DeclareMathOperator" ? "\\operatorname{" + body + "}" : body;
      if (cmd == "providecommand" && ctx.macros.count(name)) continue;
      ctx.macros[name] = std::move(mac);
    } else if (cmd == "def") {
      std::string name;
      if (!sc.cs_name(name)) continue;
      int arity = 0;
      while (sc.i + 1 < text.size() && text[sc.i] == '#' && text[sc.i + 1] >= '1' && text[sc.i + 1] <= '9') {
        arity = text[sc.i + 1] - '0';
        sc.i += 2;
      }
      std::string body;
      if (!sc.group(body)) continue;
      TexMacro mac;
      mac.arity = arity;
      mac.body = body;
      ctx.macros[name] = std::move(mac);
    }
  }
}

}  // namespace dc
