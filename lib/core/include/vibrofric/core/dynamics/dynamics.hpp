// Rig dynamics (model.md, "Rig dynamics: mass and system stiffness"): a body of mass m on a system
// spring k_s (damper c) pulled at v0, carrying the contact spring k_x whose massless contact point
// obeys Amontons. With Y = X − βφ (the body's lag behind the drive) every mode is one linear ODE
//
//     Y'' + c Y' + K Y = F(φ),   c = 4πζΩ√κ,   ω = 2πΩ,
//     stick:  K = ω²(κ + 1), F = −ω²(βφ − X_c)       (s = X − X_c)
//     slip:   K = ω²κ,       F = ∓ω² n(φ)            (s = ±n, forward / backward)
//     flight: K = ω²κ,       F = 0                   (s = 0)
//
// solved in closed form between events (the wave on each piece is a line plus harmonics: the sine,
// Fourier series and piecewise-linear waves). Events (stick → slip where |s| = n, slip → stick
// where X_c' passes zero, contact loss and touch-down at the contact boundaries) are bracketed on a
// grid finer than every oscillation of the piece and refined by toms748; jumps and kinks of n are
// segment ends where the sweeping-process rules of model.md are applied. The periodic steady state
// is found by shooting: Newton on the one-period map of (Y, Y', s), from two starts.
//
// This header is the module's contract: the parameters, the result and RigSolver's interface.
// The solver itself is private (lib/core/src/dynamics/rig_engine.hpp), compiled for double,
// long double and mpfr (lib/core/src/dynamics/rig_*.cpp).
//
// Not for: power:p and other waves without a closed-form motion. Curved contacts (the MDR row of
// springs shares one body, so the springs do not decouple): rig_row.hpp.
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

template <class Real>
struct RigParameters {
  Real kappa;  // κ = k_s/k_x
  Real omega;  // Ω = √(k_x/m)/(2πf)
  Real zeta = 0;  // ζ = c/(2√(m k_s))
  // Harmonic k with Ω²κ = k² exactly (decided by the caller from the inputs as typed), else 0:
  // slip then forces the undamped oscillator at its own frequency and the motion grows secularly.
  unsigned resonant_harmonic = 0;
};

enum class RigMode { stick, forward_slip, backward_slip, flight };

// One span of the periodic state with a single mode and a single closed form.
template <class Real>
struct RigSpan {
  RigMode mode;
  Real begin, end;
  Real y0, v0, s0;  // Y, Y', s at begin
  std::size_t segment;  // of the Contact: the piece of the wave and its contact status
};

template <class Real>
struct RigResult {
  Real mu;               // μ̄/μ0 = ∫s / ∫n
  Real retained_area;    // ∫₀¹ s dφ
  Real normal_area;      // ∫₀¹ n dφ
  Real stick_fraction = 0, slip_fraction = 0, flight_fraction = 0;  // of the period
  Real backward_fraction = 0;  // part of slip_fraction slipping backward
  Real amplitude;        // (max Y − min Y)/2: the body's oscillation about the drive, units μ0 k_z A/k_x
  Real largest_backward_slip = 0;  // largest distance the contact point moves back in one phase
  Real jump_dissipation = 0;  // ½(s₋² − s₊²) summed over the instant slips at jumps of n
  Real state_y, state_v, state_s;  // the periodic state at φ = 0 (before a jump there)
  Real relative_error;   // estimate: the two shooting starts' μ̄ apart, plus Newton's last step
  double floquet = 0;    // largest modulus of the one-period map's multipliers
  std::array<std::array<double, 3>, 3> jacobian{};  // of the one-period map of (Y, Y', s), near the state
  std::size_t newton_steps = 0;
  std::size_t events = 0;  // per period
  std::vector<RigSpan<Real>> spans;
};

// Y, Y' and s at the start of a period (the one-period map's argument).
template <class Real>
struct RigState {
  Real y, v, s;
};

namespace detail {
template <class Real>
class RigEngine;
}  // namespace detail

// The rig of one wave, β, γ and parameters: its one-period map, the periodic state and the closed
// forms of a recorded span. The wave must outlive the solver.
template <class Real>
class RigSolver {
 public:
  using State = RigState<Real>;

  RigSolver(const Waveform<Real>& w, const Real& beta, const Real& gamma, const RigParameters<Real>& p,
            const Options& opt = {});
  ~RigSolver();
  RigSolver(RigSolver&&) noexcept;
  RigSolver& operator=(RigSolver&&) noexcept;

  // The one-period map from the state at φ = 0⁻ (the end of the previous period).
  State period(const State& in, RigResult<Real>* record = nullptr) const;
  // Y, Y' and s at φ ∈ [span.begin, span.end] of a recorded span (the closed form it was solved with).
  std::array<Real, 3> at(const RigSpan<Real>& span, const Real& phi) const;
  // n and n' at φ in a recorded span.
  std::array<Real, 2> normal(const RigSpan<Real>& span, const Real& phi) const;
  // c and ω² of the body's equation (Y'' + cY' + … = −ω² s + …).
  const Real& damping() const;
  const Real& omega_squared() const;
  // The contact's segments (their ends: where n = 0 exactly at a contact boundary).
  const Contact<Real>& contact() const;

  // The periodic state by shooting from two starts (the quasi-static state and rest).
  RigResult<Real> solve() const;
  // The periodic state from one found at a lower precision (its state and the map's Jacobian).
  RigResult<Real> solve(const Real& y, const Real& v, const Real& s, const std::array<std::array<double, 3>, 3>& J) const;

 private:
  std::unique_ptr<detail::RigEngine<Real>> engine_;
};

// μ̄/μ0 and the periodic state of the rig (model.md, "Rig dynamics").
template <class Real>
RigResult<Real> solve_rig(const Waveform<Real>& w, const Real& beta, const Real& gamma, const RigParameters<Real>& p,
                          const Options& opt = {}) {
  detail::check_beta(w, beta);
  detail::check_contact(w, gamma);
  try {
    const RigSolver<Real> solver(w, beta, gamma, p, opt);
    return solver.solve();
  } catch (const SolverError& e) {
    throw SolverError(detail::context<Real>(w, beta, &gamma) + ": " + e.what());
  }
}

// The same from a state found at a lower precision (RigSolver::solve(y, v, s, J)).
template <class Real>
RigResult<Real> solve_rig(const Waveform<Real>& w, const Real& beta, const Real& gamma, const RigParameters<Real>& p,
                          const RigResult<Real>& seed, const Options& opt = {}) {
  detail::check_beta(w, beta);
  detail::check_contact(w, gamma);
  try {
    const RigSolver<Real> solver(w, beta, gamma, p, opt);
    return solver.solve(Real(seed.state_y), Real(seed.state_v), Real(seed.state_s), seed.jacobian);
  } catch (const SolverError& e) {
    throw SolverError(detail::context<Real>(w, beta, &gamma) + ": " + e.what());
  }
}

// Compiled for double, long double and mpfr (lib/core/src/dynamics/rig_*.cpp).
extern template class RigSolver<double>;
extern template class RigSolver<long double>;
extern template class RigSolver<mpfr>;

}  // namespace vibrofric
