#include "derivations/core/integral_equal.hpp"

#include <string>

#include <ginac/ginac.h>

#include "derivations/core/printer.hpp"
#include "derivations/core/prove_detail.hpp"
#include "derivations/kernel/quadrature.hpp"

namespace dc {

using GiNaC::ex;

namespace {

bool is_integral(const Node& n) { return n.kind == NodeKind::Call && n.text == "integral"; }

bool contains_integral(const Node& n) {
  if (is_integral(n)) return true;
  for (const auto& a : n.args)
    if (contains_integral(a)) return true;
  return false;
}

Verdict undecided_because(const std::string& why) {
  Verdict v;
  v.kind = VerdictKind::Undecided;
  v.method = "integral";
  v.reason = why;
  return v;
}

bool is_infinity(const Node& n) {
  const Node& v = n.kind == NodeKind::Neg ? n.args[0] : n;
  return v.kind == NodeKind::Symbol && v.text == "oo";
}

}  // namespace

bool continuous_everywhere(const ex& e, const GiNaC::symbol& x) {
  if (!e.has(x)) return true;
  if (e.is_equal(x)) return true;
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!continuous_everywhere(e.op(i), x)) return false;
    return true;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex& n = e.op(1);
    if (n.has(x)) {
      // c^(g(x)) with a constant positive base c would do; only exp is accepted (below).
      return false;
    }
    return GiNaC::is_a<GiNaC::numeric>(n) && GiNaC::ex_to<GiNaC::numeric>(n).is_nonneg_integer() &&
           continuous_everywhere(e.op(0), x);
  }
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (name != "exp" && name != "sin" && name != "cos" && name != "atan" && !detail::is_abstract_application(e))
      return false;
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!continuous_everywhere(e.op(i), x)) return false;
    return true;
  }
  return false;
}

namespace {

std::string prefixed(const std::string& head, const std::string& method) {
  return method.empty() ? head : head + " + " + method;
}

// ---- integrals inside larger expressions -------------------------------------------------

Node make_node(NodeKind k, std::string text, std::vector<Node> args, const Node& at) {
  Node n;
  n.kind = k;
  n.text = std::move(text);
  n.args = std::move(args);
  n.pos = at.pos;
  n.length = at.length;
  return n;
}

bool mentions(const Node& n, const std::string& name) {
  if ((n.kind == NodeKind::Symbol || n.kind == NodeKind::Call) && n.text == name) return true;
  for (const auto& a : n.args)
    if (mentions(a, name)) return true;
  return false;
}

Node substituted(const Node& n, const std::string& name, const Node& value) {
  if (n.kind == NodeKind::Symbol && n.text == name) {
    Node v = value;
    v.parenthesized = true;   // keeps its grouping wherever it lands
    return v;
  }
  Node out = n;
  for (auto& a : out.args) a = substituted(a, name, value);
  return out;
}

// The rewrites: d/dx of integral(f, t, a, b) is f(b)*db/dx - f(a)*da/dx (Leibniz) when f does
// not contain x and is continuous in t on the whole line; a polynomial integrand is integrated
// exactly and put back into the tree as its closed form.
class IntegralRewriter {
 public:
  explicit IntegralRewriter(const SymbolTable& table) : table_(table) {}

  // false (with why_) when an integral is left that neither rewrite handles
  bool rewrite(Node& n) {
    // d/dx of an integral first (Leibniz needs the integral itself, not its closed form); the
    // integral's own parts are rewritten before
    if (n.kind == NodeKind::Call && n.text == "diff" && n.args.size() == 2 && is_integral(n.args[0])) {
      for (auto& a : n.args[0].args)
        if (!rewrite(a)) return false;
      if (!rewrite(n.args[1])) return false;
      return leibniz(n) && rewrite(n);   // the result may hold diff(closed form) or nothing left
    }
    for (auto& a : n.args)
      if (!rewrite(a)) return false;
    if (is_integral(n)) return exact(n);
    return true;
  }

  GiNaC::ex value(const Node& n) const { return to_ginac(n, table_); }
  const std::vector<std::string>& steps() const { return steps_; }
  const std::string& why() const { return why_; }

 private:
  const SymbolTable& table_;
  std::vector<std::string> steps_;
  std::string why_;

  bool fail(const std::string& why) {
    why_ = why;
    return false;
  }

  // The integral's parts; false (with why_) for a malformed or improper one.
  // t is the variable as an ex (a symbol): GiNaC symbols are held by ex, never copied into a
  // GiNaC::symbol variable (a copy that lost its status flags recurses in symbol::eval).
  bool parts(const Node& in, GiNaC::ex& f, GiNaC::ex& t, GiNaC::ex& a, GiNaC::ex& b) {
    if (in.args.size() != 4) throw InputError(in.pos, "expected integral(f, x, a, b): 4 arguments", in.length);
    if (is_infinity(in.args[2]) || is_infinity(in.args[3]))
      return fail("improper integrals (a limit of integration at oo or -oo) are not checked yet");
    const GiNaC::ex te = to_ginac(in.args[1], table_);
    if (!GiNaC::is_a<GiNaC::symbol>(te))
      throw InputError(in.args[1].pos, "the variable of integration must be a symbol", in.args[1].length);
    t = te;
    f = value(in.args[0]);
    a = value(in.args[2]);
    b = value(in.args[3]);
    if (a.has(t) || b.has(t))
      throw InputError(in.pos, "a limit of integration contains the variable of integration", in.length);
    return true;
  }

  bool leibniz(Node& d) {
    const Node& in = d.args[0];
    const Node& x = d.args[1];
    GiNaC::ex f, t, a, b;
    if (!parts(in, f, t, a, b)) return false;
    if (x.kind != NodeKind::Symbol || mentions(in.args[0], x.text) || x.text == in.args[1].text)
      return exact(d.args[0]);   // d/dx of the closed form, if there is one
    if (!continuous_everywhere(f, GiNaC::ex_to<GiNaC::symbol>(t)))
      return fail("d/d" + x.text + " of an integral whose integrand is not continuous on the whole line (Leibniz's "
                  "rule is applied only then)");
    const Node& var = in.args[1];
    Node fb = substituted(in.args[0], var.text, in.args[3]);
    Node fa = substituted(in.args[0], var.text, in.args[2]);
    Node db = make_node(NodeKind::Call, "diff", {in.args[3], x}, d);
    Node da = make_node(NodeKind::Call, "diff", {in.args[2], x}, d);
    Node upper = make_node(NodeKind::Mul, "", {fb, db}, d);
    Node lower = make_node(NodeKind::Mul, "", {fa, da}, d);
    Node r = make_node(NodeKind::Sub, "", {upper, lower}, d);
    r.parenthesized = true;
    steps_.push_back("d/d" + x.text + " of the integral by Leibniz's rule (continuous integrand)");
    d = std::move(r);
    return true;
  }

  bool exact(Node& in) {
    GiNaC::ex f, t, a, b;
    if (!parts(in, f, t, a, b)) return false;
    if (!f.is_polynomial(t))
      return fail("an integral inside a larger expression is evaluated only for a polynomial integrand (here "
                  "it is not); write it as a whole side, 'integral(f, x, a, b) = G'");
    GiNaC::ex exact;
    try {
      exact = GiNaC::integral(t, a, b, f).eval_integ();   // integral(x, a, b, f): x an ex
    } catch (const std::exception& e) {
      return fail(std::string("GiNaC could not integrate the polynomial: ") + e.what());
    }
    for (GiNaC::const_preorder_iterator it = exact.preorder_begin(); it != exact.preorder_end(); ++it)
      if (GiNaC::is_a<GiNaC::integral>(*it)) return fail("GiNaC left the polynomial integral unevaluated");
    // Back into the tree as an expression (not a placeholder symbol: a diff or limit around it
    // must see how it depends on its variables); the printed form must denote the same value.
    Node node;
    try {
      node = parse_expression(print_text(exact, table_), in.pos);
      if (!(to_ginac(node, table_) - exact).expand().is_zero()) return fail("the integral's closed form did not print exactly");
    } catch (const std::exception& e) {
      return fail(std::string("the integral's closed form did not print exactly: ") + e.what());
    }
    steps_.push_back("integral of a polynomial = " + print_text(exact, table_));
    node.parenthesized = true;
    node.pos = in.pos;
    node.length = in.length;
    in = std::move(node);
    return true;
  }
};

std::optional<Verdict> integrals_in_expressions(const Node& lhs, const Node& rhs, const SymbolTable& table,
                                                const ProveOptions& opt) {
  IntegralRewriter rw(table);
  Node l = lhs, r = rhs;
  if (!rw.rewrite(l) || !rw.rewrite(r)) return undecided_because(rw.why());
  Verdict v = prove_equal(rw.value(l), rw.value(r), table, opt);
  std::string how;
  for (const auto& s : rw.steps()) how += (how.empty() ? "" : "; ") + s;
  v.method = prefixed("integral (" + how + ")", v.method);
  return v;
}

}  // namespace

std::optional<Verdict> integral_equality(const Node& lhs, const Node& rhs, const SymbolTable& table,
                                         const ProveOptions& opt) {
  const bool in_l = contains_integral(lhs), in_r = contains_integral(rhs);
  if (!in_l && !in_r) return std::nullopt;
  const Node* integral = nullptr;
  const Node* other = nullptr;
  if (is_integral(lhs) && !in_r) integral = &lhs, other = &rhs;
  else if (is_integral(rhs) && !in_l) integral = &rhs, other = &lhs;
  // an integral inside an expression, or integrals nested in the integral's own parts
  bool nested = false;
  if (integral)
    for (const auto& a : integral->args) nested = nested || contains_integral(a);
  if (!integral) return integrals_in_expressions(lhs, rhs, table, opt);
  if (nested) {
    // the inner integrals by their closed forms, then the whole-side methods below
    IntegralRewriter rw(table);
    Node in = *integral;
    for (auto& a : in.args)
      if (!rw.rewrite(a)) return undecided_because(rw.why());
    std::optional<Verdict> v = integral == &lhs ? integral_equality(in, rhs, table, opt)
                                                : integral_equality(lhs, in, table, opt);
    std::string how;
    for (const auto& step : rw.steps()) how += (how.empty() ? "" : "; ") + step;
    if (v) v->method = prefixed("inner integrals (" + how + ")", v->method);
    return v;
  }
  if (integral->args.size() != 4)
    throw InputError(integral->pos, "expected integral(f, x, a, b): 4 arguments", integral->length);
  if (is_infinity(integral->args[2]) || is_infinity(integral->args[3]))
    return undecided_because("improper integrals (a limit of integration at oo or -oo) are not checked yet");
  const ex f = to_ginac(integral->args[0], table);
  const ex xe = to_ginac(integral->args[1], table);
  if (!GiNaC::is_a<GiNaC::symbol>(xe))
    throw InputError(integral->args[1].pos, "the variable of integration must be a symbol", integral->args[1].length);
  const GiNaC::symbol& x = GiNaC::ex_to<GiNaC::symbol>(xe);
  const ex a = to_ginac(integral->args[2], table);
  const ex b = to_ginac(integral->args[3], table);
  if (a.has(x) || b.has(x))
    throw InputError(integral->pos, "a limit of integration contains the variable of integration", integral->length);
  const ex G = to_ginac(*other, table);

  // 1. A polynomial integrand: GiNaC integrates it exactly. (Only then: eval_integ also
  // "integrates" 1/x to log across 0, where the integral diverges.)
  if (f.is_polynomial(x)) try {
    ex exact = GiNaC::integral(x, a, b, f).eval_integ();
    if (!exact.has(GiNaC::integral(x, a, b, f)) && !GiNaC::is_a<GiNaC::integral>(exact)) {
      bool residual = false;
      for (GiNaC::const_preorder_iterator it = exact.preorder_begin(); it != exact.preorder_end(); ++it)
        residual = residual || GiNaC::is_a<GiNaC::integral>(*it);
      if (!residual) {
        Verdict v = prove_equal(exact, G, table, opt);
        if (v.kind == VerdictKind::Proved || v.kind == VerdictKind::Refuted) {
          v.method = prefixed("integral (polynomial integrand, integrated exactly: " + print_text(exact, table) + ")",
                              v.method);
          return v;
        }
      }
    }
  } catch (const std::exception&) {
  }

  // 2. G as an antiderivative in the upper limit.
  std::string symbolic_note;
  // Both f (in x) and G (in b) must be continuous: G = exp(b) + atan(1/b) + atan(b) has the
  // derivative exp(b) wherever it is defined, but jumps by pi at b = 0.
  if (GiNaC::is_a<GiNaC::symbol>(b) && !f.has(b) && !a.has(b) && continuous_everywhere(f, x) &&
      continuous_everywhere(G, GiNaC::ex_to<GiNaC::symbol>(b))) {
    const GiNaC::symbol& bs = GiNaC::ex_to<GiNaC::symbol>(b);
    Verdict d = prove_equal(G.diff(bs), f.subs(x == b), table, opt);
    if (d.kind == VerdictKind::Proved) {
      Verdict z = prove_equal(G.subs(b == a), 0, table, opt);
      if (z.kind == VerdictKind::Proved) {
        Verdict v;
        v.kind = VerdictKind::Proved;
        v.method = "integral: d/d" + bs.get_name() + " of the closed form is the integrand at " + bs.get_name() +
                   " (" + d.method + "), and the closed form is 0 at " + bs.get_name() + " = " + print_text(a, table) +
                   " (" + z.method + ")";
        return v;
      }
    }
    symbolic_note = "; d/d" + bs.get_name() + " of the closed form is " + (d.holds() ? "the integrand" : "not proved to be the integrand");
  }

  // 3. Rigorous quadrature at sampled parameter values.
  Verdict v = kernel::probe_definite_integral(f, x, a, b, G, table, opt);
  v.method = prefixed("integral", v.method);
  if (v.kind == VerdictKind::Undecided && !symbolic_note.empty()) v.reason += symbolic_note;
  return v;
}

}  // namespace dc
