// The s-stage Gauss–Legendre collocation method (order 2s) for the linear slip system of
// core/inplane/planar.hpp, y' = M(t) y with y = (u, v), and the quadratures on its stages.
#pragma once
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <boost/math/special_functions/legendre.hpp>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric::detail {

// Nodes c_i, weights b_i on [0, 1] and A_ij = ∫₀^{c_i} ℓ_j (ℓ_j the Lagrange basis of the nodes).
template <class Real>
struct GaussTableau {
  int s = 0;
  std::vector<Real> c, b, a;  // a row-major s × s

  explicit GaussTableau(int stages) : s(stages) {
    using std::abs;
    // The zeros of P_s on [0, 1] and their weights 2 / ((1 − x²) P_s'(x)²), mapped to [0, 1].
    const std::vector<Real> zeros = boost::math::legendre_p_zeros<Real>(s);
    std::vector<Real> x;
    for (auto it = zeros.rbegin(); it != zeros.rend(); ++it)
      if (*it != 0) x.push_back(-*it);
    for (const Real& z : zeros) x.push_back(z);
    if (static_cast<int>(x.size()) != s) throw SolverError("Gauss-Legendre nodes: " + std::to_string(x.size()) +
                                                           " zeros of P_" + std::to_string(s));
    for (const Real& z : x) {
      const Real d = boost::math::legendre_p_prime<Real>(s, z);
      c.push_back((1 + z) / 2);
      b.push_back(1 / ((1 - z * z) * d * d));
    }
    // ∫₀^{c_i} ℓ_j = c_i Σ_k b_k ℓ_j(c_i c_k): the s-point rule is exact for the degree s − 1 of ℓ_j.
    a.assign(static_cast<std::size_t>(s * s), Real(0));
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        Real sum = 0;
        for (int k = 0; k < s; ++k) {
          const Real t = c[i] * c[k];
          Real l = 1;
          for (int m = 0; m < s; ++m)
            if (m != j) l *= (t - c[m]) / (c[j] - c[m]);
          sum += b[k] * l;
        }
        a[static_cast<std::size_t>(i * s + j)] = c[i] * sum;
      }
  }
  const Real& A(int i, int j) const { return a[static_cast<std::size_t>(i * s + j)]; }
};

// Solves K x = r in place (K n × n row-major, partial pivoting); false where K is singular.
template <class Real>
bool solve_linear(std::vector<Real>& K, std::vector<Real>& r, int n) {
  using std::abs;
  using std::swap;
  for (int col = 0; col < n; ++col) {
    int piv = col;
    for (int row = col + 1; row < n; ++row)
      if (abs(K[static_cast<std::size_t>(row * n + col)]) > abs(K[static_cast<std::size_t>(piv * n + col)])) piv = row;
    if (K[static_cast<std::size_t>(piv * n + col)] == 0) return false;
    if (piv != col) {
      for (int k = 0; k < n; ++k) swap(K[static_cast<std::size_t>(piv * n + k)], K[static_cast<std::size_t>(col * n + k)]);
      swap(r[static_cast<std::size_t>(piv)], r[static_cast<std::size_t>(col)]);
    }
    const Real p = K[static_cast<std::size_t>(col * n + col)];
    for (int row = col + 1; row < n; ++row) {
      const Real f = K[static_cast<std::size_t>(row * n + col)] / p;
      if (f == 0) continue;
      for (int k = col; k < n; ++k) K[static_cast<std::size_t>(row * n + k)] -= f * K[static_cast<std::size_t>(col * n + k)];
      r[static_cast<std::size_t>(row)] -= f * r[static_cast<std::size_t>(col)];
    }
  }
  for (int row = n - 1; row >= 0; --row) {
    Real sum = r[static_cast<std::size_t>(row)];
    for (int k = row + 1; k < n; ++k) sum -= K[static_cast<std::size_t>(row * n + k)] * r[static_cast<std::size_t>(k)];
    r[static_cast<std::size_t>(row)] = sum / K[static_cast<std::size_t>(row * n + row)];
  }
  return true;
}

}  // namespace vibrofric::detail
