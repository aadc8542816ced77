// Speed of the double paths: the closed forms (where the wave has one), the solver in double as
// computed ("raw"), the guaranteed double path of evaluate.hpp (escalation ladder double →
// long double → mpfr, decimal in and out), the second algorithm (grid envelope) and the
// time-stepping baseline.
#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "common.hpp"
#include "ladder.hpp"
#include "speed.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/verification/baseline.hpp"
#include "vibrofric/verification/grid_envelope.hpp"

namespace vibrofric::bench {
namespace {

void BM_closed_form(benchmark::State& state, const std::string& wave) {
  const WaveKind kind = parse_wave(wave).kind;
  const std::vector<Input> in = speed_inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    double beta = in[i].beta, gamma = in[i].gamma;
    benchmark::DoNotOptimize(beta);  // keep the inputs opaque: no constant folding
    benchmark::DoNotOptimize(gamma);
    benchmark::DoNotOptimize(closed_form_mu(kind, beta, gamma));
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

// evaluate() with one point per call, as a caller of the string API (or `vibrofric mu --type
// double`) pays: parsing, the double solve, the escalation where the rounding bound asks for it,
// and the correctly rounded 17-digit output. Inputs are given in their shortest decimal form
// ("0.25"), as a user types them (the decimal parser costs more for long strings).
void BM_guaranteed_double(benchmark::State& state, const std::string& wave) {
  const WaveSpec spec = parse_wave(wave);
  std::vector<std::vector<Point>> in;
  for (const Input& p : speed_inputs()) in.push_back({Point{shortest_decimal(p.beta), shortest_decimal(p.gamma)}});
  Precision precision;
  precision.type = NumberType::float64;
  BatchOptions options;
  options.threads = 1;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto out = evaluate(spec, Quantity::mu, in[i], precision, options);
    benchmark::DoNotOptimize(out.data());
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  std::vector<Point> points;
  for (const auto& p : in) points.push_back(p.front());
  rung_counters(state, wave, points);
  // The time above is the mean over the inputs, which the few points that reach mpfr dominate.
  // Per input: the best of 3 means, each over two milliseconds of calls or more; the median and the largest.
  if (config().quick) return;
  std::vector<double> per_point;
  for (const auto& p : in) {
    double best = INFINITY;
    for (int round = 0; round < 3; ++round) {
      std::size_t calls = 0;
      const auto start = std::chrono::steady_clock::now();
      std::chrono::duration<double, std::nano> spent{};
      while (spent.count() < 2e6) {
        benchmark::DoNotOptimize(evaluate(spec, Quantity::mu, p, precision, options).data());
        ++calls;
        spent = std::chrono::steady_clock::now() - start;
      }
      best = std::min(best, spent.count() / static_cast<double>(calls));
    }
    per_point.push_back(best);
  }
  std::sort(per_point.begin(), per_point.end());
  const std::size_t k = per_point.size();
  state.counters["point_median_ns"] = k % 2 ? per_point[k / 2] : (per_point[k / 2 - 1] + per_point[k / 2]) / 2;
  state.counters["point_max_ns"] = per_point.back();
}

// A uniform sweep, one evaluate() call for all its points on one thread (`vibrofric sweep --type
// double`): the guaranteed path (escalate) against the same call without escalation ("raw": the
// double solve, parsing and correctly rounded printing of the double it computed). β = 0.04..4 and
// γ = −0.9..2.07 in 100 steps each: stick-slip, β ≥ β_c, jumping and not.
void BM_uniform_sweep(benchmark::State& state, const std::string& wave, bool escalate) {
  const WaveSpec spec = parse_wave(wave);
  const int n = config().quick ? 10 : 100;
  std::vector<Point> points;
  for (int j = 0; j < n; ++j)
    for (int i = 1; i <= n; ++i)
      points.push_back({shortest_decimal(4.0 * i / n), shortest_decimal(-0.9 + 2.97 * j / (n - 1))});
  Precision precision;
  precision.type = NumberType::float64;
  BatchOptions options;
  options.threads = 1;
  options.escalate = escalate;
  for (auto _ : state) {
    const auto out = evaluate(spec, Quantity::mu, points, precision, options);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
  state.counters["points"] = static_cast<double>(points.size());
  if (escalate) rung_counters(state, wave, points);
}

void BM_grid_envelope(benchmark::State& state, const std::string& wave) {
  const auto w = make_waveform<double>(parse_wave(wave));
  const std::vector<Input> in = speed_inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto r = grid_envelope(*w, in[i].beta, in[i].gamma, grid_points);
    benchmark::DoNotOptimize(r.mu);
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["points"] = grid_points;
}

void BM_baseline(benchmark::State& state, const std::string& wave) {
  const auto w = make_waveform<double>(parse_wave(wave));
  const std::vector<Input> in = speed_inputs();
  BaselineOptions opt;
  opt.steps = baseline_steps;
  std::size_t i = 0, periods = 0;
  for (auto _ : state) {
    const auto r = simulate_spring(*w, in[i].beta, in[i].gamma, opt);
    benchmark::DoNotOptimize(r.mu);
    periods += r.periods;
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["steps"] = baseline_steps;
  state.counters["periods_mean"] = state.iterations() ? double(periods) / double(state.iterations()) : 0.0;
}

}  // namespace

void register_speed_double() {
  for (const auto& wave : waves()) {
    const std::string prefix = "speed/" + wave + "/";
    if (has_closed_form(parse_wave(wave).kind))
      speed_settings(benchmark::RegisterBenchmark((prefix + "closed_form_double").c_str(), BM_closed_form, wave));
    speed_settings(benchmark::RegisterBenchmark((prefix + "solver_double").c_str(), BM_solver<double>, wave, 0));
    speed_settings(benchmark::RegisterBenchmark((prefix + "guaranteed_double").c_str(), BM_guaranteed_double, wave));
    if (wave == "sine") {
      speed_settings(benchmark::RegisterBenchmark((prefix + "uniform_sweep_raw_double").c_str(), BM_uniform_sweep, wave, false));
      speed_settings(benchmark::RegisterBenchmark((prefix + "uniform_sweep_guaranteed_double").c_str(), BM_uniform_sweep, wave,
                                                  true));
    }
    speed_settings(benchmark::RegisterBenchmark((prefix + "grid_envelope_double").c_str(), BM_grid_envelope, wave));
    speed_settings(benchmark::RegisterBenchmark((prefix + "baseline_double").c_str(), BM_baseline, wave));
  }
}

}  // namespace vibrofric::bench
