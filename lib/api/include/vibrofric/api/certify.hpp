// Certified values (README, "Precision"): μ̄/μ0 (Eq. 15) and Ψ_w(β) (Eq. 12) of the
// piecewise-linear waves as exact rationals (core/exact.hpp), of the sine, power:P and Fourier
// series as interval enclosures (core/certified/enclosure.hpp) narrowed until they decide the rounding, and
// the proof that a value evaluate() printed is their correct rounding in the number type or to
// the digits asked for.
#pragma once
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/inplane.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/certified/curved_enclosure.hpp"
#include "vibrofric/core/certified/enclosure.hpp"
#include "vibrofric/core/certified/rig_enclosure.hpp"
#include "vibrofric/core/exact.hpp"

namespace vibrofric {

struct Certificate {
  // μ̄/μ0 or Ψ lies in [lower, upper]: equal, the exact value, for the piecewise-linear waves
  // (`exact` its text: "p/q", or "p" for an integer); the dyadic ends of an enclosure for the
  // others (`lower_text`, `upper_text`: decimals rounded outward, three digits past the precision's).
  exact::Rational lower, upper;
  std::string exact, lower_text, upper_text;
  // For an enclosure: the longest decimal both its ends round to (to nearest; up to three digits
  // past the value's, as lower_text), so the exact value correctly rounded to that many digits,
  // every digit proven: what to cite (a double's shortest text may lie outside the enclosure, as
  // the double itself may); with its digit count.
  std::string cite;
  int cite_digits = 0;
  mpfr_prec_t bits = 0;  // the enclosure's precision that decided the rounding (0: exact)
  // The texts of the correctly rounded value at the precision (two where the exact value is a
  // tie between them), and whether the printed text is one of them.
  std::vector<std::string> nearest;
  bool correctly_rounded = false;
};

// Certificates for the points of one wave: the sine, power:P, Fourier series, the triangle, both sawtooths, the
// square wave and samples, on the flat punch, and the sine on power:N (sphere, cone) and
// wearflat:LAMBDA. The constructor throws InputError for any other wave or profile, naming it. An enclosure that has not decided the rounding at
// max_certify_bits is a SolverError.
class Certifier {
 public:
  Certifier(const WaveSpec& wave, const ProfileSpec& profile);
  // The certificate of `printed`, the text evaluate() gave for the point at `precision` (the
  // point's β and γ as typed: a computed point (Point::beta_value) has no exact inputs and is an
  // InputError, as is a point evaluate() refuses).
  Certificate operator()(Quantity q, const Point& point, const Precision& precision, const std::string& printed) const;
  // Whether its certificates are enclosures (the sine, power:P with P ≠ 1, Fourier
  // series) or exact values.
  bool encloses() const { return !wave_; }

 private:
  std::optional<exact::Wave> wave_;       // piecewise linear
  std::optional<exact::Rational> power_;  // power:P, P ≠ 1
  std::optional<std::vector<certified::RationalHarmonic>> fourier_;  // none of the three: the sine
  std::optional<certified::CurvedProfile> curved_;                   // the sine on a curved profile
  std::string name_;
  // A Fourier series' shape per precision, built once (shared by copies, and by threads).
  struct Shapes {
    std::mutex mutex;
    std::map<mpfr_prec_t, std::shared_ptr<const certified::FourierShape>> at;
  };
  std::shared_ptr<Shapes> shapes_ = std::make_shared<Shapes>();
  std::shared_ptr<const certified::FourierShape> shape(mpfr_prec_t bits) const;
};

// The longitudinal drive's certificate (core/inplane/inplane_exact.hpp): a piecewise-linear normal
// wave (or a constant normal force) and in-plane wave at decimal β, γ, a_l and P give μ̄/μ0 and the
// mode fractions as exact rationals ("p/q"); `mu` proves `printed`, the text evaluate_inplane gave
// at `precision`, as for Certifier. InputError for a transverse drive, a wave that is not piecewise
// linear, or a computed input; SolverError where no unique periodic state exists.
struct InPlaneCertificate {
  Certificate mu;
  std::string stick_fraction, slip_fraction, backward_fraction, flight_fraction;
};
InPlaneCertificate certify_inplane(const WaveSpec& normal, const Point& point, const InPlaneSpec& spec,
                                   const Precision& precision, const std::string& printed);
// certify_inplane's refusals that need no solve (a transverse drive, a wave that is not piecewise
// linear), for a caller to give before it computes the value.
void check_certifiable(const WaveSpec& normal, const InPlaneSpec& spec);

inline constexpr mpfr_prec_t max_certify_bits = 1 << 16;

// The wave as an exact piecewise-linear wave (samples normalised exactly, from their decimal
// text); InputError naming it for a wave that is not piecewise linear.
exact::Wave exact_wave(const WaveSpec& wave);

// A proven periodic state of the rig (core/certified/rig_enclosure.hpp): the sine, Fourier series and
// piecewise-linear waves on the flat punch, β, γ, κ, Ω, ζ as typed. μ̄/μ0 enclosed and its rounding decided as for Certifier; the
// fractions and the largest Floquet multiplier enclosed ("[lo, hi]", rounded outward); the box
// where the periodic state exists and is unique, at the section phase. InputError for another
// wave or profile, a computed input, the sine at γ = 1; SolverError
// where the proof is not found up to four times the first bits (naming what stayed open).
struct RigCertificate {
  Certificate mu;
  std::string stick_fraction, slip_fraction, backward_fraction, flight_fraction, multiplier;
  bool stable = false;  // both multipliers certainly inside the unit circle
  std::string section, section_mode, state_y, state_v;  // φ0, its mode (rig_mode_name), the box of (Y, Y') there
};
// The certificate's fields after mu's, as the front ends print them: periodic_state, the section,
// the state's box, the enclosures, stability.
std::vector<std::pair<std::string, std::string>> rig_certificate_fields(const RigCertificate& c);
// One attempt at `bits`: the rig solved at about that precision, its periodic state proven from
// the middle of its longest span of slip or flight (certified::Undecided where it is not there).
struct ProvenRig {
  certified::RigEnclosure enclosure;
  certified::RigSeed seed;
  RigMode section_mode;  // the seed's, as the rig solver names it
};
ProvenRig prove_rig(const WaveSpec& wave, const Point& point, const RigSpec& rig, mpfr_prec_t bits, const Options& solver = {});
// The wave of a proven rig state, exactly: InputError for power:P (P ≠ 1) and other waves without one.
certified::RigWaveInput rig_wave_input(const WaveSpec& wave);
RigCertificate certify_rig(const WaveSpec& wave, const Point& point, const RigSpec& rig, const Precision& precision,
                           const std::string& printed, const ProfileSpec& profile = {}, const Options& solver = {});

// The waves with certified values, for messages: "triangle, sawtooth-right, …".
extern const char* const certified_waves;

}  // namespace vibrofric
