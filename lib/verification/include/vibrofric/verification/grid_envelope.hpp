// μ̄/μ0 = ∫s/∫n (paper Eqs. 9, 13, 15) from the steady-state characterisation of model.md,
//     s(φ) = min over 0 ≤ τ < 1 of [ n(φ − τ) + βτ ],   n = max(γ + w, 0),
// on a uniform grid, for ANY waveform, from point values w(φ) only: no waveform pieces, no events
// (Eqs. 4, 8), no root finding. It shares no code and no stick/slip classification with the event
// sweep (solver.hpp) or the exact rational envelope (envelope.hpp, piecewise-linear waves only),
// which makes it an independent cross-check of both.
//
// Method, N points, h = 1/N, g = γ + w:
//  - n is replaced by n_h = max(I_h g, 0), I_h the piecewise-linear interpolant of g through
//    g(ih). Its nodes are the grid points and the zero crossings of I_h g (closed form in the
//    cell). Clipping after interpolating puts the contact boundary within O(h²) of the true one;
//    interpolating the clipped values would misplace it by O(h) and make the stick level O(h).
//  - s_h, the exact envelope of n_h: n_h(ψ) − βψ is linear between nodes, so its minimum over the
//    window (φ_j − 1, φ_j] is at a node: a monotone-deque sliding-window minimum over the nodes of
//    two periods gives s_h(φ_j) for all j in O(N). Inside a cell s_h = min(n_h, ramp from the
//    cell start, ramp from a crossing in the cell), integrated exactly, as is n_h.
//
// Accuracy (continuous w). Let ε_I ≥ sup |I_h g − g| (≤ M₂h²/8 if |w''| ≤ M₂; ≤ (h/4)·max over
// cells of TV(w') in the cell for piecewise-linear w, hence 0 when every vertex is a grid point).
// Then |n_h − n| ≤ ε_I; the envelope is monotone in n and shifts with constants, so |s_h − s| ≤
// ε_I; hence |∫s_h − ∫s|, |∫n_h − ∫n| ≤ ε_I and
//     |μ_h − μ̄| ≤ (1 + μ̄)·ε_I / ∫n_h ≤ 2ε_I / ∫n_h          (grid_error_bound).
// This is second order for C² waves, and for piecewise-linear waves on a grid through their
// vertices exact to rounding. With a jump in w (square, sawtooth-left) the bound does not apply
// and the error is O(h): the stick level after an upward jump is read one node early.
//
// Measured (tests/unit/test_second_algorithm.cpp, error averaged over 8 grid positions, fitted
// over N = 2^8 … 2^14): order 2.0 for the sine and random Fourier series, with and without
// clipping; 1.0 for the square wave (jump) and the triangle with its vertex, a stick onset, off
// the grid; exact to rounding on a grid through the vertices of a piecewise-linear wave. The h²
// coefficient is not a constant: the stick level is off by ½|w''|δ², δ the distance from the
// onset (Eq. 4) to the nearest node, which jumps around in [0, h/2] as N doubles (for one grid
// position the order from N to 2N ranged from 0.7 to 4.8). There is no asymptotic expansion to
// extrapolate: Richardson (4μ_N − μ_{N/2})/3 halved the median error on 1,799 random Fourier
// cases but was more than 2× worse than μ_N in 11% of them, up to 341×, and has no bound; it
// is not offered. error_estimate = |μ_N − μ_{N/2}| is a guide, not a bound (the error exceeded
// it up to 65× there); grid_error_bound is the bound.
#pragma once
#include <cmath>
#include <cstddef>
#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

template <class Real>
struct GridEnvelope {
  Real mu;              // μ_h = ∫s_h / ∫n_h at N points
  Real retained_area;   // ∫₀¹ s_h
  Real normal_area;     // ∫₀¹ n_h
  Real lost_area;       // ∫₀¹ (n_h − s_h), summed directly (no cancellation for small β)
  Real coarse_mu;       // μ_h at N/2 points (every other sample: no new evaluations)
  Real error_estimate;  // |mu − coarse_mu|; a guide only, see the header
  // max_j |s_h(φ_j) from the window − s_h(φ_j) from the in-cell formula of cell j − 1|: the two
  // must agree to rounding (a self-check of the sliding window).
  Real recursion_mismatch;
  std::size_t points = 0;
  std::size_t evaluations = 0;  // w(φ) calls
  std::size_t crossings = 0;    // zero crossings of I_h g at N points (contact boundaries of n_h)
};

namespace detail {

template <class Real>
struct GridSample {
  Real retained_area = 0, normal_area = 0, lost = 0, mismatch = 0;
  std::size_t crossings = 0;
};

// ∫ over a subcell of length L of min(n, r) (retained), max(n − r, 0) (lost) and n, where n runs
// linearly from a to b and the ramp r from r0 with slope β.
template <class Real>
void integrate_subcell(const Real& L, const Real& a, const Real& b, const Real& r0, const Real& beta, GridSample<Real>& acc) {
  const Real r1 = r0 + beta * L;
  const Real d0 = a - r0, d1 = b - r1;  // n − r at the ends
  acc.normal_area += L * (a + b) / 2;
  if (d0 >= 0 && d1 >= 0) {  // stick throughout: s = r
    acc.retained_area += L * (r0 + r1) / 2;
    acc.lost += L * (d0 + d1) / 2;
  } else if (d0 <= 0 && d1 <= 0) {  // slip throughout: s = n
    acc.retained_area += L * (a + b) / 2;
  } else {  // one sign change of the linear n − r, at θL
    const Real theta = d0 / (d0 - d1);
    const Real xm = theta * L, ym = r0 + beta * xm;  // n = r = ym there
    if (d0 > 0) {
      acc.retained_area += xm * (r0 + ym) / 2 + (L - xm) * (ym + b) / 2;
      acc.lost += xm * d0 / 2;
    } else {
      acc.retained_area += xm * (a + ym) / 2 + (L - xm) * (ym + r1) / 2;
      acc.lost += (L - xm) * d1 / 2;
    }
  }
}

// The envelope of n_h for the samples g[0], g[stride], … (N = g.size()/stride points).
template <class Real>
GridSample<Real> grid_sample(const std::vector<Real>& g, std::size_t stride, const Real& beta) {
  const std::size_t n = g.size() / stride;
  const long N = static_cast<long>(n);
  auto gv = [&](long i) -> const Real& { return g[static_cast<std::size_t>(((i % N) + N) % N) * stride]; };
  auto clip = [](const Real& x) { return x > 0 ? x : Real(0); };
  // Crossing of I_h g in cell i (from node i to i + 1), as a fraction t ∈ (0, 1], or t < 0 if none.
  std::vector<Real> cross(n, Real(-1));
  GridSample<Real> acc;
  for (long i = 0; i < N; ++i) {
    const Real &a = gv(i), &b = gv(i + 1);
    if ((a > 0 && b < 0) || (a < 0 && b > 0)) {
      cross[static_cast<std::size_t>(i)] = a / (a - b);
      ++acc.crossings;
    }
  }
  // Window minimum of f = n_h(ψ) − βψ over nodes ψ = (k + t)/N with k ∈ [−N, N): entries keep
  // the node (k, t, n_h) and f; f increases from front to back.
  struct Node {
    long k;
    Real t, nv, f;
  };
  std::deque<Node> window;
  auto push = [&](long k, const Real& t, const Real& nv) {
    const Real f = nv - beta * ((k + t) / N);
    while (!window.empty() && window.back().f >= f) window.pop_back();
    window.push_back({k, t, nv, f});
  };
  auto push_crossing = [&](long k) {
    const Real& t = cross[static_cast<std::size_t>(((k % N) + N) % N)];
    if (t >= 0) push(k, t, Real(0));
  };
  for (long k = -N; k < 0; ++k) {
    push(k, Real(0), clip(gv(k)));
    push_crossing(k);
  }
  std::vector<Real> s(n + 1);
  for (long j = 0; j < N; ++j) {
    push(j, Real(0), clip(gv(j)));
    // Out of (j − N, j]: a grid node at k ≤ j − N, a crossing at k + t ≤ j − N, i.e. k < j − N.
    while (window.front().t == 0 ? window.front().k <= j - N : window.front().k < j - N) window.pop_front();
    const Node& m = window.front();
    s[static_cast<std::size_t>(j)] = m.nv + beta * ((Real(j - m.k) - m.t) / N);
    push_crossing(j);  // after s_j: it lies right of φ_j
  }
  s[n] = s[0];
  // Cells: s_h = min(n_h, ramp); at a crossing the ramp restarts from n_h = 0 if that is lower.
  const Real h = Real(1) / N;
  for (long j = 0; j < N; ++j) {
    const std::size_t jj = static_cast<std::size_t>(j);
    const Real n0 = clip(gv(j)), n1 = clip(gv(j + 1));
    Real r = s[jj];
    Real end;
    if (cross[jj] >= 0) {
      const Real L = cross[jj] * h;
      integrate_subcell(L, n0, Real(0), r, beta, acc);
      r = r + beta * L;
      if (r > 0) r = 0;  // n_h = 0 at the crossing
      integrate_subcell(Real(h - L), Real(0), n1, r, beta, acc);
      end = r + beta * (h - L);
    } else {
      integrate_subcell(h, n0, n1, r, beta, acc);
      end = r + beta * h;
    }
    if (end > n1) end = n1;
    using std::abs;
    const Real mis = abs(end - s[jj + 1]);
    if (mis > acc.mismatch) acc.mismatch = mis;
  }
  return acc;
}

}  // namespace detail

// μ_h for w given as a callable Real(const Real& φ), φ ∈ [0, 1), on N = points grid points
// (even, ≥ 4), with the N/2 value and their difference. Throws InputError for β ≤ 0, non-finite
// β or γ, or a bad N, and DomainError if n_h vanishes on the grid (no contact seen).
template <class Real, class W>
GridEnvelope<Real> grid_envelope(const W& w, const Real& beta, const Real& gamma, std::size_t points) {
  using std::abs;
  using std::isfinite;
  if (!(beta > 0) || !isfinite(beta))
    throw InputError("grid envelope: beta = " + detail::short_str(beta) + ": expected a finite number > 0");
  if (!isfinite(gamma)) throw InputError("grid envelope: gamma = " + detail::short_str(gamma) + ": expected a finite number");
  if (points < 4 || points % 2 != 0 || points > (std::size_t(1) << 40))
    throw InputError("grid envelope: " + std::to_string(points) + " points: expected an even number ≥ 4");
  std::vector<Real> g(points);
  for (std::size_t i = 0; i < points; ++i) g[i] = gamma + w(Real(i) / points);
  const detail::GridSample<Real> fine = detail::grid_sample(g, 1, beta);
  if (!(fine.normal_area > 0))
    throw DomainError("grid envelope: gamma = " + detail::short_str(gamma) + ": n vanishes at all " + std::to_string(points) +
                      " grid points (no contact)");
  const detail::GridSample<Real> coarse = detail::grid_sample(g, 2, beta);
  GridEnvelope<Real> r;
  r.mu = fine.retained_area / fine.normal_area;
  r.retained_area = fine.retained_area;
  r.normal_area = fine.normal_area;
  r.lost_area = fine.lost;
  r.coarse_mu = coarse.normal_area > 0 ? Real(coarse.retained_area / coarse.normal_area) : std::numeric_limits<Real>::quiet_NaN();
  r.error_estimate = coarse.normal_area > 0 ? Real(abs(r.mu - r.coarse_mu)) : std::numeric_limits<Real>::infinity();
  r.recursion_mismatch = fine.mismatch > coarse.mismatch ? fine.mismatch : coarse.mismatch;
  r.points = points;
  r.evaluations = points;
  r.crossings = fine.crossings;
  return r;
}

// The same for a Waveform (only its point values are used).
template <class Real>
GridEnvelope<Real> grid_envelope(const Waveform<Real>& w, const Real& beta, const Real& gamma, std::size_t points) {
  return grid_envelope<Real>([&w](const Real& phi) -> Real { return w(phi); }, beta, gamma, points);
}

// Bound on |μ_h − μ̄| for a continuous w (header): 2ε_I/∫n_h, where the caller supplies
// interpolation_error ≥ sup |I_h g − g| including the rounding of its w(φ) values, plus the
// rounding of the algorithm: two sums of 2N positive terms and O(1) operations per term, each
// relatively (2N + 16)·eps in the worst case, on μ ≤ 1.
template <class Real>
Real grid_error_bound(const GridEnvelope<Real>& r, const Real& interpolation_error) {
  const Real eps = std::numeric_limits<Real>::epsilon();
  return 2 * interpolation_error / r.normal_area + 2 * (2 * Real(r.points) + 16) * eps;
}

}  // namespace vibrofric
