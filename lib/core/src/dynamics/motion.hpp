// The rig's motion between events (core/dynamics/dynamics.hpp, model.md "Rig dynamics"): the wave on a
// piece as a line plus harmonics, and the closed-form solution of Y'' + cY' + KY = F on it.
#pragma once
#include <array>
#include <cmath>
#include <vector>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/waves/user_waveforms.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

namespace detail {

// The wave on one piece: w(φ) = p0 + p1 (φ − origin) + Σ_k a_k cos 2πkφ + b_k sin 2πkφ.
template <class Real>
struct WaveForm {
  Real origin = 0, p0 = 0, p1 = 0;
  const std::vector<Real>* a = nullptr;  // index k, k = 1 … size − 1
  const std::vector<Real>* b = nullptr;
};

template <class Real>
class RigWave {
 public:
  explicit RigWave(const Waveform<Real>& w) : w_(w) {
    if (auto* pl = dynamic_cast<const PiecewiseLinear<Real>*>(&w)) {
      for (std::size_t i = 0; i < w.piece_count(); ++i) {
        const auto& p = pl->piece(i);
        forms_.push_back({p.begin, p.anchor, p.slope, nullptr, nullptr});
      }
      return;
    }
    if (dynamic_cast<const Sine<Real>*>(&w)) {
      a_ = {Real(0), Real(0)};
      b_ = {Real(0), Real(1)};
    } else if (auto* f = dynamic_cast<const FourierSeries<Real>*>(&w)) {
      a_.assign(f->max_harmonic() + 1, Real(0));
      b_.assign(f->max_harmonic() + 1, Real(0));
      for (unsigned k = 1; k <= f->max_harmonic(); ++k) {
        a_[k] = f->cos_coefficient(k);
        b_[k] = f->sin_coefficient(k);
      }
    } else {
      throw InputError("rig dynamics needs the motion between events in closed form: the sine, "
                       "Fourier series and piecewise-linear waves (triangle, sawtooth, square, samples); "
                       "wave " + w.name() + " is none of them");
    }
    for (std::size_t i = 0; i < w.piece_count(); ++i) forms_.push_back({Real(0), Real(0), Real(0), &a_, &b_});
  }
  const WaveForm<Real>& form(std::size_t piece) const { return forms_[piece]; }
  unsigned harmonics() const { return a_.empty() ? 0 : static_cast<unsigned>(a_.size() - 1); }
  const Waveform<Real>& wave() const { return w_; }

 private:
  const Waveform<Real>& w_;
  std::vector<Real> a_, b_;
  std::vector<WaveForm<Real>> forms_;
};

// w and its first two derivatives from a WaveForm.
template <class Real>
std::array<Real, 3> wave_derivatives(const WaveForm<Real>& f, const Real& phi) {
  std::array<Real, 3> r{f.p0 + f.p1 * (phi - f.origin), f.p1, Real(0)};
  if (!f.a) return r;
  const Real two_pi = boost::math::constants::two_pi<Real>();
  const auto [s1, c1] = sin_cos(Real(two_pi * phi));
  Real c = c1, s = s1;
  for (std::size_t k = 1; k < f.a->size(); ++k) {
    if (k > 1) {
      const Real cn = c * c1 - s * s1;
      s = s * c1 + c * s1;
      c = cn;
    }
    const Real nu = two_pi * static_cast<unsigned>(k);
    const Real& A = (*f.a)[k];
    const Real& B = (*f.b)[k];
    if (A == 0 && B == 0) continue;
    r[0] += A * c + B * s;
    r[1] += nu * (B * c - A * s);
    r[2] -= nu * nu * (A * c + B * s);
  }
  return r;
}

// ∫_a^b w dφ from a WaveForm.
template <class Real>
Real wave_integral(const WaveForm<Real>& f, const Real& a, const Real& b) {
  const Real da = a - f.origin, db = b - f.origin;
  Real r = f.p0 * (b - a) + f.p1 * (db * db - da * da) / 2;
  if (!f.a) return r;
  const Real two_pi = boost::math::constants::two_pi<Real>();
  for (std::size_t k = 1; k < f.a->size(); ++k) {
    const Real& A = (*f.a)[k];
    const Real& B = (*f.b)[k];
    if (A == 0 && B == 0) continue;
    const Real nu = two_pi * static_cast<unsigned>(k);
    const auto [sa, ca] = sin_cos(Real(nu * a));
    const auto [sb, cb] = sin_cos(Real(nu * b));
    r += (A * (sb - sa) - B * (cb - ca)) / nu;
  }
  return r;
}

// The closed-form motion on one span: Y = Yp + Y_h, Yp = q0 + q1 (φ − a) + Σ harmonic responses.
template <class Real>
class Motion {
 public:
  // F = f0 + f1 (φ − a) + scale·(Σ_k a_k cos + b_k sin) + scale·(p0 + p1 (φ − origin)) of `form`.
  Motion(const Real& c, const Real& K, const Real& a, const Real& y, const Real& v, Real f0, Real f1,
         const WaveForm<Real>* form, const Real& scale, unsigned resonant)
      : c_(c), K_(K), a_(a) {
    if (form) {
      f0 += scale * (form->p0 + form->p1 * (a - form->origin));
      f1 += scale * form->p1;
      if (form->a) {
        const Real two_pi = boost::math::constants::two_pi<Real>();
        for (std::size_t k = 1; k < form->a->size(); ++k) {
          const Real A = scale * (*form->a)[k], B = scale * (*form->b)[k];
          if (A == 0 && B == 0) continue;
          const Real nu = two_pi * static_cast<unsigned>(k);
          Harmonic h{nu, 0, 0, false};
          if (c == 0 && resonant == k) {
            // y'' + ν²y = A cos νφ + B sin νφ: y = φ (P cos νφ + Q sin νφ), P = −B/(2ν), Q = A/(2ν).
            h.resonant = true;
            h.P = -B / (2 * nu);
            h.Q = A / (2 * nu);
          } else {
            const Real d = K - nu * nu, e = c * nu, D = d * d + e * e;
            if (D == 0) throw SolverError("rig dynamics: harmonic " + std::to_string(k) + " at resonance undecided");
            h.P = (d * A - e * B) / D;
            h.Q = (e * A + d * B) / D;
          }
          harmonics_.push_back(h);
        }
      }
    }
    q1_ = f1 / K;
    q0_ = (f0 - c * q1_) / K;
    const auto p = particular(a);
    y0_ = y - p[0];
    v0_ = v - p[1];
    h_ = c / 2;
    m2_ = h_ * h_ - K;
    using std::sqrt;
    if (m2_ < 0) root_ = sqrt(Real(-m2_));
    if (m2_ > 0) root_ = sqrt(m2_);
    f0_ = f0;
    f1_ = f1;
  }

  // Y, Y' at φ.
  std::array<Real, 2> operator()(const Real& phi) const {
    const auto p = particular(phi);
    const auto [EC, ES] = basis(Real(phi - a_));
    const Real w = v0_ + h_ * y0_;
    return {p[0] + y0_ * EC + w * ES, p[1] - h_ * (y0_ * EC + w * ES) + y0_ * m2_ * ES + w * EC};
  }
  // ∫_a^b F dφ over this span's forcing (poly and harmonics).
  Real forcing_integral(const Real& b) const {
    const Real t = b - a_;
    Real r = f0_ * t + f1_ * t * t / 2;
    for (const auto& h : harmonics_) {
      // ∫ F_k = ∫ (K − ν²)Yp_k + c Yp_k' (non-resonant) — use the response directly: F_k = Yp'' + cYp' + KYp.
      const auto ya = response(h, a_), yb = response(h, b);
      const Real iy = integral(h, a_, b);
      r += (yb[1] - ya[1]) + c_ * (yb[0] - ya[0]) + K_ * iy;
    }
    return r;
  }
  // Bounds of |Y'| and |Y''| on [φ, end of span] (φ ≤ 1): the particular solution's plus the
  // homogeneous part's, whose envelope e^{−ht} (e^{−(h−μ)t} overdamped) only decays:
  // |e^{−ht}C|, |e^{−ht}S|·max(1, ω) ≤ env; |(e^{−ht}C)'| ≤ √K·env, |(e^{−ht}S)'| ≤ √K/ω·env
  // underdamped (h·env and env critically, h·env and h/μ·env overdamped); Y_h'' = −cY_h' − KY_h.
  Real slope_bound(const Real& phi) const {
    using std::abs;
    Real b = abs(q1_);
    for (const auto& h : harmonics_) b += (abs(h.P) + abs(h.Q)) * h.nu * (h.resonant ? Real(1 + h.nu) : Real(1));
    return b + envelope(phi) * homogeneous_slope();
  }
  Real curvature_bound(const Real& phi) const {
    using std::abs;
    Real b = 0;
    for (const auto& h : harmonics_) b += (abs(h.P) + abs(h.Q)) * h.nu * (h.resonant ? Real(2 + h.nu) : h.nu);
    const Real w = abs(Real(v0_ + h_ * y0_)), y = abs(y0_);
    const Real S = m2_ < 0 && root_ > 1 ? Real(1 / root_) : Real(1);
    return b + envelope(phi) * (c_ * homogeneous_slope() + K_ * (y + w * S));
  }
  const Real& K() const { return K_; }
  const Real& c() const { return c_; }
  // The fastest angular rate in this motion (for the event grid).
  Real rate() const {
    using std::sqrt;
    Real r = sqrt(K_) + h_;
    for (const auto& h : harmonics_) r = std::max(r, h.nu);
    return r;
  }

 private:
  struct Harmonic {
    Real nu, P, Q;
    bool resonant;
  };
  std::array<Real, 2> response(const Harmonic& h, const Real& phi) const {
    const auto [s, c] = sin_cos(Real(h.nu * phi));
    const Real y = h.P * c + h.Q * s, dy = h.nu * (h.Q * c - h.P * s);
    if (!h.resonant) return {y, dy};
    return {phi * y, y + phi * dy};
  }
  // ∫_a^b of a harmonic response.
  Real integral(const Harmonic& h, const Real& a, const Real& b) const {
    const auto [sa, ca] = sin_cos(Real(h.nu * a));
    const auto [sb, cb] = sin_cos(Real(h.nu * b));
    const Real n = h.nu;
    if (!h.resonant) return (h.P * (sb - sa) - h.Q * (cb - ca)) / n;
    // ∫ φ (P cos νφ + Q sin νφ) = φ (P sin − Q cos)/ν + (P cos + Q sin)/ν²
    return (b * (h.P * sb - h.Q * cb) - a * (h.P * sa - h.Q * ca)) / n +
           (h.P * (cb - ca) + h.Q * (sb - sa)) / (n * n);
  }
  std::array<Real, 2> particular(const Real& phi) const {
    std::array<Real, 2> r{q0_ + q1_ * (phi - a_), q1_};
    for (const auto& h : harmonics_) {
      const auto y = response(h, phi);
      r[0] += y[0];
      r[1] += y[1];
    }
    return r;
  }
  // e^{−ht}·C(t), e^{−ht}·S(t) with C(0) = 1, C'(0) = 0, S(0) = 0, S'(0) = 1 for y'' = m2 y.
  std::pair<Real, Real> basis(const Real& t) const {
    using std::cos;
    using std::cosh;
    using std::exp;
    using std::sinh;
    const Real E = exp(Real(-h_ * t));
    if (m2_ < 0) {
      const auto [s, c] = sin_cos(Real(root_ * t));
      return {E * c, E * s / root_};
    }
    if (m2_ == 0) return {E, E * t};
    const Real mt = root_ * t;
    if (mt <= 1) return {E * cosh(mt), E * sinh(mt) / root_};
    // e^{(μ − h)t} with μ − h = −K/(μ + h) (no cancellation), and e^{−(μ + h)t}.
    const Real ep = exp(Real(-K_ / (root_ + h_) * t)), em = exp(Real(-(root_ + h_) * t));
    return {(ep + em) / 2, (ep - em) / (2 * root_)};
  }

  Real envelope(const Real& phi) const {
    using std::exp;
    const Real t = phi > a_ ? Real(phi - a_) : Real(0);
    if (m2_ > 0) return exp(Real(-K_ / (root_ + h_) * t));
    return exp(Real(-h_ * t));
  }
  Real homogeneous_slope() const {
    using std::abs;
    using std::sqrt;
    const Real w = abs(Real(v0_ + h_ * y0_)), y = abs(y0_);
    if (m2_ < 0) return sqrt(K_) * (y + w / root_);
    if (m2_ == 0) return h_ * y + w;
    return h_ * (y + w / root_);
  }

  Real c_, K_, a_;
  Real q0_ = 0, q1_ = 0, f0_ = 0, f1_ = 0;
  Real y0_ = 0, v0_ = 0, h_ = 0, m2_ = 0, root_ = 0;
  std::vector<Harmonic> harmonics_;
};

}  // namespace detail

}  // namespace vibrofric
