// A proven periodic state of the rig for the sine wave (core/certified/rig_enclosure.hpp).
#include "vibrofric/core/certified/rig_enclosure.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vibrofric::certified {
namespace {

using exact::Rational;

// A value with its derivatives with respect to the section's (Y, Y'), all enclosed.
struct D {
  Interval v, d0, d1;
  explicit D(const Interval& x) : v(x), d0(x.precision()), d1(x.precision()) {}
  D(Interval x, Interval a, Interval b) : v(std::move(x)), d0(std::move(a)), d1(std::move(b)) {}
};
D operator+(const D& a, const D& b) { return {a.v + b.v, a.d0 + b.d0, a.d1 + b.d1}; }
D operator-(const D& a, const D& b) { return {a.v - b.v, a.d0 - b.d0, a.d1 - b.d1}; }
D operator-(const D& a) { return {-a.v, -a.d0, -a.d1}; }
D operator*(const D& a, const D& b) { return {a.v * b.v, a.d0 * b.v + a.v * b.d0, a.d1 * b.v + a.v * b.d1}; }
D operator+(const D& a, const Interval& b) { return {a.v + b, a.d0, a.d1}; }
D operator-(const D& a, const Interval& b) { return {a.v - b, a.d0, a.d1}; }
D operator*(const D& a, const Interval& b) { return {a.v * b, a.d0 * b, a.d1 * b}; }
D operator*(const Interval& b, const D& a) { return a * b; }
D operator/(const D& a, const Interval& b) { return {a.v / b, a.d0 / b, a.d1 / b}; }
D exp(const D& a) {
  Interval e = exp(a.v);
  return {e, e * a.d0, e * a.d1};
}
std::pair<D, D> sin_cos(const D& a) {
  auto [s, c] = sin_cos(a.v);
  D sd{s, c * a.d0, c * a.d1}, cd{c, -s * a.d0, -s * a.d1};
  return {std::move(sd), std::move(cd)};
}

const Interval& val(const Interval& x) { return x; }
const Interval& val(const D& x) { return x.v; }
template <class T>
T cst(const Interval& x) {
  if constexpr (std::is_same_v<T, D>)
    return D(x);
  else
    return x;
}

Interval point(const mpfr& x, mpfr_prec_t bits) { return Interval::exact(x, bits); }
std::string phase_text(const mpfr& x) { return detail::short_str(x); }

// The homogeneous motion of y'' + c y' + K y = 0: its kind fixed exactly from the inputs.
struct Oscillator {
  Interval c, K, h, m2, root;
  int kind;  // −1 underdamped, 0 critical, +1 overdamped
};

enum class Guard { upper, lower, forward, backward };  // s − n, −s − n, −X_c', X_c'

struct Model {
  mpfr_prec_t bits;
  Interval beta, gamma, two_pi, nu, omega2;
  Oscillator stick, slip;
  Interval P1, Q1;  // the slip response to ω² sin νφ: P cos νφ + Q sin νφ
  Rational gamma_q;

  Model(const RigPoint& p, mpfr_prec_t b)
      : bits(b), beta(Interval::rational(p.beta.backend().data(), b)),
        gamma(Interval::rational(p.gamma.backend().data(), b)), two_pi(Interval::pi(b) * 2), nu(two_pi),
        omega2(b), stick{Interval(b), Interval(b), Interval(b), Interval(b), Interval(b), 0},
        slip{Interval(b), Interval(b), Interval(b), Interval(b), Interval(b), 0}, P1(b), Q1(b), gamma_q(p.gamma) {
    const Interval kappa = Interval::rational(p.kappa.backend().data(), b);
    const Interval omega = Interval::rational(p.omega.backend().data(), b);
    const Interval zeta = Interval::rational(p.zeta.backend().data(), b);
    const Interval w = two_pi * omega;
    omega2 = w * w;
    const Interval c = two_pi * zeta * omega * sqrt(kappa) * 2;
    // m2 = c²/4 − K = (2πΩ)²(ζ²κ − κ') with κ' = κ in slip, κ + 1 in stick: its sign exactly.
    const Rational z2k = p.zeta * p.zeta * p.kappa;
    auto make = [&](const Interval& K, const Rational& kprime) {
      Oscillator o{c, K, c / Interval::integer(2, b), Interval(b), Interval(b), 0};
      o.m2 = o.h * o.h - K;
      const Rational d = z2k - kprime;
      o.kind = d < 0 ? -1 : d > 0 ? 1 : 0;
      if (o.kind != 0 && (o.kind < 0 ? -o.m2 : o.m2).sign() != Sign::positive)
        throw Undecided("rig certificate: the damping's kind (above or below critical) is not resolved at " +
                        std::to_string(b) + " bits");
      if (o.kind < 0) o.root = sqrt(-o.m2);
      if (o.kind > 0) o.root = sqrt(o.m2);
      return o;
    };
    slip = make(omega2 * kappa, p.kappa);
    stick = make(omega2 * (kappa + Interval::integer(1, b)), Rational(p.kappa + 1));
    // y'' + cy' + Ky = ω² sin νφ: P = −e ω²/Δ, Q = d ω²/Δ, d = K − ν², e = cν, Δ = d² + e².
    const Interval d = slip.K - nu * nu, e = c * nu, delta = d * d + e * e;
    if (delta.sign() != Sign::positive)
      throw Undecided("rig certificate: the slip oscillator's resonance with the drive is not excluded at " +
                      std::to_string(b) + " bits");
    P1 = -e * omega2 / delta;
    Q1 = d * omega2 / delta;
  }

  // n, n', n'' at φ (in contact).
  template <class T>
  std::array<T, 3> normal(const T& phi) const {
    auto [s, c] = sin_cos(T(phi * nu));
    return {s + gamma, c * nu, -(s * (nu * nu))};
  }
};

// The closed-form motion of one mode from (a, Y, Y', s) (motion.hpp's, on intervals).
template <class T>
class Flow {
 public:
  Flow(const Model& m, RigMode mode, T a, const T& y, const T& v, T s)
      : m_(m), mode_(mode), a_(std::move(a)), y_(y), s_(std::move(s)),
        o_(mode == RigMode::stick ? &m.stick : &m.slip), q0_(cst<T>(Interval(m.bits))), q1_(m.bits),
        f0_(cst<T>(Interval(m.bits))), f1_(m.bits), y0h_(cst<T>(Interval(m.bits))), w_(cst<T>(Interval(m.bits))) {
    const Interval& K = o_->K;
    if (mode == RigMode::stick) {
      f0_ = (s_ - y) * (-m.omega2);
      f1_ = -(m.omega2 * m.beta);
      q1_ = f1_ / K;
      q0_ = (f0_ - o_->c * q1_) / K;
    } else if (mode != RigMode::flight) {
      q0_ = cst<T>(m.omega2 * m.gamma * Interval::integer(sign(), m.bits) / K);
    }
    const auto p = particular(a_);
    y0h_ = y - p[0];
    w_ = (v - p[1]) + o_->h * y0h_;
  }

  // Y, Y', Y'' at φ.
  std::array<T, 3> at(const T& phi) const {
    const T t = phi - a_;
    const auto p = particular(phi);
    T EC = cst<T>(Interval(m_.bits)), ES = EC;
    basis(t, EC, ES);
    const T hom = y0h_ * EC + w_ * ES;
    T y = p[0] + hom;
    T dy = p[1] - o_->h * hom + y0h_ * (o_->m2 * ES) + w_ * EC;
    T ddy = force(phi, t) - o_->c * dy - o_->K * y;
    return {std::move(y), std::move(dy), std::move(ddy)};
  }
  // s at φ where Y = y (stick: the spring; slip: ±n; flight: 0).
  T s_at(const T& phi, const T& y) const {
    if (mode_ == RigMode::stick) return s_ + (y - y_) + m_.beta * (phi - a_);
    if (mode_ == RigMode::flight) return cst<T>(Interval(m_.bits));
    return m_.normal(phi)[0] * Interval::integer(-sign(), m_.bits);
  }
  // g, g', g'' of a guard at φ (g'' only for the stick's guards).
  std::array<T, 3> guard(Guard g, const T& phi) const {
    const auto yv = at(phi);
    const auto n = m_.normal(phi);
    const T xdot = yv[1] + m_.beta;
    switch (g) {
      case Guard::upper: return {s_at(phi, yv[0]) - n[0], xdot - n[1], yv[2] - n[2]};
      case Guard::lower: return {-s_at(phi, yv[0]) - n[0], -xdot - n[1], -yv[2] - n[2]};
      case Guard::forward: return {n[1] - xdot, n[2] - yv[2], cst<T>(Interval(m_.bits))};
      default: return {xdot + n[1], yv[2] + n[2], cst<T>(Interval(m_.bits))};
    }
  }
  // ∫_a^b s dφ of this span, b, Y(b), Y'(b) given (values only).
  Interval area(const Interval& b, const Interval& yb, const Interval& vb, const Interval& v_a) const {
    const Interval t = b - val(a_);
    if (mode_ == RigMode::flight) return Interval(m_.bits);
    if (mode_ != RigMode::stick) {
      auto [sa, ca] = sin_cos(val(a_) * m_.nu);
      auto [sb, cb] = sin_cos(b * m_.nu);
      const Interval in = m_.gamma * t + (ca - cb) / m_.nu;
      return sign() < 0 ? in : -in;
    }
    // K∫Y = ∫F − [Y'] − c[Y]; s = Y + (s_a − Y_a) + β(φ − a).
    const Interval two = Interval::integer(2, m_.bits);
    const Interval iF = val(f0_) * t + f1_ * t * t / two;
    const Interval iy = (iF - (vb - v_a) - o_->c * (yb - val(y_))) / o_->K;
    return iy + (val(s_) - val(y_)) * t + m_.beta * t * t / two;
  }

 private:
  // −1 forward slip (F = −ω²n), +1 backward.
  long sign() const { return mode_ == RigMode::forward_slip ? -1 : 1; }
  std::array<T, 2> particular(const T& phi) const {
    if (mode_ == RigMode::stick) return {q0_ + q1_ * (phi - a_), cst<T>(q1_)};
    if (mode_ == RigMode::flight) return {cst<T>(Interval(m_.bits)), cst<T>(Interval(m_.bits))};
    auto [s, c] = sin_cos(T(phi * m_.nu));
    const Interval sg = Interval::integer(sign(), m_.bits);
    const Interval P = m_.P1 * sg, Q = m_.Q1 * sg;
    return {q0_ + c * P + s * Q, (c * Q - s * P) * m_.nu};
  }
  T force(const T& phi, const T& t) const {
    if (mode_ == RigMode::stick) return f0_ + f1_ * t;
    if (mode_ == RigMode::flight) return cst<T>(Interval(m_.bits));
    return m_.normal(phi)[0] * (m_.omega2 * Interval::integer(sign(), m_.bits));
  }
  // e^{−ht}C(t), e^{−ht}S(t): C(0) = 1, C'(0) = 0, S(0) = 0, S'(0) = 1 for y'' = m2 y.
  void basis(const T& t, T& EC, T& ES) const {
    const Oscillator& o = *o_;
    const T E = exp(T(-(t * o.h)));
    if (o.kind < 0) {
      auto [s, c] = sin_cos(T(t * o.root));
      EC = E * c;
      ES = E * s / o.root;
    } else if (o.kind == 0) {
      EC = E;
      ES = E * t;
    } else {
      const T ep = exp(T(t * (o.root - o.h))), em = exp(T(-(t * (o.root + o.h))));
      EC = (ep + em) / Interval::integer(2, m_.bits);
      ES = (ep - em) / (o.root * Interval::integer(2, m_.bits));
    }
  }

  const Model& m_;
  RigMode mode_;
  T a_, y_, s_;
  const Oscillator* o_;
  T q0_;
  Interval q1_;
  T f0_;
  Interval f1_;
  T y0h_, w_;
};

// A fixed phase of the period where the contact changes: contact loss or touch-down.
struct Boundary {
  Interval phi;
  bool touch;  // touch-down (else contact loss); the end of the period: neither
  bool end;
};

template <class T>
struct Walk {
  RigMode mode;
  T a, y, v, s;
  std::array<int, 2> order{0, 0};  // the order to which the stick's guards (upper, lower) vanish at a
  Interval area, stick, slip, backward, flight;
  std::size_t events = 0;
};

class Certifier {
 public:
  Certifier(const RigPoint& p, const mpfr& section, mpfr_prec_t bits) : m_(p, bits), section_(section) {
    const mpfr_prec_t b = bits;
    if (p.gamma >= 1) {
      if (p.gamma == 1)
        throw InputError("rig certificate: gamma = 1 (n touches zero at one instant of the period) is not certified");
    } else {
      // γ + sin νφ = 0: contact loss at 1/2 + asin γ/2π, touch-down at 1 − asin γ/2π (mod 1).
      const Interval as = asin(m_.gamma) / m_.two_pi;
      const Interval half = Interval::integer(1, b) / Interval::integer(2, b);
      Interval loss = half + as, touch = Interval::integer(1, b) - as;
      if (m_.gamma_q <= 0) touch = touch - Interval::integer(1, b);
      const Interval s0 = point(section, b);
      for (auto [phi, is_touch] : {std::pair{loss, false}, std::pair{touch, true}}) {
        const Sign c = compare(phi, s0);
        if (c == Sign::undecided || c == Sign::zero)
          throw Undecided("rig certificate: the section phase " + phase_text(section) + " meets a contact boundary");
        bounds_.push_back({c == Sign::positive ? phi : phi + Interval::integer(1, b), is_touch, false});
      }
      if (compare(bounds_[0].phi, bounds_[1].phi) == Sign::positive) std::swap(bounds_[0], bounds_[1]);
      // ∫n over the contact, from touch-down to loss.
      Interval from = touch, to = loss;
      if (compare(to, from) != Sign::positive) to = to + Interval::integer(1, b);
      auto [sf, cf] = sin_cos(from * m_.nu);
      auto [st, ct] = sin_cos(to * m_.nu);
      normal_area_ = m_.gamma * (to - from) + (cf - ct) / m_.nu;
    }
    if (!normal_area_) normal_area_ = m_.gamma;  // γ > 1: ∫ sin over a period is 0
    bounds_.push_back({point(mpfr(section + 1), b), false, true});
  }

  const Model& model() const { return m_; }
  const Interval& normal_area() const { return *normal_area_; }

  // One period from the section, mode `mode`, the state (y, v) at φ0.
  template <class T>
  Walk<T> period(RigMode mode, const T& y, const T& v) const {
    const mpfr_prec_t b = m_.bits;
    evaluations_ = 0;
    Walk<T> w{mode, cst<T>(point(section_, b)), y, v, cst<T>(Interval(b)), {0, 0},
              Interval(b), Interval(b), Interval(b), Interval(b), Interval(b), 0};
    if (mode == RigMode::flight) {
      if (m_.normal(point(section_, b))[0].sign() != Sign::negative)
        throw SolverError("rig certificate: the section " + phase_text(section_) + " is not certainly in flight");
    } else {
      const Interval n = m_.normal(point(section_, b))[0];
      if (n.sign() != Sign::positive)
        throw SolverError("rig certificate: the section " + phase_text(section_) + " is not certainly in contact");
      w.s = cst<T>(mode == RigMode::forward_slip ? n : -n);
    }
    for (const Boundary& target : bounds_) {
      for (std::size_t guard = 0;; ++guard) {
        if (guard > 100000) throw Undecided("rig certificate: more than 100000 events in one period");
        if (w.mode == RigMode::flight) {
          advance(w, Flow<T>(m_, w.mode, w.a, w.y, w.v, w.s), cst<T>(target.phi));
          break;
        }
        const Flow<T> flow(m_, w.mode, w.a, w.y, w.v, w.s);
        const Flow<Interval> fv(m_, w.mode, val(w.a), val(w.y), val(w.v), val(w.s));
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
        const RigMode before = w.mode;
        advance(w, flow, at);
        ++w.events;
        const T n = m_.normal(w.a)[0];
        switch (g) {
          case Guard::upper:
            w.mode = RigMode::forward_slip;
            w.s = n;
            break;
          case Guard::lower:
            w.mode = RigMode::backward_slip;
            w.s = -n;
            break;
          default:
            w.mode = RigMode::stick;
            w.s = before == RigMode::forward_slip ? n : T(-n);
            w.order = before == RigMode::forward_slip ? std::array<int, 2>{2, 0} : std::array<int, 2>{0, 2};
        }
      }
      if (target.end) break;
      if (!target.touch) {
        w.mode = RigMode::flight;
        w.s = cst<T>(Interval(b));
        continue;
      }
      // Touch-down: stick if |X'| < n', else slip the way X' goes.
      const Interval xdot = val(w.v) + m_.beta, dn = m_.normal(target.phi)[1];
      w.s = cst<T>(Interval(b));
      if ((dn - xdot).sign() == Sign::positive && (dn + xdot).sign() == Sign::positive) {
        w.mode = RigMode::stick;
        w.order = {1, 1};
      } else if ((xdot - dn).sign() == Sign::positive) {
        w.mode = RigMode::forward_slip;
      } else if ((xdot + dn).sign() == Sign::negative) {
        w.mode = RigMode::backward_slip;
      } else {
        throw Undecided("rig certificate: the mode at touch-down (phase " + phase_text(target.phi.midpoint()) +
                        ") is undecided: |X'| and n' are not separated");
      }
    }
    if (w.mode != mode)
      throw SolverError("rig certificate: the mode at the section " + phase_text(section_) + " does not repeat after a period");
    return w;
  }

 private:
  template <class T>
  void advance(Walk<T>& w, const Flow<T>& flow, const T& to) const {
    const auto yv = flow.at(to);
    const Interval t = val(to) - val(w.a);
    w.area += flow.area(val(to), val(yv[0]), val(yv[1]), val(w.v));
    switch (w.mode) {
      case RigMode::stick: w.stick += t; break;
      case RigMode::flight: w.flight += t; break;
      case RigMode::backward_slip:
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
    if (w.mode == RigMode::stick) {
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
    const Guard g = w.mode == RigMode::forward_slip ? Guard::forward : Guard::backward;
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
    const mpfr rate = mpfr((m_.stick.root.upper() + m_.stick.h.upper() + m_.nu.upper()));
    const mpfr cell = std::min(mpfr(len / 8), mpfr(m_.two_pi.upper() / rate / 16));
    mpfr x = a_hi + delta;
    while (x < t_hi) {
      mpfr next = x + cell;
      if (!(next < t_hi) || mpfr(t_hi - next) < cell / 1024) next = t_hi;
      if (auto r = scan(f, g, x, next, 0)) {
        if (compare(*r, target) != Sign::negative)
          throw Undecided("rig certificate: an event meets a contact boundary near " + phase_text(t_lo));
        return r;
      }
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
  std::vector<Boundary> bounds_;
  std::optional<Interval> normal_area_;
  mutable long evaluations_ = 0;  // of scan, a period: bisection near a grazing guard is bounded
};

// A 2×2 interval matrix (the section map's Jacobian).
using Mat = std::array<std::array<Interval, 2>, 2>;

}  // namespace

RigEnclosure enclose_rig_sine(const RigPoint& p, const RigSeed& seed, mpfr_prec_t bits) {
  // Phases and radii as mpfr at the enclosure's precision (they enter the intervals exactly).
  PrecisionScope scope(static_cast<unsigned>(bits * 0.30103) + 10);
  if (p.zeta == 0 && p.omega * p.omega * p.kappa == 1)
    throw InputError("rig certificate: the exact undamped resonance omega^2 kappa = 1 (the slip's motion grows "
                     "secularly) is not certified");
  if (seed.mode == RigMode::stick) throw SolverError("rig certificate: the section must lie in slip or flight");
  const Certifier cert(p, seed.section, bits);
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

}  // namespace vibrofric::certified
