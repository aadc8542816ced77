// Certified enclosures of μ̄/μ0 = g_w(β, γ) (Eq. 15) and Ψ_w(β) (Eq. 12) for the harmonic wave
// w = sin 2πφ at rational β and γ, in interval arithmetic (core/interval.hpp): every interval
// holds the exact value. n = max(γ + sin 2πφ, 0) has one maximum per period, so the steady state
// (model.md) has at most one stick phase, and its structure is decided by certain comparisons:
//  - no stick where β ≥ β_c(γ) (Eq. 6): 2π for γ ≥ 0, 2π√(1 − γ²) below; then μ̄ = 1 exactly;
//  - onset (Eq. 4) at first contact φ_c = asin(−γ)/2π, level 0, where n' = 2π√(1 − γ²) > β
//    there, else where n' falls to β, φ_1 = −acos(β/2π)/2π, level γ − √(1 − (β/2π)²);
//  - end (Eq. 8) at the root of F(φ) = n(φ) − level − β(φ − φ_1) on the falling flank: a bracket
//    with certain signs, then interval Newton once F' = 2π cos 2πφ − β < 0 certainly on it, so
//    the root exists and is unique for every value of the enclosed parameters;
//  - areas from the antiderivative γφ − cos(2πφ)/2π (Eqs. 9–12): ∫n = γ without jumping, else
//    γ(1/2 − 2φ_c) + cos(2πφ_c)/π; lost = ∫ over the stick phase of n minus the ramp.
// β against β_c and the onset's kind compare a rational with an irrational number, so more bits
// always decide them; at too few bits a comparison is Undecided (never a guess).
#pragma once
#include <optional>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/exact.hpp"
#include "vibrofric/core/interval.hpp"

namespace vibrofric::certified {

// A decision of the structure that the enclosures at this precision leave open: more bits decide.
class Undecided : public PrecisionError {
 public:
  using PrecisionError::PrecisionError;
};

struct SineEnclosure {
  explicit SineEnclosure(mpfr_prec_t bits)
      : mu(bits), retained_area(bits), normal_area(bits), lost_area(bits), beta_c(bits) {}
  Interval mu, retained_area, normal_area, lost_area;  // lost_area: Ψ at γ ≥ 1 (Eq. 12)
  Interval beta_c;                                     // Eq. 6
  bool stick = false;           // a stick phase exists (β < β_c); else μ̄ = 1 exactly
  bool jumping = false;         // γ < 1
  bool onset_at_contact = false;
  std::optional<Interval> onset, end, level;  // the stick phase: phases (end > onset) and s(onset)
};

// At `bits` per endpoint. InputError for β ≤ 0, DomainError for γ ≤ −1 (no contact), Undecided
// where this precision does not decide a comparison, SolverError if the end cannot be enclosed.
SineEnclosure enclose_sine(const exact::Rational& beta, const exact::Rational& gamma, mpfr_prec_t bits);

}  // namespace vibrofric::certified
