// A proven periodic state of the rig (model.md, "Rig dynamics: mass and system stiffness") on the
// flat punch, for the sine, Fourier series and piecewise-linear waves, in interval arithmetic
// (core/certified/interval.hpp).
//
// The one-period map is taken at a section φ0 inside a span of slip or flight, where s is not free
// (s = ±n or 0): a map of (Y, Y') alone, smooth near a state whose events are all transversal.
// It is evaluated on a box of states from the closed-form flows (the rig solver's, motion.hpp):
//  - each event (stick → slip where s = ±n, slip → stick where X_c' = 0) is one simple root of its
//    guard g, enclosed by interval Newton on a cell where g' excludes 0 and g changes sign with
//    certainty; before it, g < 0 on every cell of the span (mean-value enclosures, bisected);
//  - at a span's start the guard vanishes to a known order (slip → stick: g = g' = 0; touch-down
//    in stick: g = 0), and the first derivative that does not vanish is shown negative on a
//    neighbourhood, so the span does not end at once;
//  - contact loss and touch-down at the roots of γ + w (exact for a piecewise-linear wave, simple
//    roots enclosed for the smooth ones); at a vertex of a piecewise-linear wave the rules of
//    model.md (an upward jump ends slip, a downward jump below |s| projects s, a kink ends slip
//    where X' − n' changes sign; touch-down sticks if |X'| < n', else slips the way X' goes), each
//    decided with certainty;
//  - derivatives with respect to (Y, Y') are carried through by forward differentiation, event
//    times by the implicit function theorem (dT = −g_x/g_φ), so the map's Jacobian is enclosed on
//    the whole box.
// Existence and uniqueness of the fixed point in the box: the Krawczyk test K(X) ⊂ int X. The
// enclosures of μ̄/μ0, the fractions and the Jacobian (its multipliers: stability where both lie
// certainly inside the unit circle) are then evaluated on K(X). A decision that stays open (a
// guard grazing zero, an event at a contact boundary, a box that does not contract) is Undecided,
// naming the phase: more bits or no certificate, never a guess.
//
// Not covered: power:p (no closed-form motion); n touching zero without crossing (the sine at
// γ = 1).
#pragma once
#include <cstddef>
#include <vector>

#include "vibrofric/core/certified/enclosure.hpp"
#include "vibrofric/core/certified/interval.hpp"
#include "vibrofric/core/exact.hpp"

namespace vibrofric::certified {

// The contact's mode, as the rig solver's RigMode (core/dynamics/dynamics.hpp), which this module,
// on the foundation only, does not include.
enum class ContactMode { stick, forward_slip, backward_slip, flight };

// β, γ and the rig's κ, Ω, ζ, exactly (the decimals as typed).
struct RigPoint {
  exact::Rational beta, gamma, kappa, omega, zeta;
};

// Where the proof starts: an approximate periodic state (the solver's, at about the enclosure's
// precision) at the section φ0, which lies inside a span of forward or backward slip or flight.
struct RigSeed {
  mpfr section;
  ContactMode mode;
  mpfr y, v;  // Y = X − βφ and Y' at φ0
};

struct RigEnclosure {
  explicit RigEnclosure(mpfr_prec_t bits)
      : mu(bits), retained_area(bits), normal_area(bits), stick_fraction(bits), slip_fraction(bits),
        backward_fraction(bits), flight_fraction(bits), y(bits), v(bits), trace(bits), determinant(bits),
        multiplier(bits) {}
  Interval mu, retained_area, normal_area;  // μ̄/μ0 = ∫s/∫n
  Interval stick_fraction, slip_fraction, backward_fraction, flight_fraction;  // backward: part of slip
  Interval y, v;                 // the box holding the one periodic state at the section
  Interval trace, determinant;   // of the section map's Jacobian, on that box
  Interval multiplier;           // the largest modulus of its two multipliers
  bool stable = false;           // both certainly inside the unit circle
  std::size_t events = 0;        // stick–slip events a period
};

// The wave, exactly: the sine; a Fourier series as typed (normalised here as the solver's
// FourierSeries: mean dropped, divided by (max − min)/2, the extrema enclosed as simple roots of
// u'); a piecewise-linear wave's vertices (exact.hpp: the triangle, sawtooths, square, samples).
struct RigWaveInput {
  enum class Kind { sine, fourier, piecewise_linear } kind;
  exact::Wave piecewise;
  std::vector<RationalHarmonic> series;
};

// At the exact undamped resonance (ζ = 0, Ω²κ = k² with a harmonic k of the wave) the slip's
// response to that harmonic is the secular φ (P cos + Q sin), as the rig solver's. InputError for
// the sine at γ = 1; Undecided as above (also where n touches zero: a contact boundary that is not a
// simple root); SolverError where the seed's section is not in slip or flight, or its mode does
// not repeat after a period.
RigEnclosure enclose_rig(const RigWaveInput& wave, const RigPoint& p, const RigSeed& seed, mpfr_prec_t bits);
RigEnclosure enclose_rig_sine(const RigPoint& p, const RigSeed& seed, mpfr_prec_t bits);

}  // namespace vibrofric::certified
