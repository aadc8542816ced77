// The generic speed benchmark: solve(w, β, γ) (solver.hpp, Eqs. 3–15) in one number type,
// cycling through speed_inputs(). One evaluation per iteration, so the time per iteration is the
// time per evaluation of μ̄/μ0; it includes make_contact (the γ-dependent set-up), as a single
// call from a user does. The waveform is built once, outside the timed loop.
#pragma once
#include <optional>
#include <utility>
#include <vector>

#include "common.hpp"
#include "floor.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric::bench {

// digits: working precision of mpfr (ignored for the fixed types).
template <class Real>
void BM_solver(benchmark::State& state, const std::string& wave, int digits) {
  std::optional<PrecisionScope> scope;
  if constexpr (is_runtime_precision_v<Real>) scope.emplace(static_cast<unsigned>(digits));
  const auto w = make_waveform<Real>(parse_wave(wave));
  std::vector<std::pair<Real, Real>> in;
  for (const Input& p : speed_inputs()) in.emplace_back(Real(p.beta), Real(p.gamma));  // exact
  std::size_t i = 0;
  for (auto _ : state) {
    const Result<Real> r = solve(*w, in[i].first, in[i].second);
    benchmark::DoNotOptimize(r.mu);
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["digits"] = working_digits10<Real>();
  state.counters["inputs"] = static_cast<double>(in.size());
  if constexpr (is_runtime_precision_v<Real>) floor_counters(state, *w, in, wave == "sine", digits);
}

// Registers speed/<wave>/<path> for every wave.
template <class Real>
void register_solver(const std::string& path, int digits) {
  for (const auto& wave : waves()) {
    const std::string name = "speed/" + wave + "/" + path;
    speed_settings(benchmark::RegisterBenchmark(name.c_str(), BM_solver<Real>, wave, digits));
  }
}

}  // namespace vibrofric::bench
