// Which rung of evaluate.hpp's double ladder answers a point, decided with the same tests as
// detail::evaluate_fixed (evaluate_impl.hpp): the double value if its rounding bound is at most
// ε_double; else the long double value if its bound is at most ε_double/4; else mpfr. The
// guaranteed-path benchmarks report the share of each rung, which explains their cost.
#pragma once
#include <exception>
#include <limits>
#include <string>

#include "common.hpp"
#include "vibrofric/solver.hpp"

namespace vibrofric::bench {

enum class Rung { float64 = 0, float80 = 1, mpfr = 2 };

inline Rung ladder_rung(const Waveform<double>& wd, const Waveform<long double>& wld, double beta, double gamma) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  if (solve(wd, beta, gamma).relative_error <= eps) return Rung::float64;
  const long double bound = solve(wld, static_cast<long double>(beta), static_cast<long double>(gamma)).relative_error;
  return bound <= eps / 4 ? Rung::float80 : Rung::mpfr;
}

// Sets counters rung_double, rung_long_double, rung_mpfr: the share of `inputs` on each rung
// (points where the double solver throws count on none).
template <class Inputs>
void rung_counters(benchmark::State& state, const std::string& wave, const Inputs& inputs) {
  const WaveSpec spec = parse_wave(wave);
  const auto wd = make_waveform<double>(spec);
  const auto wld = make_waveform<long double>(spec);
  double count[3] = {0, 0, 0};
  for (const auto& p : inputs) {
    try {
      count[static_cast<int>(ladder_rung(*wd, *wld, p.beta, p.gamma))] += 1;
    } catch (const std::exception&) {
    }
  }
  const double n = static_cast<double>(inputs.size());
  state.counters["rung_double"] = count[0] / n;
  state.counters["rung_long_double"] = count[1] / n;
  state.counters["rung_mpfr"] = count[2] / n;
}

}  // namespace vibrofric::bench
