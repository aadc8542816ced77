// Number types of vibrofric and their precision handling.
// mpfr is runtime precision: set it per thread with PrecisionScope before constructing values
// (Boost 1.81 keeps the default precision thread-local).
#pragma once
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

namespace vibrofric {

using mpfr = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>,
                                           boost::multiprecision::et_off>;
using bin50 = boost::multiprecision::cpp_bin_float_50;
using bin100 = boost::multiprecision::cpp_bin_float_100;

template <class Real>
inline constexpr bool is_runtime_precision_v = std::is_same_v<Real, mpfr>;

// Sets the calling thread's default mpfr precision (decimal digits) and restores it on exit.
class PrecisionScope {
 public:
  explicit PrecisionScope(unsigned digits10)
      : saved_(mpfr::thread_default_precision()) {
    mpfr::thread_default_precision(digits10);
  }
  ~PrecisionScope() { mpfr::thread_default_precision(saved_); }
  PrecisionScope(const PrecisionScope&) = delete;
  PrecisionScope& operator=(const PrecisionScope&) = delete;

 private:
  unsigned saved_;
};

// Decimal digits the working type carries now (the current thread precision for mpfr).
template <class Real>
int working_digits10() {
  if constexpr (is_runtime_precision_v<Real>)
    return static_cast<int>(mpfr::thread_default_precision());
  else
    return std::numeric_limits<Real>::digits10;
}

// Significant digits that round-trip the type: 17 for double, 21 for x87 long double.
template <class Real>
int round_trip_digits10() {
  if constexpr (is_runtime_precision_v<Real>)
    return working_digits10<Real>();
  else
    return std::numeric_limits<Real>::max_digits10;
}

// x with `digits` significant digits in positional notation ("0.0123…"), no trailing-zero
// trimming so the precision stays visible. Values outside [1e-5, 1e15) use scientific notation.
template <class Real>
std::string format_significant(const Real& x, int digits) {
  std::ostringstream os;
  os.precision(digits - 1);
  os << std::scientific << x;
  const std::string sci = os.str();
  const auto e = sci.find_first_of("eE");
  if (e == std::string::npos) return sci;  // inf/nan never reach here; kept for safety
  const int exponent = std::stoi(sci.substr(e + 1));
  if (x == 0 || exponent < -5 || exponent >= 15) return sci;
  std::string mantissa = sci.substr(0, e);
  std::string sign;
  if (mantissa[0] == '-') {
    sign = "-";
    mantissa.erase(0, 1);
  }
  std::string ds;
  for (char c : mantissa)
    if (c != '.') ds += c;
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

}  // namespace vibrofric
