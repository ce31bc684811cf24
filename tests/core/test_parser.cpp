// The expression parser: tree shape, positions, to_text round trips, and every error class
// with its exact position.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/source.hpp"

using namespace dc;

namespace {

const SourcePos kOrigin{"f.dc", 1, 1};

Node parse(const std::string& s) { return parse_expression(s, kOrigin); }

// Structural equality including the parenthesized flags, ignoring positions.
bool same_tree(const Node& a, const Node& b) {
  if (a.kind != b.kind || a.text != b.text || a.parenthesized != b.parenthesized || a.args.size() != b.args.size())
    return false;
  for (std::size_t i = 0; i < a.args.size(); ++i)
    if (!same_tree(a.args[i], b.args[i])) return false;
  return true;
}

// Parses `text` expecting an InputError; returns it.
InputError parse_error(const std::string& text, const ParseLimits& limits = {}) {
  try {
    parse_expression(text, kOrigin, limits);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text.substr(0, 80));
  throw std::logic_error("unreachable");
}

// A random expression string from the grammar (with random spacing and redundant parens).
std::string random_expr(std::mt19937& rng, int depth) {
  std::uniform_int_distribution<int> pick(0, 9);
  static const char* atoms[] = {"a", "b", "m1", "v_2", "2", "0.5", "pi", "10"};
  auto atom = [&] { return std::string(atoms[rng() % 8]); };
  if (depth <= 0) return atom();
  // A signed term right after a binary + or - must be parenthesized (x + -y is an error).
  auto term = [&](int d) {
    std::string t = random_expr(rng, d);
    return t[0] == '-' ? "(" + t + ")" : t;
  };
  switch (pick(rng)) {
    case 0: return atom();
    case 1: return random_expr(rng, depth - 1) + " + " + term(depth - 1);
    case 2: return random_expr(rng, depth - 1) + "-" + term(depth - 1);
    case 3: return random_expr(rng, depth - 1) + "*" + random_expr(rng, depth - 1);
    case 4: return random_expr(rng, depth - 1) + " / " + random_expr(rng, depth - 1);
    case 5: return "(" + random_expr(rng, depth - 1) + ")^" + atom();
    case 6: return "-" + atom();
    case 7: return "sqrt(" + random_expr(rng, depth - 1) + ")";
    case 8: return "(" + random_expr(rng, depth - 1) + ")";
    default: return "diff(" + random_expr(rng, depth - 1) + ", a)";
  }
}

}  // namespace

TEST_CASE("parser builds the author's tree with precedence and associativity", "[parser]") {
  Node n = parse("m1*v1 + m2*v2");
  REQUIRE(n.kind == NodeKind::Add);
  REQUIRE(n.args[0].kind == NodeKind::Mul);
  REQUIRE(n.args[1].kind == NodeKind::Mul);
  CHECK(n.args[1].args[1].text == "v2");

  Node s = parse("a - b - c");  // left-associative
  REQUIRE(s.kind == NodeKind::Sub);
  CHECK(s.args[0].kind == NodeKind::Sub);
  CHECK(s.args[1].text == "c");

  Node p = parse("2^3^2");  // right-associative
  REQUIRE(p.kind == NodeKind::Pow);
  CHECK(p.args[0].text == "2");
  CHECK(p.args[1].kind == NodeKind::Pow);

  Node m = parse("-x^2");  // unary minus binds looser than ^
  REQUIRE(m.kind == NodeKind::Neg);
  CHECK(m.args[0].kind == NodeKind::Pow);

  Node e = parse("x^-1");
  REQUIRE(e.kind == NodeKind::Pow);
  CHECK(e.args[1].kind == NodeKind::Neg);

  Node q = parse("a/b*c");
  REQUIRE(q.kind == NodeKind::Mul);
  CHECK(q.args[0].kind == NodeKind::Div);
}

TEST_CASE("numbers keep their literal text, parentheses are remembered", "[parser]") {
  Node n = parse("0.50*(x + 1)");
  REQUIRE(n.kind == NodeKind::Mul);
  CHECK(n.args[0].kind == NodeKind::Number);
  CHECK(n.args[0].text == "0.50");
  CHECK_FALSE(n.args[0].parenthesized);
  CHECK(n.args[1].parenthesized);
  CHECK(n.args[1].kind == NodeKind::Add);
  CHECK_FALSE(n.parenthesized);
}

TEST_CASE("positions: nodes, operators and multi-line text", "[parser]") {
  Node n = parse_expression("m1*v1 + m2*v2", SourcePos{"f.dc", 3, 10});
  CHECK(n.pos.file == "f.dc");
  CHECK(n.pos.line == 3);
  CHECK(n.pos.col == 10);
  CHECK(n.length == 13);
  CHECK(n.op_pos.col == 16);  // the '+'
  CHECK(n.args[1].pos.col == 18);
  CHECK(n.args[1].length == 5);
  CHECK(n.args[1].args[1].pos.col == 21);

  Node c = parse("  sqrt(2*g*x)");
  CHECK(c.kind == NodeKind::Call);
  CHECK(c.pos.col == 3);
  CHECK(c.length == 11);
  CHECK(c.args[0].pos.col == 8);

  // A claim continued on an indented line: positions follow the line breaks.
  Node m = parse_expression("(m1*v1 +\n      m2*v2)/M", SourcePos{"f.dc", 7, 12});
  REQUIRE(m.kind == NodeKind::Div);
  const Node& sum = m.args[0];
  CHECK(sum.pos.line == 7);
  CHECK(sum.pos.col == 12);
  CHECK(sum.args[1].pos.line == 8);
  CHECK(sum.args[1].pos.col == 7);
  CHECK(m.args[1].pos.line == 8);
  CHECK(m.args[1].pos.col == 14);
  CHECK(m.op_pos.line == 8);
  CHECK(m.op_pos.col == 13);
}

TEST_CASE("relations: chains of '='", "[parser]") {
  Relation r = parse_relation("F = m*a = diff(p, t)", kOrigin);
  REQUIRE(r.sides.size() == 3);
  CHECK(r.is_equation());
  CHECK(r.sides[2].kind == NodeKind::Call);
  CHECK(r.sides[2].pos.col == 11);
  CHECK(to_text(r) == "F = m*a = diff(p, t)");
  Relation single = parse_relation("x + 1", kOrigin);
  try {
    parse_relation("a == b", kOrigin);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.pos().col == 4);
    CHECK(e.message() == "expected an expression after '=', found '=' (write a single '=')");
  }
  try {
    parse_relation("a = b < c", kOrigin);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.pos().col == 7);
    CHECK(e.message() == "unexpected character '<'");
  }
  CHECK_FALSE(single.is_equation());
}

TEST_CASE("to_text prints minimal parentheses and keeps the author's", "[parser][to_text]") {
  struct Case {
    const char* in;
    const char* out;
  };
  const Case cases[] = {
      {"a+b*c", "a + b*c"},
      {"(a+b)*c", "(a + b)*c"},
      {"a-(b-c)", "a - (b - c)"},
      {"a-(b+c)", "a - (b + c)"},
      {"(a*b)", "(a*b)"},
      {"a/(b*c)", "a/(b*c)"},
      {"(a^b)^c", "(a^b)^c"},
      {"a^b^c", "a^b^c"},
      {"-x^2", "-x^2"},
      {"(-x)^2", "(-x)^2"},
      {"x^-1", "x^-1"},
      {"- - x", "--x"},
      {"+x", "x"},
      {"f(a,b ,c)", "f(a, b, c)"},
      {"(m1*v1 + m2*v2)/(m1 + m2)", "(m1*v1 + m2*v2)/(m1 + m2)"},
      {"0.50", "0.50"},
      {"x - (-y)", "x - (-y)"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.in);
    CHECK(to_text(parse(c.in)) == c.out);
  }
}

TEST_CASE("to_text round trip on hand-built trees adds the parentheses the tree needs", "[parser][to_text]") {
  auto sym = [](const char* s) { Node n; n.kind = NodeKind::Symbol; n.text = s; return n; };
  auto bin = [](NodeKind k, Node a, Node b) { Node n; n.kind = k; n.args = {std::move(a), std::move(b)}; return n; };
  Node neg;
  neg.kind = NodeKind::Neg;
  neg.args = {sym("y")};
  // x + (-y) built without the parenthesized flag must not print as "x + -y" (a parse error).
  Node t = bin(NodeKind::Add, sym("x"), neg);
  CHECK(to_text(t) == "x + (-y)");
  Node back = parse(to_text(t));
  CHECK(back.kind == NodeKind::Add);
  CHECK(back.args[1].kind == NodeKind::Neg);
  // a - (b - c) and (a + b)^2 built without flags.
  CHECK(to_text(bin(NodeKind::Sub, sym("a"), bin(NodeKind::Sub, sym("b"), sym("c")))) == "a - (b - c)");
  CHECK(to_text(bin(NodeKind::Pow, bin(NodeKind::Add, sym("a"), sym("b")), sym("n"))) == "(a + b)^n");
  CHECK(to_text(bin(NodeKind::Div, sym("a"), bin(NodeKind::Mul, sym("b"), sym("c")))) == "a/(b*c)");
}

TEST_CASE("to_text round trip: parse(to_text(parse(s))) is the same tree", "[parser][to_text]") {
  const unsigned seed = 20261121;
  std::mt19937 rng(seed);
  CAPTURE(seed);
  for (int i = 0; i < 500; ++i) {
    std::string s = random_expr(rng, 5);
    CAPTURE(s);
    Node a = parse(s);
    std::string t = to_text(a);
    CAPTURE(t);
    Node b = parse(t);
    CHECK(same_tree(a, b));
    CHECK(to_text(b) == t);
  }
}

TEST_CASE("collect_identifiers lists symbols and calls once, in order of first use", "[parser]") {
  Node n = parse("v(t) + m*v(0) + sqrt(2*g*x) - m");
  std::vector<const Node*> ids;
  collect_identifiers(n, ids);
  std::vector<std::string> names;
  for (const Node* p : ids) names.push_back(p->text);
  CHECK(names == std::vector<std::string>{"v", "t", "m", "sqrt", "g", "x"});
  CHECK(ids[0]->kind == NodeKind::Call);
  CHECK(ids[2]->pos.col == 8);  // first use of m
}

TEST_CASE("builtin and reserved names", "[parser]") {
  for (const char* f : {"sqrt", "exp", "log", "ln", "sin", "cos", "tan", "asin", "acos", "atan", "abs", "diff",
                        "limit", "integral"}) {
    CAPTURE(f);
    CHECK(is_builtin_function(f));
    CHECK(is_reserved_name(f));
  }
  CHECK(is_reserved_name("pi"));
  CHECK(is_reserved_name("oo"));
  CHECK_FALSE(is_builtin_function("pi"));
  CHECK_FALSE(is_reserved_name("e"));
  CHECK_FALSE(is_reserved_name("v"));
  CHECK_FALSE(is_builtin_function("sqr"));
}

TEST_CASE("syntax errors name what was expected, at the offending character", "[parser][errors]") {
  struct Case {
    const char* text;
    int line, col;
    const char* message;
  };
  const Case cases[] = {
      {"x + + y", 1, 5, "expected an expression after '+', found '+'"},
      {"x - -y", 1, 5, "expected an expression after '-', found '-' (put a negative term in parentheses)"},
      {"(a + b", 1, 7, "expected ')' to close '(' opened at 1:1, found end of expression"},
      {"f(a, (b*c)", 1, 11, "expected ',' or ')' to close '(' of f(...) opened at 1:2, found end of expression"},
      {"a $ b", 1, 3, "unexpected character '$'"},
      {"a * μ", 1, 5, "unexpected character 'μ'"},
      {"a + b)", 1, 6, "unexpected ')' without a matching '('"},
      {"2x", 1, 2, "expected an operator or the end of the expression after '2', found 'x' (write '*' for a product)"},
      {"a = b", 1, 3, "unexpected '=': an expression is expected here, not an equation"},
      {"x**2", 1, 2, "'**' is not an operator; write '^' for a power"},
      {"1. + x", 1, 2, "expected a digit after '.' in the number '1.'"},
      {".5", 1, 1, "a number must start with a digit: write 0.5"},
      {"f()", 1, 3, "expected an argument of 'f', found ')'"},
      {"", 1, 1, "expected an expression, found end of expression"},
      {"a *", 1, 4, "expected an expression after '*', found end of expression"},
      {"()", 1, 2, "expected an expression after '(', found ')'"},
      {"[a]", 1, 1, "a vector has 2 or 3 components, found 1"},
      {"{a}", 1, 1, "unexpected character '{'; use '(' and ')' for grouping"},
      {"[a, b", 1, 6, "expected ',' or ']' to close the vector '[' opened at 1:1, found end of expression"},
      {"a * +b", 1, 5, "expected an expression after '*', found '+'"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.text);
    InputError e = parse_error(c.text);
    CHECK(e.message() == c.message);
    CHECK(e.pos().file == "f.dc");
    CHECK(e.pos().line == c.line);
    CHECK(e.pos().col == c.col);
  }
}

TEST_CASE("errors on continuation lines carry the right line", "[parser][errors]") {
  try {
    parse_relation("v = (a +\n    b", SourcePos{"g.dc", 4, 6});
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.pos().line == 5);
    CHECK(e.pos().col == 6);
    CHECK(e.message() == "expected ')' to close '(' opened at 4:10, found end of expression");
  }
}

TEST_CASE("limits: 10^5 nested parentheses give an error, not a stack overflow", "[parser][limits]") {
  std::string s(100000, '(');
  s += "x";
  s += std::string(100000, ')');
  ParseLimits lim;
  lim.max_length = 300000;
  InputError e = parse_error(s, lim);
  CHECK(e.pos().col == 201);  // the first '(' beyond the default depth of 200
  CHECK_THAT(e.message(), Catch::Contains("nested too deeply (limit 200)"));
  // Unbalanced: 10^5 '(' and nothing else.
  InputError e2 = parse_error(std::string(100000, '('));
  CHECK(e2.pos().col == 201);
}

TEST_CASE("limits: a huge max_depth is capped so the descent cannot overflow the stack", "[parser][limits]") {
  ParseLimits lim;
  lim.max_length = 300000;
  lim.max_depth = 100000000;
  std::string s(100000, '(');
  s += "x" + std::string(100000, ')');
  InputError e = parse_error(s, lim);
  CHECK(e.pos().col == 1001);
}

TEST_CASE("limits: 20000 unary minuses count as nesting", "[parser][limits]") {
  std::string s(20000, '-');
  s += "x";
  InputError e = parse_error(s);
  CHECK(e.pos().col == 201);
  CHECK_THAT(e.message(), Catch::Contains("nested too deeply (limit 200)"));
  // 200 are fine and give 200 nested Neg nodes.
  Node n = parse(std::string(200, '-') + "x");
  int depth = 0;
  for (const Node* p = &n; p->kind == NodeKind::Neg; p = &p->args[0]) ++depth;
  CHECK(depth == 200);
}

TEST_CASE("limits: exponent towers count as nesting", "[parser][limits]") {
  std::string s = "x";
  for (int i = 0; i < 300; ++i) s += "^x";
  InputError e = parse_error(s);
  CHECK(e.pos().col == 2 * 201);  // the 201st '^'
}

TEST_CASE("limits: input length and literal digits", "[parser][limits]") {
  ParseLimits lim;
  lim.max_length = 50;
  InputError e = parse_error(std::string(51, 'x'), lim);
  CHECK(e.message() == "expression is 51 characters long (limit 50)");
  CHECK(e.pos().col == 1);

  std::string big = "x + " + std::string(401, '7');
  InputError d = parse_error(big);
  CHECK(d.message() == "numeric literal has 401 digits (limit 400)");
  CHECK(d.pos().col == 5);
  CHECK(d.length() == 401);
  CHECK_NOTHROW(parse("x + " + std::string(400, '7')));
  InputError f = parse_error("1." + std::string(400, '5'));
  CHECK(f.message() == "numeric literal has 401 digits (limit 400)");
}

TEST_CASE("limits: long chains are accepted up to max_tree_depth and printed without recursion", "[parser][limits]") {
  std::string s = "x0";
  for (int i = 1; i < 4000; ++i) s += " + x" + std::to_string(i);
  Node n = parse(s);
  CHECK(to_text(n) == s);
  std::vector<const Node*> ids;
  collect_identifiers(n, ids);
  CHECK(ids.size() == 4000);

  std::string t = "x";
  for (int i = 1; i < 6000; ++i) t += "*x";
  InputError e = parse_error(t);
  CHECK_THAT(e.message(), Catch::Contains("limit 5000"));
  CHECK(e.pos().col == 2 * 5000);  // the operator creating the 5001st level
}
