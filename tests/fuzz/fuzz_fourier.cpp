// Fuzz target: the fourier:FILE reader (lines 'k a_k b_k') and what is built from it. The input is
// the file's contents; malformed and huge files, NaNs, non-finite and zero coefficients must end in
// a clean InputError naming the file, and an accepted file must evaluate cleanly and consistently
// (fuzz_waves.hpp). Cost bound: evaluation only for harmonics k ≤ 8 (the root search over w' and
// w'' is O(k²) evaluations of O(k) each, and ASan multiplies it); larger files are still parsed.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "fuzz_waves.hpp"
#include "vibrofric/api/catalogue.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vibrofric;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const fuzz::MemFile file(data, size);
  WaveSpec spec;
  const auto parsed = fuzz::clean(input, "parse_wave(fourier:FILE)", [&] { spec = parse_wave("fourier:" + file.path()); });
  if (parsed != fuzz::Outcome::value) return 0;
  if (spec.kind != WaveKind::fourier || spec.harmonics.empty()) fuzz::finding("accepted fourier file without harmonics", input);
  long double sum = 0;
  for (const auto& h : spec.harmonics) {
    if (h.k > 100000) fuzz::finding("accepted harmonic k > 100000", input);
    if (h.k > 8) return 0;
    sum += h.k * (std::fabs(std::strtold(h.a.text().c_str(), nullptr)) + std::fabs(std::strtold(h.b.text().c_str(), nullptr)));
  }
  // κ = Σ k(|a_k| + |b_k|)/scale, the scale from the 20-digit wave (fuzz_waves.hpp).
  double kappa = 1;
  {
    PrecisionScope digits(31);
    std::unique_ptr<Waveform<mpfr>> w;
    if (fuzz::clean(input, "make_waveform<mpfr>", [&] { w = make_waveform<mpfr>(spec); }) == fuzz::Outcome::value)
      kappa = static_cast<double>(sum / static_cast<long double>(w->normalisation().scale));
  }
  fuzz::check_user_wave(spec, input, kappa);
  return 0;
}
