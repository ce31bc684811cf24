// SI dimensions: exponents of the seven base quantities, exact rationals (sqrt(2 g x) is m/s;
// a wave function in one dimension is m^(-1/2)).
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
  // exponent p/q (q > 0); returns false when a resulting exponent's numerator or denominator
  // would exceed kMaxPart (the exponents stay small exact rationals).
  bool pow(int p, int q, Dimension& out) const;
  // false when a product or quotient overflowed kMaxPart (dimension_of reports it)
  bool representable() const { return !overflow_; }
  static constexpr long long kMaxPart = 1000000;
  bool operator==(const Dimension& o) const { return num_ == o.num_ && den_ == o.den_ && overflow_ == o.overflow_; }
  bool operator!=(const Dimension& o) const { return !(*this == o); }
  bool dimensionless() const;
  // "kg·m/s²", "m^(1/2)", "1/m^(1/2)", "1" for dimensionless. Deterministic.
  std::string to_string() const;
  // The same, ASCII only ("kg*m/s^2").
  std::string to_ascii() const;

 private:
  // exponent i = num_[i] / den_[i], reduced, den_[i] > 0
  std::array<long long, kBase> num_{};
  std::array<long long, kBase> den_{1, 1, 1, 1, 1, 1, 1};
  bool overflow_ = false;
  void set(int i, __int128 n, __int128 d);
};

// Parse a dimension written as a unit expression: products/quotients/powers (integers or
// fractions such as m^(-1/2)) of kg m s A K mol cd, derived N J W Pa Hz, the dimensionless
// rad (radian) and sr (steradian), the names mass length time velocity acceleration force
// energy momentum power frequency dimensionless, and the number 1.
// Throws InputError at the offending node ("unknown unit 'kgs'; expected one of kg, m, s, ...").
Dimension parse_dimension(const Node& unit_expr);

// Does the unit expression name only units (kg, N, rad, ...), no dimension words (velocity,
// mass, dimensionless) and not just 1? Then it is worth printing as the author wrote it.
bool unit_as_written(const Node& unit_expr);

}  // namespace dc
