// The atoms of TeX math: numbers, groups, |x|, \frac (and derivatives written as fractions),
// \sqrt, functions, \int, \lim, finite \sum and \prod, evaluation bars, \mathrm{..} names.
#include <algorithm>
#include <cctype>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "derivations/syntax/tex/internal/parser.hpp"

namespace dc::tex {

namespace {
bool digit(const Token& t) { return t.kind == TokKind::Char && t.text.size() == 1 && t.text[0] >= '0' && t.text[0] <= '9'; }
bool letter(const Token& t) {
  return t.kind == TokKind::Char && t.text.size() == 1 &&
         ((t.text[0] >= 'a' && t.text[0] <= 'z') || (t.text[0] >= 'A' && t.text[0] <= 'Z'));
}
bool roman_cs(const Token& t) {
  return t.kind == TokKind::Cs && (t.text == "mathrm" || t.text == "text" || t.text == "textrm" || t.text == "operatorname" ||
                                   t.text == "mathit" || t.text == "mathsf" || t.text == "mbox" || t.text == "textit" ||
                                   t.text == "mathcal" || t.text == "mathscr" || t.text == "mathbb" || t.text == "mathfrak" ||
                                   t.text == "textnormal" || t.text == "textsf");
}
const char* inverse_of(const std::string& f) {
  if (f == "sin") return "asin";
  if (f == "cos") return "acos";
  if (f == "tan") return "atan";
  if (f == "sinh") return "asinh";
  if (f == "cosh") return "acosh";
  if (f == "tanh") return "atanh";
  return nullptr;
}
bool is_minus_one(const Node& n) {
  return n.kind == NodeKind::Neg && n.args[0].kind == NodeKind::Number && n.args[0].text == "1";
}
}  // namespace

Parsed Parser::atom() {
  const Token& t = peek();
  if (t.kind == TokKind::Char) {
    if (digit(t)) return number();
    if (letter(t)) {
      if (t.is('d') && (differential_at(pos_) || (pos_ + 1 < end_ && toks_[pos_ + 1].is('(') && !toks_[pos_ + 1].space_before)))
        return slash_derivative(t);
      return name();
    }
    if (t.is('(')) return group(next(), ")", true);
    if (t.is('[') && species_at(pos_)) return name();   // [\mathrm{A}], a concentration
    if (t.is('[')) {
      Parsed g = group(next(), "]", true);
      if (peek().is('_') || peek().is('^')) return eval_bar(std::move(g), toks_[pos_ - 1]);
      return g;
    }
    if (t.is('{')) {
      std::size_t b = pos_ + 1, e = match_[pos_];
      pos_ = e + 1;
      Parsed g = parse_range(b, e, "an expression in braces", &Parser::sum);
      return g;
    }
    if (t.is('|')) return abs_value(next());
    fail(t, "unexpected character '" + t.text + "'");
  }
  const std::string& cs = t.text;
  if (cs == "pi") return symbol("pi", next());
  if (cs == "infty") return symbol("oo", next());
  if (starts_name(t) && !roman_cs(t)) return name();
  if (cs == "frac" || cs == "dfrac" || cs == "tfrac" || cs == "cfrac") return frac(next());
  if (cs == "sqrt") return sqrt(next());
  if (const char* f = function_name(cs)) return function(next(), f);
  if (cs == "int") return integral(next());
  if (cs == "lim") return limit(next());
  if (cs == "sum" || cs == "prod") return big_operator(next());
  if (cs == "{") return group(next(), "}", true);
  if (cs == "|" || cs == "lvert" || cs == "lVert" || cs == "Vert") return abs_value(next());
  if (roman_cs(t)) return roman(t);
  if (cs == "pm" || cs == "mp") fail(t, "\\" + cs + " is not read yet: write the two cases as two rows");
  if (cs == "boxed" || cs == "underbrace" || cs == "overbrace" || cs == "cancelto" || cs == "bigl") {
    next();
    auto [b, e] = arg_range("an expression after \\" + cs);
    Parsed g = parse_range(b, e, "an expression", &Parser::sum);
    if ((cs == "underbrace" && peek().is('_')) || (cs == "overbrace" && peek().is('^'))) {
      next();
      arg_range("a brace label");
    }
    return g;
  }
  if (cs == "SI" || cs == "qty" || cs == "quantity") {
    next();
    auto [nb, ne] = arg_range("the number of \\" + cs);
    Parsed n = parse_range(nb, ne, "a number", &Parser::sum);
    auto [ub, ue] = arg_range("the unit of \\" + cs);
    unit_ = unit_text(plain(ub, ue));
    return n;
  }
  if (cs == "iint" || cs == "iiint" || cs == "oint")
    fail(t, "\\" + cs + " (a multiple or closed integral) is not read yet");
  if (cs == "partial") fail(t, "a partial derivative outside \\frac{\\partial ..}{\\partial ..} is not read yet");
  if (cs == "cdots" || cs == "ldots" || cs == "dots" || cs == "dotsb" || cs == "dotsc")
    fail(t, "an ellipsis \\" + cs + " is not read yet");
  if (cs == "begin") fail(t, "an environment inside a row (a matrix or cases) is not read yet");
  if (cs == "nabla") fail(t, "\\nabla (vector calculus) is not read yet");
  if (cs == "binom" || cs == "choose") fail(t, "binomial coefficients are not read yet");
  if (cs == "langle") fail(t, "\\langle (a bracket or mean value) is not read yet");
  if (cs == "Delta") return name();
  static const char* const kRelations[] = {"gg", "ll", "propto", "in", "notin", "subset", "subseteq", "forall",
                                            "exists", "perp", "parallel", "cong", "lesssim", "gtrsim", "asymp"};
  for (const char* r : kRelations)
    if (cs == r) fail(t, "the relation \\" + cs + " is not read yet");
  fail(t, "unknown control sequence \\" + cs + " (define it with \\newcommand in the preamble if it is yours)");
}

Parsed Parser::number() {
  const Token& first = peek();
  std::size_t digits = 0;
  std::string s;
  const Token* last = &first;
  while (digit(peek()) && (s.empty() || !peek().space_before)) {
    s += peek().text;
    last = &next();
    ++digits;
  }
  if (peek().is('.') && !peek().space_before && pos_ + 1 < end_ && digit(toks_[pos_ + 1]) &&
      !toks_[pos_ + 1].space_before) {
    s += '.';
    next();
    while (digit(peek()) && !peek().space_before) {
      s += peek().text;
      last = &next();
      ++digits;
    }
  }
  if (digits > static_cast<std::size_t>(std::max(1, ctx_.limits.max_int_digits)))
    fail(first, "numeric literal has " + std::to_string(digits) + " digits (limit " +
                    std::to_string(ctx_.limits.max_int_digits) + ")");
  return leaf(NodeKind::Number, s, first, *last);
}

Parsed Parser::group(const Token& open, const char* close, bool parenthesized) {
  enter(open);
  Parsed inner = sum();
  const Token& c = peek();
  bool ok = (c.kind == TokKind::Char && c.text == close) || (c.kind == TokKind::Cs && std::string("\\") + c.text == std::string("\\") + close && std::string(close) == "}");
  if (!ok) {
    std::string o = open.kind == TokKind::Cs ? "\\" + open.text : open.text;
    std::string cl = std::string(close) == "}" ? "\\}" : close;
    fail(c, "expected '" + cl + "' to close '" + o + "' at " + std::to_string(open.line) + ":" +
                std::to_string(open.col) + ", found " + describe(c));
  }
  next();
  --nest_;
  inner.node.parenthesized = parenthesized;
  inner.node.pos = at(open);
  inner.begin = open.off;
  extend(inner, c);
  return inner;
}

Parsed Parser::abs_value(const Token& open) {
  enter(open);
  ++abs_depth_;
  Parsed inner = sum();
  --abs_depth_;
  const Token& c = peek();
  bool ok = open.is('|') ? c.is('|')
                         : (c.is_cs("|") || c.is_cs("rvert") || c.is_cs("rVert") || c.is_cs("Vert") || c.is('|'));
  if (!ok)
    fail(c, "expected '|' to close '|' at " + std::to_string(open.line) + ":" + std::to_string(open.col) + ", found " +
                describe(c));
  next();
  --nest_;
  std::vector<Parsed> a;
  a.push_back(std::move(inner));
  Parsed out = call("abs", std::move(a), open);
  extend(out, c);
  return out;
}

// d<name>/d<var>, d^2x/dt^2, d/dt (...), \mathrm{d}, \partial: a derivative; nullopt when the
// fraction is an ordinary one.
std::optional<Parsed> Parser::derivative(std::size_t nb, std::size_t ne, std::size_t db, std::size_t de, const Token& cs) {
  std::size_t na = 0, da = 0;
  while (ne > nb + 1 && toks_[nb].is('{') && match_[nb] == ne - 1) ++nb, --ne;  // \frac{{dx}}{{dt}}
  while (de > db + 1 && toks_[db].is('{') && match_[db] == de - 1) ++db, --de;
  if (!is_d_mark(nb, na) || !is_d_mark(db, da)) return std::nullopt;
  if (toks_[nb].is_cs("partial") != toks_[db].is_cs("partial")) return std::nullopt;
  if (na > ne || da >= de || !starts_name(toks_[da])) return std::nullopt;
  if (na < ne && (toks_[na].is('_') || toks_[na].is('\''))) return std::nullopt;  // d_1 is a name
  if (na < ne && !toks_[na].is('^') && !starts_name(toks_[na]) && !toks_[na].is('(') && !toks_[na].is('{') &&
      !roman_cs(toks_[na]))
    return std::nullopt;
  // denominator: the variable and its order
  std::size_t save_pos = pos_, save_end = end_;
  Token save_tok = end_tok_;
  set_range(da, de);
  Parsed var = name();
  if (pos_ < end_) fail(peek(), "expected the end of the derivative's denominator, found " + describe(peek()));
  int order = 1;
  if (var.node.kind == NodeKind::Pow && var.node.args[0].kind == NodeKind::Symbol &&
      var.node.args[1].kind == NodeKind::Number) {
    order = std::atoi(var.node.args[1].text.c_str());
    Node v = std::move(var.node.args[0]);
    var.node = std::move(v);
  }
  if (var.node.kind != NodeKind::Symbol) fail(toks_[da], "expected a variable after d in the derivative's denominator");
  // numerator: its order, then the differentiated expression (or nothing: d/dt ...)
  int norder = 1;
  set_range(na, ne);
  if (peek().is('^')) {
    const Token& caret = next();
    Script sc = script();
    if (sc.kind != Script::Expr || sc.value.node.kind != NodeKind::Number) fail(caret, "expected the order of the derivative");
    norder = std::atoi(sc.value.node.text.c_str());
  }
  std::optional<Parsed> body;
  if (pos_ < end_) body = sum();
  if (pos_ < end_) fail(peek(), "expected the end of the derivative's numerator, found " + describe(peek()));
  pos_ = save_pos;
  end_ = save_end;
  end_tok_ = save_tok;
  if (norder != order)
    fail(cs, "the derivative's numerator has order " + std::to_string(norder) + " and its denominator " +
                 std::to_string(order));
  if (!body) {
    if (!starts_factor(peek())) fail(peek(), "expected what d/d" + var.node.text + " applies to, found " + describe(peek()));
    body = term(true);
    body->node.parenthesized = false;  // d/dt (m v): the parentheses belong to the operator
  }
  std::vector<Parsed> args;
  args.push_back(std::move(*body));
  args.push_back(std::move(var));
  if (order != 1) args.push_back(leaf(NodeKind::Number, std::to_string(order), cs, cs));
  Parsed out = call("diff", std::move(args), cs);
  extend(out, toks_[pos_ - 1]);
  return out;
}

Parsed Parser::frac(const Token& cs) {
  enter(cs);
  auto [nb, ne] = arg_range("the numerator of \\" + cs.text);
  auto [db, de] = arg_range("the denominator of \\" + cs.text);
  const Token& last = toks_[pos_ - 1];
  if (auto d = derivative(nb, ne, db, de, cs)) {
    --nest_;
    return std::move(*d);
  }
  Parsed num;
  if (int_depth_ > 0 && differential_at(nb) && nb + 1 < ne) {
    // \int_a^b \frac{dm}{m}: the numerator is the differential
    std::size_t save_pos = pos_, save_end = end_;
    Token save_tok = end_tok_;
    set_range(nb, ne);
    Parsed v = take_differential();
    if (pos_ < end_) fail(peek(), "expected the end of the numerator after the differential, found " + describe(peek()));
    pos_ = save_pos;
    end_ = save_end;
    end_tok_ = save_tok;
    frac_dvar_ = v.node.text;
    num = leaf(NodeKind::Number, "1", toks_[nb], toks_[nb]);
  } else {
    num = parse_range(nb, ne, "the numerator of \\" + cs.text, &Parser::sum);
  }
  Parsed den = parse_range(db, de, "the denominator of \\" + cs.text, &Parser::sum);
  Parsed out = binary(NodeKind::Div, std::move(num), std::move(den), cs);
  out.node.pos = at(cs);
  out.begin = cs.off;
  extend(out, last);
  --nest_;
  return out;
}

Parsed Parser::sqrt(const Token& cs) {
  enter(cs);
  std::optional<Parsed> index;
  if (peek().is('[')) {
    std::size_t b = pos_ + 1, e = b;
    int depth = 0;
    while (e < end_ && !(depth == 0 && toks_[e].is(']'))) {
      if (toks_[e].is('{')) e = match_[e];
      ++e;
    }
    if (e >= end_) fail(peek(), "expected ']' to close the index of \\sqrt");
    pos_ = e + 1;
    index = parse_range(b, e, "the index of \\sqrt", &Parser::sum);
  }
  auto [b, e] = arg_range("the argument of \\sqrt");
  const Token& last = toks_[pos_ - 1];
  Parsed x = parse_range(b, e, "the argument of \\sqrt", &Parser::sum);
  --nest_;
  if (!index || (index->node.kind == NodeKind::Number && index->node.text == "2")) {
    std::vector<Parsed> a;
    a.push_back(std::move(x));
    Parsed out = call("sqrt", std::move(a), cs);
    extend(out, last);
    return out;
  }
  Parsed inv = binary(NodeKind::Div, leaf(NodeKind::Number, "1", cs, cs), std::move(*index), cs);
  Parsed out = binary(NodeKind::Pow, std::move(x), std::move(inv), cs);
  out.node.pos = at(cs);
  out.begin = cs.off;
  extend(out, last);
  return out;
}

// \sin x, \sin(x), \sin^2 x, \sin^{-1} x, \ln\frac{a}{b}
Parsed Parser::function(const Token& cs, const char* fname) {
  enter(cs);
  std::string f = fname;
  std::optional<Parsed> expo;
  const Token* caret = nullptr;
  while (peek().is('^')) {
    caret = &next();
    Script sc = script();
    if (sc.kind != Script::Expr) fail(*caret, "expected a power of \\" + cs.text);
    if (is_minus_one(sc.value.node)) {
      const char* inv = inverse_of(f);
      if (!inv) fail(*caret, "\\" + cs.text + "^{-1} is not read yet");
      f = inv;
    } else if (expo) {
      fail(*caret, "a second power of \\" + cs.text);
    } else {
      expo = std::move(sc.value);
    }
  }
  std::optional<Parsed> base;
  if (peek().is('_') && f == "log") {  // \log_{10} x is log(x)/log(10)
    next();
    Script sc = script();
    if (sc.kind != Script::Expr) fail(cs, "expected the base of \\log");
    base = std::move(sc.value);
    if (peek().is('^')) fail(peek(), "a power of a logarithm with a base is not read yet");
  }
  if (peek().is('_')) fail(peek(), "a subscript on \\" + cs.text + " is not read yet");
  Parsed arg;
  const Token* last = nullptr;
  if (peek().is('(')) {
    const Token& open = next();
    enter(open);
    arg = sum();
    if (!peek().is(')'))
      fail(peek(), "expected ')' to close '(' at " + std::to_string(open.line) + ":" + std::to_string(open.col) +
                       ", found " + describe(peek()));
    last = &next();
    --nest_;
  } else {
    if (!starts_factor(peek())) fail(peek(), "expected the argument of \\" + cs.text + ", found " + describe(peek()));
    arg = term(true);
  }
  --nest_;
  std::vector<Parsed> a;
  a.push_back(std::move(arg));
  Parsed out = call(f, std::move(a), cs);
  if (last) extend(out, *last);
  if (base) {
    std::vector<Parsed> b;
    b.push_back(std::move(*base));
    Parsed den = call("log", std::move(b), cs);
    Parsed q = binary(NodeKind::Div, std::move(out), std::move(den), cs);
    q.node.pos = at(cs);
    return q;
  }
  if (expo) out = binary(NodeKind::Pow, std::move(out), std::move(*expo), *caret);
  return out;
}

Parsed Parser::integral(const Token& cs) {
  enter(cs);
  std::optional<Parsed> lo, hi;
  while (peek().is('_') || peek().is('^')) {
    bool low = next().is('_');
    Script sc = script();
    if (sc.kind != Script::Expr) fail(cs, "expected a limit of the integral");
    (low ? lo : hi) = std::move(sc.value);
  }
  if (!lo || !hi) fail(cs, "an indefinite integral is not read yet: write its limits, \\int_a^b");
  ++int_depth_;
  std::string save = std::exchange(frac_dvar_, std::string());
  Parsed f, var;
  if (differential_at(pos_)) {
    var = take_differential();
    f = sum();
  } else {
    f = sum();
    if (differential_at(pos_)) {
      var = take_differential();
    } else if (!frac_dvar_.empty()) {
      var = symbol(frac_dvar_, cs);
    } else {
      fail(peek(), "expected the differential (dx) that ends the integral at " + std::to_string(cs.line) + ":" +
                       std::to_string(cs.col) + ", found " + describe(peek()));
    }
  }
  --int_depth_;
  frac_dvar_ = save;
  last_int_var_ = var.node.text;
  --nest_;
  std::vector<Parsed> a;
  a.push_back(std::move(f));
  a.push_back(std::move(var));
  a.push_back(std::move(*lo));
  a.push_back(std::move(*hi));
  Parsed out = call("integral", std::move(a), cs);
  extend(out, toks_[pos_ - 1]);
  return out;
}

Parsed Parser::limit(const Token& cs) {
  enter(cs);
  if (!peek().is('_')) fail(peek(), "expected _{x \\to a} after \\lim, found " + describe(peek()));
  next();
  auto [b, e] = arg_range("the subscript of \\lim");
  std::size_t arrow = e;
  for (std::size_t i = b; i < e; ++i) {
    if (toks_[i].is('{')) i = match_[i];
    else if (toks_[i].is_cs("to") || toks_[i].is_cs("rightarrow") || toks_[i].is_cs("longrightarrow")) {
      arrow = i;
      break;
    }
  }
  if (arrow == e) fail(toks_[b], "expected x \\to a in the subscript of \\lim");
  Parsed var = parse_range(b, arrow, "the variable of the limit", &Parser::sum);
  if (var.node.kind != NodeKind::Symbol) fail(toks_[b], "expected a name before \\to in the subscript of \\lim");
  Parsed point = parse_range(arrow + 1, e, "the limit point", &Parser::sum);
  if (!starts_factor(peek()) && !peek().is('-')) fail(peek(), "expected what the limit is taken of, found " + describe(peek()));
  Parsed f = term(false);
  --nest_;
  std::vector<Parsed> a;
  a.push_back(std::move(f));
  a.push_back(std::move(var));
  a.push_back(std::move(point));
  Parsed out = call("limit", std::move(a), cs);
  extend(out, toks_[pos_ - 1]);
  return out;
}

// \sum_{i=1}^{3} a_i -> a_1 + a_2 + a_3 (the operand read once per value, at most 100 terms)
Parsed Parser::big_operator(const Token& cs) {
  enter(cs);
  std::size_t lb = 0, le = 0, hb = 0, he = 0;
  bool has_lo = false, has_hi = false;
  while (peek().is('_') || peek().is('^')) {
    bool low = next().is('_');
    auto [b, e] = arg_range("a bound of \\" + cs.text);
    (low ? lb : hb) = b;
    (low ? le : he) = e;
    (low ? has_lo : has_hi) = true;
  }
  const std::string what = cs.text == "sum" ? "a sum" : "a product";
  // `\sum \mathbf{F}`, `\sum_i^n m_i v_i`: a sum over an index the row does not count out is
  // one quantity, named after its terms (Sum_m_i_v_i), a vector when its terms are; the rows
  // that use it are restatements or laws about it (document/justify never refutes them)
  auto opaque_sum = [&]() {
    if (!starts_factor(peek())) fail(peek(), "expected the terms of the sum, found " + describe(peek()));
    Parsed t = term(false);
    std::string name = "Sum_";
    bool vector = false;
    std::function<void(const Node&)> visit = [&](const Node& n) {
      if (n.kind == NodeKind::Symbol && row_.vector_names.count(n.text)) vector = true;
      for (const auto& a : n.args) visit(a);
    };
    visit(t.node);
    for (char c : to_text(t.node)) {
      const bool word = std::isalnum(static_cast<unsigned char>(c)) != 0;
      if (word) name += c;
      else if (name.back() != '_') name += '_';
    }
    while (name.size() > 4 && name.back() == '_') name.pop_back();
    if (name.size() <= 4) fail(cs, what + " of nothing is not read");
    if (vector) row_.vector_names.insert(name);
    --nest_;
    Parsed out = symbol(name, cs);
    out.end = t.end;
    out.end_line = t.end_line;
    out.node.pos = at(cs);
    return out;
  };
  if ((!has_lo || !has_hi) && cs.text == "sum") return opaque_sum();
  if (!has_lo || !has_hi) fail(cs, what + " without both bounds (\\" + cs.text + "_{i=1}^{3}) is not read yet");
  auto integer = [&](std::size_t b, std::size_t e, long& v) {
    if (b >= e || e - b > 4) return false;
    std::string s;
    for (std::size_t i = b; i < e; ++i) {
      if (!digit(toks_[i])) return false;
      s += toks_[i].text;
    }
    v = std::stol(s);
    return true;
  };
  long lo = 0, hi = 0;
  bool ok = le >= lb + 3 && letter(toks_[lb]) && toks_[lb + 1].is('=') && integer(lb + 2, le, lo) && integer(hb, he, hi);
  if (!ok && cs.text == "sum") return opaque_sum();
  if (!ok) fail(cs, what + " with symbolic bounds is not read yet (only numbers: \\" + cs.text + "_{i=1}^{3})");
  if (hi < lo || hi - lo >= 100) fail(cs, what + " of more than 100 terms, or of none, is not read yet");
  const std::string index = toks_[lb].text;
  std::optional<std::string> outer;
  if (subst_.count(index)) outer = subst_[index];
  std::size_t start = pos_;
  std::optional<Parsed> acc;
  for (long v = lo; v <= hi; ++v) {
    subst_[index] = std::to_string(v);
    pos_ = start;
    if (!starts_factor(peek())) fail(peek(), "expected the terms of the " + cs.text + ", found " + describe(peek()));
    Parsed t = term(false);
    if (++sum_terms_ > 1000) fail(cs, "sums in one row expand to more than 1000 terms");
    acc = acc ? binary(cs.text == "sum" ? NodeKind::Add : NodeKind::Mul, std::move(*acc), std::move(t), cs) : std::move(t);
  }
  if (outer) subst_[index] = *outer;
  else subst_.erase(index);
  --nest_;
  acc->node.parenthesized = true;
  acc->node.pos = at(cs);
  return std::move(*acc);
}

// [F]_a^b, F|_a^b, [F]_{x=a}^{b}: eval_between(F, x, a, b)
Parsed Parser::eval_bar(Parsed f, const Token& bar) {
  std::size_t lb = 0, le = 0, hb = 0, he = 0;
  bool has_lo = false, has_hi = false;
  while (peek().is('_') || peek().is('^')) {
    bool low = next().is('_');
    auto [b, e] = arg_range("a bound of the evaluation bar");
    (low ? lb : hb) = b;
    (low ? le : he) = e;
    (low ? has_lo : has_hi) = true;
  }
  if (!has_lo || !has_hi) fail(bar, "an evaluation at one point, F|_{x=a}, is not read yet (a bar needs both ends, [F]_a^b)");
  std::size_t eq = le;
  for (std::size_t i = lb; i < le; ++i)
    if (toks_[i].is('=')) eq = i;
  Parsed var;
  if (eq < le) {
    var = parse_range(lb, eq, "the variable of the evaluation bar", &Parser::sum);
    if (var.node.kind != NodeKind::Symbol) fail(toks_[lb], "expected a name before '=' in the evaluation bar");
    lb = eq + 1;
  } else if (!last_int_var_.empty()) {
    var = symbol(last_int_var_, bar);
  } else {
    fail(bar, "write the variable of the evaluation bar in its lower end, [F]_{x=a}^{b}");
  }
  Parsed a = parse_range(lb, le, "the lower end", &Parser::sum);
  Parsed b = parse_range(hb, he, "the upper end", &Parser::sum);
  std::vector<Parsed> args;
  const Token first = toks_[0];
  SourcePos fpos = f.node.pos;
  std::size_t fbegin = f.begin;
  args.push_back(std::move(f));
  args.push_back(std::move(var));
  args.push_back(std::move(a));
  args.push_back(std::move(b));
  Parsed out = call("eval_between", std::move(args), bar);
  out.node.pos = fpos;
  out.begin = fbegin;
  extend(out, toks_[pos_ - 1]);
  (void)first;
  return out;
}

// dv/dt, d\mathbf{p}/dt, d(mv)/dt, \mathrm{d}x/\mathrm{d}t: a derivative written with a slash;
// dv on its own: differential(v).
Parsed Parser::slash_derivative(const Token& d) {
  std::size_t start = pos_, after = 0;
  is_d_mark(pos_, after);
  auto not_yet = [&]() {
    std::string what = plain(start, std::min(end_, after + 1));
    fail(d, "a differential " + what + " outside a derivative or an integral is not read yet (write \\frac{d..}{dt} or \\int_a^b .. dt)");
  };
  if (after >= end_) not_yet();
  pos_ = after;
  enter(d);
  Parsed body;
  if (peek().is('(')) body = group(next(), ")", true);
  else if (starts_name(peek())) body = name();
  else not_yet();
  std::size_t dd = 0;
  if (!peek().is('/') || pos_ + 1 >= end_ || !is_d_mark(pos_ + 1, dd) || dd >= end_ || !starts_name(toks_[dd])) {
    // a differential on its own (`dv = a\,dt`, `\frac{dm}{m}`): differential(v). Only the
    // document reader takes it, dividing the row by the differential of the display's variable
    // (or reporting the row as not read); any other reader rejects the unknown function.
    if (body.node.kind != NodeKind::Symbol) {
      pos_ = start;
      not_yet();
    }
    --nest_;
    std::vector<Parsed> args;
    args.push_back(std::move(body));
    Parsed out = call("differential", std::move(args), d);
    extend(out, toks_[pos_ - 1]);
    return out;
  }
  pos_ = dd;
  Parsed var = name();
  --nest_;
  if (var.node.kind != NodeKind::Symbol) fail(toks_[dd], "expected the variable after d in the derivative");
  body.node.parenthesized = false;
  std::vector<Parsed> args;
  args.push_back(std::move(body));
  args.push_back(std::move(var));
  Parsed out = call("diff", std::move(args), d);
  extend(out, toks_[pos_ - 1]);
  return out;
}

// \mathrm{..}, \text{..}, \operatorname{..}: a function, a name, or an error
Parsed Parser::roman(const Token& cs) {
  std::size_t at_cs = pos_;
  next();
  if (!peek().is('{')) fail(peek(), "expected '{' after \\" + cs.text);
  std::size_t b = pos_ + 1, e = match_[pos_];
  std::string s = plain(b, e);
  if (s == "d") {
    pos_ = at_cs;
    return slash_derivative(cs);
  }
  if (const char* f = (cs.text == "operatorname" || cs.text == "mathrm") ? function_name(s) : nullptr) {
    pos_ = e + 1;
    return function(cs, f);
  }
  while (!s.empty() && (s.back() == '.' || s.back() == ' ')) s.pop_back();  // \text{const.}
  bool word = !s.empty();
  for (char c : s) word = word && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_');
  if (!word) fail(cs, "text '" + s + "' inside an expression is not read yet");
  pos_ = at_cs;
  return name();
}

}  // namespace dc::tex
