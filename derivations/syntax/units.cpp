// SI dimensions as exponent vectors (stored doubled, so half-integer powers such as the
// sqrt(2*g*x) of Example 9.7 stay exact) and the parser of unit expressions like [kg*m/s^2].
#include "derivations/syntax/units.hpp"

#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>

#include "derivations/syntax/source.hpp"

namespace dc {
namespace {

constexpr std::array<const char*, Dimension::kBase> kBaseNames = {"kg", "m", "s", "A", "K", "mol", "cd"};

// Unicode superscripts for integer exponents: s², m³, s⁻¹ is never needed (negatives go
// below the fraction bar).
std::string superscript(int n) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string s;
  for (char c : std::to_string(n)) s += digits[c - '0'];
  return s;
}

// One factor "kg", "s²" / "s^2", "m^(1/2)"; `twice` > 0.
std::string factor(int index, int twice, bool ascii) {
  std::string s = kBaseNames[static_cast<std::size_t>(index)];
  if (twice == 2) return s;
  if (twice % 2 == 0) return s + (ascii ? "^" + std::to_string(twice / 2) : superscript(twice / 2));
  return s + "^(" + std::to_string(twice) + "/2)";
}

std::string render(const std::array<int, Dimension::kBase>& twice, bool ascii) {
  const std::string dot = ascii ? "*" : "·";
  std::string num, den;
  int nden = 0;
  for (int i = 0; i < Dimension::kBase; ++i) {
    int t = twice[static_cast<std::size_t>(i)];
    if (t > 0) {
      if (!num.empty()) num += dot;
      num += factor(i, t, ascii);
    } else if (t < 0) {
      if (!den.empty()) den += dot;
      den += factor(i, -t, ascii);
      ++nden;
    }
  }
  if (num.empty() && den.empty()) return "1";
  if (num.empty()) num = "1";
  if (den.empty()) return num;
  return num + "/" + (nden > 1 ? "(" + den + ")" : den);
}

// Exponent vectors (not doubled) of the named units: kg, m, s, A, K, mol, cd.
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
      int p = 0;
      bool too_large = false;
      if (!integer_exponent(n.args[1], p, too_large)) {
        if (too_large)
          throw InputError(n.args[1].pos,
                           "unit exponent '" + to_text(n.args[1]) + "' is too large: a unit exponent is an integer from -" +
                               std::to_string(kMaxUnitExponent) + " to " + std::to_string(kMaxUnitExponent),
                           n.args[1].length);
        throw InputError(n.args[1].pos, "a unit exponent must be an integer such as 2 or -1", n.args[1].length);
      }
      Dimension out;
      if (!base.pow(p, 1, out))
        throw InputError(n.args[1].pos, "unit exponent " + std::to_string(p) + " is too large", n.args[1].length);
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
  if (index >= 0 && index < kBase) d.twice_[static_cast<std::size_t>(index)] = 2;
  return d;
}

Dimension Dimension::operator*(const Dimension& o) const {
  Dimension d;
  for (std::size_t i = 0; i < twice_.size(); ++i) d.twice_[i] = twice_[i] + o.twice_[i];
  return d;
}

Dimension Dimension::operator/(const Dimension& o) const {
  Dimension d;
  for (std::size_t i = 0; i < twice_.size(); ++i) d.twice_[i] = twice_[i] - o.twice_[i];
  return d;
}

bool Dimension::pow(int p, int q, Dimension& out) const {
  if (q <= 0) return false;
  Dimension d;
  for (std::size_t i = 0; i < twice_.size(); ++i) {
    long long v = static_cast<long long>(twice_[i]) * p;
    if (v % q != 0) return false;
    v /= q;
    if (v > 1000000 || v < -1000000) return false;
    d.twice_[i] = static_cast<int>(v);
  }
  out = d;
  return true;
}

bool Dimension::dimensionless() const {
  for (int t : twice_)
    if (t != 0) return false;
  return true;
}

std::string Dimension::to_string() const { return render(twice_, false); }
std::string Dimension::to_ascii() const { return render(twice_, true); }

Dimension parse_dimension(const Node& unit_expr) { return parse_unit(unit_expr); }

}  // namespace dc
