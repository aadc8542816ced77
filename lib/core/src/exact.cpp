// Exact μ̄/μ0 and Ψ for piecewise-linear waves (exact.hpp; model.md, "Steady state, closed
// characterisation").
#include "vibrofric/core/exact.hpp"

namespace vibrofric::exact {

namespace {

Rational lower(const Vertex& v) { return v.left < v.right ? v.left : v.right; }
Rational upper(const Vertex& v) { return v.left < v.right ? v.right : v.left; }

// The clipped n = max(γ + w, 0), with a vertex (value 0) where γ + w changes sign inside a piece.
std::vector<Vertex> clipped(const Wave& w, const Rational& gamma, Result& r) {
  const auto& v = w.vertices;
  const std::size_t m = v.size();
  auto clip = [](const Rational& y) { return y > 0 ? y : Rational(0); };
  std::vector<Rational> left(m), right(m);  // γ + w at each vertex, from the left and the right
  for (std::size_t k = 0; k < m; ++k) left[k] = gamma + v[k].left, right[k] = gamma + v[k].right;
  const Rational one = 1;
  std::vector<Vertex> n;
  n.reserve(2 * m);
  for (std::size_t k = 0; k < m; ++k) {
    n.push_back({v[k].x, clip(left[k]), clip(right[k])});
    const Rational &a = v[k].x, &b = k + 1 < m ? v[k + 1].x : one;
    const Rational &ya = right[k], &yb = left[(k + 1) % m];
    if ((ya < 0 && yb > 0) || (ya > 0 && yb < 0)) {
      n.push_back({a + (b - a) * ya / (ya - yb), 0, 0});
      ++r.contact_boundaries;
    }
    if (ya < 0 || yb < 0) r.jumping = true;
  }
  return n;
}

}  // namespace

void check(const Wave& w) {
  const auto& v = w.vertices;
  if (v.empty() || v.front().x != 0) throw SolverError("exact wave " + w.name + ": no vertex at phase 0");
  for (std::size_t k = 1; k < v.size(); ++k)
    if (!(v[k - 1].x < v[k].x) || !(v[k].x < 1))
      throw SolverError("exact wave " + w.name + ": vertex phases not increasing in [0, 1)");
}

Rational Wave::minimum() const {
  Rational m = lower(vertices.at(0));
  for (const Vertex& v : vertices) m = std::min(m, lower(v));
  return m;
}

Rational Wave::maximum() const {
  Rational m = upper(vertices.at(0));
  for (const Vertex& v : vertices) m = std::max(m, upper(v));
  return m;
}

Wave triangle() { return {"triangle", {{0, -1, -1}, {Rational(1, 2), 1, 1}}}; }
Wave sawtooth_right() { return {"sawtooth-right", {{0, 1, -1}}}; }
Wave sawtooth_left() { return {"sawtooth-left", {{0, -1, 1}}}; }
Wave square() { return {"square", {{0, -1, 1}, {Rational(1, 2), 1, -1}}}; }
Wave power_one() {
  return {"power:1", {{0, 0, 0}, {Rational(1, 4), 1, 1}, {Rational(1, 2), 0, 0}, {Rational(3, 4), -1, -1}}};
}

Wave samples(std::string name, const std::vector<Rational>& y, const std::vector<Rational>& phases) {
  const std::size_t n = y.size();
  if (n < 2) throw InputError("sampled waveform " + name + " has " + std::to_string(n) + " sample(s): expected at least 2");
  if (!phases.empty() && phases.size() != n) throw SolverError("exact samples " + name + ": phases and samples differ in number");
  auto phase = [&](std::size_t j) { return phases.empty() ? Rational(j, n) : phases[j]; };
  Rational lo = y[0], hi = y[0], mean = 0;
  for (std::size_t j = 0; j < n; ++j) {
    lo = std::min(lo, y[j]);
    hi = std::max(hi, y[j]);
    // The interpolant's integral, the trapezoid rule: Σ y_j (φ_{j+1} − φ_{j−1})/2.
    const Rational next = j + 1 < n ? phase(j + 1) : Rational(1), prev = j > 0 ? phase(j - 1) : Rational(phase(n - 1) - 1);
    mean += y[j] * (next - prev) / 2;
  }
  if (!(hi > lo)) throw InputError("sampled waveform " + name + " is constant: expected a signal with non-zero amplitude");
  const Rational scale = (hi - lo) / 2;
  Wave w{std::move(name), {}};
  w.vertices.reserve(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Rational v = (y[j] - mean) / scale;
    w.vertices.push_back({phase(j), v, v});
  }
  check(w);
  return w;
}

Result solve(const Wave& w, const Rational& beta, const Rational& gamma) {
  check(w);
  if (!(beta > 0)) throw InputError("exact solve of " + w.name + ": beta must be > 0");
  if (!(gamma + w.maximum() > 0)) throw DomainError("exact solve of " + w.name + ": gamma gives no contact");
  Result r;
  const std::vector<Vertex> n = clipped(w, gamma, r);
  const std::size_t m = n.size();
  const Rational one = 1;
  auto end_of = [&](std::size_t k) -> const Rational& { return k + 1 < m ? n[k + 1].x : one; };

  // Per piece k, on [a, b): n's slope, and h = n − βφ at a (from the right) and at b (from the
  // left), computed once for both passes below. The arithmetic is in place, on scratch rationals
  // t and u reused from piece to piece: a temporary per operation was most of the cost.
  std::vector<Rational> slope(m), h_begin(m), h_end(m);
  Rational t, u, twice_area;  // twice_area: 2 ∫n, then 2 ∫s
  // β_c: the largest slope of a piece, or none (∞) at an upward jump of n.
  bool jump_up = false;
  Rational steepest = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const Rational &a = n[k].x, &b = end_of(k), &na = n[k].right, &nb = n[(k + 1) % m].left;
    if (n[k].right > n[k].left) jump_up = true;
    u = b, u -= a;                                    // the piece's length
    slope[k] = nb, slope[k] -= na, slope[k] /= u;     // (nb − na)/(b − a)
    if (slope[k] > steepest) steepest = slope[k];
    t = na, t += nb, t *= u, twice_area += t;         // (b − a)(na + nb)
    t = beta, t *= a, h_begin[k] = na, h_begin[k] -= t;
    t = beta, t *= b, h_end[k] = nb, h_end[k] -= t;
  }
  r.normal_area = twice_area / 2;
  twice_area = 0;
  if (!jump_up) r.beta_c = steepest;

  // min of h = n − βψ over the period before [0, 1): β + its minimum over [0, 1), one-sided
  // limits included (the left limit at 1 is n's at 0 from the left, minus β: h_end of the last
  // piece; the left limit at a vertex x_k > 0 is h_end of the piece before).
  Rational low = h_end[m - 1];
  for (std::size_t k = 0; k < m; ++k) {
    if (h_begin[k] < low) low = h_begin[k];
    if (h_end[k] < low) low = h_end[k];
  }
  Rational M = low + beta;  // min of h over ψ ≤ φ, so far; s = βφ + M

  // A ramp is an interval on which M is constant (s = βφ + M); it is a stick phase where s < n
  // on part of it (`strict`). The ramp running at φ = 0 began in the period before: it is the
  // one still running at φ = 1 (M(1⁻) + β = M(0)), so its end is kept to close that one.
  Rational ramp_from = 0;
  bool strict = false, initial = true, strict_initial = false;
  std::optional<Rational> first_end;
  auto close_ramp = [&](const Rational& x) {
    if (initial) {
      first_end = x;
      strict_initial = strict;
      initial = false;
    } else if (strict && x > ramp_from) {
      r.stick_phases.push_back({ramp_from, x, beta * ramp_from + M});
    }
    strict = false;
  };
  // Twice the ramp's integral over [from, to], (to − from)(2M + β(from + to)), into twice_area.
  auto add_ramp = [&](const Rational& from, const Rational& to) {
    t = from, t += to, t *= beta, t += M, t += M, u = to, u -= from, t *= u, twice_area += t;
  };
  for (std::size_t k = 0; k < m; ++k) {
    const Rational &a = n[k].x, &b = end_of(k), &na = n[k].right, &nb = n[(k + 1) % m].left;
    const Rational &ha = h_begin[k], &hb = h_end[k];
    if (ha < M) {  // n jumps down below the ramp at a: slip onto n
      close_ramp(a);
      M = ha;
      ramp_from = a;
    }
    if (M <= hb) {  // the minimum stays on the whole piece: ramp
      if (M < ha || slope[k] > beta) strict = true;
      add_ramp(a, b);
      continue;
    }
    // h falls below M at c ∈ [a, b): ramp on [a, c], then s = n (slip) to b.
    Rational c = a;
    if (M < ha) {
      t = slope[k], t -= beta, c = M, c -= ha, c /= t, c += a;  // a + (M − h(a))/(n' − β)
      strict = true;
      add_ramp(a, c);
    }
    close_ramp(c);
    // Twice the slip's integral, (b − c)(n(c) + nb), n(c) = na + (c − a) n'.
    t = c, t -= a, t *= slope[k], t += na, t += nb, u = b, u -= c, t *= u, twice_area += t;
    M = hb;
    ramp_from = b;
  }
  r.retained_area = twice_area / 2;
  // The ramp running at φ = 1 goes on into the next period to the initial ramp's end.
  if (!first_end) throw SolverError("exact solve of " + w.name + ": the minimum never follows n (a bug)");
  Rational end = *first_end + 1;
  if ((strict || strict_initial) && end > ramp_from) {
    const Rational level = beta * ramp_from + M;
    if (ramp_from == 1) {  // it starts at the period's end: it is the period's first, from φ = 0
      r.stick_phases.insert(r.stick_phases.begin(), StickPhase{0, *first_end, level});
    } else {
      r.stick_phases.push_back({ramp_from, end, level});
    }
  }
  r.lost_area = r.normal_area - r.retained_area;
  r.mu = r.retained_area / r.normal_area;
  return r;
}

Result psi(const Wave& w, const Rational& beta) { return solve(w, beta, -w.minimum()); }

}  // namespace vibrofric::exact
