// Interval Newton for the certified enclosures (enclosure.cpp, curved_enclosure.cpp): the
// contraction of a box that holds one simple root, to the rounding floor of its bits.
#pragma once
#include <optional>
#include <string>

#include "vibrofric/core/certified/interval.hpp"

namespace vibrofric::certified {

// X within 2^ulps ulps of its larger end at `bits`.
inline bool within_ulps(const Interval& X, mpfr_prec_t bits, long ulps) {
  const mpfr w = X.width(), top = std::max(abs(X.lower()), abs(X.upper()));
  if (w == 0) return true;
  return mpfr_get_exp(w.backend().data()) <= mpfr_get_exp(top.backend().data()) - bits + ulps;
}

// X within 64 ulps: a Newton step could not halve it any more.
inline bool at_rounding_floor(const Interval& X, mpfr_prec_t bits) { return within_ulps(X, bits, 6); }

// Interval Newton on X, where f' excludes 0: X ∩ (m − f(m)/f'(X)) while it halves, or until X is
// at the rounding floor (a verified box's first step often lands there).
template <class F, class DF>
Interval newton(Interval X, F f, DF df, mpfr_prec_t bits, const std::string& what) {
  for (int k = 0; k < 200 && !at_rounding_floor(X, bits); ++k) {
    const Interval m = Interval::exact(X.midpoint(), bits);
    const Interval N = m - f(m) / df(X);
    std::optional<Interval> next = intersection(X, N);
    if (!next) throw SolverError(what + ": interval Newton lost the root (a bug)");
    const bool shrank = next->width() < X.width() / 2;
    X = *next;
    if (!shrank) break;
  }
  return X;
}

}  // namespace vibrofric::certified
