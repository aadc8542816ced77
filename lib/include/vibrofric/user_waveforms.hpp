// User waveforms for Eq. (2): a finite Fourier series and a sampled periodic signal (piecewise
// linear through the samples), both normalised to zero mean and unit amplitude (model.md).
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "vibrofric/waveform.hpp"

namespace vibrofric {

namespace detail {

// All roots of a smooth 1-periodic f on [0, 1), given L ≥ max |f'| and M ≥ max |f|. A cell
// [a, b] is dropped when |f(mid)| > L·(b − a)/2 + 64·eps·M (then f has no zero in it, even with
// f's rounding); otherwise it is halved, down to a width of 2^-30 cells, where a sign change is
// refined to working precision. A zero of even multiplicity (no sign change) is not reported:
// it does not split a monotone piece.
template <class Real, class F>
std::vector<Real> periodic_roots(F f, const Real& lipschitz, const Real& magnitude, std::size_t cells,
                                 const char* what, RootStats& stats) {
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
    if (abs(fm) > lipschitz * (c.b - c.a) / 2 + margin) continue;
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
    const auto extrema = detail::periodic_roots<Real>(
        [&](const Real& x) -> Real { return derivative(x, 1); }, bound(2), bound(1), cells(), "extremum of the Fourier waveform", stats);
    const auto inflections = detail::periodic_roots<Real>(
        [&](const Real& x) -> Real { return derivative(x, 2); }, bound(3), bound(2), cells(), "inflection of the Fourier waveform", stats);
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
  }

  Real value(std::size_t, const Real& phi) const override { return derivative(phi, 0); }
  Real slope(std::size_t, const Real& phi) const override { return derivative(phi, 1); }
  bool has_antiderivative() const override { return true; }
  Real antiderivative(std::size_t, const Real& phi) const override { return derivative(phi, -1); }
  unsigned max_harmonic() const { return max_k_; }

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
};

// Periodic samples y_0 … y_{N−1} at φ_j = j/N, joined by straight lines (y_N = y_0), normalised.
// The mean of the piecewise-linear signal is the mean of the samples.
template <class Real>
std::unique_ptr<Waveform<Real>> make_samples(std::string name, const std::vector<Real>& y) {
  const std::size_t n = y.size();
  if (n < 2)
    throw InputError("sampled waveform " + name + " has " + std::to_string(n) + " sample(s): expected at least 2");
  // Scale by a power of two (exact) so that the largest |y| is in [1/2, 1): the mean and the range
  // then neither overflow (samples near ±1e308 in double) nor lose bits (subnormal samples).
  Real big = 0;
  for (const Real& v : y) {
    using std::abs;
    big = std::max(big, Real(abs(v)));
  }
  using std::frexp;
  using std::ldexp;
  int e = 0;
  frexp(big, &e);
  Real mean = 0, lo = ldexp(y[0], -e), hi = lo;
  for (const Real& raw : y) {
    const Real v = ldexp(raw, -e);
    mean += v;
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  mean /= n;
  if (!(hi > lo)) throw InputError("sampled waveform " + name + " is constant: expected a signal with non-zero amplitude");
  const Real scale = (hi - lo) / 2;
  using P = typename PiecewiseLinear<Real>::Piece;
  std::vector<P> pieces;
  for (std::size_t j = 0; j < n; ++j) {
    const Real y0 = (ldexp(y[j], -e) - mean) / scale, y1 = (ldexp(y[(j + 1) % n], -e) - mean) / scale;
    pieces.push_back({Real(j) / n, y0, (y1 - y0) * n});
  }
  struct Sampled final : PiecewiseLinear<Real> {
    Sampled(std::string nm, std::vector<P> p, Normalisation<Real> norm) : PiecewiseLinear<Real>(std::move(nm), std::move(p)) {
      this->norm_ = norm;
    }
  };
  return std::make_unique<Sampled>(std::move(name), std::move(pieces), Normalisation<Real>{true, ldexp(mean, e), ldexp(scale, e)});
}

}  // namespace vibrofric
