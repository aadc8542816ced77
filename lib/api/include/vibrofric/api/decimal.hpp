// Decimal output of every number type, the API's "decimal out": μ̄/μ0 (Eq. 15), Ψ (Eq. 17) and
// every other value as the correctly rounded significant digits that the tool, the module and
// the reports print (README, "Precision"). The core computes in binary and prints nothing.
#pragma once
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>

#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

// Whether a and b, each correctly rounded to `digits` significant decimal digits (MPFR's
// conversion), are the same number: a decision on values, not on their printed forms.
inline bool same_significant(const mpfr& a, const mpfr& b, int digits) {
  if (a == 0 || b == 0) return a == b;
  const auto rounded = [digits](const mpfr& x, mpfr_exp_t& e) {
    char* raw = mpfr_get_str(nullptr, &e, 10, static_cast<std::size_t>(digits), x.backend().data(), MPFR_RNDN);
    std::string ds(raw);
    mpfr_free_str(raw);
    return ds;
  };
  mpfr_exp_t ea = 0, eb = 0;
  const std::string da = rounded(a, ea), db = rounded(b, eb);
  return ea == eb && da == db;
}

// x correctly rounded to `digits` significant digits, in positional notation ("0.0123…") with
// trailing zeros kept so that the precision stays visible; zero is "0"; values outside
// [1e-5, 1e15) in scientific notation. The digits of double and long double come from
// std::to_chars, which rounds the exact binary value correctly (ten times faster than MPFR for 17
// digits); those of the other types from MPFR's correctly rounded conversion of an exact copy.
template <class Real>
std::string format_significant(const Real& x, int digits) {
  if (x == 0) return "0";
  std::string ds;
  long e10 = 0;  // value = 0.ddd × 10^e10
  if constexpr (std::is_same_v<Real, double> || std::is_same_v<Real, long double>) {
    std::string buf(static_cast<std::size_t>(digits) + 40, '\0');
    const auto end = std::to_chars(buf.data(), buf.data() + buf.size(), x, std::chars_format::scientific, digits - 1).ptr;
    buf.resize(static_cast<std::size_t>(end - buf.data()));  // "-d.ddde-xx"
    const std::size_t e = buf.find('e');
    if (e == std::string::npos) return buf;                  // inf, nan
    e10 = std::strtol(buf.c_str() + e + 1, nullptr, 10) + 1;
    for (std::size_t i = 0; i < e; ++i)
      if (buf[i] != '.') ds += buf[i];
  } else {
    mpfr_t v;
    if constexpr (is_runtime_precision_v<Real>) {
      mpfr_init2(v, mpfr_get_prec(x.backend().data()));
      mpfr_set(v, x.backend().data(), MPFR_RNDN);
    } else {
      // cpp_bin_float: converted exactly, at more bits than the type has.
      PrecisionScope scope(static_cast<unsigned>(std::numeric_limits<Real>::digits10 + 20));
      const mpfr copy(x);
      mpfr_init2(v, mpfr_get_prec(copy.backend().data()));
      mpfr_set(v, copy.backend().data(), MPFR_RNDN);
    }
    mpfr_exp_t e = 0;
    char* raw = mpfr_get_str(nullptr, &e, 10, static_cast<std::size_t>(digits), v, MPFR_RNDN);
    ds = raw;
    e10 = static_cast<long>(e);
    mpfr_free_str(raw);
    mpfr_clear(v);
  }
  std::string sign;
  if (ds[0] == '-') {
    sign = "-";
    ds.erase(0, 1);
  }
  const long exponent = e10 - 1;  // value = d.ddd × 10^exponent
  if (exponent < -5 || exponent >= 15) {
    std::string m = ds.substr(0, 1);
    if (ds.size() > 1) m += "." + ds.substr(1);
    char e[32];
    std::snprintf(e, sizeof e, "e%c%02ld", exponent < 0 ? '-' : '+', exponent < 0 ? -exponent : exponent);
    return sign + m + e;
  }
  std::string out;
  if (exponent < 0) {
    out = "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + ds;
  } else {
    const auto int_len = static_cast<std::size_t>(exponent + 1);
    if (ds.size() <= int_len)
      out = ds + std::string(int_len - ds.size(), '0');
    else
      out = ds.substr(0, int_len) + "." + ds.substr(int_len);
  }
  return sign + out;
}

// A result as the API hands it to the front ends: the value and the significant digits it is known
// to. The front ends print text(); a front end storing numbers takes `value`.
struct Significant {
  mpfr value;
  int digits = 1;
  std::string text() const {
    using std::isinf;
    using std::isnan;
    if (isnan(value)) return "nan";
    if (isinf(value)) return value > 0 ? "inf" : "-inf";
    return format_significant(value, digits);
  }
};

}  // namespace vibrofric
