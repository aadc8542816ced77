// Truncated Taylor series with interval coefficients: the arithmetic of the curved enclosure's
// Taylor models (curved_enclosure.cpp; model.md, "Curved contacts (MDR)"). A series holds the
// coefficients c_k of f(ξ + h) = Σ c_k h^k up to its size, for every ξ its base encloses: at a thin
// base, f's Taylor coefficients there; at a box, enclosures of f^(k)(ξ)/k! over the box (each
// recurrence below is isotone in its inputs), which bound a Taylor model's Lagrange remainder.
#pragma once
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "vibrofric/core/certified/interval.hpp"

namespace vibrofric::certified::taylor {

class Series {
 public:
  Series(std::size_t size, mpfr_prec_t bits) : c_(size, Interval(bits)) {}
  // value + slope·h
  static Series line(const Interval& value, const Interval& slope, std::size_t size) {
    Series s(size, value.precision());
    s.c_[0] = value;
    if (size > 1) s.c_[1] = slope;
    return s;
  }
  static Series constant(const Interval& value, std::size_t size) { return line(value, Interval(value.precision()), size); }

  std::size_t size() const { return c_.size(); }
  mpfr_prec_t bits() const { return c_.front().precision(); }
  const Interval& operator[](std::size_t k) const { return c_[k]; }
  Interval& operator[](std::size_t k) { return c_[k]; }

  // d/dh: one coefficient fewer.
  Series derivative() const {
    Series d(size() - 1, bits());
    for (std::size_t k = 0; k + 1 < size(); ++k) d.c_[k] = c_[k + 1] * static_cast<long>(k + 1);
    return d;
  }
  // f/h^m for an f whose first m coefficients are zero at every point of the base (the caller
  // knows it; the intervals there only enclose 0). At a box, f/h^m's k-th coefficient lies in
  // f's (k+m)-th: f/h^m = ∫ f^(m)(sh) times a positive kernel of total mass 1/m!.
  Series shifted(std::size_t m) const {
    Series d(size() - m, bits());
    for (std::size_t k = 0; k < d.size(); ++k) d.c_[k] = c_[k + m];
    return d;
  }

  friend Series operator+(Series a, const Series& b) {
    a.trim(b.size());
    for (std::size_t k = 0; k < a.size(); ++k) a.c_[k] += b.c_[k];
    return a;
  }
  friend Series operator-(Series a, const Series& b) {
    a.trim(b.size());
    for (std::size_t k = 0; k < a.size(); ++k) a.c_[k] -= b.c_[k];
    return a;
  }
  friend Series operator-(Series a) {
    for (Interval& x : a.c_) x = -x;
    return a;
  }
  friend Series operator+(Series a, const Interval& v) {
    a.c_[0] += v;
    return a;
  }
  friend Series operator+(const Interval& v, Series a) { return std::move(a) + v; }
  friend Series operator-(const Interval& v, Series a) { return -std::move(a) + v; }
  friend Series operator-(Series a, const Interval& v) {
    a.c_[0] -= v;
    return a;
  }
  friend Series operator*(Series a, const Interval& v) {
    for (Interval& x : a.c_) x *= v;
    return a;
  }
  friend Series operator*(const Interval& v, Series a) { return std::move(a) * v; }
  friend Series operator*(const Series& a, const Series& b) {
    const std::size_t n = std::min(a.size(), b.size());
    // a line (the variable) or a constant has few terms: only those are convolved
    const std::size_t na = a.terms(), nb = b.terms();
    Series r(n, a.bits());
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t j = k + 1 > nb ? k + 1 - nb : 0; j <= k && j < na; ++j) r.c_[k].add_mul(a.c_[j], b.c_[k - j]);
    return r;
  }
  friend Series operator/(const Series& a, const Series& b) {
    const std::size_t n = std::min(a.size(), b.size());
    Series q(n, a.bits());
    for (std::size_t k = 0; k < n; ++k) {
      Interval s = a.c_[k];
      for (std::size_t j = 1; j <= k; ++j) s.sub_mul(b.c_[j], q.c_[k - j]);
      q.c_[k] = s / b.c_[0];
    }
    return q;
  }
  friend Series sqrt(const Series& x) {
    Series y(x.size(), x.bits());
    y.c_[0] = sqrt(x.c_[0]);
    const Interval twice = y.c_[0] * 2L;
    for (std::size_t k = 1; k < x.size(); ++k) {
      Interval s = x.c_[k];
      for (std::size_t j = 1; j < k; ++j) s.sub_mul(y.c_[j], y.c_[k - j]);
      y.c_[k] = s / twice;
    }
    return y;
  }
  // x^α for x > 0 on the base: k x_0 y_k = Σ_{j=1..k} (α j − (k − j)) x_j y_{k−j}
  //   = (α + 1) Σ j x_j y_{k−j} − k Σ x_j y_{k−j}.
  friend Series pow(const Series& x, const Interval& alpha) {
    Series y(x.size(), x.bits());
    const Series jx = x.weighted();
    const Interval alpha_1 = alpha + Interval::integer(1, x.bits());
    y.c_[0] = exp(alpha * log(x.c_[0]));
    for (std::size_t k = 1; k < x.size(); ++k) {
      Interval s1(x.bits()), s2(x.bits());
      for (std::size_t j = 1; j <= k; ++j) {
        s1.add_mul(jx.c_[j], y.c_[k - j]);
        s2.add_mul(x.c_[j], y.c_[k - j]);
      }
      y.c_[k] = (alpha_1 * s1 - s2 * static_cast<long>(k)) / (x.c_[0] * static_cast<long>(k));
    }
    return y;
  }
  // sin x and cos x: k s_k = Σ j x_j c_{k−j}, k c_k = −Σ j x_j s_{k−j}.
  friend std::pair<Series, Series> sin_cos(const Series& x) {
    Series s(x.size(), x.bits()), c(x.size(), x.bits());
    auto [s0, c0] = sin_cos(x.c_[0]);
    s.c_[0] = std::move(s0);
    c.c_[0] = std::move(c0);
    const Series jx = x.weighted();
    for (std::size_t k = 1; k < x.size(); ++k) {
      Interval ss(x.bits()), cs(x.bits());
      for (std::size_t j = 1; j <= k; ++j) {
        ss.add_mul(jx.c_[j], c.c_[k - j]);
        cs.sub_mul(jx.c_[j], s.c_[k - j]);
      }
      const Interval kk = Interval::integer(static_cast<long>(k), x.bits());
      s.c_[k] = ss / kk;
      c.c_[k] = cs / kk;
    }
    return {std::move(s), std::move(c)};
  }
  // asin x for |x| < 1 on the base: y' = x' / √(1 − x²).
  friend Series asin(const Series& x) {
    const Series one = constant(Interval::integer(1, x.bits()), x.size());
    const Series r = one / sqrt(one - x * x);
    Series y(x.size(), x.bits());
    const Series jx = x.weighted();
    y.c_[0] = asin(x.c_[0]);
    for (std::size_t k = 1; k < x.size(); ++k) {
      Interval s(x.bits());
      for (std::size_t j = 1; j <= k; ++j) s.add_mul(jx.c_[j], r.c_[k - j]);
      y.c_[k] = s / Interval::integer(static_cast<long>(k), x.bits());
    }
    return y;
  }

 private:
  // 1 + the index of the last coefficient that is not exactly 0
  std::size_t terms() const {
    std::size_t n = c_.size();
    while (n > 0 && c_[n - 1].sign() == Sign::zero) --n;
    return n;
  }
  // j·c_j: the coefficients of h·f'(h), which the recurrences of sin, cos, asin and pow convolve
  Series weighted() const {
    Series w(size(), bits());
    for (std::size_t j = 1; j < size(); ++j) w.c_[j] = c_[j] * static_cast<long>(j);
    return w;
  }
  void trim(std::size_t n) {
    if (n < c_.size()) c_.erase(c_.begin() + static_cast<std::ptrdiff_t>(n), c_.end());
  }
  std::vector<Interval> c_;
};

// sin z / z at z = z0 + slope·h, for any base z0 (0 included): from its Maclaurin series,
// sinc^(k)(z0)/k! = (1/k!) Σ_{m ≥ k/2} (−1)^m z0^(2m−k) / ((2m−k)! (2m+1)), summed while the
// terms matter and the rest bounded by 2 Z^J/J! (Z = max |z0|, J the first index left out,
// J ≥ 2Z + 1 so that the tail's terms at least halve).
inline Series sinc(const Interval& z0, const Interval& slope, std::size_t size) {
  const mpfr_prec_t bits = z0.precision();
  mpfr Z = abs(z0.lower());
  if (abs(z0.upper()) > Z) Z = abs(z0.upper());
  // the first J ≥ 2Z + 1 + size with Z^J/J! < 2^−(bits + 20)
  long J = static_cast<long>(2 * Z + 2) + static_cast<long>(size);
  Interval term = Interval::integer(1, bits);  // Z^J / J!, by its factors
  const Interval Zi = Interval::exact(Z, bits);
  for (long j = 1; j <= J; ++j) term = term * Zi / Interval::integer(j, bits);
  mpfr eps;
  mpfr_set_prec(eps.backend().data(), 32);
  mpfr_set_ui_2exp(eps.backend().data(), 1, -static_cast<long>(bits) - 20, MPFR_RNDN);
  while (!(term.upper() < eps)) {
    ++J;
    term = term * Zi / Interval::integer(J, bits);
  }
  // powers over factorials e_j = z0^j / j!, j < J
  std::vector<Interval> e(static_cast<std::size_t>(J), Interval::integer(1, bits));
  for (long j = 1; j < J; ++j) e[j] = e[j - 1] * z0 / Interval::integer(j, bits);
  std::vector<Interval> minus_e;
  minus_e.reserve(e.size());
  for (const Interval& x : e) minus_e.push_back(-x);
  Series s(size, bits);
  Interval k_factorial = Interval::integer(1, bits), slope_power = Interval::integer(1, bits);
  for (std::size_t k = 0; k < size; ++k) {
    if (k > 0) {
      k_factorial = k_factorial * static_cast<long>(k);
      slope_power = slope_power * slope;
    }
    Interval sum(bits);
    for (long m = static_cast<long>((k + 1) / 2); 2 * m - static_cast<long>(k) < J; ++m) {
      // (−1)^m e_j / (2m + 1): the sign is carried by e's table of ±e_j
      sum.add_quotient(m % 2 == 0 ? e[2 * m - k] : minus_e[2 * m - k], static_cast<unsigned long>(2 * m + 1));
    }
    // the tail: |Σ_{j ≥ J} ±z0^j/(j! (2m+1))| ≤ 2 Z^J/J!
    sum += hull(term * 2L, term * -2L);
    s[k] = sum / k_factorial * slope_power;
  }
  return s;
}

}  // namespace vibrofric::certified::taylor
