// In-plane and combined oscillation of a curved contact by the MDR row (model.md, "Curved
// contacts (MDR)" and "In-plane and combined oscillation"): every spring of the row is the flat
// punch's in-plane problem under the common drive D(φ) at the shifted mean indentation
// γ' = γ − σ(x) (the same β, a_l, a_t, P: each spring has the ratio G*/E* of the whole row), so
//
//     μ̄/μ0 = ∫ Φ(γ − σ(x)) dx / ∫ N(γ − σ(x)) dx,   mean_lateral = ∫ Λ dx / ∫ N dx,
//     Φ = ∫₀¹ s_x dφ,  Λ = ∫₀¹ s_y dφ,  N = ∫₀¹ n dφ  of the spring's periodic state.
//
// Partial slip appears by itself: the outer springs carry little normal force and slip while
// the inner ones stick.
//
// Φ and Λ are analytic in γ' while the spring's event structure (its spans' modes and segments)
// stays the same. The x-integral is cut at the contact boundaries (γ' = −w at w's piece ends, as
// in curved.hpp) and at every γ' where the structure changes: each spring evaluated reports its
// structure, and two neighbouring nodes of a quadrature piece with different structures bracket a
// change, located by bisection on the structure itself; the piece is then integrated again in
// parts. Each piece by curved.hpp's rules (Gauss–Kronrod, Gauss, tanh-sinh, with the square-root
// behaviour at its ends removed by t = a + (b − a) u²(3 − 2u)).
//
// The springs carry no rounding bound here (the in-plane solvers give none): the API evaluates
// at two precisions and prints the digits they agree on.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/inplane/inplane.hpp"
#include "vibrofric/core/inplane/planar.hpp"

namespace vibrofric {

// One spring's periodic state: its areas and its event structure (a span's mode and segment,
// mode·2^16 + segment, zero-length spans left out, neighbours alike merged).
template <class Real>
struct InPlaneSpring {
  Real retained_area = 0, lateral_area = 0, normal_area = 0;
  std::vector<std::size_t> structure;
};

template <class Real>
struct InPlaneCurvedResult {
  Real mu;                  // ∫Φ dx / ∫N dx
  Real mean_lateral;        // ∫Λ dx / ∫N dx
  Real friction_integral;   // ∫₀^X Φ dx over the half-row (profile units)
  Real lateral_integral;    // ∫₀^X Λ dx
  Real normal_integral;     // ∫₀^X N dx
  Real contact_radius;      // X: σ(X) = γ + max w
  Real quadrature_error;    // the three integrals' estimates, summed (absolute)
  std::vector<Real> structure_breaks;  // γ' where the springs' event structure changes, ascending
  std::size_t segments = 0;            // quadrature pieces of the last pass
  std::size_t springs = 0;             // in-plane solves
};

namespace detail {

template <class Span>
std::vector<std::size_t> span_structure(const std::vector<Span>& spans) {
  std::vector<std::size_t> out;
  for (const auto& s : spans) {
    if (!(s.end > s.begin)) continue;
    const std::size_t key = (static_cast<std::size_t>(s.mode) << 16) + s.segment;
    if (out.empty() || out.back() != key) out.push_back(key);
  }
  return out;
}

}  // namespace detail

// One spring at γ' under the drive: the longitudinal stop operator where a_t = 0, else the
// planar sweeping process. No contact (γ' + max w ≤ 0): zeros.
template <class Real>
InPlaneSpring<Real> inplane_spring(const Waveform<Real>& w, const Real& gamma, const Waveform<Real>& in_plane,
                                   const Real& beta, const PlanarDrive<Real>& drive, const Options& opt = {}) {
  InPlaneSpring<Real> v;
  if (!(gamma + w.maximum() > 0)) return v;
  if (drive.transverse == 0) {
    const InPlaneSolver<Real> solver(&w, gamma, in_plane, beta, InPlaneDrive<Real>{drive.longitudinal, drive.phase}, opt);
    const InPlaneResult<Real> r = solver.solve();
    v.retained_area = r.retained_area;
    v.normal_area = r.normal_area;
    v.structure = detail::span_structure(r.spans);
  } else {
    const PlanarSolver<Real> solver(&w, gamma, in_plane, beta, drive, opt);
    const PlanarResult<Real> r = solver.solve();
    v.retained_area = r.retained_area;
    v.lateral_area = r.lateral_area;
    v.normal_area = r.normal_area;
    v.structure = detail::span_structure(r.spans);
  }
  return v;
}

// μ̄/μ0 and the mean lateral force of the curved contact, each integral to `tol` relative to
// ∫N dx. spring(γ') gives one spring (inplane_spring, or a test's own). SolverError where a piece
// does not converge or the structure keeps splitting (more than 64 passes).
template <class Real>
InPlaneCurvedResult<Real> solve_inplane_curved(const Waveform<Real>& w, const Profile<Real>& profile, const Real& gamma,
                                               const std::function<InPlaneSpring<Real>(const Real&)>& spring,
                                               const Real& tol, const Options& opt = {}) {
  using std::abs;
  using std::log10;
  using std::pow;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real sigma_max = gamma + w.maximum();
  if (!(sigma_max > 0)) throw DomainError("gamma = " + detail::short_str(gamma) + ": no contact");
  if (sigma_max > profile.sigma_limit())
    throw DomainError("gamma = " + detail::short_str(gamma) + " for profile " + profile.name() +
                      ": the contact reaches beyond its last sample");
  InPlaneCurvedResult<Real> r;
  r.contact_radius = profile.x_at_sigma(sigma_max);

  std::map<Real, InPlaneSpring<Real>> memo;  // by t
  const auto at_t = [&](const Real& t) -> const InPlaneSpring<Real>& {
    auto it = memo.find(t);
    if (it != memo.end()) return it->second;
    ++r.springs;
    return memo.emplace(t, spring(Real(gamma - profile.sigma_at_t(t)))).first->second;
  };

  // The contact boundaries: γ' = −w at w's piece ends (between −max w and γ), the profile's kinks.
  const Real t0 = profile.t_at_sigma(Real(0)), t1 = profile.t_at_sigma(sigma_max);
  std::vector<Real> ts{t0, t1};
  for (std::size_t i = 0; i < w.piece_count(); ++i)
    for (const Real& g : {Real(-w.begin_value(i)), Real(-w.end_value(i))})
      if (g > -w.maximum() && g < gamma) ts.push_back(profile.t_at_sigma(Real(gamma - g)));
  for (const Real& t : profile.t_breaks())
    if (t > t0 && t < t1) ts.push_back(t);

  // A structure change is located to δ with δ^1.5 below tol: a sliver of width δ on the wrong
  // branch moves a piece's Gauss value by about δ^1.5 (its nodes cluster at the ends as √δ).
  const Real width = t1 - t0;
  const Real locate = std::max(Real(width * pow(tol, Real(2) / 3)), Real(8 * eps * (abs(t1) + abs(t0))));

  // The centre's flat part (wear flat): the central spring over its length.
  const InPlaneSpring<Real> center = spring(gamma);
  ++r.springs;
  for (int pass = 0;; ++pass) {
    if (pass == 64) throw SolverError("the springs' event structure kept splitting the contact (64 passes)");
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    const std::vector<Real> ps = detail::graded_pieces(ts);
    Real F = profile.flat_length() * center.retained_area, L = profile.flat_length() * center.lateral_area,
         N = profile.flat_length() * center.normal_area, err = 0;
    // The accuracy asked of a piece is relative to ∫N dx, estimated by the midpoint rule first.
    Real scale = N;
    for (std::size_t k = 0; k + 1 < ps.size(); ++k)
      scale += (ps[k + 1] - ps[k]) * at_t(Real((ps[k] + ps[k + 1]) / 2)).normal_area * profile.dx_dt(Real((ps[k] + ps[k + 1]) / 2));
    std::vector<Real> found;
    r.segments = 0;
    for (std::size_t k = 0; k + 1 < ps.size(); ++k) {
      const Real &a = ps[k], &b = ps[k + 1];
      if (!(b > a)) continue;
      ++r.segments;
      // The first rule's nodes (those integrate_piece takes first, as it maps them) probe the
      // piece's structure before it is integrated: a change found splits it instead.
      {
        const double digits = -static_cast<double>(log10(tol));
        const std::size_t n = std::max<std::size_t>(8, static_cast<std::size_t>(std::ceil(digits / 0.75)));
        const Real width = b - a;
        for (const Real& u : detail::gauss_kronrod<Real>(n).nodes) {
          const Real t = u < Real(1) / 2 ? Real(a + width * u * u * (3 - 2 * u)) : Real(b - width * (1 - u) * (1 - u) * (1 + 2 * u));
          if (t > a && t < b) at_t(t);
        }
      }
      // Neighbouring nodes inside (a, b) with different structures bracket a change (collected
      // first: the bisection adds nodes to memo).
      struct Bracket {
        Real x, y;
        std::vector<std::size_t> left;
      };
      std::vector<Bracket> brackets;
      const auto hi = memo.lower_bound(b);
      for (auto it = memo.upper_bound(a); it != hi && std::next(it) != hi; ++it) {
        const auto next = std::next(it);
        if (it->second.structure == next->second.structure) continue;
        // A change next to a known break is that break, located to `locate` before.
        const auto near = std::lower_bound(ts.begin(), ts.end(), Real(it->first - 2 * locate));
        if (near != ts.end() && *near <= next->first + 2 * locate) continue;
        brackets.push_back({it->first, next->first, it->second.structure});
      }
      for (Bracket& br : brackets) {
        while (br.y - br.x > locate) {
          const Real m = (br.x + br.y) / 2;
          if (!(m > br.x) || !(m < br.y)) break;
          if (at_t(m).structure == br.left) br.x = m;
          else br.y = m;
        }
        found.push_back((br.x + br.y) / 2);
      }
      if (!brackets.empty()) continue;  // integrated in parts in the next pass
      Real* sums[3] = {&F, &L, &N};
      for (int which = 0; which < 3; ++which) {
        const auto h = [&](const Real& t) -> Real {
          const InPlaneSpring<Real>& v = at_t(t);
          const Real area = which == 0 ? v.retained_area : (which == 1 ? v.lateral_area : v.normal_area);
          return area * profile.dx_dt(t);
        };
        Real value = 0, e = 0, l1 = 0;
        detail::integrate_piece(h, a, b, tol, Real(tol * scale), opt, which == 0 ? "Phi" : (which == 1 ? "Lambda" : "N"),
                                value, e, l1);
        *sums[which] += value;
        err += e;
      }
    }
    if (found.empty()) {
      r.friction_integral = F;
      r.lateral_integral = L;
      r.normal_integral = N;
      r.quadrature_error = err;
      r.mu = F / N;
      r.mean_lateral = L / N;
      break;
    }
    for (const Real& t : found) {
      r.structure_breaks.push_back(Real(gamma - profile.sigma_at_t(t)));
      ts.push_back(t);
    }
  }
  std::sort(r.structure_breaks.begin(), r.structure_breaks.end());
  return r;
}

}  // namespace vibrofric
