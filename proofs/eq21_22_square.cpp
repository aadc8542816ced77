// Eqs. 21-22: square wave in the jumping range -1 < gamma < 1:
//   mu/mu0 = beta/(4(1+gamma)) for beta < 2(1+gamma), 1 - (1+gamma)/beta for beta > 2(1+gamma),
// continuous at beta = 2(1+gamma), and = 1 - Psi_sqr(xi), xi = 2 beta/(1+gamma), where Psi_sqr is
// derived here from the non-jumping square wave (quoted: 1 - xi/8 for xi <= 4, 2/xi for xi >= 4).
#include "engine.hpp"
using namespace proofs;

int main() {
  Checker ck;
  const ex b = B(), g = G();
  const ex xi = 2 * b / (1 + g);
  Regime RA = make_regime("0 < beta < 2(1+gamma), -1 < gamma < 1", {{0, -1}, {0, 1}, {4, 1}});
  Regime RB = make_regime("beta > 2(1+gamma), -1 < gamma < 1", {{0, -1}, {4, 1}}, {{1, 0}});
  Result A = run(clip(wave("sqr"), g, RA), b, RA);
  Result Bq = run(clip(wave("sqr"), g, RB), b, RB);
  print_run("sqr jumping, branch A", A, RA);
  print_run("sqr jumping, branch B", Bq, RB);
  const ex pA = b / (4 * (1 + g)), pB = 1 - (1 + g) / b;
  ck.zero(A.mu - pA, "Eq. 22 branch beta < 2(1+gamma): mu/mu0 = beta/(4(1+gamma))");
  ck.zero(Bq.mu - pB, "Eq. 22 branch beta > 2(1+gamma): mu/mu0 = 1 - (1+gamma)/beta");
  ck.zero(A.mu.subs(b == 2 * (1 + g)) - Bq.mu.subs(b == 2 * (1 + g)),
          "continuity at beta = 2(1+gamma) (both branches give " + ex_to_string(normal(A.mu.subs(b == 2 * (1 + g)))) + ")");
  // on the threshold line itself (beta = 2(1+gamma) exactly), run the construction there too
  Regime RT = make_regime("beta = 2(1+gamma), -1 < gamma < 1", {{0, -1}, {4, 1}});
  Result T = run(clip(wave("sqr"), g, RT), 2 * (1 + g), RT);
  ck.zero(T.mu - pA.subs(b == 2 * (1 + g)), "on the threshold line the construction gives the common value");

  // Psi_sqr from the non-jumping square wave (gamma > 1), two branches in beta
  Regime N1 = make_regime("0 < beta < 4, gamma > 1", {{0, 1}, {4, 1}}, {{0, 1}});
  Regime N2 = make_regime("beta > 4, gamma > 1", {{4, 1}}, {{1, 0}, {0, 1}});
  Result P1 = run(clip(wave("sqr"), g, N1), b, N1), P2 = run(clip(wave("sqr"), g, N2), b, N2);
  print_run("sqr non-jumping, beta < 4", P1, N1);
  print_run("sqr non-jumping, beta > 4", P2, N2);
  ck.zero(P1.Red - (1 - b / 8), "Psi_sqr(x) = 1 - x/8 for x < 4 (Eq. 36 of [10], as quoted)");
  ck.zero(P2.Red - 2 / b, "Psi_sqr(x) = 2/x for x > 4");
  ck.zero(diff(P1.Red, G()), "Psi_sqr independent of gamma (branch x < 4)");
  ck.zero(diff(P2.Red, G()), "Psi_sqr independent of gamma (branch x > 4)");
  // regime mapping: beta < 2(1+gamma)  <=>  xi < 4
  ck.ok(decide(xi - 4, RA, "xi - 4 on branch A") < 0, "xi < 4 throughout branch A (proved sign)");
  ck.ok(decide(xi - 4, RB, "xi - 4 on branch B") > 0, "xi > 4 throughout branch B (proved sign)");
  ck.zero(A.mu - (1 - P1.Red.subs(b == xi)), "Eq. 20-21 branch A: mu/mu0 = 1 - Psi_sqr(2 beta/(1+gamma))");
  ck.zero(Bq.mu - (1 - P2.Red.subs(b == xi)), "Eq. 20-21 branch B: mu/mu0 = 1 - Psi_sqr(2 beta/(1+gamma))");

  // wrong variants
  ck.nonzero(A.mu - (1 - P1.Red.subs(b == 2 * b / (1 - g))), "xi = 2 beta/(1-gamma)");
  ck.nonzero(A.mu - (1 - P1.Red.subs(b == b / (1 + g))), "xi = beta/(1+gamma)");
  ck.nonzero(A.mu - b / (4 * (1 - g)), "branch A = beta/(4(1-gamma))");
  ck.nonzero(Bq.mu - (1 + (1 + g) / b), "branch B = 1 + (1+gamma)/beta");
  ck.throws([&] {
    Regime W = make_regime("0 < beta < 2(1-gamma), -1 < gamma < 1  (wrong threshold)", {{0, -1}, {4, -1}, {0, 1}});
    run(clip(wave("sqr"), g, W), b, W);
  }, "threshold 2(1-gamma): the construction is not uniform on {beta < 2(1-gamma)}");
  ck.throws([&] {
    Regime W = make_regime("0 < beta < 4, -1 < gamma < 1  (threshold ignoring gamma)", {{0, -1}, {0, 1}, {4, 1}, {4, -1}});
    run(clip(wave("sqr"), g, W), b, W);
  }, "threshold beta < 4 independent of gamma");
  print_conditions();
  return ck.finish("proof.eq21_22_square");
}
