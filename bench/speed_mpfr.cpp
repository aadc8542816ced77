// Speed of the solver in mpfr at 50, 100, 300 and 1000 working digits (the cost-versus-digits
// series that bench/run fits), and of the guaranteed mpfr path of evaluate.hpp (what `vibrofric mu
// --digits D` computes: D + 10 + D/20 working digits, raised where the rounding bound asks for
// it, correctly rounded decimal output) at 50 and 1000 digits. And the unit of the counted floor
// (floor.hpp): one mpfr_sin_cos at each of those working precisions.
#include <mpfr.h>

#include "floor.hpp"
#include "speed.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/ladder.hpp"

namespace vibrofric::bench {
namespace {

void BM_evaluate_mpfr(benchmark::State& state, const std::string& wave, int digits) {
  const WaveSpec spec = parse_wave(wave);
  std::vector<std::vector<Point>> in;
  for (const Input& p : speed_inputs()) in.push_back({Point{shortest_decimal(p.beta), shortest_decimal(p.gamma)}});
  Precision precision;
  precision.type = NumberType::mpfr;
  precision.digits = digits;
  BatchOptions options;
  options.threads = 1;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto out = evaluate(spec, Quantity::mu, in[i], precision, options);
    benchmark::DoNotOptimize(out.data());
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["digits"] = digits;
  // Untimed: transcendental calls per point at the requested digits' precision or more, and for
  // the sine the floor of the events at the first working precision (digits + guard digits).
  {
    PrecisionScope scope(static_cast<unsigned>(digits));
    count_reset(static_cast<long>(mpfr_get_prec(mpfr(0).backend().data())));
  }
  for (const auto& point : in) benchmark::DoNotOptimize(evaluate(spec, Quantity::mu, point, precision, options).data());
  const CallCount c = count_read();
  state.counters["fp_calls"] = static_cast<double>(c.full) / static_cast<double>(in.size());
  state.counters["reduced_calls"] = static_cast<double>(c.reduced) / static_cast<double>(in.size());
  state.counters["working_digits"] = digits + guard_digits(digits);
  if (wave == "sine") {
    const int working = digits + guard_digits(digits);
    double floor;
    {
      PrecisionScope scope(static_cast<unsigned>(working));
      const auto w = make_waveform<mpfr>(spec);
      std::vector<std::pair<mpfr, mpfr>> exact;
      for (const Input& p : speed_inputs()) exact.emplace_back(mpfr(p.beta), mpfr(p.gamma));
      floor = mean_sine_floor(*w, exact);
    }
    state.counters["floor_calls"] = floor;
    interleaved_floor(
        state, [&] {
          for (const auto& point : in) benchmark::DoNotOptimize(evaluate(spec, Quantity::mu, point, precision, options).data());
        },
        in.size(), floor, working);
  }
}

// One mpfr_sin_cos at `digits` working digits, on sin_cos_phases(): the unit of the counted floor.
void BM_sin_cos(benchmark::State& state, int digits) {
  PrecisionScope scope(static_cast<unsigned>(digits));
  const std::vector<mpfr> x = sin_cos_phases();
  mpfr s, c;
  std::size_t i = 0;
  for (auto _ : state) {
    mpfr_sin_cos(s.backend().data(), c.backend().data(), x[i].backend().data(), MPFR_RNDN);
    benchmark::DoNotOptimize(s.backend().data());
    if (++i == x.size()) i = 0;
  }
  state.counters["digits"] = digits;
}

}  // namespace

void register_speed_mpfr() {
  for (int digits : {50, 100, 300, 1000}) register_solver<mpfr>("solver_mpfr_" + std::to_string(digits), digits);
  for (int digits : {50, 1000})
    for (const auto& wave : waves()) {
      const std::string name = "speed/" + wave + "/guaranteed_mpfr_" + std::to_string(digits);
      speed_settings(benchmark::RegisterBenchmark(name.c_str(), BM_evaluate_mpfr, wave, digits));
    }
  for (int digits : {50, 100, 300, 1000, 50 + guard_digits(50), 1000 + guard_digits(1000)}) {
    const std::string name = "floor/mpfr_sin_cos_" + std::to_string(digits);
    speed_settings(benchmark::RegisterBenchmark(name.c_str(), BM_sin_cos, digits));
  }
}

}  // namespace vibrofric::bench
