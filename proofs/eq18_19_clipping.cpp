// Eqs. 18-19: in the jumping range -1 < gamma < 1 (and gamma = 1), for the triangular waves
// mu/mu0 = beta/2 (str, beta < 2), beta/(2+beta) (stl), 2 beta/(4+beta) (tri, beta < 4),
// independent of gamma and equal to the non-jumping value at gamma = 1, 1 - Psi_w(beta).
#include "engine.hpp"
using namespace proofs;

int main() {
  Checker ck;
  const ex b = B(), g = G();
  struct Case { std::string w; numeric bc; ex paper; ex wrong; std::string wrong_txt; };
  std::vector<Case> cases = {
      {"str", 2, b / 2, b / (2 + b), "beta/(2+beta)"},
      {"stl", 0, b / (2 + b), b / (2 - b), "beta/(2-beta)"},
      {"tri", 4, 2 * b / (4 + b), 2 * b / (4 - b), "2beta/(4-beta)"},
  };
  for (auto& c : cases) {
    std::string bc = ex_to_string(c.bc);
    Regime R = c.bc.is_zero() ? make_regime("beta > 0, -1 < gamma < 1", {{0, -1}, {0, 1}}, {{1, 0}})
                              : make_regime("0 < beta < " + bc + ", -1 < gamma < 1",
                                            {{0, -1}, {0, 1}, {c.bc, 1}, {c.bc, -1}});
    Result r = run(clip(wave(c.w), g, R), b, R);
    print_run(c.w + " (jumping)", r, R);
    ck.zero(r.mu - c.paper, "Eq. 19 mu_" + c.w + "/mu0 = " + ex_to_string(c.paper) + " on " + R.text);
    ck.zero(diff(r.mu, G()), "gamma cancels in mu_" + c.w);
    ck.nonzero(r.mu - c.wrong, "mu_" + c.w + "/mu0 = " + c.wrong_txt);
    // Eq. 18: equal to the value at gamma = 1, computed independently (non-jumping run there)
    Regime R1 = c.bc.is_zero() ? make_regime("beta > 0, gamma = 1", {{0, 1}}, {{1, 0}})
                               : make_regime("0 < beta < " + bc + ", gamma = 1", {{0, 1}, {c.bc, 1}});
    Result r1 = run(clip(wave(c.w), ex(1), R1), b, R1);
    ck.zero(r.mu - (1 - r1.Red), "Eq. 18 mu(beta, gamma) = mu(beta, 1) = 1 - Psi_" + c.w + "(beta)");
    // control: the non-jumping formula 1 - Psi/gamma does NOT hold once n is clipped
    ck.nonzero(r.mu - (1 - r1.Red / g), "Eq. 13 (1 - Psi/gamma) carried into the jumping range for " + c.w);
    // control: clipping actually happened (contact point depends on gamma)
    bool contact = false;
    for (auto& e : r.events) if (e.at.has(g)) contact = true;
    ck.ok(contact, "an event of the construction depends on gamma (clipping is active) for " + c.w);
  }
  print_conditions();
  return ck.finish("proof.eq18_19_clipping");
}
