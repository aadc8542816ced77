// A decimal number as written: the API's "decimal in" (README, "Numbers"; decimal.hpp is its
// "decimal out"). Every decimal text the library takes (a flag, a Python string, a field of a wave
// or profile file) is read by Decimal::read, with one grammar,
//
//     [+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]{1,9})?
//
// (at most 9 exponent digits: no value of the model needs |exponent| ≥ 10^9, and Boost's
// cpp_bin_float reader overflows from 15 on), and held exactly: sign, significand digits and power
// of ten, with the text as typed for messages. Each number type takes its correctly rounded value
// (to<Real>), certification the exact rational (exact_input.hpp), comparisons are exact (compare).
#pragma once
#include <cstdlib>
#include <iosfwd>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

class Decimal {
 public:
  // The decimal `text` writes, or none where it is outside the grammar (the caller names the input
  // in its refusal: check_decimal, catalogue.hpp).
  static std::optional<Decimal> read(const std::string& text);

  const std::string& text() const { return text_; }
  bool negative() const { return negative_; }
  bool is_zero() const { return zero_; }
  // value = ±digits · 10^exponent; digits without leading zeros, "" for zero. Made from the text
  // when asked (a record of millions of samples keeps one string per value).
  std::string digits() const;
  long exponent() const { return exponent_; }
  // The digits the text writes before any exponent, leading zeros included ("0.0012" has 5).
  int written_digits() const;

  // The value correctly rounded to nearest in Real (mpfr: at the current precision): the C
  // library's strtod/strtold for double and long double, MPFR's and Boost's readers otherwise;
  // a subnormal result is a value, not an error.
  template <class Real>
  Real to() const {
    if constexpr (std::is_same_v<Real, double>)
      return std::strtod(text_.c_str(), nullptr);
    else if constexpr (std::is_same_v<Real, long double>)
      return std::strtold(text_.c_str(), nullptr);
    else
      return Real(text_);
  }


 private:
  std::string text_;
  long exponent_ = 0;
  bool negative_ = false, zero_ = true;
};

// Its text, for messages.
std::ostream& operator<<(std::ostream& out, const Decimal& d);

// Exact comparison: −1, 0 or 1 as a < b, a = b, a > b.
int compare(const Decimal& a, const Decimal& b);

// Σ terms exactly, written "Me-E" (M the integer sum of the significands at the smallest power).
std::string exact_sum_text(const std::vector<const Decimal*>& terms);

}  // namespace vibrofric
