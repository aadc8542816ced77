// A curved contact over one period (model.md, "Curved contacts (MDR)"; Fig. 2 of the paper for
// the flat punch): the normal and tangential forces summed over the MDR row at a phase φ,
//
//   N(φ) = ∫₀^X n(φ; γ − σ(x)) dx = c·x_c − ∫₀^{x_c} σ dx,   c = γ + w(φ), σ(x_c) = c,
//   S(φ) = ∫₀^X s(φ; γ − σ(x)) dx,
//
// and the row's stick integral ∫₀^X t_stick(γ − σ(x)) dx, t_stick(γ') the share of the period
// a spring sticks. Half-row, profile units, flat part included, as CurvedResult: ∫₀¹ N dφ and
// ∫₀¹ S dφ are its normal_integral and friction_integral.
//
// S(φ) as a function of γ' (one spring per γ', solver.hpp's tangential_force) is not analytic
// where the spring's state at φ changes. Between two of solve_curved's γ' breakpoints the
// event structure is fixed, and the state at φ changes only where an event passes φ: the
// contact boundary (γ' = −w(φ)), or the end of a stick anchored at first contact, whose onset
// moves with γ' (the root of the monotone g + w(φ) − β(φ − onset(g)), as in gamma_breakpoints;
// a stick anchored on n starts and ends at fixed phases). Those are the breakpoints of S(φ)'s
// x-integral. Between them one state holds at φ, read from a spring near one end of the piece,
// and s is in closed form in γ': n = γ' + w(φ) in slip; level + β(φ − begin) in stick, the
// level 0 and the begin the onset for an anchored stick, the level n(begin) = γ' + w(begin) for
// one on n. So the quadrature nodes need no springs; one near the other end checks the form.
// Springs are kept from phase to phase: most pieces recur.
#pragma once
#include <algorithm>
#include <map>
#include <vector>

#include "vibrofric/core/curved/curved.hpp"

namespace vibrofric {

template <class Real>
struct CurvedTraceRow {
  Real phi, n, s;  // N(φ), S(φ) over the half-row
  Real error;      // quadrature estimate of S (absolute; N is in closed form)
};

namespace detail {

// The stick phase of r holding φ ∈ [0, 1) (or φ + 1, a stick wrapping the period's end), and that
// phase as the stick counts it; nullptr where the spring slips or flies at φ.
template <class Real>
const StickPhase<Real>* stick_at(const Result<Real>& r, const Real& phi, Real& at) {
  for (const auto& st : r.stick_phases)
    for (int k = 0; k < 2; ++k) {
      const Real x = phi + k;
      if (x >= st.begin && x < st.end) {  // as tangential_force
        at = x;
        return &st;
      }
    }
  return nullptr;
}

// The shared set-up of a row's trace and stick integral, after solve_curved's preconditions:
// springs (kept), the central one, and the γ' breakpoints of solve_curved.
template <class Real>
class RowStructure {
 public:
  RowStructure(const Waveform<Real>& w, const Profile<Real>& profile, const Real& beta, const Real& gamma, const Options& opt)
      : where(check_curved(w, profile, beta, gamma)), profile_(profile), gamma_(gamma), row_(w, beta, opt) {
    center_ = row_.result(gamma);
    nodes_.push_back(Real(-w.maximum()));
    for (const Real& g : gamma_breakpoints(row_, Real(-w.maximum()), gamma)) nodes_.push_back(g);
    nodes_.push_back(gamma);
  }
  SpringRow<Real>& row() { return row_; }
  const Result<Real>& center() const { return center_; }
  // −max w, the γ' breakpoints, γ: ascending.
  const std::vector<Real>& nodes() const { return nodes_; }
  const Result<Real>& middle(std::size_t k) { return spring(Real((nodes_[k] + nodes_[k + 1]) / 2)); }
  // The spring at γ', kept: the pieces of a trace lie between the same breakpoints at most
  // phases, so their springs recur from phase to phase.
  const Result<Real>& spring(const Real& g) {
    auto it = springs_.find(g);
    if (it == springs_.end()) it = springs_.emplace(g, row_.result(g)).first;
    return it->second;
  }
  // The t-breakpoints of the row from σ = 0 to σ = c (c ≤ γ + max w): the γ' breakpoints in
  // (γ − c, γ), the extra ones given, and the profile's kinks.
  std::vector<Real> pieces(const Real& c, const std::vector<Real>& extra) const {
    const Real t0 = profile_.t_at_sigma(Real(0)), t1 = profile_.t_at_sigma(c);
    std::vector<Real> ts{t0};
    auto add = [&](const Real& g) {
      if (g > gamma_ - c && g < gamma_) ts.push_back(profile_.t_at_sigma(Real(gamma_ - g)));
    };
    for (std::size_t k = 1; k + 1 < nodes_.size(); ++k) add(nodes_[k]);
    for (const Real& g : extra) add(g);
    for (const Real& t : profile_.t_breaks())
      if (t > t0 && t < t1) ts.push_back(t);
    ts.push_back(t1);
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    return graded_pieces(ts);
  }
  const std::string where;  // the case, for messages (check_curved)

 private:
  const Profile<Real>& profile_;
  Real gamma_;
  SpringRow<Real> row_;
  Result<Real> center_;
  std::vector<Real> nodes_;
  std::map<Real, Result<Real>> springs_;
};

}  // namespace detail

// N(φ) and S(φ) at each phase (in [0, 1]; 1 is 0 again), S to `rel` of itself (s ≥ 0, so the
// pieces' L1 norms add to S) or to the rounding floor below, with the quadrature's estimate in
// `error`. Preconditions and errors as solve_curved; SolverError also where a check spring of a
// piece disagrees with the closed form (a breakpoint missed).
template <class Real>
std::vector<CurvedTraceRow<Real>> curved_trace(const Waveform<Real>& w, const Profile<Real>& profile, const Real& beta,
                                               const Real& gamma, const std::vector<Real>& phases, const Real& rel,
                                               const Options& opt = {}) {
  using detail::short_str;
  using std::abs;
  using std::floor;
  detail::RowStructure<Real> rs(w, profile, beta, gamma, opt);
  const Real eps = std::numeric_limits<Real>::epsilon();
  std::vector<CurvedTraceRow<Real>> rows;
  rows.reserve(phases.size());
  try {
    for (const Real& phase : phases) {
      const Real phi = phase - floor(phase);
      const Real wphi = w(phi), c = gamma + wphi;
      CurvedTraceRow<Real> row{phase, Real(0), Real(0), Real(0)};
      if (!(c > 0)) {
        rows.push_back(row);
        continue;
      }
      const Real xc = profile.x_at_sigma(c);
      row.n = c * xc - profile.sigma_integral(xc);
      // The anchored sticks' ends passing φ, interval by interval.
      std::vector<Real> extra{Real(-wphi)};
      const auto& nodes = rs.nodes();
      for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
        const Real &a = nodes[k], &b = nodes[k + 1];
        if (!(b > -wphi)) continue;  // no spring of this interval touches at φ
        const Real m = (a + b) / 2;
        if (!(m > a) || !(m < b)) continue;
        for (const auto& st : rs.middle(k).stick_phases) {
          if (st.level != 0) continue;
          const detail::AnchoredOnset<Real> onset(w, st, m, rs.row().stats());
          for (int shift = 0; shift <= 1; ++shift) {
            const Real t = phi + shift;
            if (onset.at_jump) {
              const Real g = beta * (t - st.begin) - wphi;
              if (g > a && g < b) extra.push_back(g);
              continue;
            }
            auto F = [&](const Real& g) -> Real { return g + wphi - beta * (t - onset(g)); };
            const Real fa = F(a), fb = F(b);
            if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0))
              extra.push_back(detail::bracketed_root<Real>(F, a, b, fa, fb, "stick end passes the phase", rs.row().stats()));
          }
        }
      }
      const std::vector<Real> ps = rs.pieces(c, extra);
      // What rounding leaves of s, integrated over the row: a few eps of β and of n's terms each.
      // Just after first contact s is far below it (β times the time since), and S(φ) is then
      // known only to this, not to rel of itself: the caller sees it in the row's error.
      const Real floor_abs = 64 * eps * (beta + 1) * (abs(gamma) + 2) * xc;
      Real s = profile.flat_length() * tangential_force(w, rs.center(), beta, gamma, phi);
      for (std::size_t k = 0; k + 1 < ps.size(); ++k) {
        const Real &a = ps[k], &b = ps[k + 1];
        if (!(b > a)) continue;
        // The state at φ from the spring 1/16 into the piece, checked by the one 1/16 before its
        // end: a breakpoint missed inside the piece changes the state at φ between them, which
        // moves s there by the slope's jump times the distance, far above the events' rounding
        // (a few eps times β and n).
        const Real sigma_m = profile.sigma_at_t(Real(a + (b - a) / 16)), gm = gamma - sigma_m;
        const Result<Real>& mid = rs.spring(gm);
        Real at = 0;
        const StickPhase<Real>* st = detail::stick_at(mid, phi, at);
        std::optional<detail::AnchoredOnset<Real>> onset;
        if (st && st->level == 0) onset.emplace(w, *st, gm, rs.row().stats());
        // s of the spring at σ (γ' = γ − σ), from σ: n = c − σ has no cancellation where c is small.
        auto s_of = [&](const Real& sigma) -> Real {
          if (!st) return c - sigma;  // slip: s = n
          if (onset) return beta * (at - (*onset)(Real(gamma - sigma)));
          return st->level + (sigma_m - sigma) + beta * (at - st->begin);  // the level is n at the onset
        };
        for (const Real& t : {Real(a + (b - a) / 16), Real(b - (b - a) / 16)}) {
          const Real sigma = profile.sigma_at_t(t), g = gamma - sigma;
          const Real own = tangential_force(w, rs.spring(g), beta, g, phi), closed = s_of(sigma);
          if (!(abs(own - closed) <= 256 * eps * (abs(g) + 2) * (beta + 1)))
            throw SolverError("trace at phase " + short_str(phi) + ": the spring at gamma' = " + short_str(g) + " has s = " +
                              short_str(own) + ", the closed form of its piece " + short_str(closed) + " (a breakpoint missed)");
        }
        Real value, err, l1;
        detail::integrate_piece([&](const Real& t) -> Real { return s_of(profile.sigma_at_t(t)) * profile.dx_dt(t); },
                                a, b, rel, floor_abs, opt, "s", value, err, l1);
        s += value;
        row.error += err;
      }
      row.s = s < row.n ? s : row.n;  // s ≤ n for every spring: above is rounding
      rows.push_back(row);
    }
  } catch (const PrecisionError&) {
    throw;
  } catch (const SolverError& e) {
    throw SolverError(rs.where + ": " + e.what());
  }
  return rows;
}

// The row's stick integral ∫₀^X t_stick(γ − σ(x)) dx (flat part included) to `rel` of itself,
// with its quadrature estimate in `err`. t_stick changes its form only where the event
// structure does: solve_curved's breakpoints. Divided by X (CurvedResult::contact_radius) it
// is the springs' stick share averaged over the row; on a flat punch, the stick fraction.
template <class Real>
Real curved_stick_integral(const Waveform<Real>& w, const Profile<Real>& profile, const Real& beta, const Real& gamma,
                           const Real& rel, Real& err, const Options& opt = {}) {
  detail::RowStructure<Real> rs(w, profile, beta, gamma, opt);
  const auto stick_time = [](const Result<Real>& r) {
    Real t = 0;
    for (const auto& st : r.stick_phases) t += st.end - st.begin;
    return t;
  };
  Real total = profile.flat_length() * stick_time(rs.center());
  err = 0;
  if (!(beta < rs.center().beta_c)) return total;  // no spring sticks (Eq. 6; β_c grows with γ')
  try {
    const std::vector<Real> ps = rs.pieces(Real(gamma + w.maximum()), {});
    // A piecewise-linear wave: every event phase is affine in γ' between two breakpoints (curved.hpp,
    // QuadraticSprings), and so is t_stick: two springs an interval (at its quarters) give it there,
    // a third at its middle checks it (to 64 eps of the period); one that misses leaves the
    // interval to a spring at every node.
    const bool linear = dynamic_cast<const PiecewiseLinear<Real>*>(&w) != nullptr;
    const auto& nodes = rs.nodes();
    struct Affine {
      bool fitted = false, usable = false;
      Real at_lo, slope;  // t_stick = at_lo + slope (γ' − lo)
    };
    std::vector<Affine> lines(nodes.size());
    const Real eps = std::numeric_limits<Real>::epsilon();
    const auto spring_stick = [&](const Real& g) -> Real {
      if (!(g + w.maximum() > 0)) return Real(0);
      return stick_time(rs.row().result(g));
    };
    const auto stick_at = [&](const Real& g) -> Real {
      if (!linear) return spring_stick(g);
      const std::size_t k = std::min<std::size_t>(
          static_cast<std::size_t>(std::upper_bound(nodes.begin(), nodes.end(), g) - nodes.begin()), nodes.size() - 1);
      if (k == 0) return spring_stick(g);
      Affine& line = lines[k - 1];
      const Real &lo = nodes[k - 1], &hi = nodes[k];
      if (!line.fitted) {
        line.fitted = true;
        const Real q1 = lo + (hi - lo) / 4, q3 = hi - (hi - lo) / 4, m = (lo + hi) / 2;
        if (q1 > lo && q3 < hi && q1 < m && m < q3) {
          const Real y1 = spring_stick(q1), y3 = spring_stick(q3);
          line.slope = (y3 - y1) / (q3 - q1);
          line.at_lo = y1 - line.slope * (q1 - lo);
          using std::abs;
          line.usable = abs(line.at_lo + line.slope * (m - lo) - spring_stick(m)) <= 64 * eps;
        }
      }
      return line.usable ? Real(line.at_lo + line.slope * (g - lo)) : spring_stick(g);
    };
    const auto h = [&](const Real& t) -> Real { return stick_at(Real(gamma - profile.sigma_at_t(t))) * profile.dx_dt(t); };
    // The accuracy asked of a piece is relative to the whole integral, estimated by the midpoint
    // rule first (as solve_curved): a piece between two nearly equal breakpoints (a noisy signal's)
    // cannot reach digits relative to its own tiny size, nor needs to.
    Real scale = total;
    for (std::size_t k = 0; k + 1 < ps.size(); ++k)
      if (ps[k + 1] > ps[k]) scale += (ps[k + 1] - ps[k]) * h(Real((ps[k] + ps[k + 1]) / 2));
    for (std::size_t k = 0; k + 1 < ps.size(); ++k) {
      const Real &a = ps[k], &b = ps[k + 1];
      if (!(b > a)) continue;
      Real value, e, l1;
      detail::integrate_piece(h, a, b, rel, Real(rel * scale / ps.size()), opt, "t_stick", value, e, l1);
      total += value;
      err += e;
    }
  } catch (const PrecisionError&) {
    throw;
  } catch (const SolverError& e) {
    throw SolverError(rs.where + ": " + e.what());
  }
  return total;
}

}  // namespace vibrofric
