// The number types of the API (README, "Precision"): their names, the digits each prints, and the
// one visitor that maps a NumberType to its C++ type, so that no other file switches on it.
#pragma once
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

enum class NumberType { float64, float80, bin50, bin100, mpfr };

// The type a name denotes (double, long-double, cpp_bin_float_50, cpp_bin_float_100, mpfr), or
// none; a front end words the refusal in its own terms, listing number_type_choices.
std::optional<NumberType> number_type_named(const std::string& text);
inline constexpr const char* number_type_choices = "double, long-double, cpp_bin_float_50, cpp_bin_float_100 or mpfr";
std::string number_type_name(NumberType t);
// Every type's name, in the order of number_type_choices (a front end's "did you mean").
std::vector<std::string> number_type_names();

template <class Real>
struct TypeTag {
  using type = Real;
};

// f(TypeTag<Real>{}) for the C++ type t names; every call of f returns the same type.
template <class F>
decltype(auto) visit_number_type(NumberType t, F&& f) {
  switch (t) {
    case NumberType::float64: return f(TypeTag<double>{});
    case NumberType::float80: return f(TypeTag<long double>{});
    case NumberType::bin50: return f(TypeTag<bin50>{});
    case NumberType::bin100: return f(TypeTag<bin100>{});
    case NumberType::mpfr: break;
  }
  return f(TypeTag<mpfr>{});
}

struct Precision {
  NumberType type = NumberType::mpfr;
  int digits = 50;  // mpfr: significant digits asked for, in [min_digits, max_digits]
};

// Digits printed for a precision: the request for mpfr, round-trip digits for hardware types,
// 50 or 100 for cpp_bin_float.
int output_digits(const Precision& p);

}  // namespace vibrofric
