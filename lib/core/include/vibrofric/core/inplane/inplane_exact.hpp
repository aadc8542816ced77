// Exact longitudinal oscillation (model.md, "In-plane and combined oscillation"; inplane.hpp) for
// piecewise-linear normal and in-plane waves at rational β, γ, a_l and P, in GMP rationals: the
// certified rung of the longitudinal drive. Between the vertices of w, of p shifted by −P and the
// contact boundaries, n = max(γ + w, 0) (or n ≡ 1) and D = βφ + a_l p(φ + P) are linear, so a
// stick phase ends where a linear function (s ∓ n) reaches 0, a slip lasts to the segment's end
// (its rate D' ∓ n' is constant there), and every event, area and fraction is rational.
//
// The one-period map of the stop operator is F(s) = clamp(s + β, L, U): each stretch of the period
// shifts s or projects it, and shifts and projections compose to one of each. F(n(0⁻)) = U is
// therefore the periodic state for β > 0, and it is unique; at β = 0 every s in [L, U] is one,
// and the state is unique only where F(−n(0⁻)) = F(n(0⁻)). No code is shared with the engine
// (lib/core/src/inplane/inplane_engine.hpp), whose events are roots found in floating point.
#pragma once
#include <vector>

#include "vibrofric/core/exact.hpp"
#include "vibrofric/core/inplane/inplane.hpp"

namespace vibrofric::exact {

struct InPlaneSpan {
  InPlaneMode mode;
  Rational begin, end;
  Rational s0;  // s at begin (after a jump there)
};

struct InPlaneResult {
  Rational mu;             // μ̄/μ0 = ∫s / ∫n over the periodic state
  Rational retained_area;  // ∫₀¹ s dφ
  Rational normal_area;    // ∫₀¹ n dφ
  Rational stick_fraction, slip_fraction, backward_fraction, flight_fraction;  // backward ⊂ slip
  Rational state_s;        // s at φ = 0⁻
  std::vector<InPlaneSpan> spans;  // of positive length, φ ascending over [0, 1)
};

// normal == nullptr: a constant normal force n ≡ 1 (gamma unused). InputError for β < 0 or
// a_l < 0, DomainError where γ leaves no contact, SolverError where the periodic state is not
// unique (β = 0: the contact sticks through the period).
InPlaneResult solve_inplane(const Wave* normal, const Rational& gamma, const Wave& in_plane, const Rational& beta,
                            const Rational& longitudinal, const Rational& phase);

}  // namespace vibrofric::exact
