// Exact μ̄/μ0 = g_w(β, γ) (Eq. 15) and Ψ_w(β) (Eq. 12) for piecewise-linear waves at rational
// β and γ, in GMP rationals: the certified rung of issue 28 for the triangle, both sawtooths, the
// square wave, power:1 and sampled signals (model.md, "Waveform catalogue"). Every event of a
// piecewise-linear n is the root of a linear function, so it, every area and μ̄ are rational.
//
// The steady state is s(φ) = βφ + min_{ψ ≤ φ} h(ψ), h = n − βψ (model.md, "Steady state, closed
// characterisation"; solver.hpp): a running minimum. h(ψ − 1) = h(ψ) + β, so the minimum over
// ψ < 0 is β plus the minimum of h over one period, and one walk over the pieces of [0, 1) gives
// s exactly: on a piece h is linear, the minimum stays (stick: s rises on the ramp) or follows h
// from the point where h falls below it (slip: s = n). Linear in the number of vertices; it
// shares no code with solver.hpp (whose events are roots found in floating point) or with the
// verification's envelope.hpp (the same characterisation evaluated as a lower envelope of lines).
#pragma once
#include <boost/multiprecision/gmp.hpp>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/core/errors.hpp"

namespace vibrofric::exact {

// Without expression templates: std::min, std::optional and the closed-form templates take it as is.
using Rational = boost::multiprecision::number<boost::multiprecision::gmp_rational, boost::multiprecision::et_off>;

// A vertex of a periodic piecewise-linear function: phase x ∈ [0, 1), left and right limits (a
// jump where they differ). Between consecutive vertices (the last one's piece ending at the
// first's x + 1) the function is the straight line from the right limit to the next left limit.
struct Vertex {
  Rational x, left, right;
};

// A piecewise-linear wave w: vertices with increasing x ∈ [0, 1), the first at x = 0.
struct Wave {
  std::string name;
  std::vector<Vertex> vertices;
  Rational minimum() const;
  Rational maximum() const;
};

struct StickPhase {
  Rational begin, end;  // begin ∈ [0, 1), end > begin (past 1 where it wraps the period)
  Rational level;       // s(begin); s = level + β (φ − begin) on the phase
};

struct Result {
  Rational mu;              // μ̄/μ0 = ∫s / ∫n
  Rational retained_area;   // ∫₀¹ s dφ
  Rational normal_area;     // ∫₀¹ n dφ
  Rational lost_area;       // ∫₀¹ (n − s) dφ: Ψ_w(β) without jumping (Eq. 12)
  std::optional<Rational> beta_c;  // largest rising slope of n (Eq. 6); none: an upward jump (∞)
  bool jumping = false;            // n = 0 on a piece of the period
  std::vector<StickPhase> stick_phases;
  std::size_t contact_boundaries = 0;  // phases where n leaves or re-enters 0 inside a piece
};

// Vertices sorted, x ∈ [0, 1), the first at 0: SolverError otherwise (a malformed list is a bug of
// the caller).
void check(const Wave& w);

// The catalogue's piecewise-linear waves (model.md's table) and power:1 (the triangle shifted by
// 1/4), exactly.
Wave triangle();
Wave sawtooth_right();
Wave sawtooth_left();
Wave square();
Wave power_one();

// Samples y_j at phases φ_j (φ_0 = 0 < φ_1 < … < φ_{N−1} < 1; empty: φ_j = j/N), joined by
// straight lines (y_N = y_0), normalised exactly as model.md says and user_waveforms.hpp does:
// w_j = (y_j − mean)/scale, mean = ∫₀¹ of the interpolant, scale = (max − min)/2. InputError for
// fewer than two samples or a constant signal.
Wave samples(std::string name, const std::vector<Rational>& y, const std::vector<Rational>& phases = {});


// μ̄/μ0 at β > 0, γ with contact (γ + max w > 0): DomainError otherwise.
Result solve(const Wave& w, const Rational& beta, const Rational& gamma);
// Ψ_w(β) = lost_area at γ = −min w (Eq. 12), where n touches 0 without jumping.
Result psi(const Wave& w, const Rational& beta);

}  // namespace vibrofric::exact
