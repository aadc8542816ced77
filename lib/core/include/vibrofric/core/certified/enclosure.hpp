// Certified enclosures of μ̄/μ0 = g_w(β, γ) (Eq. 15) and Ψ_w(β) (Eq. 12) at rational β and γ,
// in interval arithmetic (core/certified/interval.hpp), for the waves with the sine's symmetries: the
// harmonic wave sin 2πφ and power:p, p > 1 (model.md's catalogue). Both are odd on their rising
// flank r(t), t ∈ [−1/4, 1/4] (r' largest at 0, r concave for t > 0), with w(1/2 − φ) = w(φ)
// and w(φ + 1/2) = −w(φ). So n = max(γ + w, 0) has one maximum per period, the steady state
// (model.md) at most one stick phase, and its structure is decided by certain comparisons:
//  - no stick where β ≥ β_c(γ) (Eq. 6): r'(0) for γ ≥ 0, r'(t_c) below, t_c = r⁻¹(−γ) the first
//    contact; then μ̄ = 1 exactly;
//  - onset (Eq. 4) at first contact, level 0, where n' = r'(t_c) > β there, else where n' falls
//    to β on the convex side, t_1 = −top, r'(top) = β, level γ − r(top);
//  - end (Eq. 8) at the root of F(φ) = n(φ) − level − β(φ − t_1) on the falling flank, where
//    F' = w' − β < 0: a small box about a long double seed that interval Newton maps into itself
//    (so the root exists and is unique in it for every value of the enclosed parameters), or,
//    where no box verifies, a bracket with certain signs, bisected until Newton contracts;
//  - areas from the antiderivative R of r (Eqs. 9–12): ∫n = γ without jumping, else
//    γ(1/2 − 2t_c) + 2(R(1/4) − R(t_c)); lost = ∫ over the stick phase of n minus the ramp.
// Comparisons of a rational with an irrational number (β against β_c for the sine) are decided
// by more bits; at too few bits a comparison is Undecided (never a guess).
//
// A finite Fourier series u = Σ a_k cos 2πkφ + b_k sin 2πkφ (rational coefficients, normalised
// as the solver does: w = u/S, S = (max u − min u)/2, model.md's catalogue) has no such symmetry:
// n may have several maxima, so several stick phases. Its enclosure works with the whole
// structure of h = n − βφ, whose steady state s − βφ is the running minimum of h (model.md):
//  - every event of h on the circle is isolated with a certain sign change and a derivative that
//    excludes 0 (so it is one simple root): contact boundaries (γ + w = 0) and turning points in
//    contact (w' = β); between two events h is strictly monotone, its direction decided at one
//    point;
//  - each valley of h (decreasing, then increasing) starts a stick phase unless it lies inside an
//    earlier valley's; a stick ends at the first return of h to its valley's level, found by
//    walking the monotone pieces (each comparison certain) and enclosed in the one piece where it
//    lies (bracketed_root, as for the sine's stick end);
//  - S from the enclosed extrema of u (every root of u'), areas from the antiderivative.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/exact.hpp"
#include "vibrofric/core/certified/interval.hpp"

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

// One stick phase of an enclosure: onset < end (phases, onset in [o, o + 1) for the enclosure's
// cut o), the level s(onset), and whether it starts at first contact.
struct StickEnclosure {
  Interval onset, end, level;
  bool at_contact = false;
};

struct FourierEnclosure {
  explicit FourierEnclosure(mpfr_prec_t bits)
      : mu(bits), retained_area(bits), normal_area(bits), lost_area(bits), scale(bits), minimum(bits) {}
  Interval mu, retained_area, normal_area, lost_area;  // in the normalised wave's units, as the solver's
  Interval scale;                                      // S: w = u/S
  Interval minimum;                                    // min w (Ψ needs γ ≥ −min w)
  bool jumping = false;                                // n vanishes on an interval
  std::vector<StickEnclosure> sticks;                  // in order of onset; none: μ̄ = 1 exactly (Eq. 6)
};

// The series' harmonics: k ≥ 1 with a_k, b_k (k = 0, the mean, is removed by the normalisation).
struct RationalHarmonic {
  unsigned k;
  exact::Rational a, b;
};

// At `bits` per endpoint. InputError for β ≤ 0, DomainError for γ ≤ −1 (no contact), Undecided
// where this precision does not decide a comparison, SolverError if the end cannot be enclosed.
SineEnclosure enclose_sine(const exact::Rational& beta, const exact::Rational& gamma, mpfr_prec_t bits);
// power:p, p > 1 (InputError otherwise; power:1 is piecewise linear: exact.hpp).
SineEnclosure enclose_power(const exact::Rational& p, const exact::Rational& beta, const exact::Rational& gamma,
                            mpfr_prec_t bits);

// The part of a Fourier series' enclosure that depends on neither β nor γ, at `bits`: the series'
// extrema and its slope's, each enclosed as a simple root (Undecided where two do not separate).
// Computed once per series and precision; InputError for a series without a harmonic k ≥ 1.
class FourierShape {
 public:
  FourierShape(const std::vector<RationalHarmonic>& series, mpfr_prec_t bits);
  mpfr_prec_t bits() const;
  struct Data;

 private:
  std::shared_ptr<const Data> data_;
  friend FourierEnclosure enclose_fourier(const FourierShape&, const exact::Rational&, const exact::Rational&);
};

// A Fourier series (a k repeated adds up; k = 0 ignored). InputError for β ≤ 0 (or the shape's),
// DomainError where γ + w < 0 everywhere, Undecided as above (two events that do not separate; n
// touching zero at a maximum of w, γ = −max w). Where n touches zero at a minimum (γ = −min w,
// as for an odd series at γ = 1) no bits decide whether it vanishes there: the enclosure is
// widened by the undecided dip instead (jumping false), and narrows with the bits.
FourierEnclosure enclose_fourier(const std::vector<RationalHarmonic>& series, const exact::Rational& beta,
                                 const exact::Rational& gamma, mpfr_prec_t bits);
FourierEnclosure enclose_fourier(const FourierShape& shape, const exact::Rational& beta, const exact::Rational& gamma);

}  // namespace vibrofric::certified
