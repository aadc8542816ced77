// Axisymmetric indenter profiles and their MDR transform (model.md, "Curved contacts (MDR)"):
// the 1D profile σ(x) = g(x)/A of the row of flat-punch springs, g(x) = |x| ∫₀^|x| f'(r)/√(x² − r²) dr.
//
// Dimensionless conventions (μ̄ is a ratio of two x-integrals, so a common scale of x drops out):
// - power:N (N ≥ 1; sphere = power:2, cone = power:1): σ = x^N.
// - wearflat:λ (λ = b²/(R A) > 0): x in units of the flat radius b, σ = 0 for x ≤ 1,
//   σ = λ x √(x² − 1) beyond.
// - profile:FILE: measured f(r) as samples 'r f', piecewise linear, f(0) = 0, f non-decreasing,
//   heights in units of the amplitude A (the tool's physical command reads metres and divides);
//   r in any unit; f convex (slopes non-decreasing), else g is not monotone. g is exact per
//   segment: ∫ dr/√(x² − r²) = asin(r/x).
// The spring integral runs over a variable t of the profile's choice: x for power laws and
// measured profiles, σ itself beyond the flat for the wear-flat sphere (x(σ) is smooth there,
// while σ(x) has a square-root onset at x = 1).
// Profiles as written (names, files, decimal text) are the API's: vibrofric/api/profile_spec.hpp.
#pragma once
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

enum class ProfileKind { flat, power, wearflat, measured };

template <class Real>
class Profile {
 public:
  virtual ~Profile() = default;
  const std::string& name() const { return name_; }
  ProfileKind kind() const { return kind_; }

  // σ(x) = g(x)/A at x ≥ 0 (the spring row's coordinate, in the profile's unit of length).
  virtual Real sigma_at_x(const Real& x) const = 0;
  // The smallest x with σ(x) = s, for 0 ≤ s ≤ sigma_limit().
  virtual Real x_at_sigma(const Real& s) const = 0;
  // ∫₀^x σ(x') dx' (closed form per kind): with it the row's load at a uniform indentation n of
  // every spring, ∫₀^X (n − σ) dx = n X − Σ(X) at σ(X) = n, the load at the period's deepest instant.
  virtual Real sigma_integral(const Real& x) const = 0;
  // The largest σ the profile defines (a measured profile ends at its last sample).
  virtual Real sigma_limit() const { return std::numeric_limits<Real>::infinity(); }
  // Length of the central part with σ = 0 (the wear flat): x ∈ [0, flat_length()].
  virtual Real flat_length() const { return Real(0); }

  // The integration variable beyond the flat: t ∈ [t(0), t(s_max)], x = x(t), weight dx/dt.
  virtual Real t_at_sigma(const Real& s) const { return x_at_sigma(s); }
  virtual Real sigma_at_t(const Real& t) const { return sigma_at_x(t); }
  virtual Real dx_dt(const Real&) const { return Real(1); }
  // Kinks of σ(t) or of dx/dt inside the range, in t (the measured profile's sample radii).
  virtual std::vector<Real> t_breaks() const { return {}; }

 protected:
  Profile(std::string name, ProfileKind kind) : name_(std::move(name)), kind_(kind) {}

 private:
  std::string name_;
  ProfileKind kind_;
};

// σ = x^N.
template <class Real>
class PowerProfile final : public Profile<Real> {
 public:
  PowerProfile(const Real& n, std::string name) : Profile<Real>(std::move(name), ProfileKind::power), n_(n) {
    if (!(n >= 1)) throw InputError("profile power:N needs N >= 1 (got " + detail::short_str(n) + ")");
  }
  const Real& exponent() const { return n_; }
  Real sigma_at_x(const Real& x) const override {
    using std::pow;
    return n_ == 1 ? x : (n_ == 2 ? Real(x * x) : Real(pow(x, n_)));
  }
  Real x_at_sigma(const Real& s) const override {
    using std::pow;
    using std::sqrt;
    if (!(s > 0)) return Real(0);
    return n_ == 1 ? s : (n_ == 2 ? Real(sqrt(s)) : Real(pow(s, 1 / n_)));
  }
  Real sigma_integral(const Real& x) const override {
    if (!(x > 0)) return Real(0);
    return sigma_at_x(x) * x / (n_ + 1);
  }

 private:
  Real n_;
};

// Sphere with a wear flat: σ = λ x √(x² − 1) beyond x = 1. Beyond the flat the variable is σ:
// x(σ) = √((1 + √(1 + 4 (σ/λ)²))/2) is analytic at σ = 0, dx/dσ = q/(λ x √(1 + 4q²)), q = σ/λ.
template <class Real>
class WearFlatProfile final : public Profile<Real> {
 public:
  WearFlatProfile(const Real& lambda, std::string name)
      : Profile<Real>(std::move(name), ProfileKind::wearflat), lambda_(lambda) {
    using std::isfinite;
    if (!(lambda > 0) || !isfinite(lambda))
      throw InputError("profile wearflat:LAMBDA needs a finite LAMBDA > 0 (got " + detail::short_str(lambda) + ")");
  }
  const Real& lambda() const { return lambda_; }
  Real sigma_at_x(const Real& x) const override {
    using std::sqrt;
    if (!(x > 1)) return Real(0);
    return lambda_ * x * sqrt(Real((x - 1) * (x + 1)));
  }
  Real x_at_sigma(const Real& s) const override {
    using std::sqrt;
    if (!(s > 0)) return Real(1);
    const Real q = s / lambda_;
    // (1 + √(1 + 4q²))/2 = 1 + 2q²/(1 + √(1 + 4q²)): no cancellation for small q.
    return sqrt(Real(1 + 2 * q * q / (1 + sqrt(Real(1 + 4 * q * q)))));
  }
  // ∫₁^x λ t √(t² − 1) dt = (λ/3)(x² − 1)^(3/2).
  Real sigma_integral(const Real& x) const override {
    using std::sqrt;
    if (!(x > 1)) return Real(0);
    const Real q = (x - 1) * (x + 1);
    return lambda_ * q * sqrt(q) / 3;
  }
  Real flat_length() const override { return Real(1); }
  Real t_at_sigma(const Real& s) const override { return s; }
  Real sigma_at_t(const Real& t) const override { return t; }
  Real dx_dt(const Real& t) const override {
    using std::sqrt;
    const Real q = t / lambda_;
    return q / (lambda_ * x_at_sigma(t) * sqrt(Real(1 + 4 * q * q)));
  }

 private:
  Real lambda_;
};

// Measured profile: f piecewise linear through (r_j, f_j), slope m_j on [r_j, r_{j+1}];
// g(x) = x Σ_{r_j < x} m_j [asin(min(r_{j+1}, x)/x) − asin(r_j/x)], exact per segment. σ = g
// (heights are in units of A). g has a square-root onset at every r_j where the slope changes:
// those radii are quadrature breakpoints.
template <class Real>
class MeasuredProfile final : public Profile<Real> {
 public:
  MeasuredProfile(std::vector<Real> r, std::vector<Real> f, std::string name)
      : Profile<Real>(std::move(name), ProfileKind::measured), r_(std::move(r)), f_(std::move(f)) {
    // Slopes non-decreasing (parse_profile_file checked it exactly): rounding in this type must
    // not make one drop, or g would dip.
    for (std::size_t j = 0; j + 1 < r_.size(); ++j) {
      Real m = (f_[j + 1] - f_[j]) / (r_[j + 1] - r_[j]);
      if (j > 0 && m < m_.back()) m = m_.back();
      m_.push_back(m);
    }
    flat_ = 0;
    for (std::size_t j = 0; j < m_.size() && m_[j] == 0; ++j) flat_ = j + 1;
    if (flat_ == m_.size())
      throw InputError("profile " + this->name() + " is flat (f = 0 at every sample): expected a curved profile (this one is the flat punch)");
    limit_ = g(r_.back());
  }
  Real sigma_at_x(const Real& x) const override { return g(x); }
  Real x_at_sigma(const Real& s) const override {
    if (!(s > 0)) return r_[flat_];
    if (s >= limit_) return r_.back();
    // g is increasing beyond the flat: bisect over the samples, then a bracketed root.
    std::size_t lo = flat_, hi = r_.size() - 1;
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      (g(r_[mid]) < s ? lo : hi) = mid;
    }
    detail::RootStats stats;
    stats.max_iterations = 200 + static_cast<std::uintmax_t>(4 * working_digits10<Real>());
    return detail::bracketed_root<Real>([&](const Real& x) -> Real { return g(x) - s; }, r_[lo], r_[hi],
                                        Real(g(r_[lo]) - s), Real(g(r_[hi]) - s), "profile contact radius", stats);
  }
  // Term by term, ∫_{r}^{x} t acos(r/t) dt = (x²/2) acos(r/x) − (r/2) √(x² − r²).
  Real sigma_integral(const Real& x) const override {
    using std::atan2;
    return over_kinks(x, [&](const Real& r, const Real& root) { return Real((x * x * atan2(root, r) - r * root) / 2); });
  }
  Real sigma_limit() const override { return limit_; }
  Real flat_length() const override { return r_[flat_]; }
  std::vector<Real> t_breaks() const override {
    std::vector<Real> out;
    for (std::size_t j = flat_ + 1; j + 1 < r_.size(); ++j)
      if (m_[j] != m_[j - 1]) out.push_back(r_[j]);
    return out;
  }
  const std::vector<Real>& radii() const { return r_; }
  const std::vector<Real>& heights() const { return f_; }

 private:
  // Summed by parts: g(x) = x Σ_{r_j < x} (m_j − m_{j−1}) acos(r_j/x), every term ≥ 0 (convex f), and
  // acos(r/x) = atan2(√((x − r)(x + r)), r) keeps its relative accuracy as x → r_j.
  Real g(const Real& x) const {
    using std::atan2;
    return x * over_kinks(x, [](const Real& r, const Real& root) { return Real(atan2(root, r)); });
  }
  // Σ_{r_j < x} (m_j − m_{j−1}) term(r_j, √((x − r_j)(x + r_j))), m_{−1} = 0: 0 for x ≤ 0.
  template <class Term>
  Real over_kinks(const Real& x, Term term) const {
    using std::sqrt;
    if (!(x > 0)) return Real(0);
    Real sum = 0;
    for (std::size_t j = 0; j < m_.size() && r_[j] < x; ++j) {
      const Real dm = j == 0 ? m_[0] : Real(m_[j] - m_[j - 1]);
      if (dm == 0) continue;
      sum += dm * term(r_[j], Real(sqrt(Real((x - r_[j]) * (x + r_[j])))));
    }
    return sum;
  }
  std::vector<Real> r_, f_, m_;
  std::size_t flat_ = 0;
  Real limit_;
};

}  // namespace vibrofric
