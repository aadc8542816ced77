// Decimal inputs as exact rationals (core/exact.hpp): certification's inputs and the rig's exact
// resonance test. Apart from decimal_value.hpp, so that the many files that read decimals do not
// compile GMP's rational arithmetic.
#pragma once
#include <string>

#include "vibrofric/api/decimal_value.hpp"
#include "vibrofric/core/exact.hpp"

namespace vibrofric {

// The exact value of d; InputError naming `what` where its power of ten is beyond
// ±max_rational_exponent (the rational would have that many digits).
constexpr long max_rational_exponent = 100000;
exact::Rational rational(const Decimal& d, const std::string& what);

// The exact rational of decimal text. Text outside the grammar is check_decimal's refusal
// (catalogue.hpp); any magnitude is a value (rational()'s limit on its power of ten).
exact::Rational exact_decimal(const std::string& text, const std::string& what);

}  // namespace vibrofric
