// Certified enclosure of μ̄/μ0 on a curved indenter for the sine (model.md, "Curved contacts
// (MDR)"): μ̄/μ0 = ∫Φ(β, γ − σ(x)) dx / ∫N(γ − σ(x)) dx over the row, with Φ and N of the flat
// punch (Eqs. 9–15) at the spring's mean indentation γ' = γ − σ. For the sine, Φ(γ') is known on
// four ranges of γ', split where β = β_c(γ') (γ' = ±g, g = √(1 − (β/2π)²)) and at γ' = ±1:
//  - slip (−1 < γ' < −g): Φ = N = (√(1 − γ'²) + γ'(π/2 + asin γ'))/π;
//  - a stick phase from touch-down (−g < γ' < g): Φ = N − L with L the area between n and the
//    ramp; parametrised by the stick's length τ (in radians), the touch-down phase is in closed form,
//    θ = acos(b / sinc(τ/2)) − τ/2, b = β/2π, γ' = −sin θ (the stick's length → 0 at −g);
//  - a stick phase from n' = β (g < γ' < 1): Φ = N − Ψ(β), Ψ enclosed by enclosure.hpp;
//  - no jumping (γ' ≥ 1): Φ = γ' − Ψ(β), N = γ'.
// The x-integral becomes one over t = σ = γ − γ' with weight dx/dt: (1/n) t^(1/n − 1) for σ = x^n
// (power:N, sphere N = 2, cone N = 1), and the wear flat's (σ = λ x √(x² − 1) beyond x = 1, whose
// flat part adds Φ(γ) and N(γ)). Each range is integrated by Taylor models in intervals: on a piece,
// the integrand's Taylor coefficients at one end and an enclosure of its K-th over the piece (the
// Lagrange remainder), each term integrated exactly against the end's algebraic factor h^e. At
// γ' = ±1 the variable is u, γ' = ∓(1 − u²), which makes N analytic; at γ' = γ the weight's power
// t^(1/n − 1) is that factor. Pieces are bisected until the enclosure is as narrow as the bits
// allow; where it cannot be, or a comparison is left open, Undecided.
#pragma once
#include <cstddef>

#include "vibrofric/core/certified/enclosure.hpp"
#include "vibrofric/core/exact.hpp"

namespace vibrofric::certified {

// The profile: σ = x^N (N ≥ 1; the sphere N = 2, the cone N = 1) or the wear flat with
// σ = λ x √(x² − 1) for x ≥ 1, 0 before (x in units of the flat's radius; λ = b²/(R A)).
struct CurvedProfile {
  enum class Kind { power, wearflat } kind = Kind::power;
  exact::Rational parameter;  // N or λ
};

struct CurvedEnclosure {
  explicit CurvedEnclosure(mpfr_prec_t bits) : mu(bits), retained_area(bits), normal_area(bits) {}
  Interval mu;
  Interval retained_area, normal_area;  // ∫Φ dx and ∫N dx over x ≥ 0, x in the profile's units
  bool stick = false;                   // some spring sticks (β < 2π): else μ̄ = μ0 exactly
  std::size_t pieces = 0;               // the Taylor models summed
};

// At `bits`: InputError for β ≤ 0 or a profile parameter out of range (N < 1, λ ≤ 0), DomainError
// for γ ≤ −1 (no contact), Undecided where this precision does not decide.
CurvedEnclosure enclose_curved_sine(const CurvedProfile& profile, const exact::Rational& beta,
                                    const exact::Rational& gamma, mpfr_prec_t bits);

}  // namespace vibrofric::certified
