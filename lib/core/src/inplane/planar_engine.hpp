// The two-dimensional sweeping process's engine (core/inplane/planar.hpp has the model and the method).
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

#include "radau_collocation.hpp"
#include "inplane_engine.hpp"
#include "vibrofric/core/inplane/planar.hpp"

namespace vibrofric::detail {

template <class Real>
class PlanarEngine {
 public:
  using Seg = InPlaneSegment<Real>;
  using Vec = std::array<Real, 2>;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  PlanarEngine(const Waveform<Real>* w, const Real& gamma, const Waveform<Real>& p, const Real& beta,
               const PlanarDrive<Real>& d, const Options& opt)
      : w_(w),
        p_(p),
        gamma_(w ? gamma : Real(0)),
        beta_(beta),
        al_(d.longitudinal),
        at_(d.transverse),
        tableau_(radau_tableau<Real>(stages_for(boost::math::tools::digits<Real>()))),
        opt_(opt) {
    using std::floor;
    using std::ldexp;
    phase_ = d.phase - floor(d.phase);
    if (!(phase_ < 1)) phase_ = 0;
    root_iterations_ = root_budget<Real>(opt);
    bits_ = boost::math::tools::digits<Real>();
    resolution_ = ldexp(Real(1), 2 - bits_);
    // 2^12 ulps a step: step doubling's own rounding reaches 2^7 ulps where n → 0, and a tolerance
    // at that floor would stall the step size there.
    step_tol_ = ldexp(Real(1), 12 - bits_);
    if (w) contact_.emplace(*w, gamma, opt);
    segs_ = inplane_segments(contact_ ? &*contact_ : nullptr, p_, phase_);
    // One catalogue wave for both, in phase: n' and p' are one function where the contact holds.
    in_phase_ = w && phase_ == 0 && w->name() == p.name();
  }

  // Order 2s − 1 with s = (decimal digits)/4 + 4: the step that reaches the working precision stays near 1/L.
  static int stages_for(int bits) { return std::clamp(bits / 13 + 4, 4, 64); }

  Vec period(const Vec& s_in, PlanarResult<Real>* record) const {
    Pass pass{*this, record};
    return pass.run(s_in);
  }

  PlanarResult<Real> solve() const {
    if (beta_ == 0 && al_ == 0) return across();
    using std::ldexp;
    using std::max;
    const Seg& last = segs_.back();
    const Real top = n(last, last.v);  // n(0⁻)
    const Real scale = max(top, Real(1));
    // The one-period map carries the integration's tolerance over its steps, up to 2^20 ulps a period.
    const Real noise = ldexp(scale, 24 - bits_);
    std::size_t periods = 0;
    Real cond = 1, cond_other = 1;
    const Vec s = settle(Vec{top, Real(0)}, noise, top, periods, cond);
    if (top > 0) {
      const bool zero = s[0] == 0 && s[1] == 0;
      const Vec other = settle(zero ? Vec{Real(-top), Real(0)} : Vec{Real(-s[0]), Real(-s[1])}, noise, top, periods,
                               cond_other);
      // Each state is within |(F' − I)⁻¹| · noise of the fixed point: a weak contraction (a slow
      // slip, β and the amplitudes small) widens that, up to 2^(bits/4); a band of states (sticking
      // through the period) differs by far more.
      const Real widen = std::min(max(cond, cond_other), ldexp(Real(1), bits_ / 4));
      if (dist(other, s) > 64 * noise * widen)
        throw SolverError("in-plane oscillation: no unique periodic state (from s(0) = (" + short_str(top) +
                          ", 0) the state is (" + short_str(s[0]) + ", " + short_str(s[1]) + "), from the opposite start (" +
                          short_str(other[0]) + ", " + short_str(other[1]) + ")): the contact sticks through the period");
    }
    PlanarResult<Real> r;
    const Vec again = period(s, &r);
    if (dist(again, s) > 64 * noise)
      throw SolverError("in-plane oscillation: the periodic state does not repeat ((" + short_str(s[0]) + ", " +
                        short_str(s[1]) + "), then (" + short_str(again[0]) + ", " + short_str(again[1]) + "))");
    r.state = s;
    r.periods = periods + 1;
    r.stages = tableau_.s;
    r.mu = r.retained_area / r.normal_area;
    r.mean_lateral = r.lateral_area / r.normal_area;
    return r;
  }

  std::array<Real, 3> at(const PlanarSpan<Real>& span, const Real& phi) const {
    const Seg& g = segs_[span.segment];
    const Real nn = n(g, phi);
    switch (span.mode) {
      case PlanarMode::stick: {
        const Vec d0 = D(g, span.begin), d = D(g, phi);
        return {nn, span.sx + (d[0] - d0[0]), span.sy + (d[1] - d0[1])};
      }
      case PlanarMode::slip: {
        if (nn == 0) return {nn, Real(0), Real(0)};
        // As Pass::segment integrates it: from touch-down along D' past the start's cut, and up to
        // the end's cut where contact is lost (|s| ≤ n is below 2^-bits beyond it).
        Real t = span.begin;
        Uv y = from_angle(span.sx, span.sy);
        if (span.sx == 0 && span.sy == 0) {
          t = std::min(contact_cut(g, false), phi);
          const Vec d = dD(g, t);
          y = from_angle(d[0], d[1]);
        }
        const std::size_t k = span.segment;
        const Seg& next = segs_[k + 1 < segs_.size() ? k + 1 : 0];
        const Real stop = on_contact(g) && (n(g, g.v) == 0 || !on_contact(next)) ? std::min(phi, contact_cut(g, true)) : phi;
        Real h = (stop - t) / 4;
        while (t < stop) {
          const Real hh = std::min(h, Real(stop - t));
          Real next_h;
          Step st;
          if (!controlled(g, t, y, hh, st, next_h)) {
            using std::abs;
            if (!(next_h > resolution_ * std::max(Real(1), abs(t))))
              throw SolverError("in-plane oscillation: the slip integrator's step underflows at phase " + short_str(t));
            h = next_h;
            continue;
          }
          t = hh == stop - t ? stop : Real(t + hh);
          y = st.y;
          h = next_h;
        }
        const Vec e = unit(y);
        return {nn, nn * e[0], nn * e[1]};
      }
      default: return {nn, Real(0), Real(0)};
    }
  }

  const std::vector<Seg>& segments() const { return segs_; }

  // No sliding and no longitudinal drive (β = 0, a_l = 0): D' lies along y, s_x = 0 is invariant,
  // s_x stays in stick, and |s_x| falls in slip (s_x' = −λ cos θ) and at every projection. A
  // periodic state that slips at all therefore has s_x = 0: the longitudinal stop operator of s_y
  // (inplane.hpp) with the amplitude a_t, which also says where the contact sticks through the
  // period (a band of states here too: a narrower disc cannot let a wider one's slip stick). The
  // one-period map's fixed point is not found where it is reached only algebraically (a slip of
  // measure zero, a_t at the edge of sticking).
  PlanarResult<Real> across() const {
    const InPlaneEngine<Real> line(w_, gamma_, p_, Real(0), InPlaneDrive<Real>{at_, phase_}, opt_);
    const InPlaneResult<Real> q = line.solve();
    PlanarResult<Real> r;
    r.mu = 0;
    r.retained_area = 0;
    r.mean_lateral = q.mu;
    r.lateral_area = q.retained_area;
    r.normal_area = q.normal_area;
    r.stick_fraction = q.stick_fraction;
    r.slip_fraction = q.slip_fraction;
    r.flight_fraction = q.flight_fraction;
    r.state = {Real(0), q.state_s};
    r.events = q.events;
    r.periods = q.periods;
    r.stages = tableau_.s;
    for (const auto& span : q.spans) {
      const PlanarMode mode = span.mode == InPlaneMode::stick    ? PlanarMode::stick
                              : span.mode == InPlaneMode::flight ? PlanarMode::flight
                                                                 : PlanarMode::slip;
      r.spans.push_back({mode, span.begin, span.end, Real(0), span.s0, span.segment});
    }
    return r;
  }

 private:
  static constexpr std::size_t max_periods = 1000;
  static constexpr std::size_t search_budget = 1 << 14;
  static constexpr std::size_t max_steps = 20000;  // tried steps of one slip span

  struct Uv {
    Real u, v;  // tan(θ/2) = u/v, normalised to u² + v² = 1
  };
  struct Step {
    Uv y;
    Real ix, iy;  // ∫ n cos θ, ∫ n sin θ over the step
  };
  struct Iv {
    Real lo, hi;
  };

  static Real dist(const Vec& a, const Vec& b) {
    using std::hypot;
    return hypot(a[0] - b[0], a[1] - b[1]);
  }

  // The fixed point of the one-period map F from s: Broyden's quasi-Newton steps on r(x) = F(x) − x
  // (B starts at −I, the plain iteration x ← F(x)), falling back to the plain step where r does
  // not shrink (F is only piecewise smooth: an event may appear). Each trial is projected onto the
  // disc |x| ≤ top, as a period's start is: where F shifts a sticking state (F' = I, B singular),
  // the long secant step then ends on the disc's edge instead of crawling by β a period. Stops
  // where |r| ≤ noise; `cond` is |B⁻¹| there (the fixed point's sensitivity to F's error), 1 where
  // B was not updated.
  Vec settle(const Vec& s, const Real& noise, const Real& top, std::size_t& periods, Real& cond) const {
    using std::abs;
    using std::max;
    const auto map = [&](const Vec& x) {
      if (periods++ >= max_periods)
        throw SolverError("in-plane oscillation: no periodic state after " + std::to_string(max_periods) +
                          " periods (s(0) = (" + short_str(x[0]) + ", " + short_str(x[1]) + "))");
      return period(x, nullptr);
    };
    const auto norm = [](const Vec& v) {
      using std::hypot;
      return hypot(v[0], v[1]);
    };
    Vec x = s, fx = map(x);
    Vec r{fx[0] - x[0], fx[1] - x[1]};
    std::array<Real, 4> B{Real(-1), Real(0), Real(0), Real(-1)};
    while (norm(r) > noise) {
      const Real det = B[0] * B[3] - B[1] * B[2];
      Vec xn;
      if (det != 0) {
        xn = {x[0] - (B[3] * r[0] - B[1] * r[1]) / det, x[1] - (-B[2] * r[0] + B[0] * r[1]) / det};
        Pass::project(xn, top);
      } else if (top > 0) {
        // B singular: F shifts x along r (a sticking state). Go to the disc's edge along r.
        const Real k = 2 * top / norm(r);
        xn = {x[0] + k * r[0], x[1] + k * r[1]};
        Pass::project(xn, top);
      } else {
        xn = fx;
      }
      Vec fn = map(xn);
      Vec rn{fn[0] - xn[0], fn[1] - xn[1]};
      if (!(norm(rn) < norm(r)) && xn != fx) {  // no progress: the plain step, and B afresh
        xn = fx;
        fn = map(xn);
        rn = {fn[0] - xn[0], fn[1] - xn[1]};
        B = {Real(-1), Real(0), Real(0), Real(-1)};
      }
      const Vec dx{xn[0] - x[0], xn[1] - x[1]}, dr{rn[0] - r[0], rn[1] - r[1]};
      const Real dd = dx[0] * dx[0] + dx[1] * dx[1];
      if (dd > 0) {
        const Vec q{dr[0] - (B[0] * dx[0] + B[1] * dx[1]), dr[1] - (B[2] * dx[0] + B[3] * dx[1])};
        B = {B[0] + q[0] * dx[0] / dd, B[1] + q[0] * dx[1] / dd, B[2] + q[1] * dx[0] / dd, B[3] + q[1] * dx[1] / dd};
      }
      x = xn;
      fx = fn;
      r = rn;
    }
    const Real det = B[0] * B[3] - B[1] * B[2];
    cond = det == 0 ? Real(std::numeric_limits<Real>::infinity())
                    : Real(max(Real(abs(B[3]) + abs(B[1])), Real(abs(B[2]) + abs(B[0]))) / abs(det));
    if (cond < 1) cond = 1;
    return fx;
  }

  bool on_contact(const Seg& g) const {
    return g.contact_segment == npos || contact_->segments()[g.contact_segment].contact;
  }
  Real x(const Seg& g, const Real& phi) const { return phi + phase_ - g.shift; }
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
  Real pv(const Seg& g, const Real& phi) const { return p_.value(g.piece, x(g, phi)); }
  Real dp(const Seg& g, const Real& phi) const { return p_.slope(g.piece, x(g, phi)); }
  Vec D(const Seg& g, const Real& phi) const {
    const Real q = pv(g, phi);
    return {beta_ * phi + al_ * q, at_ * q};
  }
  Vec dD(const Seg& g, const Real& phi) const {
    const Real q = dp(g, phi);
    return {beta_ + al_ * q, at_ * q};
  }
  Real n_area(const Seg& g, const Real& a, const Real& b) const {
    if (g.contact_segment == npos) return b - a;
    const auto& c = contact_->segments()[g.contact_segment];
    if (!c.contact) return Real(0);
    return gamma_ * (b - a) + (w_->antiderivative(c.piece, b) - w_->antiderivative(c.piece, a));
  }
  Real p_area(const Seg& g, const Real& a, const Real& b) const {
    return p_.antiderivative(g.piece, x(g, b)) - p_.antiderivative(g.piece, x(g, a));
  }

  // Ranges over [a, b] of a segment: p, p', n and n' are monotone there.
  static Iv hull(const Real& a, const Real& b) { return a <= b ? Iv{a, b} : Iv{b, a}; }
  static Iv mul(const Iv& a, const Iv& b) {
    using std::max;
    using std::min;
    const Real p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    return {min(min(p1, p2), min(p3, p4)), max(max(p1, p2), max(p3, p4))};
  }
  static Iv add(const Iv& a, const Iv& b) { return {a.lo + b.lo, a.hi + b.hi}; }
  static Iv affine(const Real& c, const Real& k, const Iv& a) {  // c + k a, k ≥ 0
    return {c + k * a.lo, c + k * a.hi};
  }
  // cos over [lo, hi]: its end values, and ±1 where a multiple of π lies inside.
  static Iv cos_range(const Real& lo, const Real& hi) {
    using std::ceil;
    using std::cos;
    using std::max;
    using std::min;
    const Real pi = boost::math::constants::pi<Real>();
    if (hi - lo >= 2 * pi) return {Real(-1), Real(1)};
    const Real a = cos(lo), b = cos(hi);
    Iv r{min(a, b), max(a, b)};
    if (2 * pi * ceil(lo / (2 * pi)) <= hi) r.hi = 1;
    if (2 * pi * ceil((lo - pi) / (2 * pi)) + pi <= hi) r.lo = -1;
    return r;
  }
  Iv dD_range(const Seg& g, const Real& a, const Real& b, int k) const {
    const Iv q = hull(dp(g, a), dp(g, b));
    return k == 0 ? affine(beta_, al_, q) : affine(Real(0), at_, q);
  }
  Iv dn_range(const Seg& g, const Real& a, const Real& b) const { return hull(dn(g, a), dn(g, b)); }
  Iv n_range(const Seg& g, const Real& a, const Real& b) const { return hull(n(g, a), n(g, b)); }

  // The slip rate λ = D'·e − n' and its rounding level on a segment.
  static Vec unit(const Uv& y) {
    const Real r = y.u * y.u + y.v * y.v;
    return {(y.v * y.v - y.u * y.u) / r, 2 * y.u * y.v / r};
  }
  static Uv from_angle(const Real& sx, const Real& sy) {
    using std::atan2;
    using std::cos;
    using std::sin;
    const Real half = atan2(sy, sx) / 2;
    return {sin(half), cos(half)};
  }
  // An angle difference into (−π, π].
  static Real wrap(Real d) {
    const Real pi = boost::math::constants::pi<Real>();
    while (d > pi) d -= 2 * pi;
    while (d <= -pi) d += 2 * pi;
    return d;
  }
  static Real angle(const Uv& y) {
    using std::atan2;
    return 2 * atan2(y.u, y.v);
  }
  Real lambda(const Seg& g, const Real& t, const Vec& e) const {
    const Vec d = dD(g, t);
    return d[0] * e[0] + d[1] * e[1] - dn(g, t);
  }
  Real lambda_tol(const Seg& g) const {
    using std::abs;
    using std::max;
    const Iv dx = dD_range(g, g.u, g.v, 0), dy = dD_range(g, g.u, g.v, 1), dnr = dn_range(g, g.u, g.v);
    return 16 * std::numeric_limits<Real>::epsilon() *
           (max(abs(dx.lo), abs(dx.hi)) + max(abs(dy.lo), abs(dy.hi)) + max(abs(dnr.lo), abs(dnr.hi)));
  }

  // One Radau IIA step of length h from (t, y) on the angle equation θ' = (D'·e⊥)/n = (|D'|/n) sin(ψ − θ)
  // (ψ the angle of D'): the stage system by Newton's method from θ(t), each update at most π/4
  // (the stages stay on the branch that θ follows); false where n vanishes at a stage, the Jacobian
  // is singular or Newton does not converge. Where |D'|/n ≫ 1/h the angle relaxes onto ψ within the
  // step, and the L-stable method follows that in steps as long as ψ's own variation allows.
  bool radau(const Seg& g, const Real& t, const Uv& y, const Real& h, Step& out) const {
    using std::abs;
    using std::cos;
    using std::ldexp;
    using std::max;
    using std::sin;
    const int s = tableau_.s;
    std::vector<Real> nn(static_cast<std::size_t>(s)), dx(static_cast<std::size_t>(s)), dy(static_cast<std::size_t>(s));
    for (int i = 0; i < s; ++i) {
      const Real ti = t + tableau_.c[static_cast<std::size_t>(i)] * h;
      const Real ni = n(g, ti);
      if (!(ni > 0)) return false;
      const Vec d = dD(g, ti);
      nn[static_cast<std::size_t>(i)] = ni;
      dx[static_cast<std::size_t>(i)] = d[0] / ni;
      dy[static_cast<std::size_t>(i)] = d[1] / ni;
    }
    const Real theta0 = angle(y);
    const Real pi = boost::math::constants::pi<Real>();
    const Real tol = ldexp(Real(8), -bits_) * (1 + abs(theta0));
    std::vector<Real> th(static_cast<std::size_t>(s), theta0), f(static_cast<std::size_t>(s)), df(static_cast<std::size_t>(s));
    std::vector<Real> K(static_cast<std::size_t>(s * s)), r(static_cast<std::size_t>(s));
    Real last = std::numeric_limits<Real>::infinity();
    for (int iter = 0;; ++iter) {
      if (iter == 60) return false;
      for (int j = 0; j < s; ++j) {
        const std::size_t J = static_cast<std::size_t>(j);
        const Real sn = sin(th[J]), cs = cos(th[J]);
        f[J] = dy[J] * cs - dx[J] * sn;
        df[J] = -(dx[J] * cs + dy[J] * sn);
      }
      for (int i = 0; i < s; ++i) {
        Real sum = 0;
        for (int j = 0; j < s; ++j) {
          const Real ha = h * tableau_.A(i, j);
          sum += ha * f[static_cast<std::size_t>(j)];
          K[static_cast<std::size_t>(i * s + j)] = (i == j ? Real(1) : Real(0)) - ha * df[static_cast<std::size_t>(j)];
        }
        r[static_cast<std::size_t>(i)] = theta0 + sum - th[static_cast<std::size_t>(i)];
      }
      if (!solve_linear(K, r, s)) return false;
      Real big = 0;
      for (const Real& d : r) big = max(big, Real(abs(d)));
      const Real scale = big > pi / 4 ? Real(pi / 4 / big) : Real(1);
      for (int i = 0; i < s; ++i) th[static_cast<std::size_t>(i)] += scale * r[static_cast<std::size_t>(i)];
      if (big <= tol) break;
      // Past the quadratic phase the updates stall at the rounding of the stage sums.
      if (big < ldexp(Real(1), -bits_ / 2) && !(big < last / 2)) break;
      last = big;
    }
    Real ix = 0, iy = 0;
    for (int i = 0; i < s; ++i) {
      const std::size_t I = static_cast<std::size_t>(i);
      ix += tableau_.b[I] * nn[I] * cos(th[I]);
      iy += tableau_.b[I] * nn[I] * sin(th[I]);
    }
    const Real half = th.back() / 2;
    out.y = Uv{sin(half), cos(half)};
    out.ix = h * ix;
    out.iy = h * iy;
    return true;
  }

  // A step of h with step doubling: true (and the two half steps' result) where the difference is
  // within step_tol_; next_h the step to try next either way.
  bool controlled(const Seg& g, const Real& t, const Uv& y, const Real& h, Step& out, Real& next_h) const {
    using std::abs;
    using std::max;
    using std::pow;
    Step full, a, b;
    const Real half = h / 2;
    if (!radau(g, t, y, h, full) || !radau(g, t, y, half, a) || !radau(g, Real(t + half), a.y, half, b)) {
      next_h = h / 4;
      return false;
    }
    // The error in s = n e(θ) and in its areas: where n → 0 an error in θ moves s by n times as
    // much (and the slip equation damps it), while n's own rounding there, relative to n, sets a
    // floor under θ's error that would stall the step. (u, v) and −(u, v) are one angle.
    const Real sign = full.y.u * b.y.u + full.y.v * b.y.v < 0 ? Real(-1) : Real(1);
    const Real n_max = max(n(g, t), n(g, Real(t + h)));
    const Real err = max(n_max * max(abs(full.y.u - sign * b.y.u), abs(full.y.v - sign * b.y.v)),
                         abs(full.ix - a.ix - b.ix) + abs(full.iy - a.iy - b.iy));
    const Real order = 2 * tableau_.s;  // the local error of an order 2s − 1 method
    Real factor = err == 0 ? Real(4) : Real(Real(0.9) * pow(step_tol_ / err, 1 / order));
    factor = std::clamp(factor, Real(0.2), Real(4));
    next_h = h * factor;
    if (err > step_tol_) return false;
    out.y = b.y;
    out.ix = a.ix + b.ix;
    out.iy = a.iy + b.iy;
    return true;
  }

  // The first φ in [a, b] of the step from (x0, y0) where λ < −tol; ya, yb the states at a and b.
  std::optional<Real> slip_end(const Seg& g, const Real& x0, const Uv& y0, const Real& a, const Uv& ya, const Real& b,
                               const Uv& yb, const Real& tol, const Real& step, std::size_t& budget) const {
    using std::abs;
    using std::max;
    using std::min;
    const Real pi = boost::math::constants::pi<Real>();
    const Real w = b - a;
    // λ's range: D' and n' from the pieces' ends, e from θ's range, the narrower of two enclosures:
    // |θ'| ≤ |D'|/n from both ends; and, θ' = (|D'|/n) sin(ψ − θ) turning θ towards D''s angle ψ,
    // the hull of θ(a) and ψ's range (invariant while it is narrower than π), which stays narrow
    // where |D'|/n is large (the stiff slip of a large amplitude).
    const Iv dx = dD_range(g, a, b, 0), dy = dD_range(g, a, b, 1), dnr = dn_range(g, a, b);
    const Iv nr = n_range(g, a, b);
    bool excluded = false;
    if (nr.lo > 0) {
      const Real ta = angle(ya);
      std::optional<Iv> range;  // θ − θ(a)
      const Real speed = max(abs(dx.lo), abs(dx.hi)) + max(abs(dy.lo), abs(dy.hi));
      const Real sweep = speed / nr.lo * w;
      if (sweep < pi) {
        const Real d = wrap(Real(angle(yb) - ta));
        range = Iv{(d - sweep) / 2, (d + sweep) / 2};
      }
      // D' = (β + a_l q, a_t q) with q = p' in its range: a segment, whose angle is monotone along it.
      const Iv q = hull(dp(g, a), dp(g, b));
      const Vec d0{beta_ + al_ * q.lo, at_ * q.lo}, d1{beta_ + al_ * q.hi, at_ * q.hi};
      const Real cross = d0[0] * d1[1] - d0[1] * d1[0], dot = d0[0] * d1[0] + d0[1] * d1[1];
      if ((d0[0] != 0 || d0[1] != 0) && (d1[0] != 0 || d1[1] != 0) && (cross != 0 || dot > 0)) {  // 0 not on it
        using std::atan2;
        const Real p0 = wrap(Real(atan2(d0[1], d0[0]) - ta));
        const Real p1 = p0 + wrap(Real(atan2(d1[1], d1[0]) - ta - p0));
        const Iv inv{std::min({p0, p1, Real(0)}), max({p0, p1, Real(0)})};
        if (inv.hi - inv.lo < pi)
          range = range ? Iv{max(range->lo, inv.lo), std::min(range->hi, inv.hi)} : inv;
      }
      if (range) {
        const Real lo = ta + range->lo, hi = ta + range->hi;
        const Iv c = cos_range(lo, hi), s = cos_range(Real(lo - pi / 2), Real(hi - pi / 2));
        const Iv lam = add(mul(dx, c), mul(dy, s));
        excluded = lam.lo - dnr.hi >= -tol;
        if (!excluded && in_phase_ && g.contact_segment != npos && on_contact(g)) {
          // n' = p' here: λ = β e_x + p' (|a| cos(θ − ψ_a) − 1) with a = (a_l, a_t), whose enclosure
          // keeps the tie |a| cos(θ − ψ_a) = 1 (the force riding the circle at the rate the disc grows) at 0.
          using std::atan2;
          using std::hypot;
          const Real psi_a = atan2(at_, al_);
          const Iv k = affine(Real(-1), hypot(al_, at_), cos_range(Real(lo - psi_a), Real(hi - psi_a)));
          excluded = add(mul(Iv{beta_, beta_}, c), mul(q, k)).lo >= -tol;
        }
      }
    }
    if (excluded) return std::nullopt;
    const Real la = lambda(g, a, unit(ya)), lb = lambda(g, b, unit(yb));
    if (w <= resolution_ * max(Real(1), abs(b))) {
      if (lb < -tol) return b;
      return std::nullopt;
    }
    if (budget-- == 0)
      throw SolverError("in-plane oscillation: the slip rate stays near 0 on [" + short_str(a) + ", " + short_str(b) +
                        "]: the end of slip cannot be separated");
    if (la >= -tol && lb < -tol && w * 64 <= step) {
      // One crossing bracketed on a short interval: refined by toms748.
      const auto f = [&](const Real& t) -> Real {
        if (t == x0) return lambda(g, t, unit(y0)) + tol;
        Step st;
        if (!radau(g, x0, y0, Real(t - x0), st))
          throw SolverError("in-plane oscillation: the slip integrator failed between phases " + short_str(x0) +
                            " and " + short_str(t));
        return lambda(g, t, unit(st.y)) + tol;
      };
      const int bits = bits_;
      boost::math::tools::eps_tolerance<Real> rel(static_cast<unsigned>(bits > 3 ? bits - 2 : 1));
      const auto stop = [&](const Real& p, const Real& q) { return rel(p, q) || abs(p - q) <= resolution_; };
      std::uintmax_t it = root_iterations_;
      std::pair<Real, Real> r;
      try {
        r = boost::math::tools::toms748_solve(f, a, b, Real(la + tol), Real(lb + tol), stop, it);
      } catch (const std::exception& ex) {
        throw SolverError(std::string("in-plane oscillation: the end of slip on [") + short_str(a) + ", " +
                          short_str(b) + "]: " + ex.what());
      }
      if (it >= root_iterations_ && !stop(r.first, r.second))
        throw SolverError("in-plane oscillation: the end of slip on [" + short_str(a) + ", " + short_str(b) +
                          "] did not converge");
      return f(r.first) < 0 ? r.first : r.second;
    }
    const Real m = a + w / 2;
    Step sm;
    if (!radau(g, x0, y0, Real(m - x0), sm))
      throw SolverError("in-plane oscillation: the slip integrator failed between phases " + short_str(x0) + " and " +
                        short_str(m));
    if (auto r = slip_end(g, x0, y0, a, ya, m, sm.y, tol, step, budget)) return r;
    return slip_end(g, x0, y0, m, sm.y, b, yb, tol, step, budget);
  }

  // Stick from s0 at t0: the first φ in (t0, b] where |s|² − n² > tol, or none.
  std::optional<Real> stick_end(const Seg& g, const Vec& c, const Real& a, const Real& b, const Real& tol,
                                std::size_t& budget) const {
    using std::abs;
    using std::max;
    const Real w = b - a, m = a + w / 2;
    const auto G = [&](const Real& t) {
      const Vec d = D(g, t);
      const Real sx = c[0] + d[0], sy = c[1] + d[1], nn = n(g, t);
      return sx * sx + sy * sy - nn * nn;
    };
    // G' = 2 (s·D' − n n') over [a, b], s = c + D from the pieces' ends.
    const Iv q = hull(pv(g, a), pv(g, b));
    const Iv sx = add(Iv{c[0] + beta_ * a, c[0] + beta_ * b}, Iv{al_ * q.lo, al_ * q.hi});
    const Iv sy = affine(c[1], at_, q);
    const Iv nr = n_range(g, a, b);
    const Iv dg = add(add(mul(sx, dD_range(g, a, b, 0)), mul(sy, dD_range(g, a, b, 1))),
                      mul(Iv{-nr.hi, -nr.lo}, dn_range(g, a, b)));
    Real slope = 2 * max(abs(dg.lo), abs(dg.hi));
    if (in_phase_ && g.contact_segment != npos && on_contact(g)) {
      // n = γ + p and n' = p' here: G'/2 = β s_x + p' (c·a + β a_l φ + (|a|² − 1) p − γ), which
      // keeps a force that follows the disc's edge (|a| = 1, s ∥ a) at G' = 0.
      const Iv k = add(Iv{c[0] * al_ + c[1] * at_ - gamma_ + beta_ * al_ * a, c[0] * al_ + c[1] * at_ - gamma_ + beta_ * al_ * b},
                       mul(Iv{al_ * al_ + at_ * at_ - 1, al_ * al_ + at_ * at_ - 1}, q));
      const Iv dg2 = add(mul(Iv{beta_, beta_}, sx), mul(hull(dp(g, a), dp(g, b)), k));
      slope = std::min(slope, Real(2 * max(abs(dg2.lo), abs(dg2.hi))));
    }
    if (G(m) + slope * w / 2 <= tol) return std::nullopt;
    // G within twice its rounding across [a, b]: the force meets the circle at a vanishing angle
    // (or touches it), where this precision cannot tell touching from leaving; the stick goes on.
    if (G(m) <= tol && slope * w / 2 <= tol) return std::nullopt;
    if (w <= resolution_ * max(Real(1), abs(b))) {
      if (G(b) > tol) return b;
      return std::nullopt;
    }
    if (budget-- == 0)
      throw SolverError("in-plane oscillation: the tangential force stays at the friction limit's rounding on [" +
                        short_str(a) + ", " + short_str(b) + "]: the end of stick cannot be separated");
    if (auto r = stick_end(g, c, a, m, tol, budget)) return r;
    return stick_end(g, c, m, b, tol, budget);
  }

  struct Pass {
    const PlanarEngine& e;
    PlanarResult<Real>* rec;
    Real retained = 0, lateral = 0, normal = 0;
    std::size_t events = 0, steps = 0;

    void span(PlanarMode mode, const Real& a, const Real& b, const Vec& s0, std::size_t k) {
      if (!rec || !(b > a)) return;
      const Real len = b - a;
      switch (mode) {
        case PlanarMode::stick: rec->stick_fraction += len; break;
        case PlanarMode::slip: rec->slip_fraction += len; break;
        default: rec->flight_fraction += len;
      }
      rec->spans.push_back({mode, a, b, s0[0], s0[1], k});
    }

    Vec run(Vec s) {
      using std::hypot;
      const auto& segs = e.segs_;
      const Seg& last = segs.back();
      Vec d_prev = e.D(last, last.v);
      d_prev[0] -= e.beta_;  // D(0⁻) = D(1⁻) − (β, 0)
      project(s, e.n(last, last.v));
      PlanarMode mode = PlanarMode::stick;
      bool first = true;
      for (std::size_t k = 0; k < segs.size(); ++k) {
        const Seg& g = segs[k];
        const Real nu = e.n(g, g.u);
        if (g.p_jump) {
          const Vec d = e.D(g, g.u);
          if (d[0] != d_prev[0] || d[1] != d_prev[1]) {
            s[0] += d[0] - d_prev[0];
            s[1] += d[1] - d_prev[1];
            ++events;
          }
        }
        if (project(s, nu) && g.n_jump) ++events;
        const PlanarMode before = mode;
        mode = decide(g, g.u, s);
        if (!first && mode != before) ++events;
        first = false;
        s = segment(k, mode, s);
        d_prev = e.D(g, g.v);
      }
      if (rec) {
        rec->retained_area = retained;
        rec->lateral_area = lateral;
        rec->normal_area = normal;
        rec->events = events;
        rec->steps = steps;
      }
      return s;
    }

    // s onto the disc of radius nn; true where it moved.
    static bool project(Vec& s, const Real& nn) {
      using std::hypot;
      const Real r = hypot(s[0], s[1]);
      if (!(r > nn)) return false;
      if (nn == 0) {
        s = {Real(0), Real(0)};
      } else {
        s[0] = s[0] / r * nn;
        s[1] = s[1] / r * nn;
      }
      return true;
    }

    // The mode at φ with s admissible there: slip where s is on the circle to rounding and λ ≥ 0.
    PlanarMode decide(const Seg& g, const Real& phi, Vec& s) {
      using std::hypot;
      if (!e.on_contact(g)) {
        s = {Real(0), Real(0)};
        return PlanarMode::flight;
      }
      const Real nn = e.n(g, phi), r = hypot(s[0], s[1]);
      if (nn == 0) {
        // Touch-down (s = 0 = n): slip at once where the drive keeps up with the growing disc (its
        // rate λ = |D'| − n' not below its rounding, as on the circle below).
        s = {Real(0), Real(0)};
        const Vec d = e.dD(g, phi);
        const Real speed = hypot(d[0], d[1]);
        if (speed > 0 && speed - e.dn(g, phi) >= -e.lambda_tol(g)) {
          return PlanarMode::slip;
        }
        return PlanarMode::stick;
      }
      if (nn > 0 && r > 0 && r >= nn * (1 - 16 * std::numeric_limits<Real>::epsilon())) {
        const Vec u{s[0] / r, s[1] / r};
        if (e.lambda(g, phi, u) >= -e.lambda_tol(g)) {
          s = {nn * u[0], nn * u[1]};
          return PlanarMode::slip;
        }
      }
      return PlanarMode::stick;
    }

    Vec segment(std::size_t k, PlanarMode& mode, Vec s) {
      using std::abs;
      using std::hypot;
      using std::max;
      const Seg& g = e.segs_[k];
      if (rec) normal += e.n_area(g, g.u, g.v);
      const Real lam_tol = e.lambda_tol(g);
      // Where contact ends at v, slip is integrated to `cut`: ∫ n over [cut, v] ≤ n(cut)(v − cut) ≤ 2^-bits.
      Real cut = g.v;
      const Seg& next = e.segs_[k + 1 < e.segs_.size() ? k + 1 : 0];
      if (e.on_contact(g) && (e.n(g, g.v) == 0 || !e.on_contact(next))) cut = e.contact_cut(g, true);
      Real phi = g.u;
      for (std::size_t guard = 0;; ++guard) {
        if (guard > 100000)
          throw SolverError("in-plane oscillation: more than 100000 events on one segment at phase " + short_str(phi));
        if (mode == PlanarMode::flight) {
          span(mode, phi, g.v, s, k);
          return Vec{Real(0), Real(0)};
        }
        if (mode == PlanarMode::slip) {
          span(mode, phi, g.v, s, k);  // its end is corrected below where slip ends early
          const std::size_t at_span = rec ? rec->spans.size() : 0;
          Uv y = e.from_angle(s[0], s[1]);
          Real t = phi;
          if (s[0] == 0 && s[1] == 0) {
            // From touch-down, where the angle equation is singular (n = 0), slip starts along D' once
            // ∫ n over the start is above 2^-bits; s lags D' there by O(n), and the start adds below 2^-bits.
            t = e.contact_cut(g, false);
            const Vec d = e.dD(g, t);
            y = e.from_angle(d[0], d[1]);
          }
          Real h = max(Real((cut - phi) / 8), e.resolution_);
          std::optional<Real> end;
          for (std::size_t tries = 0; t < cut; ++tries) {
            if (tries == max_steps)
              throw SolverError("in-plane oscillation: slip from phase " + short_str(phi) + " needs more than " +
                                std::to_string(max_steps) + " integration steps (reached phase " + short_str(t) + ")");
            const Real hh = std::min(h, Real(cut - t));
            Step st;
            Real next_h;
            if (!e.controlled(g, t, y, hh, st, next_h)) {
              if (!(next_h > e.resolution_ * max(Real(1), abs(t))))
                throw SolverError("in-plane oscillation: the slip integrator's step underflows at phase " +
                                  short_str(t));
              h = next_h;
              continue;
            }
            const Real t1 = hh == cut - t ? cut : Real(t + hh);
            std::size_t budget = search_budget;
            end = e.slip_end(g, t, y, t, y, t1, st.y, lam_tol, hh, budget);
            if (end) {
              Step part;
              if (*end != t && !e.radau(g, t, y, Real(*end - t), part))
                throw SolverError("in-plane oscillation: the slip integrator failed between phases " + short_str(t) +
                                  " and " + short_str(*end));
              if (*end != t) {
                y = part.y;
                retained += part.ix;
                lateral += part.iy;
              }
              ++steps;
              break;
            }
            y = st.y;
            retained += st.ix;
            lateral += st.iy;
            ++steps;
            t = t1;
            h = next_h;
          }
          if (!end) {
            if (cut < g.v) return Vec{Real(0), Real(0)};  // n(v) ≈ 0: the rest is below 2^-bits
            const Real nv = e.n(g, g.v);
            const Vec u = unit(y);
            return Vec{nv * u[0], nv * u[1]};
          }
          if (rec && at_span > 0) rec->spans[at_span - 1].end = *end, rec->slip_fraction -= g.v - *end;
          const Real ne = e.n(g, *end);
          const Vec u = unit(y);
          s = {ne * u[0], ne * u[1]};
          phi = *end;
          mode = PlanarMode::stick;
          ++events;
          continue;
        }
        // stick: s = c + D
        const Vec d0 = e.D(g, phi);
        const Vec c{s[0] - d0[0], s[1] - d0[1]};
        Real tol;
        {
          const Iv q = hull(e.pv(g, phi), e.pv(g, g.v));
          const Real big = max(abs(c[0]) + abs(e.beta_) * max(abs(phi), abs(g.v)) + e.al_ * max(abs(q.lo), abs(q.hi)),
                               abs(c[1]) + e.at_ * max(abs(q.lo), abs(q.hi)));
          const Iv nr = e.n_range(g, phi, g.v);
          tol = 16 * std::numeric_limits<Real>::epsilon() * (2 * big * big + nr.hi * nr.hi);
        }
        std::size_t budget = search_budget;
        const auto end = e.stick_end(g, c, phi, g.v, tol, budget);
        const Real stop = end ? *end : g.v;
        span(mode, phi, stop, s, k);
        if (rec) {
          const Real len = stop - phi;
          retained += c[0] * len + e.beta_ * (stop - phi) * (stop + phi) / 2 + e.al_ * e.p_area(g, phi, stop);
          lateral += c[1] * len + e.at_ * e.p_area(g, phi, stop);
        }
        const Vec d = e.D(g, stop);
        s = {c[0] + d[0], c[1] + d[1]};
        if (!end) return s;
        project(s, e.n(g, stop));
        // on the circle (it was just outside): slip where its rate is not negative, else a touch
        const Real r = hypot(s[0], s[1]), ne = e.n(g, stop);
        if (r > 0 && ne > 0) s = {s[0] / r * ne, s[1] / r * ne};
        phi = stop;
        ++events;
        mode = decide(g, phi, s);
      }
    }
  };

  // Where n falls to 0 at v (at_end) or rises from 0 at u: the φ in [u, v] with ∫ n beyond it (before
  // it) at most n(φ)|v − φ| ≤ 2^-bits (n(φ)|φ − u|); n is monotone on the segment. Where n rises to v
  // (at_end: the contact ends by a jump of n, as a sawtooth's drop) or falls from u, n is not small
  // at that edge and nothing is cut.
  Real contact_cut(const Seg& g, bool at_end) const {
    using std::abs;
    using std::ldexp;
    if (at_end ? n(g, g.u) < n(g, g.v) : n(g, g.u) > n(g, g.v)) return at_end ? g.v : g.u;
    const Real limit = ldexp(Real(1), -bits_);
    const Real& edge = at_end ? g.v : g.u;
    const auto small = [&](const Real& phi) { return n(g, phi) * abs(edge - phi) <= limit; };
    Real lo = g.u, hi = g.v;  // at_end: small(hi), not small(lo); else small(lo), not small(hi)
    if (at_end ? small(lo) : small(hi)) return at_end ? lo : hi;
    for (int k = 0; k < 4 * bits_ && hi - lo > resolution_; ++k) {
      const Real m = lo + (hi - lo) / 2;
      (small(m) == at_end ? hi : lo) = m;
    }
    return at_end ? hi : lo;
  }

  const Waveform<Real>* w_;
  const Waveform<Real>& p_;
  Real gamma_, beta_, al_, at_, phase_;
  RadauTableau<Real> tableau_;
  Options opt_;
  std::optional<Contact<Real>> contact_;
  std::vector<Seg> segs_;
  std::uintmax_t root_iterations_ = 200;
  int bits_ = 0;
  bool in_phase_ = false;
  Real resolution_, step_tol_;
};

}  // namespace vibrofric::detail
