// A proven periodic state of the rig (core/certified/rig_enclosure.hpp): the walk over a period from
// the section (events, boundaries, areas) and the Krawczyk test. The arithmetic: rig_flow.hpp.
#include "vibrofric/core/certified/rig_enclosure.hpp"

#include <algorithm>
#include <functional>
#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "rig_flow.hpp"

namespace vibrofric::certified {
namespace {

using namespace rig_detail;
using exact::Rational;


// A phase of the period where n changes its law: a vertex of a piecewise-linear wave (a kink or a
// jump of n), or a contact boundary (n leaves 0 or reaches it inside a piece).
struct Boundary {
  Interval phi;
  Place after;         // the piece that follows
  bool contact;        // in contact just after
  bool touch;          // n = 0 just after, rising: the touch-down rule
  int jump;            // sign of n⁺ − n⁻, exact
  Interval n_after;    // n⁺
  bool end = false;    // the period's end (no rule)
};

template <class T>
struct Walk {
  ContactMode mode;
  T a, y, v, s;
  std::array<int, 2> order{0, 0};  // the order to which the stick's guards (upper, lower) vanish at a
  Interval area, stick, slip, backward, flight;
  std::size_t events = 0;
};

class Certifier {
 public:
  Certifier(const RigWaveInput& wave, const RigPoint& p, const mpfr& section, mpfr_prec_t bits)
      : m_(wave, p, bits), section_(section), normal_area_(bits) {
    const mpfr_prec_t b = bits;
    mpq_t q;
    mpq_init(q);
    mpfr_get_q(q, section.backend().data());
    const Rational s0(q);
    mpq_clear(q);
    // The boundaries in [0, 1), each with the piece after it at its own start (origin).
    std::vector<std::pair<Boundary, std::optional<Rational>>> period;
    const auto place = [&](std::size_t i) { return Place{i, Interval::rational(m_.pieces[i].x.backend().data(), b)}; };
    std::size_t first = 0;  // the piece holding the section
    if (m_.smooth) {
      // contact boundaries: the simple roots of γ + w (Undecided where n touches zero)
      unsigned kmax = 1;
      for (const Harmonic& h : m_.harmonics) kmax = std::max(kmax, h.k);
      const Place whole{0, Interval(b)};
      const auto roots = Model::periodic_roots(
          [&](const Interval& x, int o) { return m_.normal(x, whole)[static_cast<std::size_t>(o)]; }, kmax, b,
          "a contact boundary (gamma + w = 0)");
      for (const Interval& r : roots) {
        const bool rising = m_.normal(r, whole)[1].sign() == Sign::positive;
        period.push_back({{r, whole, rising, rising, 0, Interval(b)}, std::nullopt});
      }
    } else {
      for (std::size_t i = 0; i < m_.pieces.size(); ++i) {
        const Piece& pc = m_.pieces[i];
        const Rational &x1 = pc.end, &slope = pc.slope;
        const Rational g0 = p.gamma + pc.right, gl = p.gamma + pc.left;
        const Rational n_plus = std::max(g0, Rational(0)), n_minus = std::max(gl, Rational(0));
        const bool touch = g0 == 0 && slope > 0;
        period.push_back({{Interval::rational(pc.x.backend().data(), b), place(i), g0 > 0 || touch, touch,
                           n_plus > n_minus ? 1 : n_plus < n_minus ? -1 : 0,
                           Interval::rational(n_plus.backend().data(), b)},
                          pc.x});
        if (pc.x <= s0) first = i;
        // a contact boundary inside the piece
        if (slope != 0) {
          const Rational r = pc.x - g0 / slope;
          if (r > pc.x && r < x1)
            period.push_back({{Interval::rational(r.backend().data(), b), place(i), slope > 0, slope > 0, 0, Interval(b)}, r});
        }
      }
    }
    // ∫n over the period: the contact segments between consecutive boundaries.
    std::sort(period.begin(), period.end(), [&](const auto& a, const auto& c) {
      if (a.second && c.second) return *a.second < *c.second;
      return compare(a.first.phi, c.first.phi) == Sign::negative;
    });
    if (period.empty()) {
      normal_area_ = m_.gamma;  // a smooth wave in contact all period: ∫ of its harmonics is 0
    } else {
      for (std::size_t j = 0; j < period.size(); ++j) {
        const Boundary& bj = period[j].first;
        if (!bj.contact) continue;
        const Interval to = j + 1 < period.size() ? period[j + 1].first.phi : period[0].first.phi + Interval::integer(1, b);
        normal_area_ += m_.normal_integral(bj.phi, to, bj.after);
      }
    }
    // In the window (φ0, φ0 + 1]: a boundary before the section a period on.
    start_ = m_.smooth ? Place{0, Interval(b)} : place(first);
    const Interval sp = point(section_, b);
    for (auto& [bd, exact_phase] : period) {
      const Sign c = exact_phase ? (*exact_phase > s0 ? Sign::positive : *exact_phase < s0 ? Sign::negative : Sign::zero)
                                 : compare(bd.phi, sp);
      if (c == Sign::undecided || c == Sign::zero)
        throw Undecided("rig certificate: the section phase " + phase_text(section_) + " meets a boundary of n");
      if (c == Sign::negative) {
        bd.phi = bd.phi + Interval::integer(1, b);
        bd.after.origin = bd.after.origin + Interval::integer(1, b);
      }
      bounds_.push_back(bd);
    }
    std::sort(bounds_.begin(), bounds_.end(), [](const Boundary& a, const Boundary& c) { return a.phi.upper() < c.phi.lower(); });
    for (std::size_t j = 1; j < bounds_.size(); ++j)
      if (compare(bounds_[j - 1].phi, bounds_[j].phi) != Sign::negative)
        throw Undecided("rig certificate: two boundaries of n are not separated");
    Boundary end{point(mpfr(section + 1), b), start_, false, false, 0, Interval(b), true};
    end.after.origin = end.after.origin + Interval::integer(1, b);
    bounds_.push_back(end);
  }

  const Model& model() const { return m_; }
  const Interval& normal_area() const { return normal_area_; }

  // One period from the section, mode `mode`, the state (y, v) at φ0.
  template <class T>
  Walk<T> period(ContactMode mode, const T& y, const T& v) const {
    const mpfr_prec_t b = m_.bits;
    evaluations_ = 0;
    Walk<T> w{mode, cst<T>(point(section_, b)), y, v, cst<T>(Interval(b)), {0, 0},
              Interval(b), Interval(b), Interval(b), Interval(b), Interval(b), 0};
    Place here = start_;
    const Interval n0 = m_.normal(point(section_, b), here)[0];
    if (mode == ContactMode::flight) {
      if (n0.sign() != Sign::negative)
        throw SolverError("rig certificate: the section " + phase_text(section_) + " is not certainly in flight");
    } else {
      if (n0.sign() != Sign::positive)
        throw SolverError("rig certificate: the section " + phase_text(section_) + " is not certainly in contact");
      w.s = cst<T>(mode == ContactMode::forward_slip ? n0 : -n0);
    }
    for (const Boundary& target : bounds_) {
      for (std::size_t guard = 0;; ++guard) {
        if (guard > 100000) throw Undecided("rig certificate: more than 100000 events in one period");
        if (w.mode == ContactMode::flight) {
          advance(w, Flow<T>(m_, w.mode, here, w.a, w.y, w.v, w.s), cst<T>(target.phi));
          break;
        }
        const Flow<T> flow(m_, w.mode, here, w.a, w.y, w.v, w.s);
        const Flow<Interval> fv(m_, w.mode, here, val(w.a), val(w.y), val(w.v), val(w.s));
        const auto event = first_event(w, fv, target.phi);
        if (!event) {
          advance(w, flow, cst<T>(target.phi));
          break;
        }
        const auto& [when, g] = *event;
        T at = cst<T>(when);
        if constexpr (std::is_same_v<T, D>) {
          // dT = −g_x/g_φ at the event.
          const D gx = flow.guard(g, at)[0];
          const Interval gphi = fv.guard(g, when)[1];
          at = D(when, -gx.d0 / gphi, -gx.d1 / gphi);
        }
        const ContactMode before = w.mode;
        advance(w, flow, at);
        ++w.events;
        const T n = m_.normal(w.a, here)[0];
        switch (g) {
          case Guard::upper:
            w.mode = ContactMode::forward_slip;
            w.s = n;
            break;
          case Guard::lower:
            w.mode = ContactMode::backward_slip;
            w.s = -n;
            break;
          default:
            w.mode = ContactMode::stick;
            w.s = before == ContactMode::forward_slip ? n : T(-n);
            w.order = before == ContactMode::forward_slip ? std::array<int, 2>{2, 0} : std::array<int, 2>{0, 2};
        }
      }
      if (target.end) break;
      here = target.after;
      enter(w, target);
    }
    if (w.mode != mode)
      throw SolverError("rig certificate: the mode at the section " + phase_text(section_) + " does not repeat after a period");
    return w;
  }

 private:
  // The sweeping process's rules at a boundary of n (model.md; the rig solver's enter()), each
  // decision certain or Undecided; the orders to which the stick's guards vanish just after.
  template <class T>
  void enter(Walk<T>& w, const Boundary& at) const {
    const mpfr_prec_t b = m_.bits;
    const auto undecided = [&](const char* what) {
      return Undecided(std::string("rig certificate: ") + what + " at phase " + phase_text(at.phi.midpoint()) + " is undecided");
    };
    if (!at.contact) {
      w.mode = ContactMode::flight;
      w.s = cst<T>(Interval(b));
      return;
    }
    const Interval xdot = val(w.v) + m_.beta, dn = m_.normal(at.phi, at.after)[1];
    const auto positive = [](const Interval& x) { return x.sign() == Sign::positive; };
    const auto negative = [](const Interval& x) { return x.sign() == Sign::negative; };
    if (at.touch) {
      // touch-down: the contact forms stress-free; stick if |X'| < n', else slip the way X' goes
      w.s = cst<T>(Interval(b));
      if (positive(dn - xdot) && positive(dn + xdot)) {
        w.mode = ContactMode::stick;
        w.order = {1, 1};
      } else if (positive(xdot - dn)) {
        w.mode = ContactMode::forward_slip;
      } else if (negative(xdot + dn)) {
        w.mode = ContactMode::backward_slip;
      } else {
        throw undecided("the mode at touch-down (|X'| against n')");
      }
      return;
    }
    // after a projection onto ±n⁺ (or a kink under slip): slip on where X' − n' keeps its sign
    const auto on_boundary = [&](bool upper) {
      w.s = cst<T>(upper ? at.n_after : Interval(-at.n_after));
      const Interval rel = upper ? Interval(xdot - dn) : Interval(xdot + dn);
      if (upper ? positive(rel) : negative(rel)) {
        w.mode = upper ? ContactMode::forward_slip : ContactMode::backward_slip;
      } else if (upper ? negative(rel) : positive(rel)) {
        w.mode = ContactMode::stick;
        w.order = upper ? std::array<int, 2>{1, 0} : std::array<int, 2>{0, 1};
      } else {
        throw undecided("slip or stick after a kink or a jump of n");
      }
    };
    switch (w.mode) {
      case ContactMode::flight:  // an upward jump out of the air: the contact re-forms stress-free and sticks
        w.mode = ContactMode::stick;
        w.s = cst<T>(Interval(b));
        return;
      case ContactMode::forward_slip:
      case ContactMode::backward_slip:
        // s = ±n⁻ exactly: the jump's sign decides
        if (at.jump > 0) {
          w.mode = ContactMode::stick;  // an upward jump ends slip; |s| < n⁺
          return;
        }
        on_boundary(w.mode == ContactMode::forward_slip);
        return;
      default:
        if (at.jump == 0) return;  // |s| < n on the span up to here, n continuous: stick goes on
        if (positive(val(w.s) - at.n_after)) {
          on_boundary(true);
        } else if (negative(val(w.s) + at.n_after)) {
          on_boundary(false);
        } else if (!(negative(val(w.s) - at.n_after) && positive(val(w.s) + at.n_after))) {
          throw undecided("|s| against n after a jump of n");
        }
    }
  }

  template <class T>
  void advance(Walk<T>& w, const Flow<T>& flow, const T& to) const {
    const auto yv = flow.at(to);
    const Interval t = val(to) - val(w.a);
    w.area += flow.area(val(to), val(yv[0]), val(yv[1]), val(w.v));
    switch (w.mode) {
      case ContactMode::stick: w.stick += t; break;
      case ContactMode::flight: w.flight += t; break;
      case ContactMode::backward_slip:
        w.backward += t;
        w.slip += t;
        break;
      default: w.slip += t;
    }
    w.s = flow.s_at(to, yv[0]);
    w.y = yv[0];
    w.v = yv[1];
    w.a = to;
    w.order = {0, 0};
  }

  // The first event of the current mode before `target`, with the guard that fires it.
  template <class T>
  std::optional<std::pair<Interval, Guard>> first_event(const Walk<T>& w, const Flow<Interval>& fv,
                                                        const Interval& target) const {
    if (w.mode == ContactMode::stick) {
      auto up = root(fv, Guard::upper, w.order[0], val(w.a), target);
      auto lo = root(fv, Guard::lower, w.order[1], val(w.a), target);
      if (up && lo) {
        const Sign c = compare(*up, *lo);
        if (c == Sign::undecided || c == Sign::zero)
          throw Undecided("rig certificate: two stick events at one phase near " + phase_text(up->midpoint()));
        return c == Sign::negative ? std::pair{*up, Guard::upper} : std::pair{*lo, Guard::lower};
      }
      if (up) return std::pair{*up, Guard::upper};
      if (lo) return std::pair{*lo, Guard::lower};
      return std::nullopt;
    }
    const Guard g = w.mode == ContactMode::forward_slip ? Guard::forward : Guard::backward;
    if (auto r = root(fv, g, 0, val(w.a), target)) return std::pair{*r, g};
    return std::nullopt;
  }

  // The first root of guard g in (a, target), or none where g < 0 there. `order`: g vanishes at a
  // to that order (its order-th derivative is the first shown negative just after a).
  std::optional<Interval> root(const Flow<Interval>& f, Guard g, int order, const Interval& a, const Interval& target) const {
    const mpfr_prec_t b = m_.bits;
    const mpfr a_hi = a.upper(), t_lo = target.lower(), t_hi = target.upper();
    if (!(t_lo > a_hi))
      throw Undecided("rig certificate: a span starting near " + phase_text(a_hi) + " meets its end");
    const mpfr len = mpfr(t_lo - a_hi);
    mpfr delta = len / 64;
    bool clear = false;
    for (int k = 0; k < 200 && !clear; ++k) {
      const Interval H = Interval::hull(a.lower(), mpfr(a_hi + delta), b);
      clear = f.guard(g, H)[static_cast<std::size_t>(order)].sign() == Sign::negative;
      if (!clear) delta /= 2;
    }
    if (!clear)
      throw Undecided("rig certificate: the guard at the start of the span near " + phase_text(a_hi) + " is undecided");
    // Cells no wider than 1/16 of the fastest oscillation.
    mpfr fastest = m_.two_pi.upper();
    for (const Harmonic& h : m_.harmonics) fastest = std::max(fastest, h.nu.upper());
    const mpfr rate = mpfr(m_.stick.root.upper() + m_.stick.h.upper() + fastest);
    const mpfr cell = std::min(mpfr(len / 8), mpfr(m_.two_pi.upper() / rate / 16));
    // A cell shown negative whole doubles the next (a fast body's stick far from slip is cleared
    // in a few wide cells, as the solver's stride does); one that needed bisection halves it.
    mpfr x = a_hi + delta, step = cell;
    while (x < t_hi) {
      mpfr next = x + step;
      if (!(next < t_hi) || mpfr(t_hi - next) < cell / 1024) next = t_hi;
      const long before = splits_;
      if (auto r = scan(f, g, x, next, 0)) {
        if (compare(*r, target) != Sign::negative)
          throw Undecided("rig certificate: an event meets a contact boundary near " + phase_text(t_lo));
        return r;
      }
      step = splits_ == before ? mpfr(std::min(mpfr(step * 2), len)) : mpfr(std::max(mpfr(step / 2), cell));
      x = next;
    }
    return std::nullopt;
  }

  // g < 0 on [lo, hi] (none), or its first root there, bisecting up to 60 times.
  std::optional<Interval> scan(const Flow<Interval>& f, Guard g, const mpfr& lo, const mpfr& hi, int depth) const {
    const mpfr_prec_t b = m_.bits;
    const Interval X = Interval::hull(lo, hi, b);
    const auto gx = f.guard(g, X);
    if (gx[0].sign() == Sign::negative) return std::nullopt;
    const Interval M = point(mpfr((lo + hi) / 2), b);
    const Interval mean = f.guard(g, M)[0] + gx[1] * (X - M);
    if (mean.sign() == Sign::negative) return std::nullopt;
    if (gx[1].sign() == Sign::positive && f.guard(g, point(lo, b))[0].sign() == Sign::negative &&
        f.guard(g, point(hi, b))[0].sign() == Sign::positive)
      return newton(f, g, X);
    if (depth >= 60 || ++evaluations_ > 200000)
      throw Undecided("rig certificate: a guard grazes zero near phase " + phase_text(lo) + " (no certain sign)");
    ++splits_;
    const mpfr mid = (lo + hi) / 2;
    if (auto r = scan(f, g, lo, mid, depth + 1)) return r;
    return scan(f, g, mid, hi, depth + 1);
  }

  // The one root in X (g' > 0 on X, a sign change at its ends), narrowed by interval Newton.
  Interval newton(const Flow<Interval>& f, Guard g, Interval X) const {
    for (int k = 0; k < 400; ++k) {
      const Interval M = point(X.midpoint(), m_.bits);
      const Interval N = M - f.guard(g, M)[0] / f.guard(g, X)[1];
      auto next = intersection(X, N);
      if (!next) throw SolverError("rig certificate: interval Newton lost the event near " + phase_text(M.midpoint()));
      const bool shrank = next->width() < X.width() / 2;
      X = *next;
      if (!shrank) break;
    }
    return X;
  }

  Model m_;
  mpfr section_;
  Interval normal_area_;
  Place start_{0, Interval(m_.bits)};
  std::vector<Boundary> bounds_;
  mutable long evaluations_ = 0;  // of scan, a period: bisection near a grazing guard is bounded
  mutable long splits_ = 0;       // bisections by scan (the cell size's feedback)
};

// A 2×2 interval matrix (the section map's Jacobian).
using Mat = std::array<std::array<Interval, 2>, 2>;

}  // namespace

RigEnclosure enclose_rig(const RigWaveInput& wave, const RigPoint& p, const RigSeed& seed, mpfr_prec_t bits) {
  // Phases and radii as mpfr at the enclosure's precision (they enter the intervals exactly).
  PrecisionScope scope(static_cast<unsigned>(bits * 0.30103) + 10);
  if (wave.kind == RigWaveInput::Kind::sine && p.gamma == 1)
    throw InputError("rig certificate: gamma = 1 (n touches zero at one instant of the period) is not certified");
  if (wave.kind == RigWaveInput::Kind::piecewise_linear) exact::check(wave.piecewise);
  if (seed.mode == ContactMode::stick) throw SolverError("rig certificate: the section must lie in slip or flight");
  const Certifier cert(wave, p, seed.section, bits);
  const Model& m = cert.model();
  const mpfr_prec_t b = bits;
  const Interval yh = point(seed.y, b), vh = point(seed.v, b);
  // The map at the seed itself (a thin start).
  const Walk<Interval> at_seed = cert.period(seed.mode, yh, vh);
  using std::abs;
  const mpfr residual = std::max(mpfr(abs(mpfr((at_seed.y - yh).midpoint())) + (at_seed.y - yh).width()),
                                 mpfr(abs(mpfr((at_seed.v - vh).midpoint())) + (at_seed.v - vh).width()));
  const Interval one = Interval::integer(1, b);
  auto jacobian = [&](const Walk<D>& w) {
    return Mat{{{w.y.d0, w.y.d1}, {w.v.d0, w.v.d1}}};
  };
  // Krawczyk: K = x̂ − C(P(x̂) − x̂) + (I − C(J(X) − I))(X − x̂) ⊂ int X, C ≈ (J − I)⁻¹; f = P(x̂) − x̂,
  // (dy, dv) = X − x̂.
  auto krawczyk = [&](const Mat& J, const Interval& y0, const Interval& v0, const Interval& f0, const Interval& f1,
                      const Interval& dy, const Interval& dv) {
    const mpfr a00 = mpfr(J[0][0].midpoint() - 1), a01 = J[0][1].midpoint(), a10 = J[1][0].midpoint(),
               a11 = mpfr(J[1][1].midpoint() - 1);
    const mpfr det = a00 * a11 - a01 * a10;
    if (det == 0) throw Undecided("rig certificate: the one-period map's Jacobian has a multiplier 1");
    const Interval c00 = point(mpfr(a11 / det), b), c01 = point(mpfr(-a01 / det), b), c10 = point(mpfr(-a10 / det), b),
                   c11 = point(mpfr(a00 / det), b);
    const Interval A00 = J[0][0] - one, A01 = J[0][1], A10 = J[1][0], A11 = J[1][1] - one;
    const Interval B00 = one - (c00 * A00 + c01 * A10), B01 = -(c00 * A01 + c01 * A11),
                   B10 = -(c10 * A00 + c11 * A10), B11 = one - (c10 * A01 + c11 * A11);
    return std::pair{Interval(y0 - (c00 * f0 + c01 * f1) + B00 * dy + B01 * dv),
                     Interval(v0 - (c10 * f0 + c11 * f1) + B10 * dy + B11 * dv)};
  };
  // Y' varies on the scale of the body's frequency 2πΩ.
  const mpfr scale_v = std::max(mpfr(1), mpfr((m.two_pi * Interval::rational(p.omega.backend().data(), b)).upper()));
  mpfr r0 = std::max(mpfr(residual * 1024), mpfr(ldexp(mpfr(1), -static_cast<int>(bits / 2))));
  std::optional<std::pair<Interval, Interval>> box;
  std::string why;
  for (int attempt : {0, 8, -8, 16, -16, 32}) {
    const mpfr r = ldexp(r0, attempt);
    const Interval ry = Interval::hull(mpfr(-r), r, b), rv = Interval::hull(mpfr(-r * scale_v), mpfr(r * scale_v), b);
    const Interval Y = yh + ry, V = vh + rv;
    std::optional<Walk<D>> w;
    try {
      w.emplace(cert.period(seed.mode, D(Y, one, Interval(b)), D(V, Interval(b), one)));
    } catch (const SolverError& e) {  // a box too wide for the walk's decisions: a smaller one may do
      why = e.what();
      continue;
    }
    const auto [Ky, Kv] = krawczyk(jacobian(*w), yh, vh, at_seed.y - yh, at_seed.v - vh, ry, rv);
    if (mpfi_is_strictly_inside(Ky.data(), Y.data()) > 0 && mpfi_is_strictly_inside(Kv.data(), V.data()) > 0) {
      box.emplace(Ky, Kv);
      break;
    }
    why = "the Krawczyk box does not contract";
  }
  if (!box) throw Undecided("rig certificate: no periodic state proven at " + std::to_string(bits) + " bits (" + why + ")");
  // Every fixed point in X lies in K(X), for any centre in X: narrow the box by Krawczyk steps
  // about its midpoint while they halve it (the first step's radius was chosen for existence).
  for (int k = 0; k < 4; ++k) {
    const Interval Y = box->first, V = box->second;
    const Interval ym = point(Y.midpoint(), b), vm = point(V.midpoint(), b);
    const Walk<Interval> at_mid = cert.period(seed.mode, ym, vm);
    const Walk<D> w = cert.period(seed.mode, D(Y, one, Interval(b)), D(V, Interval(b), one));
    const auto [Ky, Kv] = krawczyk(jacobian(w), ym, vm, at_mid.y - ym, at_mid.v - vm, Y - ym, V - vm);
    auto ny = intersection(Ky, Y), nv = intersection(Kv, V);
    if (!ny || !nv) throw SolverError("rig certificate: a Krawczyk step left the proven box");
    const bool halved = ny->width() < Y.width() / 2 || nv->width() < V.width() / 2;
    box.emplace(*ny, *nv);
    if (!halved) break;
  }
  // On the proven box: the enclosures.
  const Walk<D> w = cert.period(seed.mode, D(box->first, one, Interval(b)), D(box->second, Interval(b), one));
  RigEnclosure out(b);
  out.y = box->first;
  out.v = box->second;
  out.retained_area = w.area;
  out.normal_area = cert.normal_area();
  out.mu = w.area / cert.normal_area();
  out.stick_fraction = w.stick;
  out.slip_fraction = w.slip;
  out.backward_fraction = w.backward;
  out.flight_fraction = w.flight;
  out.events = w.events;
  const Mat J = jacobian(w);
  out.trace = J[0][0] + J[1][1];
  out.determinant = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const Interval disc = out.trace * out.trace - out.determinant * Interval::integer(4, b);
  const Interval two = Interval::integer(2, b);
  if (disc.sign() == Sign::negative) {
    out.multiplier = sqrt(out.determinant);  // a complex pair: |λ|² = det
  } else if (disc.sign() == Sign::positive) {
    out.multiplier = (abs(out.trace) + sqrt(disc)) / two;
  } else {
    // real or complex undecided: |λ| ≤ max(√|det|, (|tr| + √max(disc, 0))/2)
    const Interval pos = Interval::hull(mpfr(0), std::max(mpfr(0), disc.upper()), b);
    const mpfr hi = std::max(sqrt(abs(out.determinant)).upper(), ((abs(out.trace) + sqrt(pos)) / two).upper());
    out.multiplier = Interval::hull(mpfr(0), hi, b);
  }
  out.stable = (one - out.multiplier).sign() == Sign::positive;
  return out;
}

RigEnclosure enclose_rig_sine(const RigPoint& p, const RigSeed& seed, mpfr_prec_t bits) {
  return enclose_rig(RigWaveInput{RigWaveInput::Kind::sine, {}, {}}, p, seed, bits);
}

}  // namespace vibrofric::certified
