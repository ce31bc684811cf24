// SI dimensions as exponent vectors of exact rationals (so the sqrt(2*g*x) of Example 9.7 and
// the m^(-1/2) of a wave function stay exact) and the parser of unit expressions like [kg*m/s^2].
#include "derivations/syntax/units.hpp"

#include <cstdlib>
#include <numeric>
#include <string>
#include <string_view>
#include <utility>

#include "derivations/syntax/source.hpp"

namespace dc {
namespace {

constexpr std::array<const char*, Dimension::kBase> kBaseNames = {"kg", "m", "s", "A", "K", "mol", "cd"};

// Unicode superscripts for integer exponents: s², m³, s⁻¹ is never needed (negatives go
// below the fraction bar).
std::string superscript(long long n) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string s;
  for (char c : std::to_string(n)) s += digits[c - '0'];
  return s;
}

// One factor "kg", "s²" / "s^2", "m^(1/2)"; the exponent num/den > 0.
std::string factor(int index, long long num, long long den, bool ascii) {
  std::string s = kBaseNames[static_cast<std::size_t>(index)];
  if (den == 1 && num == 1) return s;
  if (den == 1) return s + (ascii ? "^" + std::to_string(num) : superscript(num));
  return s + "^(" + std::to_string(num) + "/" + std::to_string(den) + ")";
}

std::string render(const std::array<long long, Dimension::kBase>& num, const std::array<long long, Dimension::kBase>& den,
                   bool ascii) {
  const std::string dot = ascii ? "*" : "·";
  std::string up, down;
  int ndown = 0;
  for (int i = 0; i < Dimension::kBase; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (num[k] > 0) {
      if (!up.empty()) up += dot;
      up += factor(i, num[k], den[k], ascii);
    } else if (num[k] < 0) {
      if (!down.empty()) down += dot;
      down += factor(i, -num[k], den[k], ascii);
      ++ndown;
    }
  }
  if (up.empty() && down.empty()) return "1";
  if (up.empty()) up = "1";
  if (down.empty()) return up;
  return up + "/" + (ndown > 1 ? "(" + down + ")" : down);
}

// Exponent vectors of the named units: kg, m, s, A, K, mol, cd. The radian and the steradian
// are SI's dimensionless derived units (m/m and m²/m²): [rad/s] is 1/s.
struct NamedUnit {
  const char* name;
  std::array<int, Dimension::kBase> exps;
};
constexpr NamedUnit kUnits[] = {
    {"kg", {1, 0, 0, 0, 0, 0, 0}},
    {"m", {0, 1, 0, 0, 0, 0, 0}},
    {"s", {0, 0, 1, 0, 0, 0, 0}},
    {"A", {0, 0, 0, 1, 0, 0, 0}},
    {"K", {0, 0, 0, 0, 1, 0, 0}},
    {"mol", {0, 0, 0, 0, 0, 1, 0}},
    {"cd", {0, 0, 0, 0, 0, 0, 1}},
    {"N", {1, 1, -2, 0, 0, 0, 0}},
    {"J", {1, 2, -2, 0, 0, 0, 0}},
    {"W", {1, 2, -3, 0, 0, 0, 0}},
    {"Pa", {1, -1, -2, 0, 0, 0, 0}},
    {"Hz", {0, 0, -1, 0, 0, 0, 0}},
    {"rad", {0, 0, 0, 0, 0, 0, 0}},
    {"sr", {0, 0, 0, 0, 0, 0, 0}},
    {"mass", {1, 0, 0, 0, 0, 0, 0}},
    {"length", {0, 1, 0, 0, 0, 0, 0}},
    {"time", {0, 0, 1, 0, 0, 0, 0}},
    {"velocity", {0, 1, -1, 0, 0, 0, 0}},
    {"acceleration", {0, 1, -2, 0, 0, 0, 0}},
    {"force", {1, 1, -2, 0, 0, 0, 0}},
    {"energy", {1, 2, -2, 0, 0, 0, 0}},
    {"momentum", {1, 1, -1, 0, 0, 0, 0}},
    {"power", {1, 2, -3, 0, 0, 0, 0}},
    {"frequency", {0, 0, -1, 0, 0, 0, 0}},
    {"dimensionless", {0, 0, 0, 0, 0, 0, 0}},
};

std::string accepted_names() {
  std::string s;
  for (const auto& u : kUnits) {
    s += u.name;
    s += ", ";
  }
  return s + "1";
}

// The first entries are units; from "mass" on they are names of dimensions.
constexpr std::size_t kFirstDimensionName = 14;
static_assert(std::string_view(kUnits[kFirstDimensionName].name) == "mass");

Dimension from_exps(const std::array<int, Dimension::kBase>& e) {
  Dimension d;
  for (int i = 0; i < Dimension::kBase; ++i) {
    Dimension b = Dimension::base(i);
    int k = e[static_cast<std::size_t>(i)];
    for (int j = 0; j < std::abs(k); ++j) d = k > 0 ? d * b : d / b;
  }
  return d;
}

// The largest unit exponent accepted (docs/format.md): kg^999 is the most any unit needs and
// more. Larger literals are refused with this limit, not mistaken for non-integers.
constexpr int kMaxUnitExponent = 999;

// An integer exponent written as a literal, optionally negated: 2, -1, (-2). Sets too_large
// for an integer literal beyond kMaxUnitExponent.
bool integer_exponent(const Node& n, int& out, bool& too_large);

// A unit exponent: an integer (2, -1) or a fraction of two integers, optionally negated
// (1/2, -1/2, (-3/2), -(1/2)). Sets p/q with q > 0.
bool rational_exponent(const Node& n, int& p, int& q, bool& too_large) {
  if (n.kind == NodeKind::Neg) {
    if (!rational_exponent(n.args[0], p, q, too_large)) return false;
    p = -p;
    return true;
  }
  if (n.kind == NodeKind::Div) {
    int a = 0, b = 0;
    if (!integer_exponent(n.args[0], a, too_large) || !integer_exponent(n.args[1], b, too_large)) return false;
    if (b == 0) return false;
    if (b < 0) a = -a, b = -b;
    const int g = std::gcd(std::abs(a), b);
    p = g ? a / g : 0;
    q = g ? b / g : 1;
    return true;
  }
  q = 1;
  return integer_exponent(n, p, too_large);
}

bool integer_exponent(const Node& n, int& out, bool& too_large) {
  if (n.kind == NodeKind::Neg) {
    if (!integer_exponent(n.args[0], out, too_large)) return false;
    out = -out;
    return true;
  }
  if (n.kind != NodeKind::Number || n.text.empty()) return false;
  for (char c : n.text)
    if (c < '0' || c > '9') return false;   // 2.5, 1e3
  std::size_t first = n.text.find_first_not_of('0');
  std::string digits = first == std::string::npos ? "0" : n.text.substr(first);
  if (digits.size() > 3) {
    too_large = true;
    return false;
  }
  out = std::stoi(digits);
  return true;
}

bool is_one(const Node& n) { return n.kind == NodeKind::Number && n.text == "1"; }

Dimension parse_unit(const Node& n) {
  switch (n.kind) {
    case NodeKind::Number:
      if (n.text == "1") return Dimension();
      throw InputError(n.pos, "a unit may contain the number 1 only, found '" + n.text + "'", n.length);
    case NodeKind::Symbol:
      for (const auto& u : kUnits)
        if (n.text == u.name) return from_exps(u.exps);
      throw InputError(n.pos, "unknown unit '" + n.text + "'; expected one of " + accepted_names(), n.length);
    case NodeKind::Mul:
      return parse_unit(n.args[0]) * parse_unit(n.args[1]);
    case NodeKind::Div:
      return parse_unit(n.args[0]) / parse_unit(n.args[1]);
    case NodeKind::Pow: {
      Dimension base = parse_unit(n.args[0]);
      int p = 0, q = 1;
      bool too_large = false;
      if (!rational_exponent(n.args[1], p, q, too_large)) {
        if (too_large)
          throw InputError(n.args[1].pos,
                           "unit exponent '" + to_text(n.args[1]) + "' is too large: a unit exponent is an integer from -" +
                               std::to_string(kMaxUnitExponent) + " to " + std::to_string(kMaxUnitExponent) +
                               " or a fraction of two such integers",
                           n.args[1].length);
        throw InputError(n.args[1].pos, "a unit exponent must be an integer such as 2 or -1, or a fraction such as (-1/2)",
                         n.args[1].length);
      }
      Dimension out;
      if (!base.pow(p, q, out))
        throw InputError(n.args[1].pos, "unit exponent " + to_text(n.args[1]) + " is too large", n.args[1].length);
      return out;
    }
    case NodeKind::Add:
    case NodeKind::Sub:
      throw InputError(n.op_pos.line ? n.op_pos : n.pos, "units cannot be added or subtracted; combine them with '*', '/' and '^'");
    case NodeKind::Neg:
      throw InputError(n.pos, "a unit cannot be negative");
    case NodeKind::Call:
      throw InputError(n.pos, "'" + n.text + "(...)' is not a unit; expected one of " + accepted_names(), n.length);
  }
  throw InputError(n.pos, "malformed unit");
}

}  // namespace

Dimension Dimension::base(int index) {
  Dimension d;
  if (index >= 0 && index < kBase) d.num_[static_cast<std::size_t>(index)] = 1;
  return d;
}

// Exponent i becomes n/d, reduced; a part beyond kMaxPart marks the dimension unrepresentable.
void Dimension::set(int i, __int128 n, __int128 d) {
  const auto k = static_cast<std::size_t>(i);
  if (d < 0) n = -n, d = -d;
  __int128 a = n < 0 ? -n : n, b = d;
  while (b != 0) {
    __int128 t = a % b;
    a = b;
    b = t;
  }
  const __int128 g = a == 0 ? d : a;
  n /= g;
  d /= g;
  if (n > kMaxPart || n < -kMaxPart || d > kMaxPart) {
    overflow_ = true;
    num_[k] = 0;
    den_[k] = 1;
    return;
  }
  num_[k] = static_cast<long long>(n);
  den_[k] = static_cast<long long>(d);
}

Dimension Dimension::operator*(const Dimension& o) const {
  Dimension d;
  d.overflow_ = overflow_ || o.overflow_;
  for (int i = 0; i < kBase; ++i) {
    const auto k = static_cast<std::size_t>(i);
    d.set(i, static_cast<__int128>(num_[k]) * o.den_[k] + static_cast<__int128>(o.num_[k]) * den_[k],
          static_cast<__int128>(den_[k]) * o.den_[k]);
  }
  return d;
}

Dimension Dimension::operator/(const Dimension& o) const {
  Dimension d;
  d.overflow_ = overflow_ || o.overflow_;
  for (int i = 0; i < kBase; ++i) {
    const auto k = static_cast<std::size_t>(i);
    d.set(i, static_cast<__int128>(num_[k]) * o.den_[k] - static_cast<__int128>(o.num_[k]) * den_[k],
          static_cast<__int128>(den_[k]) * o.den_[k]);
  }
  return d;
}

bool Dimension::pow(int p, int q, Dimension& out) const {
  if (q <= 0 || overflow_) return false;
  Dimension d;
  for (int i = 0; i < kBase; ++i) {
    const auto k = static_cast<std::size_t>(i);
    d.set(i, static_cast<__int128>(num_[k]) * p, static_cast<__int128>(den_[k]) * q);
  }
  if (d.overflow_) return false;
  out = d;
  return true;
}

bool Dimension::dimensionless() const {
  if (overflow_) return false;
  for (long long t : num_)
    if (t != 0) return false;
  return true;
}

std::string Dimension::to_string() const { return overflow_ ? "(unrepresentable)" : render(num_, den_, false); }
std::string Dimension::to_ascii() const { return overflow_ ? "(unrepresentable)" : render(num_, den_, true); }

bool unit_as_written(const Node& n) {
  switch (n.kind) {
    case NodeKind::Symbol:
      for (std::size_t i = 0; i < kFirstDimensionName; ++i)
        if (n.text == kUnits[i].name) return true;
      return false;
    case NodeKind::Mul:
    case NodeKind::Div:
      return (unit_as_written(n.args[0]) || is_one(n.args[0])) && unit_as_written(n.args[1]);
    case NodeKind::Pow:
      return unit_as_written(n.args[0]);
    default:
      return false;
  }
}

Dimension parse_dimension(const Node& unit_expr) { return parse_unit(unit_expr); }

}  // namespace dc
