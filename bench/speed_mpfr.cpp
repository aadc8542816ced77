// Speed of the solver in mpfr at 50, 100, 300 and 1000 working digits (the cost-versus-digits
// series that bench/run fits), and of the guaranteed mpfr path of evaluate.hpp (what `vibrofric mu
// --digits D` computes: D + 10 + D/20 working digits, raised where the rounding bound asks for
// it, correctly rounded decimal output) at 50 and 1000 digits.
#include "speed.hpp"
#include "vibrofric/api/evaluate.hpp"

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
}

}  // namespace

void register_speed_mpfr() {
  for (int digits : {50, 100, 300, 1000}) register_solver<mpfr>("solver_mpfr_" + std::to_string(digits), digits);
  for (int digits : {50, 1000})
    for (const auto& wave : waves()) {
      const std::string name = "speed/" + wave + "/guaranteed_mpfr_" + std::to_string(digits);
      speed_settings(benchmark::RegisterBenchmark(name.c_str(), BM_evaluate_mpfr, wave, digits));
    }
}

}  // namespace vibrofric::bench
