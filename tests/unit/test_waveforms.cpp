// Waveform catalogue and user waveforms (model.md, "Waveform catalogue"; Eq. 16).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "vibrofric/catalogue.hpp"
#include "vibrofric/numbers.hpp"
#include "vibrofric/solver.hpp"

namespace {

using namespace vibrofric;

std::unique_ptr<Waveform<double>> wave(const std::string& name) { return make_waveform<double>(parse_wave(name)); }

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
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
  EXPECT_EQ(parse_wave("power:2.5").exponent, "2.5");
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
  const std::string path = temp_file("tri_samples.txt", "# triangle\n2 5\n8\n5\n");
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

}  // namespace
