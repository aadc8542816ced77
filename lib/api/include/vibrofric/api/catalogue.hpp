// Waveform names and files (model.md, "Waveform catalogue"): parsed once, without a number type,
// then built at any precision by make_waveform<Real>. Numbers are read once, as Decimals, so that
// each precision takes them correctly rounded ("0.1" at 100 digits is 0.1 to 100 digits).
#pragma once
#include <array>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/api/decimal_value.hpp"
#include "vibrofric/api/decimal.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/waves/user_waveforms.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

enum class WaveKind { sine, triangle, sawtooth_right, sawtooth_left, square, power, fourier, samples };

struct WaveSpec {
  WaveKind kind = WaveKind::sine;
  std::string name;      // canonical: "sine", "triangle", …, "power:2.5", "fourier:FILE"
  Decimal exponent;  // power:p
  struct Harmonic {
    unsigned k;
    Decimal a, b;
  };
  std::vector<Harmonic> harmonics;  // fourier: w = Σ a_k cos 2πkφ + b_k sin 2πkφ
  std::vector<Decimal> samples;  // samples: y_j at φ = j/N, or at the times below
  std::vector<Decimal> times;    // samples with a time column: t_0 … t_N (t_N − t_0 = the period), else empty
  // samples: which columns were read. `column` is the value column as chosen by
  // WaveReadOptions::column, canonical (the header's name if it names that column once, else the
  // 1-based index), and empty without the option; it is what tells "samples:a#b" (file a, column
  // b) from a file named "a#b". value_column/time_column: the header's names ("" without a header
  // or time column), for describe_normalisation.
  std::string column, value_column, time_column;
  // samples with a time column but no end point, as a DAQ writes t_j = t_0 + j·dt (README, "File
  // formats"): every stamp is that to its printed digits, so the N samples sit at φ = j/N (times
  // is then empty) and this is the period N·dt as a decimal (40 digits). None otherwise.
  std::optional<Decimal> period_from_stamps;
  // samples averaged from a record of this many periods (WaveReadOptions::periods): each y_j is
  // then the exact sum of the K values at its phase, whose normalised wave is their mean's; raw
  // values (describe_normalisation, fit) divide by it.
  unsigned periods_averaged = 1;
};

// How to read a samples:FILE (README, "File formats"). column: the value column, a header name
// (exact, as in the header line) or a 1-based index; it lets a file have more than two columns
// (the time column, if the header names one 'time' or 't', still gives the phases). Empty: the
// one- and two-column layouts only, as without options.
// periods: how many periods the record holds (README, "File formats"). 0: one, and a record that
// looks like K ≥ 2 noisy periods is refused with what to give; 1: one, not checked; K ≥ 2: the
// K periods are averaged sample by sample (uniform phases, N a multiple of K).
constexpr int max_record_periods = 100000;
struct WaveReadOptions {
  std::string column;
  std::string column_name = "column";  // what the caller calls the choice, for messages ("--column")
  int periods = 0;
  std::string periods_name = "periods";  // ("--periods")
  // The lines of a file's preamble ("Messung: …", "Datum: …") before its header (pandas' skiprows).
  int skip_rows = 0;
  std::string skip_rows_name = "skip_rows";  // ("--skip-rows")
};

// Accepts sine, harmonic, triangle|tri, sawtooth-right|str, sawtooth-left|stl, square|sqr,
// power:P (P ≥ 1), fourier:FILE, samples:FILE. Throws InputError naming the text otherwise.
// With options.column the name is "samples:FILE#COLUMN" (COLUMN canonical, WaveSpec::column);
// without, the name is unchanged.
WaveSpec parse_wave(const std::string& text);
WaveSpec parse_wave(const std::string& text, const WaveReadOptions& options);

// A samples wave's period in seconds, from its time column (the stamps' span, or N·dt without an
// end point) and the unit its header names: "time [s]", "t (ms)", "time_us", "t/ns", "time in µs"
// (s, ms, us, µs, ns, min); a header without a unit is taken as seconds (`assumed` set). None for
// a wave without a time column or with a unit not in that list.
struct StampedPeriod {
  mpfr seconds;
  std::string unit;  // as the header writes it ("s" where assumed)
  bool assumed = false;
};
std::optional<StampedPeriod> stamped_period(const WaveSpec& wave);
// The unit a column's header names, as written: "time [s]", "t (ms)", "disp_um", "t/ns",
// "height in µm" give s, ms, um, ns, µm; "" where it names none.
std::string column_unit(const std::string& header);

// The normalisation a user wave gets (model.md, "Waveform catalogue": "the normalisation used is
// reported"), as name/value pairs with values to `digits` significant digits, computed by the code
// that normalises the wave (normalise_samples, the FourierSeries constructor). scale is the
// divisor of w = (raw − offset)/scale, (max − min)/2 as in Waveform::normalisation() and the
// README; factor = 1/scale = 2/(max − min) is the multiplier. A samples mean below the accuracy it
// is computed to (relative to max|y|) is shown as 0. digits: 1 to 10000.
std::vector<std::pair<std::string, std::string>> describe_normalisation(const WaveSpec& wave, int digits);

// Names of the catalogue waves, for help texts and tests.
const std::vector<std::string>& catalogue_names();

// Strict decimal grammar: [+-]digits[.digits][e[+-]digits], finite, within double's range.
// Throws InputError naming `what` and the text.
void check_decimal(const std::string& text, const std::string& what);

// Decimal text to Real, correctly rounded at the current precision (after check_decimal).
template <class Real>
Real parse_real(const std::string& text, const std::string& what) {
  check_decimal(text, what);
  return Decimal::read(text)->template to<Real>();
}


namespace detail {
// Text for messages: characters as written ('Weg [µm]'), every byte of a control, an invisible
// or space-like character ('sine\r', '\xC2\xA0') and of ill-formed UTF-8 escaped (src/text.cpp).
std::string visible(const std::string& s);
// A samples wave's inputs to make_samples_from, shared with describe_normalisation: the largest
// count of significant digits of a sample, y_j at the current mpfr precision, and with a time
// column φ_j = (t_j − t_0)/(t_N − t_0) at the current mpfr precision (empty function without).
int distinct_digits(const WaveSpec& spec);
mpfr sample_value(const WaveSpec& spec, std::size_t j);
std::function<mpfr(std::size_t)> sample_phase(const WaveSpec& spec);
}  // namespace detail

template <class Real>
std::unique_ptr<Waveform<Real>> make_waveform(const WaveSpec& spec) {
  switch (spec.kind) {
    case WaveKind::sine: return std::make_unique<Sine<Real>>();
    case WaveKind::triangle: return make_triangle<Real>();
    case WaveKind::sawtooth_right: return make_sawtooth_right<Real>();
    case WaveKind::sawtooth_left: return make_sawtooth_left<Real>();
    case WaveKind::square: return make_square<Real>();
    case WaveKind::power:
      return std::make_unique<Power<Real>>(spec.exponent.to<Real>(), spec.name);
    case WaveKind::fourier: {
      std::vector<unsigned> k;
      std::vector<Real> a, b;
      for (const auto& h : spec.harmonics) {
        k.push_back(h.k);
        a.push_back(h.a.to<Real>());
        b.push_back(h.b.to<Real>());
      }
      return std::make_unique<FourierSeries<Real>>(spec.name, k, a, b);
    }
    case WaveKind::samples: {
      // Normalised from the decimals themselves: their rounding to Real would be amplified by the
      // offset-to-amplitude ratio.
      return make_samples_from<Real>(
          spec.name, spec.samples.size(), [&](std::size_t j) { return detail::sample_value(spec, j); },
          detail::distinct_digits(spec), detail::sample_phase(spec));
    }
  }
  throw InputError("unknown wave kind");
}

}  // namespace vibrofric
