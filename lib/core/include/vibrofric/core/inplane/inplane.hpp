// In-plane and combined oscillation (model.md, "In-plane and combined oscillation"), the
// longitudinal case: the drive moves along the sliding direction as D(φ) = βφ + a p(φ + P), the
// normal force is n(φ) = max(γ + w(φ), 0) (or n ≡ 1, a constant normal force), and the tangential
// force s = D − x_c is the stop operator of D in the moving interval [−n, n]:
//
//     stick            s' = D'                      while |s| < n
//     forward slip     s = n    while λ_f = D' − n' ≥ 0   (the contact point moves forward)
//     backward slip    s = −n   while λ_b = D' + n' ≤ 0
//     flight           s = 0    where n = 0
//
// A jump of D moves s with it; s is then projected onto [−n, n], as it is at a downward jump of n.
// With a = 0 this is the paper's model (s is the lower envelope of n under ramps of slope β).
//
// Events are found on segments where every part of the problem is one smooth branch: the pieces
// of w (split at the contact boundaries, flat/solver.hpp's Contact) and of p shifted by −P.
// There p and w are monotone with monotone slopes (the waves' contract, waveform.hpp), so the
// range of s − n, −n − s, λ_f and λ_b over any sub-interval is enclosed by its terms' end values;
// the first event is found by subdividing where the enclosure holds zero, down to the working
// precision, and refined by toms748 where the function is monotone. The areas are exact (the
// antiderivatives of w and p). The periodic state is the fixed point of the one-period map of s
// from the largest start s = n(0⁻); a second start just below it must reach the same state.
//
// This header is the module's contract; the engine is lib/core/src/inplane/inplane_engine.hpp,
// compiled for double, long double and mpfr (inplane_*.cpp). The transverse and general
// two-dimensional drive is planar.hpp; not here yet: curved contacts.
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

template <class Real>
struct InPlaneDrive {
  Real longitudinal = 0;  // a_l = k_x u_x / force unit (≥ 0)
  Real phase = 0;         // P: the in-plane oscillation's lag behind the normal one, in periods
};

enum class InPlaneMode { stick, forward_slip, backward_slip, flight };

// One span of the periodic state in one mode on one segment.
template <class Real>
struct InPlaneSpan {
  InPlaneMode mode;
  Real begin, end;
  Real s0;              // s at begin (after a jump there)
  std::size_t segment;  // of InPlaneSolver::segments()
};

template <class Real>
struct InPlaneResult {
  Real mu;             // μ̄/μ0 = ∫s / ∫n over the periodic state
  Real mean_lateral;   // ∫s_y / ∫n: 0 in the longitudinal case
  Real retained_area;  // ∫₀¹ s dφ
  Real normal_area;    // ∫₀¹ n dφ
  Real stick_fraction = 0, slip_fraction = 0, flight_fraction = 0;  // of the period
  Real backward_fraction = 0;  // the part of slip_fraction slipping backward
  Real state_s;        // s at φ = 0⁻ (before a jump there)
  std::size_t events = 0;   // mode changes and jumps per period
  std::size_t periods = 0;  // one-period maps evaluated to find and check the state
  std::vector<InPlaneSpan<Real>> spans;
};

// An elementary segment: one branch of n and one of p.
template <class Real>
struct InPlaneSegment {
  Real u, v;
  std::size_t contact_segment;  // of Contact::segments(), or npos for a constant normal force
  std::size_t piece;            // of p
  Real shift;                   // p's argument is φ + P − shift (P reduced to [0, 1))
  bool n_jump, p_jump;          // w (p) has a breakpoint at u where it may jump
};

namespace detail {
template <class Real>
class InPlaneEngine;
}  // namespace detail

// The longitudinal oscillation of one normal wave (or none), β, γ, in-plane wave and drive.
// The waves must outlive the solver.
template <class Real>
class InPlaneSolver {
 public:
  // normal == nullptr: n ≡ 1 and gamma is not used.
  InPlaneSolver(const Waveform<Real>* normal, const Real& gamma, const Waveform<Real>& in_plane, const Real& beta,
                const InPlaneDrive<Real>& drive, const Options& opt = {});
  ~InPlaneSolver();
  InPlaneSolver(InPlaneSolver&&) noexcept;
  InPlaneSolver& operator=(InPlaneSolver&&) noexcept;

  // s at φ = 1⁻ from s at φ = 0⁻ (|s| ≤ n(0⁻)); the spans and areas of that period in `record`.
  Real period(const Real& s, InPlaneResult<Real>* record = nullptr) const;
  // The periodic state: SolverError where the two starts do not reach one state.
  InPlaneResult<Real> solve() const;

  const std::vector<InPlaneSegment<Real>>& segments() const;
  // n, D and s at φ in a recorded span (s from the span's mode and s0).
  std::array<Real, 3> at(const InPlaneSpan<Real>& span, const Real& phi) const;

 private:
  std::unique_ptr<detail::InPlaneEngine<Real>> engine_;
};

// Checked inputs, then InPlaneSolver::solve(); errors name the case.
template <class Real>
InPlaneResult<Real> solve_inplane(const Waveform<Real>* normal, const Real& gamma, const Waveform<Real>& in_plane,
                                  const Real& beta, const InPlaneDrive<Real>& drive, const Options& opt = {}) {
  using std::isfinite;
  if (!(beta >= 0) || !isfinite(beta))
    throw InputError("beta = " + detail::short_str(beta) + ": expected a finite number >= 0");
  if (!(drive.longitudinal >= 0) || !isfinite(drive.longitudinal))
    throw InputError("longitudinal amplitude = " + detail::short_str(drive.longitudinal) +
                     ": expected a finite number >= 0");
  if (!isfinite(drive.phase))
    throw InputError("phase = " + detail::short_str(drive.phase) + ": expected a finite number of periods");
  if (normal) detail::check_contact(*normal, gamma);
  const InPlaneSolver<Real> solver(normal, gamma, in_plane, beta, drive, opt);
  return solver.solve();
}

extern template class InPlaneSolver<double>;
extern template class InPlaneSolver<long double>;
extern template class InPlaneSolver<mpfr>;

}  // namespace vibrofric
