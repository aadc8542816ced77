// Certified enclosures of μ̄/μ0 = g_w(β, γ) (Eq. 15) and Ψ_w(β) (Eq. 12) at rational β and γ,
// in interval arithmetic (core/interval.hpp), for the waves with the sine's symmetries: the
// harmonic wave sin 2πφ and power:p, p > 1 (model.md's catalogue). Both are odd on their rising
// flank r(t), t ∈ [−1/4, 1/4] (r' largest at 0, r concave for t > 0), with w(1/2 − φ) = w(φ)
// and w(φ + 1/2) = −w(φ). So n = max(γ + w, 0) has one maximum per period, the steady state
// (model.md) at most one stick phase, and its structure is decided by certain comparisons:
//  - no stick where β ≥ β_c(γ) (Eq. 6): r'(0) for γ ≥ 0, r'(t_c) below, t_c = r⁻¹(−γ) the first
//    contact; then μ̄ = 1 exactly;
//  - onset (Eq. 4) at first contact, level 0, where n' = r'(t_c) > β there, else where n' falls
//    to β on the convex side, t_1 = −top, r'(top) = β, level γ − r(top);
//  - end (Eq. 8) at the root of F(φ) = n(φ) − level − β(φ − t_1) on the falling flank: a bracket
//    with certain signs, then interval Newton once F' = w' − β < 0 certainly on it, so the root
//    exists and is unique for every value of the enclosed parameters;
//  - areas from the antiderivative R of r (Eqs. 9–12): ∫n = γ without jumping, else
//    γ(1/2 − 2t_c) + 2(R(1/4) − R(t_c)); lost = ∫ over the stick phase of n minus the ramp.
// Comparisons of a rational with an irrational number (β against β_c for the sine) are decided
// by more bits; at too few bits a comparison is Undecided (never a guess).
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
// power:p, p > 1 (InputError otherwise; power:1 is piecewise linear: exact.hpp).
SineEnclosure enclose_power(const exact::Rational& p, const exact::Rational& beta, const exact::Rational& gamma,
                            mpfr_prec_t bits);

}  // namespace vibrofric::certified
