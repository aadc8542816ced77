// Tests' helpers for interval enclosures (core/certified/): whether a reference value lies in an
// enclosure, and an enclosure's width in units of its precision.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>

#include "vibrofric/core/certified/interval.hpp"
#include "vibrofric/core/exact.hpp"

namespace vibrofric::testing {

inline mpfr to_mpfr(const exact::Rational& x) {
  mpfr r;
  mpfr_set_q(r.backend().data(), x.backend().data(), MPFR_RNDN);
  return r;
}

// x lies in the enclosure widened by the reference's own error.
inline ::testing::AssertionResult holds(const Interval& e, const mpfr& x, const mpfr& slack) {
  // At 400 bits, directed: the enclosure's ends carry fewer bits, and Boost's mpfr arithmetic
  // would round the slack away at the first operand's precision.
  mpfr_t lo, hi;
  mpfr_inits2(400, lo, hi, static_cast<mpfr_ptr>(nullptr));
  mpfr_sub(lo, e.lower().backend().data(), slack.backend().data(), MPFR_RNDD);
  mpfr_add(hi, e.upper().backend().data(), slack.backend().data(), MPFR_RNDU);
  const bool inside = mpfr_cmp(lo, x.backend().data()) <= 0 && mpfr_cmp(x.backend().data(), hi) <= 0;
  mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
  if (inside) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << x.str(100) << " outside [" << e.lower().str(70) << ", " << e.upper().str(70) << "]";
}

// Width in units of 2^−bits, relative to max(1, |value|): the areas are differences of O(1)
// antiderivative values, so a small μ̄ or Ψ (β → 0) has a small absolute, not relative, width
// (the decision of a rounding then takes more bits, as in the solver's ladder).
inline double width_in_ulps(const Interval& e, mpfr_prec_t bits) {
  const mpfr scale = std::max(mpfr(1), std::max(abs(e.lower()), abs(e.upper())));
  return static_cast<double>(e.width() / scale * pow(mpfr(2), static_cast<long>(bits)));
}

}  // namespace vibrofric::testing
