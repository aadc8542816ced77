// Certified values of the piecewise-linear waves (certify.hpp).
#include "vibrofric/api/certify.hpp"

#include <cmath>
#include <limits>

#include "vibrofric/api/decimal.hpp"

namespace vibrofric {

const char* const certified_waves = "triangle, sawtooth-right, sawtooth-left, square, power:1 and samples:FILE";

using exact::Rational;
using Integer = boost::multiprecision::mpz_int;

exact::Wave exact_wave(const WaveSpec& spec) {
  switch (spec.kind) {
    case WaveKind::triangle: return exact::triangle();
    case WaveKind::sawtooth_right: return exact::sawtooth_right();
    case WaveKind::sawtooth_left: return exact::sawtooth_left();
    case WaveKind::square: return exact::square();
    case WaveKind::power:
      if (exact::decimal(spec.exponent, "power exponent p") == 1) return exact::power_one();
      break;
    case WaveKind::samples: {
      std::vector<Rational> y, phases;
      for (const std::string& t : spec.samples) y.push_back(exact::decimal(t, spec.name + " sample"));
      if (!spec.times.empty()) {  // t_0 … t_N: φ_j = (t_j − t_0)/(t_N − t_0)
        const Rational t0 = exact::decimal(spec.times.front(), spec.name + " time"),
                       period = exact::decimal(spec.times.back(), spec.name + " time") - t0;
        for (std::size_t j = 0; j < spec.samples.size(); ++j)
          phases.push_back((exact::decimal(spec.times[j], spec.name + " time") - t0) / period);
      }
      return exact::samples(spec.name, y, phases);
    }
    case WaveKind::sine:
    case WaveKind::fourier: break;
  }
  throw InputError("wave '" + detail::visible(spec.name) + "' has no certified values: they exist for " + certified_waves +
                   " (piecewise linear, so every event and area is an exact rational)");
}

namespace {

std::string text_of(const Rational& x) {
  const Integer num = numerator(x), den = denominator(x);
  return den == 1 ? num.str() : num.str() + "/" + den.str();
}

Integer power(long base, long e) { return pow(Integer(base), static_cast<unsigned>(e)); }

// x · base^e, exactly.
Rational scaled(const Rational& x, long base, long e) {
  return e >= 0 ? Rational(x * Rational(power(base, e))) : Rational(x / Rational(power(base, -e)));
}

// The e with base^(e−1) ≤ x < base^e, x > 0.
long exponent_of(const Rational& x, long base) {
  // A first guess from the sizes of numerator and denominator, then exact steps.
  const double bits = static_cast<double>(msb(numerator(x))) - static_cast<double>(msb(denominator(x)));
  long e = static_cast<long>(bits / std::log2(static_cast<double>(base)));
  while (scaled(x, base, -e) >= 1) ++e;
  while (scaled(x, base, -(e - 1)) < 1) --e;
  return e;
}

// The multiples k·base^q nearest x ≥ 0, as (k, q): one, or two on an exact tie. The quantum is
// base^(e − digits) for x in [base^(e−1), base^e), and at least base^min_q (subnormals).
std::vector<std::pair<Integer, long>> nearest(const Rational& x, long base, long digits, long min_q) {
  if (x == 0) return {{Integer(0), 0}};
  const long q = std::max(exponent_of(x, base) - digits, min_q);
  const Rational t = scaled(x, base, -q);
  const Integer k = numerator(t) / denominator(t);  // floor, t > 0
  const Rational rest = t - Rational(k);
  if (rest == 0) return {{k, q}};
  if (rest < Rational(1, 2)) return {{k, q}};
  if (rest > Rational(1, 2)) return {{Integer(k + 1), q}};
  return {{k, q}, {Integer(k + 1), q}};
}

template <class Real>
std::vector<std::string> nearest_in(const Rational& x, int digits_printed) {
  using L = std::numeric_limits<Real>;
  const long min_q = L::has_denorm == std::denorm_present ? L::min_exponent - L::digits : L::min_exponent - 1;
  std::vector<std::string> out;
  for (const auto& [k, q] : nearest(x, 2, L::digits, min_q)) {
    mpfr v;
    mpfr_set_prec(v.backend().data(), L::digits + 2);
    mpfr_set_z(v.backend().data(), k.backend().data(), MPFR_RNDN);  // k < 2^(digits + 1): exact
    mpfr_mul_2si(v.backend().data(), v.backend().data(), q, MPFR_RNDN);
    out.push_back(format_significant(detail::rounded<Real>(v), digits_printed));
  }
  return out;
}

std::vector<std::string> nearest_decimals(const Rational& x, int digits) {
  std::vector<std::string> out;
  for (const auto& [k, q] : nearest(x, 10, digits, std::numeric_limits<long>::min() / 2)) {
    // k·10^q to `digits` digits: through a binary value that holds it to more than those digits.
    PrecisionScope scope(static_cast<unsigned>(digits + 20));
    const mpfr v = mpfr(k.str()) * pow(mpfr(10), q);
    out.push_back(format_significant(v, digits));
  }
  return out;
}

}  // namespace

Certifier::Certifier(const WaveSpec& wave, const ProfileSpec& profile) : wave_(exact_wave(wave)) {
  if (profile.kind != ProfileKind::flat)
    throw InputError("profile " + detail::visible(profile.name) +
                     " has no certified values: they exist for the flat punch (a curved contact integrates over springs)");
}

Certificate Certifier::operator()(Quantity q, const Point& point, const Precision& precision, const std::string& printed) const {
  if (point.beta_value || point.gamma_value)
    throw InputError("a computed point (beta " + point.beta + ") has no exact inputs to certify");
  const Rational beta = exact::decimal(point.beta, "beta");
  Certificate c;
  c.value = q == Quantity::psi ? exact::psi(wave_, beta).lost_area
                               : exact::solve(wave_, beta, exact::decimal(point.gamma, "gamma")).mu;
  c.exact = text_of(c.value);
  const int digits = output_digits(precision);
  switch (precision.type) {
    case NumberType::float64: c.nearest = nearest_in<double>(c.value, digits); break;
    case NumberType::float80: c.nearest = nearest_in<long double>(c.value, digits); break;
    case NumberType::bin50: c.nearest = nearest_in<bin50>(c.value, digits); break;
    case NumberType::bin100: c.nearest = nearest_in<bin100>(c.value, digits); break;
    case NumberType::mpfr: c.nearest = nearest_decimals(c.value, digits); break;
  }
  for (const std::string& t : c.nearest) c.correctly_rounded = c.correctly_rounded || t == printed;
  return c;
}

}  // namespace vibrofric
