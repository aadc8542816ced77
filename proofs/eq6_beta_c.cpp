// Eq. 6: stick occurs iff beta < beta_c, the largest rising slope of n (infinite with an upward
// jump). Checked for the catalogue waves in both gamma ranges, including beta = beta_c exactly.
#include "engine.hpp"
using namespace proofs;

int main() {
  Checker ck;
  const ex b = B(), g = G();
  struct GR { std::string txt; numeric g0, g1; bool ray; };
  std::vector<GR> granges = {{"gamma > 1", 1, 1, true}, {"-1 < gamma < 1", -1, 1, false}};
  auto regime = [&](const std::string& btxt, numeric b0, numeric b1, bool bray, const GR& gr) {
    std::vector<std::pair<numeric, numeric>> v, r;
    if (gr.ray) { v = {{b0, gr.g0}}; if (!(b1 == b0)) v.push_back({b1, gr.g0}); r.push_back({0, 1}); }
    else { v = {{b0, gr.g0}, {b0, gr.g1}}; if (!(b1 == b0)) { v.push_back({b1, gr.g1}); v.push_back({b1, gr.g0}); } }
    if (bray) r.push_back({1, 0});
    return make_regime(btxt + ", " + gr.txt, v, r);
  };
  // finite beta_c: str (2) and tri (4)
  for (auto w : {std::pair<std::string, numeric>{"str", 2}, {"tri", 4}}) {
    numeric bc = w.second;
    std::string s = ex_to_string(bc);
    for (auto& gr : granges) {
      Regime above = regime("beta > " + s, bc, bc, true, gr);
      Result r = run(clip(wave(w.first), g, above), b, above);
      ck.ok(r.sticks == 0 && normal(r.Red).is_zero() && normal(r.mu - 1).is_zero(),
            w.first + ": no stick, mu = mu0 for beta > " + s + ", " + gr.txt);
      Regime at = regime("beta = " + s, bc, bc, false, gr);
      Result ra = run(clip(wave(w.first), g, at), ex(bc), at);
      ck.ok(ra.sticks == 0 && normal(ra.mu - 1).is_zero(), w.first + ": no stick at beta = beta_c = " + s + ", " + gr.txt);
      Regime below = regime("0 < beta < " + s, 0, bc, false, gr);
      Result rb = run(clip(wave(w.first), g, below), b, below);
      ck.ok(rb.sticks == 1 && decide(rb.Red, below, "int(n-s) below beta_c") > 0,
            w.first + ": stick and int(n - s) > 0 (proved sign) for 0 < beta < " + s + ", " + gr.txt);
      // wrong variant: a smaller critical value beta_c/2 would claim no stick on (beta_c/2, beta_c)
      Regime wrong = regime(ex_to_string(bc / 2) + " < beta < " + s, bc / 2, bc, false, gr);
      Result rw = run(clip(wave(w.first), g, wrong), b, wrong);
      ck.ok(rw.sticks > 0 && !normal(rw.Red).is_zero(),
            "wrong variant rejected: beta_c = " + ex_to_string(bc / 2) + " for " + w.first + " (stick found above it), " + gr.txt);
    }
  }
  // beta_c infinite (upward jump): stl, sqr -- stick for every beta > 0
  for (std::string w : {"stl", "sqr"})
    for (auto& gr : granges) {
      // for sqr the jumping construction splits at beta = 2(1+gamma), the non-jumping one at 4
      std::vector<Regime> rs;
      if (w == "stl") rs.push_back(regime("beta > 0", 0, 0, true, gr));
      else if (gr.ray) { rs.push_back(regime("0 < beta < 4", 0, 4, false, gr)); rs.push_back(regime("beta > 4", 4, 4, true, gr)); }
      else {
        rs.push_back(make_regime("0 < beta < 2(1+gamma), -1 < gamma < 1", {{0, -1}, {0, 1}, {4, 1}}));
        rs.push_back(make_regime("beta > 2(1+gamma), -1 < gamma < 1", {{0, -1}, {4, 1}}, {{1, 0}}));
      }
      for (auto& R : rs) {
        Result r = run(clip(wave(w), g, R), b, R);
        ck.ok(r.sticks == 1 && decide(r.Red, R, "int(n-s)") > 0 && decide(1 - r.mu, R, "1 - mu") > 0,
              w + ": stick, mu < mu0 (proved sign) for " + R.text + "  (beta_c = infinity)");
      }
    }
  print_conditions();
  return ck.finish("proof.eq6_beta_c");
}
