// Eq. 17: Psi_str = 1 - beta/2 (0<beta<2), Psi_stl = 2/(2+beta) (beta>0),
// Psi_tri = (4-beta)/(4+beta) (0<beta<4), non-jumping (gamma > 1, and gamma = 1 separately).
#include "engine.hpp"
using namespace proofs;

int main() {
  Checker ck;
  const ex b = B(), g = G();
  struct Case { std::string w; numeric bc; ex paper; ex wrong; std::string wrong_txt; };
  std::vector<Case> cases = {
      {"str", 2, 1 - b / 2, 1 + b / 2, "1 + beta/2 (flipped sign)"},
      {"stl", 0, 2 / (2 + b), 2 / (2 - b), "2/(2 - beta) (flipped sign)"},
      {"tri", 4, (4 - b) / (4 + b), (4 + b) / (4 - b), "(4+beta)/(4-beta) (inverted)"},
  };
  for (auto& c : cases) {
    // regime gamma > 1, 0 < beta < beta_c (beta_c = infinity for stl)
    Regime R = c.bc.is_zero()
        ? make_regime("beta > 0, gamma > 1", {{0, 1}}, {{1, 0}, {0, 1}})
        : make_regime("0 < beta < " + ex_to_string(c.bc) + ", gamma > 1", {{0, 1}, {c.bc, 1}}, {{0, 1}});
    Result r = run(clip(wave(c.w), g, R), b, R);
    print_run(c.w, r, R);
    ck.zero(r.Red - c.paper, "Eq. 17 Psi_" + c.w + " = " + ex_to_string(c.paper) + " on " + R.text);
    ck.ok(r.sticks == 1, "exactly one stick phase per period (" + c.w + ")");
    ck.nonzero(r.Red - c.wrong, "Psi_" + c.w + " = " + c.wrong_txt);
    // boundary gamma = 1 (n touches zero at its minimum)
    Regime R1 = c.bc.is_zero() ? make_regime("beta > 0, gamma = 1", {{0, 1}}, {{1, 0}})
                               : make_regime("0 < beta < " + ex_to_string(c.bc) + ", gamma = 1", {{0, 1}, {c.bc, 1}});
    Result r1 = run(clip(wave(c.w), ex(1), R1), b, R1);
    print_run(c.w + " at gamma = 1", r1, R1);
    ck.zero(r1.Red - c.paper, "Eq. 17 Psi_" + c.w + " also at gamma = 1");
  }
  print_conditions();
  return ck.finish("proof.eq17_triangular_psi");
}
