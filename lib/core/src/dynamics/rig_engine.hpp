// The rig's solver (core/dynamics/dynamics.hpp, model.md "Rig dynamics: mass and system stiffness"): the
// closed-form motion of each mode between events, the events' bracketing and refinement, the
// sweeping-process rules at jumps and kinks of n, and the shooting for the periodic state. Private
// to the core: RigSolver forwards to RigEngine, instantiated in rig_double.cpp, rig_long_double.cpp
// and rig_mpfr.cpp.
#pragma once
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "vibrofric/core/dynamics/dynamics.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/waves/user_waveforms.hpp"
#include "vibrofric/core/waves/waveform.hpp"
#include "motion.hpp"
#include "period_map.hpp"

namespace vibrofric {
namespace detail {
template <class Real>
class RigEngine {
 public:
  using State = RigState<Real>;

  RigEngine(const Waveform<Real>& w, const Real& beta, const Real& gamma, const RigParameters<Real>& p,
            const Options& opt = {})
      : wave_(w), contact_(w, gamma, opt), beta_(beta), gamma_(gamma), p_(p) {
    using std::sqrt;
    if (!(p.kappa > 0) || !(p.omega > 0) || !(p.zeta >= 0))
      throw DomainError("rig dynamics: expected kappa > 0, omega > 0, zeta >= 0");
    const Real two_pi = boost::math::constants::two_pi<Real>();
    omega2_ = two_pi * p.omega * (two_pi * p.omega);
    c_ = 2 * two_pi * p.zeta * p.omega * sqrt(p.kappa);
    stats_.max_iterations = root_budget<Real>(opt);
    // Exact resonance: K = ω²κ is taken as ν² itself, as the caller decided Ω²κ = k² exactly.
    K_slip_ = p.resonant_harmonic ? Real(two_pi * p.resonant_harmonic * (two_pi * p.resonant_harmonic))
                                  : Real(omega2_ * p.kappa);
    K_stick_ = omega2_ * (p.kappa + 1);
    normal_area_ = 0;
    for (const auto& g : contact_.segments())
      if (g.contact) normal_area_ += gamma * (g.v - g.u) + detail::wave_integral(rig_wave().form(g.piece), g.u, g.v);
  }

  // The one-period map from the state at φ = 0⁻ (the end of the previous period).
  State period(const State& in, RigResult<Real>* record = nullptr) const {
    Run run{in.y, in.v, in.s, RigMode::flight, record};
    const auto& segs = contact_.segments();
    // The mode at 0⁻, from the state against n at the period's end.
    const auto& last = segs.back();
    run.mode = initial_mode(run, last);
    for (std::size_t i = 0; i < segs.size(); ++i) {
      run.segment = i;
      enter(run, i == 0 ? last : segs[i - 1], segs[i]);
      traverse(run, segs[i]);
    }
    return {run.y, run.v, run.s};
  }

  // Y, Y' and s at φ ∈ [span.begin, span.end] of a recorded span (the closed form it was solved with).
  std::array<Real, 3> at(const RigSpan<Real>& span, const Real& phi) const {
    const Segment& g = contact_.segments()[span.segment];
    const Run r{span.y0, span.v0, span.s0, span.mode, nullptr};
    const auto yv = motion(r, g, span.begin)(phi);
    switch (span.mode) {
      case RigMode::stick: return {yv[0], yv[1], Real(span.s0 + (yv[0] - span.y0) + beta_ * (phi - span.begin))};
      case RigMode::forward_slip: return {yv[0], yv[1], n_at(g, phi)};
      case RigMode::backward_slip: return {yv[0], yv[1], Real(-n_at(g, phi))};
      default: return {yv[0], yv[1], Real(0)};
    }
  }
  // n and n' at φ in a recorded span.
  std::array<Real, 2> normal(const RigSpan<Real>& span, const Real& phi) const {
    std::array<Real, 3> d;
    n_at(contact_.segments()[span.segment], phi, &d);
    return {d[0], d[1]};
  }
  // c and ω² of the body's equation (Y'' + cY' + … = −ω² s + …).
  const Real& damping() const { return c_; }
  const Real& omega_squared() const { return omega2_; }
  // The contact's segments (their ends: where n = 0 exactly at a contact boundary).
  const Contact<Real>& contact() const { return contact_; }

  RigResult<Real> solve() const {
    const Real eps = std::numeric_limits<Real>::epsilon();
    // Start 1: the quasi-static state of the series stiffness (the Ω → ∞ limit).
    const Real beta_eff = beta_ * p_.kappa / (p_.kappa + 1);
    State qs{0, 0, 0};
    {
      const Result<Real> r = vibrofric::solve(contact_, beta_eff);
      const Real phi0 = 1 - std::numeric_limits<Real>::epsilon();
      qs.s = tangential_force(wave_, r, beta_eff, gamma_, phi0);
      qs.y = -qs.s / p_.kappa;
    }
    std::size_t steps1 = 0, steps2 = 0;
    double floquet1 = 0, floquet2 = 0;
    Real last1 = 0, last2 = 0;
    const State a = shoot_or_settle(qs, steps1, floquet1, last1);
    const auto J1 = jacobian_;
    const State b = shoot_or_settle(State{0, 0, 0}, steps2, floquet2, last2);
    RigResult<Real> res, other;
    res.retained_area = other.retained_area = 0;
    period(a, &res);
    period(b, &other);
    res.normal_area = other.normal_area = normal_area_;
    res.mu = res.retained_area / normal_area_;
    other.mu = other.retained_area / normal_area_;
    using std::abs;
    const Real diff = abs(Real(res.mu - other.mu));
    const Real scale = std::max(Real(1), abs(res.mu));
    // Two starts, two periodic states: a multiplicity the shooting cannot resolve by itself.
    using std::sqrt;
    if (diff > sqrt(eps) * scale)
      throw SolverError("rig dynamics: two periodic states from two starts (mu = " + detail::short_str(res.mu) +
                        " from the quasi-static state, " + detail::short_str(other.mu) + " from rest)");
    res.state_y = a.y;
    res.state_v = a.v;
    res.state_s = a.s;
    res.newton_steps = steps1;
    res.floquet = floquet1;
    res.jacobian = J1;
    res.relative_error = (diff + abs(last1) + 16 * eps * abs(res.mu)) / abs(res.mu);
    return res;
  }

  // The periodic state from one found at a lower precision (its state and the map's Jacobian):
  // chord iterations u ← u − (J − I)⁻¹(P(u) − u), each one period, which gain the lower
  // precision's digits again per step; Newton from the seed where they do not contract.
  RigResult<Real> solve(const Real& y, const Real& v, const Real& s, const std::array<std::array<double, 3>, 3>& J) const {
    using std::abs;
    const Real eps = std::numeric_limits<Real>::epsilon();
    State u{y, v, s};
    Real last = 0;
    std::size_t steps = 0;
    double floquet = 0;
    if (!chord(u, J, last, steps)) u = shoot(State{y, v, s}, steps, floquet, last, false);
    RigResult<Real> res;
    res.retained_area = 0;
    period(u, &res);
    res.normal_area = normal_area_;
    res.mu = res.retained_area / normal_area_;
    res.state_y = u.y;
    res.state_v = u.v;
    res.state_s = u.s;
    res.newton_steps = steps;
    res.jacobian = J;
    res.floquet = resolved_multiplier(J);
    res.relative_error = (abs(last) + 16 * eps * abs(res.mu)) / abs(res.mu);
    return res;
  }

 private:
  struct Run {
    Real y, v, s;
    RigMode mode;
    RigResult<Real>* record;
    Real ymin = std::numeric_limits<Real>::infinity(), ymax = -std::numeric_limits<Real>::infinity();
    std::size_t segment = 0;
    Real back = 0;  // distance the contact point has moved back in the current backward phase
  };
  using Segment = typename Contact<Real>::Segment;

  // A bound of |n'| (order 1) or |n''| (order 2) on segment g: |p1| + Σ (2πk)^order (|a_k| + |b_k|).
  Real slope_bound(const Segment& g, int order) const {
    if (!g.contact) return Real(0);
    using std::abs;
    const auto& f = form_(g);
    Real b = order == 1 ? Real(abs(f.p1)) : Real(0);
    if (f.a)
      for (std::size_t k = 1; k < f.a->size(); ++k) {
        const Real nu = boost::math::constants::two_pi<Real>() * static_cast<unsigned>(k);
        b += (order == 1 ? nu : Real(nu * nu)) * (abs((*f.a)[k]) + abs((*f.b)[k]));
      }
    return b;
  }
  Real n_at(const Segment& g, const Real& phi, std::array<Real, 3>* d = nullptr) const {
    if (!g.contact) {
      if (d) *d = {Real(0), Real(0), Real(0)};
      return Real(0);
    }
    auto w = detail::wave_derivatives(form_(g), phi);
    w[0] += gamma_;
    if (d) *d = w;
    return w[0];
  }
  const detail::WaveForm<Real>& form_(const Segment& g) const { return rig_wave().form(g.piece); }
  const detail::RigWave<Real>& rig_wave() const {
    if (!rw_) rw_.emplace(wave_);
    return *rw_;
  }

  RigMode initial_mode(Run& r, const Segment& last) const {
    const Real n = last.contact ? last.nv : Real(0);
    const Real dn = last.contact ? last.dnv : Real(0);
    if (!(n > 0)) {
      r.s = 0;
      return RigMode::flight;
    }
    // Within the periodic state's tolerance of ±n (shoot's: 64 eps of the state's scale), s is on
    // the boundary: a stick span of a few ulp at φ = 0 before the slip it ends in would be an
    // artefact of the state's last bits (trace showed one of 2e-36 at β = 100).
    using std::abs;
    const Real scale = state_scale(r.y, r.v, r.s);
    const Real tol = 64 * std::numeric_limits<Real>::epsilon() * scale;
    if (r.s >= n - tol && r.v + beta_ - dn > 0) {
      r.s = n;
      return RigMode::forward_slip;
    }
    if (r.s >= n) {
      r.s = n;
      return RigMode::stick;
    }
    if (r.s <= -n + tol && r.v + beta_ + dn < 0) {
      r.s = -n;
      return RigMode::backward_slip;
    }
    if (r.s <= -n) {
      r.s = -n;
      return r.v + beta_ + dn < 0 ? RigMode::backward_slip : RigMode::stick;
    }
    return RigMode::stick;
  }

  void dissipate(Run& r, const Real& s_new) const {
    if (r.record) r.record->jump_dissipation += (r.s * r.s - s_new * s_new) / 2;
    r.s = s_new;
  }
  // s projected onto [−n, n] in contact at a downward jump of n (instant slip): from below
  // (s < −n) the contact point moves back by the jump of s at once, part of a backward phase.
  void project(Run& r, const Real& s_new) const {
    if (s_new > r.s) {
      r.back += s_new - r.s;
      if (r.record && r.back > r.record->largest_backward_slip) r.record->largest_backward_slip = r.back;
    }
    dissipate(r, s_new);
  }

  // The sweeping-process rules of model.md at the start of segment g (after segment prev).
  void enter(Run& r, const Segment& /*prev*/, const Segment& g) const {
    const Real n = g.contact ? g.nu : Real(0), dn = g.contact ? g.dnu : Real(0);
    const Real xdot = r.v + beta_;
    if (!g.contact) {
      if (r.s != 0) dissipate(r, Real(0));
      r.mode = RigMode::flight;
      return;
    }
    if (n == 0) {
      // Touch-down at a contact boundary, or n touching zero inside the contact (a minimum of
      // γ + w at 0: no flight, but |s| ≤ n = 0 there): the contact forms stress-free, and sticks
      // if |X'| ≤ n', else slips the way X' goes.
      if (r.s != 0) dissipate(r, Real(0));
      using std::abs;
      r.mode = abs(xdot) <= dn ? RigMode::stick : xdot > 0 ? RigMode::forward_slip : RigMode::backward_slip;
      return;
    }
    if (r.mode == RigMode::flight) {  // an upward jump out of the air: the contact re-forms stress-free and sticks
      r.mode = RigMode::stick;
      return;
    }
    if (r.mode == RigMode::forward_slip) {
      if (n > r.s) {  // an upward jump ends slip
        r.mode = RigMode::stick;
        return;
      }
      if (n < r.s) project(r, n);
      if (!(xdot - dn > 0)) r.mode = RigMode::stick;
      return;
    }
    if (r.mode == RigMode::backward_slip) {
      if (n > -r.s) {
        r.mode = RigMode::stick;
        return;
      }
      if (n < -r.s) project(r, Real(-n));
      if (!(xdot + dn < 0)) r.mode = RigMode::stick;
      return;
    }
    // stick: a downward jump below |s| projects s and slips.
    if (r.s > n) {
      project(r, n);
      r.mode = xdot - dn > 0 ? RigMode::forward_slip : RigMode::stick;
    } else if (r.s < -n) {
      project(r, Real(-n));
      r.mode = xdot + dn < 0 ? RigMode::backward_slip : RigMode::stick;
    }
  }

  detail::Motion<Real> motion(const Run& r, const Segment& g, const Real& a) const {
    switch (r.mode) {
      case RigMode::stick: {
        // F = −ω²(βφ − X_c) with βa − X_c = s_a − Y_a.
        return detail::Motion<Real>(c_, K_stick_, a, r.y, r.v, Real(-omega2_ * (r.s - r.y)), Real(-omega2_ * beta_),
                                    nullptr, Real(0), 0);
      }
      case RigMode::forward_slip:
      case RigMode::backward_slip: {
        const Real sign = r.mode == RigMode::forward_slip ? Real(-1) : Real(1);
        return detail::Motion<Real>(c_, K_slip_, a, r.y, r.v, Real(sign * omega2_ * gamma_), Real(0), &form_(g),
                                    Real(sign * omega2_), p_.resonant_harmonic);
      }
      default:
        return detail::Motion<Real>(c_, K_slip_, a, r.y, r.v, Real(0), Real(0), nullptr, Real(0), 0);
    }
  }

  // g(φ) < 0 while the mode holds; its derivative for the touching test.
  std::pair<Real, Real> event(const Run& r, const Segment& g, const detail::Motion<Real>& m, const Real& a,
                              const Real& phi) const {
    const auto yv = m(phi);
    std::array<Real, 3> d;
    n_at(g, phi, &d);
    switch (r.mode) {
      case RigMode::stick: {
        const Real s = r.s + (yv[0] - r.y) + beta_ * (phi - a);
        const Real ds = yv[1] + beta_;
        using std::abs;
        return s >= 0 ? std::pair<Real, Real>{s - d[0], ds - d[1]} : std::pair<Real, Real>{-s - d[0], -ds - d[1]};
      }
      case RigMode::forward_slip: {
        // X_c' = Y' + β − n' > 0 while slipping; (X_c')' = Y'' − n''.
        const Real acc = accel(m, yv, d[0], Real(-1));
        return {-(yv[1] + beta_ - d[1]), -(acc - d[2])};
      }
      case RigMode::backward_slip: {
        const Real acc = accel(m, yv, d[0], Real(1));
        return {yv[1] + beta_ + d[1], acc + d[2]};
      }
      default:
        return {Real(-1), Real(0)};
    }
  }
  // Y'' = F − cY' − KY in slip (s = ±n).
  Real accel(const detail::Motion<Real>& m, const std::array<Real, 2>& yv, const Real& n, const Real& sign) const {
    return sign * omega2_ * n - m.c() * yv[1] - m.K() * yv[0];
  }

  void traverse(Run& r, const Segment& g) const {
    Real a = g.u;
    const Real end = g.v;
    auto f = [&](const detail::Motion<Real>& m, const Real& x) { return event(r, g, m, a, x); };
    // Stick and slip alternate at most a few times per oscillation of the body (K_stick is its
    // fastest): more events than that is chattering, an error.
    using std::ceil;
    using std::sqrt;
    const Real oscillations = ceil(Real((sqrt(K_stick_) + c_ / 2) * (end - a) / boost::math::constants::two_pi<Real>()));
    const long most = 64 + 8 * static_cast<long>(std::min(oscillations, Real(1e7)));
    for (long guard = 0; guard < most; ++guard) {
      const detail::Motion<Real> m = motion(r, g, a);
      Real stop = end;
      bool fired = false;
      if (r.mode != RigMode::flight && end > a) {
        // Grid: 16 points per period of the fastest oscillation in the span, at least 4.
        using std::ceil;
        const Real two_pi = boost::math::constants::two_pi<Real>();
        const Real rate = std::max(m.rate(), Real(two_pi * rig_wave().harmonics()));
        const Real per = ceil(Real(rate * (end - a) / two_pi * 16));
        if (per > 5e7) throw SolverError("rig dynamics: more than 5e7 event-grid points in one span");
        const std::size_t steps = std::max<std::size_t>(4, static_cast<std::size_t>(per) + 1);
        // In stick, g = |s| − n has |g'| ≤ G = max|Y'| + β + max|n'|: no root lies within
        // |g(x)|/G of a point x, which lets the search stride over the long stick phases of a fast
        // body (Ω ≫ 1) instead of resolving each of its oscillations.
        // In slip, g = ∓(Y' + β ∓ n') has |g'| ≤ max|Y''| + max|n''|.
        const Real n1 = slope_bound(g, 1), n2 = slope_bound(g, 2);
        auto G = [&](const Real& x) {
          return r.mode == RigMode::stick ? Real(m.slope_bound(x) + beta_ + n1) : Real(m.curvature_bound(x) + n2);
        };
        const Real cell = (end - a) / static_cast<unsigned>(steps);
        Real x0 = a;
        auto [g0, d0] = f(m, a);
        // The span may start on the event that began it (g = 0 up to rounding, and g' too at a
        // slip → stick event): the first crossing is searched just inside, and where g ≥ 0 at every
        // point down to the start the new mode ends at once.
        const bool at_event = !(g0 < 0);
        if (at_event) g0 = Real(-1);
        while (!fired && x0 < end) {
          Real x1 = x0 + cell;
          // (on the recorded period also no farther than Y can reach a new extreme)
          if (g0 < 0 && !(at_event && x0 == a)) {
            using std::abs;
            Real clear = abs(g0) / G(x0) * Real(0.9375);
            if (r.record) clear = std::min(clear, unremarkable(r, m, x0));
            if (clear > cell) x1 = x0 + clear;
          }
          if (!(x1 < end) || end - x1 < cell / 1024) x1 = end;
          auto [g1, d1] = f(m, x1);
          if (g1 >= 0) {
            Real lo = x0, glo = g0;
            if (at_event && x0 == a) {
              // a point of (a, x1) where g < 0, halving toward a; the first root lies above it
              bool found = false;
              Real hi = x1;
              for (int k = 0; k < 200 && !found; ++k) {
                const Real x = a + (hi - a) / 2;
                if (!(x > a) || !(x < hi)) break;
                const Real gx = f(m, x).first;
                if (gx < 0) {
                  lo = x;
                  glo = gx;
                  found = true;
                } else {
                  hi = x;
                }
              }
              if (!found) {
                stop = a;
                fired = true;
                break;
              }
              x1 = hi;
              g1 = f(m, hi).first;
            }
            stop = detail::bracketed_root<Real>([&](const Real& x) { return f(m, x).first; }, lo, x1, glo, g1,
                                                "rig dynamics event", stats_, Real(1));
            fired = true;
            break;
          }
          if (d0 > 0 && d1 < 0 && !(at_event && x0 == a)) {
            // a local maximum between grid points: does it reach 0? Bisected on g' until it is
            // found, or until |g'| ≤ G rules out g ≥ 0 on [lo, hi] with a margin above rounding
            // (max g ≤ (g(lo) + g(hi))/2 + G (hi − lo)/2): no root, at a few evaluations instead of
            // one per bit of the working precision.
            Real lo = x0, hi = x1, glo = g0, ghi = g1;
            const Real slope = G(x0), margin = 64 * std::numeric_limits<Real>::epsilon() * (1 + abs(g0) + abs(g1));
            bool excluded = false;
            for (int it = 0; it < 400; ++it) {
              if ((glo + ghi) / 2 + slope * (hi - lo) / 2 < -margin) {
                excluded = true;
                break;
              }
              const Real c2 = (lo + hi) / 2;
              if (!(c2 > lo) || !(c2 < hi)) break;
              const auto [gc, dc] = f(m, c2);
              if (dc > 0) {
                lo = c2;
                glo = gc;
              } else {
                hi = c2;
                ghi = gc;
              }
            }
            const Real xm = (lo + hi) / 2;
            const Real gm = excluded ? Real(-1) : f(m, xm).first;
            if (gm >= 0) {
              stop = detail::bracketed_root<Real>([&](const Real& x) { return f(m, x).first; }, x0, xm, g0, gm,
                                                  "rig dynamics event", stats_, Real(1));
              fired = true;
              break;
            }
          }
          if (r.record) track(r, m, x0, x1);
          x0 = x1;
          g0 = g1;
          d0 = d1;
        }
        if (fired && r.record && stop > x0) track(r, m, x0, stop);
      }
      finish(r, g, m, a, stop);
      if (!fired) return;
      // the event at `stop`: stick → slip (|s| = n) or slip → stick (X_c' = 0)
      if (r.record) ++r.record->events;
      if (r.mode == RigMode::stick) {
        const Real n = n_at(g, stop);
        r.mode = r.s >= 0 ? RigMode::forward_slip : RigMode::backward_slip;
        r.s = r.s >= 0 ? n : Real(-n);
      } else {
        r.mode = RigMode::stick;
      }
      a = stop;
      if (!(a < end)) return;
    }
    throw SolverError("rig dynamics: more than " + std::to_string(most) + " events in one piece of the wave (chattering)");
  }

  // How far beyond x0 Y has no extreme outside those seen (for the amplitude's grid): where Y'
  // cannot vanish (|Y'(x0)|/max|Y''|: an extreme is then an end, which track() sees), or Y stays
  // inside [min, max] seen (the room over max|Y'|).
  Real unremarkable(const Run& r, const detail::Motion<Real>& m, const Real& x0) const {
    using std::abs;
    const auto yv = m(x0);
    const Real B1 = m.slope_bound(x0), B2 = m.curvature_bound(x0);
    Real clear = B2 > 0 ? Real(abs(yv[1]) / B2) : Real(1);
    const Real room = std::min(Real(r.ymax - yv[0]), Real(yv[0] - r.ymin));
    if (room > 0 && B1 > 0) clear = std::max(clear, Real(room / B1));
    return clear * Real(0.9375);
  }

  // Y's extremes between two grid points (for the amplitude).
  void track(Run& r, const detail::Motion<Real>& m, const Real& x0, const Real& x1) const {
    const auto y0 = m(x0), y1 = m(x1);
    r.ymin = std::min({r.ymin, y0[0], y1[0]});
    r.ymax = std::max({r.ymax, y0[0], y1[0]});
    if ((y0[1] > 0) != (y1[1] > 0) && y0[1] != 0 && y1[1] != 0) {
      const Real x = detail::bracketed_root<Real>([&](const Real& x) { return m(x)[1]; }, x0, x1, y0[1], y1[1],
                                                  "rig dynamics: extremum of the body's lag", stats_, Real(1));
      const Real y = m(x)[0];
      r.ymin = std::min(r.ymin, y);
      r.ymax = std::max(r.ymax, y);
    }
  }

  // Advance the state to `stop` in the current mode and record the span.
  void finish(Run& r, const Segment& g, const detail::Motion<Real>& m, const Real& a, const Real& stop) const {
    const auto yv = m(stop);
    const Real t = stop - a;
    Real s_end;
    Real area = 0;
    switch (r.mode) {
      case RigMode::stick:
        s_end = r.s + (yv[0] - r.y) + beta_ * t;
        if (r.record) {
          // ∫Y from the ODE: K∫Y = ∫F − [Y'] − c[Y]; s = Y + (s_a − Y_a) + β(φ − a).
          const Real iy = (m.forcing_integral(stop) - (yv[1] - r.v) - c_ * (yv[0] - r.y)) / m.K();
          area = iy + (r.s - r.y) * t + beta_ * t * t / 2;
        }
        break;
      case RigMode::forward_slip:
      case RigMode::backward_slip: {
        const Real n = n_at(g, stop);
        s_end = r.mode == RigMode::forward_slip ? n : Real(-n);
        if (r.record) {
          const Real in = gamma_ * t + detail::wave_integral(form_(g), a, stop);
          area = r.mode == RigMode::forward_slip ? in : Real(-in);
        }
        break;
      }
      default:
        s_end = 0;
    }
    if (r.mode != RigMode::backward_slip) r.back = 0;
    if (r.record && stop > a) {
      auto& res = *r.record;
      res.spans.push_back({r.mode, a, stop, r.y, r.v, r.s, r.segment});
      res.retained_area += area;
      switch (r.mode) {
        case RigMode::stick: res.stick_fraction += t; break;
        case RigMode::flight: res.flight_fraction += t; break;
        case RigMode::backward_slip:
          res.backward_fraction += t;
          res.slip_fraction += t;
          // X_c = X − s moves back by −(ΔY + βt − Δs) over the span.
          r.back -= (yv[0] - r.y) + beta_ * t - (s_end - r.s);
          if (r.back > res.largest_backward_slip) res.largest_backward_slip = r.back;
          break;
        default: res.slip_fraction += t;
      }
      if (r.mode == RigMode::flight) {
        // flight: Y's extremes on a grid of 16 points per oscillation, striding where |Y'| cannot
        // reach 0 (|Y'(x)|/max|Y''|)
        using std::abs;
        using std::ceil;
        const Real cell = t / (ceil(Real(m.rate() * t / boost::math::constants::two_pi<Real>() * 16)) + 1);
        Real x0 = a;
        while (x0 < stop) {
          Real x1 = x0 + cell;
          const Real clear = unremarkable(r, m, x0);
          if (clear > cell) x1 = x0 + clear;
          if (!(x1 < stop) || stop - x1 < cell / 1024) x1 = stop;
          track(r, m, x0, x1);
          x0 = x1;
        }
      }
      r.ymin = std::min(r.ymin, yv[0]);
      r.ymax = std::max(r.ymax, yv[0]);
      res.amplitude = (r.ymax - r.ymin) / 2;
    }
    r.y = yv[0];
    r.v = yv[1];
    r.s = s_end;
  }

  // Newton on P(u) − u = 0 with a finite-difference Jacobian, after a few periods of transient.
  State shoot(State u, std::size_t& steps, double& floquet, Real& last_step, bool transient = true) const {
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    if (transient)
      for (int k = 0; k < 4; ++k) u = period(u);
    auto residual = [&](const State& x, State& px) {
      px = period(x);
      return std::array<Real, 3>{px.y - x.y, px.v - x.v, px.s - x.s};
    };
    auto norm = [](const std::array<Real, 3>& r) {
      using std::abs;
      return std::max({abs(r[0]), abs(r[1]), abs(r[2])});
    };
    State pu;
    auto r = residual(u, pu);
    Real nr = norm(r);
    // While the map contracts fast (residual at least halved a period) its own iteration is the
    // surest way in, also where the state sits on a kink of the map (s clamped to ±n at φ = 0,
    // where difference quotients straddle the kink and Newton wanders).
    for (int k = 0; k < 200; ++k) {
      const Real scale = state_scale(u.y, u.v, u.s);
      if (nr <= 64 * eps * scale) break;
      State next;
      const auto rn = residual(pu, next);
      const Real nn = norm(rn);
      u = pu;
      pu = next;
      r = rn;
      const bool fast = nn <= nr / 2;
      nr = nn;
      if (!fast) break;
    }
    // Where the map is a translation, P(u) = u + r with the same r at P(u) (all slip at an exact
    // undamped resonance: the body's swing grows by the same amount every period, and J = I),
    // Newton has no direction and the dynamics takes as many periods as the state is far. Follow
    // the translation by doubling multiples of r while it holds, bisect for where it ends, and go
    // on from just beyond (sine, beta = 1000, Omega^2 kappa = 1: the state lies 70 periods out).
    auto same = [&](const std::array<Real, 3>& x, const std::array<Real, 3>& y) {
      return norm(std::array<Real, 3>{x[0] - y[0], x[1] - y[1], x[2] - y[2]}) <= norm(x) / 1024;
    };
    auto translated = [&](const Real& m, std::array<Real, 3>& rm) {
      const State t{u.y + m * r[0], u.v + m * r[1], u.s + m * r[2]};
      State pt;
      try {
        rm = residual(t, pt);
      } catch (const SolverError&) {
        return false;
      }
      return same(r, rm);
    };
    auto glide = [&]() {
      if (!(nr > 0)) return;
      std::array<Real, 3> rm;
      if (!translated(Real(1), rm)) return;
      Real lo = 1, hi = 2;
      for (; translated(hi, rm); hi *= 2) {
        lo = hi;
        if (hi > 1e6)
          throw SolverError("rig dynamics: no periodic state found (the one-period map is a translation by " +
                            detail::short_str(nr) + " a period over a million periods: the body's swing grows without bound)");
      }
      for (int k = 0; k < 8; ++k) {
        const Real mid = (lo + hi) / 2;
        (translated(mid, rm) ? lo : hi) = mid;
      }
      u = State{u.y + hi * r[0], u.v + hi * r[1], u.s + hi * r[2]};
      r = residual(u, pu);
      nr = norm(r);
    };
    glide();
    std::array<std::array<Real, 3>, 3> J{};
    // Whole periods of stick (a start far below the state: s climbs by about β a period, and
    // the map is neutral in s meanwhile) may last up to 2 max n/β periods: rounds of 8 periods.
    using std::ceil;
    const Real climb = ceil(Real(2 * (gamma_ + wave_.maximum()) / beta_ / 8));
    const int neutral_rounds = 8 + static_cast<int>(std::min(climb, Real(2000)));
    const int max_steps = 60 + neutral_rounds;
    int neutral = 0, restarts = 0;
    // Jacobian of P by central differences (step ε^(1/3) relative).
    auto jacobian = [&]() {
      using std::cbrt;
      const Real h0 = cbrt(eps);
      for (int j = 0; j < 3; ++j) {
        State up = u, um = u;
        Real* cp = j == 0 ? &up.y : j == 1 ? &up.v : &up.s;
        Real* cm = j == 0 ? &um.y : j == 1 ? &um.v : &um.s;
        const Real h = h0 * std::max(Real(1), abs(*cp));
        *cp += h;
        *cm -= h;
        const State pp = period(up), pm = period(um);
        J[0][j] = (pp.y - pm.y) / (2 * h);
        J[1][j] = (pp.v - pm.v) / (2 * h);
        J[2][j] = (pp.s - pm.s) / (2 * h);
      }
    };
    for (int it = 0; it < max_steps; ++it) {
      const Real scale = state_scale(u.y, u.v, u.s);
      if (nr <= 64 * eps * scale) {
        if (it == 0) jacobian();
        steps = static_cast<std::size_t>(it);
        floquet = store(J);
        last_step = nr;
        return u;
      }
      jacobian();
      // Solve (J − I) δ = −r.
      std::array<std::array<Real, 4>, 3> M;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) M[i][j] = J[i][j] - (i == j ? 1 : 0);
        M[i][3] = -r[i];
      }
      std::array<Real, 3> d;
      if (!solve3(M, d)) {
        // A neutral direction of J (a whole period of stick from a transient start, where any X_c
        // would repeat): no Newton step; let the dynamics move the state on.
        if (++neutral > neutral_rounds)
          throw SolverError("rig dynamics: no periodic state found (the one-period map stays neutral)");
        for (int k = 0; k < 8; ++k) u = period(u);
        r = residual(u, pu);
        nr = norm(r);
        glide();
        continue;
      }
      // Damped step: halve until the residual decreases.
      Real lambda = 1;
      // Far from the state a full step can land anywhere (the map is only piecewise smooth):
      // at most the state's own size plus one, and a trial the map cannot follow is a bad step.
      bool improved = false;
      const Real size = std::max({abs(d[0]), abs(d[1]) / (2 * boost::math::constants::pi<Real>() * p_.omega), abs(d[2])});
      if (size > scale + 1) lambda = (scale + 1) / size;
      for (int h = 0; h < 12; ++h) {
        const State trial{u.y + lambda * d[0], u.v + lambda * d[1], u.s + lambda * d[2]};
        State pt;
        std::array<Real, 3> rt;
        try {
          rt = residual(trial, pt);
        } catch (const SolverError&) {
          lambda /= 2;
          continue;
        }
        const Real nt = norm(rt);
        if (nt < nr) {
          u = trial;
          r = rt;
          nr = nt;
          improved = true;
          break;
        }
        lambda /= 2;
      }
      if (!improved) {
        if (nr <= sqrt(eps) * scale) {  // rounding floor reached above 64 eps: accept, report it
          steps = static_cast<std::size_t>(it);
          floquet = store(J);
          last_step = nr;
          return u;
        }
        // Far from the state, where the map's pieces (its mode sequences) change within the
        // step: move on with the dynamics and try again.
        if (++restarts > 12)
          throw SolverError("rig dynamics: no periodic state found (Newton on the one-period map stalled at residual " +
                            detail::short_str(nr) + ")");
        for (int k = 0; k < 16; ++k) u = period(u);
        r = residual(u, pu);
        nr = norm(r);
        glide();
      }
    }
    throw SolverError("rig dynamics: no periodic state found in " + std::to_string(max_steps) +
                      " Newton steps (residual " + detail::short_str(nr) + ")");
  }

  // The size a state's residual is measured against (shoot's and chord's convergence, the boundary
  // tolerance at φ = 0): Y, s and Y' in units of the body's frequency, at least 1.
  Real state_scale(const Real& y, const Real& v, const Real& s) const {
    using std::abs;
    return std::max({Real(1), abs(y), Real(abs(v) / (2 * boost::math::constants::pi<Real>() * p_.omega)), abs(s)});
  }

  // shoot(u), and where Newton finds no state from u: the dynamics' own transient from u, up to
  // 4000 periods while it still contracts (a weakly attracting state of an undamped rig, multiplier
  // ~0.97, where the map has a kink in every one of its many stick-slip switches), then Newton
  // from where it got to. Its error again where that does not help either.
  State shoot_or_settle(const State& u, std::size_t& steps, double& floquet, Real& last_step) const {
    try {
      return shoot(u, steps, floquet, last_step);
    } catch (const SolverError& first) {
      using std::abs;
      using std::sqrt;
      const Real eps = std::numeric_limits<Real>::epsilon();
      State x = u;
      Real best = -1;
      int since_best = 0;
      try {
        for (int k = 0; k < 4000 && since_best < 200; ++k) {
          const State p = period(x);
          const Real change = std::max({abs(Real(p.y - x.y)), abs(Real(p.v - x.v)), abs(Real(p.s - x.s))});
          x = p;
          if (best < 0 || change < best) {
            best = change;
            since_best = 0;
          } else {
            ++since_best;
          }
          if (change <= sqrt(eps) * state_scale(x.y, x.v, x.s)) break;
        }
        return shoot(x, steps, floquet, last_step, false);
      } catch (const SolverError&) {
        throw first;  // the transient's own failure says less than Newton's
      }
    }
  }

  // Chord iterations from u with a fixed J (see solve(y, v, s, J)); false where they do not contract.
  bool chord(State& u, const std::array<std::array<double, 3>, 3>& Jd, Real& last, std::size_t& steps) const {
    using std::abs;
    const Real eps = std::numeric_limits<Real>::epsilon();
    Real previous = -1;
    for (int it = 0; it < 40; ++it) {
      State pu;
      try {
        pu = period(u);
      } catch (const SolverError&) {
        return false;
      }
      const std::array<Real, 3> r{pu.y - u.y, pu.v - u.v, pu.s - u.s};
      const Real nr = std::max({abs(r[0]), abs(r[1]), abs(r[2])});
      const Real scale = state_scale(u.y, u.v, u.s);
      if (nr <= 64 * eps * scale) {
        last = nr;
        steps = static_cast<std::size_t>(it);
        return true;
      }
      if (previous >= 0 && !(nr < previous / 4)) return false;
      previous = nr;
      std::array<std::array<Real, 4>, 3> M;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) M[i][j] = Real(Jd[i][j]) - (i == j ? 1 : 0);
        M[i][3] = -r[i];
      }
      std::array<Real, 3> d;
      if (!solve3(M, d)) return false;
      u = State{u.y + d[0], u.v + d[1], u.s + d[2]};
    }
    return false;
  }
  // Keeps J (in double) for the result and returns its largest multiplier.
  double store(const std::array<std::array<Real, 3>, 3>& J) const {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) jacobian_[i][j] = static_cast<double>(J[i][j]);
    return resolved_multiplier(jacobian_);
  }
  // The largest multiplier, 0 where it is below what the difference quotients resolve
  // (ε^(2/3) of the working type times the size of J): the map forgets its start within the period
  // (flight, or strong damping), and the bisection's last bits would be printed as a value.
  static double resolved_multiplier(const std::array<std::array<double, 3>, 3>& J) {
    using std::cbrt;
    double size = 0;
    for (const auto& row : J)
      for (double v : row) size = std::max(size, std::abs(v));
    const Real c = cbrt(std::numeric_limits<Real>::epsilon());
    const double floor = static_cast<double>(c * c) * (1 + size);
    const double m = largest_multiplier(J);
    return m < floor ? 0.0 : m;
  }

  const Waveform<Real>& wave_;
  Contact<Real> contact_;
  Real beta_, gamma_;
  RigParameters<Real> p_;
  Real omega2_, c_, K_slip_, K_stick_, normal_area_;
  mutable std::optional<detail::RigWave<Real>> rw_;
  mutable std::array<std::array<double, 3>, 3> jacobian_{};
  mutable detail::RootStats stats_;
};
}  // namespace detail

}  // namespace vibrofric
