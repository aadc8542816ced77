// Exact longitudinal oscillation for piecewise-linear waves (inplane_exact.hpp; model.md,
// "In-plane and combined oscillation").
#include "vibrofric/core/inplane/inplane_exact.hpp"

#include <algorithm>
#include <gmp.h>
#include <string>

namespace vibrofric::exact {

namespace {

// x − ⌊x⌋ ∈ [0, 1).
Rational fraction(const Rational& x) {
  mpz_t q;
  mpz_init(q);
  mpz_fdiv_q(q, mpq_numref(x.backend().data()), mpq_denref(x.backend().data()));
  Rational f;
  mpq_set_z(f.backend().data(), q);
  mpz_clear(q);
  return x - f;
}

// A wave's piece holding x ∈ [0, 1): the last vertex at or before x.
std::size_t piece_of(const Wave& w, const Rational& x) {
  std::size_t k = 0;
  while (k + 1 < w.vertices.size() && w.vertices[k + 1].x <= x) ++k;
  return k;
}

// The straight line of piece k: its value at x (anywhere on the piece, ends included) and slope.
struct Line {
  Rational x0, y0, slope;
  Rational at(const Rational& x) const { return y0 + slope * (x - x0); }
};

Line line_of(const Wave& w, std::size_t k) {
  const auto& v = w.vertices;
  const Rational x1 = k + 1 < v.size() ? v[k + 1].x : Rational(1);
  const Rational& y1 = v[(k + 1) % v.size()].left;
  return {v[k].x, v[k].right, (y1 - v[k].right) / (x1 - v[k].x)};
}

// One segment [u, v]: n and D linear on it (n ≡ 0 in flight).
struct Segment {
  Rational u, v;
  bool flight = false;
  Rational n_u, n_slope;  // n(φ) = n_u + n_slope (φ − u)
  Rational d_u, d_slope;  // D(φ) = d_u + d_slope (φ − u)
  Rational n(const Rational& phi) const { return n_u + n_slope * (phi - u); }
  Rational d(const Rational& phi) const { return d_u + d_slope * (phi - u); }
};

class Walk {
 public:
  Walk(const Wave* normal, const Rational& gamma, const Wave& p, const Rational& beta, const Rational& a,
       const Rational& phase)
      : beta_(beta) {
    const Rational shift = fraction(phase);
    std::vector<Rational> cuts{Rational(0)};
    if (normal) {
      for (std::size_t k = 0; k < normal->vertices.size(); ++k) {
        cuts.push_back(normal->vertices[k].x);
        // a contact boundary inside the piece: γ + w changes sign
        const Line l = line_of(*normal, k);
        const Rational x1 = k + 1 < normal->vertices.size() ? normal->vertices[k + 1].x : Rational(1);
        const Rational ya = gamma + l.y0, yb = gamma + l.at(x1);
        if ((ya < 0 && yb > 0) || (ya > 0 && yb < 0)) cuts.push_back(l.x0 - ya / l.slope);
      }
    }
    for (const Vertex& q : p.vertices) cuts.push_back(fraction(q.x - shift));
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    for (std::size_t k = 0; k < cuts.size(); ++k) {
      Segment g;
      g.u = cuts[k];
      g.v = k + 1 < cuts.size() ? cuts[k + 1] : Rational(1);
      if (normal) {
        const Line l = line_of(*normal, piece_of(*normal, g.u));
        // On a segment γ + w keeps its sign: in contact where it is positive at the midpoint.
        g.flight = !(gamma + l.at((g.u + g.v) / 2) > 0);
        if (!g.flight) g.n_u = gamma + l.at(g.u), g.n_slope = l.slope;
      } else {
        g.n_u = 1;
      }
      const Rational x = fraction(g.u + shift);
      const Line l = line_of(p, piece_of(p, x));
      g.d_u = beta * g.u + a * l.at(x);
      g.d_slope = beta + a * l.slope;
      segs_.push_back(g);
    }
  }

  // n(0⁻): the largest admissible state.
  Rational top() const { return segs_.back().n(segs_.back().v); }

  // s at 1⁻ from s at 0⁻; the spans, areas and fractions of the period in `r`.
  Rational period(Rational s, InPlaneResult* r) const {
    const Segment& last = segs_.back();
    Rational d_before = last.d(last.v) - beta_;  // D(0⁻) = D(1⁻) − β
    for (const Segment& g : segs_) {
      // D's jump moves s with it; then s is projected onto [−n, n] (n may have jumped).
      s += g.d_u - d_before;
      const Rational bound = g.flight ? Rational(0) : g.n_u;
      if (s > bound) s = bound;
      if (s < -bound) s = -bound;
      s = run(g, s, r);
      d_before = g.d(g.v);
      if (r) r->normal_area += g.flight ? Rational(0) : (g.n_u + g.n(g.v)) / 2 * (g.v - g.u);
    }
    return s;
  }

 private:
  static void record(InPlaneResult* r, InPlaneMode mode, const Rational& a, const Rational& b, const Rational& s0,
                     const Rational& s1) {
    if (!r) return;
    const Rational len = b - a;
    r->retained_area += (s0 + s1) / 2 * len;
    switch (mode) {
      case InPlaneMode::stick: r->stick_fraction += len; break;
      case InPlaneMode::forward_slip: r->slip_fraction += len; break;
      case InPlaneMode::backward_slip:
        r->slip_fraction += len;
        r->backward_fraction += len;
        break;
      default: r->flight_fraction += len;
    }
    r->spans.push_back({mode, a, b, s0});
  }

  // From s at g.u (admissible) to s at g.v.
  static Rational run(const Segment& g, Rational s, InPlaneResult* r) {
    if (g.flight) {
      record(r, InPlaneMode::flight, g.u, g.v, 0, 0);
      return 0;
    }
    const Rational forward = g.d_slope - g.n_slope, backward = g.d_slope + g.n_slope;  // λ_f, λ_b
    Rational t = g.u;
    for (;;) {
      const Rational nt = g.n(t);
      // Slip goes on where its rate is not negative, here to the segment's end (the rate is constant).
      if (s >= nt && forward >= 0) {
        record(r, InPlaneMode::forward_slip, t, g.v, nt, g.n(g.v));
        return g.n(g.v);
      }
      if (s <= -nt && backward <= 0) {
        record(r, InPlaneMode::backward_slip, t, g.v, -nt, -g.n(g.v));
        return -g.n(g.v);
      }
      // Stick: s = s_t + D'(φ − t) until it reaches n (rising faster than n) or −n.
      Rational end = g.v;
      if (forward > 0) end = std::min(end, t + (nt - s) / forward);
      if (backward < 0) end = std::min(end, t + (s + nt) / -backward);
      const Rational s_end = s + g.d_slope * (end - t);
      record(r, InPlaneMode::stick, t, end, s, s_end);
      if (end == g.v) return s_end;
      s = s_end;
      t = end;
    }
  }

  Rational beta_;
  std::vector<Segment> segs_;
};

std::string text(const Rational& x) { return x.str(); }

}  // namespace

InPlaneResult solve_inplane(const Wave* normal, const Rational& gamma, const Wave& in_plane, const Rational& beta,
                            const Rational& longitudinal, const Rational& phase) {
  if (normal) check(*normal);
  check(in_plane);
  if (beta < 0) throw InputError("exact in-plane solve: beta = " + text(beta) + ": expected a number >= 0");
  if (longitudinal < 0)
    throw InputError("exact in-plane solve: longitudinal amplitude = " + text(longitudinal) + ": expected a number >= 0");
  if (normal && !(gamma + normal->maximum() > 0))
    throw DomainError("exact in-plane solve of " + normal->name + ": gamma = " + text(gamma) + " gives no contact");
  const Walk walk(normal, gamma, in_plane, beta, longitudinal, phase);
  const Rational top = walk.top();
  const Rational state = walk.period(top, nullptr);
  if (beta == 0) {
    const Rational low = walk.period(-top, nullptr);
    if (low != state)
      throw SolverError("exact in-plane solve: no unique periodic state (from s(0) = " + text(-top) +
                        " the contact comes back to " + text(low) + ", from " + text(top) + " to " + text(state) +
                        "): it sticks through the period");
  }
  InPlaneResult r;
  const Rational again = walk.period(state, &r);
  // F(U) = U for F = clamp(s + β, L, U): anything else is a bug of this walk.
  if (again != state)
    throw SolverError("exact in-plane solve: the periodic state does not repeat (" + text(state) + ", then " +
                      text(again) + ")");
  r.state_s = state;
  r.mu = r.retained_area / r.normal_area;
  return r;
}

}  // namespace vibrofric::exact
