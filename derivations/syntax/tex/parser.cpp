// TeX math rows -> the expression tree (tex_math.hpp has the notation and the names).
//
// The row is lexed and its macros expanded (lexer.cpp), cleaned of what only typesets
// (spacing, \left/\right, sizes, \label, \tag; row.cpp), checked for balanced braces and
// depth by an iterative scan, split at top-level separators, and each piece is read by the
// recursive descent below. The descent counts its nesting against ParseLimits::max_depth
// (capped at 1000), so no input reaches the stack limit; chains a+b+c are built in loops.
#include "derivations/syntax/tex_math.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "derivations/syntax/tex/internal/parser.hpp"

namespace dc::tex {

namespace {
bool is_digit_tok(const Token& t) { return t.kind == TokKind::Char && t.text.size() == 1 && t.text[0] >= '0' && t.text[0] <= '9'; }
bool is_letter_tok(const Token& t) {
  return t.kind == TokKind::Char && t.text.size() == 1 &&
         ((t.text[0] >= 'a' && t.text[0] <= 'z') || (t.text[0] >= 'A' && t.text[0] <= 'Z'));
}
bool is_vector_cs(std::string_view s) {
  return s == "mathbf" || s == "textbf" || s == "vec" || s == "boldsymbol" || s == "bm" || s == "mathbfit" || s == "pmb" ||
         s == "overrightarrow" || s == "vb" || s == "va";
}
const char* decoration_of(std::string_view s) {
  if (s == "dot") return "dot";
  if (s == "ddot") return "ddot";
  if (s == "dddot") return "dddot";
  if (s == "hat" || s == "widehat") return "hat";
  if (s == "bar" || s == "overline") return "bar";
  if (s == "tilde" || s == "widetilde") return "tilde";
  if (s == "check") return "check";
  if (s == "breve") return "breve";
  return nullptr;
}
bool is_roman_cs(std::string_view s) {
  return s == "mathrm" || s == "text" || s == "textrm" || s == "mathit" || s == "operatorname" || s == "mathsf" ||
         s == "textit" || s == "mbox" || s == "textnormal" || s == "mathcal" || s == "mathscr" || s == "mathbb" ||
         s == "mathfrak" || s == "textsf";
}
}  // namespace

Parser::Parser(std::string_view text, const SourcePos& origin, const TexContext& ctx, std::vector<Token> toks,
               TexRow& row)
    : text_(text), origin_(origin), ctx_(ctx), toks_(std::move(toks)), row_(row) {
  max_depth_ = std::clamp(ctx.limits.max_depth, 1, 1000);
  max_tree_depth_ = std::max(1, ctx.limits.max_tree_depth);
  end_ = toks_.size() - 1;
  end_tok_ = toks_.back();
  match_.assign(toks_.size(), 0);
}

// ---- tokens ----------------------------------------------------------------------------------

const Token& Parser::peek(std::size_t k) const {
  return pos_ + k < end_ ? toks_[pos_ + k] : end_tok_;
}

const Token& Parser::next() {
  const Token& t = peek();
  if (pos_ < end_) ++pos_;
  return t;
}

SourcePos Parser::at(const Token& t) const { return SourcePos{origin_.file, t.line, t.col}; }

std::string Parser::describe(const Token& t) const {
  if (t.kind == TokKind::End) {
    if (end_ >= toks_.size() - 1) return "end of row";
    return describe_real(toks_[end_]);
  }
  return describe_real(t);
}

std::string Parser::describe_real(const Token& t) const {
  if (t.kind == TokKind::End) return "end of row";
  std::string s = "'";  // appended piece by piece (GCC 12 warns falsely on "'" + std::string(..))
  if (t.kind == TokKind::Cs) s += '\\';
  s += t.text;
  s += '\'';
  return s;
}

void Parser::fail(const Token& t, const std::string& msg) const {
  int len = static_cast<int>(std::max<std::size_t>(1, t.end - t.off));
  if (t.kind == TokKind::End) len = 1;
  throw InputError(at(t), msg, len);
}

void Parser::enter(const Token& t) {
  if (++nest_ > max_depth_) fail(t, "expression nested too deeply (limit " + std::to_string(max_depth_) + ")");
}

// The braces must balance (an iterative scan, before any recursion) and no group may open
// more than max_depth levels; match_ pairs each '{' with its '}'.
void Parser::check_groups() {
  std::vector<std::size_t> open;
  int paren = 0;
  for (std::size_t i = 0; i + 1 < toks_.size(); ++i) {
    const Token& t = toks_[i];
    if (t.is('{')) {
      open.push_back(i);
      if (static_cast<int>(open.size()) + paren > max_depth_)
        fail(t, "groups nested too deeply (limit " + std::to_string(max_depth_) + ")");
    } else if (t.is('}')) {
      if (open.empty()) fail(t, "unexpected '}' without a matching '{'");
      match_[open.back()] = i;
      open.pop_back();
    } else if (t.is('(') || t.is('[')) {
      if (static_cast<int>(open.size()) + ++paren > max_depth_)
        fail(t, "parentheses nested too deeply (limit " + std::to_string(max_depth_) + ")");
    } else if ((t.is(')') || t.is(']')) && paren > 0) {
      --paren;
    }
  }
  if (!open.empty()) {
    const Token& o = toks_[open.back()];
    fail(toks_.back(), "expected '}' to close '{' at " + std::to_string(o.line) + ":" + std::to_string(o.col));
  }
}

// ---- nodes -----------------------------------------------------------------------------------

int Parser::length_of(const Parsed& p) const {
  if (p.end_line == p.node.pos.line) return static_cast<int>(std::max<std::size_t>(1, p.end - p.begin));
  std::size_t nl = text_.find('\n', p.begin);
  return static_cast<int>(std::max<std::size_t>(1, (nl == std::string_view::npos ? text_.size() : nl) - p.begin));
}

Parsed Parser::leaf(NodeKind kind, std::string text, const Token& first, const Token& last) const {
  Parsed p;
  p.node.kind = kind;
  p.node.text = std::move(text);
  p.node.pos = at(first);
  p.begin = first.off;
  p.end = std::max(last.end, first.end);
  p.end_line = last.line;
  p.node.length = length_of(p);
  return p;
}

Parsed Parser::binary(NodeKind kind, Parsed left, Parsed right, const Token& op) const {
  Parsed out;
  out.depth = 1 + std::max(left.depth, right.depth);
  if (out.depth > max_tree_depth_)
    fail(op, "expression too large: more than " + std::to_string(max_tree_depth_) + " operations nested in one chain");
  out.begin = std::min(left.begin, right.begin);
  out.end = std::max(left.end, right.end);
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

Parsed Parser::call(std::string name, std::vector<Parsed> args, const Token& first) const {
  Parsed out;
  out.node.kind = NodeKind::Call;
  out.node.text = std::move(name);
  out.node.pos = at(first);
  out.begin = first.off;
  out.end = first.end;
  out.end_line = first.line;
  int depth = 1;
  for (Parsed& a : args) {
    depth = std::max(depth, a.depth + 1);
    if (a.end > out.end) out.end = a.end, out.end_line = a.end_line;
    out.node.args.push_back(std::move(a.node));
  }
  out.depth = depth;
  out.node.length = length_of(out);
  return out;
}

Parsed Parser::symbol(const std::string& name, const Token& at_tok) const {
  return leaf(NodeKind::Symbol, name, at_tok, at_tok);
}

void Parser::extend(Parsed& p, const Token& last) const {
  if (last.end > p.end) {
    p.end = last.end;
    p.end_line = last.line;
  }
  p.node.length = length_of(p);
}

// ---- groups ----------------------------------------------------------------------------------

// The argument of a command: [begin, end) of a {group}'s inside, or of a single token.
std::pair<std::size_t, std::size_t> Parser::arg_range(const std::string& what) {
  const Token& t = peek();
  if (t.kind == TokKind::End) fail(t, "expected " + what + ", found " + describe(t));
  if (t.is('{')) {
    std::size_t b = pos_ + 1, e = match_[pos_];
    if (e > end_) fail(t, "expected '}' to close '{' at " + std::to_string(t.line) + ":" + std::to_string(t.col));
    pos_ = e + 1;
    return {b, e};
  }
  if (t.is('}')) fail(t, "expected " + what + ", found '}'");
  // _\text{max}, ^\mathbf{v}: a command and its group are one argument
  if (t.kind == TokKind::Cs && pos_ + 1 < end_ && toks_[pos_ + 1].is('{') &&
      (is_roman_cs(t.text) || is_vector_cs(t.text) || decoration_of(t.text))) {
    std::size_t b = pos_;
    pos_ = match_[pos_ + 1] + 1;
    return {b, pos_};
  }
  ++pos_;
  return {pos_ - 1, pos_};
}

Parsed Parser::parse_range(std::size_t b, std::size_t e, const std::string& what, Parsed (Parser::*f)()) {
  std::size_t save_pos = pos_, save_end = end_;
  Token save_tok = end_tok_;
  pos_ = b;
  end_ = e;
  end_tok_ = toks_[e];
  end_tok_.kind = TokKind::End;
  if (pos_ >= end_) fail(end_tok_, "expected " + what + ", found an empty group");
  Parsed p = (this->*f)();
  if (pos_ < end_) fail(peek(), "expected the end of " + what + ", found " + describe(peek()));
  pos_ = save_pos;
  end_ = save_end;
  end_tok_ = save_tok;
  return p;
}

// The text of tokens [b, e) as written (for \text{..} contents and tags).
std::string Parser::plain(std::size_t b, std::size_t e) const {
  std::string s;
  for (std::size_t i = b; i < e; ++i) {
    if (i > b && toks_[i].space_before) s += ' ';
    if (toks_[i].kind == TokKind::Cs) s += "\\";
    s += toks_[i].text;
  }
  return s;
}

// ---- names -----------------------------------------------------------------------------------

bool Parser::starts_name(const Token& t) const {
  if (is_letter_tok(t)) return true;
  if (t.is('[') && !toks_.empty() && &t >= toks_.data() && &t < toks_.data() + toks_.size())
    return species_at(static_cast<std::size_t>(&t - toks_.data())) != 0;
  if (t.kind != TokKind::Cs) return false;
  return is_greek(t.text) || is_vector_cs(t.text) || decoration_of(t.text) != nullptr ||
         ((t.text == "mathrm" || t.text == "text" || t.text == "operatorname") && false);
}

// `[\mathrm{A}]`, `[\text{H2O}]`: a concentration, one name (conc_A) in chemistry's notation.
// The index just after the `]` when the bracket at i holds only an upright species name, else 0.
std::size_t Parser::species_at(std::size_t i) const {
  if (i + 4 >= toks_.size() || !toks_[i].is('[')) return 0;
  const Token& cs = toks_[i + 1];
  if (!(cs.is_cs("mathrm") || cs.is_cs("text") || cs.is_cs("textrm") || cs.is_cs("ce") || cs.is_cs("mathsf")) ||
      !toks_[i + 2].is('{'))
    return 0;
  const std::size_t close = match_[i + 2];
  if (close <= i + 3 || close + 1 >= toks_.size() || !toks_[close + 1].is(']')) return 0;
  for (std::size_t k = i + 3; k < close; ++k)
    if (!(is_letter_tok(toks_[k]) || is_digit_tok(toks_[k]))) return 0;
  return close + 2;
}

// Subscript text: letters, digits, Greek names, \text{..}; a finite sum's index is replaced by
// its value (m_i -> m_2).
std::string Parser::subscript_text(std::size_t b, std::size_t e) const {
  std::string s;
  for (std::size_t i = b; i < e; ++i) {
    const Token& t = toks_[i];
    if (t.is('{') || t.is('}') || t.is(',')) continue;
    if (t.kind == TokKind::Char && (is_letter_tok(t) || is_digit_tok(t))) {
      auto it = subst_.find(t.text);
      s += it != subst_.end() ? it->second : t.text;
      continue;
    }
    if (t.kind == TokKind::Cs && (is_greek(t.text) || t.text == "max" || t.text == "min" || t.text == "infty")) {
      s += t.text == "infty" ? "inf" : t.text;
      continue;
    }
    if (t.kind == TokKind::Cs && (is_roman_cs(t.text) || is_vector_cs(t.text))) continue;  // its group follows
    if (t.kind == TokKind::Cs && (t.text == "prime" || t.text == "ast")) {
      s += t.text == "prime" ? "prime" : "star";
      continue;
    }
    if (t.is('*')) {
      s += "star";
      continue;
    }
    if (t.is('/')) {   // t_{1/2}, the half-life: one name
      s += "over";
      continue;
    }
    if (t.is(' ') || t.is('-') || t.is('.')) continue;
    fail(t, "a subscript is read as part of a name; " + describe_real(t) + " in a subscript is not read yet");
  }
  return s;
}

// A name with its subscripts, primes, decorations and a following exponent.
Parsed Parser::name() {
  const Token& first = peek();
  enter(first);
  NameParts parts;
  name_core(parts);
  // subscripts, primes and one exponent, in any order
  std::optional<Script> expo;
  const Token* expo_tok = nullptr;
  while (true) {
    const Token& t = peek();
    if (t.is('_')) {
      next();
      auto [b, e] = arg_range("a subscript");
      std::string s = subscript_text(b, e);
      if (!s.empty()) parts.subs += (parts.subs.empty() ? "" : "") + s;
      last_ = toks_[e > b ? e - 1 : b];
      if (e < toks_.size() && toks_[e].is('}')) last_ = toks_[e];
    } else if (t.is('\'')) {
      ++parts.primes;
      last_ = next();
    } else if (t.is('^')) {
      const Token& caret = next();
      Script sc = script();
      if (sc.kind == Script::Prime) {
        parts.primes += sc.primes;
      } else if (sc.kind == Script::Star) {
        parts.star = true;
      } else {
        if (expo) fail(caret, "a second exponent on one name (write the power with braces)");
        expo = std::move(sc);
        expo_tok = &caret;
      }
    } else {
      break;
    }
  }
  std::string id = parts.base;
  if (!parts.subs.empty()) id += "_" + parts.subs;
  if (!parts.deco.empty()) id += "_" + parts.deco;
  if (parts.primes == 1) id += "_prime";
  if (parts.primes > 1) id += "_prime" + std::to_string(parts.primes);
  if (parts.star) id += "_star";
  Parsed p;
  auto sub = subst_.find(id);
  if (sub != subst_.end()) {
    p = leaf(NodeKind::Number, sub->second, first, last_);
  } else {
    p = leaf(NodeKind::Symbol, id, first, last_);
    if (parts.vector) row_.vector_names.insert(id);
    row_.tex_of.emplace(id, std::string(text_.substr(first.off, std::max(last_.end, first.end) - first.off)));
  }
  // `v(0)`, `x(t_1)`, `v(t)`: a name written against a parenthesised single number or name is
  // that quantity's value there (value_at(v, 0)), not a product; `m(v_1 - v_2)` stays a product.
  // The document reader decides what the value is (docs/documents.md), or does not read the row.
  if (p.node.kind == NodeKind::Symbol && !ctx_.functions.count(id) && peek().is('(') && !peek().space_before) {
    const std::size_t save = pos_;
    const Token& open = next();
    Parsed arg = group(open, ")", true);
    const Node& a = arg.node;
    if (a.kind == NodeKind::Number || a.kind == NodeKind::Symbol ||
        (a.kind == NodeKind::Neg && a.args[0].kind == NodeKind::Number)) {
      arg.node.parenthesized = false;
      const Token& close = toks_[pos_ - 1];
      std::vector<Parsed> args;
      args.push_back(std::move(p));
      args.push_back(std::move(arg));
      p = call("value_at", std::move(args), first);
      extend(p, close);
    } else {
      pos_ = save;
    }
  }
  // a declared function: f(x)
  if (ctx_.functions.count(id) && peek().is('(')) {
    const Token& open = next();
    std::vector<Parsed> args;
    while (true) {
      args.push_back(sum());
      if (peek().is(',')) {
        next();
        continue;
      }
      if (!peek().is(')'))
        fail(peek(), "expected ',' or ')' to close '(' of " + id + "(...) opened at " + std::to_string(open.line) + ":" +
                         std::to_string(open.col) + ", found " + describe(peek()));
      break;
    }
    const Token& close = next();
    p = call(id, std::move(args), first);
    extend(p, close);
  }
  --nest_;
  if (expo) {
    // Euler's number
    bool is_e = id == "e" && parts.plain_e;
    if (is_e && ctx_.e_is_euler) {
      bool numeric = expo->kind == Script::Expr && is_plain_number(expo->value.node);
      if (ctx_.e_numeric_power_is_symbol && numeric) {
        row_.readings.push_back({at(first), 1, "e^" + to_text(expo->value.node) + " read as the symbol e to a power, "
                                                  "not Euler's number"});
      } else {
        row_.readings.push_back({at(first), 1, "e read as Euler's number: e^(...) is exp(...)"});
        std::vector<Parsed> a;
        a.push_back(std::move(expo->value));
        return call("exp", std::move(a), first);
      }
    }
    return apply_script(std::move(p), std::move(*expo), *expo_tok);
  }
  // the two letters the issue names as ambiguous: say how they were read
  if (p.node.kind == NodeKind::Symbol && parts.plain_e && id == "e" && ctx_.e_is_euler)
    row_.readings.push_back({at(first), 1, "e without an exponent read as a symbol e, not Euler's number"});
  if (p.node.kind == NodeKind::Symbol && id == "d" && parts.subs.empty())
    row_.readings.push_back({at(first), 1, "d read as a symbol (a distance), not a differential"});
  return p;
}

bool Parser::is_plain_number(const Node& n) {
  if (n.kind == NodeKind::Number) return true;
  if (n.kind == NodeKind::Neg) return is_plain_number(n.args[0]);
  if (n.kind == NodeKind::Div) return is_plain_number(n.args[0]) && is_plain_number(n.args[1]);
  return false;
}

// The base of a name: a letter, a Greek letter, \Delta x, \mathbf{v}, \dot{x}, \mathrm{KE}.
void Parser::name_core(NameParts& parts) {
  const Token& t = next();
  last_ = t;
  if (is_letter_tok(t)) {
    parts.base = t.text;
    parts.plain_e = t.text == "e";
    return;
  }
  if (t.is('[')) {   // a concentration [\mathrm{A}]
    const std::size_t at_bracket = pos_ - 1, after = species_at(at_bracket);
    if (after == 0) fail(t, "expected a name, found " + describe(t));
    parts.base = "conc_";
    for (std::size_t k = at_bracket + 3; k + 2 < after; ++k) parts.base += toks_[k].text;
    pos_ = after;
    last_ = toks_[after - 1];
    return;
  }
  if (t.kind != TokKind::Cs) fail(t, "expected a name, found " + describe(t));
  if (t.text == "Delta" && starts_name(peek()) && !peek().is_cs("Delta")) {
    NameParts inner;
    enter(t);
    name_core(inner);
    --nest_;
    parts.base = "Delta_" + inner.base;
    parts.deco = inner.deco;
    parts.vector = inner.vector;
    return;
  }
  if (t.text == "Sigma" && starts_name(peek()))
    fail(t, "\\Sigma " + describe_real(peek()) + " (a sum written with \\Sigma) is not read yet");
  if (is_greek(t.text)) {
    parts.base = t.text;
    return;
  }
  bool vec = is_vector_cs(t.text);
  const char* deco = decoration_of(t.text);
  if (vec || deco || is_roman_cs(t.text)) {
    auto [b, e] = arg_range("a name after \\" + t.text);
    if (is_roman_cs(t.text)) {
      std::string s;
      for (std::size_t i = b; i < e; ++i) {
        const Token& x = toks_[i];
        if (x.is('.') && i + 1 == e) continue;  // \text{const.}
        if (!(is_letter_tok(x) || is_digit_tok(x) || x.is('_'))) fail(x, "expected letters in \\" + t.text + "{...}, found " + describe_real(x));
        s += x.text;
      }
      if (s.empty() || !is_letter_tok(toks_[b])) fail(t, "expected a name in \\" + t.text + "{...}");
      parts.base = s;
      parts.plain_e = s == "e";
    } else {
      // the inside is a name itself (\mathbf{v_1}, \dot{\mathbf{r}})
      std::size_t save_pos = pos_, save_end = end_;
      Token save_tok = end_tok_;
      pos_ = b;
      end_ = e;
      end_tok_ = toks_[e];
      end_tok_.kind = TokKind::End;
      if (pos_ >= end_ || !starts_name(peek())) fail(toks_[b], "expected a name after \\" + t.text);
      Parsed inner = name();
      if (pos_ < end_) fail(peek(), "expected the end of the name after \\" + t.text + ", found " + describe(peek()));
      if (inner.node.kind != NodeKind::Symbol) fail(toks_[b], "expected a name after \\" + t.text);
      pos_ = save_pos;
      end_ = save_end;
      end_tok_ = save_tok;
      parts.base = inner.node.text;
      if (row_.vector_names.count(parts.base)) parts.vector = true;
    }
    if (vec) parts.vector = true;
    if (deco) parts.deco = parts.deco.empty() ? deco : parts.deco;
    last_ = toks_[e < toks_.size() && toks_[e].is('}') ? e : e - 1];
    return;
  }
  fail(t, "expected a name, found " + describe(t));
}

// ---- scripts ---------------------------------------------------------------------------------

// What follows '^' (or '_' for bounds): a single token or a {group}; ^\circ, ^\prime, ^* are marks.
Script Parser::script() {
  Script sc;
  const Token& t = peek();
  auto [b, e] = arg_range("an exponent");
  // marks
  bool all_primes = e > b;
  for (std::size_t i = b; i < e; ++i) all_primes = all_primes && (toks_[i].is_cs("prime") || toks_[i].is('\''));
  if (all_primes) {
    sc.kind = Script::Prime;
    sc.primes = static_cast<int>(e - b);
    return sc;
  }
  if (e == b + 1 && (toks_[b].is_cs("circ") || toks_[b].is_cs("degree"))) {
    sc.kind = Script::Degree;
    sc.value = symbol("deg", toks_[b]);
    return sc;
  }
  if (e == b + 1 && (toks_[b].is('*') || toks_[b].is_cs("ast") || toks_[b].is_cs("star"))) {
    sc.kind = Script::Star;
    return sc;
  }
  if (!t.is('{') && t.is('-') && pos_ < end_) {
    // x^-1 (TeX shows x^- 1): the sign and the next token
    pos_ = b + 1;
    auto [b2, e2] = arg_range("an exponent");
    (void)b2;
    Parsed inner = parse_range(b, e2, "an exponent", &Parser::sum);
    sc.value = std::move(inner);
    return sc;
  }
  if (e == b + 1 && (toks_[b].is('+') || toks_[b].is('-')))
    fail(toks_[b], "a one-sided limit or a sign as an exponent is not read yet");
  sc.value = parse_range(b, e, "an exponent", &Parser::sum);
  return sc;
}

Parsed Parser::apply_script(Parsed base, Script sc, const Token& caret) {
  if (sc.kind == Script::Degree) return binary(NodeKind::Mul, std::move(base), std::move(sc.value), caret);
  if (sc.kind != Script::Expr) fail(caret, "a prime or star on an expression (not a name) is not read yet");
  return binary(NodeKind::Pow, std::move(base), std::move(sc.value), caret);
}

// ---- sums and products -------------------------------------------------------------------------

bool Parser::starts_factor(const Token& t) const {
  if (t.kind == TokKind::End) return false;
  if (t.kind == TokKind::Char) {
    if (is_digit_tok(t) || is_letter_tok(t)) return true;
    if (t.is('(') || t.is('[') || t.is('{')) return true;
    if (t.is('|')) return abs_depth_ == 0;
    if (t.is('.')) return false;
    return t.text.size() > 1;  // a UTF-8 character: an error in atom() names it
  }
  TexRel rel;
  if (relation_of(t, rel)) return false;
  if (t.text == "|" || t.text == "Vert") return abs_depth_ == 0;
  static const char* const kNot[] = {"cdot", "times", "div", "quad", "qquad", "right", "rvert", "rVert", "}", "degree", "circ", "ast", "pm", "mp"};
  for (const char* s : kNot)
    if (t.text == s) return false;
  return true;
}

Parsed Parser::sum() {
  Parsed left = term(false);
  while (true) {
    const Token& t = peek();
    const bool both = t.is_cs("pm") || t.is_cs("mp");   // a \pm b: pm(a, b), both signs
    if (!(t.is('+') || t.is('-') || both)) break;
    const Token& op = next();
    if (peek().is('+') || peek().is('-'))
      fail(peek(), "expected an expression after '" + op.text + "', found " + describe(peek()));
    Parsed right = term(false);
    left = binary(op.is('-') ? NodeKind::Sub : NodeKind::Add, std::move(left), std::move(right), op);
    if (both) {
      left.node.kind = NodeKind::Call;
      left.node.text = op.is_cs("pm") ? "pm" : "mp";
    }
  }
  return left;
}

// Is toks_[i] the d of a differential (dx, d\theta, \mathrm{d}x, \text d x)? Returns the index of
// the variable's first token, or 0.
std::size_t Parser::differential_at(std::size_t i) const {
  std::size_t after = 0;
  if (i >= end_ || toks_[i].is_cs("partial") || !is_d_mark(i, after) || after >= end_ || !starts_name(toks_[after]))
    return 0;
  if (toks_[i].is('d') && toks_[after].space_before) return 0;  // d x: a product with a distance d
  return after;
}

// d, \partial, \mathrm{d}, \text{d}, \mathrm d, \operatorname{d}: after is the next token.
bool Parser::is_d_mark(std::size_t i, std::size_t& after) const {
  const Token& t = toks_[i];
  if (t.is('d') || t.is_cs("partial")) return after = i + 1, true;
  std::size_t inner = 0;
  if (t.is('{') && match_[i] > i + 1 && is_d_mark(i + 1, inner) && inner == match_[i])  // {\rm d}
    return after = match_[i] + 1, true;
  bool roman = t.kind == TokKind::Cs && (t.text == "mathrm" || t.text == "text" || t.text == "operatorname" ||
                                         t.text == "mathit" || t.text == "textrm" || t.text == "rm");
  if (!roman || i + 1 >= toks_.size()) return false;
  if (toks_[i + 1].is('d')) return after = i + 2, true;
  if (i + 3 < toks_.size() && toks_[i + 1].is('{') && toks_[i + 2].is('d') && toks_[i + 3].is('}'))
    return after = i + 4, true;
  return false;
}

// The variable of a differential at pos_ (dx -> x).
Parsed Parser::take_differential() {
  std::size_t v = differential_at(pos_);
  pos_ = v;
  const Token& first = peek();
  Parsed p = name();
  if (p.node.kind != NodeKind::Symbol) fail(first, "expected the variable of the differential");
  return p;
}

bool Parser::is_numeric(const Node& n) {
  if (n.kind == NodeKind::Number) return true;
  if (n.kind == NodeKind::Neg) return is_numeric(n.args[0]);
  if (n.kind == NodeKind::Mul || n.kind == NodeKind::Div || n.kind == NodeKind::Pow)
    return is_numeric(n.args[0]) && is_numeric(n.args[1]);
  return false;
}

// A product: explicit (\cdot \times * / \div) and implicit (juxtaposition). In `operand` mode
// (a function's argument written without parentheses) only juxtaposition, stopping at the next
// function name.
Parsed Parser::term(bool operand) {
  Parsed left = signed_factor();
  while (true) {
    const Token& t = peek();
    if (int_depth_ > 0 && differential_at(pos_)) break;
    if (int_depth_ > 0 && (t.is('*') || t.is_cs("cdot")) && differential_at(pos_ + 1)) {
      next();  // f(x) \cdot dx
      break;
    }
    if (!operand && (t.is('*') || t.is_cs("cdot") || t.is_cs("times"))) {
      const Token& op = next();
      Parsed right = signed_factor();
      left = binary(NodeKind::Mul, std::move(left), std::move(right), op);
      if (op.is_cs("times")) left.node.text = "times";   // between two vectors, a cross product
      continue;
    }
    if (!operand && (t.is('/') || t.is_cs("div"))) {
      const Token& op = next();
      Parsed right = signed_factor();
      // v^2/2g: factors written against the denominator without a space belong to it
      bool joined = false;
      while (starts_factor(peek()) && !peek().space_before && !(int_depth_ > 0 && differential_at(pos_)) &&
             !peek().is('(') && !is_unit_group(pos_)) {
        const Token& jt = peek();
        Parsed more = factor();
        right = binary(NodeKind::Mul, std::move(right), std::move(more), jt);
        joined = true;
      }
      if (joined)
        row_.readings.push_back({at(op), 1, "a/bc read as a/(b*c): the factors written against the denominator belong to it"});
      left = binary(NodeKind::Div, std::move(left), std::move(right), op);
      continue;
    }
    if (t.is('|') && abs_depth_ == 0 && (peek(1).is('_') || peek(1).is('^'))) {
      left = eval_bar(std::move(left), next());
      continue;
    }
    if (!starts_factor(t)) break;
    if (operand && t.kind == TokKind::Cs && (function_name(t.text) || t.text == "lim" || t.text == "int")) break;
    if (is_unit_group(pos_) && is_numeric(left.node)) {
      // a unit belongs to a side (9.81\,\mathrm{m/s^2}); inside a fraction or a group it would
      // need unit algebra
      if (nest_ > 0) fail(t, "a number with a unit inside an expression is not read yet (only a side that is a number and its unit)");
      take_unit();
      continue;
    }
    {
      const Node& prev = left.node.kind == NodeKind::Mul && !left.node.parenthesized ? left.node.args[1] : left.node;
      if (is_digit_tok(t) && prev.kind == NodeKind::Number && !prev.parenthesized)
        fail(t, "two numbers side by side (a thousands separator, 10\\,000?) are not read yet: write one number");
    }
    Parsed right = factor();
    left = binary(NodeKind::Mul, std::move(left), std::move(right), t);
  }
  return left;
}

bool Parser::is_unit_group(std::size_t i) const {
  if (i + 1 >= end_) return false;
  const Token& t = toks_[i];
  if (!(t.is_cs("mathrm") || t.is_cs("text") || t.is_cs("textrm") || t.is_cs("si") || t.is_cs("mbox") ||
        t.is_cs("unit")) || !toks_[i + 1].is('{'))
    return false;
  return looks_like_unit(plain(i + 2, match_[i + 1]));
}

void Parser::take_unit() {
  const Token& t = next();
  std::size_t b = pos_ + 1, e = match_[pos_];
  pos_ = e + 1;
  std::string u = unit_text(plain(b, e));
  if (!unit_.empty() && unit_end_ == b - 2) {
    unit_ += "*" + u;  // 1\,\mathrm{kg}\,\mathrm{m}: adjacent unit groups multiply
  } else {
    if (!unit_.empty() && unit_ != u)
      fail(t, "two different units in one side ('" + unit_ + "' and '" + u + "') are not read yet");
    unit_ = u;
  }
  unit_end_ = pos_;
}

Parsed Parser::signed_factor() {
  std::vector<const Token*> signs;
  while (peek().is('-') || peek().is('+')) {
    enter(peek());
    signs.push_back(&next());
  }
  const Token* both = nullptr;   // \pm x: pm(x)
  if (signs.empty() && (peek().is_cs("pm") || peek().is_cs("mp"))) {
    enter(peek());
    both = &next();
  }
  if (int_depth_ > 0 && differential_at(pos_)) fail(peek(), "expected an integrand before the differential");
  Parsed p = factor();
  if (both) {
    --nest_;
    Parsed out;
    out.depth = p.depth + 1;
    if (out.depth > max_tree_depth_) fail(*both, "expression too large");
    out.begin = both->off;
    out.end = p.end;
    out.end_line = p.end_line;
    out.node.kind = NodeKind::Call;
    out.node.text = both->is_cs("pm") ? "pm" : "mp";
    out.node.pos = at(*both);
    out.node.args.push_back(std::move(p.node));
    out.node.length = length_of(out);
    p = std::move(out);
  }
  nest_ -= static_cast<int>(signs.size());
  for (auto it = signs.rbegin(); it != signs.rend(); ++it) {
    if ((*it)->is('+')) continue;
    Parsed out;
    out.depth = p.depth + 1;
    if (out.depth > max_tree_depth_) fail(**it, "expression too large");
    out.begin = (*it)->off;
    out.end = p.end;
    out.end_line = p.end_line;
    out.node.kind = NodeKind::Neg;
    out.node.pos = at(**it);
    out.node.args.push_back(std::move(p.node));
    out.node.length = length_of(out);
    p = std::move(out);
  }
  return p;
}

// factor := atom ( '^' script | \degree )*
Parsed Parser::factor() {
  const Token& first = peek();
  if (!starts_factor(first)) {
    std::string msg = "expected an expression";
    if (pos_ > 0 && pos_ <= end_ && pos_ - 1 < toks_.size()) msg += " after " + describe_real(toks_[pos_ - 1]);
    fail(first, msg + ", found " + describe(first));
  }
  enter(first);
  Parsed p = atom();
  while (true) {
    if (peek().is('^')) {
      const Token& caret = next();
      Script sc = script();
      p = apply_script(std::move(p), std::move(sc), caret);
    } else if (peek().is_cs("degree")) {
      const Token& d = next();
      p = binary(NodeKind::Mul, std::move(p), symbol("deg", d), d);
    } else if (peek().is('!')) {
      fail(peek(), "a factorial is not read yet");
    } else if (peek().is_cs("%")) {
      const Token& pc = next();  // 5\% is 5/100
      p = binary(NodeKind::Div, std::move(p), leaf(NodeKind::Number, "100", pc, pc), pc);
    } else {
      break;
    }
  }
  --nest_;
  return p;
}

}  // namespace dc::tex
