// The curved contact's rig, its one-period map (core/dynamics/rig_row.hpp, model.md "Rig dynamics",
// "On a curved contact"): the row's springs under one body, their events through H± = X ∓ w and the
// closed-form motion between events (motion.hpp), from the section at w's minimum to the next.
// Private to the core; the periodic state is rig_row_engine.hpp's.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/dynamics/rig_row.hpp"
#include "vibrofric/core/errors.hpp"
#include "motion.hpp"

namespace vibrofric {
namespace detail {

template <class Real>
class RowRigPeriod {
 public:
  using State = std::array<Real, 2>;  // Y, Y' at the section
  enum class Mode { out, stick, forward, backward };
  struct Spring {
    Mode mode = Mode::out;
    Real xc = 0;          // the contact point X_c (stick; set again where a slip ends)
    Real back_start = 0;  // X_c where the current backward phase began
  };
  using Row = std::vector<Spring>;

  RowRigPeriod(const Waveform<Real>& w, const Real& beta, const Real& gamma, const RigParameters<Real>& p,
               const std::vector<RowSpring<Real>>& row, const Options& opt)
      : wave_(w), rw_(w), beta_(beta), gamma_(gamma), p_(p), row_(row) {
    using std::abs;
    using std::sqrt;
    if (!(p.kappa > 0) || !(p.omega > 0) || !(p.zeta >= 0))
      throw DomainError("rig dynamics: expected kappa > 0, omega > 0, zeta >= 0");
    if (row.empty()) throw DomainError("rig dynamics on a curved contact: the row has no spring");
    for (const RowSpring<Real>& sp : row) carried_ = carried_ || gamma - sp.sigma + w.minimum() > 0;
    const Real two_pi = boost::math::constants::two_pi<Real>();
    omega2_ = two_pi * p.omega * (two_pi * p.omega);
    c_ = 2 * two_pi * p.zeta * p.omega * sqrt(p.kappa);
    K_slip_ = p.resonant_harmonic ? Real(two_pi * p.resonant_harmonic * (two_pi * p.resonant_harmonic))
                                  : Real(omega2_ * p.kappa);
    stats_.max_iterations = root_budget<Real>(opt);
    const std::size_t P = w.piece_count(), i0 = w.argmin_break();
    section_ = w.piece_begin(i0);
    normal_area_ = 0;
    for (std::size_t k = 0; k < P; ++k) {
      const std::size_t i = (i0 + k) % P;
      const Real shift = i < i0 ? Real(1) : Real(0);
      Piece pc;
      pc.a = w.piece_begin(i) + shift;
      pc.b = w.piece_end(i) + shift;
      pc.form = rw_.form(i);
      if (!pc.form.a) pc.form.origin += shift;
      pc.jump = w.jump_at(i);  // at the section too: the carried springs arrive at its left limit
      pc.prev_end = w.end_value((i + P - 1) % P);
      pc.begin = w.begin_value(i);
      pc.w1 = abs(pc.form.p1);
      pc.w2 = 0;
      if (pc.form.a)
        for (std::size_t h = 1; h < pc.form.a->size(); ++h) {
          const Real nu = two_pi * static_cast<unsigned>(h);
          const Real size = abs((*pc.form.a)[h]) + abs((*pc.form.b)[h]);
          pc.w1 += nu * size;
          pc.w2 += nu * nu * size;
        }
      pc.parts.resize(row.size());
      for (std::size_t j = 0; j < row.size(); ++j) {
        Part& part = pc.parts[j];
        const Real gj = gamma - row[j].sigma;
        Real c0, c1;
        if (!w.contact_part(i, gj, c0, c1, stats_)) continue;
        part.in = true;
        part.c0 = c0 + shift;
        part.c1 = c1 + shift;
        part.enters = gj + w.begin_value(i) < 0;
        part.leaves = gj + w.end_value(i) < 0;
        if (part.enters) pc.schedule.push_back({part.c0, j, true});
        if (part.leaves) pc.schedule.push_back({part.c1, j, false});
        normal_area_ += row[j].weight * (gj * (part.c1 - part.c0) + wave_integral(pc.form, part.c0, part.c1));
      }
      std::sort(pc.schedule.begin(), pc.schedule.end(),
                [](const Scheduled& x, const Scheduled& y) { return x.phi < y.phi; });
      pieces_.push_back(std::move(pc));
    }
    if (!(normal_area_ > 0)) throw DomainError("rig dynamics on a curved contact: no spring of the row touches");
  }

  // The one-period map of (Y, Y') from the section to the section a period later; where springs
  // stay in contact through the section (carried_), also of their states (`row_in`, none: all out,
  // so that they touch down there), each contact point relative to the drive (X_c − βφ).
  State period(const State& in, RowRigResult<Real>* record = nullptr, const Row* row_in = nullptr,
               Row* row_out = nullptr, const std::vector<Real>* phases = nullptr,
               std::vector<RowRigSample<Real>>* samples = nullptr) const {
    Run r;
    r.y = in[0];
    r.v = in[1];
    r.s.assign(row_.size(), Spring{});
    // phases on this period's run, in order; φ = 1 the period's end, its left value (side 0)
    std::vector<Wanted> want;
    if (phases && samples) {
      samples->assign(phases->size(), RowRigSample<Real>{});
      for (std::size_t k = 0; k < phases->size(); ++k) {
        const Real& phi = (*phases)[k];
        want.push_back({phi < section_ ? Real(phi + 1) : phi, phi == 1 ? 0 : 1, k});
      }
      std::sort(want.begin(), want.end(), [](const Wanted& x, const Wanted& y) {
        return x.phi < y.phi || (x.phi == y.phi && x.side < y.side);
      });
      r.want = &want;
      r.samples = samples;
    }
    if (row_in) {
      const Real X0 = beta_ * section_;
      for (std::size_t j = 0; j < row_.size(); ++j) {
        const Spring& sp = (*row_in)[j];
        if (sp.mode == Mode::out) continue;
        set_mode(r, j, sp.mode, Real(sp.xc + X0));
        r.s[j].back_start = sp.back_start + X0;
      }
    }
    r.record = record != nullptr;
    for (const Piece& pc : pieces_) piece(r, pc);
    if (r.want) {
      if (r.next_sample != want.size())
        throw SolverError("rig dynamics on a curved contact: a phase to sample was not reached in the period");
      for (std::size_t k = 0; k < phases->size(); ++k) (*samples)[k].phi = (*phases)[k];
    }
    if (row_out) {
      const Real X1 = beta_ * (section_ + 1);
      *row_out = r.s;
      for (Spring& sp : *row_out) {
        sp.xc -= X1;
        sp.back_start -= X1;
      }
    }
    if (record) {
      record->retained_area = r.retained;
      record->lag_integral = r.lag;
      record->stick_fraction = r.stick;
      record->slip_fraction = r.slip;
      record->backward_fraction = r.back;
      record->flight_fraction = 1 - r.stick - r.slip;
      record->amplitude = (r.ymax - r.ymin) / 2;
      record->largest_backward_slip = r.largest_back;
      record->events = r.events;
    }
    return {r.y, r.v};
  }


  // The row moved with the body by dy, its forces held: every stick spring's contact point too.
  static Row shift(Row R, const Real& dy) {
    for (Spring& sp : R)
      if (sp.mode == Mode::stick) sp.xc += dy;
    return R;
  }

  // Spring j's force at the section in state (Y, sp): stick Y − (X_c − βφ), slip ±n, out 0 (n at
  // the section's left limit, where the carried states are taken).
  Real section_force(const Real& y, const Spring& sp, std::size_t j) const {
    const Real n = std::max(Real(gj(j) + pieces_.front().prev_end), Real(0));
    switch (sp.mode) {
      case Mode::stick:
        return y - sp.xc;
      case Mode::forward:
        return n;
      case Mode::backward:
        return -n;
      default:
        return 0;
    }
  }
  // The row at the section with these forces, the body at Y = y: each spring in contact there
  // sticking at its force clamped to its bound (on the bound the period's start rules slip, as the
  // sweeping process does), the others out.
  Row row_of_forces(const Real& y, const std::vector<Real>& forces) const {
    Row R(row_.size());
    for (std::size_t j = 0; j < row_.size(); ++j) {
      const Real n = std::max(Real(gj(j) + pieces_.front().prev_end), Real(0));
      if (!(n > 0)) continue;
      R[j].mode = Mode::stick;
      R[j].xc = y - std::clamp(forces[j], Real(-n), n);
    }
    return R;
  }
  // The largest change of a spring's force at the section between two states.
  Real row_change(const Real& y0, const Row& a, const Real& y1, const Row& b) const {
    using std::abs;
    Real d = 0;
    for (std::size_t j = 0; j < row_.size(); ++j)
      d = std::max(d, Real(abs(Real(section_force(y1, b[j], j) - section_force(y0, a[j], j)))));
    return d;
  }
  Real body_size(const State& d) const {
    using std::abs;
    using std::sqrt;
    return abs(d[0]) + abs(d[1]) / sqrt(Real(omega2_ * (p_.kappa + 1)));
  }

 protected:
  struct Part {
    bool in = false, enters = false, leaves = false;
    Real c0 = 0, c1 = 0;
  };
  struct Scheduled {
    Real phi;
    std::size_t spring;
    bool touch;  // touch-down, else contact loss
  };
  struct Piece {
    Real a, b, prev_end, begin, w1, w2;  // w1, w2: bounds of |w'|, |w''| on the piece
    WaveForm<Real> form;
    bool jump;
    std::vector<Part> parts;
    std::vector<Scheduled> schedule;
  };
  // The row's sums in the current modes: ⟨s⟩ = Ws (Y + βφ) − As + Gf − Gb + (Wf − Wb) w.
  struct Wanted {
    Real phi;
    int side;  // 0: the left value at phi, 1: the right
    std::size_t index;
  };
  struct Sums {
    Real Ws = 0, As = 0, Wf = 0, Gf = 0, Wb = 0, Gb = 0;
    Real C = 0, D = 0;  // min over stick springs of X_c + γ_j, max of X_c − γ_j
    bool stick = false, forward = false, backward = false;
  };
  // A period's state: the springs, and by mode their sums (kept as springs change mode, summed
  // afresh at every piece of the wave against drift) and the stick springs' thresholds in order,
  // so that an event costs O(log n) and a period O(n log n).
  struct Run {
    Real y, v;
    std::vector<Spring> s;
    bool record = false;
    Real retained = 0, lag = 0, stick = 0, slip = 0, back = 0, largest_back = 0;
    Real ymin = std::numeric_limits<Real>::infinity(), ymax = -std::numeric_limits<Real>::infinity();
    std::size_t events = 0;
    Sums sums;
    std::set<std::pair<Real, std::size_t>> up, down;  // stick: X_c + γ_j, X_c − γ_j
    std::set<std::size_t> forward, backward;
    const std::vector<Wanted>* want = nullptr;  // phases to sample, ascending
    std::size_t next_sample = 0;
    std::vector<RowRigSample<Real>>* samples = nullptr;
  };

  // The samples of r.want up to b, the end of a span under motion m, from where the last span ended:
  // before b the right values, at b those of side 0 (the left values) and where b ends the period.
  void sample(Run& r, const Piece& pc, const Sums& S, const Motion<Real>& m, const Real& b) const {
    const Real end = section_ + 1;
    for (; r.next_sample < r.want->size(); ++r.next_sample) {
      const Real& phi = (*r.want)[r.next_sample].phi;
      const std::size_t k = (*r.want)[r.next_sample].index;
      if (!(phi < b) && !(phi == b && (b == end || (*r.want)[r.next_sample].side == 0))) return;
      const auto yv = m(phi);
      const Real w = wave_derivatives(pc.form, phi)[0];
      const Real X = yv[0] + beta_ * phi;
      Real n = 0, flight = 0, s_step = 0, s_prev = 0;
      for (std::size_t j = 0; j < row_.size(); ++j) {
        const Real nj = std::max(Real(gj(j) + w), Real(0));
        const Mode mode = r.s[j].mode;
        const Real sj = mode == Mode::stick ? Real(X - r.s[j].xc) : mode == Mode::forward ? nj
                        : mode == Mode::backward ? Real(-nj) : Real(0);
        n += row_[j].weight * nj;
        if (mode == Mode::out) flight += row_[j].weight;
        // neighbours of the quadrature (a wear flat's spring at σ = 0 stands for its flat exactly)
        if (j > 0 && row_[j - 1].sigma > 0) {
          using std::abs;
          s_step = std::max(s_step, Real(abs(Real(sj - s_prev))));
        }
        s_prev = sj;
      }
      RowRigSample<Real>& out = (*r.samples)[k];
      out.flight = flight;
      out.s_step = s_step;
      out.n = n;
      out.s = S.Ws * (yv[0] + beta_ * phi) - S.As + S.Gf - S.Gb + (S.Wf - S.Wb) * w;
      out.y = yv[0];
      out.v = yv[1];
      out.stick = S.Ws;
      out.slip = S.Wf + S.Wb;
      out.backward = S.Wb;
    }
  }

  Real gj(std::size_t j) const { return gamma_ - row_[j].sigma; }

  Sums sums(const Run& r) const {
    Sums S = r.sums;
    S.stick = !r.up.empty();
    S.forward = !r.forward.empty();
    S.backward = !r.backward.empty();
    if (S.stick) {
      S.C = r.up.begin()->first;
      S.D = r.down.rbegin()->first;
    }
    return S;
  }

  // Spring j leaves its mode (its share of the sums and its place in the ordered sets) and
  // enters `mode` with contact point xc.
  void set_mode(Run& r, std::size_t j, Mode mode, const Real& xc = Real(0)) const {
    Spring& sp = r.s[j];
    const Real& wt = row_[j].weight;
    Sums& S = r.sums;
    switch (sp.mode) {
      case Mode::stick:
        S.Ws -= wt;
        S.As -= wt * sp.xc;
        r.up.erase({Real(sp.xc + gj(j)), j});
        r.down.erase({Real(sp.xc - gj(j)), j});
        if (r.up.empty()) S.Ws = S.As = 0;
        break;
      case Mode::forward:
        S.Wf -= wt;
        S.Gf -= wt * gj(j);
        r.forward.erase(j);
        if (r.forward.empty()) S.Wf = S.Gf = 0;
        break;
      case Mode::backward:
        S.Wb -= wt;
        S.Gb -= wt * gj(j);
        r.backward.erase(j);
        if (r.backward.empty()) S.Wb = S.Gb = 0;
        break;
      default:
        break;
    }
    sp.mode = mode;
    switch (mode) {
      case Mode::stick:
        sp.xc = xc;
        S.Ws += wt;
        S.As += wt * xc;
        r.up.insert({Real(xc + gj(j)), j});
        r.down.insert({Real(xc - gj(j)), j});
        break;
      case Mode::forward:
        S.Wf += wt;
        S.Gf += wt * gj(j);
        r.forward.insert(j);
        break;
      case Mode::backward:
        S.Wb += wt;
        S.Gb += wt * gj(j);
        r.backward.insert(j);
        break;
      default:
        break;
    }
  }

  // The sums afresh from the springs' modes (against the drift of adding and removing).
  void resum(Run& r) const {
    Sums S;
    for (std::size_t j = 0; j < row_.size(); ++j) {
      const Spring& sp = r.s[j];
      const Real& wt = row_[j].weight;
      if (sp.mode == Mode::stick) {
        S.Ws += wt;
        S.As += wt * sp.xc;
      } else if (sp.mode == Mode::forward) {
        S.Wf += wt;
        S.Gf += wt * gj(j);
      } else if (sp.mode == Mode::backward) {
        S.Wb += wt;
        S.Gb += wt * gj(j);
      }
    }
    r.sums = S;
  }

  Motion<Real> motion(const Run& r, const Piece& pc, const Sums& S, const Real& a) const {
    const bool slip_only = !S.stick;
    const Real K = slip_only ? K_slip_ : Real(omega2_ * (p_.kappa + S.Ws));
    const Real f0 = -omega2_ * (S.Ws * beta_ * a - S.As + S.Gf - S.Gb);
    const Real f1 = -omega2_ * S.Ws * beta_;
    return Motion<Real>(c_, K, a, r.y, r.v, f0, f1, &pc.form, Real(-omega2_ * (S.Wf - S.Wb)),
                        slip_only ? p_.resonant_harmonic : 0u);
  }

  // X, X', X'' and w, w', w'' at φ under motion m.
  struct Body {
    Real x, dx, ddx;
    std::array<Real, 3> w;
  };
  Body at(const Motion<Real>& m, const Piece& pc, const Sums& S, const Real& phi) const {
    const auto yv = m(phi);
    const auto w = wave_derivatives(pc.form, phi);
    const Real mean_s = S.Ws * (yv[0] + beta_ * phi) - S.As + S.Gf - S.Gb + (S.Wf - S.Wb) * w[0];
    // Y'' from the body's equation as the motion solves it (K may be the resonance's ν² exactly).
    const Real K_used = S.stick ? Real(omega2_ * (p_.kappa + S.Ws)) : K_slip_;
    const Real forcing = -omega2_ * (mean_s - S.Ws * yv[0]);
    const Real ddy = forcing - c_ * yv[1] - K_used * yv[0];
    return {yv[0] + beta_ * phi, yv[1] + beta_, ddy, w};
  }

  // The first φ in (a, end] where g ≥ 0, g(φ) and g'(φ) from f; G(x) bounds |g'| beyond x. As the
  // flat rig's search (rig_engine.hpp): a grid of 16 points per oscillation of the fastest rate,
  // strided where |g|/G rules a root out; a local maximum between grid points bisected on g'; a
  // start on an event (g(a) ≥ 0) searched just inside, and a at once where g ≥ 0 down to a.
  template <class F, class Bound>
  std::optional<Real> first_root(F f, const Real& a, const Real& end, const Real& rate, Bound G) const {
    using std::abs;
    using std::ceil;
    const Real two_pi = boost::math::constants::two_pi<Real>();
    const Real per = ceil(Real(rate * (end - a) / two_pi * 16));
    if (per > 5e7) throw SolverError("rig dynamics on a curved contact: more than 5e7 event-grid points in one span");
    const std::size_t steps = std::max<std::size_t>(4, static_cast<std::size_t>(per) + 1);
    const Real cell = (end - a) / static_cast<unsigned>(steps);
    Real x0 = a;
    auto [g0, d0] = f(a);
    const bool at_event = !(g0 < 0);
    if (at_event) g0 = Real(-1);
    while (x0 < end) {
      Real x1 = x0 + cell;
      if (g0 < 0 && !(at_event && x0 == a)) {
        const Real clear = abs(g0) / G(x0) * Real(0.9375);
        if (clear > cell) x1 = x0 + clear;
      }
      if (!(x1 < end) || end - x1 < cell / 1024) x1 = end;
      auto [g1, d1] = f(x1);
      if (g1 >= 0) {
        Real lo = x0, glo = g0;
        if (at_event && x0 == a) {
          bool found = false;
          Real hi = x1;
          for (int k = 0; k < 200 && !found; ++k) {
            const Real x = a + (hi - a) / 2;
            if (!(x > a) || !(x < hi)) break;
            const Real gx = f(x).first;
            if (gx < 0) {
              lo = x;
              glo = gx;
              found = true;
            } else {
              hi = x;
            }
          }
          if (!found) return a;
          x1 = hi;
          g1 = f(hi).first;
        }
        return bracketed_root<Real>([&](const Real& x) { return f(x).first; }, lo, x1, glo, g1,
                                    "rig dynamics event (curved contact)", stats_, Real(1));
      }
      if (d0 > 0 && d1 < 0 && !(at_event && x0 == a)) {
        // a local maximum between grid points: bisected on g' until it is found or ruled out
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
          const auto [gc, dc] = f(c2);
          if (dc > 0) {
            lo = c2;
            glo = gc;
          } else {
            hi = c2;
            ghi = gc;
          }
        }
        const Real xm = (lo + hi) / 2;
        const Real gm = excluded ? Real(-1) : f(xm).first;
        if (gm >= 0)
          return bracketed_root<Real>([&](const Real& x) { return f(x).first; }, x0, xm, g0, gm,
                                      "rig dynamics event (curved contact)", stats_, Real(1));
      }
      x0 = x1;
      g0 = g1;
      d0 = d1;
    }
    return std::nullopt;
  }

  // Y's extremes on [a, b] (the amplitude): a grid of 16 points per oscillation, Y' = 0 refined.
  void track(Run& r, const Motion<Real>& m, const Real& a, const Real& b, const Real& rate) const {
    using std::ceil;
    const Real two_pi = boost::math::constants::two_pi<Real>();
    const std::size_t steps =
        std::max<std::size_t>(2, static_cast<std::size_t>(std::min(Real(1e7), ceil(Real(rate * (b - a) / two_pi * 16)))));
    auto x0 = a;
    auto y0 = m(a);
    const auto see = [&](const Real& y) {
      r.ymin = std::min(r.ymin, y);
      r.ymax = std::max(r.ymax, y);
    };
    see(y0[0]);
    for (std::size_t k = 1; k <= steps; ++k) {
      const Real x1 = k == steps ? b : Real(a + (b - a) * static_cast<unsigned>(k) / static_cast<unsigned>(steps));
      const auto y1 = m(x1);
      see(y1[0]);
      if ((y0[1] > 0) != (y1[1] > 0) && y0[1] != 0 && y1[1] != 0) {
        const Real e = bracketed_root<Real>([&](const Real& x) { return m(x)[1]; }, x0, x1, y0[1], y1[1],
                                            "rig dynamics extreme (curved contact)", stats_, Real(1));
        see(m(e)[0]);
      }
      x0 = x1;
      y0 = y1;
    }
  }

  void end_backward(Run& r, std::size_t j, const Real& xc_end) const {
    if (r.s[j].mode == Mode::backward)
      r.largest_back = std::max(r.largest_back, Real(r.s[j].back_start - xc_end));
  }

  // The sweeping-process rules at φ where modes may change without an event of the body: a
  // slip whose direction no longer holds ends (at kinks of w), a stick spring on its boundary and
  // moving out of it slips, a new contact's mode by its rate (model.md: touch-down).
  void classify(Run& r, const Piece& pc, const Real& phi) const {
    using std::abs;
    const auto w = wave_derivatives(pc.form, phi);
    const Real X = r.y + beta_ * phi, dX = r.v + beta_;
    const Real Hp = X - w[0], dHp = dX - w[1], Hm = X + w[0], dHm = dX + w[1];
    const Real tol = 64 * std::numeric_limits<Real>::epsilon() * (1 + abs(X) + abs(w[0]) + abs(gamma_));
    const auto n = [&](std::size_t j) { return std::max(Real(gj(j) + w[0]), Real(0)); };
    if (dHp < 0)
      for (const std::size_t j : std::vector<std::size_t>(r.forward.begin(), r.forward.end()))
        set_mode(r, j, Mode::stick, Real(X - n(j)));
    if (dHm > 0)
      for (const std::size_t j : std::vector<std::size_t>(r.backward.begin(), r.backward.end())) {
        end_backward(r, j, Real(X + n(j)));
        set_mode(r, j, Mode::stick, Real(X + n(j)));
      }
    // stick springs on the forward bound (s ≥ n − tol: X_c + γ_j ≤ H+ + tol) slip where H+ rises;
    // else those beyond it by rounding are clipped onto it
    std::vector<std::size_t> on;
    for (auto it = r.up.begin(); it != r.up.end() && it->first <= Hp + tol; ++it)
      if (dHp > 0 || it->first < Hp) on.push_back(it->second);
    for (const std::size_t j : on) set_mode(r, j, dHp > 0 ? Mode::forward : Mode::stick, Real(X - n(j)));
    on.clear();
    for (auto it = r.down.rbegin(); it != r.down.rend() && it->first >= Hm - tol; ++it)
      if (dHm < 0 || it->first > Hm) on.push_back(it->second);
    for (const std::size_t j : on) {
      if (r.s[j].mode != Mode::stick) continue;  // slipped forward just now (n = 0: on both bounds)
      if (dHm < 0) {
        set_mode(r, j, Mode::backward);
        r.s[j].back_start = X + n(j);
      } else {
        set_mode(r, j, Mode::stick, Real(X + n(j)));
      }
    }
  }

  void touch(Run& r, std::size_t j, const Real& phi) const { set_mode(r, j, Mode::stick, Real(r.y + beta_ * phi)); }
  void lose(Run& r, std::size_t j, const Real& phi) const {
    end_backward(r, j, Real(r.y + beta_ * phi));
    set_mode(r, j, Mode::out);
  }

  void piece(Run& r, const Piece& pc) const {
    const Real X = r.y + beta_ * pc.a;
    for (std::size_t j = 0; j < row_.size(); ++j) {
      Spring& sp = r.s[j];
      const Part& part = pc.parts[j];
      const bool in_now = part.in && !part.enters;
      if (sp.mode != Mode::out && !in_now) {
        lose(r, j, pc.a);
      } else if (sp.mode == Mode::out && in_now) {
        touch(r, j, pc.a);
      } else if (sp.mode != Mode::out && pc.jump) {
        // a jump of n: the spring holds its force, projected onto the new bound (instant slip)
        const Real n_old = std::max(Real(gj(j) + pc.prev_end), Real(0));
        const Real n_new = std::max(Real(gj(j) + pc.begin), Real(0));
        Real s = sp.mode == Mode::stick ? Real(X - sp.xc) : (sp.mode == Mode::forward ? n_old : Real(-n_old));
        if (sp.mode == Mode::backward) end_backward(r, j, Real(X - s));
        const Real before = X - s;
        if (s > n_new) s = n_new;
        if (s < -n_new) {
          s = -n_new;
          r.largest_back = std::max(r.largest_back, Real(X - s - before) < 0 ? Real(before - (X - s)) : Real(0));
        }
        set_mode(r, j, Mode::stick, Real(X - s));
      }
    }
    resum(r);
    classify(r, pc, pc.a);
    Real a = pc.a;
    std::size_t next = 0;
    while (true) {
      const Real stop = next < pc.schedule.size() ? pc.schedule[next].phi : pc.b;
      if (stop > a) traverse(r, pc, a, stop);
      if (next >= pc.schedule.size()) break;
      a = std::max(a, stop);
      for (; next < pc.schedule.size() && !(pc.schedule[next].phi > stop); ++next) {
        const Scheduled& e = pc.schedule[next];
        if (e.touch) touch(r, e.spring, a);
        else lose(r, e.spring, a);
      }
      classify(r, pc, a);
    }
  }

  void traverse(Run& r, const Piece& pc, Real a, const Real& end) const {
    using std::abs;
    using std::sqrt;
    const Real two_pi = boost::math::constants::two_pi<Real>();
    const long most = 64 + 16 * static_cast<long>(row_.size()) +
                      8 * static_cast<long>(std::min(Real(1e7), Real(sqrt(Real(omega2_ * (p_.kappa + 1))) * (end - a) / two_pi)));
    for (long guard = 0; guard < most; ++guard) {
      const Sums S = sums(r);
      const Motion<Real> m = motion(r, pc, S, a);
      const Real rate = std::max(m.rate(), Real(two_pi * rw_.harmonics()));
      std::optional<Real> stop;
      int which = -1;
      const auto consider = [&](int k, const std::optional<Real>& x) {
        if (x && (!stop || *x < *stop)) {
          stop = x;
          which = k;
        }
      };
      const auto lip1 = [&](const Real& x) { return Real(m.slope_bound(x) + abs(beta_) + pc.w1); };
      const auto lip2 = [&](const Real& x) { return Real(m.curvature_bound(x) + pc.w2); };
      if (S.stick) {
        consider(0, first_root([&](const Real& x) {
                   const Body q = at(m, pc, S, x);
                   return std::pair<Real, Real>{q.x - q.w[0] - S.C, q.dx - q.w[1]};
                 }, a, end, rate, lip1));
        consider(1, first_root([&](const Real& x) {
                   const Body q = at(m, pc, S, x);
                   return std::pair<Real, Real>{S.D - q.x - q.w[0], -q.dx - q.w[1]};
                 }, a, end, rate, lip1));
      }
      if (S.forward)
        consider(2, first_root([&](const Real& x) {
                   const Body q = at(m, pc, S, x);
                   return std::pair<Real, Real>{-(q.dx - q.w[1]), -(q.ddx - q.w[2])};
                 }, a, end, rate, lip2));
      if (S.backward)
        consider(3, first_root([&](const Real& x) {
                   const Body q = at(m, pc, S, x);
                   return std::pair<Real, Real>{q.dx + q.w[1], q.ddx + q.w[2]};
                 }, a, end, rate, lip2));
      const Real b = stop ? *stop : end;
      // the span [a, b] in these modes: its integrals, and Y's extremes on the recorded period
      if (b > a) {
        const auto ya = m(a), yb = m(b);
        const Real K = S.stick ? Real(omega2_ * (p_.kappa + S.Ws)) : K_slip_;
        const Real lag = (m.forcing_integral(b) - (yb[1] - ya[1]) - c_ * (yb[0] - ya[0])) / K;
        r.lag += lag;
        r.retained += S.Ws * (lag + beta_ * (b * b - a * a) / 2) + (S.Gf - S.Gb - S.As) * (b - a) +
                      (S.Wf - S.Wb) * wave_integral(pc.form, a, b);
        r.stick += S.Ws * (b - a);
        r.slip += (S.Wf + S.Wb) * (b - a);
        r.back += S.Wb * (b - a);
        if (r.record) track(r, m, a, b, rate);
        if (r.want) sample(r, pc, S, m, b);
      }
      const auto yb = m(b);
      r.y = yb[0];
      r.v = yb[1];
      if (!stop) return;
      ++r.events;
      const Body q = at(m, pc, S, b);
      const Real tol = 64 * std::numeric_limits<Real>::epsilon() * (1 + abs(q.x) + abs(q.w[0]) + abs(gamma_));
      const auto n = [&](std::size_t j) { return std::max(Real(gj(j) + q.w[0]), Real(0)); };
      std::vector<std::size_t> change;
      if (which == 0) {
        for (auto it = r.up.begin(); it != r.up.end() && it->first <= S.C + tol; ++it) change.push_back(it->second);
        for (const std::size_t j : change) set_mode(r, j, Mode::forward);
      } else if (which == 1) {
        for (auto it = r.down.rbegin(); it != r.down.rend() && it->first >= S.D - tol; ++it) change.push_back(it->second);
        for (const std::size_t j : change) {
          set_mode(r, j, Mode::backward);
          r.s[j].back_start = q.x + n(j);
        }
      } else if (which == 2) {
        for (const std::size_t j : std::vector<std::size_t>(r.forward.begin(), r.forward.end()))
          set_mode(r, j, Mode::stick, Real(q.x - n(j)));
      } else {
        for (const std::size_t j : std::vector<std::size_t>(r.backward.begin(), r.backward.end())) {
          end_backward(r, j, Real(q.x + n(j)));
          set_mode(r, j, Mode::stick, Real(q.x + n(j)));
        }
      }
      classify(r, pc, b);
      a = b;
      if (!(a < end)) return;
    }
    throw SolverError("rig dynamics on a curved contact: more than " + std::to_string(most) +
                      " events in one span of the wave (chattering)");
  }

  const Waveform<Real>& wave_;
  RigWave<Real> rw_;
  Real beta_, gamma_;
  RigParameters<Real> p_;
  std::vector<RowSpring<Real>> row_;
  Real omega2_, c_, K_slip_, section_, normal_area_;
  bool carried_ = false;  // some spring in contact at the section (γ − σ + min w > 0)
  std::vector<Piece> pieces_;
  mutable RootStats stats_;
};

}  // namespace detail
}  // namespace vibrofric
