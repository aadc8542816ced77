// Rig dynamics at a requested precision (model.md, "Rig dynamics: mass and system stiffness"):
// μ̄/μ0 of the periodic state of a body of mass m on a system spring, with what a tribologist
// checks of it, from decimal inputs to decimal text. The core's RigSolver (core/dynamics/dynamics.hpp)
// computes in mpfr at two working precisions; the printed digits are those both agree on. On a
// curved contact (core/dynamics/rig_row.hpp) the row of springs is solved in double at two sizes,
// n and 2n, doubled until they agree to 8 digits (or n = 3200); the printed digits are those the
// two sizes agree on: the row's quadrature error, not the precision, limits them.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/input_value.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/dynamics/dynamics.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric {

struct Point;
struct Precision;
struct BatchOptions;

// The rig's dimensionless parameters: κ = k_s/k_x, Ω = √(k_x/m)/(2πf), ζ = c/(2√(m k_s)), each a
// decimal as typed or a value computed from a mass and stiffnesses (physical's: then no exact
// resonance is decided).
struct RigSpec {
  InputValue kappa, omega, zeta = InputValue(*Decimal::read("0"));
};

// One point's periodic state. Each number with the significant digits (at most the request's, and
// 17) on which the two working precisions agree; the front ends print them (Significant::text).
struct RigReport {
  std::string mu;  // μ̄/μ0, as evaluate() prints it
  Significant stick_fraction, slip_fraction, backward_fraction, flight_fraction;  // of the period
  Significant amplitude;              // (max − min)/2 of X − βφ, in units of μ0 k_z A/k_x
  Significant largest_backward_slip;  // of the contact point in one phase, same units
  Significant relative_error;         // estimate: the two precisions apart (2 digits)
  double floquet = 0;                 // largest modulus of the one-period map's multipliers
  int working_digits = 0;             // the higher of the two precisions
  // The paper's quasi-static μ̄/μ0 at the same point (evaluate()'s text), and, where the rig's
  // value differs from it by more than 10 %, a sentence naming the rig's nearest resonance: the
  // stick oscillator Ω√(1+κ) (body on both springs) or the slip oscillator Ω√κ (on k_s alone)
  // nearest a whole multiple of the drive's frequency. Empty otherwise.
  std::string quasi_static_mu;
  std::string resonance_note;
  // A curved contact: the significant digits of mu that the row's two sizes agree on (mu's text
  // has them), and the larger size. 0 on the flat punch (mu: the request's digits).
  int mu_digits = 0;
  std::size_t springs = 0;
};

// κ, Ω, ζ checked (finite decimals, κ > 0, Ω > 0, ζ ≥ 0): InputError quoting the text otherwise.
void check_rig(const RigSpec& rig);
// k with Ω²κ = k² exactly and ζ = 0 as typed (the undamped slip resonance of harmonic k; the
// solver's RigParameters::resonant_harmonic), else 0 (also for computed values).
unsigned exact_resonance(const RigSpec& rig);

// InputError for bad input, Ψ or a wave without a closed-form motion (power:p); SolverError where no periodic
// state is found, two are, or the precisions (the row's sizes) do not agree.
RigReport evaluate_rig(const WaveSpec& wave, const Point& point, const RigSpec& rig, const Precision& precision,
                       const Options& solver = {}, const ProfileSpec& profile = {});

// One row of the periodic state for `trace` (the rig's Fig. 2): φ, n, s, the body's lag
// Y = X − βφ behind the drive and its rate Y' (units μ0 k_z A/k_x, per period), and the mode.
const char* rig_mode_name(RigMode mode);  // the front ends' names: "stick", "slip", "backward", "flight"
struct RigTraceRow {
  mpfr phi, n, s, lag, lag_rate;  // each to the request's digits: format_significant(x, digits)
  RigMode mode;
};

// Rows over one period, φ ascending: `points` + 1 equally spaced phases and both ends of every
// span of one mode (where one span ends and the next begins, two rows at one φ: the left and the
// right values, which differ where s or n jumps),
// `digits` significant digits. The state is found at digits + 10 and, from it, at digits + 22
// (raised while their μ̄ differ in the printed digits); the rows are the higher's.
struct TraceRequest;
std::vector<RigTraceRow> rig_trace_rows(const WaveSpec& wave, const TraceRequest& request, const RigSpec& rig,
                                        const Options& solver = {});

// One row of a curved contact's rig trace (core/dynamics/rig_row.hpp, model.md "On a curved
// contact"): φ; n and s summed over the half-row (units of the row, as trace_rows' curved rows:
// mean(s)/mean(n) over the period is μ̄/μ0); the body's lag Y = X − βφ and its rate Y' (units
// μ0 E* A/G*, per period); the row's shares (weights) in stick, in slip (backward included), in
// backward slip and out of contact. n exactly (the profile's closed form: the normal motion is
// prescribed) to the request's digits; the others to the digits the row's two sizes agree on (at
// most the request's and 17; s and the shares fewer, by the midpoint rule's cell at a kink); φ at
// the request's digits plus guard digits (exact where the body lands and lifts off).
struct RigRowTraceRow {
  mpfr phi;
  Significant n, s, lag, lag_rate, stick, slip, backward, flight;
};

// Rows over one period, φ ascending: `points` + 1 equally spaced phases and where the body lands
// and lifts off (the central spring's contact boundaries: n = s = 0 there); at an event the
// value after it, at φ = 1 the period's end. InputError on the flat punch (rig_trace_rows).
std::vector<RigRowTraceRow> rig_row_trace_rows(const WaveSpec& wave, const TraceRequest& request, const RigSpec& rig,
                                               const Options& solver = {});

namespace detail {
// The value evaluate() prints for `precision` under options.rig: correctly rounded to the type (or
// to the digits for mpfr) wherever the two precisions' difference is a true bound of the error.
mpfr rig_value(const WaveSpec& wave, const Point& point, const RigSpec& rig, const Precision& precision,
               const Options& solver, RigReport* report = nullptr);
// The same on a curved contact (the row, rig_row.hpp): the value with the digits the row's two
// sizes agree on (at most the request's).
Significant row_rig_value(const WaveSpec& wave, const Point& point, const RigSpec& rig, const ProfileSpec& profile,
                          const Precision& precision, const Options& solver, RigReport* report = nullptr);
// The text evaluate() prints for that value: rounded to the type, its significant digits.
std::string rig_text(const mpfr& value, const Precision& precision);
// That value rounded to the type (held exactly) with the digits evaluate() prints; mpfr as it is.
Significant type_significant(const mpfr& value, const Precision& precision);
}  // namespace detail

}  // namespace vibrofric
