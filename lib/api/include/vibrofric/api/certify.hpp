// Certified values (README, "Precision"): μ̄/μ0 (Eq. 15) and Ψ_w(β) (Eq. 12) of the
// piecewise-linear waves as exact rationals (core/exact.hpp), and the proof that a value evaluate()
// printed is their correct rounding in the number type or to the digits asked for. The waves
// that are not piecewise linear (the sine, power:P for P ≠ 1, Fourier series) have no certified
// values yet.
#pragma once
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/exact.hpp"

namespace vibrofric {

struct Certificate {
  exact::Rational value;  // μ̄/μ0 or Ψ, exactly
  std::string exact;      // its text: "p/q", or "p" where it is an integer
  // The texts of the correctly rounded value at the precision (two where the exact value is a
  // tie between them), and whether the printed text is one of them.
  std::vector<std::string> nearest;
  bool correctly_rounded = false;
};

// Certificates for the points of one wave: the triangle, both sawtooths, the square wave,
// power:P with P = 1 and samples, on the flat punch. The constructor throws InputError for any
// other wave or profile, naming it.
class Certifier {
 public:
  Certifier(const WaveSpec& wave, const ProfileSpec& profile);
  // The certificate of `printed`, the text evaluate() gave for the point at `precision` (the
  // point's β and γ as typed: a computed point (Point::beta_value) has no exact inputs and is an
  // InputError, as is a point evaluate() refuses).
  Certificate operator()(Quantity q, const Point& point, const Precision& precision, const std::string& printed) const;

 private:
  exact::Wave wave_;
};

// The wave as an exact piecewise-linear wave (samples normalised exactly, from their decimal
// text); InputError naming it for a wave that is not piecewise linear.
exact::Wave exact_wave(const WaveSpec& wave);

// The waves with certified values, for messages: "triangle, sawtooth-right, …".
extern const char* const certified_waves;

}  // namespace vibrofric
