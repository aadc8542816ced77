// The naive second algorithm for curved contacts: a direct time-stepping simulation of the MDR
// row of springs (model.md, "Curved contacts (MDR)"), as a researcher without the event theory
// would write it. It exists as an independent check of solve_curved (curved.hpp), and is
// deliberately naive: no events, no breakpoints, no quadrature beyond the midpoint rule; it
// never calls solve() or solve_curved().
//
// The row: the half-row x ∈ [0, X], X = x(σ = γ + max w) the contact edge, in the profile's
// unit of length. The central flat part x ∈ [0, L], L = flat_length() (the wear flat; 0 for
// power laws), is one block of springs at σ = 0 with weight L. The curved part [L, X] is cut
// into M equal cells, one spring at each cell's midpoint x_i with weight Δx = (X − L)/M (the
// midpoint rule in x, the MDR measure E* dx). Spring i has the flat-punch normal force
// n_i(φ) = max(γ − σ(x_i) + w(φ), 0) (model.md, "Dimensionless dynamics").
//
// Each spring in time: the map of baseline.hpp's simulate_spring, with w tabulated once at the
// N steps φ_k = (k + phase)/N for the whole row. One step of h = 1/N: the spring end moves on,
// s += βh (stick predictor); if s > n_k the contact slips and s = n_k. Start at s = 0 at the
// step where n is least, then whole periods until two consecutive periods give the same Σs (to
// summation rounding); Φ_i = h Σ s, N_i = h Σ n over that period. Then
//   μ̄/μ0 = (L Φ_flat + Δx Σ Φ_i) / (L N_flat + Δx Σ N_i),
// and the two integrals are returned with the normalisation of CurvedResult (half-row, profile
// units, flat part included), with the time the row spends in stick (for the error bound).
//
// Accuracy, measured in tests/unit/test_spring_row.cpp against solve_curved at 30 digits.
// First order, with M = N refined together: observed order 0.99–1.05 over M = N = 64 … 1024
// (sphere, cone, wear flat, a measured profile; sine, triangle, square; jumping and non-jumping
// γ; error averaged over 8 grid offsets), 1.00–1.04 up to 4096. The time step sets it: every
// curved contact has outer springs that jump, whose stick starts at first contact or at an
// upward jump, between two steps; the steady state of the map is the envelope of n over the
// steps only, so that stick is anchored up to one step early (baseline.hpp): an O(h) lag of
// one sign, which does not average out over the row (μ_row ≥ μ in every case measured). The
// midpoint rule in x alone converges faster: order 2 (cone) to 2.6 (sphere, whose edge
// singularity is (X − x)^(3/2)), about 3/2 for the wear flat and measured profiles (σ has
// square-root onsets at x = L and at every sample radius where the slope changes). The error
// is about 0.5/N at β = 1; the bound derived in the test, whose largest measured use is 0.6 of
// it (150 random profiles, waves, β and γ):
//   |μ_row − μ| ≤ h (β + K_w) S / ∫N dx + h²   (K_w the largest |w'| at a kink or jump of w,
//   S = stick_integral; on a grid through the kinks of w).
#pragma once
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/curved/profile.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

template <class Real>
struct SpringRowResult {
  Real mu;                 // μ̄/μ0 = friction_integral / normal_integral
  Real friction_integral;  // ≈ ∫₀^X Φ_w(β, γ − σ(x)) dx, half-row, profile units, flat part included
  Real normal_integral;    // ≈ ∫₀^X N_w(γ − σ(x)) dx
  Real contact_radius;     // X
  Real stick_integral;     // ∫₀^X (fraction of the steady period's steps in stick, s < n) dx
  std::size_t periods = 0;  // the most periods any spring of the row needed
  std::size_t steps = 0;    // N, steps per period
  std::size_t springs = 0;  // M, springs on the curved part (the flat block comes on top)
  // With SpringRowOptions::trace: the row's sums of n and s at each step φ_k of the steady period
  // (as friction_integral: half-row, flat part included), k = 0 … N − 1.
  std::vector<Real> trace_n, trace_s;
};

struct SpringRowOptions {
  std::size_t springs = 256;  // M, springs over the curved part [L, X] of the half-row
  std::size_t steps = 1024;   // N, time steps per period
  // Periods allowed per spring before non-convergence is an error; 0: 3 + ceil(n_max/β), the
  // ramp from s = 0 meeting n, one period to settle and one to confirm (as baseline.hpp).
  std::size_t max_periods = 0;
  // Offset of the time grid, in steps: φ_k = (k + phase)/N, 0 ≤ phase < 1. μ̄ does not depend
  // on a phase shift of w (model.md), the O(h) errors do: averaging over offsets measures orders.
  double phase = 0;
  bool trace = false;  // also sum n and s over the row at every step (SpringRowResult::trace_n, trace_s)
};

namespace detail {

template <class Real>
struct RowSpring {
  Real retained_area, normal_area;  // h Σ s and h Σ n over the steady period (Φ_i, N_i)
  Real stick;                       // fraction of that period's steps with s < n
  std::size_t periods = 0;
  std::vector<Real> s;  // s at step k of the steady period (where asked for)
};

// One spring of the row at shifted mean indentation γ' = γ − σ(x): w_table[k] = w(φ_k).
// No contact at any step gives zeros.
template <class Real>
RowSpring<Real> step_row_spring(const std::vector<Real>& w_table, const Real& beta, const Real& gamma_shifted,
                                std::size_t max_periods, bool trace = false) {
  using std::abs;
  using std::ceil;
  const std::size_t N = w_table.size();
  std::vector<Real> n(N);
  std::size_t start = 0;
  Real n_max = 0;
  for (std::size_t k = 0; k < N; ++k) {
    const Real v = gamma_shifted + w_table[k];
    n[k] = v > 0 ? v : Real(0);
    if (n[k] < n[start]) start = k;
    if (n[k] > n_max) n_max = n[k];
  }
  RowSpring<Real> out{Real(0), Real(0), Real(0), 0, {}};
  if (trace) out.s.assign(N, Real(0));
  if (!(n_max > 0)) return out;
  if (max_periods == 0) max_periods = 3 + static_cast<std::size_t>(static_cast<double>(ceil(n_max / beta)));
  const Real step = beta / N;
  const Real eps = std::numeric_limits<Real>::epsilon();
  Real s = 0, previous = -1;
  for (std::size_t p = 1; p <= max_periods; ++p) {
    Real sum_s = 0, sum_n = 0;
    std::size_t sticking = 0;
    for (std::size_t m = 1; m <= N; ++m) {
      const Real& nk = n[(start + m) % N];
      s += step;
      if (s > nk) s = nk;
      else if (s < nk) ++sticking;
      if (trace) out.s[(start + m) % N] = s;
      sum_s += s;
      sum_n += nk;
    }
    if (p >= 2 && abs(sum_s - previous) <= 4 * Real(N) * eps * sum_s) {
      out.retained_area = sum_s / N;
      out.normal_area = sum_n / N;
      out.stick = Real(sticking) / N;
      out.periods = p;
      return out;
    }
    previous = sum_s;
  }
  throw SolverError("spring row: beta = " + short_str(beta) + ", gamma' = " + short_str(gamma_shifted) +
                    ": Σs still changing after " + std::to_string(max_periods) + " periods");
}

// w at the steps φ_k = (k + phase)/N of one period.
template <class Real>
std::vector<Real> tabulate(const Waveform<Real>& w, std::size_t N, double phase) {
  std::vector<Real> t(N);
  for (std::size_t k = 0; k < N; ++k) t[k] = w(Real(Real(k) + Real(phase)) / N);
  return t;
}

}  // namespace detail

// μ̄/μ0 of a curved contact by direct simulation of the spring row (see above). Throws
// InputError for β ≤ 0, non-finite β or γ, 0 springs or fewer than 2 steps; DomainError if
// γ + max w ≤ 0 (no contact), no step sees contact, or the contact reaches beyond a measured
// profile's last sample; SolverError if a spring does not settle.
template <class Real>
SpringRowResult<Real> simulate_spring_row(const Waveform<Real>& w, const Profile<Real>& p, const Real& beta, const Real& gamma,
                                          SpringRowOptions opt = {}) {
  using detail::short_str;
  using std::isfinite;
  if (!(beta > 0) || !isfinite(beta)) throw InputError("spring row: beta = " + short_str(beta) + ": expected a finite number > 0");
  if (!isfinite(gamma)) throw InputError("spring row: gamma = " + short_str(gamma) + ": expected a finite number");
  if (opt.springs < 1) throw InputError("spring row: 0 springs: expected at least 1");
  if (opt.steps < 2) throw InputError("spring row: " + std::to_string(opt.steps) + " steps per period: expected at least 2");
  if (!(opt.phase >= 0 && opt.phase < 1))
    throw InputError("spring row: phase = " + short_str(opt.phase) + " steps: expected 0 <= phase < 1");
  const Real sigma_max = gamma + w.maximum();
  if (!(sigma_max > 0))
    throw DomainError("spring row: gamma = " + short_str(gamma) + " gives no contact for wave " + w.name());
  if (sigma_max > p.sigma_limit())
    throw DomainError("spring row: gamma = " + short_str(gamma) + " for profile " + p.name() +
                      ": the contact reaches beyond its last sample");

  const std::vector<Real> table = detail::tabulate(w, opt.steps, opt.phase);
  const Real L = p.flat_length(), X = p.x_at_sigma(sigma_max);
  const Real dx = (X - L) / opt.springs;
  SpringRowResult<Real> r;
  r.contact_radius = X;
  r.steps = opt.steps;
  r.springs = opt.springs;
  Real F = 0, N = 0, S = 0;
  if (opt.trace) {
    r.trace_n.assign(opt.steps, Real(0));
    r.trace_s.assign(opt.steps, Real(0));
  }
  // A spring of weight `weight` at γ', into the row's trace.
  auto add_trace = [&](const detail::RowSpring<Real>& c, const Real& gamma_shifted, const Real& weight) {
    if (!opt.trace) return;
    for (std::size_t k = 0; k < opt.steps; ++k) {
      const Real n = gamma_shifted + table[k];
      if (n > 0) r.trace_n[k] += weight * n;
      r.trace_s[k] += weight * c.s[k];
    }
  };
  if (L > 0) {
    const detail::RowSpring<Real> c = detail::step_row_spring(table, beta, gamma, opt.max_periods, opt.trace);
    F += L * c.retained_area;
    N += L * c.normal_area;
    S += L * c.stick;
    r.periods = c.periods;
    add_trace(c, gamma, L);
  }
  Real cf = 0, cn = 0, cs = 0;
  for (std::size_t i = 0; i < opt.springs; ++i) {
    const Real x = L + (Real(i) + Real(0.5)) * dx;
    const Real g = gamma - p.sigma_at_x(x);
    const detail::RowSpring<Real> c = detail::step_row_spring(table, beta, g, opt.max_periods, opt.trace);
    cf += c.retained_area;
    cn += c.normal_area;
    cs += c.stick;
    if (c.periods > r.periods) r.periods = c.periods;
    add_trace(c, g, dx);
  }
  F += dx * cf;
  N += dx * cn;
  S += dx * cs;
  r.stick_integral = S;
  r.friction_integral = F;
  r.normal_integral = N;
  if (!(N > 0))  // contact so slight that no step sees it (as baseline.hpp)
    throw DomainError("spring row: gamma = " + short_str(gamma) + ": no spring in contact at any of the " +
                      std::to_string(opt.steps) + " steps");
  r.mu = F / N;
  return r;
}

}  // namespace vibrofric
