// Fuzz target: the samples:FILE reader (one period of values y_j, whitespace separated) and what is
// built from it. The input is the file's contents; malformed and huge files, NaNs, a single sample,
// constant signals must end in a clean InputError naming the file, and an accepted file must
// evaluate cleanly and consistently (fuzz_waves.hpp). Cost bound: evaluation for at most 2,000
// samples.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_common.hpp"
#include "fuzz_waves.hpp"
#include "vibrofric/catalogue.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vibrofric;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const fuzz::MemFile file(data, size);
  WaveSpec spec;
  const auto parsed = fuzz::clean(input, "parse_wave(samples:FILE)", [&] { spec = parse_wave("samples:" + file.path()); });
  if (parsed != fuzz::Outcome::value) return 0;
  if (spec.kind != WaveKind::samples || spec.samples.size() < 2) fuzz::finding("accepted samples file with fewer than 2 samples", input);
  if (spec.samples.size() > 2000) return 0;
  // Every type normalises from the decimal text in mpfr (user_waveforms.hpp): no κ amplification.
  const double kappa = 1.0;
  fuzz::check_user_wave(spec, input, kappa);
  return 0;
}
