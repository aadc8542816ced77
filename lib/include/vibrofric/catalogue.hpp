// Waveform names and files (model.md, "Waveform catalogue"): parsed once, without a number type,
// then built at any precision by make_waveform<Real>. Numbers are kept as decimal strings so that
// each precision reads them exactly ("0.1" at 100 digits is 0.1 to 100 digits).
#pragma once
#include <array>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "vibrofric/errors.hpp"
#include "vibrofric/numbers.hpp"
#include "vibrofric/user_waveforms.hpp"
#include "vibrofric/waveform.hpp"

namespace vibrofric {

enum class WaveKind { sine, triangle, sawtooth_right, sawtooth_left, square, power, fourier, samples };

struct WaveSpec {
  WaveKind kind = WaveKind::sine;
  std::string name;      // canonical: "sine", "triangle", …, "power:2.5", "fourier:FILE"
  std::string exponent;  // power:p, as written
  struct Harmonic {
    unsigned k;
    std::string a, b;
  };
  std::vector<Harmonic> harmonics;  // fourier: w = Σ a_k cos 2πkφ + b_k sin 2πkφ
  std::vector<std::string> samples;  // samples: y_j at φ = j/N, or at the times below
  std::vector<std::string> times;    // samples with a time column: t_0 … t_N (t_N − t_0 = the period), else empty
};

// Accepts sine, harmonic, triangle|tri, sawtooth-right|str, sawtooth-left|stl, square|sqr,
// power:P (P ≥ 1), fourier:FILE, samples:FILE. Throws InputError naming the text otherwise.
WaveSpec parse_wave(const std::string& text);

// Names of the catalogue waves, for help texts and tests.
const std::vector<std::string>& catalogue_names();

// Strict decimal grammar: [+-]digits[.digits][e[+-]digits], finite, within double's range.
// Throws InputError naming `what` and the text.
void check_decimal(const std::string& text, const std::string& what);

// Decimal text to Real at the current precision (after check_decimal).
template <class Real>
Real parse_real(const std::string& text, const std::string& what) {
  check_decimal(text, what);
  // strtod/strtold, not stod: a subnormal result is a value, not an error.
  if constexpr (std::is_same_v<Real, double>)
    return std::strtod(text.c_str(), nullptr);
  else if constexpr (std::is_same_v<Real, long double>)
    return std::strtold(text.c_str(), nullptr);
  else
    return Real(text);
}

template <class Real>
std::unique_ptr<Waveform<Real>> make_waveform(const WaveSpec& spec) {
  switch (spec.kind) {
    case WaveKind::sine: return std::make_unique<Sine<Real>>();
    case WaveKind::triangle: return make_triangle<Real>();
    case WaveKind::sawtooth_right: return make_sawtooth_right<Real>();
    case WaveKind::sawtooth_left: return make_sawtooth_left<Real>();
    case WaveKind::square: return make_square<Real>();
    case WaveKind::power:
      return std::make_unique<Power<Real>>(parse_real<Real>(spec.exponent, "power exponent p"), spec.name);
    case WaveKind::fourier: {
      std::vector<unsigned> k;
      std::vector<Real> a, b;
      for (const auto& h : spec.harmonics) {
        k.push_back(h.k);
        a.push_back(parse_real<Real>(h.a, spec.name + " coefficient a_" + std::to_string(h.k)));
        b.push_back(parse_real<Real>(h.b, spec.name + " coefficient b_" + std::to_string(h.k)));
      }
      return std::make_unique<FourierSeries<Real>>(spec.name, k, a, b);
    }
    case WaveKind::samples: {
      // Normalised from the decimal text itself (parse_wave checked its grammar and range): its
      // rounding to Real would be amplified by the offset-to-amplitude ratio.
      int distinct = 1;
      for (const std::string& t : spec.samples) {
        int d = 0;
        for (const char c : t) {
          if (c == 'e' || c == 'E') break;
          if (c >= '0' && c <= '9') ++d;
        }
        distinct = std::max(distinct, d);
      }
      if (spec.times.empty())
        return make_samples_from<Real>(spec.name, spec.samples.size(),
                                       [&](std::size_t j) { return mpfr(spec.samples[j]); }, distinct);
      // A time column: φ_j = (t_j − t_0)/(t_N − t_0), at the current mpfr precision.
      return make_samples_from<Real>(
          spec.name, spec.samples.size(), [&](std::size_t j) { return mpfr(spec.samples[j]); }, distinct,
          [&](std::size_t j) {
            const mpfr t0(spec.times.front());
            return mpfr((mpfr(spec.times[j]) - t0) / (mpfr(spec.times.back()) - t0));
          });
    }
  }
  throw InputError("unknown wave kind");
}

}  // namespace vibrofric
