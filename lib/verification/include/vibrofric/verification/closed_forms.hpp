// The paper's closed forms, kept apart from the solver so that tests set one against the other:
// Eq. 13 (composition), Eq. 17 (Ψ of str, stl, tri), Eq. 19 (jumping str, stl, tri),
// Eqs. 20–22 (square wave, with Ψ_sqr from Eq. 36 of the paper's ref. [10]), Eqs. 23–24 (ξ remappings).
// Each is stated for β > 0; the sawtooth/triangle forms are continued by their no-stick value
// (Ψ = 0, μ̄ = μ0) for β ≥ β_c, per Eq. 6.
#pragma once
#include <cmath>

namespace vibrofric::closed_form {

// Eq. 17.
template <class Real> Real psi_sawtooth_right(const Real& beta) { return beta < 2 ? Real(1 - beta / 2) : Real(0); }
template <class Real> Real psi_sawtooth_left(const Real& beta) { return 2 / (2 + beta); }
template <class Real> Real psi_triangle(const Real& beta) { return beta < 4 ? Real((4 - beta) / (4 + beta)) : Real(0); }
// Ψ_sqr (ref. [10], Eq. 36): 1 − β/8 for β ≤ 4, 2/β after.
template <class Real> Real psi_square(const Real& beta) { return beta <= 4 ? Real(1 - beta / 8) : Real(2 / beta); }

// Eq. 13: μ̄/μ0 = 1 − αΨ = 1 − Ψ/γ without jumping (γ ≥ 1 for the catalogue).
template <class Real> Real mu_from_psi(const Real& psi, const Real& gamma) { return 1 - psi / gamma; }

// Eq. 19: jumping range −1 < γ < 1 (no γ dependence, by Eq. 18).
template <class Real> Real mu_sawtooth_right_jumping(const Real& beta) { return beta < 2 ? Real(beta / 2) : Real(1); }
template <class Real> Real mu_sawtooth_left_jumping(const Real& beta) { return beta / (2 + beta); }
template <class Real> Real mu_triangle_jumping(const Real& beta) { return beta < 4 ? Real(2 * beta / (4 + beta)) : Real(1); }

// Eq. 21: ξ_sqr(β, γ) = 2β/(1 + γ), the argument of Ψ_sqr in Eq. 20.
template <class Real> Real xi_square(const Real& beta, const Real& gamma) { return 2 * beta / (1 + gamma); }

// Eq. 22: square wave in the jumping range.
template <class Real> Real mu_square_jumping(const Real& beta, const Real& gamma) {
  return beta < 2 * (1 + gamma) ? Real(beta / (4 * (1 + gamma))) : Real(1 - (1 + gamma) / beta);
}

// Eq. 23: ξ_2(β, γ) = β √((1 + γ0)/(1 + γ)), harmonic wave, relative to γ0.
template <class Real> Real xi_harmonic(const Real& beta, const Real& gamma, const Real& gamma0) {
  using std::sqrt;
  return beta * sqrt((1 + gamma0) / (1 + gamma));
}

// Eq. 24 as printed: ξ_n(β, γ) = β ((1 + γ0)/(1 + γ))^(1/n) for a power-law cap of order n.
template <class Real> Real xi_power_as_printed(const Real& beta, const Real& gamma, const Real& gamma0, const Real& n) {
  using std::pow;
  return beta * pow((1 + gamma0) / (1 + gamma), 1 / n);
}

}  // namespace vibrofric::closed_form
