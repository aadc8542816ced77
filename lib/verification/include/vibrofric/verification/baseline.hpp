// The naive baseline: time-stepping the spring of the paper's Fig. 1 (Sec. 2; Amontons, Eq. 3),
// as a user without the theory would write it, then μ̄/μ0 = ∫s/∫n over the last period (Eq. 15).
//
// State: the contact point x_c; in the units of model.md the tangential force is s = βφ − x_c.
// One step of h = 1/N: the spring end moves on, so s += βh (stick predictor; exact, the ramp is
// linear); if then s > n(φ) the contact slips and s = n (the massless spring relaxes at once).
// Start: s = 0 (spring relaxed, admissible as n ≥ 0) at the grid point where n is least; then
// whole periods until the period-to-period change of Σs is at rounding level. ∫s, ∫n by the
// rectangle rule (= trapezoid for periodic data).
//
// Accuracy, measured in tests/unit/test_second_algorithm.cpp: the steady state of this map is
// the envelope of n over grid points only, so a stick phase that starts at a kink of n lying
// between grid points (first contact in the jumping range, a jump, a vertex of a sampled wave
// off the grid) starts at a level off by O(h): first order. Where every stick onset is smooth
// (w' = β, Eq. 4) or on a grid point the level is off by O(h²), as is the rectangle rule across
// the kinks of s at stick ends: second order.
#pragma once
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

template <class Real>
struct BaselineResult {
  Real mu;             // μ̄/μ0 ≈ Σs/Σn over the last period
  Real retained_area;  // h·Σs
  Real normal_area;    // h·Σn
  std::size_t periods = 0;  // periods simulated, the last two agreeing
  std::size_t steps = 0;    // steps per period
};

struct BaselineOptions {
  std::size_t steps = 4096;  // N, steps per period
  // Periods allowed before non-convergence is an error; 0: 3 + ceil(max n / β), enough for the
  // ramp from s = 0 to meet n, one period to settle and one to confirm.
  std::size_t max_periods = 0;
};

// w is a callable Real(const Real& φ), φ ∈ [0, 1). Throws InputError for bad β, γ or N,
// DomainError if n vanishes at every step, SolverError if the periods do not settle.
template <class Real, class W>
BaselineResult<Real> simulate_spring(const W& w, const Real& beta, const Real& gamma, const BaselineOptions& opt = {}) {
  using std::abs;
  using std::ceil;
  using std::isfinite;
  if (!(beta > 0) || !isfinite(beta))
    throw InputError("baseline: beta = " + detail::short_str(beta) + ": expected a finite number > 0");
  if (!isfinite(gamma)) throw InputError("baseline: gamma = " + detail::short_str(gamma) + ": expected a finite number");
  if (opt.steps < 2) throw InputError("baseline: " + std::to_string(opt.steps) + " steps per period: expected at least 2");
  const std::size_t N = opt.steps;
  // n at the steps of one period (the same every period).
  std::vector<Real> n(N);
  std::size_t start = 0;
  Real n_max = 0;
  for (std::size_t k = 0; k < N; ++k) {
    const Real v = gamma + w(Real(k) / N);
    n[k] = v > 0 ? v : Real(0);
    if (n[k] < n[start]) start = k;
    if (n[k] > n_max) n_max = n[k];
  }
  if (!(n_max > 0)) throw DomainError("baseline: gamma = " + detail::short_str(gamma) + ": no contact at any step");
  std::size_t max_periods = opt.max_periods;
  if (max_periods == 0) max_periods = 3 + static_cast<std::size_t>(static_cast<double>(ceil(n_max / beta)));
  const Real step = beta / N;
  const Real eps = std::numeric_limits<Real>::epsilon();
  Real s = 0, previous = -1;
  for (std::size_t p = 1; p <= max_periods; ++p) {
    Real sum_s = 0, sum_n = 0;
    for (std::size_t m = 1; m <= N; ++m) {
      const Real& nk = n[(start + m) % N];
      s += step;
      if (s > nk) s = nk;
      sum_s += s;
      sum_n += nk;
    }
    // Once s has met n the map repeats itself exactly a period later; allow summation rounding.
    if (p >= 2 && abs(sum_s - previous) <= 4 * Real(N) * eps * sum_s) {
      BaselineResult<Real> r;
      r.mu = sum_s / sum_n;
      r.retained_area = sum_s / N;
      r.normal_area = sum_n / N;
      r.periods = p;
      r.steps = N;
      return r;
    }
    previous = sum_s;
  }
  throw SolverError("baseline: beta = " + detail::short_str(beta) + ", gamma = " + detail::short_str(gamma) + ": Σs still changing after " +
                    std::to_string(max_periods) + " periods");
}

template <class Real>
BaselineResult<Real> simulate_spring(const Waveform<Real>& w, const Real& beta, const Real& gamma, const BaselineOptions& opt = {}) {
  return simulate_spring<Real>([&w](const Real& phi) -> Real { return w(phi); }, beta, gamma, opt);
}

}  // namespace vibrofric
