// SI dimensions: exponents of the seven base quantities, in halves (sqrt(2 g x) is allowed).
#pragma once
#include <array>
#include <string>

#include "derivations/syntax/expr.hpp"

namespace dc {

class Dimension {
 public:
  // order: kg, m, s, A, K, mol, cd
  static constexpr int kBase = 7;
  Dimension() = default;                           // dimensionless
  static Dimension base(int index);                // 0 = mass (kg), 1 = length (m), 2 = time (s), ...
  Dimension operator*(const Dimension& o) const;
  Dimension operator/(const Dimension& o) const;
  // exponent p/q with q in {1, 2}; returns false when the result is not representable in halves
  bool pow(int p, int q, Dimension& out) const;
  bool operator==(const Dimension& o) const { return twice_ == o.twice_; }
  bool operator!=(const Dimension& o) const { return !(*this == o); }
  bool dimensionless() const;
  // "kg·m/s²", "m^(1/2)", "1" for dimensionless. Deterministic.
  std::string to_string() const;
  // The same, ASCII only ("kg*m/s^2").
  std::string to_ascii() const;

 private:
  std::array<int, kBase> twice_{};  // exponent * 2
};

// Parse a dimension written as a unit expression: products/quotients/integer powers of
// kg m s A K mol cd, derived N J W Pa Hz, the names mass length time velocity acceleration
// force energy momentum power frequency dimensionless, and the number 1.
// Throws InputError at the offending node ("unknown unit 'kgs'; expected one of kg, m, s, ...").
Dimension parse_dimension(const Node& unit_expr);

}  // namespace dc
