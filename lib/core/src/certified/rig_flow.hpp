// The proven rig state's arithmetic (rig_enclosure.cpp; core/certified/rig_enclosure.hpp): values
// with their derivatives along the section's (Y, Y') in intervals, the wave on its pieces (model.md's
// catalogue) and the closed-form motion of each mode between events (model.md, "Rig dynamics"; the
// rig solver's motion.hpp, here on intervals). Private to src/certified/.
#pragma once
#include <algorithm>
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "vibrofric/core/certified/rig_enclosure.hpp"
#include "vibrofric/core/detail/roots.hpp"

namespace vibrofric::certified::rig_detail {

using exact::Rational;

// A value with its derivatives with respect to the section's (Y, Y'), all enclosed.
struct D {
  Interval v, d0, d1;
  explicit D(const Interval& x) : v(x), d0(x.precision()), d1(x.precision()) {}
  D(Interval x, Interval a, Interval b) : v(std::move(x)), d0(std::move(a)), d1(std::move(b)) {}
};
inline D operator+(const D& a, const D& b) { return {a.v + b.v, a.d0 + b.d0, a.d1 + b.d1}; }
inline D operator-(const D& a, const D& b) { return {a.v - b.v, a.d0 - b.d0, a.d1 - b.d1}; }
inline D operator-(const D& a) { return {-a.v, -a.d0, -a.d1}; }
inline D operator*(const D& a, const D& b) { return {a.v * b.v, a.d0 * b.v + a.v * b.d0, a.d1 * b.v + a.v * b.d1}; }
inline D operator+(const D& a, const Interval& b) { return {a.v + b, a.d0, a.d1}; }
inline D operator-(const D& a, const Interval& b) { return {a.v - b, a.d0, a.d1}; }
inline D operator*(const D& a, const Interval& b) { return {a.v * b, a.d0 * b, a.d1 * b}; }
inline D operator*(const Interval& b, const D& a) { return a * b; }
inline D operator/(const D& a, const Interval& b) { return {a.v / b, a.d0 / b, a.d1 / b}; }
inline D exp(const D& a) {
  Interval e = exp(a.v);
  return {e, e * a.d0, e * a.d1};
}
inline std::pair<D, D> sin_cos(const D& a) {
  auto [s, c] = sin_cos(a.v);
  D sd{s, c * a.d0, c * a.d1}, cd{c, -s * a.d0, -s * a.d1};
  return {std::move(sd), std::move(cd)};
}

inline const Interval& val(const Interval& x) { return x; }
inline const Interval& val(const D& x) { return x.v; }
template <class T>
T cst(const Interval& x) {
  if constexpr (std::is_same_v<T, D>)
    return D(x);
  else
    return x;
}

inline Interval point(const mpfr& x, mpfr_prec_t bits) { return Interval::exact(x, bits); }
inline std::string phase_text(const mpfr& x) { return detail::short_str(x); }

// The homogeneous motion of y'' + c y' + K y = 0: its kind fixed exactly from the inputs.
struct Oscillator {
  Interval c, K, h, m2, root;
  int kind;  // −1 underdamped, 0 critical, +1 overdamped
};

enum class Guard { upper, lower, forward, backward };  // s − n, −s − n, −X_c', X_c'

// The wave on its pieces: w = p0 + p1 (φ − origin) + Σ_k a_k cos ν_k φ + b_k sin ν_k φ, the
// harmonics the same on every piece (the sine and the Fourier series: one piece, p0 = p1 = 0; the
// piecewise-linear waves: no harmonics). origin is the piece's start, shifted by the period
// where the walk meets it a period on.
struct Harmonic {
  unsigned k;
  Interval nu, a, b;
  Interval P, Q;  // the slip oscillator's response to ω²(a cos + b sin): P cos + Q sin
  bool resonant = false;  // ζ = 0 and Ω²κ = k² exactly: the response is φ (P cos + Q sin)
};
struct Piece {
  Rational x;  // start in [0, 1) (piecewise linear; 0 otherwise)
  Interval p0, p1;
  // a piecewise-linear wave's piece exactly: its end, w's left limit at x, w(x⁺) and the slope
  Rational end, left, right, slope;
};
struct Place {
  std::size_t piece;
  Interval origin;
};

struct Model {
  mpfr_prec_t bits;
  Interval beta, gamma, two_pi, omega2;
  Oscillator stick, slip;
  std::vector<Piece> pieces;
  std::vector<Harmonic> harmonics;
  bool smooth;  // one piece, harmonics only

  Model(const RigWaveInput& wave, const RigPoint& p, mpfr_prec_t b)
      : bits(b), beta(Interval::rational(p.beta.backend().data(), b)),
        gamma(Interval::rational(p.gamma.backend().data(), b)), two_pi(Interval::pi(b) * 2), omega2(b),
        stick{Interval(b), Interval(b), Interval(b), Interval(b), Interval(b), 0},
        slip{Interval(b), Interval(b), Interval(b), Interval(b), Interval(b), 0},
        smooth(wave.kind != RigWaveInput::Kind::piecewise_linear) {
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
    if (smooth) {
      pieces.push_back({Rational(0), Interval(b), Interval(b), Rational(1), Rational(0), Rational(0), Rational(0)});
      if (wave.kind == RigWaveInput::Kind::sine) {
        harmonics.push_back({1, two_pi, Interval(b), Interval::integer(1, b), Interval(b), Interval(b)});
      } else {
        series(wave.series);
      }
      const Rational o2k = p.omega * p.omega * p.kappa;
      for (Harmonic& h : harmonics) {
        if (p.zeta == 0 && o2k == Rational(h.k) * h.k) {
          // y'' + ν²y = ω²(a cos νφ + b sin νφ): y = φ (P cos νφ + Q sin νφ), P = −ω²b/(2ν), Q = ω²a/(2ν)
          h.resonant = true;
          const Interval two_nu = h.nu * Interval::integer(2, b);
          h.P = -(omega2 * h.b) / two_nu;
          h.Q = omega2 * h.a / two_nu;
          continue;
        }
        // y'' + cy' + Ky = ω²(a cos νφ + b sin νφ): P = ω²(d a − e b)/Δ, Q = ω²(e a + d b)/Δ,
        // d = K − ν², e = cν, Δ = d² + e².
        const Interval d = slip.K - h.nu * h.nu, e = c * h.nu, delta = d * d + e * e;
        if (delta.sign() != Sign::positive)
          throw Undecided("rig certificate: the slip oscillator's resonance with harmonic " + std::to_string(h.k) +
                          " is not excluded at " + std::to_string(b) + " bits");
        h.P = omega2 * (d * h.a - e * h.b) / delta;
        h.Q = omega2 * (e * h.a + d * h.b) / delta;
      }
    } else {
      const auto& v = wave.piecewise.vertices;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const Rational x1 = i + 1 < v.size() ? v[i + 1].x : Rational(1);
        const Rational left1 = i + 1 < v.size() ? v[i + 1].left : v[0].left;
        const Rational slope = (left1 - v[i].right) / (x1 - v[i].x);
        pieces.push_back({v[i].x, Interval::rational(v[i].right.backend().data(), b),
                          Interval::rational(slope.backend().data(), b), x1, v[i].left, v[i].right, slope});
      }
    }
  }

  // n, n', n'' at φ on a placed piece (in contact: γ + w).
  template <class T>
  std::array<T, 3> normal(const T& phi, const Place& at) const {
    const Piece& pc = pieces[at.piece];
    T n = (phi - at.origin) * pc.p1 + pc.p0 + gamma;
    T dn = cst<T>(pc.p1), ddn = cst<T>(Interval(bits));
    for (const Harmonic& h : harmonics) {
      auto [s, c] = sin_cos(T(phi * h.nu));
      n = n + (c * h.a + s * h.b);
      dn = dn + (c * h.b - s * h.a) * h.nu;
      ddn = ddn - (c * h.a + s * h.b) * (h.nu * h.nu);
    }
    return {std::move(n), std::move(dn), std::move(ddn)};
  }
  // ∫_a^b n dφ on a placed piece.
  Interval normal_integral(const Interval& a, const Interval& b, const Place& at) const {
    const Piece& pc = pieces[at.piece];
    const Interval da = a - at.origin, db = b - at.origin;
    Interval r = (gamma + pc.p0) * (b - a) + pc.p1 * (db * db - da * da) / Interval::integer(2, bits);
    for (const Harmonic& h : harmonics) {
      auto [sa, ca] = sin_cos(a * h.nu);
      auto [sb, cb] = sin_cos(b * h.nu);
      r += (h.a * (sb - sa) - h.b * (cb - ca)) / h.nu;
    }
    return r;
  }

 private:
  // A Fourier series normalised as the solver's FourierSeries: the mean (k = 0) dropped, then
  // divided by S = (max u − min u)/2, the extrema enclosed at the roots of u' (each simple).
  void series(const std::vector<RationalHarmonic>& raw) {
    const mpfr_prec_t b = bits;
    std::vector<Harmonic> hs;
    for (const RationalHarmonic& r : raw) {
      if (r.k == 0) continue;
      auto it = std::find_if(hs.begin(), hs.end(), [&](const Harmonic& h) { return h.k == r.k; });
      if (it == hs.end()) {
        hs.push_back({r.k, two_pi * Interval::integer(r.k, b), Interval(b), Interval(b), Interval(b), Interval(b)});
        it = hs.end() - 1;
      }
      it->a += Interval::rational(r.a.backend().data(), b);
      it->b += Interval::rational(r.b.backend().data(), b);
    }
    unsigned kmax = 0;
    for (const Harmonic& h : hs) kmax = std::max(kmax, h.k);
    if (kmax == 0) throw InputError("rig certificate: a Fourier series without a harmonic k >= 1");
    // u and its first two derivatives at φ
    auto u = [&](const Interval& phi, int order) {
      Interval r(b);
      for (const Harmonic& h : hs) {
        auto [s, c] = sin_cos(phi * h.nu);
        if (order == 0) r += c * h.a + s * h.b;
        if (order == 1) r += (c * h.b - s * h.a) * h.nu;
        if (order == 2) r -= (c * h.a + s * h.b) * (h.nu * h.nu);
        if (order == 3) r -= (c * h.b - s * h.a) * (h.nu * h.nu * h.nu);
      }
      return r;
    };
    const auto extrema = periodic_roots([&](const Interval& x, int o) { return u(x, o + 1); }, kmax, b,
                                        "an extremum of the Fourier series");
    if (extrema.empty()) throw SolverError("rig certificate: the Fourier series has no extrema");
    std::optional<Interval> hi, lo;
    for (const Interval& x : extrema) {
      const Interval v = u(x, 0);
      hi = hi ? Interval::hull(std::max(hi->lower(), v.lower()), std::max(hi->upper(), v.upper()), b) : v;
      lo = lo ? Interval::hull(std::min(lo->lower(), v.lower()), std::min(lo->upper(), v.upper()), b) : v;
    }
    const Interval scale = (*hi - *lo) / Interval::integer(2, b);
    if (scale.sign() != Sign::positive) throw Undecided("rig certificate: the Fourier series' range is not resolved");
    for (Harmonic& h : hs) {
      h.a = h.a / scale;
      h.b = h.b / scale;
      if (!(h.a.sign() == Sign::zero && h.b.sign() == Sign::zero)) harmonics.push_back(h);
    }
  }

 public:
  // The simple roots over one period of a 1-periodic smooth f (f(x, 0), its derivative f(x, 1))
  // whose fastest harmonic is kmax: cells of 1/(32 kmax) (offset by 1/7 of a cell, so that no
  // rational root with a small denominator falls on a cell end), each with no root (f certainly nonzero) or
  // one (f' certainly nonzero, a certain sign change), bisected; Undecided where f touches zero.
  template <class F>
  static std::vector<Interval> periodic_roots(F f, unsigned kmax, mpfr_prec_t b, const std::string& what) {
    std::vector<Interval> out;
    long budget = 200000;
    // cell j is [(7j − 6)/(7N), (7j + 1)/(7N)], j = 0 … N − 1: each end computed from its integers,
    // so the N cells meet and cover one period exactly, whatever the rounding
    const long cells = 32 * static_cast<long>(kmax);
    const auto end = [&](long j) { return mpfr(mpfr(7 * j - 6) / (7 * cells)); };
    std::function<void(const mpfr&, const mpfr&, int)> scan = [&](const mpfr& lo, const mpfr& hi, int depth) {
      const Interval X = Interval::hull(lo, hi, b);
      const Interval fx = f(X, 0);
      if (fx.sign() == Sign::positive || fx.sign() == Sign::negative) return;
      const Interval d = f(X, 1);
      if (d.sign() == Sign::positive || d.sign() == Sign::negative) {
        const Sign a = f(point(lo, b), 0).sign(), z = f(point(hi, b), 0).sign();
        if ((a == Sign::positive || a == Sign::negative) && (z == Sign::positive || z == Sign::negative)) {
          if (a == z) return;  // monotone without a sign change
          Interval R = X;
          for (int k = 0; k < 400; ++k) {
            const Interval M = point(R.midpoint(), b);
            auto next = intersection(R, M - f(M, 0) / f(R, 1));
            if (!next) throw SolverError("rig certificate: interval Newton lost " + what);
            const bool shrank = next->width() < R.width() / 2;
            R = *next;
            if (!shrank) break;
          }
          out.push_back(R);
          return;
        }
      }
      if (depth >= 50 || --budget < 0)
        throw Undecided("rig certificate: " + what + " near phase " + phase_text(lo) + " is not a simple root");
      const mpfr mid = (lo + hi) / 2;
      scan(lo, mid, depth + 1);
      scan(mid, hi, depth + 1);
    };
    for (long j = 0; j < cells; ++j) scan(end(j), end(j + 1), 0);
    // The cells span [−6/(7N), 1 − 6/(7N)), so each root is found once; one certainly
    // below 0 is taken a period on. A root at 0 itself (the sine at γ = 0) keeps its enclosure
    // about 0: the walk places every boundary by comparison with the section.
    std::vector<Interval> reduced;
    for (Interval& r : out) {
      if (r.upper() < 0) r = r + Interval::integer(1, b);
      reduced.push_back(r);
    }
    std::sort(reduced.begin(), reduced.end(), [](const Interval& a, const Interval& c) { return a.upper() < c.lower(); });
    return reduced;
  }
};

// The closed-form motion of one mode from (a, Y, Y', s) on a placed piece (motion.hpp's, on
// intervals).
template <class T>
class Flow {
 public:
  Flow(const Model& m, ContactMode mode, const Place& at, T a, const T& y, const T& v, T s)
      : m_(m), mode_(mode), at_(at), a_(std::move(a)), y_(y), s_(std::move(s)),
        o_(mode == ContactMode::stick ? &m.stick : &m.slip), q0_(cst<T>(Interval(m.bits))), q1_(m.bits),
        f0_(cst<T>(Interval(m.bits))), f1_(m.bits), y0h_(cst<T>(Interval(m.bits))), w_(cst<T>(Interval(m.bits))) {
    const Interval& K = o_->K;
    if (mode == ContactMode::stick) {
      f0_ = (s_ - y) * (-m.omega2);
      f1_ = -(m.omega2 * m.beta);
    } else if (mode != ContactMode::flight) {
      // F = σω² n: its line part σω²(γ + p0 + p1 (φ − origin)) about a
      const Piece& pc = m.pieces[at.piece];
      const Interval sw = m.omega2 * Interval::integer(sign(), m.bits);
      f0_ = ((a_ - at.origin) * pc.p1 + pc.p0 + m.gamma) * sw;
      f1_ = pc.p1 * sw;
    }
    q1_ = f1_ / K;
    q0_ = (f0_ - o_->c * q1_) / K;
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
    if (mode_ == ContactMode::stick) return s_ + (y - y_) + m_.beta * (phi - a_);
    if (mode_ == ContactMode::flight) return cst<T>(Interval(m_.bits));
    return m_.normal(phi, at_)[0] * Interval::integer(-sign(), m_.bits);
  }
  // g, g', g'' of a guard at φ (g'' only for the stick's guards).
  std::array<T, 3> guard(Guard g, const T& phi) const {
    const auto yv = at(phi);
    const auto n = m_.normal(phi, at_);
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
    if (mode_ == ContactMode::flight) return Interval(m_.bits);
    if (mode_ != ContactMode::stick) {
      const Interval in = m_.normal_integral(val(a_), b, at_);
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
  long sign() const { return mode_ == ContactMode::forward_slip ? -1 : 1; }
  std::array<T, 2> particular(const T& phi) const {
    std::array<T, 2> r{q0_ + q1_ * (phi - a_), cst<T>(q1_)};
    if (mode_ == ContactMode::stick || mode_ == ContactMode::flight) return r;
    const Interval sg = Interval::integer(sign(), m_.bits);
    for (const Harmonic& h : m_.harmonics) {
      auto [s, c] = sin_cos(T(phi * h.nu));
      const T y = (c * h.P + s * h.Q) * sg, dy = (c * h.Q - s * h.P) * (h.nu * sg);
      if (h.resonant) {  // φ y, y + φ y'
        r[0] = r[0] + phi * y;
        r[1] = r[1] + y + phi * dy;
      } else {
        r[0] = r[0] + y;
        r[1] = r[1] + dy;
      }
    }
    return r;
  }
  T force(const T& phi, const T& t) const {
    if (mode_ == ContactMode::stick) return f0_ + f1_ * t;
    if (mode_ == ContactMode::flight) return cst<T>(Interval(m_.bits));
    return m_.normal(phi, at_)[0] * (m_.omega2 * Interval::integer(sign(), m_.bits));
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
  ContactMode mode_;
  Place at_;
  T a_, y_, s_;
  const Oscillator* o_;
  T q0_;
  Interval q1_;
  T f0_;
  Interval f1_;
  T y0h_, w_;
};

}  // namespace vibrofric::certified::rig_detail
