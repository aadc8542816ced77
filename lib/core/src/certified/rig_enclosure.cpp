// A proven periodic state of the rig for the sine wave (core/certified/rig_enclosure.hpp).
#include "vibrofric/core/certified/rig_enclosure.hpp"

#include <algorithm>
#include <functional>
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
      pieces.push_back({Rational(0), Interval(b), Interval(b)});
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
                          Interval::rational(slope.backend().data(), b)});
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
  // The simple roots in [0, 1) of a 1-periodic smooth f (f(x, 0), its derivative f(x, 1)) whose
  // fastest harmonic is kmax: cells of 1/(32 kmax) (offset by 1/7 of a cell, so that no rational
  // root with a small denominator falls on a cell end), each with no root (f certainly nonzero) or
  // one (f' certainly nonzero, a certain sign change), bisected; Undecided where f touches zero.
  template <class F>
  static std::vector<Interval> periodic_roots(F f, unsigned kmax, mpfr_prec_t b, const std::string& what) {
    std::vector<Interval> out;
    long budget = 200000;
    const mpfr cell = mpfr(1) / (32 * static_cast<long>(kmax));
    const mpfr offset = cell / 7;
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
    for (mpfr x = offset - cell; x < 1 + offset - cell; x += cell) scan(x, mpfr(x + cell), 0);
    // the cells span [offset − cell, offset − cell + 1]: roots reduced into [0, 1), once each
    std::vector<Interval> reduced;
    for (Interval& r : out) {
      if (r.upper() < 0) r = r + Interval::integer(1, b);
      if (!(r.lower() >= 0 && r.upper() < 1)) {
        if (r.lower() < 0 || r.upper() >= 1) throw Undecided("rig certificate: " + what + " at the period's start");
      }
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
  Flow(const Model& m, RigMode mode, const Place& at, T a, const T& y, const T& v, T s)
      : m_(m), mode_(mode), at_(at), a_(std::move(a)), y_(y), s_(std::move(s)),
        o_(mode == RigMode::stick ? &m.stick : &m.slip), q0_(cst<T>(Interval(m.bits))), q1_(m.bits),
        f0_(cst<T>(Interval(m.bits))), f1_(m.bits), y0h_(cst<T>(Interval(m.bits))), w_(cst<T>(Interval(m.bits))) {
    const Interval& K = o_->K;
    if (mode == RigMode::stick) {
      f0_ = (s_ - y) * (-m.omega2);
      f1_ = -(m.omega2 * m.beta);
    } else if (mode != RigMode::flight) {
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
    if (mode_ == RigMode::stick) return s_ + (y - y_) + m_.beta * (phi - a_);
    if (mode_ == RigMode::flight) return cst<T>(Interval(m_.bits));
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
    if (mode_ == RigMode::flight) return Interval(m_.bits);
    if (mode_ != RigMode::stick) {
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
  long sign() const { return mode_ == RigMode::forward_slip ? -1 : 1; }
  std::array<T, 2> particular(const T& phi) const {
    std::array<T, 2> r{q0_ + q1_ * (phi - a_), cst<T>(q1_)};
    if (mode_ == RigMode::stick || mode_ == RigMode::flight) return r;
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
    if (mode_ == RigMode::stick) return f0_ + f1_ * t;
    if (mode_ == RigMode::flight) return cst<T>(Interval(m_.bits));
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
  RigMode mode_;
  Place at_;
  T a_, y_, s_;
  const Oscillator* o_;
  T q0_;
  Interval q1_;
  T f0_;
  Interval f1_;
  T y0h_, w_;
};

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
  RigMode mode;
  T a, y, v, s;
  std::array<int, 2> order{0, 0};  // the order to which the stick's guards (upper, lower) vanish at a
  Interval area, stick, slip, backward, flight;
  std::size_t events = 0;
};

class Certifier {
 public:
  Certifier(const RigWaveInput& wave, const RigPoint& p, const mpfr& section, mpfr_prec_t bits)
      : m_(wave, p, bits), section_(section), gamma_(p.gamma), normal_area_(bits) {
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
      const auto& v = wave.piecewise.vertices;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const Rational x1 = i + 1 < v.size() ? v[i + 1].x : Rational(1);
        const Rational left1 = i + 1 < v.size() ? v[i + 1].left : v[0].left;
        const Rational slope = (left1 - v[i].right) / (x1 - v[i].x);
        const Rational g0 = p.gamma + v[i].right, gl = p.gamma + v[i].left;
        const Rational n_plus = std::max(g0, Rational(0)), n_minus = std::max(gl, Rational(0));
        const bool touch = g0 == 0 && slope > 0;
        period.push_back({{Interval::rational(v[i].x.backend().data(), b), place(i), g0 > 0 || touch, touch,
                           n_plus > n_minus ? 1 : n_plus < n_minus ? -1 : 0,
                           Interval::rational(n_plus.backend().data(), b)},
                          v[i].x});
        if (v[i].x <= s0) first = i;
        // a contact boundary inside the piece
        if (slope != 0) {
          const Rational r = v[i].x - g0 / slope;
          if (r > v[i].x && r < x1)
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
  Walk<T> period(RigMode mode, const T& y, const T& v) const {
    const mpfr_prec_t b = m_.bits;
    evaluations_ = 0;
    Walk<T> w{mode, cst<T>(point(section_, b)), y, v, cst<T>(Interval(b)), {0, 0},
              Interval(b), Interval(b), Interval(b), Interval(b), Interval(b), 0};
    Place here = start_;
    const Interval n0 = m_.normal(point(section_, b), here)[0];
    if (mode == RigMode::flight) {
      if (n0.sign() != Sign::negative)
        throw SolverError("rig certificate: the section " + phase_text(section_) + " is not certainly in flight");
    } else {
      if (n0.sign() != Sign::positive)
        throw SolverError("rig certificate: the section " + phase_text(section_) + " is not certainly in contact");
      w.s = cst<T>(mode == RigMode::forward_slip ? n0 : -n0);
    }
    for (const Boundary& target : bounds_) {
      for (std::size_t guard = 0;; ++guard) {
        if (guard > 100000) throw Undecided("rig certificate: more than 100000 events in one period");
        if (w.mode == RigMode::flight) {
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
        const RigMode before = w.mode;
        advance(w, flow, at);
        ++w.events;
        const T n = m_.normal(w.a, here)[0];
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
      w.mode = RigMode::flight;
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
        w.mode = RigMode::stick;
        w.order = {1, 1};
      } else if (positive(xdot - dn)) {
        w.mode = RigMode::forward_slip;
      } else if (negative(xdot + dn)) {
        w.mode = RigMode::backward_slip;
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
        w.mode = upper ? RigMode::forward_slip : RigMode::backward_slip;
      } else if (upper ? negative(rel) : positive(rel)) {
        w.mode = RigMode::stick;
        w.order = upper ? std::array<int, 2>{1, 0} : std::array<int, 2>{0, 1};
      } else {
        throw undecided("slip or stick after a kink or a jump of n");
      }
    };
    switch (w.mode) {
      case RigMode::flight:  // an upward jump out of the air: the contact re-forms stress-free and sticks
        w.mode = RigMode::stick;
        w.s = cst<T>(Interval(b));
        return;
      case RigMode::forward_slip:
      case RigMode::backward_slip:
        // s = ±n⁻ exactly: the jump's sign decides
        if (at.jump > 0) {
          w.mode = RigMode::stick;  // an upward jump ends slip; |s| < n⁺
          return;
        }
        on_boundary(w.mode == RigMode::forward_slip);
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
  Rational gamma_;
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
  if (seed.mode == RigMode::stick) throw SolverError("rig certificate: the section must lie in slip or flight");
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
