// x^e and x^(1/e) for x ≥ 0 with a fixed exponent e, formed without std::pow for the exponents
// that occur in connector potentials (1, 1.5, 2 and small integers;
// derived-components-and-potentials.md §5). The potential evaluation and the grouped plastic
// return raise contributions to α_i and take the β-th root at every local iteration.
#pragma once

#include <cmath>
#include <cstdint>

namespace clinch {

class FixedPower {
 public:
  explicit FixedPower(double exponent = 2.0) : exponent_(exponent), inverse_(1.0 / exponent) {
    if (exponent == 1.0) {
      kind_ = Kind::One;
    } else if (exponent == 1.5) {
      kind_ = Kind::ThreeHalves;
    } else if (exponent == 2.0) {
      kind_ = Kind::Two;
    } else if (exponent == std::round(exponent) && exponent > 2.0 && exponent <= 16.0) {
      kind_ = Kind::Integer;
      integer_ = static_cast<int>(exponent);
    } else {
      kind_ = Kind::General;
    }
  }

  double exponent() const { return exponent_; }
  bool is_one() const { return kind_ == Kind::One; }

  double power(double x) const {  // x^e
    switch (kind_) {
      case Kind::One: return x;
      case Kind::ThreeHalves: return x * std::sqrt(x);
      case Kind::Two: return x * x;
      case Kind::Integer: {
        double r = x;
        for (int i = 1; i < integer_; ++i) r *= x;
        return r;
      }
      case Kind::General: break;
    }
    return std::pow(x, exponent_);
  }

  double root(double x) const {  // x^(1/e)
    switch (kind_) {
      case Kind::One: return x;
      case Kind::Two: return std::sqrt(x);
      case Kind::ThreeHalves: {
        const double r = std::cbrt(x);
        return r * r;
      }
      case Kind::Integer:
        if (integer_ == 3) return std::cbrt(x);
        if (integer_ == 4) return std::sqrt(std::sqrt(x));
        break;
      case Kind::General: break;
    }
    return std::pow(x, inverse_);
  }

 private:
  enum class Kind : std::uint8_t { One, ThreeHalves, Two, Integer, General };
  Kind kind_ = Kind::Two;
  int integer_ = 0;
  double exponent_ = 2.0, inverse_ = 0.5;
};

}  // namespace clinch
