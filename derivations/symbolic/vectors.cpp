// Vectors as their components (vectors.hpp).
#include "derivations/symbolic/vectors.hpp"

namespace dc {

namespace {

const SymbolInfo* vector_info(const Node& n, const SymbolTable& t) {
  if (n.kind != NodeKind::Symbol && n.kind != NodeKind::Call) return nullptr;
  const SymbolInfo* s = t.find(n.text);
  if (!s || s->vector_dim == 0) return nullptr;
  return (n.kind == NodeKind::Call) == s->is_function ? s : nullptr;
}

bool literal_zero(const Node& n) {
  if (n.kind == NodeKind::Neg) return literal_zero(n.args[0]);
  return n.kind == NodeKind::Number && n.text.find_first_not_of("0.") == std::string::npos;
}

bool is_call(const Node& n, const char* name) { return n.kind == NodeKind::Call && n.text == name; }

Node leaf(NodeKind kind, const std::string& text, const SourcePos& pos) {
  Node n;
  n.kind = kind;
  n.text = text;
  n.pos = pos;
  n.length = static_cast<int>(text.size());
  return n;
}

Node bin(NodeKind kind, Node a, Node b, const SourcePos& pos) {
  Node n;
  n.kind = kind;
  n.pos = pos;
  n.op_pos = pos;
  n.args.push_back(std::move(a));
  n.args.push_back(std::move(b));
  return n;
}

// A subtree put in the place of another: printing parenthesizes by structure, so only the
// author's own parentheses are dropped (they belonged to the vector expression).
Node grouped(Node n) {
  n.parenthesized = false;
  return n;
}

[[noreturn]] void shape_error(const SourcePos& at, const std::string& msg, int length = 1) {
  throw InputError(at, msg, length);
}

class Vectors {
 public:
  explicit Vectors(const SymbolTable& t) : t_(t) {}

  int shape(const Node& n) {
    switch (n.kind) {
      case NodeKind::Number: return 0;
      case NodeKind::Symbol: {
        const SymbolInfo* v = vector_info(n, t_);
        return v ? v->vector_dim : 0;
      }
      case NodeKind::Neg: return shape(n.args[0]);
      case NodeKind::Add:
      case NodeKind::Sub: return sum_shape(n, n.args[0], n.args[1], n.kind == NodeKind::Add ? "add" : "subtract");
      case NodeKind::Mul: {
        const int a = shape(n.args[0]), b = shape(n.args[1]);
        if (a && b) shape_error(n.op_pos, "a product of two vectors: write dot(u, v) or cross(u, v)");
        return a ? a : b;
      }
      case NodeKind::Div:
        if (shape(n.args[1])) shape_error(n.args[1].pos, "cannot divide by a vector", n.args[1].length);
        return shape(n.args[0]);
      case NodeKind::Pow:
        if (shape(n.args[0]) || shape(n.args[1]))
          shape_error(n.op_pos, "a vector has no power: write dot(v, v) or norm(v)^2");
        return 0;
      case NodeKind::Call: return call_shape(n);
    }
    return 0;
  }

  Node component(const Node& n, int k) {
    switch (n.kind) {
      case NodeKind::Number:   // the zero vector
        return n;
      case NodeKind::Symbol: {
        const SymbolInfo* v = vector_info(n, t_);
        Node out = leaf(NodeKind::Symbol, v->components.at(static_cast<std::size_t>(k - 1)), n.pos);
        out.length = n.length;
        return out;
      }
      case NodeKind::Neg: {
        Node out = n;
        out.args[0] = grouped(component(n.args[0], k));
        return out;
      }
      case NodeKind::Add:
      case NodeKind::Sub: {
        Node out = n;
        for (auto& a : out.args) a = grouped(component(a, k));
        return out;
      }
      case NodeKind::Mul: {
        Node out = n;
        const bool left = shape(n.args[0]) != 0;
        out.args[0] = grouped(left ? component(n.args[0], k) : scalar(n.args[0]));
        out.args[1] = grouped(left ? scalar(n.args[1]) : component(n.args[1], k));
        return out;
      }
      case NodeKind::Div: {
        Node out = n;
        out.args[0] = grouped(component(n.args[0], k));
        out.args[1] = grouped(scalar(n.args[1]));
        return out;
      }
      default:
        break;
    }
    // calls
    if (is_call(n, "vec")) return grouped(scalar(n.args.at(static_cast<std::size_t>(k - 1))));
    if (is_call(n, "cross")) {
      // (u x w)_k = u_{k+1} w_{k+2} - u_{k+2} w_{k+1}, indices mod 3
      auto c = [&](const Node& v, int i) { return grouped(component(v, (i - 1) % 3 + 1)); };
      return grouped(bin(NodeKind::Sub, bin(NodeKind::Mul, c(n.args[0], k + 1), c(n.args[1], k + 2), n.pos),
                         bin(NodeKind::Mul, c(n.args[0], k + 2), c(n.args[1], k + 1), n.pos), n.pos));
    }
    if (const SymbolInfo* v = vector_info(n, t_)) {   // r(t) -> r_y(t)
      Node out = n;
      out.text = v->components.at(static_cast<std::size_t>(k - 1));
      for (auto& a : out.args) a = scalar(a);
      return out;
    }
    // diff, integral, limit, eval_between, ±: the vector argument componentwise, the rest as is
    Node out = n;
    for (auto& a : out.args) a = shape(a) ? component(a, k) : scalar(a);
    return out;
  }

  Node scalar(const Node& n) {
    if (const int s = shape(n))
      shape_error(n.pos, "'" + short_text(n) + "' is a vector of " + std::to_string(s) +
                             " components where a number is expected (an equation between vectors is checked "
                             "component by component; dot(u, v) and norm(v) are numbers)",
                  n.length);
    if (n.kind == NodeKind::Number || n.kind == NodeKind::Symbol) return n;
    if (is_call(n, "dot")) return grouped(dot(n.args[0], n.args[1], n.pos));
    if (is_call(n, "norm") || (is_call(n, "abs") && n.args.size() == 1 && shape(n.args[0]))) {   // |v|
      Node out = leaf(NodeKind::Call, "sqrt", n.pos);
      out.args.push_back(dot(n.args[0], n.args[0], n.pos));
      out.length = n.length;
      return out;
    }
    if (is_call(n, "cross")) {   // two 2-D vectors: the scalar u_x*v_y - u_y*v_x
      auto c = [&](const Node& v, int i) { return grouped(component(v, i)); };
      return grouped(bin(NodeKind::Sub, bin(NodeKind::Mul, c(n.args[0], 1), c(n.args[1], 2), n.pos),
                         bin(NodeKind::Mul, c(n.args[0], 2), c(n.args[1], 1), n.pos), n.pos));
    }
    Node out = n;
    for (auto& a : out.args) a = scalar(a);
    return out;
  }

 private:
  int sum_shape(const Node& n, const Node& l, const Node& r, const char* verb) {
    const int a = literal_zero(l) ? -1 : shape(l), b = literal_zero(r) ? -1 : shape(r);
    if (a < 0 || b < 0) return std::max(std::max(a, b), 0);   // 0 adopts the other side's shape
    if (a != b) {
      if (a == 0 || b == 0) shape_error(n.op_pos, std::string("cannot ") + verb + " a vector and a number");
      shape_error(n.op_pos, std::string("cannot ") + verb + " vectors of " + std::to_string(a) + " and " +
                                std::to_string(b) + " components");
    }
    return a;
  }

  void require_scalar(const Node& call, const Node& arg) {
    if (shape(arg))
      shape_error(arg.pos, "the argument of " + call.text + " must be a number, not a vector", arg.length);
  }

  int call_shape(const Node& n) {
    const std::string& f = n.text;
    if (f == "vec") {
      for (const auto& a : n.args)
        if (shape(a)) shape_error(a.pos, "a component of a vector must be a number, not a vector", a.length);
      return static_cast<int>(n.args.size());
    }
    if (f == "dot" || f == "cross") {
      if (n.args.size() != 2) shape_error(n.pos, f + "(u, v) takes two vectors", n.length);
      const int a = shape(n.args[0]), b = shape(n.args[1]);
      if (a == 0 || b == 0)
        shape_error(n.pos, f + "(u, v) takes two vectors; '" + short_text(a == 0 ? n.args[0] : n.args[1]) +
                               "' is a number",
                    n.length);
      if (a != b) shape_error(n.pos, f + " of vectors of " + std::to_string(a) + " and " + std::to_string(b) + " components", n.length);
      return f == "cross" && a == 3 ? 3 : 0;
    }
    if (f == "abs" && n.args.size() == 1 && shape(n.args[0])) return 0;   // |v|, the length
    if (f == "norm") {
      if (n.args.size() != 1 || shape(n.args[0]) == 0)
        shape_error(n.pos, "norm(v) takes one vector", n.length);
      return 0;
    }
    if (f == "pm" || f == "mp") {
      if (n.args.size() == 2) return sum_shape(n, n.args[0], n.args[1], "add");
      return n.args.empty() ? 0 : shape(n.args[0]);
    }
    if (const SymbolInfo* v = vector_info(n, t_)) {
      for (const auto& a : n.args) require_scalar(n, a);
      return v->vector_dim;
    }
    if ((f == "diff" || f == "integral" || f == "limit" || f == "eval_between") && !n.args.empty()) {
      for (std::size_t i = 1; i < n.args.size(); ++i) require_scalar(n, n.args[i]);
      return shape(n.args[0]);
    }
    for (const auto& a : n.args) require_scalar(n, a);
    return 0;
  }

  // u_x*w_x + u_y*w_y (+ u_z*w_z)
  Node dot(const Node& u, const Node& w, const SourcePos& pos) {
    const int dim = shape(u);
    Node sum;
    for (int k = 1; k <= dim; ++k) {
      Node term = bin(NodeKind::Mul, grouped(component(u, k)), grouped(component(w, k)), pos);
      sum = k == 1 ? std::move(term) : bin(NodeKind::Add, std::move(sum), std::move(term), pos);
    }
    return sum;
  }

  static std::string short_text(const Node& n) {
    std::string s = to_text(n);
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
  }

  const SymbolTable& t_;
};

bool uses_vectors(const Node& n, const SymbolTable& t) {
  if (n.kind == NodeKind::Call && (n.text == "vec" || n.text == "dot" || n.text == "cross" || n.text == "norm"))
    return true;
  if (vector_info(n, t)) return true;
  for (const auto& a : n.args)
    if (uses_vectors(a, t)) return true;
  return false;
}

}  // namespace

bool has_vector_notation(const Node& n, const SymbolTable& table) { return uses_vectors(n, table); }

int vector_shape(const Node& n, const SymbolTable& table) {
  if (!uses_vectors(n, table)) return 0;
  return Vectors(table).shape(n);
}

int vector_shape(const Relation& r, const SymbolTable& table) {
  int out = -1;
  for (const auto& side : r.sides) {
    if (literal_zero(side)) continue;
    const int s = vector_shape(side, table);
    if (out >= 0 && s != out)
      throw InputError(side.pos, s == 0 || out == 0 ? "a vector equated with a number: compare vectors with vectors"
                                                    : "vectors of " + std::to_string(out) + " and " + std::to_string(s) +
                                                          " components equated",
                       side.length);
    out = s;
  }
  return std::max(out, 0);
}

Node vector_component(const Node& n, const SymbolTable& table, int k) {
  Vectors v(table);
  if (literal_zero(n)) return n;
  v.shape(n);
  return v.component(n, k);
}

Relation vector_component(const Relation& r, const SymbolTable& table, int k) {
  Relation out;
  for (const auto& side : r.sides) {
    out.sides.push_back(vector_component(side, table, k));
    out.sides.back().parenthesized = false;   // a side needs no parentheses of its own
  }
  return out;
}

Node scalar_form(const Node& n, const SymbolTable& table) { return Vectors(table).scalar(n); }

std::vector<std::string> default_component_names(const std::string& vector_name, int dim) {
  std::vector<std::string> out;
  for (int k = 0; k < dim; ++k) out.push_back(vector_name + "_" + std::string(1, "xyz"[k]));
  return out;
}

}  // namespace dc
