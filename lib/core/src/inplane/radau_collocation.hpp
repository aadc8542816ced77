// The s-stage Radau IIA collocation method (order 2s − 1, stiffly accurate and L-stable) for the
// slip equation of core/inplane/planar.hpp, built with the s-point Gauss–Legendre rule, and a
// dense linear solve for its Newton steps.
#pragma once
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <boost/math/special_functions/legendre.hpp>
#include <boost/math/tools/precision.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include "vibrofric/core/detail/gauss_legendre.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric::detail {

// Radau IIA: nodes c_i = (1 + x_i)/2 with x_i the zeros of P_s − P_{s−1} (x_s = 1; one zero
// between each two neighbouring zeros of P_s, where P_s − P_{s−1} = −P_{s−1} alternates in sign),
// A_ij = ∫₀^{c_i} ℓ_j by the s-point Gauss rule (exact for the degree s − 1 of ℓ_j), b_j = A_sj.
// Built once per thread, precision and s (radau_tableau below).
template <class Real>
struct RadauTableau {
  int s = 0;
  std::vector<Real> c, b, a;  // a row-major s × s

  explicit RadauTableau(int stages) : s(stages) {
    const GaussRule<Real>& gauss = gauss_legendre<Real>(static_cast<std::size_t>(s));  // nodes ascending
    const auto f = [&](const Real& x) {
      return boost::math::legendre_p<Real>(s, x) - boost::math::legendre_p<Real>(s - 1, x);
    };
    const int bits = boost::math::tools::digits<Real>();
    for (int k = 0; k + 1 < s; ++k) {
      const Real lo = 2 * gauss.nodes[static_cast<std::size_t>(k)] - 1, hi = 2 * gauss.nodes[static_cast<std::size_t>(k + 1)] - 1;
      std::uintmax_t it = 400;
      const auto r = boost::math::tools::toms748_solve(f, lo, hi, f(lo), f(hi),
                                                       boost::math::tools::eps_tolerance<Real>(static_cast<unsigned>(bits)), it);
      if (it >= 400) throw SolverError("Radau node " + std::to_string(k) + " of " + std::to_string(s) + " did not converge");
      using std::abs;
      const Real x = abs(f(r.first)) <= abs(f(r.second)) ? r.first : r.second;
      c.push_back((1 + x) / 2);
    }
    c.push_back(Real(1));
    a.assign(static_cast<std::size_t>(s * s), Real(0));
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        Real sum = 0;
        for (int k = 0; k < s; ++k) {
          const Real t = c[static_cast<std::size_t>(i)] * gauss.nodes[static_cast<std::size_t>(k)];
          Real l = 1;
          for (int m = 0; m < s; ++m)
            if (m != j) l *= (t - c[static_cast<std::size_t>(m)]) / (c[static_cast<std::size_t>(j)] - c[static_cast<std::size_t>(m)]);
          sum += gauss.weights[static_cast<std::size_t>(k)] * l;
        }
        a[static_cast<std::size_t>(i * s + j)] = c[static_cast<std::size_t>(i)] * sum;
      }
    b.assign(a.end() - s, a.end());
  }
  const Real& A(int i, int j) const { return a[static_cast<std::size_t>(i * s + j)]; }
};

template <class Real>
const RadauTableau<Real>& radau_tableau(int stages) {
  thread_local std::map<std::pair<int, int>, RadauTableau<Real>> cache;
  const std::pair<int, int> key{working_digits10<Real>(), stages};
  if (const auto hit = cache.find(key); hit != cache.end()) return hit->second;
  return cache.emplace(key, RadauTableau<Real>(stages)).first->second;
}

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
