// Fuzz target: the samples:FILE reader (the table grammar of README "File formats", with and
// without a chosen column, averaged as two periods) and what is built from it: the wave, its normalisation report and its
// Fourier fit. The input is the file's contents; malformed and huge files, NaNs, a single sample,
// constant signals must end in a clean InputError naming the file, and an accepted file must
// evaluate cleanly and consistently (fuzz_waves.hpp). Cost bound: evaluation and fit for at most
// 2,000 samples.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_common.hpp"
#include "fuzz_waves.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/fit.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vibrofric;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const fuzz::MemFile file(data, size);
  WaveSpec spec;
  auto parsed = fuzz::clean(input, "parse_wave(samples:FILE)", [&] { spec = parse_wave("samples:" + file.path()); });
  // A table of several columns: the second column, by index, then by the header's second name.
  if (parsed != fuzz::Outcome::value)
    parsed = fuzz::clean(input, "parse_wave(samples:FILE, column 2)",
                         [&] { spec = parse_wave("samples:" + file.path(), WaveReadOptions{"2"}); });
  if (parsed != fuzz::Outcome::value)
    parsed = fuzz::clean(input, "parse_wave(samples:FILE, column value)",
                         [&] { spec = parse_wave("samples:" + file.path(), WaveReadOptions{"value"}); });
  // A record of two periods, averaged (exact decimal sums of every written form): a clean
  // refusal or a wave that evaluates like any other.
  WaveReadOptions two;
  two.periods = 2;
  WaveSpec averaged;
  if (fuzz::clean(input, "parse_wave(samples:FILE, periods 2)", [&] { averaged = parse_wave("samples:" + file.path(), two); }) ==
          fuzz::Outcome::value &&
      averaged.samples.size() <= 2000)
    fuzz::check_user_wave(averaged, input, 1.0);
  if (parsed != fuzz::Outcome::value) return 0;
  if (spec.kind != WaveKind::samples || spec.samples.size() < 2) fuzz::finding("accepted samples file with fewer than 2 samples", input);
  if (spec.samples.size() > 2000) return 0;
  // Every type normalises from the decimal text in mpfr (user_waveforms.hpp): no κ amplification.
  const double kappa = 1.0;
  fuzz::check_user_wave(spec, input, kappa);
  fuzz::clean(input, "describe_normalisation", [&] { describe_normalisation(spec, 17); });
  // The fit: a clean refusal (too few samples, rank deficient) or a file that reads back.
  FourierFit fit;
  if (fuzz::clean(input, "fit_fourier", [&] { fit = fit_fourier(spec, 2); }) == fuzz::Outcome::value) {
    const std::string text = fourier_file_text(fit, "fuzz");
    const fuzz::MemFile fitted(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    fuzz::clean(text, "parse_wave(fourier:fitted)", [&] { parse_wave("fourier:" + fitted.path()); });
  }
  return 0;
}
