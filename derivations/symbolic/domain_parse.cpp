// parse_domain: "positive", "nonnegative", "negative", "real", and intervals "in [a, b]",
// "in (a, b]", ... (the "in" is optional) with constant bounds: rationals, decimals and
// multiples of pi (0, 1, -1/2, 0.25, pi, pi/2, 3*pi/2).
#include <string>
#include <string_view>

#include <ginac/ginac.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/literal.hpp"
#include "derivations/syntax/source.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace dc {
namespace {

const char* kExpected =
    "expected positive, nonnegative, negative, real, integer (also positive integer, ...) or an interval such as "
    "in [0, 1], in (0, pi) or in [0, pi/2)";

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// A constant bound: numbers, pi, + - * / and small integer powers. Exact.
GiNaC::ex constant_value(const Node& n) {
  switch (n.kind) {
    case NodeKind::Number:
      return exact_literal(n.text);
    case NodeKind::Symbol:
      if (n.text == "pi") return GiNaC::Pi;
      if (n.text == "deg") return GiNaC::Pi / 180;
      if (n.text == "oo")
        throw InputError(n.pos, "an interval bound must be finite; use 'positive', 'nonnegative' or 'negative' for half-lines",
                         n.length);
      throw InputError(n.pos, "an interval bound must be a constant (a number or a multiple of pi), found '" + n.text + "'",
                       n.length);
    case NodeKind::Neg:
      return -constant_value(n.args[0]);
    case NodeKind::Add:
      return constant_value(n.args[0]) + constant_value(n.args[1]);
    case NodeKind::Sub:
      return constant_value(n.args[0]) - constant_value(n.args[1]);
    case NodeKind::Mul:
      return constant_value(n.args[0]) * constant_value(n.args[1]);
    case NodeKind::Div: {
      GiNaC::ex d = constant_value(n.args[1]);
      if (d.is_zero()) throw InputError(n.op_pos, "division by zero in an interval bound");
      return constant_value(n.args[0]) / d;
    }
    case NodeKind::Pow: {
      GiNaC::ex b = constant_value(n.args[0]);
      GiNaC::ex e = constant_value(n.args[1]);
      if (!GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_integer() ||
          GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e)) > 100)
        throw InputError(n.args[1].pos, "an exponent in an interval bound must be an integer between -100 and 100",
                         n.args[1].length);
      if (b.is_zero() && GiNaC::ex_to<GiNaC::numeric>(e).is_negative())
        throw InputError(n.op_pos, "division by zero in an interval bound");
      if (b.is_zero() && e.is_zero()) throw InputError(n.pos, "0^0 is undefined in an interval bound", n.length);
      return GiNaC::pow(b, e);
    }
    case NodeKind::Call:
      throw InputError(n.pos, "an interval bound must be a constant (a number or a multiple of pi), found a call of '" +
                                  n.text + "'",
                       n.length);
  }
  throw InputError(n.pos, "malformed interval bound");
}

}  // namespace

Domain parse_domain(std::string_view text, const SourcePos& pos) {
  std::size_t b = 0, e = text.size();
  while (b < e && is_space(text[b])) ++b;
  while (e > b && is_space(text[e - 1])) --e;
  std::string_view t = text.substr(b, e - b);
  if (t.empty()) throw InputError(pos, std::string("missing domain; ") + kExpected);
  // "integer", "positive integer", "integer in [1, 10]": the domain without the word, integer
  if (t == "integer") {
    Domain d = Domain::real();
    d.integer = true;
    return d;
  }
  if (t.size() > 8 && t.substr(t.size() - 8) == " integer") {
    const std::size_t word = b + t.size() - 7;
    Domain d = parse_domain(text.substr(0, word - 1), pos);
    if (d.kind == Domain::Kind::Interval)
      throw InputError(position_in(text, pos, word), "write an integer interval as 'integer in [a, b]'", 7);
    d.integer = true;
    return d;
  }
  if (t.size() > 8 && t.substr(0, 8) == "integer " ) {
    std::size_t i = b + 8;
    while (i < e && is_space(text[i])) ++i;
    if (text.substr(i, e - i).substr(0, 2) != "in")
      throw InputError(position_in(text, pos, i),
                       "expected 'in [a, b]' after 'integer', or a sign before it ('positive integer')");
    Domain d = parse_domain(text.substr(0, e).substr(i), position_in(text, pos, i));
    d.integer = true;
    return d;
  }
  if (t == "real") return Domain::real();
  if (t == "positive") return Domain::positive();
  if (t == "nonnegative") return Domain::nonnegative();
  if (t == "negative") return Domain::negative();

  std::size_t i = b;
  if (t.substr(0, 2) == "in" && (t.size() == 2 || is_space(t[2]) || t[2] == '[' || t[2] == '(')) {
    i += 2;
    while (i < e && is_space(text[i])) ++i;
  }
  if (i >= e || (text[i] != '[' && text[i] != '(')) {
    std::size_t w = b;
    while (w < e && !is_space(text[w])) ++w;
    throw InputError(position_in(text, pos, b), "unknown domain '" + std::string(text.substr(b, w - b)) + "'; " + kExpected,
                     static_cast<int>(w - b));
  }
  const std::size_t open = i;
  const char close_c = text[e - 1];
  if (close_c != ']' && close_c != ')')
    throw InputError(position_in(text, pos, e - 1),
                     std::string("expected ']' or ')' to close the interval opened with '") + text[open] + "'");
  // The comma separating the bounds, outside any parentheses inside a bound.
  std::size_t comma = std::string_view::npos;
  int depth = 0;
  for (std::size_t k = open + 1; k + 1 < e; ++k) {
    char c = text[k];
    if (c == '(') ++depth;
    else if (c == ')') --depth;
    else if (c == ',' && depth == 0) {
      if (comma != std::string_view::npos)
        throw InputError(position_in(text, pos, k), "an interval has exactly two bounds; unexpected second ','");
      comma = k;
    }
  }
  if (comma == std::string_view::npos)
    throw InputError(position_in(text, pos, e - 1), "expected ',' between the two bounds of the interval");

  auto bound = [&](std::size_t from, std::size_t to) -> GiNaC::ex {
    std::string_view s = text.substr(from, to - from);
    std::size_t k = 0;
    while (k < s.size() && is_space(s[k])) ++k;
    if (k == s.size()) throw InputError(position_in(text, pos, from), "missing interval bound");
    Node n = parse_expression(s, position_in(text, pos, from));
    return constant_value(n);
  };
  GiNaC::ex lo = bound(open + 1, comma);
  GiNaC::ex hi = bound(comma + 1, e - 1);
  const bool lo_open = text[open] == '(';
  const bool hi_open = close_c == ')';

  // Bounds are exact constants (rationals times powers of pi at most), so a 30-digit
  // evaluation decides their order; equal bounds are detected exactly.
  GiNaC::ex diff = (hi - lo).evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(diff) || !GiNaC::ex_to<GiNaC::numeric>(diff).is_real())
    throw InputError(position_in(text, pos, open), "interval bounds must be real constants",
                     static_cast<int>(e - open));
  bool equal = (hi - lo).expand().is_zero();
  if ((!equal && GiNaC::ex_to<GiNaC::numeric>(diff).is_negative()) || (equal && (lo_open || hi_open)))
    throw InputError(position_in(text, pos, open),
                     "the interval " + std::string(text.substr(open, e - open)) + " is empty",
                     static_cast<int>(e - open));
  return Domain::interval(lo, lo_open, hi, hi_open);
}

}  // namespace dc
