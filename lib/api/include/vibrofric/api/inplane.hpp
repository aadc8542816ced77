// In-plane and combined oscillation at a requested precision (model.md, "In-plane and combined
// oscillation"): μ̄/μ0 of the longitudinal stop operator (core/inplane/inplane.hpp) or, with a
// transverse amplitude, of the two-dimensional sweeping process (core/inplane/planar.hpp), with the
// mode fractions, from decimal inputs to decimal text. Computed in mpfr at two working precisions; the
// printed digits are those both agree on. With a zero amplitude the value is the paper's model's,
// computed by its solver (evaluate.hpp), so that it prints exactly what `mu` prints.
#pragma once
#include <optional>
#include <string>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/input_value.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/inplane/inplane.hpp"

namespace vibrofric {

struct Point;
struct Precision;

// The in-plane drive as typed: a_l = k_x u_x / force unit (≥ 0), the phase P of the in-plane
// oscillation after the normal one (periods), the in-plane wave p (a catalogue wave), and whether
// the normal force is constant (n ≡ 1: the point's γ is then not given).
struct InPlaneSpec {
  InputValue longitudinal;
  InputValue transverse = InputValue(*Decimal::read("0"));  // a_t, across the sliding direction (≥ 0)
  InputValue phase = InputValue(*Decimal::read("0"));
  WaveSpec wave = parse_wave("sine");
  bool constant_normal = false;
};

// One point's periodic state; each number with the significant digits (at most the request's, and
// 17) on which the two working precisions agree.
struct InPlaneReport {
  std::string mu;  // μ̄/μ0 = ∫s_x/∫n
  Significant mean_lateral;  // ∫s_y/∫n
  Significant stick_fraction, slip_fraction, backward_fraction, flight_fraction;  // of the period
  bool planar = false;         // a transverse drive: slip has a direction, and backward_fraction is not defined
  bool curved = false;         // a curved contact (the MDR row): the fractions are the flat punch's only
  Significant relative_error;  // estimate: the two precisions apart (2 digits), relative to |μ̄|, or
                               // to 1 where μ̄ is 0 (|μ̄| ≤ 1: a symmetric drive at β = 0 gives 0)
  int working_digits = 0;      // the higher of the two precisions
  // Combined normal and longitudinal oscillation on the flat punch (asked for: with a transverse one
  // too, or on a curved contact), the contact lost once a period (γ + min w < 0, where the state at
  // β = 0 is unique): the ratchet's free velocity, the
  // β where μ̄(β) first changes sign from μ̄(0) < 0 (free_velocity_searched and none where μ̄(0) ≥ 0:
  // the oscillation does not propel the body).
  bool free_velocity_searched = false;
  std::optional<Significant> free_velocity;
};

// The drive checked: finite decimal amplitudes ≥ 0, a finite phase, a catalogue in-plane wave.
void check_inplane(const InPlaneSpec& spec);

// InputError for bad input (β < 0, an amplitude < 0, γ without contact or given with a constant
// normal force); SolverError where no unique periodic state exists (it sticks through the period)
// or the precisions do not agree.
// A curved profile integrates the row of in-plane springs (core/inplane/inplane_curved.hpp), with the
// normal oscillation only.
// free_velocity: search the free velocity of a transverse or curved drive too (InputError where the
// drive has none to search: no longitudinal oscillation, a constant normal force, a contact that
// never lifts, a curved transverse row).
InPlaneReport evaluate_inplane(const WaveSpec& normal, const Point& point, const InPlaneSpec& spec,
                               const Precision& precision, const Options& solver = {},
                               const ProfileSpec& profile = {}, bool free_velocity = false);

// One row of the periodic state for `trace`: φ, n, the tangential force's components s_x (along
// the sliding direction) and s_y (across it: 0 for a longitudinal drive), and the mode.
const char* inplane_mode_name(InPlaneMode mode);  // "stick", "slip", "backward", "flight"
struct InPlaneTraceRow {
  mpfr phi, n, s_x, s_y;  // each to the request's digits: format_significant(x, digits)
  InPlaneMode mode;
};

// Rows over one period, φ ascending: `points` + 1 equally spaced phases and both ends of every
// span of one mode (two rows at one φ where s or n jumps), `digits` significant digits. The state
// is found at digits + 10 and digits + 22 (raised while their μ̄ differ in the printed digits); the
// rows are the higher's. The request's gamma is not given for a constant normal force.
struct TraceRequest;
std::vector<InPlaneTraceRow> inplane_trace_rows(const WaveSpec& normal, const TraceRequest& request,
                                                const InPlaneSpec& spec, const Options& solver = {});

namespace detail {
// Whether the drive is the paper's model (no in-plane amplitude, the normal force oscillating):
// then the paper's solver gives the value (evaluate.hpp), exactly as without the drive.
bool papers_model(const InPlaneSpec& spec);
// The value evaluate() prints for `precision` with options.inplane (not the paper's model): the
// higher precision's μ̄, where the two precisions' difference decides the printed digits.
mpfr inplane_value(const WaveSpec& normal, const Point& point, const InPlaneSpec& spec, const Precision& precision,
                   const Options& solver, const ProfileSpec& profile = {}, InPlaneReport* report = nullptr);
}  // namespace detail

}  // namespace vibrofric
