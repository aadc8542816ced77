// The counted floor of an mpfr evaluation (issue 29): how many full-precision transcendental
// calls a point makes (counted at the link, floor.cpp), how many its events need at the least,
// and what one such call costs. bench/README.md, "The counted floor", says how bench/run uses them.
#pragma once
#include <benchmark/benchmark.h>
#include <mpfr.h>

#include <cstddef>
#include <utility>
#include <vector>

#include "vibrofric/core/solver.hpp"

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

// Full-precision transcendental calls that the events of one sine point need at the least, with
// the solver's rounding analysis as it is (paper Eqs. 4 and 8; model.md, the waveform catalogue):
// one per contact boundary (the last step of its inverse, w = −γ), one per onset by Eq. 4 (n' = β,
// a stick with level > 0; a stick from first contact starts at a boundary), and two per stick end
// by Eq. 8 (the last Newton step and the value of n at the root, which the rounding bound
// evaluates rather than infers from the ramp). n' and the antiderivative at these phases are
// algebraic in the sine and cosine the same calls give.
template <class Real>
std::size_t sine_floor_calls(const Contact<Real>& contact, const Result<Real>& r) {
  std::size_t calls = contact.boundaries();
  for (const auto& st : r.stick_phases) calls += (st.level > 0 ? 1 : 0) + 2;
  return calls;
}

// After a timed loop over `in` (untimed): the mean full-precision and reduced-precision
// transcendental calls per point of solve() at the working precision ("fp_calls",
// "reduced_calls"), and for the sine the mean counted floor ("floor_calls").
template <class Real>
void floor_counters(benchmark::State& state, const Waveform<Real>& w, const std::vector<std::pair<Real, Real>>& in,
                    bool sine) {
  count_reset(static_cast<long>(mpfr_get_prec(Real(0).backend().data())));
  for (const auto& [beta, gamma] : in) benchmark::DoNotOptimize(solve(w, beta, gamma).mu);
  const CallCount c = count_read();
  const double points = static_cast<double>(in.size());
  state.counters["fp_calls"] = static_cast<double>(c.full) / points;
  state.counters["reduced_calls"] = static_cast<double>(c.reduced) / points;
  if (!sine) return;
  std::size_t floor = 0;
  for (const auto& [beta, gamma] : in) {
    const Contact<Real> contact = make_contact(w, gamma);
    floor += sine_floor_calls(contact, solve(contact, beta));
  }
  state.counters["floor_calls"] = static_cast<double>(floor) / points;
}

}  // namespace vibrofric::bench
