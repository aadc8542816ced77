// The 3×3 algebra of the rig's one-period map (core/dynamics/dynamics.hpp): Newton's linear solve and the
// largest Floquet multiplier of the map's Jacobian.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace vibrofric {
namespace detail {

// Gaussian elimination with partial pivoting of a 3×3 system [A | b]; false if singular.
template <class Real>
bool solve3(std::array<std::array<Real, 4>, 3>& M, std::array<Real, 3>& d) {
  using std::abs;
  for (int c = 0; c < 3; ++c) {
    int piv = c;
    for (int i = c + 1; i < 3; ++i)
      if (abs(M[i][c]) > abs(M[piv][c])) piv = i;
    std::swap(M[c], M[piv]);
    if (M[c][c] == 0) return false;
    for (int i = c + 1; i < 3; ++i) {
      const Real f = M[i][c] / M[c][c];
      for (int j = c; j < 4; ++j) M[i][j] -= f * M[c][j];
    }
  }
  for (int i = 2; i >= 0; --i) {
    Real acc = M[i][3];
    for (int j = i + 1; j < 3; ++j) acc -= M[i][j] * d[j];
    d[i] = acc / M[i][i];
  }
  return true;
}

// Largest |λ| of the 3×3 Jacobian (in double: a stability indicator, not a result digit).
inline double largest_multiplier(const std::array<std::array<double, 3>, 3>& J) {
  double m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = J[i][j];
  const double tr = m[0][0] + m[1][1] + m[2][2];
  const double m2 = m[0][0] * m[1][1] - m[0][1] * m[1][0] + m[0][0] * m[2][2] - m[0][2] * m[2][0] +
                    m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  // λ³ − tr λ² + m2 λ − det: one real root by bisection, then the quadratic.
  auto p = [&](double x) { return ((x - tr) * x + m2) * x - det; };
  double bound = 1 + std::max({std::abs(tr), std::abs(m2), std::abs(det)});
  double lo = -bound, hi = bound;
  for (int it = 0; it < 200; ++it) {
    const double mid = (lo + hi) / 2;
    if ((p(mid) > 0) == (p(hi) > 0)) hi = mid; else lo = mid;
  }
  const double r = (lo + hi) / 2;
  // λ² + (r − tr) λ + (m2 + r(r − tr)) = 0
  const double b = r - tr, c = m2 + r * (r - tr);
  const double disc = b * b - 4 * c;
  double big = std::abs(r);
  if (disc >= 0) {
    big = std::max({big, std::abs((-b + std::sqrt(disc)) / 2), std::abs((-b - std::sqrt(disc)) / 2)});
  } else {
    big = std::max(big, std::sqrt(std::max(0.0, c)));
  }
  return big;
}

}  // namespace detail
}  // namespace vibrofric
