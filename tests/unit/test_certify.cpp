// Certified values (api/certify.hpp) against the guaranteed path (README, "Precision"): on random
// points of every piecewise-linear wave, of the sine, of power:P and of Fourier series (fewer
// points), the double and long double that
// evaluate() prints are the exact value (core/exact.hpp) or both ends of its enclosure
// (core/certified/enclosure.hpp) correctly rounded, as the certificate says and as MPFR's own correctly
// rounded conversion says (an independent decision); and the solver's first-order rounding bound
// in raw double and long double is a true bound of the actual error, measured against the exact
// value (the enclosed waves: against the farther end of a 256-bit enclosure). Its ratio to the actual
// error is printed.
// 400 points per wave here; VIBROFRIC_STRESS=full: 100,000 (issue 28's count).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "vibrofric/api/exact_input.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/core/certified/enclosure.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "correct_rounding.hpp"
#include "decimals.hpp"

namespace {

using namespace vibrofric;
using exact::Rational;

int points_per_wave() {
  const char* mode = std::getenv("VIBROFRIC_STRESS");
  return mode && std::string(mode) == "full" ? 100000 : 400;
}

// A decimal with `digits` significant digits, log-uniform in [lo, hi).
std::string log_uniform(std::mt19937& rng, double lo, double hi, int digits) {
  const double x = std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
  return format_significant(x, digits);
}

std::string uniform(std::mt19937& rng, double lo, double hi, int digits) {
  return format_significant(std::uniform_real_distribution<double>(lo, hi)(rng), digits);
}

// The exact value correctly rounded to T by MPFR (correct_rounding.hpp's nearest: mpfr_set_q at
// T's precision), printed as evaluate() prints T.
template <class T>
std::string mpfr_rounding(const Rational& x) {
  const boost::multiprecision::cpp_rational q(numerator(x).str() + "/" + denominator(x).str());
  return format_significant(vibrofric::testing::nearest<T>(q), std::numeric_limits<T>::max_digits10);
}

Rational exact_of(double x) {
  Rational q;
  mpq_set_d(q.backend().data(), x);
  return q;
}

Rational exact_of(long double x) {  // via MPFR, exactly (64 bits)
  mpfr_t r;
  mpfr_init2(r, 64);
  mpfr_set_ld(r, x, MPFR_RNDN);
  Rational q;
  mpfr_get_q(q.backend().data(), r);
  mpfr_clear(r);
  return q;
}

struct Ratios {
  std::vector<double> bound_over_actual;
  long exact_hits = 0;  // the type's value was exact (actual error 0)
  long unbounded = 0;   // the solver gave no finite bound in the type
  std::string summary() const {
    std::vector<double> v = bound_over_actual;
    if (v.empty()) return "no inexact values";
    std::sort(v.begin(), v.end());
    return "bound / actual error: min " + format_significant(v.front(), 3) + ", median " + format_significant(v[v.size() / 2], 3) +
           ", max " + format_significant(v.back(), 3) + " over " + std::to_string(v.size()) + " inexact values (" +
           std::to_string(exact_hits) + " exact, " + std::to_string(unbounded) + " without a finite bound)";
  }
};

// μ̄ or Ψ enclosed at 256 bits (Ψ at a γ without jumping: 1 for the sine and power:P, 2 for a
// series); a series' shape built once.
Interval enclosure_at_256_bits(const WaveSpec& spec, Quantity q, const Rational& beta, const Rational& gamma) {
  if (spec.kind == WaveKind::fourier) {
    static std::map<std::string, certified::FourierShape> shapes;
    auto it = shapes.find(spec.name);
    if (it == shapes.end()) {
      std::vector<certified::RationalHarmonic> series;
      for (const auto& h : spec.harmonics) series.push_back({h.k, rational(h.a, "a"), rational(h.b, "b")});
      it = shapes.emplace(spec.name, certified::FourierShape(series, 256)).first;
    }
    const certified::FourierEnclosure e = certified::enclose_fourier(it->second, beta, q == Quantity::psi ? Rational(2) : gamma);
    return q == Quantity::psi ? e.lost_area : e.mu;
  }
  const Rational g = q == Quantity::psi ? Rational(1) : gamma;
  const certified::SineEnclosure e = spec.kind == WaveKind::sine
                                         ? certified::enclose_sine(beta, g, 256)
                                         : certified::enclose_power(rational(spec.exponent, "p"), beta, g, 256);
  return q == Quantity::psi ? e.lost_area : e.mu;
}

// The raw solve in T: its bound must hold against the exact value.
template <class T>
void check_bound(const WaveSpec& spec, const Waveform<T>& w, Quantity q, const Point& p, Ratios& ratios) {
  const T beta = parse_real<T>(p.beta.text(), "beta");
  const Result<T> r = q == Quantity::psi ? psi(w, beta) : solve(w, beta, parse_real<T>(p.gamma.text(), "gamma"));
  const T value = q == Quantity::psi ? r.lost_area : r.mu;
  using std::isfinite;
  const T& bound = q == Quantity::psi ? r.lost_relative_error : r.relative_error;
  if (!isfinite(bound)) {  // no bound in T (the ladder goes on): nothing to check
    ++ratios.unbounded;
    return;
  }
  // The bound covers the computation from the inputs rounded to T; the inputs' own rounding
  // (relative eps/2 each, amplified by the condition number) is not the solver's: compare with
  // the exact value at the rounded inputs.
  const Rational beta_t = exact_of(beta);
  const Rational gamma_t = q == Quantity::psi ? Rational(0) : exact_of(parse_real<T>(p.gamma.text(), "gamma"));
  Rational at_rounded, actual;
  if (Certifier(spec, ProfileSpec{}).encloses()) {
    // The enclosure at 256 bits; the actual error is at most the distance to its farther end.
    const Interval v = enclosure_at_256_bits(spec, q, beta_t, gamma_t);
    Rational lo, hi;
    mpfr_get_q(lo.backend().data(), v.lower().backend().data());
    mpfr_get_q(hi.backend().data(), v.upper().backend().data());
    at_rounded = lo;
    actual = std::max(abs(exact_of(value) - lo), abs(exact_of(value) - hi));
  } else {
    const exact::Wave ew = exact_wave(spec);
    at_rounded = q == Quantity::psi ? exact::psi(ew, beta_t).lost_area : exact::solve(ew, beta_t, gamma_t).mu;
    actual = abs(exact_of(value) - at_rounded);
  }
  const Rational allowed = exact_of(bound) * abs(at_rounded);
  ASSERT_LE(actual, allowed) << spec.name << (q == Quantity::psi ? " psi" : " mu") << " in " << typeid(T).name()
                             << " beta = " << p.beta << " gamma = " << p.gamma << ", value "
                             << format_significant(static_cast<double>(at_rounded), 17) << ", stick phases "
                             << r.stick_phases.size() << ", events " << r.events << ": actual error "
                             << format_significant(static_cast<double>(actual), 3) << " over the bound "
                             << format_significant(static_cast<double>(allowed), 3);
  if (actual == 0) ++ratios.exact_hits;
  else ratios.bound_over_actual.push_back(static_cast<double>(allowed / actual));
}

std::vector<WaveSpec> certified_waves_to_test(std::mt19937& rng) {
  std::vector<WaveSpec> waves;
  for (const char* name : {"sine", "power:3", "power:1.5", "triangle", "sawtooth-right", "sawtooth-left", "square", "power:1"}) waves.push_back(parse_wave(name));
  // A noisy signal as a rig records it: 4 significant digits, 60 samples at φ = j/N.
  WaveSpec s;
  s.kind = WaveKind::samples;
  s.name = "samples:noisy";
  std::normal_distribution<double> noise(0, 0.03);
  for (int j = 0; j < 60; ++j) s.samples.push_back(dec(format_significant(2 * std::sin(6.283185307179586 * j / 60) + noise(rng), 4)));
  waves.push_back(s);
  // With time stamps (non-uniform phases), 25 samples.
  WaveSpec t = s;
  t.name = "samples:stamped";
  t.samples.resize(25);
  double time = 0;
  for (int j = 0; j <= 25; ++j) {
    t.times.push_back(dec(format_significant(time, 6)));
    time += std::uniform_real_distribution<double>(0.5, 1.5)(rng);
  }
  waves.push_back(t);
  // Fourier series: three harmonics as a user writes them, and six random ones.
  WaveSpec f;
  f.kind = WaveKind::fourier;
  f.name = "fourier:three";
  f.harmonics = {{1, dec("0"), dec("1")}, {2, dec("0.1"), dec("-0.05")}, {3, dec("0"), dec("0.333")}};
  waves.push_back(f);
  f.name = "fourier:random";
  f.harmonics.clear();
  for (unsigned k = 1; k <= 6; ++k)
    f.harmonics.push_back({k, dec(uniform(rng, -1, 1, 3)), dec(uniform(rng, -1, 1, 3))});
  waves.push_back(f);
  return waves;
}

TEST(Certify, GuaranteedValuesAreTheCertifiedRoundings) {
  std::mt19937 rng(20261127);
  for (const WaveSpec& spec : certified_waves_to_test(rng)) {
    // A series' enclosure costs milliseconds a point (its events isolated one by one, 20 ms for
    // six harmonics): a tenth of the points, a twentieth for the random one.
    const int n = points_per_wave() / (spec.kind != WaveKind::fourier ? 1 : spec.name == "fourier:three" ? 10 : 20);
    const Certifier certifier(spec, ProfileSpec{});
    const auto wd = make_waveform<double>(spec);
    const auto wl = make_waveform<long double>(spec);
    const double top = static_cast<double>(wd->maximum());
    Ratios ratios_d, ratios_l;
    std::vector<Point> points;
    for (int i = 0; i < n; ++i) {
      // β log-uniform over (1e-4, 20): both sides of every β_c; every tenth point near the
      // corners (β → 0, γ → −max w, where the ladder climbs to mpfr).
      const bool corner = i % 10 == 0;
      std::string beta = corner ? log_uniform(rng, 1e-7, 1e-3, 6) : log_uniform(rng, 1e-4, 20, 6);
      std::string gamma = corner ? format_significant(-top + std::pow(10.0, -std::uniform_real_distribution<double>(2, 9)(rng)), 12)
                                 : uniform(rng, -top + 1e-3, 3, 6);
      points.push_back({beta, gamma});
    }
    for (Quantity q : {Quantity::mu, Quantity::psi}) {
      const std::vector<std::string> d = evaluate(spec, q, points, {NumberType::float64, 0});
      std::vector<Point> some(points.begin(), points.begin() + n / 10);
      const std::vector<std::string> l = evaluate(spec, q, some, {NumberType::float80, 0});
      for (int i = 0; i < n; ++i) {
        const std::string at = spec.name + (q == Quantity::psi ? " psi" : " mu") + " beta = " + points[i].beta.text() +
                               (q == Quantity::mu ? " gamma = " + points[i].gamma.text() : std::string());
        const Certificate c = certifier(q, points[i], {NumberType::float64, 0}, d[i]);
        ASSERT_TRUE(c.correctly_rounded) << at << ": printed " << d[i] << ", exact " << c.exact << ", nearest " << c.nearest.front();
        // Both ends of an enclosure (the sine) round to the printed double; exact: the same end.
        ASSERT_EQ(d[i], mpfr_rounding<double>(c.lower)) << at;
        ASSERT_EQ(d[i], mpfr_rounding<double>(c.upper)) << at;
        if (i < n / 10) {
          const Certificate cl = certifier(q, points[i], {NumberType::float80, 0}, l[i]);
          ASSERT_TRUE(cl.correctly_rounded) << at << ": printed " << l[i] << ", exact " << cl.exact;
          ASSERT_EQ(l[i], mpfr_rounding<long double>(cl.lower)) << at;
          ASSERT_EQ(l[i], mpfr_rounding<long double>(cl.upper)) << at;
        }
        if (i % 3 == 0) {
          check_bound(spec, *wd, q, points[i], ratios_d);
          check_bound(spec, *wl, q, points[i], ratios_l);
        }
      }
    }
    std::cout << spec.name << ", double: " << ratios_d.summary() << "\n"
              << spec.name << ", long double: " << ratios_l.summary() << "\n";
  }
}

// An enclosure's texts (certify.cpp: lower_text, upper_text) are its dyadic ends rounded outward
// to a decimal: lower_text ≤ lower and upper_text ≥ upper exactly, each within one unit of its
// own last place, so the printed interval holds the value and is no wider than it must be.
TEST(Certify, EnclosureTextsAreTheEndsRoundedOutward) {
  // The exact value of a text's last place, 10^(exponent − digits after the point).
  const auto last_place = [](const std::string& text) {
    const std::size_t e = text.find_first_of("eE"), dot = text.find('.');
    const long exponent = e == std::string::npos ? 0 : std::stol(text.substr(e + 1));
    const long after = dot == std::string::npos ? 0 : static_cast<long>((e == std::string::npos ? text.size() : e) - dot - 1);
    return exact_decimal("1e" + std::to_string(exponent - after), "last place");
  };
  int checked = 0;
  for (const char* wave : {"sine", "power:2.5"}) {
    const WaveSpec spec = parse_wave(wave);
    const Certifier certifier(spec, ProfileSpec{});
    ASSERT_TRUE(certifier.encloses()) << wave;
    for (const Precision& precision : {Precision{NumberType::float64, 0}, Precision{NumberType::float80, 0}, Precision{NumberType::mpfr, 30}})
      for (const Point& point : {Point{"0.5", "0.2"}, Point{"1", "-0.3"}, Point{"3", "1.5"}, Point{"0.01", "-0.9"}}) {
        const std::string printed = evaluate(spec, Quantity::mu, {point}, precision).front();
        const Certificate c = certifier(Quantity::mu, point, precision, printed);
        const std::string at = std::string(wave) + " beta " + point.beta.text() + " gamma " + point.gamma.text() + ": [" +
                               c.lower_text + ", " + c.upper_text + "]";
        ASSERT_TRUE(c.correctly_rounded) << at;
        const Rational lo = exact_decimal(c.lower_text, "lower"), hi = exact_decimal(c.upper_text, "upper");
        EXPECT_LE(lo, c.lower) << at;
        EXPECT_GE(hi, c.upper) << at;
        EXPECT_GT(Rational(lo + last_place(c.lower_text)), c.lower) << at;
        EXPECT_LT(Rational(hi - last_place(c.upper_text)), c.upper) << at;
        // What to cite: within half its last place of both exact ends (so of the value between),
        // with at least the printed value's digits and at most the enclosure texts' three more.
        const Rational cite = exact_decimal(c.cite, "cite"), half = Rational(last_place(c.cite) / 2);
        EXPECT_LE(Rational(abs(Rational(c.lower - cite))), half) << at << " cite " << c.cite;
        EXPECT_LE(Rational(abs(Rational(c.upper - cite))), half) << at << " cite " << c.cite;
        EXPECT_GE(c.cite_digits, output_digits(precision)) << at << " cite " << c.cite;
        EXPECT_LE(c.cite_digits, output_digits(precision) + 3) << at << " cite " << c.cite;
        ++checked;
      }
  }
  EXPECT_EQ(checked, 24);
}

// The certificate is not a formality: a neighbour of the right value, and a value of the wrong
// point, are refused.
TEST(Certify, RefusesWrongValues) {
  const WaveSpec tri = parse_wave("triangle");
  const Certifier certifier(tri, ProfileSpec{});
  const Point p{"0.5", "0.2"};  // μ̄/μ0 = 2β/(4 + β) = 2/9 (Eq. 19)
  const Certificate right = certifier(Quantity::mu, p, {NumberType::float64, 0}, "0.22222222222222221");
  EXPECT_TRUE(right.correctly_rounded);
  EXPECT_EQ(right.exact, "2/9");
  EXPECT_FALSE(certifier(Quantity::mu, p, {NumberType::float64, 0}, "0.22222222222222224").correctly_rounded);
  EXPECT_FALSE(certifier(Quantity::mu, p, {NumberType::float64, 0}, "0.22222222222222218").correctly_rounded);
  EXPECT_TRUE(certifier(Quantity::mu, p, {NumberType::mpfr, 5}, "0.22222").correctly_rounded);
  EXPECT_FALSE(certifier(Quantity::mu, p, {NumberType::mpfr, 5}, "0.22223").correctly_rounded);
  // A decimal tie at 2 digits: 1/8 = 0.125 (square wave, γ = 0, β = 0.5: β/(4(1 + γ)), Eq. 22).
  const Certifier sq(parse_wave("square"), ProfileSpec{});
  const Certificate tie = sq(Quantity::mu, {"0.5", "0"}, {NumberType::mpfr, 2}, "0.13");
  EXPECT_EQ(tie.exact, "1/8");
  EXPECT_EQ(tie.nearest, (std::vector<std::string>{"0.12", "0.13"}));
  EXPECT_TRUE(tie.correctly_rounded);
  EXPECT_TRUE(sq(Quantity::mu, {"0.5", "0"}, {NumberType::mpfr, 2}, "0.12").correctly_rounded);
  EXPECT_FALSE(sq(Quantity::mu, {"0.5", "0"}, {NumberType::mpfr, 2}, "0.11").correctly_rounded);
  // No certified values for a curved profile.
  EXPECT_NO_THROW(Certifier(parse_wave("power:2"), ProfileSpec{}));
  EXPECT_THROW(Certifier(tri, parse_profile("sphere")), InputError);
}

}  // namespace
