// Symbols: the only place symbols are created.
//
// GiNaC identifies symbols by serial number, not by name, so every GiNaC symbol used for a
// derivation comes from its SymbolTable. Each symbol has a domain (used by the symbolic
// cascade: positive symbols are GiNaC possymbols; and by the numeric probe, which samples
// from the domain), a TeX name and an SI dimension.
#pragma once
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/units.hpp"

namespace dc {

struct Domain {
  enum class Kind { Real, Positive, Nonnegative, Negative, Interval };
  Kind kind = Kind::Real;
  // Interval bounds (exact: rationals or pi multiples); only for Kind::Interval.
  GiNaC::ex lo, hi;
  bool lo_open = false, hi_open = false;
  // Only integer values (`symbol n : positive integer`): the probe samples integers, the
  // cascade reduces sin(n*pi), cos(2*n*pi), (-1)^(2*n) (decide/integer.hpp). GiNaC knows
  // nothing of it: the symbol is a realsymbol (a possymbol when positive).
  bool integer = false;

  static Domain real() { return {}; }
  static Domain positive() { Domain d; d.kind = Kind::Positive; return d; }
  static Domain nonnegative() { Domain d; d.kind = Kind::Nonnegative; return d; }
  static Domain negative() { Domain d; d.kind = Kind::Negative; return d; }
  static Domain interval(GiNaC::ex lo, bool lo_open, GiNaC::ex hi, bool hi_open);

  bool contains(const GiNaC::numeric& x) const;   // exact test
  bool strictly_positive() const;                 // every value > 0
  bool nonnegative_values() const;                // every value >= 0
  bool empty() const;                             // e.g. (1,1) or [2,1]
  std::string to_string() const;                  // "positive", "in [0, 1]", "positive integer"
  // Every value is "any real" (no sign, interval or integer restriction).
  bool unrestricted() const { return kind == Kind::Real && !integer; }
};

// Parse "positive", "nonnegative", "negative", "real", "in [a,b]", "in (a,b]", ... (a, b
// constant expressions: rationals, pi, pi/2), and each of them with "integer": "integer",
// "positive integer", "integer in [1, 10]". Throws InputError at `pos` (offset into text).
Domain parse_domain(std::string_view text, const SourcePos& pos);

struct SymbolInfo {
  std::string name;          // as in the file: "v1p"
  std::string tex;           // "v'_1" (defaults to a TeX rendering of name)
  Domain domain;
  Dimension dimension;
  bool has_dimension = false;  // false: not declared (definitions infer it)
  // The unit as the author wrote it ("N*s", "rad/s", "m^(-1/2)"), kept for printing; empty
  // when it was not declared or names dimensions ("velocity", "1"). Checking uses `dimension`.
  std::string unit;
  GiNaC::ex sym;             // the GiNaC symbol (possymbol when domain is positive)
  SourcePos pos;             // where it was declared or defined
  bool is_function = false;  // declared as a function of other symbols: v(t)
  bool is_differential = false;  // the differential d(x) of a symbol (differential.hpp)
  // A vector (`vector v : 3 [m/s]`, vectors.hpp): its number of components (2 or 3) and their
  // names, each a declared real symbol (or function, for `vector r(t)`) with the same unit.
  int vector_dim = 0;
  std::vector<std::string> components;
  std::vector<std::string> params;  // for functions: parameter names
  bool defined_by_step = false;     // introduced by a definition step, not a declaration
};

// Extra relations assumed between symbols: "v1 > v2", "m_r <= m0".
struct Constraint {
  GiNaC::ex lhs, rhs;
  enum class Op { Lt, Le, Gt, Ge, Ne } op;
  std::string text;          // as written
  SourcePos pos;
};

// Does a difference lhs - rhs of sign `sign` (-1, 0 or 1) satisfy `op`?
bool sign_satisfies(Constraint::Op op, int sign);
// The same relation with its sides exchanged: a < b is b > a.
Constraint::Op flipped(Constraint::Op op);
// The relation as written in assumptions: "<", "<=", ">", ">=", "!=".
const char* op_text(Constraint::Op op);

class SymbolTable {
 public:
  // Throws InputError on redeclaration or an empty domain.
  const SymbolInfo& declare(SymbolInfo info);
  const SymbolInfo* find(const std::string& name) const;
  const SymbolInfo* find(const GiNaC::symbol& s) const;   // reverse lookup by serial
  const std::vector<SymbolInfo>& all() const { return symbols_; }
  void add_constraint(Constraint c) { constraints_.push_back(std::move(c)); }
  // Narrow the domain of a declared symbol (same GiNaC symbol): used to test which
  // declaration would make a refuted claim hold. Returns false for an unknown name.
  bool narrow_domain(const std::string& name, const Domain& d);
  // Replace the TeX name of `name` (`notation arrows` for vectors); false for an unknown name.
  bool set_tex(const std::string& name, std::string tex);
  const std::vector<Constraint>& constraints() const { return constraints_; }
  // A copy in which `name` is a fresh real symbol without domain or assumed relations: the
  // dummy variable of an integral, which must not inherit what is declared of the quantity of
  // the same name (abs(x) = x for a declared positive x would be wrong over (-1, 1)).
  SymbolTable with_bound_variable(const std::string& name) const;
  // Abstract function applications (v(t)) are GiNaC functions from a fixed pool; this maps a
  // declared function name to its pool index.
  int function_index(const std::string& name) const;

 private:
  std::vector<SymbolInfo> symbols_;  // declaration order
  std::map<std::string, std::size_t> by_name_;
  std::vector<Constraint> constraints_;
};

// Thrown by to_ginac when a limit(f, x, p) written in an expression cannot be decided by the
// limit helper; what() is the helper's reason. Not an InputError: the input is well formed.
struct UndecidedLimit : std::runtime_error {
  explicit UndecidedLimit(const std::string& reason, SourcePos where = {})
      : std::runtime_error(reason), pos(std::move(where)) {}
  SourcePos pos;  // the limit(...) call
};

// Convert the author's tree to GiNaC with the symbols of `table`.
// Errors (InputError, at the node): unknown symbol ("undefined symbol 'v_e': declare it with
// 'symbol v_e ...' or define it in an earlier step"), unknown function, wrong argument count,
// exponent too large (|n| > 1000 for a symbolic base; a numeric power whose result would have
// more than 10000 digits), 'oo' outside a limit point.
// Calculus forms: diff(f,x[,n]) is carried out; limit(f,x,p) is evaluated with the limit
// helper (an unevaluable limit throws UndecidedLimit); integral(f,x,a,b) is evaluated where a
// method applies (polynomial integrand, proved antiderivative), else UndecidedLimit.
GiNaC::ex to_ginac(const Node& n, const SymbolTable& table);

// `a ± b` (the call pm(a, b); `a ∓ b` is mp(a, b), `±b` pm(b)) has two values. to_ginac reads
// it with the sign chosen here: +1 (± as +, ∓ as -), -1, or 0, none chosen, where a '±' is an
// input error. A step with ± is checked once for each sign (rules/plus_minus.hpp), and a reader
// validates it both ways.
int plus_minus_sign();
class PlusMinusSign {
 public:
  explicit PlusMinusSign(int sign);
  ~PlusMinusSign();
  PlusMinusSign(const PlusMinusSign&) = delete;
  PlusMinusSign& operator=(const PlusMinusSign&) = delete;

 private:
  int saved_;
};
// Does n contain a ± or ∓?
bool has_plus_minus(const Node& n);

// The integrand of integral(f, x, a, b), converted with x as a fresh real variable of
// integration (SymbolTable::with_bound_variable): the dummy variable ranges over (a, b), not
// over what is declared of the quantity of the same name. `x` is that fresh symbol and `table`
// the table it belongs to (a copy of the caller's with x rebound). Throws InputError when the
// second argument is not a declared symbol, or a limit of integration contains it.
struct Integrand {
  SymbolTable table;
  GiNaC::ex f, x;
};
Integrand integrand_of(const Node& integral, const SymbolTable& table);

// The dimension of an expression; throws InputError at the first inconsistent node, e.g.
// "cannot add kg·m/s and kg·m²/s²" at the '+'. Symbols without a declared dimension
// (has_dimension false) count as dimensionless; a literal 0 in a sum takes any dimension.
Dimension dimension_of(const Node& n, const SymbolTable& table);
// A literal 0, possibly negated (`0`, `-0.0`): it has every dimension.
bool is_literal_zero(const Node& n);

}  // namespace dc
