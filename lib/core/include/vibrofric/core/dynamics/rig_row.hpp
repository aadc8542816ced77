// Rig dynamics on a curved contact (model.md, "Rig dynamics", the paragraph "On a curved contact"):
// the body carries the whole MDR row. Each spring at ξ has its own contact point and bound
// |s(ξ)| ≤ n(ξ, φ) = max(γ − σ(ξ) + w(φ), 0); the body feels the row's mean force ⟨s⟩:
//
//     Y'' + cY' + ω²κ Y = −ω²⟨s⟩,   Y = X − βφ,   c = 4πζΩ√κ,   ω = 2πΩ,
//     μ̄/μ0 = ∫⟨s⟩dφ / ∫⟨n⟩dφ,
//
// κ and Ω of the contact's largest tangential stiffness k_x,max (every spring touching at the peak).
// The row is a quadrature of the springs (mdr_row: the midpoint rule in the profile's variable, n
// nodes), solved as it stands: between events the stick springs add their stiffness W_s and the
// slipping ones ±n_j, so the body's equation is one linear ODE in closed form (motion.hpp).
// The events reduce to two functions of the body, H± = X ∓ w: a stick spring slips forward where H+
// reaches its threshold X_c + γ − σ, backward where H− reaches X_c − γ + σ; every forward slip ends
// together where H+' = 0 (X_c' = H+' for all), every backward one where H−' = 0; touch-down and
// contact loss are known phases of the wave. So a period costs O(n) events (O(n log n) work: the
// stick springs' thresholds kept in order, the sums kept by mode), each found by the
// rig's bracketing (a grid finer than the body's oscillation, strided by a slope bound) and toms748.
//
// The periodic state is taken at w's minimum. Where the contact opens fully there (γ + min w ≤ 0)
// every spring is out, the state is (Y, Y') alone: Newton on the one-period map from two starts.
// Else the springs still in contact carry their states through the section: Newton on (Y, Y') with
// the row's states held, the row carried on to the states the period ends in (each spring slips
// once a period and so follows the body), the multiplier from the full map's perturbation growth.
// The row's quadrature error (O(n⁻²)) is the caller's to estimate (the API doubles n).
#pragma once
#include <cstddef>
#include <vector>

#include "vibrofric/core/curved/profile.hpp"
#include "vibrofric/core/dynamics/dynamics.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

// One spring of the row: its σ (profile units of the amplitude) and its weight (the row's weights
// sum to 1: ⟨s⟩ = Σ weight·s).
template <class Real>
struct RowSpring {
  Real sigma, weight;
};

template <class Real>
struct RowRigResult {
  Real mu;                 // ∫⟨s⟩ / ∫⟨n⟩
  Real retained_area;      // ∫₀¹ ⟨s⟩ dφ
  Real normal_area;        // ∫₀¹ ⟨n⟩ dφ
  Real lag_integral;       // ∫₀¹ Y dφ (periodic state: ∫⟨s⟩ = −κ∫Y)
  // Of the period, weighted over the row (a spring's share is its weight):
  Real stick_fraction = 0, slip_fraction = 0, backward_fraction = 0, flight_fraction = 0;
  Real amplitude = 0;              // (max Y − min Y)/2, units μ0 k_z,max A/k_x,max
  Real largest_backward_slip = 0;  // of one spring's contact point in one backward phase
  Real state_y = 0, state_v = 0;   // Y, Y' at the section (w's minimum)
  Real section = 0;                // its phase
  Real relative_error = 0;         // the two starts apart, plus Newton's last step
  double floquet = 0;              // largest modulus of the one-period map's multipliers
  std::size_t newton_steps = 0, events = 0, springs = 0;
};

// The row of a profile for σ_max = γ + max w: a spring of weight flat_length/x_max at σ = 0 (the
// wear flat's), and n springs at the midpoints of n equal parts of the profile's variable t, split
// at its breaks, weight dx/dt·Δt/x_max (x_max = x_at_sigma(σ_max)).
template <class Real>
std::vector<RowSpring<Real>> mdr_row(const Profile<Real>& profile, const Real& sigma_max, std::size_t n);

// μ̄/μ0 and the periodic state. InputError for a wave without a closed-form motion; SolverError
// where no periodic state is found, or two are from two starts (the message names no point: the
// caller's to name as typed).
template <class Real>
RowRigResult<Real> solve_rig_row(const Waveform<Real>& w, const Real& beta, const Real& gamma,
                                 const RigParameters<Real>& p, const std::vector<RowSpring<Real>>& row,
                                 const Options& opt = {});

// The periodic state at a phase φ ∈ [0, 1]: the row's mean forces ⟨n⟩ and ⟨s⟩ (weights summing to
// 1), the body's lag Y = X − βφ and its rate Y', and the row's shares (weights) in stick, in slip
// (backward included), in backward slip and out of contact. At an event the value after it (the
// span that begins there); at φ = 1 the period's end. s_step: the largest change of a spring's s
// to its neighbour in the row (the quadrature's cells; where s has a kink or a jump across the
// row, the midpoint rule errs by up to a cell's weight times that).
template <class Real>
struct RowRigSample {
  Real phi, n, s, y, v, stick, slip, backward, flight;
  Real s_step = 0;
};

// As solve_rig_row, and the periodic state at each of `phases` (each in [0, 1], any order) into
// `samples`, in that order.
template <class Real>
RowRigResult<Real> solve_rig_row(const Waveform<Real>& w, const Real& beta, const Real& gamma,
                                 const RigParameters<Real>& p, const std::vector<RowSpring<Real>>& row,
                                 const Options& opt, const std::vector<Real>& phases,
                                 std::vector<RowRigSample<Real>>& samples);

extern template std::vector<RowSpring<double>> mdr_row(const Profile<double>&, const double&, std::size_t);
extern template RowRigResult<double> solve_rig_row(const Waveform<double>&, const double&, const double&,
                                                   const RigParameters<double>&, const std::vector<RowSpring<double>>&,
                                                   const Options&);
extern template RowRigResult<double> solve_rig_row(const Waveform<double>&, const double&, const double&,
                                                   const RigParameters<double>&, const std::vector<RowSpring<double>>&,
                                                   const Options&, const std::vector<double>&,
                                                   std::vector<RowRigSample<double>>&);

}  // namespace vibrofric
