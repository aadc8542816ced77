// User waveforms for Eq. (2): a finite Fourier series and a sampled periodic signal (piecewise
// linear through the samples), both normalised to zero mean and unit amplitude (model.md).
#pragma once
#include <functional>
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vibrofric/core/escalate.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {

namespace detail {

// All roots of a smooth 1-periodic f on [0, 1), given spread(x, r) ≥ max_{|y−x| ≤ r} |f(y) − f(x)|
// (rounding included) and M ≥ max |f|. A cell [a, b] is dropped when |f(mid)| > spread(mid, r) +
// 64·eps·M with r = (b − a)/2 (then f has no zero in it, even with f's rounding); otherwise it is
// halved, down to a width of 2^-30 cells, where a sign change is refined to working precision. A
// zero of even multiplicity (no sign change) is not reported: it does not split a monotone piece.
// With a Taylor spread of order J the cells kept near a zero of multiplicity m ≤ J stay bounded
// in number per level; a Lipschitz spread (J = 1) keeps ~2^(d(1−1/m)) at depth d.
template <class Real, class F, class S>
std::vector<Real> periodic_roots(F f, S spread, const Real& magnitude, std::size_t cells, const char* what,
                                 RootStats& stats) {
  using std::abs;
  struct Cell {
    Real a, b, fa, fb;
    int depth;
  };
  constexpr int max_depth = 30;
  const Real margin = 64 * std::numeric_limits<Real>::epsilon() * magnitude;
  std::vector<Real> roots;
  std::vector<Cell> stack;
  const Real f0 = f(Real(0));
  Real xa = 0, fa = f0;
  for (std::size_t j = 1; j <= cells; ++j) {
    const Real xb = Real(j) / cells;
    const Real fb = j == cells ? f0 : f(xb);
    stack.push_back({xa, xb, fa, fb, 0});
    xa = xb;
    fa = fb;
  }
  while (!stack.empty()) {
    Cell c = stack.back();
    stack.pop_back();
    if (c.fa == 0) {
      roots.push_back(c.a);
      continue;
    }
    if (c.fb == 0) continue;  // reported by the neighbouring cell
    const Real mid = (c.a + c.b) / 2;
    const Real fm = f(mid);
    if (abs(fm) > spread(mid, Real((c.b - c.a) / 2)) + margin) continue;
    if (c.depth >= max_depth) {
      if ((c.fa > 0) != (c.fb > 0)) roots.push_back(bracketed_root<Real>(f, c.a, c.b, c.fa, c.fb, what, stats));
      continue;
    }
    stack.push_back({mid, c.b, fm, c.fb, c.depth + 1});
    stack.push_back({c.a, mid, c.fa, fm, c.depth + 1});
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace detail

// w(φ) = Σ_k a_k cos 2πkφ + b_k sin 2πkφ, k ≥ 1, after normalisation. Pieces split at the zeros
// of w' and w'' (found by detail::periodic_roots), so that w and w' are monotone on each.
template <class Real>
class FourierSeries final : public Waveform<Real> {
 public:
  // Raw coefficients: harmonic k[j] ≥ 0 with a[j], b[j]; k = 0 is the mean and is removed.
  FourierSeries(std::string name, const std::vector<unsigned>& k, const std::vector<Real>& a,
                const std::vector<Real>& b)
      : Waveform<Real>(std::move(name)) {
    Real mean = 0;
    for (std::size_t j = 0; j < k.size(); ++j) {
      if (k[j] == 0) {
        mean += a[j];
        continue;
      }
      if (k[j] > max_k_) max_k_ = k[j];
    }
    a_.assign(max_k_ + 1, Real(0));
    b_.assign(max_k_ + 1, Real(0));
    for (std::size_t j = 0; j < k.size(); ++j)
      if (k[j] != 0) {
        a_[k[j]] += a[j];
        b_[k[j]] += b[j];
      }
    bool any = false;
    for (unsigned j = 1; j <= max_k_; ++j) any = any || a_[j] != 0 || b_[j] != 0;
    if (!any) throw InputError("Fourier waveform " + this->name() + " has zero amplitude: expected a non-zero coefficient with k ≥ 1");
    // The normalisation removes the scale: bring the largest coefficient to [1/2, 1) by a power of
    // two (exact), so that the derivative bounds of the root search neither overflow (1e300 in
    // double: no cell was ever discarded) nor underflow (1e-300: no extremum found).
    Real big = 0;
    for (unsigned j = 1; j <= max_k_; ++j) {
      using std::abs;
      big = std::max(big, std::max(Real(abs(a_[j])), Real(abs(b_[j]))));
    }
    using std::frexp;
    using std::ldexp;
    int e = 0;
    frexp(big, &e);
    for (unsigned j = 1; j <= max_k_; ++j) {
      a_[j] = ldexp(a_[j], -e);
      b_[j] = ldexp(b_[j], -e);
    }

    detail::RootStats stats;
    std::vector<Real> bounds;  // of |w^(o)|, o = 0 … 7, for the root search's spread
    for (int o = 0; o < 8; ++o) bounds.push_back(bound(o));
    const auto extrema = detail::periodic_roots<Real>(
        [&](const Real& x) -> Real { return derivative(x, 1); },
        [&](const Real& x, const Real& r) -> Real { return taylor_spread(1, x, r, bounds); }, bounds[1], cells(),
        "extremum of the Fourier waveform", stats);
    const auto inflections = detail::periodic_roots<Real>(
        [&](const Real& x) -> Real { return derivative(x, 2); },
        [&](const Real& x, const Real& r) -> Real { return taylor_spread(2, x, r, bounds); }, bounds[2], cells(),
        "inflection of the Fourier waveform", stats);
    Real lo = derivative(Real(0), 0), hi = lo;
    for (const Real& x : extrema) {
      const Real v = derivative(x, 0);
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
    const Real scale = (hi - lo) / 2;
    if (!(scale > 0)) throw SolverError("Fourier waveform " + this->name() + ": no extrema found");
    for (unsigned j = 1; j <= max_k_; ++j) {
      a_[j] /= scale;
      b_[j] /= scale;
    }
    this->norm_ = {true, mean, ldexp(scale, e)};

    std::vector<Real> begins{Real(0)};
    std::vector<Real> all(extrema);
    all.insert(all.end(), inflections.begin(), inflections.end());
    std::sort(all.begin(), all.end());
    const Real gap = 64 * std::numeric_limits<Real>::epsilon();
    for (const Real& x : all)
      if (x - begins.back() > gap && 1 - x > gap) begins.push_back(x);
    this->set_pieces(std::move(begins));

    // Rounding of one evaluation (derivative()): K products and sums, and cos/sin of 2πkφ by the
    // recurrence, whose angle carries about k·(2π + 4) eps: E = Σ_k (|a_k| + |b_k|)(K + 4 + (2π + 4)k).
    // The wave in this type: coefficients rounded once (Σ(|a_k| + |b_k|)) and divided by a scale
    // read from extrema computed with error E, which scales w by up to E relative (E·max|w|).
    using std::abs;
    const Real two_pi = boost::math::constants::two_pi<Real>();
    Real eval = 0, sum = 0, integral = 0;
    for (unsigned j = 1; j <= max_k_; ++j) {
      const Real c = abs(a_[j]) + abs(b_[j]);
      const Real per = c * (max_k_ + 4 + (two_pi + 4) * j);
      sum += c;
      eval += per;
      integral += per / (two_pi * j);
    }
    const Real top = std::max(Real(abs(this->maximum())), Real(abs(this->minimum())));
    value_error_ = eval * (1 + top) + sum;
    antiderivative_error_ = integral * (1 + top) + sum;
  }

  Real value_error() const override { return value_error_; }
  Real antiderivative_error(std::size_t, const Real&, const Real&) const override { return antiderivative_error_; }
  Real value(std::size_t, const Real& phi) const override { return derivative(phi, 0); }
  Real slope(std::size_t, const Real& phi) const override { return derivative(phi, 1); }
  bool has_antiderivative() const override { return true; }
  Real antiderivative(std::size_t, const Real& phi) const override { return derivative(phi, -1); }
  unsigned max_harmonic() const { return max_k_; }
  // w = Σ_k a_k cos 2πkφ + b_k sin 2πkφ, k = 1 … max_harmonic() (normalised).
  const Real& cos_coefficient(unsigned k) const { return a_[k]; }
  const Real& sin_coefficient(unsigned k) const { return b_[k]; }

 private:
  // d^order w / dφ^order, order ∈ {−1 (antiderivative), 0, 1, 2, 3}; cos/sin of 2πkφ by the
  // angle-addition recurrence from k = 1.
  Real derivative(const Real& phi, int order) const {
    using std::cos;
    using std::sin;
    const Real theta = boost::math::constants::two_pi<Real>() * phi;
    const Real c1 = cos(theta), s1 = sin(theta);
    Real c = c1, s = s1, sum = 0;
    for (unsigned k = 1; k <= max_k_; ++k) {
      if (k > 1) {
        const Real cn = c * c1 - s * s1;
        s = s * c1 + c * s1;
        c = cn;
      }
      const Real w = boost::math::constants::two_pi<Real>() * k;
      // (a cos + b sin)^(order) cycles with period 4 in order.
      Real term;
      switch ((order + 4) % 4) {
        case 0: term = a_[k] * c + b_[k] * s; break;
        case 1: term = -a_[k] * s + b_[k] * c; break;
        case 2: term = -a_[k] * c - b_[k] * s; break;
        default: term = a_[k] * s - b_[k] * c; break;
      }
      Real factor = 1;
      for (int o = 0; o < order; ++o) factor *= w;
      if (order < 0) factor = 1 / w;
      sum += factor * term;
    }
    return sum;
  }
  // A bound of |w^(order)(y) − w^(order)(x)| for |y − x| ≤ r: Taylor's theorem to order J = 4 at x,
  // Σ_{j=1..J} |w^(order+j)(x)|·r^j/j! + max |w^(order+J+1)|·r^(J+1)/(J+1)!, each term widened by
  // its rounding (64 eps of the derivative's bound; `bounds` holds them). One pass over the harmonics.
  Real taylor_spread(int order, const Real& phi, const Real& r, const std::vector<Real>& bounds) const {
    constexpr int J = 4;
    using std::abs;
    using std::cos;
    using std::sin;
    const Real two_pi = boost::math::constants::two_pi<Real>();
    const Real theta = two_pi * phi;
    const Real c1 = cos(theta), s1 = sin(theta);
    Real c = c1, s = s1, sum[J + 1] = {};
    for (unsigned k = 1; k <= max_k_; ++k) {
      if (k > 1) {
        const Real cn = c * c1 - s * s1;
        s = s * c1 + c * s1;
        c = cn;
      }
      const Real w = two_pi * k;
      Real factor = 1;
      for (int o = 0; o <= order; ++o) factor *= w;
      for (int j = 1; j <= J; ++j, factor *= w) {
        switch ((order + j) % 4) {
          case 0: sum[j] += factor * (a_[k] * c + b_[k] * s); break;
          case 1: sum[j] += factor * (-a_[k] * s + b_[k] * c); break;
          case 2: sum[j] += factor * (-a_[k] * c - b_[k] * s); break;
          default: sum[j] += factor * (a_[k] * s - b_[k] * c); break;
        }
      }
    }
    const Real eps64 = 64 * std::numeric_limits<Real>::epsilon();
    Real total = 0, rj = 1, fact = 1;
    for (int j = 1; j <= J; ++j) {
      rj *= r;
      fact *= j;
      total += (abs(sum[j]) + eps64 * bounds[order + j]) * rj / fact;
    }
    return total + bounds[order + J + 1] * rj * r / (fact * (J + 1));
  }
  // Σ_k (2πk)^order·sqrt(a_k² + b_k²): a bound on |w^(order)|.
  Real bound(int order) const {
    using std::sqrt;
    Real s = 0;
    for (unsigned k = 1; k <= max_k_; ++k) {
      Real f = 1;
      for (int o = 0; o < order; ++o) f *= boost::math::constants::two_pi<Real>() * k;
      s += f * sqrt(a_[k] * a_[k] + b_[k] * b_[k]);
    }
    return s;
  }
  std::size_t cells() const { return 16 * static_cast<std::size_t>(max_k_) + 16; }

  std::vector<Real> a_, b_;
  unsigned max_k_ = 0;
  Real value_error_ = 0, antiderivative_error_ = 0;
};

// The normalisation of samples y_0 … y_{N−1} (model.md, "Waveform catalogue": user waves are
// normalised to zero mean and unit amplitude, and the normalisation used is reported), shared by
// make_samples_from and describe_normalisation so that the reported numbers are the ones used.
// mean is the mean of the piecewise-linear signal: Σ y_j / N at φ_j = j/N, or with `phase` (a
// time column) the trapezoid rule's Σ y_j (φ_{j+1} − φ_{j−1})/2; scale = (max − min)/2.
// With an offset large against the amplitude the subtraction cancels log10 κ digits,
// κ = 2·max|y|/(max − min) (1000, 1000.001, 1000: κ ≈ 2·10^6), so everything is computed in mpfr
// at `digits` = wanted + those digits + log10 N for the mean, from the exact samples; the values
// carry that precision, and the caller subtracts and divides at it (PrecisionScope(digits)).
// `sample(j)` returns y_j at the current mpfr precision, correctly rounded; `distinct_digits`
// bounds the significant digits of any y_j, so that two samples that differ still differ at that
// precision (else the signal is constant).
struct SampleNormalisation {
  unsigned digits = 0;  // the mpfr precision (decimal digits) of the values below
  mpfr mean, lo, hi, scale;
};

template <class Sample>
SampleNormalisation normalise_samples(const std::string& name, std::size_t n, Sample sample, int distinct_digits,
                                      const std::function<mpfr(std::size_t)>& phase, int wanted) {
  if (n < 2)
    throw InputError("sampled waveform " + name + " has " + std::to_string(n) + " sample(s): expected at least 2");
  using std::abs;
  const int log_n = static_cast<int>(std::ceil(std::log10(static_cast<double>(n))));
  int attempts = 0;
  long following = 0;  // the precision the last attempt asks for next
  const auto attempt = [&](long p) -> std::optional<SampleNormalisation> {
    ++attempts;
    PrecisionScope scope(static_cast<unsigned>(p));
    mpfr sum = 0, lo = sample(0), hi = lo, big = abs(lo);
    for (std::size_t j = 0; j < n; ++j) {
      const mpfr v = sample(j);
      sum += v;
      if (v < lo) lo = v;
      if (v > hi) hi = v;
      if (abs(v) > big) big = abs(v);
    }
    if (!(hi > lo)) {
      if (p >= distinct_digits + log_n + 10)
        throw InputError("sampled waveform " + name + " is constant: expected a signal with non-zero amplitude");
      following = distinct_digits + log_n + 10;
      return std::nullopt;
    }
    const int cancelled = static_cast<int>(std::ceil(static_cast<double>(log10(2 * big / (hi - lo)))));
    if (wanted + log_n + cancelled + 2 > p) {
      following = wanted + log_n + cancelled + 2;
      return std::nullopt;
    }
    mpfr mean = sum / n;
    if (phase) {
      mean = 0;
      for (std::size_t j = 0; j < n; ++j) {
        const mpfr next = j + 1 < n ? phase(j + 1) : mpfr(1), prev = j > 0 ? phase(j - 1) : mpfr(phase(n - 1) - 1);
        mean += sample(j) * (next - prev) / 2;
      }
    }
    return SampleNormalisation{static_cast<unsigned>(p), mean, lo, hi, mpfr((hi - lo) / 2)};
  };
  auto nz = escalate(wanted + log_n, attempt, [&](long) -> std::optional<long> {
    if (attempts == 8) return std::nullopt;
    return following;
  });
  if (!nz) throw InputError("sampled waveform " + name + ": the normalisation does not converge: offset too large against the amplitude");
  return std::move(*nz);
}

// Periodic samples y_0 … y_{N−1} at φ_j = j/N, joined by straight lines (y_N = y_0), normalised
// to w_j = (y_j − mean)/scale by normalise_samples (10 guard digits over the working precision),
// each w_j rounded to Real once.
//
// With `phase` (a time column), y_j sits at φ_j = phase(j) (φ_0 = 0 < φ_1 < … < φ_{N−1} < 1, the
// period ending at 1) and the mean is the trapezoid rule's, Σ y_j (φ_{j+1} − φ_{j−1})/2.
template <class Real, class Sample>
std::unique_ptr<Waveform<Real>> make_samples_from(std::string name, std::size_t n, Sample sample, int distinct_digits,
                                                 std::function<mpfr(std::size_t)> phase = {}) {
  const unsigned working = mpfr::thread_default_precision();  // mpfr's working precision, restored below
  const SampleNormalisation nz = normalise_samples(name, n, sample, distinct_digits, phase, working_digits10<Real>() + 10);
  std::vector<Real> w;
  Normalisation<Real> norm;
  {
    PrecisionScope scope(nz.digits);
    w.reserve(n);
    for (std::size_t j = 0; j < n; ++j) w.push_back(detail::rounded<Real>(mpfr((sample(j) - nz.mean) / nz.scale), working));
    norm = {true, detail::rounded<Real>(nz.mean, working), detail::rounded<Real>(nz.scale, working)};
  }
  using P = typename PiecewiseLinear<Real>::Piece;
  std::vector<P> pieces;
  pieces.reserve(n);
  if (phase) {
    PrecisionScope scope(static_cast<unsigned>(working_digits10<Real>() + 10));
    for (std::size_t j = 0; j < n; ++j) {
      const mpfr a = phase(j), b = j + 1 < n ? phase(j + 1) : mpfr(1);
      pieces.push_back({detail::rounded<Real>(a, working), w[j],
                        detail::rounded<Real>(mpfr((mpfr(w[(j + 1) % n]) - mpfr(w[j])) / (b - a)), working)});
    }
  } else {
    for (std::size_t j = 0; j < n; ++j) pieces.push_back({Real(j) / n, w[j], Real((w[(j + 1) % n] - w[j]) * n)});
  }
  struct Sampled final : PiecewiseLinear<Real> {
    Sampled(std::string nm, std::vector<P> p, Normalisation<Real> nz) : PiecewiseLinear<Real>(std::move(nm), std::move(p)) {
      this->norm_ = nz;
      // Every phase φ_j, value w_j and slope rounded once to the type: a vertex moves by up to
      // eps·φ_j in phase, which on a steep piece is |slope|·eps·φ_j in value; plus eps·|w_j|,
      // and the slope's own rounding over the piece, eps·|Δw|; the evaluation's subtraction
      // φ − φ_j adds eps·|Δw| again (|Δw| ≤ max − min = 2). On piece i only its own phase,
      // slope and end values enter: value_error(i). Within a rounding of a piece's end the
      // neighbour's line is used; over that sliver the error is second order in an area, the
      // only use of value_error(i).
      using std::abs;
      for (std::size_t i = 0; i < this->piece_count(); ++i) {
        const Real a = abs(this->begin_value(i)), b = abs(this->end_value(i));
        piece_error_.push_back(abs(this->begin_slope(i)) * this->piece_begin(i) + std::max(a, b) +
                               2 * abs(Real(this->end_value(i) - this->begin_value(i))));
      }
      Real steep = 0;
      for (std::size_t i = 0; i < this->piece_count(); ++i) steep = std::max(steep, Real(abs(this->begin_slope(i))));
      value_error_ = steep + std::max(Real(abs(this->maximum())), Real(abs(this->minimum()))) + 4;
    }
    Real value_error() const override { return value_error_; }
    Real value_error(std::size_t i) const override { return piece_error_[i]; }
    Real value_error_ = 0;
    std::vector<Real> piece_error_;
  };
  return std::make_unique<Sampled>(std::move(name), std::move(pieces), norm);
}

// Samples given as numbers of the working type: exact in mpfr, at most max_digits10 digits each.
template <class Real>
std::unique_ptr<Waveform<Real>> make_samples(std::string name, const std::vector<Real>& y) {
  if constexpr (is_runtime_precision_v<Real>) {
    long bits = 0;
    for (const Real& v : y) bits = std::max<long>(bits, static_cast<long>(mpfr_get_prec(v.backend().data())));
    return make_samples_from<Real>(std::move(name), y.size(), [&](std::size_t j) { return mpfr(y[j]); },
                                   static_cast<int>(bits * 0.30103) + 2);
  } else {
    return make_samples_from<Real>(std::move(name), y.size(), [&](std::size_t j) { return mpfr(y[j]); },
                                   std::numeric_limits<Real>::max_digits10);
  }
}

}  // namespace vibrofric
