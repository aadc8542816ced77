// The tool's computations that are more than one evaluation, for every front end (the tool, the
// Python module): `physical` from SI inputs (Eqs. 1, 5, 14; curved indenters by MDR, model.md)
// and `trace`, n(φ) and s(φ) over one period (Fig. 2).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/input_value.hpp"

namespace vibrofric {

// Outputs as (name, decimal text), in the tool's order: shape, E_star_Pa, G_star_Pa, k_z_N_per_m
// and k_x_N_per_m (flat) or contact_radius_max_m (curved), lambda (wearflat), beta, gamma,
// u_mean_m (given F-N), mu_over_mu0, mu, F_N_mean_N, F_x_mean_N, at the deepest instant
// F_N_peak_N, p_mean_peak_Pa and p_max_peak_Pa (Hertz on the sphere; "inf" where the elastic
// pressure is unbounded: the punch's rim, the cone's tip, a profile's kink), beta_c,
// contact_fraction (curved: the central spring's, while the body touches), stick_fraction (curved:
// the springs' stick shares averaged over the row out to the largest contact radius,
// curved_stick_integral / X of core/curved/curved_trace.hpp).
// Each a number with its significant digits (the request's; the rig's fractions and lengths those
// both precisions agree on), or a word (the shape, "inf", the Floquet multiplier's 6 digits).
struct PhysicalOutput {
  std::string name;
  Significant number;
  std::string word;  // not empty: the output is this text
  std::string text() const { return word.empty() ? number.text() : word; }
};
using PhysicalOutputs = std::vector<PhysicalOutput>;

// A text input (a shape, a unit) as typed (none: not given), and the name the caller knows it by,
// which every message about it uses (the tool's "--shape", Python's "shape"). Numbers are
// NamedInput (input_value.hpp): read where they enter.
struct InputText {
  std::optional<std::string> text;
  std::string name;
  bool given() const { return text.has_value(); }
};

// The inputs of `physical` in SI units: E1, nu1, E2, nu2, G1 and G2 (optional: by default
// E/(2(1+nu))), v0, f, A (zero-to-peak), u_mean or F_N (the mean normal load; γ then solves
// ⟨F_N⟩(γ) = F_N), mu0; shape (flat | sphere | cone | wearflat | profile:FILE, default flat) and
// its geometry: radius (flat), R (sphere, wearflat), half_angle (cone, degrees), flat_radius
// (wearflat). Each is named by its member's name until the caller renames it.
struct PhysicalRequest {
  NamedInput E1{{}, "E1"}, nu1{{}, "nu1"}, E2{{}, "E2"}, nu2{{}, "nu2"}, G1{{}, "G1"}, G2{{}, "G2"};
  NamedInput v0{{}, "v0"}, f{{}, "f"}, A{{}, "A"}, u_mean{{}, "u_mean"}, F_N{{}, "F_N"}, mu0{{}, "mu0"};
  InputText shape{{}, "shape"};
  NamedInput radius{{}, "radius"}, R{{}, "R"}, half_angle{{}, "half_angle"}, flat_radius{{}, "flat_radius"};
  // Instead of A, for a samples wave: the unit of its value column (m, mm, um, µm, nm); A is then
  // half the record's peak-to-peak, printed as A_m after the shape.
  InputText unit{{}, "unit"};
  // Rig dynamics (model.md), flat punch: the body's mass (kg), the apparatus' stiffness (N/m) and
  // an optional damper (N s/m); then κ = k_s/k_x, Ω = √(k_x/m)/(2πf), ζ = c/(2√(m k_s)) are printed
  // and μ is the rig's.
  NamedInput mass{{}, "mass"}, k_system{{}, "k_system"}, damping{{}, "damping"};
  // In-plane oscillation (model.md): zero-to-peak amplitudes along and across the sliding direction
  // (m, >= 0), the lag behind the normal oscillation (periods) and the in-plane wave (catalogue);
  // then a_l = k_x u_x/(mu0 k_z A) (the MDR row alike: G* u_x/(mu0 E* A)) and mu is the in-plane model's.
  NamedInput u_x{{}, "u_x"}, u_y{{}, "u_y"}, phase{{}, "phase"};
  InputText in_plane_wave{{}, "in_plane_wave"};
  // No normal oscillation (the tool's --wave constant): the normal load F_N is constant, the force
  // unit mu0 F_N, beta = k_x v0/(mu0 F_N f), a = k_x u/(mu0 F_N); the flat punch only.
  bool constant_normal = false;

  // Every input by its member's name, in this order: a number or a text (shape, unit).
  struct Member {
    const char* member;
    NamedInput* number;  // null for a text
    InputText* text;     // null for a number
    std::string& name() const { return number ? number->name : text->name; }
  };
  std::vector<Member> inputs();
};

// `physical` at one point (Eqs. 1, 5, 14; MDR for the curved shapes). `options` gives the solver
// controls and escalation (its profile is set from the shape). Where `warnings` is given, it
// receives one line per input outside any physical range (a modulus in GPa read as Pa, an
// amplitude in µm read as m, mu0 above 2) and where the contact radius exceeds 0.3 R (Hertz and
// the MDR take the sphere as a parabola, a ≪ R): the value is still computed, as the model defines it.
PhysicalOutputs physical_point(const WaveSpec& wave, const PhysicalRequest& request, const Precision& precision,
                               const BatchOptions& options = {}, std::vector<std::string>* warnings = nullptr);

// `physical`'s point over one period in SI units (README, "physical --trace"): the rows of
// trace_rows at its β and γ (points + 1 equally spaced phases, both ends of every stick phase,
// the contact boundaries), as the time t = φ/f, the normal and friction forces F_N = k n,
// F_x = μ0 k s (k = k_z A for the punch, 2 E* A L for a curved shape's row) and the indenter
// tip's indentation u = A (γ + w(φ)) (negative while the body is off the surface), each to
// `digits` significant digits. With a rig (mass, k_system), the rows of rig_trace_rows (the
// punch) or rig_row_trace_rows (a curved shape), F_x the contact's force on the body, and also
// the body's position x = v0 t + Y (the drive at v0 t; the apparatus' spring relaxed at x = v0 t)
// and the apparatus' force on it F_s = k_s (v0 t − x) + c (v0 − ẋ) (what a force sensor in the
// holder reads), each to the digits its inputs carry (a curved row's: those its two sizes agree
// on). InputError with an in-plane drive or a constant normal force.
struct PhysicalTraceRow {
  Significant t_s, F_N_N, F_x_N, u_m;
  std::optional<Significant> x_m, F_s_N;  // with a rig
};
std::vector<PhysicalTraceRow> physical_trace(const WaveSpec& wave, const PhysicalRequest& request, int points, int digits,
                                             const BatchOptions& options = {});

// The inputs of `trace`, each named in its caller's terms as in PhysicalRequest.
struct TraceRequest {
  NamedInput beta{{}, "beta"}, gamma{{}, "gamma"};
  int points = 1000;  // in [min_trace_points, max_trace_points]
  int digits = 17;    // in [min_digits, max_digits]
  std::string points_name = "points", digits_name = "digits";
  ProfileSpec profile;  // flat: the punch; else the MDR row's sums (core/curved/curved_trace.hpp)
};

// InputError unless β and γ are given as decimals and points and digits lie in their ranges.
void check_trace_request(const TraceRequest& request);

// Rows (φ, n, s) over one period, φ ascending: `points` + 1 equally spaced phases, both ends of
// every stick phase and the contact boundaries (where n = s = 0 exactly), `digits` significant
// digits each (at digits plus guard digits of working precision). A curved profile: n and s summed
// over the half-row (N(φ), S(φ) of curved_trace.hpp: ∫₀¹ n dφ / ∫₀¹ s dφ is the mu of `mu
// --profile`), at the equally spaced phases and the central spring's contact boundaries.
struct TraceRow {
  mpfr phi, n, s;  // each to request.digits significant digits: format_significant(x, digits)
};
std::vector<TraceRow> trace_rows(const WaveSpec& wave, const TraceRequest& request);

}  // namespace vibrofric
