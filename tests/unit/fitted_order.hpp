// The observed order of convergence of a sequence of errors: shared by the second-algorithm and
// spring-row tests.
#pragma once
#include <cmath>
#include <vector>

// −(least-squares slope of log e against log N): the observed order p in e ≈ C·N^−p.
inline double fitted_order(const std::vector<double>& n, const std::vector<double>& e) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    mx += std::log(n[i]) / n.size();
    my += std::log(e[i]) / n.size();
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    sxy += (std::log(n[i]) - mx) * (std::log(e[i]) - my);
    sxx += (std::log(n[i]) - mx) * (std::log(n[i]) - mx);
  }
  return -sxy / sxx;
}
