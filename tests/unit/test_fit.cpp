// Fourier fit of sampled signals (fit.hpp; model.md, "Waveform catalogue": user Fourier series and
// sampled signals). References are the coefficients the samples were made from (a known
// trigonometric polynomial, evaluated here in mpfr at 40 digits and written with 30), and closed
// forms (Parseval on the uniform grid) for the residuals.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <random>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/fit.hpp"
#include "vibrofric/core/numbers.hpp"

namespace {

using namespace vibrofric;

constexpr double eps = std::numeric_limits<double>::epsilon();

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// y(φ) = Σ a_k cos 2πkφ + b_k sin 2πkφ, k = 0 … 3 (b_0 unused); k = 2 absent, so that a zero
// coefficient is recovered too.
struct Signal {
  std::vector<double> a{3.25, 1.5, 0, 0.125}, b{0, -0.75, 0, 2};
  // Σ|a_k| + |b_k|: the amplitude the bounds are relative to (max|y| ≤ it).
  double amplitude() const {
    double s = 0;
    for (std::size_t k = 0; k < a.size(); ++k) s += std::abs(a[k]) + std::abs(b[k]);
    return s;
  }
  mpfr operator()(const mpfr& phi) const {
    mpfr y = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      const mpfr theta = 2 * boost::math::constants::pi<mpfr>() * k * phi;
      y += a[k] * cos(theta) + b[k] * sin(theta);
    }
    return y;
  }
};

std::string dec30(const mpfr& x) { return x.str(30, std::ios_base::scientific); }

double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }
double number(const vibrofric::Decimal& d) { return number(d.text()); }

// The recovered coefficients against the signal's. Bound 4 eps × amplitude: the samples carry 30
// digits (1e-30 relative), the fit works at ≥ 60 digits, and the 17-digit rounding of a
// coefficient c moves it by ≤ 5e-17|c| ≤ 0.23 eps × amplitude; an error in the method (a phase
// off by one sample, a factor 2) is O(amplitude).
void expect_recovered(const FourierFit& fit, const Signal& sig, unsigned harmonics) {
  ASSERT_EQ(fit.harmonics.size(), harmonics + 1u);
  const double bound = 4 * eps * sig.amplitude();
  for (unsigned k = 0; k <= harmonics; ++k) {
    const double a = k < sig.a.size() ? sig.a[k] : 0, b = k < sig.b.size() ? sig.b[k] : 0;
    EXPECT_EQ(fit.harmonics[k].k, k);
    EXPECT_NEAR(number(fit.harmonics[k].a), a, bound) << "a_" << k << " = " << fit.harmonics[k].a;
    EXPECT_NEAR(number(fit.harmonics[k].b), b, bound) << "b_" << k << " = " << fit.harmonics[k].b;
  }
  // Noise-free: the residual is the coefficients' rounding to 17 digits, ≤ Σ 5e-17|c_k|.
  EXPECT_LE(number(fit.rms_residual), bound) << fit.rms_residual;
  EXPECT_LE(number(fit.max_residual), bound) << fit.max_residual;
}

TEST(Fit, UniformSamplesRecoverTheCoefficients) {
  PrecisionScope scope(40);
  const Signal sig;
  const int n = 16;
  std::string text;
  for (int j = 0; j < n; ++j) text += dec30(sig(mpfr(j) / n)) + "\n";
  const WaveSpec wave = parse_wave("samples:" + temp_file("fit_uniform.txt", text));
  for (unsigned k : {3u, 5u, 7u}) {  // 7: the largest with 2K < 16
    const FourierFit fit = fit_fourier(wave, k);
    EXPECT_EQ(fit.samples, 16u);
    EXPECT_NE(fit.method.find("DFT"), std::string::npos) << fit.method;
    expect_recovered(fit, sig, k);
  }
}

TEST(Fit, RandomTimeStampsRecoverTheCoefficients) {
  PrecisionScope scope(40);
  const Signal sig;
  // 40 stamps over a period T = 2.5 s, each jittered by up to ±40% of the mean spacing (seeded):
  // non-uniform, and spread so that the least-squares problem is well conditioned. Stamps are
  // written with 12 digits and the phases taken from the decimals exactly.
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  const int n = 40;
  const double period = 2.5;
  std::string text = "time [s], displacement\n";
  std::string y0;
  for (int j = 0; j <= n; ++j) {
    char t[64];
    std::snprintf(t, sizeof t, "%.12g", j == 0 || j == n ? j * period / n : (j + jitter(rng)) * period / n);
    const std::string y = j == n ? y0 : dec30(sig(mpfr(mpfr(t) / mpfr("2.5"))));
    if (j == 0) y0 = y;
    text += std::string(t) + ", " + y + "\n";
  }
  const WaveSpec wave = parse_wave("samples:" + temp_file("fit_random.csv", text));
  ASSERT_EQ(wave.samples.size(), 40u);
  for (unsigned k : {3u, 6u}) {
    const FourierFit fit = fit_fourier(wave, k);
    EXPECT_NE(fit.method.find("Householder"), std::string::npos) << fit.method;
    expect_recovered(fit, sig, k);
  }
}

// A harmonic the fit leaves out: on the uniform grid (N = 32 > 2·5) the fit with K = 2 drops
// 0.5 sin 10πφ exactly, so the residual is r_j = 0.5 sin(2π·5j/32): rms 0.5/√2 (Parseval), max 0.5
// (5j ≡ 8 mod 32 at j = 8). Printed with 3 digits: within 5e-3 relative.
TEST(Fit, ResidualOfAnOmittedHarmonic) {
  PrecisionScope scope(40);
  std::string text;
  for (int j = 0; j < 32; ++j) {
    const mpfr phi = mpfr(j) / 32, two_pi = 2 * boost::math::constants::pi<mpfr>();
    text += dec30(mpfr(1 + cos(two_pi * phi) + sin(5 * two_pi * phi) / 2)) + "\n";
  }
  const FourierFit fit = fit_fourier(parse_wave("samples:" + temp_file("fit_omitted.txt", text)), 2);
  EXPECT_NEAR(number(fit.rms_residual), 0.5 / std::sqrt(2.0), 5e-3 * 0.5 / std::sqrt(2.0)) << fit.rms_residual;
  EXPECT_NEAR(number(fit.max_residual), 0.5, 5e-3 * 0.5) << fit.max_residual;
  EXPECT_NEAR(number(fit.harmonics[0].a), 1, 4 * eps * 2.5);
  EXPECT_NEAR(number(fit.harmonics[1].a), 1, 4 * eps * 2.5);
}

// The fitted file read back as fourier:FILE: the same coefficients, and the Fourier waveform (in
// double) is the signal once its reported normalisation is undone: w(φ)·scale + offset = y(φ).
// Bound 64 eps × amplitude: double evaluation of 3 harmonics by recurrence plus the
// normalisation's roundings, each a few eps of the amplitude.
TEST(Fit, FittedFileRoundTrips) {
  PrecisionScope scope(40);
  const Signal sig;
  std::string text;
  for (int j = 0; j < 16; ++j) text += dec30(sig(mpfr(j) / 16)) + "\n";
  const std::string source = temp_file("fit_trip.txt", text);
  const FourierFit fit = fit_fourier(parse_wave("samples:" + source), 3);
  const std::string file = fourier_file_text(fit, "samples:" + source + "\n0 9 9");  // a newline must stay in the comment
  EXPECT_NE(file.find("# Fourier series fitted by vibrofric to samples:" + source + "\\x0A0 9 9\n"), std::string::npos) << file;
  EXPECT_NE(file.find("# method: DFT"), std::string::npos) << file;
  EXPECT_NE(file.find("K = 3, samples N = 16"), std::string::npos) << file;
  const WaveSpec back = parse_wave("fourier:" + temp_file("fit_trip.fourier", file));
  ASSERT_EQ(back.harmonics.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(back.harmonics[k].k, fit.harmonics[k].k);
    EXPECT_EQ(back.harmonics[k].a.text(), fit.harmonics[k].a.text());
    EXPECT_EQ(back.harmonics[k].b.text(), fit.harmonics[k].b.text());
  }
  const auto w = make_waveform<double>(back);
  const double offset = w->normalisation().offset, scale = w->normalisation().scale;
  EXPECT_NEAR(offset, 3.25, 4 * eps * sig.amplitude());
  for (int i = 0; i <= 50; ++i) {
    const double phi = i / 50.0;
    EXPECT_NEAR((*w)(phi) * scale + offset, static_cast<double>(sig(mpfr(phi))), 64 * eps * sig.amplitude()) << phi;
  }
}

void expect_refused(const std::function<void()>& f, const std::string& words) {
  try {
    f();
    ADD_FAILURE() << "accepted; expected a refusal with '" << words << "'";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(words), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(Fit, Refusals) {
  const WaveSpec six = parse_wave("samples:" + temp_file("fit_six.txt", "0 1 3 2 -1 -2\n"));
  expect_refused([&] { fit_fourier(six, 0); }, "harmonics K = 0 for the fit of 'samples:");
  expect_refused([&] { fit_fourier(six, 0); }, "expected at least 1");
  expect_refused([&] { fit_fourier(six, 10001); }, "harmonics K = 10001 for the fit of");
  expect_refused([&] { fit_fourier(six, 10001); }, "expected at most 10000");
  EXPECT_NO_THROW(fit_fourier(six, 2));
  // N = 6: 2K < 6 allows K ≤ 2.
  expect_refused([&] { fit_fourier(six, 3); }, "its 6 samples determine at most 2 harmonics: expected K <= 2");
  expect_refused([&] { fit_fourier(parse_wave("sine"), 1); }, "fit of wave 'sine': expected a samples:FILE wave");
  // Time column: N = 5 samples (the end point excluded) allow K ≤ 2.
  const WaveSpec stamped = parse_wave("samples:" + temp_file("fit_stamped.csv", "t,y\n0,0\n1,2\n3,1\n4,-1\n6,-2\n7,0\n"));
  EXPECT_NO_THROW(fit_fourier(stamped, 2));
  expect_refused([&] { fit_fourier(stamped, 3); }, "its 5 samples determine at most 2 harmonics");
  // 11 stamps within 1% of the period and K = 5 (11 unknowns): distinct phases, so the matrix is
  // regular in exact arithmetic (the Haar property), but its condition number is ~1e20.
  std::string clustered = "t,y\n0,0\n";
  for (int j = 1; j <= 10; ++j) clustered += "0." + std::string(j < 10 ? "00" : "0") + std::to_string(j) + "," + std::to_string(j % 3) + "\n";
  clustered += "1,0\n";
  const WaveSpec near = parse_wave("samples:" + temp_file("fit_clustered.csv", clustered));
  ASSERT_EQ(near.samples.size(), 11u);
  expect_refused([&] { fit_fourier(near, 5); }, "the least-squares problem is rank deficient (condition number ");
  expect_refused([&] { fit_fourier(near, 5); }, "expected fewer harmonics or time stamps spread over the period");
}

}  // namespace
