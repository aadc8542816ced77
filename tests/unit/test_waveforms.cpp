// Waveform catalogue and user waveforms (model.md, "Waveform catalogue"; Eq. 16).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <random>
#include <sstream>
#include <tuple>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/verification/envelope.hpp"
#include "decimals.hpp"

namespace {

using namespace vibrofric;

std::unique_ptr<Waveform<double>> wave(const std::string& name) { return make_waveform<double>(parse_wave(name)); }

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// An integer count of 10^-9 as a decimal ("-0.000001234").
std::string decimal_nanos(long long v) {
  const unsigned long long a = static_cast<unsigned long long>(v < 0 ? -v : v);
  char out[48];
  std::snprintf(out, sizeof out, "%s%llu.%09llu", v < 0 ? "-" : "", a / 1000000000ULL, a % 1000000000ULL);
  return out;
}

// Mean by the antiderivative over each piece: zero for every catalogue wave.
double mean(const Waveform<double>& w) {
  double s = 0;
  for (std::size_t i = 0; i < w.piece_count(); ++i)
    s += w.antiderivative(i, w.piece_end(i)) - w.antiderivative(i, w.piece_begin(i));
  return s;
}

TEST(Waveforms, CatalogueValuesAtKnownPhases) {
  EXPECT_DOUBLE_EQ((*wave("tri"))(0.0), -1.0);
  EXPECT_DOUBLE_EQ((*wave("tri"))(0.25), 0.0);
  EXPECT_DOUBLE_EQ((*wave("tri"))(0.5), 1.0);
  EXPECT_DOUBLE_EQ((*wave("tri"))(0.75), 0.0);
  EXPECT_DOUBLE_EQ((*wave("str"))(0.25), -0.5);
  EXPECT_DOUBLE_EQ((*wave("stl"))(0.25), 0.5);
  EXPECT_DOUBLE_EQ((*wave("sqr"))(0.25), 1.0);
  EXPECT_DOUBLE_EQ((*wave("sqr"))(0.75), -1.0);
  EXPECT_DOUBLE_EQ((*wave("sine"))(0.25), 1.0);
  EXPECT_DOUBLE_EQ((*wave("power:2"))(0.25), 1.0);
  EXPECT_DOUBLE_EQ((*wave("power:2"))(0.125), 0.75);   // 1 − |0.5 − 1|²
  EXPECT_DOUBLE_EQ((*wave("power:2"))(0.625), -0.75);
  EXPECT_DOUBLE_EQ((*wave("tri"))(1.5), 1.0);  // periodic
  EXPECT_DOUBLE_EQ((*wave("tri"))(-0.5), 1.0);
}

TEST(Waveforms, PowerOneIsTheShiftedTriangle) {
  const auto p1 = wave("power:1"), tri = wave("tri");
  for (int j = 0; j < 40; ++j) {
    const double phi = j / 40.0;
    EXPECT_NEAR((*p1)(phi), (*tri)(phi + 0.25), 1e-15) << phi;
  }
}

// power:p in a fixed type is refused above p = 2^-10/eps (waveform.hpp, Power::unresolved): the
// flanks near u = 1 change n' by exp(16·p·eps) over a few ulp of phase, and the rounding bound is
// first order. The edge is a power of two, exact in every type; at it the type's own bound must
// cover its error against twice the digits, just above it the type refuses (the ladder then
// escalates). Measured with the edge removed (double, 36 (β, γ)): error/bound ≤ 0.15 up to
// p = 1e17, 3.5e15 at p = 1e18, so the edge keeps a margin of about 2^14 below the failure.
template <class T>
void check_power_flank_edge(unsigned bits, unsigned ref_digits) {
  using std::abs;
  using std::ldexp;
  PrecisionScope scope(ref_digits);
  const int e = static_cast<int>(bits) - 1 - 10;  // 2^-10/eps = 2^(bits - 1 - 10)
  ASSERT_EQ(std::numeric_limits<T>::epsilon(), ldexp(T(1), 1 - static_cast<int>(bits)));
  const T edge = ldexp(T(1), e), above = edge * (1 + ldexp(T(1), -20));
  const Power<T> at(edge, "power:edge"), beyond(above, "power:above");
  const Power<mpfr> at_ref(ldexp(mpfr(1), e), "power:edge");
  struct Case {
    const char *beta, *gamma;
  };
  for (const Case c : {Case{"1", "0.5"}, Case{"3", "2"}, Case{"0.5", "-0.5"}, Case{"0.2", "5"}}) {
    const T b = detail::rounded<T>(mpfr(c.beta), ref_digits), g = detail::rounded<T>(mpfr(c.gamma), ref_digits);
    const Result<T> r = solve(at, b, g);
    const Result<mpfr> ref = solve(at_ref, mpfr(b), mpfr(g));  // the same inputs, exactly
    EXPECT_LE(abs(mpfr(r.mu) - ref.mu), mpfr(r.relative_error) * abs(ref.mu))
        << "2^" << e << " beta " << c.beta << " gamma " << c.gamma;
    EXPECT_LE(abs(mpfr(r.lost_area) - ref.lost_area), mpfr(r.lost_relative_error) * abs(ref.lost_area))
        << "2^" << e << " beta " << c.beta << " gamma " << c.gamma;
    EXPECT_THROW(solve(beyond, b, g), PrecisionError) << "2^" << e << "(1 + 2^-20)";
  }
  EXPECT_THROW(psi(beyond, T(3)), PrecisionError);
}

TEST(Waveforms, PowerFlankEdgeInEveryFixedType) {
  check_power_flank_edge<double>(53, 40);
  check_power_flank_edge<long double>(64, 45);
  check_power_flank_edge<bin50>(std::numeric_limits<bin50>::digits, 110);
}

TEST(Waveforms, ExtremaMeanAndBetaC) {
  for (const char* name : {"sine", "tri", "str", "stl", "sqr", "power:1", "power:1.5", "power:8"}) {
    const auto w = wave(name);
    EXPECT_DOUBLE_EQ(w->minimum(), -1.0) << name;
    EXPECT_DOUBLE_EQ(w->maximum(), 1.0) << name;
    EXPECT_NEAR(mean(*w), 0.0, 4e-16) << name;
  }
  EXPECT_NEAR(make_contact(*wave("sine"), 1.0).beta_c(), 2 * M_PI, 1e-15);
  EXPECT_NEAR(make_contact(*wave("sine"), -0.6).beta_c(), 2 * M_PI * 0.8, 1e-14);
  EXPECT_EQ(make_contact(*wave("tri"), 0.0).beta_c(), 4.0);
  EXPECT_EQ(make_contact(*wave("str"), 0.0).beta_c(), 2.0);
  EXPECT_TRUE(std::isinf(make_contact(*wave("stl"), 0.0).beta_c()));
  EXPECT_TRUE(std::isinf(make_contact(*wave("sqr"), 0.0).beta_c()));
  EXPECT_NEAR(make_contact(*wave("power:3"), 0.5).beta_c(), 12.0, 1e-14);
}

TEST(Waveforms, JumpsOnlyWhereTheWaveIsDiscontinuous) {
  EXPECT_TRUE(wave("sqr")->jump_at(0));
  EXPECT_TRUE(wave("sqr")->jump_at(1));
  EXPECT_TRUE(wave("str")->jump_at(0));
  EXPECT_TRUE(wave("stl")->jump_at(0));
  for (const char* name : {"tri", "sine", "power:2"}) {
    const auto w = wave(name);
    for (std::size_t i = 0; i < w->piece_count(); ++i) EXPECT_FALSE(w->jump_at(i)) << name << " " << i;
  }
}

TEST(Waveforms, PiecesAreMonotoneWithMonotoneSlope) {
  for (const char* name : {"sine", "power:1.5", "power:3"}) {
    const auto w = wave(name);
    for (std::size_t i = 0; i < w->piece_count(); ++i) {
      const double a = w->piece_begin(i), b = w->piece_end(i);
      const int dir = w->value(i, b) > w->value(i, a) ? 1 : -1;
      const int sdir = w->slope(i, b) > w->slope(i, a) ? 1 : -1;
      for (int j = 1; j <= 50; ++j) {
        const double x0 = a + (b - a) * (j - 1) / 50, x1 = a + (b - a) * j / 50;
        EXPECT_GE(dir * (w->value(i, x1) - w->value(i, x0)), -1e-15) << name << " piece " << i;
        EXPECT_GE(sdir * (w->slope(i, x1) - w->slope(i, x0)), -1e-12) << name << " piece " << i;
      }
    }
  }
}

TEST(Waveforms, NamesAndAliases) {
  EXPECT_EQ(parse_wave("tri").name, "triangle");
  EXPECT_EQ(parse_wave("str").name, "sawtooth-right");
  EXPECT_EQ(parse_wave("stl").name, "sawtooth-left");
  EXPECT_EQ(parse_wave("sqr").name, "square");
  EXPECT_EQ(parse_wave("harmonic").name, "sine");
  EXPECT_EQ(parse_wave("power:2.5").exponent.text(), "2.5");
  for (const char* bad : {"", "cosine", "power:", "power:0", "power:0.5", "power:x", "power:2x", "fourier:", "samples:"})
    EXPECT_THROW(parse_wave(bad), InputError) << bad;
  try {
    parse_wave("cosine");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cosine"), std::string::npos) << e.what();
  }
}

TEST(Waveforms, SamplesAreNormalisedAndReported) {
  // Four samples of the triangle, scaled by 3 and offset by 5: the normalised wave is the triangle.
  const std::string path = temp_file("tri_samples.txt", "# triangle\n2\n5\n8\n5\n");
  const auto w = make_waveform<double>(parse_wave("samples:" + path));
  EXPECT_TRUE(w->normalisation().applied);
  EXPECT_DOUBLE_EQ(w->normalisation().offset, 5.0);
  EXPECT_DOUBLE_EQ(w->normalisation().scale, 3.0);
  const auto tri = wave("tri");
  for (int j = 0; j < 20; ++j) EXPECT_NEAR((*w)(j / 20.0), (*tri)(j / 20.0), 1e-15);
  EXPECT_THROW(parse_wave("samples:" + temp_file("one.txt", "1\n")), InputError);
  EXPECT_THROW(make_waveform<double>(parse_wave("samples:" + temp_file("const.txt", "1 1 1\n"))), InputError);
  EXPECT_THROW(parse_wave("samples:" + temp_file("nan.txt", "1 nan 2\n")), InputError);
  EXPECT_THROW(parse_wave("samples:/nonexistent/file"), InputError);
}

TEST(Waveforms, FourierNormalisedWithFoundExtrema) {
  // 7 + 2 sin 2πφ + cos 4πφ: min −3 at φ = 3/4, max 1.5 at the roots of sin 2πφ = 1/2 (normalised
  // by half of 4.5).
  const std::string path = temp_file("f.txt", "0 7 0\n1 0 2\n2 1 0\n");
  const auto w = make_waveform<double>(parse_wave("fourier:" + path));
  EXPECT_DOUBLE_EQ(w->normalisation().offset, 7.0);
  EXPECT_NEAR(w->normalisation().scale, 2.25, 1e-15);
  EXPECT_NEAR(w->minimum(), -3.0 / 2.25, 1e-15);
  EXPECT_NEAR(w->maximum(), 1.5 / 2.25, 1e-15);
  EXPECT_NEAR((*w)(0.75), -3.0 / 2.25, 1e-15);
  EXPECT_THROW(parse_wave("fourier:" + temp_file("two.txt", "1 0\n")), InputError);
  EXPECT_THROW(parse_wave("fourier:" + temp_file("dup.txt", "1 0 1\n1 1 0\n")), InputError);
  EXPECT_THROW(make_waveform<double>(parse_wave("fourier:" + temp_file("zero.txt", "1 0 0\n0 3 0\n"))), InputError);
}

// A time column with non-uniform stamps (README, "File formats"): the solver at 40 digits against
// the exact rational lower envelope (envelope.hpp) of the same piecewise-linear signal, normalised
// exactly with the trapezoid mean Σ y_j (φ_{j+1} − φ_{j−1})/2.
TEST(Waveforms, TimeColumnMatchesTheExactEnvelope) {
  using envelope::Rational;
  const std::vector<Rational> phi{0, Rational(1, 10), Rational(1, 4), Rational(3, 10), Rational(11, 20), Rational(4, 5)};
  const std::vector<Rational> y{0, Rational(9, 10), Rational(1, 5), 1, Rational(-2, 5), -1};
  const std::size_t n = phi.size();
  Rational mean = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const Rational next = j + 1 < n ? phi[j + 1] : Rational(1), prev = j > 0 ? phi[j - 1] : Rational(phi[n - 1] - 1);
    mean += y[j] * (next - prev) / 2;
  }
  envelope::Vertices v;
  for (std::size_t j = 0; j < n; ++j) v.push_back({phi[j], y[j] - mean, y[j] - mean});  // scale (1 − (−1))/2 = 1
  ASSERT_EQ(envelope::mean(v), 0) << "the trapezoid mean is the mean of the piecewise-linear signal";
  // The same record, its clock started at 0 and at 10 s: the phases are (t − t_0)/(t_N − t_0).
  for (const char* stamps : {"time [s], value\n0, 0\n0.1, 0.9\n0.25, 0.2\n0.3, 1\n0.55, -0.4\n0.8, -1\n1, 0\n",
                             "time [s], value\n10, 0\n10.1, 0.9\n10.25, 0.2\n10.3, 1\n10.55, -0.4\n10.8, -1\n11, 0\n"}) {
    SCOPED_TRACE(stamps);
    const WaveSpec spec = parse_wave("samples:" + temp_file("time_column.csv", stamps));
    ASSERT_EQ(spec.times.size(), n + 1);
    const auto period = stamped_period(spec);
    ASSERT_TRUE(period);
    EXPECT_EQ(period->seconds, 1);
    PrecisionScope scope(50);
    const auto w = make_waveform<mpfr>(spec);
    for (const Rational& beta : {Rational(1, 10), Rational(1), Rational(5)})
      for (const Rational& gamma : {Rational(3), Rational(1, 2), Rational(-1, 5), Rational(-7, 10)}) {
        if (!(gamma + envelope::range(v).second > 0)) continue;
        const Rational exact = envelope::mu(v, beta, gamma).mu;
        const mpfr b(static_cast<mpfr>(numerator(beta)) / static_cast<mpfr>(denominator(beta)));
        const mpfr g(static_cast<mpfr>(numerator(gamma)) / static_cast<mpfr>(denominator(gamma)));
        const mpfr got = solve(*w, b, g).mu;
        const mpfr want = static_cast<mpfr>(numerator(exact)) / static_cast<mpfr>(denominator(exact));
        EXPECT_LE(static_cast<double>(abs(got - want) / want), 1e-38) << "beta " << beta << ", gamma " << gamma;
      }
  }
}

// The grammar's refusals name what to do (README, "File formats"); the same table in every layout
// reads the same samples.
TEST(Waveforms, SampleFileGrammar) {
  const std::vector<std::string> y{"0", "0.9", "0.2", "1", "-0.4", "-1", "-0.3"};
  std::string column, line;
  for (const auto& v : y) {
    column += v + "\r\n";
    line += (line.empty() ? "" : " ; ") + v;
  }
  EXPECT_EQ(texts(parse_wave("samples:" + temp_file("g_column.txt", "\xEF\xBB\xBF" + column)).samples), y);
  EXPECT_EQ(texts(parse_wave("samples:" + temp_file("g_line.txt", line + "\n")).samples), y);
  const auto refused = [](const std::string& name, const std::string& text, const std::string& word) {
    try {
      parse_wave("samples:" + temp_file(name, text));
      ADD_FAILURE() << name << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << name << ": " << e.what();
    }
  };
  refused("g_two.txt", "0 0\n1 1\n2 0\n3 -1\n", "two columns");
  refused("g_end.txt", "0\n1\n0\n-1\n0\n", "repeats the first");
  refused("g_periods.txt", "0 1 -1 0 1 -1\n", "2 identical periods");
  refused("g_time_periods.csv", "t,y\n0,0\n1,1\n2,-1\n3,0\n4,1\n5,-1\n6,0\n", "2 identical periods");
  refused("g_time_end.csv", "t,y\n0,0\n1,1\n3,-1\n", "not uniform");  // no end point, steps 1 and 2
  refused("g_ragged.txt", "0\n1\n2 3\n", "same number");
  refused("g_nul.txt", std::string("0\n1\0\n-1\n", 7), "NUL");
  // No end point but uniform stamps (a DAQ's t_j = j dt, exact or printed rounded): the samples at
  // phi = j/N, the period N dt.
  for (const auto& [name, text, period] : {std::tuple<const char*, const char*, const char*>{"g_daq.csv", "t,y\n0,0\n1,1\n2,-1\n", "3"},
                                           {"g_daq_rounded.csv", "t,y\n0,0\n3.333e-5,1\n6.667e-5,-1\n", "1.00005e-4"}}) {
    const WaveSpec daq = parse_wave("samples:" + temp_file(name, text));
    EXPECT_EQ(texts(daq.samples), (std::vector<std::string>{"0", "1", "-1"})) << name;
    EXPECT_TRUE(daq.times.empty()) << name;
    PrecisionScope scope(60);
    ASSERT_TRUE(daq.period_from_stamps) << name;
    EXPECT_EQ(mpfr(daq.period_from_stamps->text()), mpfr(period)) << name << ": " << *daq.period_from_stamps;
  }
  // Values repeating at a non-uniform time shift are not several periods.
  EXPECT_NO_THROW(parse_wave("samples:" + temp_file("g_time_ok.csv", "t,y\n0,0\n1,1\n2,-1\n3,0\n5,1\n6,-1\n7,0\n")));
}

// A value column chosen by name or 1-based index (WaveReadOptions): more than two columns, the
// header's time column still giving the phases; the canonical name records the column.
// A record of K noisy periods (README, "File formats": refused without periods, averaged with
// them) at the detector's edges: K = N/8 (the largest candidate below 512 samples), K = 64 (the
// largest at 512), N = 16 (the fewest samples tried, one candidate) and K = 3. Without periods the
// message names K itself; with periods = K the wave is, value for value, that of the record of the
// K values' sums at each phase, summed here in integers (the normalised wave of the mean is the
// sum's).
TEST(Waveforms, RepeatedPeriodsFoundUpToTheLargestCandidateAndAveraged) {
  for (const auto& [n, k] : {std::pair<int, int>{128, 16}, {512, 64}, {16, 2}, {24, 3}}) {
    SCOPED_TRACE(std::to_string(n) + " samples of " + std::to_string(k) + " periods");
    std::vector<long long> y(static_cast<std::size_t>(n));  // in units of 10^-9
    std::string record;
    for (int j = 0; j < n; ++j) {
      const double v = std::sin(2 * M_PI * k * j / n) + 0.03 * std::sin(0.7 * j * j);  // noise of 4 % rms
      y[static_cast<std::size_t>(j)] = std::llround(v * 1e9);
      record += decimal_nanos(y[static_cast<std::size_t>(j)]) + "\n";
    }
    const std::string name = "periods_" + std::to_string(n) + "_" + std::to_string(k);
    const std::string path = temp_file(name + ".txt", record);
    try {
      parse_wave("samples:" + path);
      ADD_FAILURE() << "accepted as one period";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("look like " + std::to_string(k) + " periods"), std::string::npos) << e.what();
    }
    std::string sums;
    const int m = n / k;
    for (int j = 0; j < m; ++j) {
      long long sum = 0;
      for (int p = 0; p < k; ++p) sum += y[static_cast<std::size_t>(p * m + j)];
      sums += decimal_nanos(sum) + "\n";
    }
    WaveReadOptions options;
    options.periods = k;
    const auto averaged = make_waveform<double>(parse_wave("samples:" + path, options));
    const auto summed = make_waveform<double>(parse_wave("samples:" + temp_file(name + "_sums.txt", sums)));
    for (int j = 0; j <= 4 * m; ++j) {
      const double phi = static_cast<double>(j) / (4 * m);
      EXPECT_EQ((*averaged)(phi), (*summed)(phi)) << "phi " << phi;
    }
  }
}

TEST(Waveforms, ColumnSelection) {
  const std::string path = temp_file("c_multi.csv", "t;a;b\n0;1;10\n1;3;20\n3;-1;40\n4;1;10\n");
  const WaveSpec b = parse_wave("samples:" + path, {"b"});
  EXPECT_EQ(texts(b.samples), (std::vector<std::string>{"10", "20", "40"}));
  EXPECT_EQ(texts(b.times), (std::vector<std::string>{"0", "1", "3", "4"}));
  EXPECT_EQ(b.name, "samples:" + path + "#b");
  EXPECT_EQ(b.column, "b");
  EXPECT_EQ(b.time_column, "t");
  const WaveSpec three = parse_wave("samples:" + path, {"3"});  // by index: the same wave, the same name
  EXPECT_EQ(texts(three.samples), texts(b.samples));
  EXPECT_EQ(three.name, b.name);
  EXPECT_EQ(texts(parse_wave("samples:" + path, {"a"}).samples), (std::vector<std::string>{"1", "3", "-1"}));
  // Without a column: names unchanged, and more than two columns still refused.
  const std::string two = temp_file("c_two.csv", "time,value\n0,0\n1,1\n2,-1\n3,0\n");
  EXPECT_EQ(parse_wave("samples:" + two).name, "samples:" + two);
  EXPECT_EQ(parse_wave("samples:" + two, WaveReadOptions{}).name, "samples:" + two);
  EXPECT_EQ(parse_wave("sine", WaveReadOptions{}).name, "sine");
  // No header: an index only, uniform phases.
  const std::string bare = temp_file("c_bare.txt", "0 5 1\n1 6 1\n2 4 1\n");
  const WaveSpec second = parse_wave("samples:" + bare, {"2"});
  EXPECT_EQ(texts(second.samples), (std::vector<std::string>{"5", "6", "4"}));
  EXPECT_TRUE(second.times.empty());
  EXPECT_EQ(second.name, "samples:" + bare + "#2");

  const auto refused = [](const std::function<void()>& f, const std::string& words) {
    try {
      f();
      ADD_FAILURE() << "accepted; expected '" << words << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  };
  refused([&] { parse_wave("samples:" + path); }, "3 columns ('t', 'a', 'b'): expected one column of values");
  refused([&] { parse_wave("samples:" + path, {"c"}); },
          "column 'c' is not in the header of '" + path + "': expected one of 't', 'a', 'b' or an index 1 to 3");
  refused([&] { parse_wave("samples:" + path, {"4"}); },
          "column '4' of '" + path + "' is out of range: the file has 3 columns, expected an index 1 to 3");
  refused([&] { parse_wave("samples:" + path, {"0"}); }, "is out of range: the file has 3 columns");
  refused([&] { parse_wave("samples:" + path, {"t"}); }, "column 't' of '" + path + "' is its time column 't': expected a column of values");
  refused([&] { parse_wave("samples:" + path, {"1"}); }, "is its time column 't'");
  refused([&] { parse_wave("samples:" + path, {"b\r"}); }, "column 'b\\r' is not in the header");
  refused([&] { parse_wave("samples:" + bare, {"b"}); },
          "column 'b': '" + bare + "' has no header line of names, expected a 1-based column index 1 to 3");
  refused([&] { parse_wave("sine", {"2"}); }, "column '2' given for wave 'sine': a column applies to samples:FILE waves only, expected no column");
  refused([&] { parse_wave("power:2", {"2"}); }, "a column applies to samples:FILE waves only");
  refused([&] { parse_wave("fourier:" + temp_file("c_f.txt", "1 0 1\n"), {"a_k"}); }, "a column applies to samples:FILE waves only");
  refused([&] { parse_wave("samples:" + temp_file("c_dup.csv", "t,v,v\n0,1,2\n1,2,3\n2,1,2\n"), {"v"}); },
          "column 'v' names columns 2 and 3 of");
  refused([&] { parse_wave("samples:" + temp_file("c_times.csv", "t,time,v\n0,0,2\n1,1,3\n2,2,2\n"), {"v"}); },
          "the header names 2 time columns, 't' and 'time': expected at most one");
}

// The normalisation reported (model.md, "Waveform catalogue"), against hand computation.
// Files as a lab PC writes them (README, "File formats"): ';' fields with decimal commas, a time
// column named in German or by its unit, a header in UTF-8 or Windows-1252, a preamble skipped by
// skip_rows. Each is the same wave as the file written with points, in English, without preamble.
TEST(Waveforms, LabFilesAsWritten) {
  const std::string rows = "0;0,75\n0,0000125;1,5\n0,000025;0,75\n0,0000375;0\n";
  const WaveSpec plain = parse_wave("samples:" + temp_file("lab_plain.csv", "time [s],disp [um]\n0,0.75\n0.0000125,1.5\n"
                                                                             "0.000025,0.75\n0.0000375,0\n"));
  ASSERT_TRUE(plain.period_from_stamps);
  const auto same = [&](const WaveSpec& w, const std::string& what) {
    EXPECT_EQ(texts(w.samples), texts(plain.samples)) << what;
    ASSERT_TRUE(w.period_from_stamps) << what << ": the time column was not recognised";
    EXPECT_EQ(w.period_from_stamps->text(), plain.period_from_stamps->text()) << what;
  };
  same(parse_wave("samples:" + temp_file("lab_de.csv", "Zeit [s];Weg [\xC2\xB5m]\n" + rows)), "UTF-8");
  const WaveSpec latin = parse_wave("samples:" + temp_file("lab_1252.csv", "Zeit [s];Weg [\xB5m]\n" + rows));
  same(latin, "Windows-1252");
  EXPECT_EQ(latin.value_column, "Weg [\xC2\xB5m]");  // read as the character µ, kept as UTF-8
  EXPECT_EQ(column_unit(latin.value_column), "\xC2\xB5m");
  EXPECT_EQ(detail::visible(latin.value_column), "Weg [\xC2\xB5m]");  // printed as written
  // Time columns by name in five languages or by a unit of time; other units are values.
  for (const char* name : {"Zeit", "temps (s)", "tiempo [ms]", "tempo", "Messzeit [s]", "dt/ms", "Zeit in \xC2\xB5s", "T"})
    same(parse_wave("samples:" + temp_file("lab_name.csv", std::string(name) + ";y\n" + rows)), name);
  for (const char* name : {"v [m/s]", "m/s", "Weg [\xC2\xB5m]", "Kraft (N)", "speed_s", "Strom in A", "T [\xC2\xB0" "C]",
                           "Temperatur (K)"}) {
    SCOPED_TRACE(name);
    try {
      parse_wave("samples:" + temp_file("lab_value.csv", std::string(name) + ";y\n" + rows));
      ADD_FAILURE() << "a time column named " << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("expected one column of values, or a header naming one column 'time'"),
                std::string::npos) << e.what();
    }
  }
  // A rig's temperature column "T [°C]" beside "Zeit [s]": one time column, the value chosen.
  const std::string three = temp_file("lab_three.csv", "Zeit [s];Weg [\xC2\xB5m];T [\xC2\xB0" "C]\n0;0,75;21\n0,0000125;1,5;21\n"
                                                        "0,000025;0,75;22\n0,0000375;0;22\n");
  same(parse_wave("samples:" + three, {"Weg [\xC2\xB5m]"}), "three columns");
  // A preamble: named with the lines to skip, then skipped; line numbers stay the file's.
  const std::string preamble = temp_file("lab_preamble.csv", "Messung: Probe 3\nDatum: 05.12.2026\n\nZeit [s];Weg [\xC2\xB5m]\n" + rows);
  try {
    parse_wave("samples:" + preamble);
    ADD_FAILURE() << "a preamble read as samples";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":1 sample = 'Messung:'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("skip them with skip_rows 3"), std::string::npos) << e.what();
  }
  WaveReadOptions skip;
  skip.skip_rows = 3;
  same(parse_wave("samples:" + preamble, skip), "skip_rows 3");
  skip.skip_rows = 1;  // too few: "Datum: 05.12.2026" is then the header, "Zeit [s];…" a row
  EXPECT_THROW(parse_wave("samples:" + preamble, skip), InputError);
  EXPECT_THROW(parse_wave("sine", skip), InputError);
  skip.skip_rows = -1;
  EXPECT_THROW(parse_wave("samples:" + preamble, skip), InputError);
  // ',' between fields and decimal commas stay ambiguous: refused as before.
  EXPECT_THROW(parse_wave("samples:" + temp_file("lab_commas.csv", "0,75\n1,5\n0,75\n0\n")), InputError);
  // A missing file is its own error (Python's FileNotFoundError).
  EXPECT_THROW(parse_wave("samples:/nonexistent/lab.csv"), MissingFileError);
}

TEST(Waveforms, DescribeNormalisation) {
  using Pairs = std::vector<std::pair<std::string, std::string>>;
  // 2, 5, 8, 5 at φ = j/4: mean 5, min 2, max 8, scale (8 − 2)/2 = 3.
  EXPECT_EQ(describe_normalisation(parse_wave("samples:" + temp_file("d_tri.txt", "2\n5\n8\n5\n")), 6),
            (Pairs{{"samples", "4"}, {"end_point", "none"}, {"time_column", "none"}, {"period", "1 (uniform phases)"},
                   {"column", "1"}, {"raw_mean", "5.00000"}, {"raw_min", "2.00000"}, {"raw_max", "8.00000"},
                   {"scale", "3.00000"}, {"factor", "0.333333"}}));
  // 0 0 1: mean 1/3, scale 1/2.
  const WaveSpec third = parse_wave("samples:" + temp_file("d_third.txt", "0 0 1\n"));
  const Pairs t = describe_normalisation(third, 5);
  EXPECT_EQ(t[5], (std::pair<std::string, std::string>{"raw_mean", "0.33333"}));
  EXPECT_EQ(t[8], (std::pair<std::string, std::string>{"scale", "0.50000"}));
  // The same numbers as the wave's: 17 digits read back give the double normalisation exactly.
  const auto w = make_waveform<double>(third);
  EXPECT_EQ(std::strtod(describe_normalisation(third, 17)[5].second.c_str(), nullptr), w->normalisation().offset);
  EXPECT_EQ(std::strtod(describe_normalisation(third, 17)[8].second.c_str(), nullptr), w->normalisation().scale);
  // Column b at t = 0, 1, 3 (period 4, end point 10 dropped): phases 0, 1/4, 3/4, trapezoid
  // weights (φ_{j+1} − φ_{j−1})/2 = 1/4, 3/8, 3/8: mean 10/4 + 20·3/8 + 40·3/8 = 25; min 10, max 40, scale 15.
  const std::string path = temp_file("d_multi.csv", "t;a;b\n0;1;10\n1;3;20\n3;-1;40\n4;1;10\n");
  EXPECT_EQ(describe_normalisation(parse_wave("samples:" + path, {"b"}), 4),
            (Pairs{{"samples", "3"}, {"end_point", "dropped"}, {"time_column", "t"}, {"period", "4.000"}, {"column", "b"},
                   {"raw_mean", "25.00"}, {"raw_min", "10.00"}, {"raw_max", "40.00"}, {"scale", "15.00"},
                   {"factor", "0.06667"}}));
  // Column a: 1, 3, −1 with the same weights: mean 1/4 + 9/8 − 3/8 = 1; scale 2.
  const Pairs a = describe_normalisation(parse_wave("samples:" + path, {"a"}), 4);
  EXPECT_EQ(a[5].second, "1.000");
  EXPECT_EQ(a[8].second, "2.000");
  // y = 0, 2, 1, −1, −2 at t = 0, 1, 3, 4, 6, period 7: trapezoid weights 1/7, 3/14, 3/14, 3/14,
  // 3/14, mean exactly 0 (shown as 0, not as the rounding left at the working precision).
  const WaveSpec zero = parse_wave("samples:" + temp_file("d_zero.csv", "t,y\n0,0\n1,2\n3,1\n4,-1\n6,-2\n7,0\n"));
  const Pairs z = describe_normalisation(zero, 8);
  EXPECT_EQ(z[3].second, "7.0000000");
  EXPECT_EQ(z[5].second, "0");
  EXPECT_EQ(z[8].second, "2.0000000");
  // Fourier 7 + 2 sin 2πφ + cos 4πφ: max 1.5 + 7, min −3 + 7 (FourierNormalisedWithFoundExtrema).
  EXPECT_EQ(describe_normalisation(parse_wave("fourier:" + temp_file("d_f.txt", "0 7 0\n1 0 2\n2 1 0\n")), 6),
            (Pairs{{"harmonics", "2"}, {"mean_removed", "7.00000"}, {"peak_to_peak", "4.50000"}, {"scale", "2.25000"},
                   {"factor", "0.444444"}}));
  EXPECT_EQ(describe_normalisation(parse_wave("sine"), 6),
            (Pairs{{"normalisation", "none (catalogue wave, already zero mean and max - min = 2)"}}));
  EXPECT_EQ(describe_normalisation(parse_wave("power:3"), 6).size(), 1u);
  EXPECT_THROW(describe_normalisation(parse_wave("sine"), 0), InputError);
}

TEST(Numbers, StrictDecimalGrammar) {
  for (const char* good : {"1", "-0.3", "+2.5e-3", ".5", "5.", "1E10"}) EXPECT_NO_THROW(check_decimal(good, "x")) << good;
  for (const char* bad : {"", "1.5x", "nan", "inf", "-inf", "0x10", "1e400", "1.2.3", " 1", "1 ", "--1"})
    EXPECT_THROW(check_decimal(bad, "x"), InputError) << bad;
}

TEST(Numbers, FormatSignificantDigits) {
  EXPECT_EQ(format_significant(0.4, 5), "0.40000");
  EXPECT_EQ(format_significant(1.0, 3), "1.00");
  EXPECT_EQ(format_significant(0.0123, 3), "0.0123");
  EXPECT_EQ(format_significant(12.5, 4), "12.50");
  EXPECT_EQ(format_significant(-0.5, 2), "-0.50");
  EXPECT_EQ(format_significant(1.5e-9, 3), "1.50e-09");
  PrecisionScope p(60);
  EXPECT_EQ(format_significant(mpfr(1) / 3, 40), "0." + std::string(40, '3'));
}

// double and long double print through std::to_chars; its digits must be MPFR's correctly rounded
// ones (mpfr_get_str of an exact copy, a separate implementation): random values over the whole
// exponent range, subnormals, and exact decimal ties (2.5, 0.125, 1e23's neighbours), which both
// round to even.
template <class T>
void check_digits_against_mpfr(int bits, const std::vector<T>& extra) {
  std::mt19937_64 rng(20261124);
  std::vector<T> xs = extra;
  for (int i = 0; i < 20000; ++i) {
    const T m = T(rng() >> 11) / T(1ULL << 53) + T(rng() >> 11) / T(1ULL << 53) / T(1ULL << 53);
    // Every normal binade; one value in ten subnormal (at least 2 bits of precision kept).
    const int lo = std::numeric_limits<T>::min_exponent - 1, hi = std::numeric_limits<T>::max_exponent - 1;
    const int e = i % 10 ? lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1))
                         : lo - 1 - static_cast<int>(rng() % static_cast<unsigned>(bits - 3));
    xs.push_back((i % 2 ? -1 : 1) * std::ldexp(m + 1, e));
  }
  for (const T x : xs)
    for (const int digits : {1, 2, 3, 6, 15, 17, 21, 30}) {
      mpfr_t v;
      mpfr_init2(v, bits);
      if constexpr (std::is_same_v<T, double>)
        mpfr_set_d(v, x, MPFR_RNDN);
      else
        mpfr_set_ld(v, x, MPFR_RNDN);
      mpfr_exp_t e10 = 0;
      char* raw = mpfr_get_str(nullptr, &e10, 10, static_cast<std::size_t>(digits), v, MPFR_RNDN);
      std::string want(raw);
      mpfr_free_str(raw);
      mpfr_clear(v);
      // The same digits and decimal exponent, read back from the formatted text.
      std::string got = format_significant(x, digits), mantissa;
      long exponent = 0;
      const std::size_t epos = got.find('e');
      if (epos != std::string::npos) exponent = std::stol(got.substr(epos + 1)) + 1;
      std::string body = got.substr(0, epos), sign;
      if (body[0] == '-') sign = "-", body.erase(0, 1);
      const std::size_t dot = body.find('.');
      if (epos == std::string::npos) exponent = static_cast<long>(dot == std::string::npos ? body.size() : dot);
      for (const char c : body)
        if (c != '.') mantissa += c;
      const std::size_t lead = mantissa.find_first_not_of('0');
      exponent -= static_cast<long>(lead);
      mantissa.erase(0, lead);
      // An integer part longer than the digits is padded with zeros ("100" for 99.5 at 1 digit).
      ASSERT_GE(mantissa.size(), static_cast<std::size_t>(digits)) << got;
      ASSERT_EQ(mantissa.find_first_not_of('0', static_cast<std::size_t>(digits)), std::string::npos) << got;
      mantissa.resize(static_cast<std::size_t>(digits));
      ASSERT_EQ(sign + mantissa, want) << x << " at " << digits << " digits: " << got;
      ASSERT_EQ(exponent, static_cast<long>(e10)) << x << " at " << digits << " digits: " << got;
    }
}

TEST(Numbers, FormatSignificantOfHardwareTypesAsMpfr) {
  check_digits_against_mpfr<double>(53, {2.5, 0.125, 0.375, 1e23, std::nextafter(1e23, 0.0), 5e-324, 1.7976931348623157e308,
                                         0.5, 9.5, 99.5, 1e15, 1e-5, 9.9999999999999995e-6});
  check_digits_against_mpfr<long double>(64, {2.5L, 0.125L, 1e23L, std::numeric_limits<long double>::denorm_min(),
                                              std::numeric_limits<long double>::max(), 0.5L, 99.5L});
}

// Waveform::value_error's contract (waveform.hpp): |value(φ) − w(φ)| ≤ eps·(max − min + value_error)
// at every φ, w being the exact wave the input defines; the solver's rounding bounds rest on it
// (solver.hpp, value_bound). Reference: the same file read at 60 digits. The Fourier sum's error
// grows with the harmonics (the recurrence's angle carries k·(2π + 4) eps), so without its own
// term the bound would not hold for 40 harmonics; samples carry their phases' rounding. The same
// with value_error(i) on the piece i holding φ (away from a rounding of its ends, which the
// phases below are), the bound the solver charges an area over that piece; `worst_piece` is its
// largest ratio.
template <class Real>
void expect_value_error_bounds(const std::string& spec, int phases, double* worst, double* worst_piece) {
  const auto w = make_waveform<Real>(parse_wave(spec));
  const mpfr eps(std::numeric_limits<Real>::epsilon());
  const mpfr range = mpfr(w->maximum()) - mpfr(w->minimum());
  const mpfr allowed = eps * (range + mpfr(w->value_error()));
  PrecisionScope scope(60);
  const auto exact = make_waveform<mpfr>(parse_wave(spec));
  for (int j = 0; j < phases; ++j) {
    const Real phi = Real(j) / phases + Real(0.37) / phases;  // exact in Real and in mpfr
    const mpfr err = abs(mpfr((*w)(phi)) - (*exact)(mpfr(phi)));
    ASSERT_LE(err, allowed) << spec << " at phi = " << static_cast<double>(phi);
    *worst = std::max(*worst, static_cast<double>(err / allowed));
    std::size_t i = w->piece_count() - 1;
    while (i > 0 && phi < w->piece_begin(i)) --i;
    const mpfr piece_allowed = eps * (range + mpfr(w->value_error(i)));
    ASSERT_LE(mpfr(w->value_error(i)), mpfr(w->value_error())) << spec << " piece " << i;
    ASSERT_LE(err, piece_allowed) << spec << " at phi = " << static_cast<double>(phi) << " on piece " << i;
    *worst_piece = std::max(*worst_piece, static_cast<double>(err / piece_allowed));
  }
}

TEST(Waveforms, ValueErrorBoundsTheEvaluationError) {
  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> coefficient(-1, 1), noise(-0.03, 0.03);
  std::ostringstream fourier, samples;
  fourier << std::setprecision(17);
  for (int k = 1; k <= 40; ++k) fourier << k << ' ' << coefficient(random) << ' ' << coefficient(random) << '\n';
  samples << std::setprecision(9);
  for (int j = 0; j < 200; ++j) samples << 2 * std::sin(6.283185307179586 * j / 200) + noise(random) << '\n';
  const std::string f = "fourier:" + temp_file("forty.txt", fourier.str()), s = "samples:" + temp_file("noisy.txt", samples.str());
  for (const std::string& spec : {f, s}) {
    double worst_d = 0, worst_l = 0, piece_d = 0, piece_l = 0;
    expect_value_error_bounds<double>(spec, 5000, &worst_d, &piece_d);
    expect_value_error_bounds<long double>(spec, 5000, &worst_l, &piece_l);
    std::printf("%s: largest error %.3g (double), %.3g (long double) of the allowance; piece by piece %.3g, %.3g\n",
                spec.c_str(), worst_d, worst_l, piece_d, piece_l);
  }
}

// acos_fast (the sine's contact boundaries and onsets in mpfr; its early Halley steps at reduced
// precision) against MPFR's own acos at four times the bits: within 4·2^−p of the result (2 to
// 4 ulp), as Halley's last step leaves about eps/4096 and the rounding of 2h and of π − acos(−y)
// adds an ulp each. The points reach the ends: y = ±1, y = 1 − 10^(−digits/2) and
// y = 1 − 10^(2−digits). The last's √((1 − y)/2) is below double's range at 1000 and 3000 digits,
// as is the first's at 3000: the guess is then 0 and the reduced-precision steps are skipped.
TEST(Waveforms, AcosFastIsMpfrsAcosToWithinFourUlp) {
  for (unsigned digits : {20u, 50u, 300u, 1000u, 3000u}) {
    PrecisionScope scope(digits);
    const mpfr_prec_t bits = mpfr_get_prec(mpfr(1).backend().data());
    std::vector<mpfr> ys;
    for (const char* y : {"-1", "-0.99999999", "-0.5", "-1e-30", "0", "1e-30", "0.3", "0.5", "0.70710678118654752440", "0.9", "0.999999"})
      ys.emplace_back(y);
    ys.push_back(1 - pow(mpfr(10), -static_cast<int>(digits) / 2));
    ys.push_back(1 - pow(mpfr(10), -static_cast<int>(digits) + 2));
    ys.push_back(mpfr(1));
    for (const mpfr& y : ys) {
      const mpfr got = detail::acos_fast(y);
      mpfr_t ref, diff;
      mpfr_inits2(4 * bits, ref, diff, static_cast<mpfr_ptr>(nullptr));
      mpfr_acos(ref, y.backend().data(), MPFR_RNDN);
      mpfr_sub(diff, got.backend().data(), ref, MPFR_RNDN);
      mpfr_abs(diff, diff, MPFR_RNDN);
      mpfr_t allowed;
      mpfr_init2(allowed, 4 * bits);
      mpfr_abs(allowed, ref, MPFR_RNDN);
      mpfr_mul_2si(allowed, allowed, 2 - bits, MPFR_RNDN);  // 4 ulp of the result
      EXPECT_LE(mpfr_cmp(diff, allowed), 0) << "digits " << digits << ", y = " << y.str(30) << ": off by "
                                            << mpfr_get_d(diff, MPFR_RNDN) << ", allowed " << mpfr_get_d(allowed, MPFR_RNDN);
      mpfr_clears(ref, diff, allowed, static_cast<mpfr_ptr>(nullptr));
    }
  }
}

// The sine's trig anchor (mpfr): one MPFR sin_cos at an anchor h, at 64 bits more, gives sin and
// cos near h and near ±2h + jπ/2 by Taylor and a rotation, rounded only where mpfr_can_round
// decides. Every value it gives must be MPFR's own sin_cos at the working precision, bit for bit
// (the reference: mpfr_sin_cos itself); it must decide nearly always (a refusal costs the call),
// and refuse a phase too far from its anchor for its Taylor terms.
TEST(Waveforms, TrigAnchorGivesMpfrsSinCosBitForBit) {
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> unit(0, 1);
  for (unsigned digits : {20u, 50u, 300u, 1000u}) {
    PrecisionScope scope(digits);
    const mpfr_prec_t p = mpfr_get_prec(mpfr(1).backend().data());
    const mpfr half_pi = boost::math::constants::half_pi<mpfr>();
    int tried = 0, decided = 0;
    for (int trial = 0; trial < 100; ++trial) {
      // h in (0, π/4] with all p bits in use.
      mpfr h = mpfr(unit(rng)) * boost::math::constants::pi<mpfr>() / 4;
      h += ldexp(mpfr(unit(rng)), -60) * h;
      detail::TrigAnchor anchor;
      anchor.set(h.backend().data());
      for (int k = 0; k < 4; ++k) {
        // |δ| from 2^−(P/16), P = p + 64 (about 16 Taylor terms), down to below h's last bit.
        const int e = static_cast<int>(p + 64) / 16 + 1 + static_cast<int>(unit(rng) * static_cast<double>(p));
        const mpfr delta = ldexp(mpfr(unit(rng) - 0.5), -e);
        const int j = static_cast<int>(unit(rng) * 5) - 2, sigma = unit(rng) < 0.5 ? -1 : 1;
        for (int near_2h = 0; near_2h < 2; ++near_2h) {
          const mpfr x = near_2h ? mpfr(sigma * 2 * h + j * half_pi + delta) : mpfr(h + delta);
          mpfr s, c, rs, rc;
          mpfr_sin_cos(rs.backend().data(), rc.backend().data(), x.backend().data(), MPFR_RNDN);
          const bool ok = near_2h ? anchor.near_twice(x.backend().data(), s.backend().data(), c.backend().data())
                                  : anchor.near(x.backend().data(), s.backend().data(), c.backend().data());
          ++tried;
          if (!ok) continue;
          ++decided;
          EXPECT_TRUE(mpfr_equal_p(s.backend().data(), rs.backend().data()) && mpfr_equal_p(c.backend().data(), rc.backend().data()))
              << digits << " digits, x = " << x.str(40) << (near_2h ? " near 2h" : " near h") << ": sin " << s.str(40)
              << " against " << rs.str(40);
        }
      }
      // Too far for 24 Taylor terms at this precision, in every form σθ + jπ/2 + δ (θ in
      // [0.05, 0.1], x = θ + 2^−(p/32) ≤ 0.35: with σ = −1 the δ is larger, with j ≠ 0 above 1):
      // refused.
      detail::TrigAnchor small;
      const mpfr theta = mpfr(0.05 + 0.05 * unit(rng));
      small.set(theta.backend().data());
      mpfr s, c;
      EXPECT_FALSE(small.near(mpfr(theta + ldexp(mpfr(1), -static_cast<int>(p) / 32)).backend().data(), s.backend().data(),
                              c.backend().data()));
    }
    EXPECT_GE(decided, tried * 99 / 100) << digits << " digits";
    std::printf("%u digits: %d of %d decided by the anchor\n", digits, decided, tried);
  }
}

// The sine's contact boundaries and onsets in mpfr take their sine and cosine from acos's anchor
// from 500 bits (primed into the trig cache; at 50 digits the call): the value and slope there
// are those of MPFR's sin_cos of the reduced argument, bit for bit, as the phase's own call gives
// them (computed here from the definition: φ = k/4 + r, 2πr at the working precision, k quarter
// turns).
TEST(Waveforms, SineBoundaryAndOnsetTrigIsTheCallsBits) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (unsigned digits : {50u, 300u, 1000u}) {
    PrecisionScope scope(digits);
    const auto w = make_waveform<mpfr>(parse_wave("sine"));
    const mpfr two_pi = boost::math::constants::two_pi<mpfr>();
    auto reference = [&](const mpfr& phi) {
      const long k = static_cast<long>(floor(4 * phi + mpfr(1) / 2));
      const mpfr arg = two_pi * (phi - mpfr(k) / 4);
      mpfr s, c;
      mpfr_sin_cos(s.backend().data(), c.backend().data(), arg.backend().data(), MPFR_RNDN);
      const long q = ((k % 4) + 4) % 4;
      return q == 0 ? std::pair{s, c} : q == 1 ? std::pair{c, mpfr(-s)} : q == 2 ? std::pair{mpfr(-s), mpfr(-c)} : std::pair{mpfr(-c), s};
    };
    auto expect_same = [&](std::size_t i, const mpfr& phi, const char* what) {
      const auto [v, sl] = w->value_and_slope(i, phi);
      const auto [s, c] = reference(phi);
      EXPECT_TRUE(mpfr_equal_p(v.backend().data(), s.backend().data())) << digits << " digits, " << what << " at " << phi.str(30);
      EXPECT_TRUE(mpfr_equal_p(sl.backend().data(), mpfr(two_pi * c).backend().data()))
          << digits << " digits, " << what << " at " << phi.str(30);
    };
    for (int trial = 0; trial < 20; ++trial) {
      const mpfr y = mpfr(2 * unit(rng) - 1) + ldexp(mpfr(unit(rng)), -70);
      for (std::size_t i = 0; i < 4; ++i) expect_same(i, *w->solve_value(i, y), "boundary");
      const mpfr b = mpfr(unit(rng)) * two_pi;
      for (std::size_t i : {std::size_t(0), std::size_t(3)}) expect_same(i, *w->solve_slope(i, b), "onset");
    }
  }
}

}  // namespace
