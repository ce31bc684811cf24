// The expression parser: a tokenizer and a recursive-descent parser with exact positions.
//
// Robustness (design notes §2: GiNaC's parser segfaults at ~8000 nested parentheses):
//  * the input length is checked before anything else;
//  * parenthesis depth is checked by an iterative scan over the tokens before the descent, so
//    10^5 '(' are rejected at the first '(' beyond the limit without recursing at all;
//  * the descent counts its own nesting (parentheses, call arguments, unary signs, exponents)
//    against the same limit, capped at kHardMaxDepth whatever the caller asks for;
//  * runs of unary signs are collected in a loop, not by recursion;
//  * chains a+b+c+... are built in a loop; their tree depth is limited by max_tree_depth.
#include "derivations/syntax/expr.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "derivations/syntax/source.hpp"

namespace dc {
namespace {

constexpr int kHardMaxDepth = 1000;

enum class Tok { Number, Ident, Plus, Minus, PlusMinus, MinusPlus, Star, Slash, Caret, LParen, RParen, LBracket, RBracket, Comma, Equals, Degree, End };

struct Token {
  Tok kind = Tok::End;
  std::size_t begin = 0, end = 0;  // byte offsets into the text
  int line = 0, col = 0;
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_ident_char(char c) { return is_alpha(c) || is_digit(c) || c == '_'; }

// The whole UTF-8 sequence starting at text[i] (so 'μ' is quoted whole, not as a lone byte).
std::string utf8_char_at(std::string_view text, std::size_t i) {
  unsigned char c = static_cast<unsigned char>(text[i]);
  std::size_t len = 1;
  if (c >= 0xF0) len = 4;
  else if (c >= 0xE0) len = 3;
  else if (c >= 0xC0) len = 2;
  len = std::min(len, text.size() - i);
  std::string s(text.substr(i, len));
  if (c < 0x20 || c == 0x7F) {  // control characters are shown by code
    static const char* hex = "0123456789abcdef";
    return std::string("\\x") + hex[c >> 4] + hex[c & 15];
  }
  return s;
}

class Lexer {
 public:
  Lexer(std::string_view text, const SourcePos& origin, const ParseLimits& limits)
      : text_(text), origin_(origin), limits_(limits) {}

  std::vector<Token> run() {
    std::vector<Token> toks;
    int line = origin_.line, col = origin_.col;
    std::size_t i = 0, n = text_.size();
    while (i < n) {
      char c = text_[i];
      if (c == '\n') {
        ++line;
        col = 1;
        ++i;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r') {
        ++col;
        ++i;
        continue;
      }
      Token t;
      t.begin = i;
      t.line = line;
      t.col = col;
      if (is_digit(c)) {
        std::size_t j = i;
        while (j < n && is_digit(text_[j])) ++j;
        std::size_t digits = j - i;
        if (j < n && text_[j] == '.') {
          if (j + 1 >= n || !is_digit(text_[j + 1]))
            fail(line, col + static_cast<int>(j - i), "expected a digit after '.' in the number '" +
                                                          std::string(text_.substr(i, j + 1 - i)) + "'");
          ++j;
          std::size_t k = j;
          while (j < n && is_digit(text_[j])) ++j;
          digits += j - k;
          if (j < n && text_[j] == '.')
            fail(line, col + static_cast<int>(j - i), "unexpected second '.' in a number");
        }
        if (digits > static_cast<std::size_t>(std::max(1, limits_.max_int_digits)))
          fail(line, col,
               "numeric literal has " + std::to_string(digits) + " digits (limit " +
                   std::to_string(limits_.max_int_digits) + ")",
               static_cast<int>(j - i));
        t.kind = Tok::Number;
        t.end = j;
      } else if (is_alpha(c)) {
        std::size_t j = i;
        while (j < n && is_ident_char(text_[j])) ++j;
        t.kind = Tok::Ident;
        t.end = j;
      } else if ((c == '\xC2' && i + 1 < n && text_[i + 1] == '\xB1') ||
                 (c == '\xE2' && i + 2 < n && text_[i + 1] == '\x88' && text_[i + 2] == '\x93') ||
                 ((c == '+' || c == '-') && i + 2 < n && text_[i + 1] == '/' && text_[i + 2] == (c == '+' ? '-' : '+'))) {
        // '±' (U+00B1), '∓' (U+2213), or ASCII '+/-', '-/+': both signs, one column each
        // for the Unicode forms
        const bool ascii = c == '+' || c == '-';
        t.kind = (c == '\xC2' || c == '+') ? Tok::PlusMinus : Tok::MinusPlus;
        t.end = i + (ascii ? 3 : c == '\xC2' ? 2 : 3);
        col += ascii ? 3 : 1;
        i = t.end;
        toks.push_back(t);
        continue;
      } else if (c == '\xC2' && i + 1 < n && text_[i + 1] == '\xB0') {
        // '°' (U+00B0, two bytes in UTF-8): one column
        t.kind = Tok::Degree;
        t.end = i + 2;
        col += 1;
        i = t.end;
        toks.push_back(t);
        continue;
      } else {
        t.end = i + 1;
        switch (c) {
          case '+': t.kind = Tok::Plus; break;
          case '-': t.kind = Tok::Minus; break;
          case '*':
            if (i + 1 < n && text_[i + 1] == '*')
              fail(line, col, "'**' is not an operator; write '^' for a power", 2);
            t.kind = Tok::Star;
            break;
          case '/': t.kind = Tok::Slash; break;
          case '^': t.kind = Tok::Caret; break;
          case '(': t.kind = Tok::LParen; break;
          case ')': t.kind = Tok::RParen; break;
          case ',': t.kind = Tok::Comma; break;
          case '=': t.kind = Tok::Equals; break;
          case '.':
            if (i + 1 < n && is_digit(text_[i + 1]))
              fail(line, col, "a number must start with a digit: write 0" +
                                  std::string(text_.substr(i, std::min<std::size_t>(8, n - i))));
            fail(line, col, "unexpected character '.'");
            break;
          case '[': t.kind = Tok::LBracket; break;   // a vector literal [a, b, c]
          case ']': t.kind = Tok::RBracket; break;
          case '{': case '}':
            fail(line, col, std::string("unexpected character '") + c + "'; use '(' and ')' for grouping");
            break;
          default:
            fail(line, col, "unexpected character '" + utf8_char_at(text_, i) + "'");
        }
      }
      col += static_cast<int>(t.end - i);
      i = t.end;
      toks.push_back(t);
    }
    Token end;
    end.kind = Tok::End;
    end.begin = end.end = n;
    end.line = line;
    end.col = col;
    toks.push_back(end);
    return toks;
  }

 private:
  [[noreturn]] void fail(int line, int col, const std::string& msg, int length = 1) {
    throw InputError(SourcePos{origin_.file, line, col}, msg, length);
  }
  std::string_view text_;
  const SourcePos& origin_;
  const ParseLimits& limits_;
};

// Result of parsing one operand: the node, the depth of its tree and the extent of its text.
struct Parsed {
  Node node;
  int depth = 1;
  std::size_t begin = 0, end = 0;  // byte offsets of the first and one-past-last character
  int end_line = 0;
};

class Parser {
 public:
  Parser(std::string_view text, const SourcePos& origin, const ParseLimits& limits)
      : text_(text), origin_(origin), limits_(limits) {
    max_depth_ = std::clamp(limits.max_depth, 1, kHardMaxDepth);
    max_tree_depth_ = std::max(1, limits.max_tree_depth);
    if (text.size() > limits.max_length)
      throw InputError(origin, "expression is " + std::to_string(text.size()) + " characters long (limit " +
                                   std::to_string(limits.max_length) + ")");
    toks_ = Lexer(text, origin, limits).run();
    check_paren_depth();
  }

  Node expression() {
    Parsed p = sum();
    if (peek().kind == Tok::Equals)
      fail(peek(), "unexpected '=': an expression is expected here, not an equation");
    expect_end(p);
    return std::move(p.node);
  }

  Relation relation() {
    Relation r;
    Parsed p = sum();
    r.sides.push_back(std::move(p.node));
    while (peek().kind == Tok::Equals) {
      const Token& eq = next();
      if (peek().kind == Tok::Equals) fail(peek(), "expected an expression after '=', found '=' (write a single '=')");
      (void)eq;
      p = sum();
      r.sides.push_back(std::move(p.node));
    }
    expect_end(p);
    return r;
  }

 private:
  const Token& peek() const { return toks_[pos_]; }
  const Token& next() { return toks_[pos_ < toks_.size() - 1 ? pos_++ : pos_]; }
  SourcePos at(const Token& t) const { return SourcePos{origin_.file, t.line, t.col}; }
  std::string_view text_of(const Token& t) const { return text_.substr(t.begin, t.end - t.begin); }

  std::string describe(const Token& t) const {
    if (t.kind == Tok::End) return "end of expression";
    return "'" + std::string(text_of(t)) + "'";
  }

  [[noreturn]] void fail(const Token& t, const std::string& msg) const {
    int len = t.kind == Tok::End ? 1 : static_cast<int>(t.end - t.begin);
    throw InputError(at(t), msg, len);
  }

  // Iterative scan: no '(' may open more than max_depth levels. Runs before the descent, so a
  // pathological 10^5-deep input is rejected in time linear in its length, without recursion.
  void check_paren_depth() const {
    int depth = 0;
    for (const Token& t : toks_) {
      if (t.kind == Tok::LParen || t.kind == Tok::LBracket) {
        if (++depth > max_depth_)
          fail(t, "parentheses nested too deeply (limit " + std::to_string(max_depth_) + ")");
      } else if ((t.kind == Tok::RParen || t.kind == Tok::RBracket) && depth > 0) {
        --depth;
      }
    }
  }

  void enter(const Token& t) {
    if (++nest_ > max_depth_)
      fail(t, "expression nested too deeply (limit " + std::to_string(max_depth_) + ")");
  }
  void leave(int k = 1) { nest_ -= k; }

  void expect_end(const Parsed& last) {
    const Token& t = peek();
    if (t.kind == Tok::End) return;
    if (t.kind == Tok::RParen) fail(t, "unexpected ')' without a matching '('");
    std::string msg = "expected an operator or the end of the expression after '" +
                      std::string(text_.substr(last.begin, std::min<std::size_t>(last.end - last.begin, 40))) +
                      (last.end - last.begin > 40 ? "...'" : "'") + ", found " + describe(t);
    if (t.kind == Tok::Ident || t.kind == Tok::Number || t.kind == Tok::LParen)
      msg += " (write '*' for a product)";
    fail(t, msg);
  }

  int length_of(const Parsed& p) const {
    if (p.end_line == p.node.pos.line) return static_cast<int>(std::max<std::size_t>(1, p.end - p.begin));
    std::size_t nl = text_.find('\n', p.begin);
    return static_cast<int>(std::max<std::size_t>(1, (nl == std::string_view::npos ? text_.size() : nl) - p.begin));
  }

  void check_tree_depth(int depth, const Token& op) const {
    if (depth > max_tree_depth_)
      fail(op, "expression too large: more than " + std::to_string(max_tree_depth_) +
                   " operations nested in one chain (limit " + std::to_string(max_tree_depth_) + ")");
  }

  Parsed binary(NodeKind kind, Parsed left, Parsed right, const Token& op) {
    Parsed out;
    out.depth = 1 + std::max(left.depth, right.depth);
    check_tree_depth(out.depth, op);
    out.begin = left.begin;
    out.end = right.end;
    out.end_line = right.end_line;
    out.node.kind = kind;
    out.node.pos = left.node.pos;
    out.node.op_pos = at(op);
    out.node.args.reserve(2);
    out.node.args.push_back(std::move(left.node));
    out.node.args.push_back(std::move(right.node));
    out.node.length = length_of(out);
    return out;
  }

  static bool is_sign(Tok k) { return k == Tok::Plus || k == Tok::Minus || k == Tok::PlusMinus || k == Tok::MinusPlus; }

  // sum := product ( ('+'|'-'|'±'|'∓') product )*. `a ± b` is the call pm(a, b), `a ∓ b`
  // mp(a, b): one expression for both signs (a step with it is checked for each).
  Parsed sum() {
    Parsed left = product();
    while (is_sign(peek().kind)) {
      const Token& op = next();
      const Token& t = peek();
      if (is_sign(t.kind)) {
        std::string msg = "expected an expression after '" + std::string(text_of(op)) + "', found " + describe(t);
        if (t.kind == Tok::Minus) msg += " (put a negative term in parentheses)";
        fail(t, msg);
      }
      Parsed right = product();
      if (op.kind == Tok::PlusMinus || op.kind == Tok::MinusPlus) {
        left = binary(NodeKind::Add, std::move(left), std::move(right), op);
        left.node.kind = NodeKind::Call;
        left.node.text = op.kind == Tok::PlusMinus ? "pm" : "mp";
        continue;
      }
      left = binary(op.kind == Tok::Plus ? NodeKind::Add : NodeKind::Sub, std::move(left), std::move(right), op);
    }
    return left;
  }

  // product := unary ( ('*'|'/') unary )*
  Parsed product() {
    Parsed left = unary();
    while (peek().kind == Tok::Star || peek().kind == Tok::Slash) {
      const Token& op = next();
      Parsed right = unary();
      left = binary(op.kind == Tok::Star ? NodeKind::Mul : NodeKind::Div, std::move(left), std::move(right), op);
    }
    return left;
  }

  // unary := ('-'|'+') unary | power. A leading '+' is accepted only where an expression
  // starts (after '(', ',', '=' or at the beginning); it is dropped from the tree.
  Parsed unary() {
    std::size_t first = pos_;
    std::vector<std::size_t> signs;
    while (is_sign(peek().kind)) {
      const Token& t = peek();
      if (t.kind == Tok::Plus) {
        bool at_start = pos_ == first && (pos_ == 0 || toks_[pos_ - 1].kind == Tok::LParen ||
                                          toks_[pos_ - 1].kind == Tok::Comma || toks_[pos_ - 1].kind == Tok::Equals);
        if (!at_start) {
          const Token& prev = toks_[pos_ - 1];
          fail(t, "expected an expression after '" + std::string(text_of(prev)) + "', found '+'");
        }
      }
      enter(t);
      signs.push_back(pos_);
      next();
    }
    Parsed p = power();
    leave(static_cast<int>(signs.size()));
    for (auto it = signs.rbegin(); it != signs.rend(); ++it) {
      const Token& t = toks_[*it];
      if (t.kind == Tok::Plus) {
        p.begin = t.begin;  // the '+' is part of the operand's text but not of the tree
        continue;
      }
      Parsed out;
      out.depth = p.depth + 1;
      check_tree_depth(out.depth, t);
      out.begin = t.begin;
      out.end = p.end;
      out.end_line = p.end_line;
      out.node.kind = NodeKind::Neg;
      if (t.kind == Tok::PlusMinus || t.kind == Tok::MinusPlus) {   // ±x: pm(x)
        out.node.kind = NodeKind::Call;
        out.node.text = t.kind == Tok::PlusMinus ? "pm" : "mp";
      }
      out.node.pos = at(t);
      out.node.args.push_back(std::move(p.node));
      out.node.length = length_of(out);
      p = std::move(out);
    }
    return p;
  }

  // postfix := atom ( '°' )?   30° is the product 30*deg, deg = pi/180
  Parsed postfix() {
    Parsed p = atom();
    if (peek().kind != Tok::Degree) return p;
    const Token& op = next();
    if (peek().kind == Tok::Degree) fail(peek(), "unexpected second '°'");
    Parsed deg;
    deg.node.kind = NodeKind::Symbol;
    deg.node.text = "deg";
    deg.node.pos = at(op);
    deg.node.length = 1;
    deg.begin = op.begin;
    deg.end = op.end;
    deg.end_line = op.line;
    return binary(NodeKind::Mul, std::move(p), std::move(deg), op);
  }

  // power := postfix ( '^' unary )?      (right-associative through unary -> power)
  Parsed power() {
    Parsed base = postfix();
    if (peek().kind != Tok::Caret) return base;
    const Token& op = next();
    enter(op);
    Parsed expo = unary();
    leave();
    return binary(NodeKind::Pow, std::move(base), std::move(expo), op);
  }

  [[noreturn]] void expected_operand() const {
    const Token& t = peek();
    std::string msg = "expected an expression";
    if (pos_ > 0) msg += " after '" + std::string(text_of(toks_[pos_ - 1])) + "'";
    msg += ", found " + describe(t);
    fail(t, msg);
  }

  // The comma-separated arguments after `open`, up to the `close` token, into p (a call or a
  // vector literal); `closing` says what was expected.
  void arguments(Parsed& p, const Token& open, Tok close, const std::string& closing) {
    enter(open);
    int depth = 1;
    while (true) {
      Parsed a = sum();
      depth = std::max(depth, a.depth + 1);
      p.node.args.push_back(std::move(a.node));
      if (peek().kind == Tok::Comma) {
        next();
        continue;
      }
      if (peek().kind == close) break;
      fail(peek(), "expected ',' or " + closing + ", found " + describe(peek()));
    }
    leave();
    const Token& end = next();
    p.depth = depth;
    p.end = end.end;
    p.end_line = end.line;
    p.node.length = length_of(p);
  }

  // atom := number | identifier | identifier '(' args ')' | '(' sum ')' | '[' sum ',' sum [',' sum] ']'
  Parsed atom() {
    const Token& t = peek();
    Parsed p;
    p.begin = t.begin;
    p.end = t.end;
    p.end_line = t.line;
    p.node.pos = at(t);
    p.node.length = static_cast<int>(t.end - t.begin);
    switch (t.kind) {
      case Tok::Number:
        next();
        p.node.kind = NodeKind::Number;
        p.node.text = std::string(text_of(t));
        return p;
      case Tok::Ident: {
        next();
        p.node.text = std::string(text_of(t));
        if (peek().kind != Tok::LParen) {
          p.node.kind = NodeKind::Symbol;
          return p;
        }
        p.node.kind = NodeKind::Call;
        const Token& open = next();
        if (peek().kind == Tok::RParen)
          fail(peek(), "expected an argument of '" + p.node.text + "', found ')'");
        arguments(p, open, Tok::RParen,
                  "')' to close '(' of " + p.node.text + "(...) opened at " + std::to_string(open.line) + ":" +
                      std::to_string(open.col));
        return p;
      }
      case Tok::LBracket: {   // [a, b] or [a, b, c]: the vector literal vec(a, b, c)
        const Token& open = next();
        p.node.kind = NodeKind::Call;
        p.node.text = "vec";
        arguments(p, open, Tok::RBracket,
                  "']' to close the vector '[' opened at " + std::to_string(open.line) + ":" + std::to_string(open.col));
        if (p.node.args.size() < 2 || p.node.args.size() > 3)
          fail(open, "a vector has 2 or 3 components, found " + std::to_string(p.node.args.size()));
        return p;
      }
      case Tok::LParen: {
        const Token& open = next();
        enter(open);
        Parsed inner = sum();
        leave();
        if (peek().kind != Tok::RParen) {
          std::string msg = "expected ')' to close '(' opened at " + std::to_string(open.line) + ":" +
                            std::to_string(open.col) + ", found " + describe(peek());
          Tok k = peek().kind;
          if (k == Tok::Ident || k == Tok::Number || k == Tok::LParen) msg += " (write '*' for a product)";
          fail(peek(), msg);
        }
        const Token& close = next();
        if (inner.node.parenthesized) {
          // ((x)): the tree keeps one level of parentheses per node; the extra pair is dropped.
        }
        inner.node.parenthesized = true;
        inner.node.pos = at(open);
        inner.begin = open.begin;
        inner.end = close.end;
        inner.end_line = close.line;
        inner.node.length = length_of(inner);
        return inner;
      }
      default:
        expected_operand();
    }
  }

  std::string_view text_;
  const SourcePos& origin_;
  const ParseLimits& limits_;
  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  int nest_ = 0;
  int max_depth_ = 200;
  int max_tree_depth_ = 5000;
};

// ---- to_text -----------------------------------------------------------------------------

bool is_plus_minus(const Node& n) {
  return n.kind == NodeKind::Call && (n.text == "pm" || n.text == "mp") && n.args.size() == 2;
}
// (a ± b prints as a sum does, and needs the parentheses a sum needs)
bool is_sum(const Node& n) { return n.kind == NodeKind::Add || n.kind == NodeKind::Sub || is_plus_minus(n); }
bool is_prod(const Node& n) { return n.kind == NodeKind::Mul || n.kind == NodeKind::Div; }
bool is_atomic(const Node& n) {
  return n.kind == NodeKind::Number || n.kind == NodeKind::Symbol || (n.kind == NodeKind::Call && !is_plus_minus(n));
}

void emit(const Node& n, std::string& out);

void emit_operand(const Node& c, bool need_parens, std::string& out) {
  if (need_parens && !c.parenthesized) {
    out += '(';
    emit(c, out);
    out += ')';
  } else {
    emit(c, out);
  }
}

// Prints a left-nested chain of same-precedence binary operators in a loop (chains can be
// thousands long; the recursion then only follows the operands).
void emit_chain(const Node& n, std::string& out) {
  const bool sum_chain = is_sum(n);
  std::vector<const Node*> spine;
  const Node* cur = &n;
  while ((sum_chain ? is_sum(*cur) && !is_plus_minus(*cur) : is_prod(*cur)) && (cur == &n || !cur->parenthesized)) {
    spine.push_back(cur);
    cur = &cur->args[0];
  }
  emit_operand(*cur, sum_chain ? false : is_sum(*cur), out);
  for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
    const Node& op = **it;
    const Node& right = op.args[1];
    switch (op.kind) {
      case NodeKind::Add: out += " + "; break;
      case NodeKind::Sub: out += " - "; break;
      case NodeKind::Mul: out += '*'; break;
      default: out += '/'; break;
    }
    bool parens = sum_chain ? (is_sum(right) || right.kind == NodeKind::Neg) : (is_sum(right) || is_prod(right));
    emit_operand(right, parens, out);
  }
}

void emit(const Node& n, std::string& out) {
  if (n.parenthesized) out += '(';
  switch (n.kind) {
    case NodeKind::Number:
    case NodeKind::Symbol:
      out += n.text;
      break;
    case NodeKind::Call:
      if ((n.text == "pm" || n.text == "mp") && (n.args.size() == 1 || n.args.size() == 2)) {
        const char* sign = n.text == "pm" ? "\u00B1" : "\u2213";
        if (n.args.size() == 1) {
          out += sign;
          emit_operand(n.args[0], is_sum(n.args[0]) || n.args[0].kind == NodeKind::Neg, out);
        } else {
          emit_operand(n.args[0], false, out);
          out += std::string(" ") + sign + " ";
          emit_operand(n.args[1], is_sum(n.args[1]) || n.args[1].kind == NodeKind::Neg, out);
        }
        break;
      }
      if (n.text == "vec") {
        out += '[';
        for (std::size_t i = 0; i < n.args.size(); ++i) {
          if (i) out += ", ";
          emit(n.args[i], out);
        }
        out += ']';
        break;
      }
      out += n.text;
      out += '(';
      for (std::size_t i = 0; i < n.args.size(); ++i) {
        if (i) out += ", ";
        emit(n.args[i], out);
      }
      out += ')';
      break;
    case NodeKind::Add:
    case NodeKind::Sub:
    case NodeKind::Mul:
    case NodeKind::Div:
      emit_chain(n, out);
      break;
    case NodeKind::Neg:
      out += '-';
      emit_operand(n.args[0], is_sum(n.args[0]), out);
      break;
    case NodeKind::Pow:
      emit_operand(n.args[0], !is_atomic(n.args[0]), out);
      out += '^';
      emit_operand(n.args[1], is_sum(n.args[1]) || is_prod(n.args[1]), out);
      break;
  }
  if (n.parenthesized) out += ')';
}

constexpr std::array<std::string_view, 19> kBuiltins = {"sqrt", "exp",  "log",  "ln",   "sin",  "cos",  "tan",
                                                        "asin", "acos", "atan", "abs",  "diff", "limit", "integral",
                                                        "eval_between", "dot", "cross", "norm", "vec"};

}  // namespace

Node parse_expression(std::string_view text, const SourcePos& origin, const ParseLimits& limits) {
  return Parser(text, origin, limits).expression();
}

Relation parse_relation(std::string_view text, const SourcePos& origin, const ParseLimits& limits) {
  return Parser(text, origin, limits).relation();
}

void collect_identifiers(const Node& n, std::vector<const Node*>& out) {
  std::set<std::pair<int, std::string>> seen;
  for (const Node* o : out) seen.emplace(static_cast<int>(o->kind), o->text);
  std::vector<const Node*> stack{&n};
  while (!stack.empty()) {
    const Node* cur = stack.back();
    stack.pop_back();
    if (cur->kind == NodeKind::Symbol || cur->kind == NodeKind::Call) {
      if (seen.emplace(static_cast<int>(cur->kind), cur->text).second) out.push_back(cur);
    }
    for (auto it = cur->args.rbegin(); it != cur->args.rend(); ++it) stack.push_back(&*it);
  }
}

std::string to_text(const Node& n) {
  std::string out;
  emit(n, out);
  return out;
}

std::string to_text(const Relation& r) {
  std::string out;
  for (std::size_t i = 0; i < r.sides.size(); ++i) {
    if (i) out += " = ";
    emit(r.sides[i], out);
  }
  return out;
}

bool is_builtin_function(std::string_view name) {
  return std::find(kBuiltins.begin(), kBuiltins.end(), name) != kBuiltins.end();
}

bool is_reserved_name(std::string_view name) {
  return is_builtin_function(name) || name == "pi" || name == "deg" || name == "oo" || name == "pm" || name == "mp";
}

}  // namespace dc
