// The longitudinal stop operator's engine (core/inplane/inplane.hpp has the model and the method).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/precision.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/inplane/inplane.hpp"

namespace vibrofric::detail {

// The segments of the in-plane engines: the Contact's (or [0, 1) for n ≡ 1, contact == nullptr) cut at
// p's breakpoints shifted by −P (P in [0, 1)).
template <class Real>
std::vector<InPlaneSegment<Real>> inplane_segments(const Contact<Real>* contact, const Waveform<Real>& p,
                                                   const Real& phase) {
  using Seg = InPlaneSegment<Real>;
  constexpr std::size_t npos = static_cast<std::size_t>(-1);
  std::vector<Seg> segs;
  struct Part {
    Real u;
    std::size_t index;
    Real shift;
    bool jump;
  };
  std::vector<Part> normal, drive;
  if (contact) {
    const auto& cs = contact->segments();
    for (std::size_t k = 0; k < cs.size(); ++k) normal.push_back({cs[k].u, k, Real(0), cs[k].jump});
  } else {
    normal.push_back({Real(0), npos, Real(0), false});
  }
  // p's argument x = φ + P − shift in [0, 1): shift 0 for φ < 1 − P, 1 beyond.
  for (std::size_t j = 0; j < p.piece_count(); ++j) {
    const Real& b = p.piece_begin(j);
    const Real& e = p.piece_end(j);
    if (e > phase) {  // on φ ∈ [b − P, e − P) ∩ [0, 1 − P)
      const bool starts = b >= phase;
      drive.push_back({starts ? Real(b - phase) : Real(0), j, Real(0), starts && p.jump_at(j)});
    }
    if (b < phase) drive.push_back({Real(b + 1 - phase), j, Real(1), p.jump_at(j)});  // ∩ [1 − P, 1)
  }
  std::sort(drive.begin(), drive.end(), [](const Part& x, const Part& y) { return x.u < y.u; });
  std::vector<Real> cuts;
  for (const auto& q : normal) cuts.push_back(q.u);
  for (const auto& q : drive) cuts.push_back(q.u);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::size_t i = 0, j = 0;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    const Real& u = cuts[k];
    const Real v = k + 1 < cuts.size() ? cuts[k + 1] : Real(1);
    if (!(v > u)) continue;
    while (i + 1 < normal.size() && normal[i + 1].u <= u) ++i;
    while (j + 1 < drive.size() && drive[j + 1].u <= u) ++j;
    segs.push_back(Seg{u, v, normal[i].index, drive[j].index, drive[j].shift, normal[i].u == u && normal[i].jump,
                        drive[j].u == u && drive[j].jump});
  }
  if (segs.empty() || segs.front().u != 0)
    throw SolverError("in-plane oscillation: the segments do not start at phase 0");
  return segs;
}

template <class Real>
class InPlaneEngine {
 public:
  using Seg = InPlaneSegment<Real>;
  using Terms = std::array<Real, 3>;  // a function's monotone terms at one phase (their sum is it)
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  InPlaneEngine(const Waveform<Real>* w, const Real& gamma, const Waveform<Real>& p, const Real& beta,
                const InPlaneDrive<Real>& d, const Options& opt)
      : w_(w), p_(p), gamma_(w ? gamma : Real(0)), beta_(beta), a_(d.longitudinal) {
    using std::floor;
    using std::ldexp;
    phase_ = d.phase - floor(d.phase);
    if (!(phase_ < 1)) phase_ = 0;
    stats_.max_iterations = root_budget<Real>(opt);
    const int bits = boost::math::tools::digits<Real>();
    resolution_ = ldexp(Real(1), 2 - bits);
    max_depth_ = 4 * bits + 64;
    if (w) contact_.emplace(*w, gamma, opt);
    segs_ = inplane_segments(contact_ ? &*contact_ : nullptr, p_, phase_);
  }

  const std::vector<Seg>& segments() const { return segs_; }

  Real period(const Real& s_in, InPlaneResult<Real>* record) const {
    Pass pass{*this, record};
    return pass.run(s_in);
  }

  InPlaneResult<Real> solve() const {
    using std::abs;
    using std::ldexp;
    using std::max;
    const Seg& last = segs_.back();
    const Real top = n(last, last.v);  // n(0⁻): the largest admissible start
    const int bits = boost::math::tools::digits<Real>();
    // A period that changes s by less than `noise` sticks throughout (s gains β plus rounding).
    const Real scale = max(top, Real(1));
    const Real noise = ldexp(scale, -3 * bits / 4);
    std::size_t periods = 0;
    Real s = top;
    for (std::size_t k = 0;; ++k) {
      if (k == max_periods)
        throw SolverError("in-plane oscillation: no periodic state from the largest start after " +
                          std::to_string(max_periods) + " periods (s(0) = " + short_str(s) + ")");
      const Real next = period(s, nullptr);
      ++periods;
      const bool settled = next == s || abs(next - s) <= noise;
      s = next;
      if (settled) break;
    }
    // Second start, below the state: the one-period map is monotone and s ↦ F(s) − s nonincreasing,
    // so reaching s again from below proves no other state lies beneath it. A start that comes back
    // to itself is a band of states: the contact sticks through the period (β = 0, small amplitudes).
    if (top > 0) {
      Real low = s - ldexp(scale, -bits / 2);
      if (low < -top) low = -top;
      for (std::size_t k = 0;; ++k) {
        const Real next = period(low, nullptr);
        ++periods;
        if (next == s) break;
        if (abs(next - low) <= noise || k + 1 == max_periods)
          throw SolverError("in-plane oscillation: no unique periodic state (from s(0) = " + short_str(low) +
                            " the contact comes back to " + short_str(next) + ", from " + short_str(top) +
                            " to " + short_str(s) + "): it sticks through the period");
        low = next;
      }
    }
    InPlaneResult<Real> r;
    const Real again = period(s, &r);
    if (abs(again - s) > noise)
      throw SolverError("in-plane oscillation: the periodic state does not repeat (" + short_str(s) + ", then " +
                        short_str(again) + ")");
    r.state_s = s;
    r.periods = periods + 1;
    r.mu = r.retained_area / r.normal_area;
    r.mean_lateral = 0;
    return r;
  }

  std::array<Real, 3> at(const InPlaneSpan<Real>& span, const Real& phi) const {
    const Seg& g = segs_[span.segment];
    const Real nn = n(g, phi), dd = D(g, phi);
    Real s;
    switch (span.mode) {
      case InPlaneMode::stick: s = span.s0 + (dd - D(g, span.begin)); break;
      case InPlaneMode::forward_slip: s = nn; break;
      case InPlaneMode::backward_slip: s = -nn; break;
      default: s = 0;
    }
    return {nn, dd, s};
  }

 private:
  static constexpr std::size_t max_periods = 200;

  bool on_contact(const Seg& g) const {
    return g.contact_segment == npos || contact_->segments()[g.contact_segment].contact;
  }
  Real x(const Seg& g, const Real& phi) const { return phi + phase_ - g.shift; }
  // n on the segment (its cached ends exactly: 0 at a contact boundary).
  Real n(const Seg& g, const Real& phi) const {
    if (g.contact_segment == npos) return Real(1);
    const auto& c = contact_->segments()[g.contact_segment];
    if (!c.contact) return Real(0);
    if (phi == c.u) return c.nu;
    if (phi == c.v) return c.nv;
    const Real r = gamma_ + w_->value(c.piece, phi);
    return r > 0 ? r : Real(0);
  }
  Real dn(const Seg& g, const Real& phi) const {
    if (g.contact_segment == npos) return Real(0);
    const auto& c = contact_->segments()[g.contact_segment];
    return c.contact ? w_->slope(c.piece, phi) : Real(0);
  }
  Real ap(const Seg& g, const Real& phi) const { return a_ == 0 ? Real(0) : Real(a_ * p_.value(g.piece, x(g, phi))); }
  Real adp(const Seg& g, const Real& phi) const { return a_ == 0 ? Real(0) : Real(a_ * p_.slope(g.piece, x(g, phi))); }
  Real D(const Seg& g, const Real& phi) const { return beta_ * phi + ap(g, phi); }
  // Slip goes on where its rate is not negative: λ_f = D' − n' ≥ 0 forward, λ_b = D' + n' ≤ 0
  // backward, each to its rounding level (the slope functions' tol below, as the slip searches use).
  bool slips_forward(const Seg& g, const Real& phi) const {
    const Fn f = slope(g, 1, -1, beta_);
    return f.value(f.terms(phi)) >= -f.tol;
  }
  bool slips_backward(const Seg& g, const Real& phi) const {
    const Fn f = slope(g, 1, 1, beta_);
    return f.value(f.terms(phi)) <= f.tol;
  }
  // ∫ n over [a, b] of the segment.
  Real n_area(const Seg& g, const Real& a, const Real& b) const {
    if (g.contact_segment == npos) return b - a;
    const auto& c = contact_->segments()[g.contact_segment];
    if (!c.contact) return Real(0);
    return gamma_ * (b - a) + (w_->antiderivative(c.piece, b) - w_->antiderivative(c.piece, a));
  }
  // ∫ D over [a, b] of the segment.
  Real d_area(const Seg& g, const Real& a, const Real& b) const {
    Real r = beta_ * (b - a) * (b + a) / 2;
    if (a_ != 0) r += a_ * (p_.antiderivative(g.piece, x(g, b)) - p_.antiderivative(g.piece, x(g, a)));
    return r;
  }

  // A function on a segment: a constant plus three terms, each monotone on the segment. A level
  // function is c + σ_p(βφ + a p) + σ_n n (s − n and −n − s in stick, s = s0 + D − D0); a slope
  // function c + σ_p a p' + σ_n n' (±λ_f, ±λ_b, c = ±β).
  struct Fn {
    const InPlaneEngine* e;
    const Seg* g;
    bool level;
    int sp, sn;
    Real c;
    // The slip-rate functions' rounding level: below it a rate is 0 (D' = ±n' over a whole piece,
    // as p = w at a = 1: slipping and sticking at zero rate are one motion), and noise must not end
    // a slip. 0 for the level functions.
    Real tol = 0;
    // Whether p's (n's) branch is a line on the segment: a sum of lines is one monotone term, so the
    // level functions group them (only two curved terms can cancel: sine with sine, see first()).
    bool lin_p = false, lin_n = false;
    Terms terms(const Real& phi) const {
      if (level) {
        Terms t = level_terms(phi);
        if (lin_p) {
          t[0] += t[1];
          t[1] = 0;
        }
        if (lin_n) {
          t[0] += t[2];
          t[2] = 0;
        }
        return t;
      }
      return slope_terms(phi);
    }
    Terms level_terms(const Real& phi) const {
      {
        Real r = e->beta_ * phi, q = e->ap(*g, phi), nn = e->n(*g, phi);
        if (sp < 0) {
          r = -r;
          q = -q;
        }
        if (sn < 0) nn = -nn;
        return {r, q, nn};
      }
    }
    Real value(const Terms& t) const {
      Real r = c;
      for (const Real& v : t) r += v;
      return r;
    }
    bool has_slope() const { return level; }
    // A slope function's terms; for a level function, those of its derivative.
    Terms slope_terms(const Real& phi) const {
      Real dp = e->adp(*g, phi), dnn = e->dn(*g, phi);
      if (sp < 0) dp = -dp;
      if (sn < 0) dnn = -dnn;
      return {dp, dnn, Real(0)};
    }
    Real slope_c() const { return sp < 0 ? Real(-e->beta_) : e->beta_; }
  };
  Fn level(const Seg& g, int sp, const Real& c) const {
    Fn f{this, &g, true, sp, -1, c};
    linear_parts(f);
    return f;
  }
  Fn slope(const Seg& g, int sp, int sn, const Real& c) const {
    Fn f{this, &g, false, sp, sn, c};
    linear_parts(f);
    using std::abs;
    using std::max;
    const Terms a = f.terms(g.u), b = f.terms(g.v);
    f.tol = abs(c);
    for (std::size_t k = 0; k < a.size(); ++k) f.tol += max(abs(a[k]), abs(b[k]));  // the terms are monotone
    f.tol *= 16 * std::numeric_limits<Real>::epsilon();
    return f;
  }

  void linear_parts(Fn& f) const {
    f.lin_p = a_ == 0 || p_.linear(f.g->piece);
    f.lin_n = f.g->contact_segment == npos || !contact_->segments()[f.g->contact_segment].contact ||
              w_->linear(contact_->segments()[f.g->contact_segment].piece);
  }

  // The first φ in (x0, y0] where f reaches 0 (f ≥ 0; f > 0 if strict), or none. f's terms are
  // monotone on the segment, so each one's range over [x, y] lies between its end values.
  std::optional<Real> first(const Fn& f, bool strict, const Real& x0, const Real& y0) const {
    if (!(y0 > x0)) return std::nullopt;
    const Terms tx = f.terms(x0), ty = f.terms(y0);
    // monotone on the whole segment: one crossing at most
    int dir = 0;
    bool mixed = false;
    const Terms tu = f.terms(g_u(f)), tv = f.terms(g_v(f));
    for (std::size_t k = 0; k < tu.size(); ++k) {
      const int d = tv[k] > tu[k] ? 1 : (tv[k] < tu[k] ? -1 : 0);
      if (d != 0 && dir != 0 && d != dir) mixed = true;
      if (d != 0) dir = d;
    }
    if (!mixed) return monotone(f, strict, x0, y0, f.value(tx), f.value(ty));
    if (!f.lin_p && !f.lin_n) {
      // Two curved terms can cancel (p = w, a = 1: the slip rate is 0 throughout), where enclosures
      // from their ends never decide. Two sines combine into one: f is monotone between the
      // critical points of model.md's closed form below.
      if (const auto cuts = sine_critical_points(f, x0, y0)) {
        Real a = x0;
        for (std::size_t k = 0; k <= cuts->size(); ++k) {
          const Real b = k < cuts->size() ? (*cuts)[k] : y0;
          if (b > a)
            if (auto r = monotone(f, strict, a, b, f.value(f.terms(a)), f.value(f.terms(b)))) return r;
          a = b;
        }
        return std::nullopt;
      }
    }
    std::size_t budget = search_budget;
    return search(f, strict, x0, y0, tx, ty, 0, budget);
  }

  // For p and w both sines: the phases in (x0, y0) where f' = 0, ascending; none for other waves.
  // With θ = 2πφ, Δ = 2πP, A = σ_p a cos Δ + σ_n, B = σ_p a sin Δ:
  //   slope function:  f' ∝ A sin θ + B cos θ            = 0 at θ = atan2(−B, A) + kπ;
  //   level function:  f' = σ_p β + 2π R cos(θ + δ),  R = hypot(A, B), δ = atan2(B, A).
  std::optional<std::vector<Real>> sine_critical_points(const Fn& f, const Real& x0, const Real& y0) const {
    if (!dynamic_cast<const Sine<Real>*>(&p_) || !w_ || !dynamic_cast<const Sine<Real>*>(w_)) return std::nullopt;
    using std::acos;
    using std::atan2;
    using std::cos;
    using std::floor;
    using std::hypot;
    using std::sin;
    const Real two_pi = 2 * boost::math::constants::pi<Real>();
    const Real delta = two_pi * phase_;
    const Real A = f.sp * a_ * cos(delta) + f.sn, B = f.sp * a_ * sin(delta);
    std::vector<Real> thetas;
    if (!f.level) {
      if (A == 0 && B == 0) return std::vector<Real>{};  // f constant
      const Real t0 = atan2(Real(-B), A);
      thetas = {t0, Real(t0 + two_pi / 2)};
    } else {
      const Real R = hypot(A, B);
      if (R == 0) return std::vector<Real>{};  // f = c + σ_p βφ: a line
      const Real q = -f.sp * beta_ / (two_pi * R);
      if (q < -1 || q > 1) return std::vector<Real>{};  // f' keeps its sign
      const Real d = atan2(B, A), t = acos(q);
      thetas = {Real(t - d), Real(-t - d)};
    }
    std::vector<Real> cuts;
    for (const Real& th : thetas) {
      Real phi = th / two_pi;
      phi -= floor(phi);
      for (int k = -1; k <= 1; ++k) {  // θ + kπ for the slope function's period 1/2 as well
        for (const Real& c : {Real(phi + k), Real(phi + k + Real(f.level ? 0 : 1) / 2)})
          if (c > x0 && c < y0) cuts.push_back(c);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    return cuts;
  }
  // The first φ in (x, y] where a monotone f is hit: increasing, from x on if it is hit there, else at
  // its crossing; decreasing, only at x itself, where f must then be strictly past 0 (a decreasing
  // f at exactly 0 is not hit just after x).
  std::optional<Real> monotone(const Fn& f, bool strict, const Real& x, const Real& y, const Real& fx,
                               const Real& fy) const {
    if (fy >= fx) {
      if (hit(fx, strict, f.tol)) return x;
      if (!hit(fy, strict, f.tol)) return std::nullopt;
      return crossing(f, strict, x, y, fx, fy);
    }
    if (fx > f.tol) return x;
    return std::nullopt;
  }
  const Real& g_u(const Fn& f) const { return f.g->u; }
  const Real& g_v(const Fn& f) const { return f.g->v; }
  static bool hit(const Real& v, bool strict, const Real& tol) { return strict ? v > tol : v >= -tol; }

  // Evaluations allowed to one search: far more than the depth times a few roots of any wave the
  // catalogue, samples or a Fourier series give; beyond it the terms cancel and nothing separates
  // the events.
  static constexpr std::size_t search_budget = 1 << 16;

  std::optional<Real> search(const Fn& f, bool strict, const Real& x, const Real& y, const Terms& tx, const Terms& ty,
                             int depth, std::size_t& budget) const {
    using std::max;
    using std::min;
    Real hi = f.c;
    for (std::size_t k = 0; k < tx.size(); ++k) hi += max(tx[k], ty[k]);
    if (!hit(hi, strict, f.tol)) return std::nullopt;
    const Real fy = f.value(ty);
    // A level function whose slope keeps one sign on [x, y] crosses at most once there.
    if (f.has_slope()) {
      const Terms sx = f.slope_terms(x), sy = f.slope_terms(y);
      Real lo_s = f.slope_c(), hi_s = f.slope_c();
      for (std::size_t k = 0; k < sx.size(); ++k) {
        lo_s += min(sx[k], sy[k]);
        hi_s += max(sx[k], sy[k]);
      }
      if (lo_s > 0 || hi_s < 0) return monotone(f, strict, x, y, f.value(tx), fy);
    }
    if (y - x <= resolution_) {
      if (hit(fy, strict, f.tol)) return y;
      return std::nullopt;  // a touch narrower than the working precision
    }
    if (depth > max_depth_ || budget-- == 0)
      throw SolverError("in-plane oscillation: the wave's and the drive's terms cancel on [" + short_str(x) + ", " +
                        short_str(y) + "]: the events there cannot be separated");
    Real m;
    midpoint(m, x, y);
    const Terms tm = f.terms(m);
    if (auto r = search(f, strict, x, m, tx, tm, depth + 1, budget)) return r;
    return search(f, strict, m, y, tm, ty, depth + 1, budget);
  }

  // The crossing of a function monotone on [x, y] (not hit at x, hit at y): the bracket's end
  // where it is hit, or the root itself where f vanishes there.
  Real crossing(const Fn& f, bool strict, const Real& x, const Real& y, const Real& fx, const Real& fy) const {
    const auto fn = [&](const Real& t) { return f.value(f.terms(t)); };
    const int bits = boost::math::tools::digits<Real>();
    boost::math::tools::eps_tolerance<Real> relative(static_cast<unsigned>(bits > 3 ? bits - 2 : 1));
    const auto tol = [&](const Real& a, const Real& b) {
      using std::abs;
      return relative(a, b) || abs(a - b) <= resolution_;
    };
    if (fy == 0) return y;
    std::uintmax_t iterations = stats_.max_iterations;
    std::pair<Real, Real> r;
    try {
      r = boost::math::tools::toms748_solve(fn, x, y, fx, fy, tol, iterations);
    } catch (const std::exception& ex) {
      throw SolverError(std::string("in-plane oscillation: event root finder failed on [") + short_str(x) + ", " +
                        short_str(y) + "]: " + ex.what());
    }
    if (iterations >= stats_.max_iterations && !tol(r.first, r.second))
      throw SolverError("in-plane oscillation: event root finder did not converge on [" + short_str(x) + ", " +
                        short_str(y) + "]");
    if (hit(fn(r.first), strict, f.tol)) return r.first;
    return r.second;  // hit there, or f = 0 exactly at the root (a strict crossing's point)
  }

  // One period's pass from s at 0⁻.
  struct Pass {
    const InPlaneEngine& e;
    InPlaneResult<Real>* rec;
    Real retained = 0, normal = 0;
    std::size_t events = 0;

    void span(InPlaneMode mode, const Real& a, const Real& b, const Real& s0, std::size_t k) {
      if (!rec) return;
      const Seg& g = e.segs_[k];
      const Real len = b - a;
      switch (mode) {
        case InPlaneMode::stick:
          retained += (s0 - e.D(g, a)) * len + e.d_area(g, a, b);
          rec->stick_fraction += len;
          break;
        case InPlaneMode::forward_slip:
          retained += e.n_area(g, a, b);
          rec->slip_fraction += len;
          break;
        case InPlaneMode::backward_slip:
          retained -= e.n_area(g, a, b);
          rec->slip_fraction += len;
          rec->backward_fraction += len;
          break;
        default: rec->flight_fraction += len;
      }
      rec->spans.push_back({mode, a, b, s0, k});
    }

    // The mode at φ on segment g with s admissible there.
    InPlaneMode decide(const Seg& g, const Real& phi, Real& s) const {
      if (!e.on_contact(g)) {
        s = 0;
        return InPlaneMode::flight;
      }
      const Real nn = e.n(g, phi);
      if (s >= nn && e.slips_forward(g, phi)) {
        s = nn;
        return InPlaneMode::forward_slip;
      }
      if (s <= -nn && e.slips_backward(g, phi)) {
        s = -nn;
        return InPlaneMode::backward_slip;
      }
      return InPlaneMode::stick;
    }

    Real run(Real s) {
      const auto& segs = e.segs_;
      const Seg& last = segs.back();
      // The state at 0⁻ is at φ = 1⁻ of the period before: D(0⁻) = D(1⁻) − β.
      Real d_prev = e.D(last, last.v) - e.beta_;
      Real n_prev = e.n(last, last.v);
      InPlaneMode mode = InPlaneMode::stick;
      bool first_segment = true;
      if (s > n_prev) s = n_prev;
      if (s < -n_prev) s = -n_prev;
      for (std::size_t k = 0; k < segs.size(); ++k) {
        const Seg& g = segs[k];
        // Jumps at u: D moves s with it; then s is projected onto [−n, n].
        const Real nu = e.n(g, g.u);
        if (g.p_jump) {
          const Real dj = e.D(g, g.u) - d_prev;
          if (dj != 0) {
            s += dj;
            ++events;
          }
        }
        const bool continuous = !g.p_jump && !g.n_jump && !first_segment;
        if (continuous && mode == InPlaneMode::forward_slip) s = nu;
        else if (continuous && mode == InPlaneMode::backward_slip) s = -nu;
        if (s > nu) {
          s = nu;
          if (g.n_jump) ++events;
        } else if (s < -nu) {
          s = -nu;
          if (g.n_jump) ++events;
        }
        const InPlaneMode before = mode;
        mode = decide(g, g.u, s);
        if (!first_segment && mode != before) ++events;
        first_segment = false;
        s = segment(k, mode, s);
        d_prev = e.D(g, g.v);
        n_prev = e.n(g, g.v);
      }
      if (rec) {
        rec->retained_area = retained;
        rec->normal_area = normal;
        rec->events = events;
      }
      return s;
    }

    // Runs segment k from its start in `mode` with s; returns s at its end, `mode` the mode there.
    Real segment(std::size_t k, InPlaneMode& mode, Real s) {
      const Seg& g = e.segs_[k];
      if (rec) normal += e.n_area(g, g.u, g.v);
      Real phi = g.u;
      for (std::size_t guard = 0;; ++guard) {
        if (guard > 100000)
          throw SolverError("in-plane oscillation: more than 100000 events on one segment at phase " + short_str(phi));
        switch (mode) {
          case InPlaneMode::flight:
            span(mode, phi, g.v, Real(0), k);
            return Real(0);
          case InPlaneMode::forward_slip:
          case InPlaneMode::backward_slip: {
            const bool fwd = mode == InPlaneMode::forward_slip;
            // forward slip ends where −λ_f > 0, backward where λ_b > 0
            const Fn f = fwd ? e.slope(g, -1, 1, Real(-e.beta_)) : e.slope(g, 1, 1, e.beta_);
            const auto end = e.first(f, true, phi, g.v);
            const Real stop = end ? *end : g.v;
            const Real nn = e.n(g, stop);
            span(mode, phi, stop, fwd ? e.n(g, phi) : Real(-e.n(g, phi)), k);
            s = fwd ? nn : Real(-nn);
            if (!end) return s;
            phi = stop;
            mode = InPlaneMode::stick;
            ++events;
            break;
          }
          default: {
            const Real s0 = s, d0 = e.D(g, phi), n0 = e.n(g, phi);
            std::optional<Real> up, down;
            // s − n rises to 0 only after λ_f turns nonnegative; −n − s after λ_b turns nonpositive.
            // s − n rises to 0 only where λ_f ≥ 0 (its slope), −n − s only where λ_b ≤ 0: from
            // s = n (a slip that has just ended) the search starts where λ_f is back at 0.
            const Fn fu = e.level(g, 1, s0 - d0), fd = e.level(g, -1, d0 - s0);
            std::optional<Real> from_u = phi, from_d = phi;
            if (s0 >= n0) from_u = e.first(e.slope(g, 1, -1, e.beta_), false, phi, g.v);
            if (s0 <= -n0) from_d = e.first(e.slope(g, -1, -1, Real(-e.beta_)), false, phi, g.v);
            if (from_u) up = e.first(fu, false, *from_u, g.v);
            if (from_d) down = e.first(fd, false, *from_d, g.v);
            const bool is_up = up && (!down || *up <= *down);
            const std::optional<Real> end = is_up ? up : down;
            const Real stop = end ? *end : g.v;
            span(mode, phi, stop, s0, k);
            if (!end) return s0 + (e.D(g, g.v) - d0);
            phi = stop;
            ++events;
            s = is_up ? e.n(g, phi) : Real(-e.n(g, phi));
            mode = is_up ? InPlaneMode::forward_slip : InPlaneMode::backward_slip;
            // slip only where its rate is nonnegative at once; else the touch is a stick that goes on
            if (is_up ? !e.slips_forward(g, phi) : !e.slips_backward(g, phi)) mode = InPlaneMode::stick;
            break;
          }
        }
      }
    }
  };

  const Waveform<Real>* w_;
  const Waveform<Real>& p_;
  Real gamma_, beta_, a_, phase_;
  std::optional<Contact<Real>> contact_;
  std::vector<Seg> segs_;
  mutable RootStats stats_;
  Real resolution_;
  int max_depth_;
};

}  // namespace vibrofric::detail
