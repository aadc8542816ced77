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
#include "vibrofric/catalogue.hpp"

namespace {

// Known library bug (reported, issue #7; test_failures.cpp,
// KnownBug.DISABLED_FourierWithADegenerateCriticalPointIsFast): where w' and w'' vanish together
// (a zero of w' of multiplicity ≥ 2, e.g. Σ cos(2πkφ)/k² with an even number of terms at φ = 1/2)
// the root search subdivides a whole neighbourhood down to 2^-30 and takes minutes to hours. Such
// inputs (|w'|/Σ2πk|c_k| + |w''|/Σ(2πk)²|c_k| below 1e-6 somewhere on a 4096-point grid or at the
// quarter periods) are skipped. Remove when fixed.
bool near_degenerate(const vibrofric::WaveSpec& spec) {
  std::vector<long double> k, a, b;
  long double b1 = 0, b2 = 0;
  const long double two_pi = 6.283185307179586476925286766559L;
  for (const auto& h : spec.harmonics) {
    if (h.k == 0) continue;
    k.push_back(h.k);
    a.push_back(std::strtold(h.a.c_str(), nullptr));
    b.push_back(std::strtold(h.b.c_str(), nullptr));
    const long double r = std::fabs(a.back()) + std::fabs(b.back());
    b1 += two_pi * h.k * r;
    b2 += two_pi * two_pi * h.k * h.k * r;
  }
  if (!(b1 > 0) || !std::isfinite(static_cast<double>(b2))) return false;
  for (int i = 0; i < 4096; ++i) {
    const long double phi = i / 4096.0L;
    long double d1 = 0, d2 = 0;
    for (std::size_t j = 0; j < k.size(); ++j) {
      const long double w = two_pi * k[j], c = std::cos(w * phi), s = std::sin(w * phi);
      d1 += w * (-a[j] * s + b[j] * c);
      d2 -= w * w * (a[j] * c + b[j] * s);
    }
    if (std::fabs(d1) / b1 + std::fabs(d2) / b2 < 1e-6L) return true;
  }
  return false;
}

}  // namespace

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
    sum += h.k * (std::fabs(std::strtold(h.a.c_str(), nullptr)) + std::fabs(std::strtold(h.b.c_str(), nullptr)));
  }
  if (near_degenerate(spec)) return 0;
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
