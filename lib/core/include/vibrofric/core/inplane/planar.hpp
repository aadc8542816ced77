// In-plane and combined oscillation (model.md, "In-plane and combined oscillation"), the general
// two-dimensional drive D(φ) = (βφ + a_l p(φ + P), a_t p(φ + P)) with the normal force
// n(φ) = max(γ + w(φ), 0) (or n ≡ 1): the tangential force s ∈ R² is Moreau's sweeping process in
// the disc |s| ≤ n(φ):
//
//     stick    s' = D'                                   while |s| < n
//     slip     s = n e(θ),  n θ' = D'·e⊥                 while λ = D'·e − n' ≥ 0
//     flight   s = 0                                     where n = 0
//
// A jump of D moves s with it, and s is projected onto the disc, as at a downward jump of n.
// With a_t = 0 this is the longitudinal stop operator of inplane.hpp, which the tests use as a
// second algorithm.
//
// Method. Stick is exact (s = s0 + D − D0); its end, the first φ where |s|² − n² > 0 to rounding, is
// found by bisection with a mean-value enclosure whose derivative bound comes from the monotone
// pieces of p, p', n and n' (waveform.hpp's contract) on each segment of inplane_segments.
// Slip: the angle equation θ' = (|D'|/n) sin(ψ − θ) (ψ the angle of D') is integrated by the
// s-stage Radau IIA collocation method (order 2s − 1, s growing with the precision), its stage
// system solved by Newton's method, with step-doubling error control to a few ulps of the working
// precision. The method is L-stable: where |D'|/n is large (a large amplitude, or n → 0) θ relaxes
// onto ψ within a fraction of a step and the step follows ψ, not the relaxation. ∫ s_x and ∫ s_y
// are quadratures on the same stages (the method applied to them, order 2s − 1).
// Slip ends at the first φ where λ < 0 beyond its rounding: each step's range of λ is enclosed from
// the pieces' end values and the step's range of θ (|θ'| ≤ |D'|/n, or the hull of θ and ψ's
// range); where the enclosure does not exclude an end, the step is bisected and the crossing
// refined by toms748. Before contact is
// lost (n → 0 at a segment's end) slip is integrated to where ∫ n over the rest is below 2^-bits;
// the rest adds at most that to ∫ s. An event that cannot be separated, an integrator that does
// not converge or a state that is not reached is a SolverError.
//
// The periodic state is the fixed point of the one-period map (non-expansive: the sweeping
// process) from s = (n(0⁻), 0), by Broyden's quasi-Newton steps on F(s) − s with the plain
// iteration as fallback, until |F(s) − s| is below the integration's noise; a second start at −s
// must reach the same state. With β = 0 and a_l = 0 a state that slips has s_x = 0 (s_x' = −λ cos θ
// in slip): the longitudinal stop operator of s_y decides it, also where the map's fixed point is
// reached only algebraically. The solver has no error bound of its own: the API computes at two
// precisions.
//
// The engine is lib/core/src/inplane/planar_engine.hpp, compiled for double, long double and mpfr;
// curved contacts are rows of it (inplane_curved.hpp).
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/inplane/inplane.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

template <class Real>
struct PlanarDrive {
  Real longitudinal = 0;  // a_l = k_x u_x / force unit (≥ 0)
  Real transverse = 0;    // a_t = k_x u_y / force unit (≥ 0)
  Real phase = 0;         // P: the in-plane oscillation's lag behind the normal one, in periods
};

enum class PlanarMode { stick, slip, flight };

// One span of the periodic state in one mode on one segment; s = (sx, sy) at its begin.
template <class Real>
struct PlanarSpan {
  PlanarMode mode;
  Real begin, end;
  Real sx, sy;
  std::size_t segment;  // of InPlaneSegment's list (inplane_segments)
};

template <class Real>
struct PlanarResult {
  Real mu;             // μ̄/μ0 = ∫s_x / ∫n over the periodic state
  Real mean_lateral;   // ∫s_y / ∫n
  Real retained_area;  // ∫₀¹ s_x dφ
  Real lateral_area;   // ∫₀¹ s_y dφ
  Real normal_area;    // ∫₀¹ n dφ
  Real stick_fraction = 0, slip_fraction = 0, flight_fraction = 0;  // of the period
  std::array<Real, 2> state;  // s at φ = 0⁻
  std::size_t events = 0;     // mode changes and jumps per period
  std::size_t periods = 0;    // one-period maps evaluated to find and check the state
  std::size_t steps = 0;      // accepted integration steps in the recorded period
  int stages = 0;             // of the Radau IIA method
  std::vector<PlanarSpan<Real>> spans;
};

namespace detail {
template <class Real>
class PlanarEngine;
}  // namespace detail

// The two-dimensional drive of one normal wave (or none), β, γ, in-plane wave and drive.
// The waves must outlive the solver.
template <class Real>
class PlanarSolver {
 public:
  // normal == nullptr: n ≡ 1 and gamma is not used.
  PlanarSolver(const Waveform<Real>* normal, const Real& gamma, const Waveform<Real>& in_plane, const Real& beta,
               const PlanarDrive<Real>& drive, const Options& opt = {});
  ~PlanarSolver();
  PlanarSolver(PlanarSolver&&) noexcept;
  PlanarSolver& operator=(PlanarSolver&&) noexcept;

  // s at φ = 1⁻ from s at φ = 0⁻ (|s| ≤ n(0⁻)); the spans and areas of that period in `record`.
  std::array<Real, 2> period(const std::array<Real, 2>& s, PlanarResult<Real>* record = nullptr) const;
  // The periodic state: SolverError where it is not reached or the two starts disagree.
  PlanarResult<Real> solve() const;
  // n, s_x, s_y at φ in a recorded span.
  std::array<Real, 3> at(const PlanarSpan<Real>& span, const Real& phi) const;

 private:
  std::unique_ptr<detail::PlanarEngine<Real>> engine_;
};

// Checked inputs, then PlanarSolver::solve(); errors name the case.
template <class Real>
PlanarResult<Real> solve_planar(const Waveform<Real>* normal, const Real& gamma, const Waveform<Real>& in_plane,
                                const Real& beta, const PlanarDrive<Real>& drive, const Options& opt = {}) {
  using std::isfinite;
  if (!(beta >= 0) || !isfinite(beta))
    throw InputError("beta = " + detail::short_str(beta) + ": expected a finite number >= 0");
  if (!(drive.longitudinal >= 0) || !isfinite(drive.longitudinal))
    throw InputError("longitudinal amplitude = " + detail::short_str(drive.longitudinal) +
                     ": expected a finite number >= 0");
  if (!(drive.transverse >= 0) || !isfinite(drive.transverse))
    throw InputError("transverse amplitude = " + detail::short_str(drive.transverse) +
                     ": expected a finite number >= 0");
  if (!isfinite(drive.phase))
    throw InputError("phase = " + detail::short_str(drive.phase) + ": expected a finite number of periods");
  if (normal) detail::check_contact(*normal, gamma);
  const PlanarSolver<Real> solver(normal, gamma, in_plane, beta, drive, opt);
  return solver.solve();
}

extern template class PlanarSolver<double>;
extern template class PlanarSolver<long double>;
extern template class PlanarSolver<mpfr>;

}  // namespace vibrofric
