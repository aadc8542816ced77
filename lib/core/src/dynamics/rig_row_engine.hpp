// The curved contact's rig (core/dynamics/rig_row.hpp, model.md "Rig dynamics", "On a curved
// contact"): the periodic state of the one-period map (rig_row_period.hpp) by shooting from two
// starts, the row carried where it stays in contact, and the map's largest multiplier.
// Private to the core; instantiated for double in rig_row_double.cpp.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "vibrofric/core/dynamics/rig_row.hpp"
#include "vibrofric/core/errors.hpp"
#include "rig_row_period.hpp"

namespace vibrofric {
namespace detail {

template <class Real>
class RowRigEngine : public RowRigPeriod<Real> {
  using Base = RowRigPeriod<Real>;
  using typename Base::Mode;
  using typename Base::Row;
  using typename Base::Spring;
  using typename Base::State;
  using Base::beta_;
  using Base::body_size;
  using Base::carried_;
  using Base::gamma_;
  using Base::normal_area_;
  using Base::omega2_;
  using Base::p_;
  using Base::period;
  using Base::row_;
  using Base::row_change;
  using Base::row_of_forces;
  using Base::section_;
  using Base::section_force;
  using Base::shift;
  using Base::wave_;

 public:
  using Base::Base;

  // The result, and where `phases` is given the periodic state at each (samples, in its order).
  RowRigResult<Real> solve(const std::vector<Real>* phases = nullptr,
                           std::vector<RowRigSample<Real>>* samples = nullptr) const {
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    // Two starts: moving with the drive (the quasi-static limit's body) and at rest.
    Real last1 = 0, last2 = 0;
    std::size_t steps1 = 0, steps2 = 0;
    std::array<std::array<Real, 2>, 2> J1{}, J2{};
    Row ra, rb;  // the carried springs' states
    State a, b;
    if (carried_) {
      a = settle(State{Real(0), Real(0)}, ra, steps1, last1);
      b = settle(State{Real(0), Real(-beta_)}, rb, steps2, last2);
    } else {
      a = shoot(State{Real(0), Real(0)}, steps1, last1, J1);
      b = shoot(State{Real(0), Real(-beta_)}, steps2, last2, J2);
      jacobian(a, J1);
    }
    RowRigResult<Real> res, other;
    period(a, &res, carried_ ? &ra : nullptr, nullptr, phases, samples);
    period(b, &other, carried_ ? &rb : nullptr);
    res.normal_area = other.normal_area = normal_area_;
    res.mu = res.retained_area / normal_area_;
    other.mu = other.retained_area / normal_area_;
    const Real diff = abs(Real(res.mu - other.mu));
    if (diff > sqrt(eps) * std::max(Real(1), abs(res.mu)))
      throw SolverError("rig dynamics on a curved contact: two periodic states from two starts (mu = " +
                        short_str(res.mu) + " moving with the drive, " + short_str(other.mu) + " from rest)");
    res.state_y = a[0];
    res.state_v = a[1];
    res.section = section_;
    res.newton_steps = steps1;
    res.springs = row_.size();
    res.floquet = carried_ ? carried_multiplier(a, ra) : largest(J1);
    res.relative_error = (diff + abs(last1) + 16 * eps * abs(res.mu)) / std::max(abs(res.mu), eps);
    return res;
  }


 private:
  // Newton on P(u) − u = 0 with a finite-difference Jacobian, after a few periods of transient;
  // the transient alone (up to 4000 periods while it contracts) where Newton does not converge.
  State shoot(State u, std::size_t& steps, Real& last, std::array<std::array<Real, 2>, 2>& J) const {
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real body = sqrt(Real(omega2_ * (p_.kappa + 1)));  // Y' in units of the body's rate
    const auto size = [&](const State& d) { return abs(d[0]) + abs(d[1]) / body; };
    const auto scale = [&](const State& x) { return 1 + abs(x[0]) + abs(x[1]) / body; };
    for (int k = 0; k < 4; ++k) u = period(u);
    for (int attempt = 0; attempt < 2; ++attempt) {
      State Pu = period(u);
      State res{Pu[0] - u[0], Pu[1] - u[1]};
      for (int it = 0; it < 40; ++it) {
        if (size(res) <= 64 * eps * scale(u)) {
          last = size(res);
          return u;
        }
        jacobian(u, J);
        ++steps;
        const Real a11 = J[0][0] - 1, a12 = J[0][1], a21 = J[1][0], a22 = J[1][1] - 1;
        const Real det = a11 * a22 - a12 * a21;
        if (det == 0) break;
        State d{(-res[0] * a22 + res[1] * a12) / det, (-res[1] * a11 + res[0] * a21) / det};
        bool better = false;
        for (int halve = 0; halve < 12; ++halve) {
          const State un{u[0] + d[0], u[1] + d[1]};
          const State Pn = period(un);
          const State rn{Pn[0] - un[0], Pn[1] - un[1]};
          if (size(rn) < size(res)) {
            u = un;
            Pu = Pn;
            res = rn;
            better = true;
            break;
          }
          d[0] /= 2;
          d[1] /= 2;
        }
        if (!better) {
          // converged as far as the map's kinks and rounding allow?
          if (size(res) <= sqrt(eps) * scale(u)) {
            last = size(res);
            return u;
          }
          break;
        }
      }
      // the transient from here while it contracts, then Newton again
      Real prev = size(res);
      for (int k = 0; k < 4000; ++k) {
        u = Pu;
        Pu = period(u);
        res = {Pu[0] - u[0], Pu[1] - u[1]};
        const Real now = size(res);
        if (now <= 64 * eps * scale(u)) {
          last = now;
          return u;
        }
        if (k > 16 && now > prev * Real(0.999)) break;
        prev = now;
      }
    }
    throw SolverError("rig dynamics on a curved contact: no periodic state found (Newton and 4000 periods of "
                      "transient did not converge)");
  }

  // The one-period map's Jacobian at u by forward differences (its multipliers: stability), the
  // carried springs' forces (if any) held at R's: a change of Y moves their contact points along.
  void jacobian(const State& u, std::array<std::array<Real, 2>, 2>& J, const Row* R = nullptr) const {
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real body = sqrt(Real(omega2_ * (p_.kappa + 1)));
    const State Pu = period(u, nullptr, R);
    const Real h[2] = {sqrt(eps) * (1 + abs(u[0])), sqrt(eps) * (body + abs(u[1]))};
    for (int c = 0; c < 2; ++c) {
      State uh = u;
      uh[c] += h[c];
      const Row shifted = R && c == 0 ? shift(*R, h[0]) : Row{};
      const State Ph = period(uh, nullptr, R && c == 0 ? &shifted : R);
      J[0][c] = (Ph[0] - Pu[0]) / h[c];
      J[1][c] = (Ph[1] - Pu[1]) / h[c];
    }
  }

  // The periodic state where springs stay in contact through the section (γ − σ + min w > 0):
  // Newton on (Y, Y') with the row's forces held (the 2×2 Jacobian by forward differences; the
  // stick springs' contact points move with Y, so that the row's slow shift with the body, which
  // only the system spring restores, is Newton's), the row then carried on to the states the
  // period ends in, moved by Newton's step. Every spring in contact slips once a period
  // (the body advances β) and so forgets its start: the row's states follow the body's. Converged
  // where one period returns the body to 64 ε of its scale and every spring's force to 64 ε of the
  // row's largest bound; else, stalled (the map's kinks, rounding, or a slow mode of the row that
  // Newton on the body does not reach), the best state within √ε; else Newton–GMRES on the full map.
  State settle(State u, Row& R, std::size_t& steps, Real& last) const {
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real bound = 1 + abs(gamma_) + abs(wave_.maximum());
    const auto scale = [&](const State& x) { return 1 + body_size(x); };
    R.assign(row_.size(), Spring{});
    const auto advance = [&](const State& x, Row& rows) {
      Row next;
      const State Px = period(x, nullptr, &rows, &next);
      rows = std::move(next);
      return Px;
    };
    for (int k = 0; k < 4; ++k) u = advance(u, R);
    State best_u = u;
    Row best_R = R;
    Real best = std::numeric_limits<Real>::infinity();
    int stalled = 0;
    for (int it = 0; it < 200; ++it) {
      Row R1;
      const State Pu = period(u, nullptr, &R, &R1);
      const State res{Pu[0] - u[0], Pu[1] - u[1]};
      const Real now = std::max(body_size(res) / scale(u), row_change(u[0], R, Pu[0], R1) / bound);
      if (now < best) {
        if (!(now > best / 2)) stalled = 0;
        best = now;
        best_u = u;
        best_R = R;
      }
      if (now <= 64 * eps) {
        last = now * scale(u);
        return u;
      }
      if (++stalled > 12) break;
      std::array<std::array<Real, 2>, 2> J;
      jacobian(u, J, &R);
      ++steps;
      const Real a11 = J[0][0] - 1, a12 = J[0][1], a21 = J[1][0], a22 = J[1][1] - 1;
      const Real det = a11 * a22 - a12 * a21;
      const State d = det != 0 ? State{(-res[0] * a22 + res[1] * a12) / det, (-res[1] * a11 + res[0] * a21) / det}
                               : State{res[0], res[1]};
      u = {u[0] + d[0], u[1] + d[1]};
      R = shift(std::move(R1), d[0]);
    }
    if (best <= sqrt(eps)) {
      R = std::move(best_R);
      last = best * scale(best_u);
      return best_u;
    }
    R = std::move(best_R);
    return newton_krylov(best_u, R, steps, last);
  }

  // The full map's fixed point by Newton–GMRES, where Newton on the body leaves a slow mode of the
  // row (a heavy body on a contact that stays closed: multipliers near 1). The state is z = (Y, Y',
  // every spring's force at the section), scaled as settle measures it; a force maps back to a
  // stick spring at it (on its bound the period's start rules slip, as the sweeping process does),
  // the map to the forces its period ends with. Each step solves (J − I) d = z − P(z) by GMRES on
  // J's products by forward differences (a period each; the row forgets, so few directions
  // matter), to 1e-4 of the residual or 40 products, caps d at 64 residuals and halves it until
  // the residual falls by a tenth; where none does (the map is near a translation where the row
  // sticks all period), 32 plain periods (at most eight times) and Newton again.
  // Accepted at 64 ε, or within √ε where Newton can bring it no lower.
  State newton_krylov(const State& u0, Row& R, std::size_t& steps, Real& last) const {
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real bound = 1 + abs(gamma_) + abs(wave_.maximum());
    const Real body = sqrt(Real(omega2_ * (p_.kappa + 1)));
    const Real sc = 1 + body_size(u0);
    const std::size_t m = row_.size(), size = m + 2;
    using Vec = std::vector<Real>;
    const auto to_z = [&](const State& u, const Row& rows) {
      Vec z(size);
      z[0] = u[0] / sc;
      z[1] = u[1] / (body * sc);
      for (std::size_t j = 0; j < m; ++j) z[j + 2] = section_force(u[0], rows[j], j) / bound;
      return z;
    };
    const auto rows_of = [&](const Vec& z) {
      Vec forces(m);
      for (std::size_t j = 0; j < m; ++j) forces[j] = z[j + 2] * bound;
      return row_of_forces(z[0] * sc, forces);
    };
    const auto map = [&](const Vec& z) {
      const Row rows = rows_of(z);
      Row next;
      const State Pu = period(State{z[0] * sc, z[1] * body * sc}, nullptr, &rows, &next);
      return to_z(Pu, next);
    };
    const auto largest = [](const Vec& v) {
      Real n = 0;
      for (const Real& c : v) n = std::max(n, Real(abs(c)));
      return n;
    };
    const auto dot = [](const Vec& a, const Vec& b) {
      Real t = 0;
      for (std::size_t i = 0; i < a.size(); ++i) t += a[i] * b[i];
      return t;
    };
    Vec z = to_z(u0, R), g = map(z), r(size);
    for (std::size_t i = 0; i < size; ++i) r[i] = g[i] - z[i];
    Real now = largest(r);
    int plain_runs = 0;
    for (int it = 0; it < 40 && now > 64 * eps; ++it) {
      ++steps;
      // GMRES on A d = r, A v = v − J v (so that d is the step: z + d)
      const Real h = Real(1e-7);
      const Real beta = sqrt(dot(r, r));
      std::vector<Vec> V{Vec(size)};
      for (std::size_t i = 0; i < size; ++i) V[0][i] = r[i] / beta;
      std::vector<Vec> H;  // H[k]: column k, k + 2 entries
      std::vector<Real> cs, sn, e{beta};
      std::size_t k = 0;
      for (; k < 40; ++k) {
        Vec zh(size);
        for (std::size_t i = 0; i < size; ++i) zh[i] = z[i] + h * V[k][i];
        const Vec gh = map(zh);
        Vec w(size);
        for (std::size_t i = 0; i < size; ++i) w[i] = V[k][i] - (gh[i] - g[i]) / h;
        Vec col(k + 2, Real(0));
        for (std::size_t q = 0; q <= k; ++q) {
          col[q] = dot(w, V[q]);
          for (std::size_t i = 0; i < size; ++i) w[i] -= col[q] * V[q][i];
        }
        col[k + 1] = sqrt(dot(w, w));
        for (std::size_t q = 0; q < k; ++q) {  // the earlier rotations
          const Real t = cs[q] * col[q] + sn[q] * col[q + 1];
          col[q + 1] = -sn[q] * col[q] + cs[q] * col[q + 1];
          col[q] = t;
        }
        const Real rho = sqrt(col[k] * col[k] + col[k + 1] * col[k + 1]);
        cs.push_back(rho > 0 ? col[k] / rho : Real(1));
        sn.push_back(rho > 0 ? col[k + 1] / rho : Real(0));
        const Real next_norm = col[k + 1];
        col[k] = rho;
        col[k + 1] = 0;
        e.push_back(-sn[k] * e[k]);
        e[k] = cs[k] * e[k];
        H.push_back(col);
        if (!(next_norm > 0) || abs(e[k + 1]) <= Real(1e-4) * beta) {
          ++k;
          break;
        }
        Vec v(size);
        for (std::size_t i = 0; i < size; ++i) v[i] = w[i] / next_norm;
        V.push_back(std::move(v));
      }
      // back substitution for the k coefficients, the step d = V y
      std::vector<Real> y(k, Real(0));
      for (std::size_t a = k; a-- > 0;) {
        Real t = e[a];
        for (std::size_t b = a + 1; b < k; ++b) t -= H[b][a] * y[b];
        y[a] = H[a][a] != 0 ? t / H[a][a] : Real(0);
      }
      Vec d(size, Real(0));
      for (std::size_t a = 0; a < k; ++a)
        for (std::size_t i = 0; i < size; ++i) d[i] += y[a] * V[a][i];
      // a step far beyond the residual is the linear model's, not the map's (its kinks): capped at
      // 64 residuals (a slow mode of multiplier 0.98 needs 50)
      if (const Real dmax = largest(d); dmax > 64 * now)
        for (Real& c : d) c *= 64 * now / dmax;
      bool better = false;
      for (int halve = 0; halve < 10 && !better; ++halve) {
        Vec zn(size);
        for (std::size_t i = 0; i < size; ++i) zn[i] = z[i] + d[i];
        const Vec gn = map(zn);
        Vec rn(size);
        for (std::size_t i = 0; i < size; ++i) rn[i] = gn[i] - zn[i];
        const Real nn = largest(rn);
        if (nn < Real(0.9) * now) {
          z = std::move(zn);
          g = gn;
          r = std::move(rn);
          now = nn;
          better = true;
        }
        for (Real& c : d) c /= 2;
      }
      if (!better) {
        // no step of the linear model lowers it: 32 periods of the map itself, then Newton again
        if (++plain_runs > 8) break;
        for (int q = 0; q < 32; ++q) {
          z = g;
          g = map(z);
        }
        for (std::size_t i = 0; i < size; ++i) r[i] = g[i] - z[i];
        now = largest(r);
      }
    }
    if (!(now <= sqrt(eps)))
      throw SolverError("rig dynamics on a curved contact: no periodic state found with the row in contact through "
                        "the section (Newton with the row carried, then Newton-GMRES on the full map: residual " +
                        short_str(now) + " of the state's scale)");
    R = rows_of(z);
    last = now * sc;
    return State{z[0] * sc, z[1] * body * sc};
  }

  // The largest multiplier where the row is carried: of the full map's linearisation, in the
  // state (Y, Y', each spring's force at the section; a slipping spring's force is its bound and
  // stays), by forward differences of step √ε. Power iteration for 40 periods leaves the dominant
  // pair (or real multiplier); two more fit v₂ = a v₁ + b v₀ (least squares), whose roots of
  // λ² = aλ + b are it, a complex pair's modulus too. 0 where the iterate falls below what the
  // differences resolve.
  double carried_multiplier(const State& u, const Row& R) const {
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real body = sqrt(Real(omega2_ * (p_.kappa + 1)));
    const std::size_t m = row_.size();
    Row next;
    const State P0 = period(u, nullptr, &R, &next);
    std::vector<Real> z1(m);
    for (std::size_t j = 0; j < m; ++j) z1[j] = section_force(P0[0], next[j], j);
    const Real h = sqrt(eps) * (1 + body_size(u));
    // the linearised map applied to v (of largest component 1)
    const auto apply = [&](const std::vector<Real>& v) {
      const State x{u[0] + h * v[0], u[1] + h * v[1] * body};
      Row rx = R;
      for (std::size_t j = 0; j < m; ++j)
        if (rx[j].mode == Mode::stick) rx[j].xc -= h * (v[j + 2] - v[0]);  // s = Y − (X_c − βφ)
      Row out;
      const State Px = period(x, nullptr, &rx, &out);
      std::vector<Real> w(m + 2, Real(0));
      w[0] = (Px[0] - P0[0]) / h;
      w[1] = (Px[1] - P0[1]) / h / body;
      for (std::size_t j = 0; j < m; ++j)
        if (out[j].mode == Mode::stick && next[j].mode == Mode::stick) w[j + 2] = (section_force(Px[0], out[j], j) - z1[j]) / h;
      return w;
    };
    const auto norm = [](const std::vector<Real>& v) {
      Real n = 0;
      for (const Real& c : v) n = std::max(n, Real(abs(c)));
      return n;
    };
    const Real floor = 1e3 * sqrt(eps);
    std::vector<Real> v(m + 2, Real(0));
    v[0] = 1;
    for (int k = 0; k < 40; ++k) {
      v = apply(v);
      const Real size = norm(v);
      if (!(size > floor)) return 0;
      for (Real& c : v) c /= size;
    }
    std::vector<Real> v1 = apply(v);
    const Real s1 = norm(v1);
    if (!(s1 > floor)) return 0;
    std::vector<Real> v2 = apply([&] {
      std::vector<Real> t = v1;
      for (Real& c : t) c /= s1;
      return t;
    }());
    for (Real& c : v2) c *= s1;
    Real g00 = 0, g01 = 0, g11 = 0, r0 = 0, r1 = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      g00 += v1[i] * v1[i];
      g01 += v1[i] * v[i];
      g11 += v[i] * v[i];
      r0 += v1[i] * v2[i];
      r1 += v[i] * v2[i];
    }
    const Real det = g00 * g11 - g01 * g01;
    if (!(det > 1e-6 * g00 * g11)) return static_cast<double>(s1);  // one real multiplier dominates alone
    const Real a = (r0 * g11 - r1 * g01) / det, b = (g00 * r1 - g01 * r0) / det;
    const Real disc = a * a / 4 + b;
    if (disc < 0) return static_cast<double>(sqrt(Real(-b)));
    return static_cast<double>(std::max(abs(Real(a / 2 + sqrt(disc))), abs(Real(a / 2 - sqrt(disc)))));
  }

  static double largest(const std::array<std::array<Real, 2>, 2>& J) {
    const double a = static_cast<double>(J[0][0]), b = static_cast<double>(J[0][1]), c = static_cast<double>(J[1][0]),
                 d = static_cast<double>(J[1][1]);
    const double tr = a + d, det = a * d - b * c, disc = tr * tr / 4 - det;
    if (disc >= 0) return std::max(std::abs(tr / 2 + std::sqrt(disc)), std::abs(tr / 2 - std::sqrt(disc)));
    return std::sqrt(std::abs(det));
  }

};

}  // namespace detail

template <class Real>
std::vector<RowSpring<Real>> mdr_row(const Profile<Real>& profile, const Real& sigma_max, std::size_t n) {
  if (n == 0) throw DomainError("the MDR row needs at least one spring");
  const Real x_max = profile.x_at_sigma(sigma_max);
  std::vector<RowSpring<Real>> row;
  if (profile.flat_length() > 0) row.push_back({Real(0), Real(profile.flat_length() / x_max)});
  const Real t0 = profile.t_at_sigma(Real(0)), t1 = profile.t_at_sigma(sigma_max);
  std::vector<Real> ends{t0};
  for (const Real& t : profile.t_breaks())
    if (t > t0 && t < t1) ends.push_back(t);
  ends.push_back(t1);
  for (std::size_t k = 0; k + 1 < ends.size(); ++k) {
    const Real len = ends[k + 1] - ends[k];
    const std::size_t m = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::llround(static_cast<double>(len / (t1 - t0)) * static_cast<double>(n))));
    const Real h = len / static_cast<unsigned>(m);
    for (std::size_t i = 0; i < m; ++i) {
      const Real t = ends[k] + h * (Real(static_cast<unsigned>(i)) + Real(0.5));
      row.push_back({profile.sigma_at_t(t), Real(profile.dx_dt(t) * h / x_max)});
    }
  }
  return row;
}

template <class Real>
RowRigResult<Real> solve_rig_row(const Waveform<Real>& w, const Real& beta, const Real& gamma,
                                 const RigParameters<Real>& p, const std::vector<RowSpring<Real>>& row,
                                 const Options& opt) {
  detail::check_beta(w, beta);
  detail::check_contact(w, gamma);
  // Its errors name no point: the caller names it as its user typed it (the API does).
  const detail::RowRigEngine<Real> engine(w, beta, gamma, p, row, opt);
  return engine.solve();
}

template <class Real>
RowRigResult<Real> solve_rig_row(const Waveform<Real>& w, const Real& beta, const Real& gamma,
                                 const RigParameters<Real>& p, const std::vector<RowSpring<Real>>& row,
                                 const Options& opt, const std::vector<Real>& phases,
                                 std::vector<RowRigSample<Real>>& samples) {
  detail::check_beta(w, beta);
  detail::check_contact(w, gamma);
  for (const Real& phi : phases)
    if (!(phi >= 0 && phi <= 1)) throw DomainError("rig dynamics on a curved contact: a phase outside [0, 1]");
  const detail::RowRigEngine<Real> engine(w, beta, gamma, p, row, opt);
  return engine.solve(&phases, &samples);
}

}  // namespace vibrofric
