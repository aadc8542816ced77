// Closed forms of μ̄/μ0 for curved contacts (model.md, "Curved contacts (MDR)"), for the catalogue
// waves triangle, sawtooth-right, sawtooth-left and square, kept apart from the numerical solver
// (curved.hpp) so that tests set one against the other. Derivation and the symbolic (GiNaC) check:
// proofs/curved_closed_forms.md and proofs/curved_closed_forms.cpp (`ctest -R proof.curved`).
//
// Conventions (those of profile.hpp / curved.hpp). Every spring of the MDR row is the flat punch at
// the mean indentation g = γ − σ(x), with (paper Eqs. 13, 17, 19, 22; per spring, β > 0)
//   N_w(g) = ∫₀¹ max(g + w, 0) dφ:  g for g ≥ 1; (1+g)²/4 (tri, str, stl), (1+g)/2 (square) for
//            −1 < g < 1; 0 for g ≤ −1;
//   Φ_w(β, g) = ∫₀¹ s dφ:  g − Ψ_w(β) for g ≥ 1 (Eq. 13);  m_w(β) N_w(g) for −1 < g < 1 and the
//            triangular waves, m_w = 1 − Ψ_w (Eqs. 18–19); square: β/8 for 1 + g ≥ β/2,
//            (1+g)/2 − (1+g)²/(2β) below (Eq. 22 times N).
// The integrals run over the half-row x ≥ 0 up to the contact edge X, σ(X) = 1 + γ:
//   power:n      σ = xⁿ (n ≥ 1 real; sphere n = 2, cone n = 1), X = (1+γ)^(1/n);
//   wearflat:λ   x in units of the flat radius, σ = 0 on [0, 1], σ = λ x √(x² − 1) beyond.
//   friction_integral = ∫₀^X Φ_w(β, γ − σ) dx,  normal_integral = ∫₀^X N_w(γ − σ) dx,
//   mu = μ̄/μ0 = friction_integral / normal_integral (exactly 1 where β ≥ β_c: tri β ≥ 4, str β ≥ 2).
//
// Evaluation. Every formula is the closed form of the proof, rearranged so that no term is much
// larger than the integral it contributes to: the x-integrals over the outer shell and over the
// square wave's kink region are written as τ-integrals (power law) whose series have positive
// terms where they are thin, and the wear-flat kink integral as a positive Taylor series in the
// hyperbolic angle where it is thin (proofs/curved_closed_forms.md, §7, where every rearrangement is
// checked). Cost: at most one series of about 3.3·digits terms (O(terms²) for the wear-flat kink).
// Accuracy: a few ulp of Real (measured at 50 and 100 digits against tanh-sinh of the piecewise
// integrand, worst 6.5 ε over β = 1e-9…1e6, γ = −1 + 1e-11…1e4; figures in §7).
#pragma once
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "vibrofric/core/errors.hpp"

namespace vibrofric::closed_form {

enum class CatalogueWave { triangle, sawtooth_right, sawtooth_left, square };

template <class Real>
struct CurvedIntegrals {
  Real friction_integral;  // ∫₀^X Φ_w(β, γ − σ(x)) dx
  Real normal_integral;    // ∫₀^X N_w(γ − σ(x)) dx
  Real mu;                 // μ̄/μ0 = friction_integral / normal_integral
  Real contact_radius;     // X, σ(X) = 1 + γ
};

namespace detail_curved {

template <class Real>
std::string str(const Real& x) {
  std::ostringstream os;
  os.precision(std::numeric_limits<double>::max_digits10);
  os << x;
  return os.str();
}

template <class Real>
void check_beta_gamma(const char* fn, const Real& beta, const Real& gamma) {
  using std::isfinite;
  if (!(beta > 0) || !isfinite(beta))
    throw InputError(std::string("closed_form::") + fn + ": beta = " + str(beta) + ", expected a finite beta > 0");
  if (!isfinite(gamma))
    throw InputError(std::string("closed_form::") + fn + ": gamma = " + str(gamma) + ", expected a finite number");
  if (!(gamma > -1))
    throw DomainError(std::string("closed_form::") + fn + ": gamma = " + str(gamma) +
                      " gives no contact, expected gamma > -1");
}

// m_w(β) = μ̄/μ0 of the jumping flat punch (Eq. 19, = 1 − Ψ_w(β), 1 for β ≥ β_c), triangular waves.
template <class Real>
Real m_triangular(CatalogueWave w, const Real& beta) {
  switch (w) {
    case CatalogueWave::triangle: return beta < 4 ? Real(2 * beta / (4 + beta)) : Real(1);
    case CatalogueWave::sawtooth_right: return beta < 2 ? Real(beta / 2) : Real(1);
    default: return beta / (2 + beta);
  }
}
// Ψ_w(β) (Eq. 17; 0 for β ≥ β_c), triangular waves.
template <class Real>
Real psi_triangular(CatalogueWave w, const Real& beta) {
  switch (w) {
    case CatalogueWave::triangle: return beta < 4 ? Real((4 - beta) / (4 + beta)) : Real(0);
    case CatalogueWave::sawtooth_right: return beta < 2 ? Real(1 - beta / 2) : Real(0);
    default: return 2 / (2 + beta);
  }
}

// 1 − u^q for 0 ≤ u < 1, q > 0, without cancellation.
template <class Real>
Real one_minus_pow(const Real& u, const Real& q) {
  using std::expm1;
  using std::log;
  if (!(u > 0)) return Real(1);
  return -expm1(q * log(u));
}

// The power-law shell and kink integrals in τ (proof: "Evaluation"), p = 1/n ∈ (0, 1], τ ∈ (0, 1],
// u = 1 − τ given separately (it is computed without cancellation by the caller):
//   E_k(τ) = ∫₀^τ w^k (1 − w)^(p−1) dw  (k = 1, 2),   F(τ) = ∫₀^τ (τ − w)² (1 − w)^(p−1) dw.
// τ ≤ 1/2: binomial series of (1 − w)^(p−1), every term positive, ratio ≤ τ.
// τ > 1/2: the elementary antiderivatives in u = 1 − τ < 1/2 (terms within a small factor of the value).
template <class Real>
Real tau_series(int kind, const Real& p, const Real& tau) {
  const Real eps = std::numeric_limits<Real>::epsilon();
  Real a = 1, sum = 0, tp = kind == 1 ? Real(tau * tau) : Real(tau * tau * tau);  // τ^(k+1), F: τ³
  for (int j = 0;; ++j) {
    // term_j = a_j τ^(j+k+1)/(j+k+1) for E_k, a_j 2τ^(j+3)/((j+1)(j+2)(j+3)) for F (kind 3)
    Real term = kind == 3 ? Real(2 * a * tp / ((j + 1) * Real(j + 2) * (j + 3))) : Real(a * tp / (j + kind + 1));
    sum += term;
    if (!(term > eps * sum / 8) || j > 100000) break;
    a *= (1 - p + j) / (j + 1);
    tp *= tau;
  }
  return sum;
}

template <class Real>
Real E(int k, const Real& p, const Real& tau, const Real& u) {
  if (tau <= Real(1) / 2) return tau_series(k, p, tau);
  const Real o0 = one_minus_pow(u, p), o1 = one_minus_pow(u, Real(p + 1));
  if (k == 1) return o0 / p - o1 / (p + 1);
  return o0 / p - 2 * o1 / (p + 1) + one_minus_pow(u, Real(p + 2)) / (p + 2);
}

template <class Real>
Real F(const Real& p, const Real& tau, const Real& u) {
  if (tau <= Real(1) / 2) return tau_series(3, p, tau);
  return one_minus_pow(u, Real(p + 2)) / (p + 2) - 2 * u * one_minus_pow(u, Real(p + 1)) / (p + 1) +
         u * u * one_minus_pow(u, p) / p;
}

template <class Real>
Real root_n(const Real& a, const Real& n) {  // a^(1/n), a ≥ 0
  using std::pow;
  using std::sqrt;
  if (!(a > 0)) return Real(0);
  return n == 1 ? a : (n == 2 ? Real(sqrt(a)) : Real(pow(a, 1 / n)));
}

// Wear-flat sphere: a level σ = S beyond the flat, with t = x² − 1 and s = √t.
template <class Real>
struct Level {
  Real S, t, x, s;
};
template <class Real>
Level<Real> level(const Real& S, const Real& lambda) {
  using std::sqrt;
  const Real q = S / lambda;
  const Real t = 2 * q * q / (1 + sqrt(Real(1 + 4 * q * q)));  // λ² t (1 + t) = S²
  return {S, t, sqrt(Real(1 + t)), sqrt(t)};
}

// ∫ₐᵇ σ^k dx (k = 0, 1, 2) between two levels a, b (S_a ≤ S_b), dS = S_b − S_a given exactly.
template <class Real>
struct Moments {
  Real J0, J1, J2;
};
template <class Real>
Moments<Real> moments(const Level<Real>& a, const Level<Real>& b, const Real& dS, const Real& lambda) {
  // t_b − t_a = (q_b² − q_a²)/(1 + t_a + t_b)
  const Real dt = dS * (a.S + b.S) / (lambda * lambda * (1 + a.t + b.t));
  const Real dx = dt / (a.x + b.x);
  const Real ds = (a.s + b.s > 0) ? Real(dt / (a.s + b.s)) : Real(0);
  Moments<Real> m;
  m.J0 = dx;
  m.J1 = lambda * ds * (a.t + a.s * b.s + b.t) / 3;  // (λ/3)(s_b³ − s_a³)
  // λ² ∫ (x⁴ − x²) dx, expanded about x_a: every coefficient is ≥ 0
  const Real& X = a.x;
  m.J2 = lambda * lambda *
         (X * X * a.t * dx + X * (1 + 2 * a.t) * dx * dx + (5 + 6 * a.t) * dx * dx * dx / 3 +
          X * dx * dx * dx * dx + dx * dx * dx * dx * dx / 5);
  return m;
}
// ∫ₐᵇ (A − σ)^k dx from the moments.
template <class Real>
Real I1(const Real& A, const Moments<Real>& m) { return A * m.J0 - m.J1; }
template <class Real>
Real I2(const Real& A, const Moments<Real>& m) { return A * A * m.J0 - 2 * A * m.J1 + m.J2; }

// T2 = ∫ (σ − σ_k)² dx from the kink level k to the edge level e (σ_e − σ_k = dS).
// Thin (hyperbolic angle ψ_e ≤ 1/4): with x = cosh φ, σ − σ_k = λ sinh ψ cosh(ψ + 2φ_k) and
// dx = sinh(ψ + φ_k) dψ, ψ = φ − φ_k: a Taylor series in ψ with positive coefficients.
template <class Real>
Real kink_integral(const Level<Real>& k, const Level<Real>& e, const Real& dS, const Real& lambda) {
  using std::asinh;
  const Real dt = dS * (k.S + e.S) / (lambda * lambda * (1 + k.t + e.t));
  // sinh(φ_e − φ_k) = s_e x_k − s_k x_e = (t_e − t_k)/(s_e x_k + s_k x_e)
  const Real psi = asinh(Real(dt / (e.s * k.x + k.s * e.x)));
  if (psi > Real(1) / 4) {
    const Moments<Real> m = moments(k, e, dS, lambda);
    return m.J2 - 2 * k.S * m.J1 + k.S * k.S * m.J0;
  }
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real C2 = 1 + 2 * k.t, S2 = 2 * k.x * k.s;  // cosh 2φ_k, sinh 2φ_k
  // Taylor coefficients in ψ: a = cosh(ψ + 2φ_k), b = a², c = sinh²ψ = (cosh 2ψ − 1)/2, d = b c,
  // f = sinh(ψ + φ_k), g = d f: all ≥ 0, and g ≤ (C2² x_k/2) e^(5ψ) coefficientwise.
  std::vector<Real> a, b, c, d, f;
  Real sum = 0, psin = psi, inv_fact = 1, two_n = 1, major = C2 * C2 * k.x / 2;  // ψ^(n+1), 1/n!, 2ⁿ
  for (int n = 0;; ++n) {
    if (n > 0) {
      inv_fact /= n;
      two_n *= 2;
    }
    a.push_back((n % 2 == 0 ? C2 : S2) * inv_fact);
    f.push_back((n % 2 == 0 ? k.s : k.x) * inv_fact);
    c.push_back(n == 0 || n % 2 ? Real(0) : Real(two_n * inv_fact / 2));
    Real bn = 0, dn = 0, gn = 0;
    for (int i = 0; i <= n; ++i) bn += a[i] * a[n - i];
    b.push_back(bn);
    for (int i = 0; i <= n; ++i) dn += b[i] * c[n - i];
    d.push_back(dn);
    for (int i = 0; i <= n; ++i) gn += d[i] * f[n - i];
    sum += gn * psin / (n + 1);
    psin *= psi;
    // The rest of the series is at most twice its majorant's next term once 5ψ ≤ (n + 2)/2.
    major *= Real(5) / (n + 1);  // (C2² x_k/2) 5^(n+1)/(n+1)!, bounds the next coefficient of g
    if (n >= 3 && 10 * psi <= n + 2 && !(2 * major * psin / (n + 2) > eps * sum / 8)) break;
    if (n > 100000) break;
  }
  return lambda * lambda * sum;
}

}  // namespace detail_curved

// ----------------------------------------------------------------------------------- one spring

// N_w(g) = ∫₀¹ max(g + w, 0) dφ, the flat punch's normal area (units k_z A, per unit period).
template <class Real>
Real spring_normal(CatalogueWave w, const Real& g) {
  if (g >= 1) return g;
  if (!(g > -1)) return Real(0);
  const Real h = 1 + g;
  return w == CatalogueWave::square ? Real(h / 2) : Real(h * h / 4);
}

// Φ_w(β, g) = ∫₀¹ s dφ, the flat punch's friction area (units μ0 k_z A), β > 0.
template <class Real>
Real spring_friction(CatalogueWave w, const Real& beta, const Real& g) {
  using detail_curved::m_triangular;
  using detail_curved::psi_triangular;
  if (!(g > -1)) return Real(0);
  const Real h = 1 + g;
  if (w == CatalogueWave::square) {
    if (g >= 1) return beta <= 4 ? Real(g - 1 + beta / 8) : Real(g - 2 / beta);
    return 2 * h >= beta ? Real(beta / 8) : Real(h / 2 - h * h / (2 * beta));
  }
  if (g >= 1) return g - psi_triangular(w, beta);
  return m_triangular(w, beta) * h * h / 4;
}

// ------------------------------------------------------------------------------- power:n profile

// σ = xⁿ. Preconditions: n ≥ 1 (any real), β > 0, γ > −1, all finite; InputError / DomainError
// (errors.hpp) otherwise.
template <class Real>
CurvedIntegrals<Real> power_profile_integrals(CatalogueWave w, const Real& n, const Real& beta, const Real& gamma) {
  using namespace detail_curved;
  using std::isfinite;
  check_beta_gamma("power_profile_integrals", beta, gamma);
  if (!(n >= 1) || !isfinite(n))
    throw InputError("closed_form::power_profile_integrals: n = " + str(n) + ", expected a finite n >= 1");
  const Real p = 1 / n, H = 1 + gamma, X = root_n(H, n);
  // Full-range integrals ∫₀^x(A) (A − xⁿ)^k dx, x(A) = A^(1/n).
  auto A1 = [&](const Real& A, const Real& xa) -> Real { return A * xa * n / (n + 1); };
  auto A2 = [&](const Real& A, const Real& xa) -> Real { return 2 * A * A * xa * n * n / ((n + 1) * (2 * n + 1)); };
  CurvedIntegrals<Real> r;
  r.contact_radius = X;
  const bool jumping = !(gamma > 1);
  const Real c = gamma - 1, x1 = jumping ? Real(0) : root_n(c, n);
  const Real tau1 = jumping ? Real(1) : Real(2 / H), u1 = jumping ? Real(0) : Real(c / H);
  if (w != CatalogueWave::square) {
    const Real m = m_triangular(w, beta);
    if (jumping) {
      r.normal_integral = A2(H, X) / 4;
      r.friction_integral = m * r.normal_integral;
    } else {
      // core ∫₀^x₁ (γ − xⁿ) dx + shell ∫_x₁^X (H − xⁿ)²/4 dx
      r.normal_integral = x1 * (n * gamma + 1) / (n + 1) + H * H * X / n * E(2, p, tau1, u1) / 4;
      r.friction_integral = m * r.normal_integral + psi_triangular(w, beta) * A1(c, x1);
    }
  } else {
    const Real K = H - beta / 2;  // σ at the kink 1 + g = β/2
    auto kink = [&]() -> Real {   // ∫_{x_k}^X (xⁿ − K)² dx
      return H * H * X / n * F(p, Real(beta / (2 * H)), Real(K / H));
    };
    if (jumping) {
      r.normal_integral = A1(H, X) / 2;
      if (!(K > 0))
        r.friction_integral = H * X * n / (2 * (n + 1)) * (1 - 2 * H * n / (beta * (2 * n + 1)));
      else
        r.friction_integral = beta * X / 8 - kink() / (2 * beta);
    } else {
      // N/(2(N+1)) [(1+γ)^(1+1/n) + (γ−1)^(1+1/n)]: core + shell, both terms positive
      r.normal_integral = n * (H * X + c * x1) / (2 * (n + 1));
      if (beta <= 4)
        r.friction_integral = A1(c, x1) + beta * X / 8 - kink() / (2 * beta);
      else
        r.friction_integral = A1(c, x1) + (1 - 2 / beta) * x1 + H * X / n * E(1, p, tau1, u1) / 2 -
                              H * H * X / n * E(2, p, tau1, u1) / (2 * beta);
    }
  }
  r.mu = r.friction_integral / r.normal_integral;
  return r;
}

template <class Real>
Real mu_power_profile(CatalogueWave w, const Real& n, const Real& beta, const Real& gamma) {
  return power_profile_integrals(w, n, beta, gamma).mu;
}

// ---------------------------------------------------------------------------- wearflat:λ profile

// x in units of the flat radius b, σ = λ x √(x² − 1) beyond x = 1, λ = b²/(R A).
// Preconditions: λ > 0, β > 0, γ > −1, all finite; InputError / DomainError otherwise.
template <class Real>
CurvedIntegrals<Real> wearflat_integrals(CatalogueWave w, const Real& lambda, const Real& beta, const Real& gamma) {
  using namespace detail_curved;
  using std::isfinite;
  check_beta_gamma("wearflat_integrals", beta, gamma);
  if (!(lambda > 0) || !isfinite(lambda))
    throw InputError("closed_form::wearflat_integrals: lambda = " + str(lambda) + ", expected a finite lambda > 0");
  const Real H = 1 + gamma;
  const Level<Real> L0{Real(0), Real(0), Real(1), Real(0)}, Le = level(H, lambda);
  CurvedIntegrals<Real> r;
  r.contact_radius = Le.x;
  const bool jumping = !(gamma > 1);
  const Real c = gamma - 1;
  const Level<Real> L1 = jumping ? L0 : level(c, lambda);
  const Moments<Real> core = moments(L0, L1, c, lambda);      // [1, x₁]
  const Moments<Real> shell = moments(L1, Le, Real(jumping ? H : Real(2)), lambda);  // [x₁, X] (or [1, X])
  if (w != CatalogueWave::square) {
    const Real m = m_triangular(w, beta);
    if (jumping) {
      r.normal_integral = (H * H + I2(H, shell)) / 4;
      r.friction_integral = m * r.normal_integral;
    } else {
      r.normal_integral = gamma + I1(gamma, core) + I2(H, shell) / 4;
      r.friction_integral = m * r.normal_integral + psi_triangular(w, beta) * (c + I1(c, core));
    }
  } else {
    const Real K = H - beta / 2;
    auto kink = [&]() -> Real { return kink_integral(level(K, lambda), Le, Real(beta / 2), lambda); };
    if (jumping) {
      r.normal_integral = (H + I1(H, shell)) / 2;
      if (!(K > 0))
        r.friction_integral = H / 2 - H * H / (2 * beta) + I1(H, shell) / 2 - I2(H, shell) / (2 * beta);
      else
        r.friction_integral = beta * Le.x / 8 - kink() / (2 * beta);
    } else {
      r.normal_integral = gamma + I1(gamma, core) + I1(H, shell) / 2;
      if (beta <= 4)
        r.friction_integral = c + I1(c, core) + beta * Le.x / 8 - kink() / (2 * beta);
      else
        r.friction_integral =
            c + I1(c, core) + (1 - 2 / beta) * L1.x + I1(H, shell) / 2 - I2(H, shell) / (2 * beta);
    }
  }
  r.mu = r.friction_integral / r.normal_integral;
  return r;
}

template <class Real>
Real mu_wearflat(CatalogueWave w, const Real& lambda, const Real& beta, const Real& gamma) {
  return wearflat_integrals(w, lambda, beta, gamma).mu;
}

}  // namespace vibrofric::closed_form
