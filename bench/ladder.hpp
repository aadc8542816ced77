// Which rung of the double ladder (detail::evaluate_fixed, evaluate_impl.hpp) answered each point,
// as the library counts it (BatchOptions::ladder): the double value itself, the long double value,
// or mpfr rounded to double. The guaranteed-path benchmarks report the share of each rung, which
// explains their cost.
#pragma once
#include <exception>
#include <string>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/evaluate.hpp"

namespace vibrofric::bench {

// Sets counters rung_double, rung_long_double, rung_mpfr: the share of `points` (decimal β, γ)
// answered by each rung (points that fail count on none).
inline void rung_counters(benchmark::State& state, const std::string& wave, const std::vector<Point>& points) {
  const WaveSpec spec = parse_wave(wave);
  Precision precision;
  precision.type = NumberType::float64;
  LadderCounts counts;
  BatchOptions options;
  options.threads = 1;
  options.ladder = &counts;
  for (const Point& p : points) {
    try {
      evaluate(spec, Quantity::mu, {p}, precision, options);
    } catch (const std::exception&) {
    }
  }
  const double n = static_cast<double>(points.size());
  state.counters["rung_double"] = static_cast<double>(counts.own) / n;
  state.counters["rung_long_double"] = static_cast<double>(counts.long_double) / n;
  state.counters["rung_mpfr"] = static_cast<double>(counts.mpfr) / n;
}

}  // namespace vibrofric::bench
