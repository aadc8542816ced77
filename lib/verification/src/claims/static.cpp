// Sec. 3: in the jumping range the static coefficient of friction — the limit of μ̄ as the sliding
// velocity β → 0 — is zero. Derived rate: as β → 0 stick starts at first contact and its ramp
// βτ ends just before contact ends, so ∫s = β Σ L_i²/2 + o(β) over the contact intervals of
// lengths L_i, and μ̄/μ0 = β Σ L_i² / (2∫n) + o(β). The correction is O(β²) where n leaves zero
// with a nonzero slope and O(β^{3/2}) where it touches zero (γ = −min w).
#include "check.hpp"

namespace vibrofric::claims {

namespace {

// Contact length L and ∫n of each wave for −1 < γ ≤ 1 (one contact interval per period).
struct Slope {
  const char* wave;
  Real (*slope)(const Real& gamma);  // L² / (2∫n)
  bool jumping_only_cap;             // power:p — the closed form needs γ ≤ 0 (contact inside the cap)
};

Real sine_slope(const Real& gamma) {
  const Real pi = boost::math::constants::pi<Real>();
  const Real uc = acos(-gamma) / (2 * pi);
  const Real L = 2 * uc, area = 2 * gamma * uc + sqrt(1 - gamma * gamma) / pi;
  return L * L / (2 * area);
}
Real half(const Real&) { return Real(1) / 2; }  // tri, str, stl: L = (1+γ)/2, ∫n = (1+γ)²/4
Real square_slope(const Real& gamma) { return 1 / (4 * (1 + gamma)); }
// power:p cap: L = h^{1/p}/2, ∫n = h^{(p+1)/p} p/(2(p+1)), h = 1 + γ.
template <int P>
Real power_slope(const Real& gamma) {
  const Real p(P), h = 1 + gamma;
  return (p + 1) / (4 * p) * pow(h, (1 - p) / p);
}

}  // namespace

ClaimCheck sec3(int digits) {
  Check c(entry("sec3"), digits);
  c.unit("relative, of mu/beta against the derived slope");
  const std::string tiny = "1e-" + std::to_string(2 * digits + 4);
  c.out().how = "sine, tri, str, stl, square (gamma = -0.9, -0.5, 0, 0.5, 0.9, 1) and power:2, power:3 (gamma = -0.9, "
                "-0.5, 0): mu(beta)/beta at beta = " + tiny + " against the derived slope sum L_i^2/(2 int n) "
                "(relative; the O(beta^(1/2)) correction at gamma = 1 is below the threshold at this beta)";
  c.out().corrected = "the static coefficient is zero with mu/mu0 = beta sum L_i^2 / (2 int_0^1 n) + o(beta) (L_i: contact "
                      "intervals); without jumping (gamma > 1) it is 1 - 1/gamma, not zero";
  const std::vector<Slope> waves{{"sine", sine_slope, false},           {"triangle", half, false},
                                 {"sawtooth-right", half, false},       {"sawtooth-left", half, false},
                                 {"square", square_slope, false},       {"power:2", power_slope<2>, true},
                                 {"power:3", power_slope<3>, true}};
  c.numerical("a limit (beta -> 0): enclosures at finitely many beta bound mu there but not its limit; the limit "
              "itself is proofs/sec3_static.md's derivation");
  const Real beta = Real(tiny.c_str());
  double order_worst = 1e9;
  for (const auto& w : waves) {
    Solver s(w.wave, digits);
    for (const Real& gamma : reals({"-0.9", "-0.5", "0", "0.5", "0.9", "1"})) {
      if (w.jumping_only_cap && gamma > 0) continue;
      const Real slope = w.slope(gamma);
      c.compare(s.mu(beta, gamma) / beta, slope, at(w.wave, beta, &gamma) + " (mu/beta)");
      // The approach: relative deviation of μ/β at β = 1e-3 and 1e-4 gives the order of the correction.
      if (gamma < 1) {
        const double d3 = Check::deviation(s.mu(num("1e-3"), gamma) / num("1e-3"), slope);
        const double d4 = Check::deviation(s.mu(num("1e-4"), gamma) / num("1e-4"), slope);
        // Exact forms (str, sqr) have no correction: only rounding, below 10^-digits.
        if (d3 > std::pow(10.0, -digits) && d4 > std::pow(10.0, -digits)) order_worst = std::min(order_worst, std::log10(d3 / d4));
      }
    }
  }
  char o[48];
  std::snprintf(o, sizeof o, "%.3f", order_worst);
  c.measure("smallest order of (mu/beta - slope) in beta over the jumping cases gamma < 1 (beta 1e-3 -> 1e-4)", o);
  for (const char* g : {"1.5", "3"}) {
    Solver s("sine", digits);
    const Real gamma = num(g);
    const std::string mu = str(s.mu(num("1e-30"), gamma), 12), limit = str(1 - 1 / gamma, 12);
    c.measure("no jumping, sine, gamma = " + std::string(g) + ": mu(beta = 1e-30)", mu + " (1 - 1/gamma = " + limit + ")",
              {{"mu", mu}, {"one_minus_one_over_gamma", limit}});
  }
  return c.finish_exact();
}

}  // namespace vibrofric::claims
