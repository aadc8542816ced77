// Shared pieces of the precision benchmarks (issue #5): the waves, the speed inputs cycled by
// every speed benchmark, the run mode, and the closed forms of Eqs. 13, 17, 19 and 22 as one
// function per wave. bench/README.md describes the paths and the JSON they write.
#pragma once
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/verification/closed_forms.hpp"

namespace vibrofric::bench {

struct Config {
  bool quick = false;        // --quick: fewer inputs, shorter minimum time, one repetition
  std::FILE* points = nullptr;  // --accuracy_points=FILE: one CSV row per (path, grid point)
};
Config& config();

// The catalogue waves, in report order.
inline const std::vector<std::string>& waves() {
  static const std::vector<std::string> w = {"sine",          "triangle", "sawtooth-right",
                                             "sawtooth-left", "square",   "power:3"};
  return w;
}

// One (β, γ) input. Every value is a double, and every path and the reference take exactly this
// binary value (the reference converts it exactly), so input rounding never counts as error.
struct Input {
  double beta, gamma;
};

// The inputs every speed benchmark cycles through, the same for every wave and path: both
// regimes (jumping −1 < γ < 1 and not), stick-slip and, for the sawtooth-right (β_c = 2), β ≥ β_c.
inline std::vector<Input> speed_inputs() {
  if (config().quick) return {{1, -0.5}, {0.25, 0}, {1, 2}, {3, 1}};
  std::vector<Input> in;
  for (double g : {-0.5, 0.0, 1.0, 2.0})
    for (double b : {0.25, 1.0, 3.0}) in.push_back({b, g});
  return in;
}

// Minimum time and repetitions of a speed benchmark: medians of 5 in the full run (the VM is
// noisy), one short run in --quick mode.
inline benchmark::internal::Benchmark* speed_settings(benchmark::internal::Benchmark* b) {
  if (config().quick) return b->MinTime(0.01)->Repetitions(1)->Unit(benchmark::kNanosecond);
  return b->MinTime(0.2)->Repetitions(5)->ReportAggregatesOnly(true)->Unit(benchmark::kNanosecond);
}

// Closed forms exist for the piecewise-linear catalogue waves only.
inline bool has_closed_form(WaveKind k) {
  return k == WaveKind::triangle || k == WaveKind::sawtooth_right || k == WaveKind::sawtooth_left ||
         k == WaveKind::square;
}

// μ̄/μ0 from the paper's closed forms: Eq. 19 (tri, str, stl) and Eq. 22 (square) in the jumping
// range −1 < γ < 1, Eq. 13 with Eq. 17 (Ψ) for γ ≥ 1. Precondition: has_closed_form(k).
template <class Real>
Real closed_form_mu(WaveKind k, const Real& beta, const Real& gamma) {
  namespace cf = closed_form;
  const bool jumping = gamma < 1;
  switch (k) {
    case WaveKind::triangle:
      return jumping ? cf::mu_triangle_jumping(beta) : cf::mu_from_psi(cf::psi_triangle(beta), gamma);
    case WaveKind::sawtooth_right:
      return jumping ? cf::mu_sawtooth_right_jumping(beta) : cf::mu_from_psi(cf::psi_sawtooth_right(beta), gamma);
    case WaveKind::sawtooth_left:
      return jumping ? cf::mu_sawtooth_left_jumping(beta) : cf::mu_from_psi(cf::psi_sawtooth_left(beta), gamma);
    case WaveKind::square:
      return jumping ? cf::mu_square_jumping(beta, gamma) : cf::mu_from_psi(cf::psi_square(beta), gamma);
    default:
      break;
  }
  return Real(-1);
}

// Grid points of the second algorithm and time steps of the baseline, per period.
inline constexpr std::size_t grid_points = 4096;
inline constexpr std::size_t baseline_steps = 4096;

// The decimal expansion of a double to 60 significant digits: parsed back by any type it gives
// the same double, and by mpfr at ≤ 60 digits the double itself to within 1e-60.
inline std::string exact_decimal(double x) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.60e", x);
  return buf;
}

// The shortest decimal that reads back as x (what a user would type for the speed inputs).
inline std::string shortest_decimal(double x) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

void register_speed_double();
void register_speed_long_double();
void register_speed_mpfr();
void register_speed_bin50();
void register_accuracy();
void register_curved();
void register_certify();
void register_rig();
void register_inplane();

}  // namespace vibrofric::bench
