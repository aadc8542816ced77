// References for correct rounding (0 ulp), decided exactly with MPFR and GMP, independently of the
// library's own rounding code (rounds_alike, rounds_to_itself, format_significant).
#pragma once
#include <gtest/gtest.h>
#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include <boost/multiprecision/cpp_int.hpp>

#include "vibrofric/api/decimal.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric::testing {

// The T nearest x if every number within e of x rounds to it, else nothing: t = x rounded to
// nearest (mpfr_get_d/ld), then x − e and x + e strictly between the midpoints of t and its two
// neighbours (a midpoint itself may round either way). Every step is exact (a nonzero ternary
// fails the test). T is double or long double.
template <class T>
std::optional<T> rounds_to_one(const mpfr& x, const mpfr& e) {
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, long double>);
  const auto xp = x.backend().data();
  const auto ep = e.backend().data();
  if (!mpfr_number_p(xp) || !mpfr_number_p(ep) || mpfr_sgn(ep) < 0) return std::nullopt;
  auto set = [](mpfr_ptr r, T v) {
    if constexpr (std::is_same_v<T, double>)
      return mpfr_set_d(r, v, MPFR_RNDN);
    else
      return mpfr_set_ld(r, v, MPFR_RNDN);
  };
  T t;
  if constexpr (std::is_same_v<T, double>)
    t = mpfr_get_d(xp, MPFR_RNDN);
  else
    t = mpfr_get_ld(xp, MPFR_RNDN);
  const T inf = std::numeric_limits<T>::infinity();
  if (!std::isfinite(t) || !std::isfinite(std::nextafter(t, inf)) || !std::isfinite(std::nextafter(t, -inf)))
    return std::nullopt;
  const mpfr_prec_t prec = std::max(mpfr_get_prec(xp), mpfr_get_prec(ep)) + 256;
  mpfr_t lo, hi, a, b;
  mpfr_inits2(prec, lo, hi, a, b, static_cast<mpfr_ptr>(nullptr));
  int inexact = set(lo, std::nextafter(t, -inf)) | set(hi, std::nextafter(t, inf)) | set(a, t);
  inexact |= mpfr_add(lo, lo, a, MPFR_RNDN) | mpfr_div_2ui(lo, lo, 1, MPFR_RNDN);
  inexact |= mpfr_add(hi, hi, a, MPFR_RNDN) | mpfr_div_2ui(hi, hi, 1, MPFR_RNDN);
  inexact |= mpfr_sub(a, xp, lo, MPFR_RNDN) | mpfr_sub(b, hi, xp, MPFR_RNDN);
  const bool inside = mpfr_cmp(a, ep) > 0 && mpfr_cmp(b, ep) > 0;
  mpfr_clears(lo, hi, a, b, static_cast<mpfr_ptr>(nullptr));
  if (inexact != 0) {
    ADD_FAILURE() << "rounds_to_one: an operation was not exact";
    return std::nullopt;
  }
  if (!inside) return std::nullopt;
  return t;
}

// The exact value of a decimal "[-]d[.d][e[-]d]" (a test input), as a rational.
inline boost::multiprecision::cpp_rational decimal_rational(const std::string& text) {
  using boost::multiprecision::cpp_int;
  const std::size_t e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  long exponent = e == std::string::npos ? 0 : std::stol(text.substr(e + 1));
  std::string digits;
  bool negative = false;
  for (char c : mantissa) {
    if (c == '-') negative = true;
    else if (c == '.') exponent -= static_cast<long>(mantissa.size() - mantissa.find('.') - 1);
    else if (c != '+') digits += c;
  }
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));  // no octal
  const cpp_int n(digits), p = boost::multiprecision::pow(cpp_int(10), static_cast<unsigned>(std::labs(exponent)));
  boost::multiprecision::cpp_rational q = exponent >= 0 ? boost::multiprecision::cpp_rational(n * p)
                                                        : boost::multiprecision::cpp_rational(n, p);
  return negative ? boost::multiprecision::cpp_rational(-q) : q;
}

// The T nearest the rational q (one rounding, mpfr_set_q at T's precision). T is double or
// long double.
template <class T>
T nearest(const boost::multiprecision::cpp_rational& q) {
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, long double>);
  mpq_t g;
  mpq_init(g);
  const std::string text = boost::multiprecision::numerator(q).str() + "/" + boost::multiprecision::denominator(q).str();
  mpq_set_str(g, text.c_str(), 10);
  mpq_canonicalize(g);
  mpfr_t r;
  mpfr_init2(r, std::numeric_limits<T>::digits);
  mpfr_set_q(r, g, MPFR_RNDN);
  T t;
  if constexpr (std::is_same_v<T, double>)
    t = mpfr_get_d(r, MPFR_RNDN);
  else
    t = mpfr_get_ld(r, MPFR_RNDN);
  mpfr_clear(r);
  mpq_clear(g);
  return t;
}

}  // namespace vibrofric::testing
