// Number types of vibrofric and their precision handling: the working precision in which every
// equation of the paper (Eqs. 3–24) is solved and "holds exactly (to working precision)" is decided
// (model.md, "The paper's claims that the suite verifies").
// mpfr is runtime precision: set it per thread with PrecisionScope before constructing values
// (Boost 1.81 keeps the default precision thread-local).
#pragma once
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
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

namespace detail {
// x rounded once to nearest in Real (to `mpfr_digits10` decimal digits of precision when Real is
// mpfr, by default the current precision's). cpp_bin_float is rounded to its bits in MPFR first:
// Boost 1.81's conversion from mpfr missed the nearest cpp_bin_float_50 in 3,606 of 20,000 values
// within 1e-110 of a midpoint.
template <class Real>
Real rounded(const mpfr& x, unsigned mpfr_digits10 = static_cast<unsigned>(working_digits10<mpfr>())) {
  if constexpr (std::is_same_v<Real, double>) {
    return mpfr_get_d(x.backend().data(), MPFR_RNDN);
  } else if constexpr (std::is_same_v<Real, long double>) {
    return mpfr_get_ld(x.backend().data(), MPFR_RNDN);
  } else if constexpr (is_runtime_precision_v<Real>) {
    Real r;
    r.precision(mpfr_digits10);
    mpfr_set(r.backend().data(), x.backend().data(), MPFR_RNDN);
    return r;
  } else {
    mpfr t;
    mpfr_set_prec(t.backend().data(), std::numeric_limits<Real>::digits);
    mpfr_set(t.backend().data(), x.backend().data(), MPFR_RNDN);
    return static_cast<Real>(t);  // exact: t has Real's bits
  }
}

// In-place arithmetic for hot paths, where each mpfr temporary is an allocation: the same
// correctly rounded operations as the expressions they replace, so every result is bitwise
// unchanged where the operands are at the working precision (values made after PrecisionScope, as
// numbers.hpp asks). An operand made at more digits makes them round at its precision, as
// compound assignment does; Boost's operators on a temporary round at the temporary's.
// The rewritten expressions rely on et_off: with expression templates Boost may reorder them.
static_assert(std::is_same_v<bin50, boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>,
                                                                 boost::multiprecision::et_off>> &&
              std::is_same_v<bin100, boost::multiprecision::number<boost::multiprecision::cpp_bin_float<100>,
                                                                  boost::multiprecision::et_off>>);
// x += |y| for x not −0 (a sum of magnitudes): x − y for negative y is the same exact sum.
template <class Real>
void add_abs(Real& x, const Real& y) {
  if constexpr (std::is_floating_point_v<Real>) {
    using std::abs;
    x += abs(y);
  } else if (y < 0) {
    x -= y;
  } else {
    x += y;
  }
}
// x = −x.
template <class Real>
void negate(Real& x) {
  if constexpr (std::is_floating_point_v<Real>)
    x = -x;
  else
    x.backend().negate();
}
// x = a − b (x may be a or b). In place where x already has the precision the expression's
// result would have (Boost's: the largest of the thread's default and the operands' digits).
template <class Real>
void difference(Real& x, const Real& a, const Real& b) {
  if constexpr (is_runtime_precision_v<Real>) {
    const unsigned digits = std::max({Real::thread_default_precision(), a.precision(), b.precision()});
    if (mpfr_get_prec(x.backend().data()) == static_cast<mpfr_prec_t>(boost::multiprecision::detail::digits10_2_2(digits))) {
      mpfr_sub(x.backend().data(), a.backend().data(), b.backend().data(), MPFR_RNDN);
      return;
    }
  }
  x = a - b;
}
// x = (a + b) / 2 (x neither a nor b).
template <class Real>
void midpoint(Real& x, const Real& a, const Real& b) {
  x = a;
  x += b;
  x /= 2;
}
// floor(x) as a long (x within its range; NaN throws, as Boost's conversion does).
template <class Real>
long floor_to_long(const Real& x) {
  if constexpr (is_runtime_precision_v<Real>) {
    if (mpfr_nan_p(x.backend().data())) throw std::runtime_error("Could not convert NaN to integer.");
    return mpfr_get_si(x.backend().data(), MPFR_RNDD);
  } else {
    using std::floor;
    return static_cast<long>(floor(x));
  }
}
// |a| ≤ b.
template <class Real>
bool abs_le(const Real& a, const Real& b) {
  if constexpr (is_runtime_precision_v<Real>) {
    const mpfr_srcptr x = a.backend().data(), y = b.backend().data();
    return !mpfr_nan_p(x) && !mpfr_nan_p(y) && mpfr_sgn(y) >= 0 && mpfr_cmpabs(x, y) <= 0;
  } else {
    using std::abs;
    return abs(a) <= b;
  }
}
}  // namespace detail

}  // namespace vibrofric
