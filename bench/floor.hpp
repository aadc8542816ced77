// The counted floor of an mpfr evaluation (issue 29): how many full-precision transcendental
// calls a point makes (counted at the link, floor.cpp), how many its events need at the least,
// and what one such call costs. bench/README.md, "The counted floor", says how bench/run uses them.
#pragma once
#include <benchmark/benchmark.h>
#include <mpfr.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "common.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric::bench {

// Calls of MPFR's transcendental functions (sin, cos, sin_cos, tan, atan2, exp, log, log10, pow,
// pow_si, sinh, cosh, tanh, cbrt) on this thread since count_reset: `full` at `bits` or more of
// result precision, `reduced` below (the reduced-precision first steps of acos_fast and the sine's
// stick end, waveform.hpp).
struct CallCount {
  std::size_t full = 0, reduced = 0;
};
void count_reset(long bits);
CallCount count_read();

// Full-precision transcendental calls that the events of one sine point need at the least (paper
// Eqs. 4 and 8; model.md, the waveform catalogue): one per event phase, a contact boundary, an
// onset by Eq. 4 (n' = β, a stick with level > 0; a stick from first contact starts at a
// boundary) and a stick end by Eq. 8. Each phase is a new transcendental number, and its sine
// and cosine come from no other event's. The steps of its root finding, n' and the
// antiderivative there, and the value of n at the root that the rounding bound evaluates are all
// within reach of that one call (waveform.hpp, TrigAnchor: Taylor from it, decided by
// mpfr_can_round).
template <class Real>
std::size_t sine_floor_calls(const Contact<Real>& contact, const Result<Real>& r) {
  std::size_t calls = contact.boundaries();
  for (const auto& st : r.stick_phases) calls += (st.level > 0 ? 1 : 0) + 1;
  return calls;
}

// The mean counted floor per point of the sine on `in` (β, γ), at the current working precision.
template <class Real>
double mean_sine_floor(const Waveform<Real>& w, const std::vector<std::pair<Real, Real>>& in) {
  std::size_t floor = 0;
  for (const auto& [beta, gamma] : in) {
    const Contact<Real> contact = make_contact(w, gamma);
    floor += sine_floor_calls(contact, solve(contact, beta));
  }
  return static_cast<double>(floor) / static_cast<double>(in.size());
}

// CPU time of this thread, in ns (the interleaved measurement below times its own phases).
double thread_cpu_ns();
// The arguments the floor's unit is timed on: phases 2πk/17, k = 1..16, of the period (the
// solver's arguments lie in [0, 2π]), at the current working precision.
std::vector<mpfr> sin_cos_phases();
// One mpfr_sin_cos at the current working precision, `calls` times on sin_cos_phases(); returns
// the CPU time per call in ns.
double time_sin_cos(std::size_t calls);

// The median of v (the upper one of an even count).
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The floor's unit measured beside the path itself (untimed by Google Benchmark): `rounds`
// alternations of one pass over the inputs (`pass`, `points` evaluations) and one batch of
// mpfr_sin_cos at `working_digits`, so that a shared host's slow and fast phases fall on both.
// Counters: "il_point_ns" and "il_sin_cos_ns" (medians over the rounds) and "il_ratio", the point's
// time over floor_calls of the unit's.
template <class Pass>
void interleaved_floor(benchmark::State& state, Pass pass, std::size_t points, double floor_calls, int working_digits) {
  constexpr int rounds = 9;
  std::vector<double> point_ns, unit_ns;
  for (int k = 0; k < rounds; ++k) {
    const double t0 = thread_cpu_ns();
    pass();
    point_ns.push_back((thread_cpu_ns() - t0) / static_cast<double>(points));
    PrecisionScope scope(static_cast<unsigned>(working_digits));
    unit_ns.push_back(time_sin_cos(8 * points));
  }
  const double p = median(point_ns), u = median(unit_ns);
  state.counters["il_point_ns"] = p;
  state.counters["il_sin_cos_ns"] = u;
  state.counters["il_ratio"] = p / (floor_calls * u);
}

// After a timed loop over `in` (untimed): the mean full-precision and reduced-precision
// transcendental calls per point of solve() at the working precision ("fp_calls",
// "reduced_calls"); for the sine at `digits` working digits, the mean counted floor ("floor_calls")
// and the interleaved ratio.
template <class Real>
void floor_counters(benchmark::State& state, const Waveform<Real>& w, const std::vector<std::pair<Real, Real>>& in,
                    bool sine, int digits) {
  count_reset(static_cast<long>(mpfr_get_prec(Real(0).backend().data())));
  for (const auto& [beta, gamma] : in) benchmark::DoNotOptimize(solve(w, beta, gamma).mu);
  const CallCount c = count_read();
  const double points = static_cast<double>(in.size());
  state.counters["fp_calls"] = static_cast<double>(c.full) / points;
  state.counters["reduced_calls"] = static_cast<double>(c.reduced) / points;
  if (!sine) return;
  const double floor = mean_sine_floor(w, in);
  state.counters["floor_calls"] = floor;
  interleaved_floor(
      state, [&] {
        for (const auto& [beta, gamma] : in) benchmark::DoNotOptimize(solve(w, beta, gamma).mu);
      },
      in.size(), floor, digits);
}

}  // namespace vibrofric::bench
