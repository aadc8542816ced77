// Eq. 13 (with Eqs. 11-12): without jumping (gamma > 1 for the catalogue waves) the reduction
// int (n - s) does not depend on gamma, int n = gamma, hence mu/mu0 = 1 - Psi_w(beta)/gamma.
#include "engine.hpp"
using namespace proofs;

int main() {
  Checker ck;
  const ex b = B(), g = G();
  struct Case { std::string w, label; Regime R; };
  std::vector<Case> cases = {
      {"tri", "tri", make_regime("0 < beta < 4, gamma > 1", {{0, 1}, {4, 1}}, {{0, 1}})},
      {"str", "str", make_regime("0 < beta < 2, gamma > 1", {{0, 1}, {2, 1}}, {{0, 1}})},
      {"stl", "stl", make_regime("beta > 0, gamma > 1", {{0, 1}}, {{1, 0}, {0, 1}})},
      {"sqr", "sqr (beta < 4)", make_regime("0 < beta < 4, gamma > 1", {{0, 1}, {4, 1}}, {{0, 1}})},
      {"sqr", "sqr (beta > 4)", make_regime("beta > 4, gamma > 1", {{4, 1}}, {{1, 0}, {0, 1}})},
  };
  for (auto& c : cases) {
    Result r = run(clip(wave(c.w), g, c.R), b, c.R);
    print_run(c.label, r, c.R);
    ck.zero(diff(r.Red, G()), "d/dgamma int(n - s) = 0 for " + c.label + " (Psi independent of gamma)");
    ck.zero(r.In - g, "int n = gamma for " + c.label);
    ck.zero(r.mu - (1 - r.Red / g), "Eq. 13: mu/mu0 = 1 - Psi/gamma for " + c.label);
    ck.nonzero(r.mu - (1 - r.Red * g), "mu/mu0 = 1 - Psi*gamma for " + c.label);
  }
  // Non-vacuity of the gamma-independence test: in the jumping range it must detect dependence.
  {
    Regime R = make_regime("0 < beta < 2(1+gamma), -1 < gamma < 1", {{0, -1}, {0, 1}, {4, 1}});
    Result r = run(clip(wave("sqr"), g, R), b, R);
    print_run("sqr, jumping (control)", r, R);
    ck.nonzero(diff(r.Red, G()), "int(n - s) independent of gamma for the clipped square wave");
  }
  print_conditions();
  return ck.finish("proof.eq13_gamma_independence");
}
