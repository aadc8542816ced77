// The stick-slip solver: μ̄/μ0 = g_w(β, γ) (Eqs. 9, 13, 15) and Ψ_w(β) (Eqs. 11–12).
//
// n(φ) = max(γ + w(φ), 0) is the normal force in units of k_z·A, s(φ) the tangential force in
// units of μ0·k_z·A. The periodic steady state is s(φ) = βφ + min_{ψ ≤ φ} [n(ψ) − βψ] (model.md):
// starting where n is smallest (there s = n), one forward sweep over the monotone pieces of n
// finds every stick onset (Eq. 4: n' rises through β, an upward jump of n, or first contact) and
// every stick end (Eq. 8: n falls back onto the ramp, or jumps below it). Areas are exact where
// the waveform has an antiderivative; the tanh-sinh path (every event and piece end a
// breakpoint) is the cross-check.
//
// Not for: waveforms whose pieces violate the monotonicity contract of waveform.hpp.
#pragma once
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

enum class AreaMethod {
  automatic,   // exact if the waveform has an antiderivative, else quadrature
  exact,       // antiderivative differences; SolverError if there is none
  quadrature,  // tanh-sinh on every slip and stick segment
};

struct Options {
  AreaMethod area = AreaMethod::automatic;
  // Root finder: stops when the bracket is within 4 ulp; more iterations than this is an error.
  // 0: 200 plus the working precision in bits, as a bisection step gains one bit and the
  // safeguarded Newton bisects on flanks it cannot follow (power:P with P near 10^digits).
  std::uintmax_t max_root_iterations = 0;
  // tanh-sinh: at most this many halvings; stops when two levels differ by at most
  // quadrature_tolerance·L1 (0: sqrt(eps), after which the error is ~eps as convergence is
  // doubly exponential); not reaching it is an error.
  std::size_t max_quadrature_levels = 15;
  double quadrature_tolerance = 0;
};

template <class Real>
std::uintmax_t root_budget(const Options& opt) {
  if (opt.max_root_iterations > 0) return opt.max_root_iterations;
  return 200 + static_cast<std::uintmax_t>(std::ceil(working_digits10<Real>() * 3.3219280948873623));
}

template <class Real>
struct StickPhase {
  Real begin, end;  // phases, begin ∈ [0, 1), end ≥ begin (may exceed 1: wraps the period)
  Real level;       // s(begin); s = level + β·(φ − begin) on the phase
};

template <class Real>
struct Result {
  Real mu;              // μ̄/μ0 = ∫s / ∫n (Eq. 15)
  Real retained_area;   // ∫₀¹ s dφ, summed directly (no cancellation for small β)
  Real normal_area;     // ∫₀¹ n dφ
  Real lost_area;       // ∫₀¹ (n − s) dφ; equals Ψ_w(β) when there is no jumping (Eq. 12)
  Real beta_c;          // largest rising slope of n (Eq. 6); +∞ with an upward jump
  Real relative_error;  // estimated relative error of mu from rounding and quadrature
  Real lost_relative_error;  // the same for lost_area
  Real retained_error;       // bound on the absolute rounding error of retained_area
  Real normal_error;         // bound on the absolute rounding error of normal_area
  Real area_error;           // the larger of retained_error and normal_error
  bool jumping = false;      // n vanishes somewhere in the period
  AreaMethod area = AreaMethod::exact;
  std::vector<StickPhase<Real>> stick_phases;
  std::size_t events = 0;       // stick onsets + stick ends + contact boundaries
  std::size_t root_solves = 0;  // events that needed the root finder
  std::size_t root_iterations = 0;
  std::size_t quadratures = 0;
  std::size_t evaluations = 0;  // waveform value/slope/antiderivative calls
};

// The clipped normal force n = max(γ + w, 0) of Eq. 2 for one γ: the waveform's pieces split
// at the contact boundaries, with n, n' and the antiderivative at every segment end, the largest
// rising slope β_c(γ) (Eq. 6), and where the sweep starts. Nothing here depends on β, so one
// Contact serves every β of a sweep. Keeps a reference to the waveform.
template <class Real>
class Contact {
 public:
  struct Segment {
    std::size_t piece;
    Real u, v;       // sub-interval of the piece with constant contact status
    bool contact;    // n = γ + w on it (else n = 0)
    bool jump;       // u is a breakpoint where w jumps (n may jump there)
    bool convex, linear;
    Real nu, nv, dnu, dnv, Wu, Wv;  // n, n', antiderivative of w at u and v (0 off contact)
  };

  // Preconditions: γ finite with γ + max w > 0 (checked by solve()).
  Contact(const Waveform<Real>& w, const Real& gamma, const Options& opt = {}) : w_(w), gamma_(gamma) {
    detail::RootStats stats;
    stats.max_iterations = root_budget<Real>(opt);
    const std::size_t pieces = w.piece_count();
    using std::abs;
    using std::max;
    segs_.reserve(3 * pieces);  // a piece splits at most at two contact boundaries
    for (std::size_t i = 0; i < pieces; ++i) {
      if (i == w.argmin_break()) start_ = segs_.size();
      const Real& a = w.piece_begin(i);
      const Real& b = w.piece_end(i);
      const bool jump = w.jump_at(i);
      // β_c: an upward jump of n, else the largest slope at a contact segment's ends (w' is
      // monotone on the piece).
      if (jump) {
        const std::size_t prev = (i + pieces - 1) % pieces;
        const Real left = clip(gamma + w.end_value(prev)), right = clip(gamma + w.begin_value(i));
        if (right > 0 && right > left) beta_c_ = std::numeric_limits<Real>::infinity();
      }
      Real c0, c1;
      if (!w.contact_part(i, gamma, c0, c1, stats)) {
        push(i, a, b, false, jump, false, false);
        continue;
      }
      // Contact begins (ends) inside the piece where n < 0 at its start (end), even when the
      // boundary rounds onto the piece end (a flank narrower than the phase's precision).
      const bool enters = gamma + w.begin_value(i) < 0, leaves = gamma + w.end_value(i) < 0;
      if (enters) {
        ++boundaries_;
        if (c0 > a) push(i, a, c0, false, jump, false, false);
      }
      push(i, c0, c1, true, enters ? false : jump, enters, leaves);
      beta_c_ = max(beta_c_, max(segs_.back().dnu, segs_.back().dnv));
      if (leaves) {
        ++boundaries_;
        if (c1 < b) push(i, c1, b, false, false, false, false);
      }
    }
    root_solves_ = stats.solves;
    root_iterations_ = stats.iterations;
  }

  const Waveform<Real>& wave() const { return w_; }
  const Real& gamma() const { return gamma_; }
  const std::vector<Segment>& segments() const { return segs_; }
  std::size_t start() const { return start_; }  // first segment of the sweep: at argmin w
  const Real& beta_c() const { return beta_c_; }
  bool jumping() const { return gamma_ + w_.minimum() < 0; }
  Real n_min() const { return clip(gamma_ + w_.minimum()); }
  std::size_t boundaries() const { return boundaries_; }
  std::size_t root_solves() const { return root_solves_; }
  std::size_t root_iterations() const { return root_iterations_; }

 private:
  static Real clip(const Real& x) { return x > 0 ? x : Real(0); }
  // A contact segment's ends: the cached piece-end values where they are piece ends, exactly 0
  // for n at a contact boundary (its true value there). Each number made once, in its place.
  void push(std::size_t i, const Real& u, const Real& v, bool contact, bool jump, bool u_boundary, bool v_boundary) {
    if (!contact) {
      segs_.push_back(Segment{i, u, v, false, jump, w_.convex(i), w_.linear(i), 0, 0, 0, 0, 0, 0});
      return;
    }
    const bool ub = u == w_.piece_begin(i), ve = v == w_.piece_end(i);
    const bool anti = w_.has_antiderivative();
    segs_.push_back(Segment{i, u, v, true, jump, w_.convex(i), w_.linear(i),
                            end_n(u_boundary, ub, w_.begin_value(i), i, u), end_n(v_boundary, ve, w_.end_value(i), i, v),
                            ub ? Real(w_.begin_slope(i)) : w_.slope(i, u), ve ? Real(w_.end_slope(i)) : w_.slope(i, v),
                            anti ? w_.antiderivative(i, u) : Real(0), anti ? w_.antiderivative(i, v) : Real(0)});
  }
  // n = γ + w at a contact segment's end x: 0 at a contact boundary, else from the piece's cached
  // end value where x is the piece's end.
  Real end_n(bool boundary, bool piece_end, const Real& cached, std::size_t i, const Real& x) const {
    if (boundary) return Real(0);
    Real r = gamma_;
    if (piece_end)
      r += cached;
    else
      r += w_.value(i, x);
    return r;
  }

  const Waveform<Real>& w_;
  Real gamma_;
  std::vector<Segment> segs_;
  std::size_t start_ = 0, boundaries_ = 0, root_solves_ = 0, root_iterations_ = 0;
  Real beta_c_ = 0;
};

namespace detail {

// One tanh-sinh integrator per thread and precision: its tables are built at the precision that
// is current when it is constructed (toolchain.md).
// Boost 1.81's tanh_sinh builds its first rows unconditionally: fewer than 4 levels crash it.
inline constexpr std::size_t min_quadrature_levels = 4;

template <class Real>
boost::math::quadrature::tanh_sinh<Real>& integrator(std::size_t levels) {
  using Q = boost::math::quadrature::tanh_sinh<Real>;
  if (levels < min_quadrature_levels)
    throw InputError("max_quadrature_levels = " + std::to_string(levels) + ": expected at least " +
                     std::to_string(min_quadrature_levels) + " (tanh-sinh)");
  thread_local std::map<std::pair<int, std::size_t>, std::unique_ptr<Q>> cache;
  const auto key = std::make_pair(working_digits10<Real>(), levels);
  auto& slot = cache[key];
  if (!slot) slot = std::make_unique<Q>(levels);
  return *slot;
}

// One point's pass over the events of a period (Eqs. 4 and 8): the stick phases, their ends and
// the areas that solve() returns (the tool's `sweep` over many points is another thing).
template <class Real>
class EventPass {
 public:
  // `guesses`: phases near which stick ends are expected (a neighbouring spring's, curved.hpp);
  // used in double only, where they replace toms748 from the whole bracket by Newton within it.
  // (Long double's guess comes from toms748 in double: started from a neighbour's end instead,
  // the long double solve took 1.25 times as long, sphere + sine at β = 1, γ = −0.3.)
  EventPass(const Contact<Real>& contact, const Real& beta, const Options& opt,
            const std::vector<Real>* guesses = nullptr)
      : c_(contact), w_(contact.wave()), beta_(beta), gamma_(contact.gamma()), opt_(opt), guesses_(guesses) {
    const Waveform<Real>& w = w_;
    stats_.max_iterations = root_budget<Real>(opt);
    method_ = opt.area;
    if (method_ == AreaMethod::automatic)
      method_ = w.has_antiderivative() ? AreaMethod::exact : AreaMethod::quadrature;
    if (method_ == AreaMethod::exact && !w.has_antiderivative())
      throw InputError("waveform " + w.name() + " has no antiderivative: use the quadrature area method");
    if (method_ == AreaMethod::quadrature && opt.max_quadrature_levels < detail::min_quadrature_levels)
      throw InputError("max_quadrature_levels = " + std::to_string(opt.max_quadrature_levels) + ": expected at least " +
                       std::to_string(detail::min_quadrature_levels) + " (tanh-sinh)");
  }

  Result<Real> run() {
    const auto& segs = c_.segments();
    const std::size_t m = segs.size(), start = c_.start();
    // Start where n is smallest: there s = n (model.md), so the sweep needs no history.
    s_ = c_.n_min();
    sticking_ = false;
    for (std::size_t j = 0; j < m; ++j) sweep_segment(segs[(start + j) % m], start + j >= m);
    if (sticking_) close_stick(w_.piece_begin(w_.argmin_break()), 1);

    Result<Real> r;
    r.retained_area = retained_;
    r.normal_area = normal_;
    r.lost_area = lost_;
    if (stick_.empty()) {
      r.mu = 1;
    } else {
      r.mu = retained_;
      r.mu /= normal_;
    }
    // s ≤ n pointwise, so ∫s ≤ ∫n: a ratio above 1 (seen in double just below β_c at γ → −1) is
    // rounding, and 1 is nearer the truth.
    if (r.mu > 1) r.mu = 1;
    r.beta_c = c_.beta_c();
    r.jumping = c_.jumping();
    r.area = method_;
    // First-order rounding bounds (in eps) of the areas, relative to the areas themselves: large
    // where the areas are small differences of O(1) phases and values (β → 0, γ → −min w).
    // In place: eps·(err_retained/retained + err_normal/normal), eps·err_lost/lost.
    const Real eps = std::numeric_limits<Real>::epsilon();
    // An area that rounding drove to zero or below has no relative accuracy at all.
    const Real unknown = std::numeric_limits<Real>::infinity();
    if (stick_.empty()) {
      r.relative_error = 0;
    } else if (!(retained_ > 0 && normal_ > 0)) {
      r.relative_error = unknown;
    } else {
      Real part = err_normal_;
      part /= normal_;
      r.relative_error = err_retained_;
      r.relative_error /= retained_;
      r.relative_error += part;
      r.relative_error *= eps;
    }
    r.retained_error = err_retained_;
    r.retained_error *= eps;
    r.normal_error = err_normal_;
    r.normal_error *= eps;
    r.area_error = r.retained_error > r.normal_error ? r.retained_error : r.normal_error;
    if (stick_.empty()) {
      r.lost_relative_error = 0;
    } else if (lost_ > 0) {
      r.lost_relative_error = err_lost_;
      r.lost_relative_error *= eps;
      r.lost_relative_error /= lost_;
    } else {
      r.lost_relative_error = unknown;
    }
    r.events = events_ + c_.boundaries();
    r.root_solves = stats_.solves + c_.root_solves();
    r.root_iterations = stats_.iterations + c_.root_iterations();
    r.quadratures = quadratures_;
    r.evaluations = evaluations_;
    r.stick_phases = std::move(stick_);  // last: the bounds above ask whether there was a stick
    return r;
  }

 private:
  using Segment = typename Contact<Real>::Segment;

  // n and n' on a segment, remembering the last few evaluations: the sweep asks for the same
  // ends and events several times. A slot's numbers are made when it is first filled (a point
  // fills few of them). A reference from put() or find() holds until the next put().
  struct Memo {
    static constexpr std::size_t size = 4;
    static constexpr bool lazy = !std::is_floating_point_v<Real>;
    using Slot = std::conditional_t<lazy, std::optional<Real>, Real>;
    std::size_t piece[size] = {};
    Slot x[size], v[size];
    std::size_t used = 0, next = 0;
    template <class S>
    static auto& get(S& s) {
      if constexpr (lazy)
        return *s;
      else
        return s;
    }
    const Real* find(std::size_t p, const Real& at) const {
      for (std::size_t k = 0; k < used; ++k)
        if (piece[k] == p && get(x[k]) == at) return &get(v[k]);
      return nullptr;
    }
    const Real& put(std::size_t p, const Real& at, Real value) {
      const std::size_t k = next;
      next = (next + 1) % size;
      if (used < size) ++used;
      piece[k] = p;
      if constexpr (lazy) {
        if (!x[k]) {
          x[k].emplace(at);
          v[k].emplace(std::move(value));
          return *v[k];
        }
      }
      get(x[k]) = at;
      get(v[k]) = std::move(value);
      return get(v[k]);
    }
  };
  // n, n' and the antiderivative at x. For the multiprecision types (where an mpfr copy is an
  // allocation) references to the segment's ends, a memo's slot (valid until that memo's next
  // put) or zero_; values for double and long double, where a reference measured slower.
  using Value = std::conditional_t<std::is_floating_point_v<Real>, Real, const Real&>;
  Value zero() const {
    if constexpr (std::is_floating_point_v<Real>)
      return Real(0);
    else
      return zero_;
  }
  Value n(const Segment& g, const Real& x) {
    if (!g.contact) return zero();
    if (x == g.u) return g.nu;
    if (x == g.v) return g.nv;
    if (const Real* hit = n_memo_.find(g.piece, x)) return *hit;
    ++evaluations_;
    return n_memo_.put(g.piece, x, gamma_ + w_.value(g.piece, x));
  }
  Value antiderivative(const Segment& g, const Real& x) {
    if (x == g.u) return g.Wu;
    if (x == g.v) return g.Wv;
    if (const Real* hit = w_memo_.find(g.piece, x)) return *hit;
    ++evaluations_;
    return w_memo_.put(g.piece, x, w_.antiderivative(g.piece, x));
  }
  Value dn(const Segment& g, const Real& x) {
    if (!g.contact) return zero();
    if (x == g.u) return g.dnu;
    if (x == g.v) return g.dnv;
    if (const Real* hit = dn_memo_.find(g.piece, x)) return *hit;
    ++evaluations_;
    return dn_memo_.put(g.piece, x, w_.slope(g.piece, x));
  }

  // Ramp of the current stick phase at phase x of a segment shifted by `shift` periods (0 or 1):
  // level + β·((x − a) + (shift − a_shift)). Phases stay piece-local: x − a is exact-ish within a
  // period, and the shift difference is an integer. Evaluated in place, with the same roundings:
  // each multiprecision temporary is an allocation.
  Real ramp(const Real& x, int shift) const {
    if constexpr (std::is_floating_point_v<Real>) {
      return level_ + beta_ * ((x - a_) + (shift - a_shift_));
    } else {
      Real r = x - a_;
      if (shift != a_shift_) r += shift - a_shift_;
      r *= beta_;
      r += level_;
      return r;
    }
  }

  void sweep_segment(const Segment& g, bool wrapped) {
    const int shift = wrapped ? 1 : 0;
    Real pos = g.u;
    const Real n_u = n(g, g.u);
    if (!sticking_) {
      if (g.jump && n_u > s_) open_stick(g.u, shift, s_, value_bound());  // upward jump of n
    } else if (n_u <= ramp(g.u, shift)) {
      close_stick(g.u, shift);  // n jumps below (or touches) the ramp
    }
    const bool convex = !g.contact || g.convex;
    // Facts of exact arithmetic that rounding must not undo near a tangency (β ≈ β_c):
    // a stick that begins by n' ≥ β on a convex segment cannot end on it (n − ramp has a
    // non-decreasing slope from ≥ 0), and after a stick ends on a concave or linear segment n'
    // stays below β there, so no new one begins.
    bool ended_here = false;
    for (int round = 0;; ++round) {
      if (round > 4)
        throw SolverError("no progress on the segment [" + short_str(g.u) + ", " + short_str(g.v) + "] of piece " +
                          std::to_string(g.piece) + " at phase " + short_str(pos));
      bool onset_here = false;
      if (!sticking_) {
        // Slip: s = n until n' exceeds β (Eq. 4); n' is monotone on the segment.
        if (!convex && ended_here) {
          add_slip(g, pos, g.v);
          s_ = n(g, g.v);
          return;
        }
        if (dn(g, pos) > beta_) {
          const Real level = n(g, pos);
          open_stick(pos, shift, level, onset_bound(g, pos, level));
        } else if (convex && dn(g, g.v) > beta_) {
          const Real t = slope_root(g, pos, g.v);
          add_slip(g, pos, t);
          pos = t;
          open_stick(pos, shift, n(g, pos), value_bound(g.piece));
        } else {
          add_slip(g, pos, g.v);
          s_ = n(g, g.v);
          return;
        }
        onset_here = true;
      }
      // Stick: the ramp ends where n falls back onto it (Eq. 8).
      Real t;
      if (!(convex && onset_here) && stick_end(g, pos, shift, convex, t)) {
        add_stick(g, pos, t, shift);
        close_stick(t, shift);
        s_ = n(g, t);
        pos = t;
        ended_here = true;
        continue;
      }
      add_stick(g, pos, g.v, shift);
      return;
    }
  }

  // First t in (p0, v] with n(t) ≤ ramp(t), if any. d = n − ramp has d' = n' − β monotone.
  bool stick_end(const Segment& g, const Real& p0, int shift, bool convex, Real& t) {
    auto d = [&](const Real& x) -> Real { return n(g, x) - ramp(x, shift); };
    auto dd = [&](const Real& x) -> Real { return dn(g, x) - beta_; };
    const Real& v = g.v;
    if (!(v > p0)) return false;
    const Real dv = d(v);
    const bool linear = !g.contact || g.linear;
    if (linear) {
      if (dv > 0) return false;
      // d is linear here: interpolate between the ends, where d(p0) > 0 ≥ d(v), so t stays in
      // the bracket even when n' equals β to rounding (then d0/(β − n') would divide by ~0).
      const Real d0 = d(p0);
      t = d0 <= 0 ? p0 : Real(p0 + (v - p0) * (d0 / (d0 - dv)));
      if (t > v) t = v;
      ++events_;
      return true;
    }
    const Real dd0 = dd(p0);
    Real lo = p0, hi = v, dlo, dhi = dv;
    if (convex) {
      // d convex: decreasing up to the zero of d' (if any), then increasing.
      if (dd0 >= 0) return false;
      const Real ddv = dd(v);
      if (ddv > 0) {
        hi = slope_root(g, p0, v);
        dhi = d(hi);
      }
      if (dhi > 0) return false;
      dlo = d(lo);
    } else {
      // d concave: increasing up to the zero of d', then decreasing; d > 0 just after p0.
      if (dv > 0) return false;
      if (dd0 > 0) {
        const Real ddv = dd(v);
        lo = ddv >= 0 ? v : slope_root(g, p0, v);
      }
      dlo = d(lo);
      if (dlo < 0 && lo > p0) {
        // d(lo) ≥ d(p0) ≥ 0 in exact arithmetic; rounding near a tangency: end at lo.
        dlo = 0;
      }
    }
    ++events_;
    t = stick_end_root(g, shift, lo, hi, dlo, dhi);
    return true;
  }

  // Eq. 8 on [lo, hi] where d = n − ramp changes sign monotonically.
  // - Types no wider than double: toms748 on the bracket, or Newton from a neighbouring spring's
  //   end inside it (the curved row's continuation: 0.76–0.82 of a curved solve's instructions).
  // - Wider types: a double root from the waveform's shadow, then Newton at the working
  //   precision. long double too: from the double guess it needs fewer x87 sin-cos evaluations
  //   than toms748 from the bracket (measured: the long double sine solve 2.97 -> 1.80 us).
  Real stick_end_root(const Segment& g, int shift, const Real& lo, const Real& hi, const Real& dlo, const Real& dhi) {
    auto d = [&](const Real& x) -> Real { return n(g, x) - ramp(x, shift); };
    // Newton asks for d and d' at the same phase: evaluate n and n' together, remember both.
    auto d_joint = [&](const Real& x) -> Real {
      if (!g.contact || n_memo_.find(g.piece, x)) return d(x);
      auto [v, sl] = w_.value_and_slope(g.piece, x);
      evaluations_ += 2;
      n_memo_.put(g.piece, x, gamma_ + v);
      dn_memo_.put(g.piece, x, std::move(sl));
      return d(x);
    };
    // d is a difference of values of size |γ| + |w| ≤ |γ| + 2 and of the ramp: its rounding.
    auto noise = [&]() -> Real {
      using std::abs;
      return 8 * std::numeric_limits<Real>::epsilon() * (abs(gamma_) + 2 + abs(level_) + beta_);
    };
    if constexpr (std::numeric_limits<Real>::digits <= std::numeric_limits<double>::digits) {
      // A guess inside the bracket: Newton, safeguarded by the bracket (d changes sign on it
      // monotonically, so the root it converges to is this stick's end, whatever the guess).
      if (guesses_ && g.contact)
        for (const Real& e : *guesses_)
          for (const Real x : {e, Real(e - 1)})
            if (x > lo && x < hi)
              return polished_root<Real>(d_joint, [&](const Real& y) -> Real { return dn(g, y) - beta_; }, lo, hi, dlo,
                                         dhi, x, noise(), "stick end (Eq. 8)", stats_);
      return bracketed_root<Real>(d, lo, hi, dlo, dhi, "stick end (Eq. 8)", stats_);
    } else {
      const double g_ = static_cast<double>(gamma_), b_ = static_cast<double>(beta_);
      const double lvl = static_cast<double>(level_), a0 = static_cast<double>(a_), sh = shift - a_shift_;
      auto dd = [&](double x) { return g_ + w_.approx_value(g.piece, x) - (lvl + b_ * ((x - a0) + sh)); };
      const double l = static_cast<double>(lo), h = static_cast<double>(hi);
      double guess = (l + h) / 2;
      const double fl = dd(l), fh = dd(h);
      if ((fl > 0) != (fh > 0)) {
        std::uintmax_t it = 100;
        const auto r = boost::math::tools::toms748_solve(dd, l, h, fl, fh, boost::math::tools::eps_tolerance<double>(), it);
        guess = (r.first + r.second) / 2;
      }
      // d = w − βx + k: the wave may refine the guess at reduced precision first
      // (Waveform::coarse_ramp_root); a guess it moved out of the bracket is replaced there.
      Real x0(guess);
      if (g.contact && coarse_steps_pay<Real>()) w_.coarse_ramp_root(g.piece, x0, beta_, Real(gamma_ - level_ + beta_ * (a_ - (shift - a_shift_))));
      return polished_root<Real>(d_joint, [&](const Real& x) -> Real { return dn(g, x) - beta_; }, lo, hi, dlo, dhi,
                                 std::move(x0), noise(), "stick end (Eq. 8)", stats_);
    }
  }

  // Zero of n' − β on [lo, hi], where n' crosses β monotonically (Eq. 4, and the top of
  // n − ramp on a concave segment): the waveform's closed form if it has one, else toms748.
  Real slope_root(const Segment& g, const Real& lo, const Real& hi) {
    ++events_;
    if (auto r = w_.solve_slope(g.piece, beta_)) return *r < lo ? lo : (*r > hi ? hi : *r);
    return bracketed_root<Real>([&](const Real& x) -> Real { return dn(g, x) - beta_; }, lo, hi,
                                Real(dn(g, lo) - beta_), Real(dn(g, hi) - beta_), "n' = beta (Eq. 4)", stats_);
  }

  // `value_err`: the bound of the level as a value of n (value_bound of the anchor's piece).
  void open_stick(const Real& at, int shift, const Real& level, const Real& value_err) {
    using std::abs;
    sticking_ = true;
    a_ = at;
    a_shift_ = shift;
    level_ = level;
    // The level is a value of n; the anchor phase is rounded. At an onset by n' = β the two
    // errors cancel to first order (the ramp is tangent to n, and n' is nearly constant over the
    // phase error: Waveform::unresolved); at first contact or a jump the ramp shifts by β times
    // the phase error.
    level_err_ = value_err + beta_ * (1 + abs(at) + shift);
    ++events_;
  }
  void close_stick(const Real& at, int shift) {
    sticking_ = false;
    stick_.push_back({a_, Real(at + (shift - a_shift_)), level_});
  }

  // Rounding bounds, in eps. Event phases carry an error of about eps·(1 + |φ|), but the areas
  // are stationary in them wherever s and n are continuous (at a stick end d/dt of the retained
  // area is ramp − n = 0; at a contact boundary n = 0; pieces join continuously), so phases
  // enter only through where a ramp is anchored (open_stick). Bound of one evaluation of n = γ + w:
  Real value_bound() const { return value_bound_with(w_.value_error()); }
  // The same on piece i.
  Real value_bound(std::size_t i) const { return value_bound_with(w_.value_error(i)); }
  // |γ| + max w − min w + e, left to right.
  Real value_bound_with(const Real& e) const {
    Real b = 0;
    detail::add_abs(b, gamma_);
    b += w_.maximum();
    b -= w_.minimum();
    b += e;
    return b;
  }

  // The bound of the level of a stick that begins at pos by n' > β: value_bound, the error of n
  // there; except at first contact. There n = 0 exactly at the computed boundary, and the exact
  // wave's boundary lies within δ = value_bound/n' of it (n' > β nearly constant over δ:
  // Waveform::unresolved), which moves the ramp by β·δ only. Not within 2δ of the piece's ends:
  // the exact boundary may then lie on a neighbour with another slope (or the exact wave never
  // leaves contact there and the level is its n, off by value_bound).
  Real onset_bound(const Segment& g, const Real& pos, const Real& level) {
    const Real bound = value_bound(g.piece);
    if (level != 0) return bound;
    const Value slope = dn(g, pos);
    const Real reach = 2 * std::numeric_limits<Real>::epsilon() * bound / slope;
    if (!(pos - w_.piece_begin(g.piece) > reach) || !(w_.piece_end(g.piece) - pos > reach)) return bound;
    return bound * beta_ / slope;
  }

  // ∫ n over [p, q] of segment g, exact or by quadrature; adds its rounding bound to `err`.
  // Exact: γ·(q − p) + (W(q) − W(p)), and the bound (q − p)·value_bound + |W(q)| + |W(p)| + the
  // antiderivative's errors at q and p + |γ|·(q − p), each summed left to right (in place: the
  // same roundings as the expressions, without their multiprecision temporaries).
  Real area_n(const Segment& g, const Real& p, const Real& q, Real& err) {
    if (!g.contact || !(q > p)) return Real(0);
    const Real width = q - p;
    Real t = value_bound(g.piece);
    t *= width;
    err += t;
    if (method_ == AreaMethod::exact) {
      Real wq = antiderivative(g, q);
      const Value wp = antiderivative(g, p);  // no put into the memo below
      Real gw = gamma_;
      gw *= width;
      Real bound = 0;
      detail::add_abs(bound, wq);
      detail::add_abs(bound, wp);
      bound += w_.antiderivative_error(g.piece, q, wq);
      bound += w_.antiderivative_error(g.piece, p, wp);
      detail::add_abs(bound, gw);  // |γ·(q − p)| = |γ|·(q − p): rounding to nearest is symmetric
      err += bound;
      wq -= wp;
      gw += wq;
      return gw;
    }
    return quad([&](const Real& x) -> Real { return n(g, x); }, p, q, err);
  }

  template <class F>
  Real quad(F f, const Real& p, const Real& q, Real& err_bound) {
    ++quadratures_;
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real tol = opt_.quadrature_tolerance > 0 ? Real(opt_.quadrature_tolerance) : Real(sqrt(eps));
    Real err = 0, l1 = 0;
    std::size_t levels = 0;
    Real value;
    try {
      value = integrator<Real>(opt_.max_quadrature_levels).integrate(f, p, q, tol, &err, &l1, &levels);
    } catch (const std::exception& e) {
      throw SolverError(std::string("tanh-sinh quadrature failed: ") + e.what());
    }
    if (!(err <= tol * l1) && l1 > 0)
      throw SolverError("tanh-sinh quadrature did not converge on [" + short_str(p) + ", " +
                        short_str(q) + "]: error estimate " + short_str(err) + " after " +
                        std::to_string(levels) + " levels");
    // tanh-sinh: rounding of the weighted sum, plus the estimate (which overstates the error
    // of the last level: convergence is doubly exponential).
    err_bound += 4 * l1 + err / eps;
    return value;
  }

  // sum += a, compensated (Kahan: `carry` keeps the low part each addition loses), and its
  // rounding into err. Plain recursive summation errs by up to eps/2 of every partial sum, about
  // (number of segments)/2 times the area: beyond the bound on a record of hundreds of pieces at
  // large γ. Compensated, the sum errs by at most 2u·Σ|a| + O(M u²)·Σ|a| (Higham, Accuracy and
  // Stability of Numerical Algorithms, §4.3): eps·|a| per segment.
  static void accumulate(Real& sum, Real& carry, const Real& a, Real& err) {
    Real y = a;
    y -= carry;
    Real t = sum;
    t += y;
    carry = t;
    carry -= sum;
    carry -= y;
    sum = std::move(t);
    detail::add_abs(err, a);
  }

  void add_slip(const Segment& g, const Real& p, const Real& q) {
    Real err = 0;
    const Real a = area_n(g, p, q, err);
    err_normal_ += err;
    err_retained_ += err;
    accumulate(normal_, normal_carry_, a, err_normal_);
    accumulate(retained_, retained_carry_, a, err_retained_);
  }
  void add_stick(const Segment& g, const Real& p, const Real& q, int shift) {
    if (!(q > p)) return;
    // The ramp's area (q − p)·(r(p) + r(q))/2 and its bound (q − p)·(|r(p)| + |r(q)| + the level's
    // bound): rounding of its values, and the uncertainty of where it is anchored. In place, as
    // in area_n.
    const Real width = q - p;
    const Real rp = ramp(p, shift), rq = ramp(q, shift);
    Real r = rp + rq;
    r *= width;
    r /= 2;
    Real ramp_err = 0;
    detail::add_abs(ramp_err, rp);
    detail::add_abs(ramp_err, rq);
    ramp_err += level_err_;
    ramp_err *= width;
    err_retained_ += ramp_err;
    accumulate(retained_, retained_carry_, r, err_retained_);
    Real err = 0;
    if (method_ == AreaMethod::exact || !g.contact) {
      Real a = area_n(g, p, q, err);
      err_normal_ += err;
      accumulate(normal_, normal_carry_, a, err_normal_);
      a -= r;
      err += ramp_err;
      err_lost_ += err;
      accumulate(lost_, lost_carry_, a, err_lost_);
    } else {
      const Real a = area_n(g, p, q, err);
      err_normal_ += err;
      accumulate(normal_, normal_carry_, a, err_normal_);
      Real lerr = 0;
      const Real l = quad([&](const Real& x) -> Real { return n(g, x) - ramp(x, shift); }, p, q, lerr);
      lerr += ramp_err;
      lerr += err;
      err_lost_ += lerr;
      accumulate(lost_, lost_carry_, l, err_lost_);
    }
  }

  const Contact<Real>& c_;
  const Waveform<Real>& w_;
  Real beta_, gamma_;
  Options opt_;
  const std::vector<Real>* guesses_;
  AreaMethod method_;
  RootStats stats_;
  bool sticking_ = false;
  Real s_ = 0, a_ = 0, level_ = 0;
  int a_shift_ = 0;
  Real retained_ = 0, normal_ = 0, lost_ = 0;
  Real retained_carry_ = 0, normal_carry_ = 0, lost_carry_ = 0;  // accumulate's compensations
  Memo n_memo_, dn_memo_, w_memo_;
  const Real zero_ = 0;
  Real err_retained_ = 0, err_normal_ = 0, err_lost_ = 0, level_err_ = 0;
  std::vector<StickPhase<Real>> stick_;
  std::size_t events_ = 0, quadratures_ = 0, evaluations_ = 0;
};

template <class Real>
std::string context(const Waveform<Real>& w, const Real& beta, const Real* gamma) {
  std::string s = "wave " + w.name() + ", beta = " + short_str(beta);
  if (gamma) s += ", gamma = " + short_str(*gamma);
  return s;
}

template <class Real>
void check_beta(const Waveform<Real>& w, const Real& beta) {
  using std::isfinite;
  if (!(beta > 0) || !isfinite(beta))
    throw InputError("beta = " + short_str(beta) + " for wave " + w.name() + ": expected a finite number > 0");
  if (const std::string why = w.unresolved(); !why.empty()) throw PrecisionError("wave " + w.name() + ": " + why);
}

// The one message for γ without contact (γ + max w ≤ 0), γ as the caller has it (as typed, or the
// number) and the bound on γ as text.
inline DomainError no_contact(const std::string& gamma, const std::string& wave, const std::string& bound) {
  return DomainError("gamma = " + gamma + " gives no contact for wave " + wave + ": expected gamma > " + bound);
}

// γ finite (InputError) with contact (γ + max w > 0, else DomainError): the check of make_contact
// and solve_curved.
template <class Real>
void check_contact(const Waveform<Real>& w, const Real& gamma) {
  using std::isfinite;
  if (!isfinite(gamma)) throw InputError("gamma = " + short_str(gamma) + ": expected a finite number");
  if (!(gamma + w.maximum() > 0)) throw no_contact(short_str(gamma), w.name(), short_str(Real(-w.maximum())));
}

}  // namespace detail

// The Contact of (w, γ) after checking γ: finite, and contact exists (γ + max w > 0; γ ≤ −1
// for the catalogue is a DomainError). Throws SolverError if a contact boundary cannot be found.
template <class Real>
Contact<Real> make_contact(const Waveform<Real>& w, const Real& gamma, const Options& opt = {}) {
  detail::check_contact(w, gamma);
  try {
    return Contact<Real>(w, gamma, opt);
  } catch (const SolverError& e) {
    throw SolverError("wave " + w.name() + ", gamma = " + detail::short_str(gamma) + ": " + e.what());
  }
}

// μ̄/μ0 = g_w(β, γ) with diagnostics, for a Contact built once per γ (a sweep over β reuses
// it). Precondition: β > 0 finite. β ≥ β_c(γ) gives exactly 1 (Eq. 6). Throws SolverError,
// naming wave, β and γ, if an event cannot be bracketed or a root finder or integrator does not
// converge.
template <class Real>
Result<Real> solve(const Contact<Real>& contact, const Real& beta, const Options& opt = {}) {
  detail::check_beta(contact.wave(), beta);
  try {
    return detail::EventPass<Real>(contact, beta, opt).run();
  } catch (const SolverError& e) {
    throw SolverError(detail::context(contact.wave(), beta, &contact.gamma()) + ": " + e.what());
  }
}

namespace detail {
// solve() with guesses of the stick ends (EventPass; a spring row's neighbour, curved.hpp).
template <class Real>
Result<Real> solve_near(const Contact<Real>& contact, const Real& beta, const Options& opt,
                        const std::vector<Real>& guesses) {
  check_beta(contact.wave(), beta);
  try {
    return EventPass<Real>(contact, beta, opt, &guesses).run();
  } catch (const SolverError& e) {
    throw SolverError(context(contact.wave(), beta, &contact.gamma()) + ": " + e.what());
  }
}
}  // namespace detail

// The same from (w, β, γ): make_contact's checks on γ, then solve.
template <class Real>
Result<Real> solve(const Waveform<Real>& w, const Real& beta, const Real& gamma, const Options& opt = {}) {
  detail::check_beta(w, beta);
  return solve(make_contact(w, gamma, opt), beta, opt);
}

// Ψ_w(β) = ∫(n − s) without jumping (Eq. 12), computed at γ = −min w (n touches zero), where
// it holds for every γ ≥ −min w (Eq. 13). The value is lost_area of the result.
template <class Real>
Result<Real> psi(const Waveform<Real>& w, const Real& beta, const Options& opt = {}) {
  detail::check_beta(w, beta);
  const Real gamma = -w.minimum();
  try {
    const Contact<Real> contact(w, gamma, opt);
    return detail::EventPass<Real>(contact, beta, opt).run();
  } catch (const SolverError& e) {
    throw SolverError(detail::context<Real>(w, beta, nullptr) + ": " + e.what());
  }
}

// s(φ) of a solved state, for φ ∈ [0, 1): on a stick phase the ramp, elsewhere n (model.md).
// At a stick's onset its level, as w takes the value after a jump there: a stick out of zero at
// an upward jump of n starts at s = 0, not at n.
template <class Real>
Real tangential_force(const Waveform<Real>& w, const Result<Real>& r, const Real& beta,
                      const Real& gamma, const Real& phi) {
  for (const auto& st : r.stick_phases) {
    for (int k = 0; k < 2; ++k) {
      const Real x = phi + k;
      if (x >= st.begin && x < st.end) return st.level + beta * (x - st.begin);
    }
  }
  const Real v = gamma + w(phi);
  return v > 0 ? v : Real(0);
}

// The solver is compiled once per number type of the API, in lib/core/src/flat/solver_<type>.cpp
// (explicit instantiation definitions); every other translation unit sees these declarations
// and links to that copy instead of instantiating its own ([temp.explicit]). Other types are
// instantiated where they are used, as before.
#define VIBROFRIC_SOLVER_INSTANCES(EXTERN, Real)                                                          \
  EXTERN template Contact<Real> make_contact<Real>(const Waveform<Real>&, const Real&, const Options&);    \
  EXTERN template Result<Real> solve<Real>(const Contact<Real>&, const Real&, const Options&);             \
  EXTERN template Result<Real> solve<Real>(const Waveform<Real>&, const Real&, const Real&, const Options&); \
  EXTERN template Result<Real> psi<Real>(const Waveform<Real>&, const Real&, const Options&);

VIBROFRIC_SOLVER_INSTANCES(extern, double)
VIBROFRIC_SOLVER_INSTANCES(extern, long double)
VIBROFRIC_SOLVER_INSTANCES(extern, bin50)
VIBROFRIC_SOLVER_INSTANCES(extern, bin100)
VIBROFRIC_SOLVER_INSTANCES(extern, mpfr)

}  // namespace vibrofric
