// The lower-envelope characterisation of the steady state (model.md, "Steady state, closed
// characterisation"): s(φ) = inf over 0 ≤ τ < 1 of [ n(φ − τ) + βτ ], evaluated EXACTLY, in
// rational arithmetic, for a piecewise-linear periodic n (jumps allowed). It shares no code or
// event logic with the solver and is the independent check of Eqs. 9–15 (μ̄ = ∫s/∫n, Ψ = ∫(n − s)).
//
// Why it is exact and finite. Fix φ that is not a vertex. τ ↦ n(φ − τ) + βτ is piecewise linear
// on [0, 1) with breaks at τ_k = (φ − x_k) mod 1 ∈ (0, 1), so its infimum is a limit at an end of
// a linear piece: τ = 0 (value n(φ)), τ → τ_k from either side (values R_k + βτ_k and L_k + βτ_k,
// R_k/L_k the right/left limits of n at x_k), or τ → 1⁻ (n(φ) + β, never smaller than τ = 0).
// Hence  s(φ) = min( n(φ), min_k [ min(L_k, R_k) + β·((φ − x_k) mod 1) ] ).
// "mod 1" is taken in (0, 1): φ = x_k itself is a set of measure zero and does not enter ∫s.
// Between consecutive vertices every candidate, and n, is one line in φ, so s is the lower
// envelope of finitely many lines there, which is concave and integrated piece by piece exactly.
#pragma once
#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vibrofric::envelope {

using Rational = boost::multiprecision::cpp_rational;

// A vertex of a periodic piecewise-linear function: phase x ∈ [0, 1), left and right limits.
// Between consecutive vertices (cyclically) the function is the straight line from the right
// limit of one to the left limit of the next.
struct Vertex {
  Rational x, left, right;
};
using Vertices = std::vector<Vertex>;

struct Result {
  Rational retained_area;  // ∫₀¹ s
  Rational normal_area;    // ∫₀¹ n
  Rational mu;             // μ̄/μ0 = ∫s/∫n
  Rational lost() const { return normal_area - retained_area; }
};

namespace detail {

// y = c + m·φ.
struct Line {
  Rational c, m;
  Rational at(const Rational& x) const { return c + m * x; }
};

// Sorted by x, x ∈ [0, 1), distinct; throws otherwise (a malformed list is a bug in the caller).
inline void check(const Vertices& v) {
  if (v.empty()) throw std::invalid_argument("envelope: no vertices");
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k].x < 0 || v[k].x >= 1) throw std::invalid_argument("envelope: vertex phase outside [0, 1)");
    if (k > 0 && !(v[k - 1].x < v[k].x)) throw std::invalid_argument("envelope: vertex phases not increasing");
  }
}

// End of the piece that starts at vertex k (the next vertex, one period on for the last).
inline Rational next_x(const Vertices& v, std::size_t k) { return k + 1 < v.size() ? v[k + 1].x : v[0].x + 1; }

// ∫_a^b min_i lines[i], exactly. The envelope is concave: walk from a, keeping the line that is
// lowest just right of the current point (least value, then least slope), and leave it at its
// first crossing with a line of smaller slope. Each switch lowers the slope, so this ends.
inline Rational integrate_lower_envelope(const std::vector<Line>& lines, const Rational& a, const Rational& b) {
  std::size_t cur = 0;
  Rational best = lines[0].at(a);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const Rational y = lines[i].at(a);
    if (y < best || (y == best && lines[i].m < lines[cur].m)) {
      cur = i;
      best = y;
    }
  }
  Rational x = a, total = 0;
  for (;;) {
    std::size_t next = cur;
    Rational cross = b;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (!(lines[i].m < lines[cur].m)) continue;
      // Strictly right of x: at x, line i lies above cur (or equal with larger slope, excluded).
      const Rational xi = (lines[i].c - lines[cur].c) / (lines[cur].m - lines[i].m);
      if (xi < cross || (xi == cross && next != cur && lines[i].m < lines[next].m)) {
        cross = xi;
        next = i;
      }
    }
    total += (cross - x) * (lines[cur].at(x) + lines[cur].at(cross)) / 2;
    if (next == cur) return total;
    x = cross;
    cur = next;
  }
}

}  // namespace detail

// Exact ∫s, ∫n and μ̄ of the lower envelope of n (given by its vertices, n ≥ 0 not required by
// the algorithm but by the model) under ramps of slope β > 0.
inline Result lower_envelope(const Vertices& n, const Rational& beta) {
  detail::check(n);
  if (!(beta > 0)) throw std::invalid_argument("envelope: beta must be > 0");
  const std::size_t m = n.size();
  Result r;
  std::vector<detail::Line> lines(m + 1);
  for (std::size_t j = 0; j < m; ++j) {
    const Rational a = n[j].x, b = detail::next_x(n, j);
    const Vertex& end = n[(j + 1) % m];
    // n itself on (a, b).
    const Rational slope = (end.left - n[j].right) / (b - a);
    lines[0] = {n[j].right - slope * a, slope};
    // Ramps from every vertex: for φ ∈ (a, b), (φ − x_k) mod 1 is φ − x_k for k ≤ j (x_k ≤ a < φ,
    // and φ < x_0 + 1 ≤ x_k + 1), else φ − x_k + 1 (x_k ≥ b > φ > x_k − 1).
    for (std::size_t k = 0; k < m; ++k) {
      const Rational level = std::min(n[k].left, n[k].right);
      const Rational shift = k <= j ? Rational(n[k].x) : Rational(n[k].x - 1);
      lines[k + 1] = {level - beta * shift, beta};
    }
    r.retained_area += detail::integrate_lower_envelope(lines, a, b);
    r.normal_area += (b - a) * (n[j].right + end.left) / 2;
  }
  if (r.normal_area == 0) throw std::invalid_argument("envelope: n vanishes identically (no contact)");
  r.mu = r.retained_area / r.normal_area;
  return r;
}

// min and max of a PL w (over the one-sided values: those are its extremes, as infimum/supremum).
inline std::pair<Rational, Rational> range(const Vertices& w) {
  detail::check(w);
  Rational lo = std::min(w[0].left, w[0].right), hi = std::max(w[0].left, w[0].right);
  for (const Vertex& v : w) {
    lo = std::min({lo, v.left, v.right});
    hi = std::max({hi, v.left, v.right});
  }
  return {lo, hi};
}

// ∫₀¹ w.
inline Rational mean(const Vertices& w) {
  detail::check(w);
  Rational s = 0;
  for (std::size_t j = 0; j < w.size(); ++j)
    s += (detail::next_x(w, j) - w[j].x) * (w[j].right + w[(j + 1) % w.size()].left) / 2;
  return s;
}

// (w − offset)/scale with offset = ∫₀¹ w and scale = (max − min)/2: model.md's normalisation of a
// user wave (zero mean, unit amplitude), exactly.
struct Normalised {
  Vertices w;
  Rational offset, scale;
};
inline Normalised normalise(const Vertices& w) {
  const auto [lo, hi] = range(w);
  if (!(hi > lo)) throw std::invalid_argument("envelope: constant wave");
  Normalised r{w, mean(w), (hi - lo) / 2};
  for (Vertex& v : r.w) {
    v.left = (v.left - r.offset) / r.scale;
    v.right = (v.right - r.offset) / r.scale;
  }
  return r;
}

// n = max(γ + w, 0), exactly: values shifted and clipped, and a vertex added where a piece
// crosses zero (a rational phase, as the ends are rational). Clipping is then linear per piece.
inline Vertices normal_force(const Vertices& w, const Rational& gamma) {
  detail::check(w);
  const std::size_t m = w.size();
  Vertices out;
  for (std::size_t j = 0; j < m; ++j) {
    const Rational a = w[j].x, b = detail::next_x(w, j);
    const Rational ya = gamma + w[j].right, yb = gamma + w[(j + 1) % m].left;
    out.push_back({a, std::max(Rational(gamma + w[j].left), Rational(0)), std::max(ya, Rational(0))});
    if ((ya < 0 && yb > 0) || (ya > 0 && yb < 0)) {
      Rational x = a + (b - a) * ya / (ya - yb);
      if (x >= 1) x -= 1;
      out.push_back({x, Rational(0), Rational(0)});
    }
  }
  std::sort(out.begin(), out.end(), [](const Vertex& p, const Vertex& q) { return p.x < q.x; });
  return out;
}

// μ̄/μ0 for waveform w at (β, γ); requires contact (γ + max w > 0).
inline Result mu(const Vertices& w, const Rational& beta, const Rational& gamma) {
  return lower_envelope(normal_force(w, gamma), beta);
}

// Ψ_w(β) = ∫(n − s) at γ = −min w (Eq. 12), exactly.
inline Rational psi(const Vertices& w, const Rational& beta) {
  return mu(w, beta, -range(w).first).lost();
}

// ---- Waveforms, exactly (model.md's catalogue: unit period, zero mean, min −1, max +1). ----

// 4φ − 1 on [0, 1/2), 3 − 4φ after.
inline Vertices triangle() { return {{0, -1, -1}, {Rational(1, 2), 1, 1}}; }
// 2φ − 1: a downward jump 1 → −1 at φ = 0.
inline Vertices sawtooth_right() { return {{0, 1, -1}}; }
// 1 − 2φ: an upward jump −1 → 1 at φ = 0.
inline Vertices sawtooth_left() { return {{0, -1, 1}}; }
// 1 on [0, 1/2), −1 after: jumps up at 0, down at 1/2.
inline Vertices square() { return {{0, -1, 1}, {Rational(1, 2), 1, -1}}; }

// y_0 … y_{N−1} at φ = j/N, joined linearly (continuous, periodic), as given (not normalised).
inline Vertices samples(const std::vector<Rational>& y) {
  Vertices v;
  for (std::size_t j = 0; j < y.size(); ++j) v.push_back({Rational(j, y.size()), y[j], y[j]});
  return v;
}

// The samples' values normalised as their wave (the PL mean equals the sample mean), with the
// offset and scale used.
struct NormalisedSamples {
  std::vector<Rational> y;
  Rational offset, scale;
};
inline NormalisedSamples normalise_samples(const std::vector<Rational>& raw) {
  if (raw.size() < 2) throw std::invalid_argument("envelope: fewer than 2 samples");
  const Normalised n = normalise(samples(raw));
  NormalisedSamples r{{}, n.offset, n.scale};
  for (const Vertex& v : n.w) r.y.push_back(v.left);
  return r;
}

}  // namespace vibrofric::envelope
