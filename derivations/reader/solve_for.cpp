// A step solved for one of its quantities, for `derivcheck eval FILE STEP --for NAME`
// (derivation.hpp, solve_step_for; docs/cli.md, "eval").
//
// The step's equation (its first and last sides) is inverted for NAME by undoing, one at a
// time, the operations around NAME's one occurrence: + - * / and unary minus, a power with
// NAME in its base (a positive integer exponent, NAME nonnegative by its declaration) or in
// its exponent, exp, log/ln, sqrt (when the other side is nonnegative), and sin, cos, tan of
// NAME itself when NAME's declared interval lies where the inverse function gives the one
// solution ([-pi/2, pi/2], [0, pi], (-pi/2, pi/2)). Every inversion is exact where its result
// is defined, so the value eval prints satisfies the step's equation; where it is undefined
// (acos of 1.5, a division by zero) eval says the value is undefined. Anything else is a
// positioned input error naming what cannot be undone.
#include <algorithm>
#include <cmath>

#include <ginac/ginac.h>

#include "derivations/reader/derivation.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/syntax/expr.hpp"

namespace dc {
namespace {

Node make(NodeKind k, std::vector<Node> args, const SourcePos& pos) {
  Node n;
  n.kind = k;
  n.args = std::move(args);
  n.pos = pos;
  return n;
}
Node call(const char* f, Node a) {
  const SourcePos pos = a.pos;
  Node n = make(NodeKind::Call, {std::move(a)}, pos);
  n.text = f;
  return n;
}
Node number(const std::string& v, const SourcePos& pos) {
  Node n;
  n.kind = NodeKind::Number;
  n.text = v;
  n.pos = pos;
  return n;
}

int occurrences(const Node& n, const std::string& name) {
  int c = n.kind == NodeKind::Symbol && n.text == name ? 1 : 0;
  for (const auto& a : n.args) c += occurrences(a, name);
  return c;
}

void symbols_in(const Node& n, const SymbolTable& t, std::vector<std::string>& out) {
  if (n.kind == NodeKind::Symbol) {
    const SymbolInfo* s = t.find(n.text);
    if (s && !s->is_function && std::find(out.begin(), out.end(), n.text) == out.end()) out.push_back(n.text);
  }
  for (const auto& a : n.args) symbols_in(a, t, out);
}

// lo <= x <= hi for every x of the declared domain (an interval with constant bounds).
bool domain_within(const Domain& d, double lo, double hi) {
  if (d.kind != Domain::Kind::Interval) return false;
  GiNaC::ex a = GiNaC::evalf(d.lo), b = GiNaC::evalf(d.hi);
  if (!GiNaC::is_a<GiNaC::numeric>(a) || !GiNaC::is_a<GiNaC::numeric>(b)) return false;
  const double l = GiNaC::ex_to<GiNaC::numeric>(a).to_double(), h = GiNaC::ex_to<GiNaC::numeric>(b).to_double();
  // the bounds are pi multiples or rationals: compare with a margin far below their spacing
  return l >= lo - 1e-12 && h <= hi + 1e-12;
}

class Inverter {
 public:
  Inverter(const Derivation& d, const std::string& name, const Step& step) : d_(d), name_(name), step_(step) {}

  // Peel `lhs` (holding name once) until it is name; `rhs` collects the inverse operations.
  Node solve(Node lhs, Node rhs) {
    while (!(lhs.kind == NodeKind::Symbol && lhs.text == name_)) {
      const bool in0 = !lhs.args.empty() && occurrences(lhs.args[0], name_) > 0;
      const SourcePos p = lhs.pos;
      Node a = lhs.args.empty() ? Node{} : lhs.args[0];
      Node b = lhs.args.size() > 1 ? lhs.args[1] : Node{};
      switch (lhs.kind) {
        case NodeKind::Add:
          rhs = make(NodeKind::Sub, {rhs, in0 ? b : a}, p);
          lhs = in0 ? a : b;
          break;
        case NodeKind::Sub:
          if (in0) rhs = make(NodeKind::Add, {rhs, b}, p), lhs = a;
          else rhs = make(NodeKind::Sub, {a, rhs}, p), lhs = b;
          break;
        case NodeKind::Neg:
          rhs = make(NodeKind::Neg, {rhs}, p);
          lhs = a;
          break;
        case NodeKind::Mul:
          rhs = make(NodeKind::Div, {rhs, in0 ? b : a}, p);
          lhs = in0 ? a : b;
          break;
        case NodeKind::Div:
          if (in0) rhs = make(NodeKind::Mul, {rhs, b}, p), lhs = a;
          else rhs = make(NodeKind::Div, {a, rhs}, p), lhs = b;
          break;
        case NodeKind::Pow:
          if (in0) {
            // a^n = R, n a positive integer: a = R^(1/n), the one nonnegative root
            const bool integer = b.kind == NodeKind::Number && b.text.find_first_not_of("0123456789") == std::string::npos &&
                                 b.text != "0";
            if (!integer || !(a.kind == NodeKind::Symbol && a.text == name_) || !nonnegative(name_))
              fail(lhs, "a power can be undone for '" + name_ + "' only as " + name_ +
                            "^N with N a positive integer and " + name_ + " declared nonnegative");
            rhs = b.text == "2" ? call("sqrt", rhs) : make(NodeKind::Pow, {rhs, make(NodeKind::Div, {number("1", p), b}, p)}, p);
            lhs = a;
          } else {
            // a^b = R: b = log(R)/log(a)
            rhs = make(NodeKind::Div, {call("log", rhs), call("log", a)}, p);
            lhs = b;
          }
          break;
        case NodeKind::Call: lhs = undo_call(lhs, rhs); break;
        default: fail(lhs, "cannot solve for '" + name_ + "' here");
      }
    }
    return rhs;
  }

 private:
  const Derivation& d_;
  const std::string& name_;
  const Step& step_;

  bool nonnegative(const std::string& n) const {
    const SymbolInfo* s = d_.symbols.find(n);
    return s && s->domain.nonnegative_values();
  }

  [[noreturn]] void fail(const Node& at, const std::string& why) const {
    throw InputError(at.pos, "step '" + step_.label + "' cannot be solved for '" + name_ + "': " + why, at.length,
                     d_.source.line(at.pos.line));
  }

  Node undo_call(const Node& f, Node& rhs) {
    if (f.args.size() != 1) fail(f, "'" + f.text + "(...)' cannot be undone");
    const Node& a = f.args[0];
    const std::string& fn = f.text;
    if (fn == "exp") {
      rhs = call("log", rhs);
      return a;
    }
    if (fn == "log" || fn == "ln") {
      rhs = call("exp", rhs);
      return a;
    }
    if (fn == "sqrt") {
      // sqrt(a) = R holds only for R >= 0; then a = R^2
      bool nonneg = false;
      try {
        nonneg = to_ginac(rhs, d_.symbols).info(GiNaC::info_flags::nonnegative);
      } catch (const std::exception&) {
      }
      if (!nonneg)
        fail(f, "sqrt(...) = R is undone as R^2 only when R is nonnegative by its symbols' declarations, and '" +
                    to_text(rhs) + "' is not known to be");
      rhs = make(NodeKind::Pow, {rhs, number("2", rhs.pos)}, rhs.pos);
      return a;
    }
    struct Inverse {
      const char* f;
      const char* inv;
      double lo, hi;
      const char* range;
    };
    static const Inverse kTrig[] = {{"cos", "acos", 0, M_PI, "[0, pi]"},
                                    {"sin", "asin", -M_PI / 2, M_PI / 2, "[-pi/2, pi/2]"},
                                    {"tan", "atan", -M_PI / 2, M_PI / 2, "(-pi/2, pi/2)"}};
    for (const Inverse& t : kTrig) {
      if (fn != t.f) continue;
      const SymbolInfo* s = a.kind == NodeKind::Symbol ? d_.symbols.find(a.text) : nullptr;
      if (!s || a.text != name_)
        fail(f, std::string(t.f) + "(...) is undone only around '" + name_ + "' itself");
      if (!domain_within(s->domain, t.lo, t.hi))
        fail(f, std::string(t.f) + "(" + name_ + ") = R has one solution " + t.inv + "(R) only when '" + name_ +
                    "' is declared within " + t.range + " (it is declared " + s->domain.to_string() + ")");
      rhs = call(t.inv, rhs);
      return a;
    }
    fail(f, "'" + fn + "(...)' cannot be undone");
  }
};

}  // namespace

void solve_step_for(Derivation& d, const std::string& label, const std::string& for_name,
                    const std::vector<std::string>& given) {
  Step* step = nullptr;
  for (auto& s : d.steps)
    if (s.label == label) step = &s;
  if (!step) return;   // formula() reports the unknown label
  Relation& r = step->erratum ? step->erratum->corrected : step->claim;
  if (r.sides.size() < 2) return;   // formula() reports the shape
  const Node& first = r.sides[0];
  const bool formula_shape = first.kind == NodeKind::Symbol && d.symbols.find(first.text) &&
                             !d.symbols.find(first.text)->is_function;
  std::string name = for_name;
  if (name.empty()) {
    if (formula_shape) return;
    // the one quantity of the equation that --at (or the points' header) does not give
    std::vector<std::string> names, open;
    symbols_in(first, d.symbols, names);
    symbols_in(r.sides.back(), d.symbols, names);
    for (const auto& n : names)
      if (std::find(given.begin(), given.end(), n) == given.end()) open.push_back(n);
    if (open.size() != 1) {
      std::string list;
      for (std::size_t i = 0; i < open.size(); ++i) list += (i ? ", " : "") + open[i];
      throw InputError(step->pos,
                       "step '" + label + "' is not 'y = expression': name the quantity to solve it for with --for" +
                           (open.empty() ? std::string() : " (not given: " + list + ")"),
                       static_cast<int>(label.size()), d.source.line(step->pos.line));
    }
    name = open[0];
  } else {
    const SymbolInfo* s = d.symbols.find(name);
    if (!s || s->is_function)
      throw InputError({"--for", 1, 1}, "'" + name + "' is not a declared symbol of " + d.source.name);
    if (formula_shape && first.text == name && occurrences(r.sides.back(), name) == 0) return;
  }
  const int in_left = occurrences(first, name), in_right = occurrences(r.sides.back(), name);
  if (in_left + in_right != 1)
    throw InputError(step->pos,
                     "step '" + label + "' cannot be solved for '" + name + "': it occurs " +
                         std::to_string(in_left + in_right) + " times in the equation (once is needed)",
                     static_cast<int>(label.size()), d.source.line(step->pos.line));
  Inverter inv(d, name, *step);
  Node solved = in_left ? inv.solve(first, r.sides.back()) : inv.solve(r.sides.back(), first);
  Node target;
  target.kind = NodeKind::Symbol;
  target.text = name;
  target.pos = step->pos;
  r.sides = {target, solved};
}

}  // namespace dc
