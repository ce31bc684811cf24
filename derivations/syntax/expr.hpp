// The author's expression tree, with positions.
//
// derivcheck parses every formula itself (GiNaC's parser has no positions, leaks internal
// source locations and crashes on deep nesting). The tree keeps exactly what the author wrote:
// binary operators stay binary and in order, parentheses are remembered, numbers keep their
// literal text. The LaTeX writer prints this tree (so the author's term order survives);
// to_ginac() turns it into a GiNaC expression for checking.
//
// Grammar (precedence low to high; ^ is right-associative, unary minus binds looser than ^):
//   relation := sum ( '=' sum )*            a chain a = b = c claims every adjacent pair
//   sum      := product ( ('+'|'-') product )*
//   product  := unary ( ('*'|'/') unary )*
//   unary    := ('-'|'+') unary | power
//   power    := postfix ( '^' unary )?
//   postfix  := atom ( '°' )?                 30° is 30*deg (the tree holds Mul(30, deg))
//   atom     := number | identifier | identifier '(' args ')' | '(' sum ')'
//   number   := digits ( '.' digits )?        (exact: 2.5 means 5/2)
//   identifier := [A-Za-z][A-Za-z0-9_]*       'oo' is +infinity (only where a limit point is expected)
// Predefined constants: pi, and deg = pi/180 (degrees: sin(30*deg) = 1/2); 'deg' cannot be
// declared. Built-in functions: sqrt exp log ln sin cos tan asin acos atan abs
// and the calculus forms  diff(f, x)   diff(f, x, n)   limit(f, x, point)   integral(f, x, a, b)
// A call of a declared function (e.g. v(t)) is a Call node whose name is that function.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "derivations/syntax/source.hpp"

namespace dc {

enum class NodeKind {
  Number,    // text = literal as written ("2", "0.5")
  Symbol,    // text = identifier ("m1", "pi", "oo")
  Add,       // args[0] + args[1]
  Sub,       // args[0] - args[1]
  Mul,       // args[0] * args[1]
  Div,       // args[0] / args[1]
  Neg,       // -args[0]
  Pow,       // args[0] ^ args[1]
  Call,      // text = function name, args = arguments
};

struct Node {
  NodeKind kind = NodeKind::Number;
  std::string text;
  std::vector<Node> args;
  SourcePos pos;          // first character of this node
  int length = 1;         // characters spanned (on pos.line), for underlining
  bool parenthesized = false;  // the author wrote ( ... ) around exactly this node
  SourcePos op_pos;       // binary operators (Add..Pow): position of the operator character

  bool is(NodeKind k) const { return kind == k; }
};

// A chain of sides joined by '='; a single side is an expression step.
struct Relation {
  std::vector<Node> sides;
  bool is_equation() const { return sides.size() >= 2; }
};

struct ParseLimits {
  std::size_t max_length = 100000;   // characters in one expression
  int max_depth = 200;               // nesting of parentheses/operators
  int max_int_digits = 400;          // digits in one numeric literal
  // Depth of the resulting tree, counting left-nested chains (a+b+c+... is a chain of binary
  // nodes). Consumers recurse over the tree, so this keeps them far from the stack limit.
  int max_tree_depth = 5000;
  // max_depth is additionally capped at 1000 internally (the parser itself recurses).
};

// Parse one expression / relation. `origin` is the position of text[0]; positions in the
// result and in errors are computed from it (line breaks inside `text` advance the line).
// Throws InputError naming what was expected, e.g. "expected ')' to close '(' at 3:7".
Node parse_expression(std::string_view text, const SourcePos& origin, const ParseLimits& limits = {});
Relation parse_relation(std::string_view text, const SourcePos& origin, const ParseLimits& limits = {});

// Every identifier used in the tree (Symbol nodes, and Call names), in order of first use.
void collect_identifiers(const Node& n, std::vector<const Node*>& out);

// Plain-text rendering of the author's tree (used in reports). Deterministic.
std::string to_text(const Node& n);
std::string to_text(const Relation& r);

bool is_builtin_function(std::string_view name);   // sqrt, exp, ..., diff, limit, integral
bool is_reserved_name(std::string_view name);      // builtins plus pi, deg, oo

}  // namespace dc
