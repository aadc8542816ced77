// Small-beta behaviour of Psi_w (non-jumping, gamma > 1):
//   Psi_w(0+) = int n - min n = mean(w) - min(w)  (= 1 for the catalogue),
//   dPsi/dbeta(0+) = -(1/2) sum_i l_i^2, l_i the lengths of the gaps between the phases where
//   n attains its minimum (one isolated minimum per period: -1/2).
// The prediction is computed from the geometry of n; Psi is derived by the stick-slip construction.
#include "engine.hpp"
using namespace proofs;

// -(1/2) sum of squared gap lengths of the minimum set of n (unit period), from the segments.
static ex gap_prediction(const Wave& n, const Regime& R, ex& nmin) {
  nmin = n[0].a;
  for (auto& s : n) {
    ex c0 = s.a, c1 = s.a + s.m * (s.x1 - s.x0);
    if (decide(c0 - nmin, R, "min") < 0) nmin = c0;
    if (decide(c1 - nmin, R, "min") < 0) nmin = c1;
  }
  std::vector<std::pair<ex, ex>> M;  // closed intervals (points when lo == hi), in phase order
  for (auto& s : n) {
    bool z0 = normal(s.a - nmin).is_zero(), z1 = normal(s.a + s.m * (s.x1 - s.x0) - nmin).is_zero();
    if (z0 && z1) M.push_back({s.x0, s.x1});
    else if (z0) M.push_back({s.x0, s.x0});
    else if (z1) M.push_back({s.x1, s.x1});
  }
  ex sum = 0;
  for (size_t i = 0; i < M.size(); ++i) {
    ex next_lo = (i + 1 < M.size()) ? M[i + 1].first : M[0].first + 1;
    ex gap = normal(next_lo - M[i].second);
    sum += gap * gap;
  }
  return normal(-sum / 2);
}

int main() {
  Checker ck;
  const ex b = B(), g = G();
  struct Case { std::string w, label; numeric bmax; };  // bmax: end of the first beta branch
  std::vector<Case> cases = {{"tri", "tri", 4}, {"str", "str", 2}, {"stl", "stl", 0},
                             {"sqr", "sqr", 4}, {"tri2", "tri2 (two minima per period)", 8}};
  for (auto& c : cases) {
    Regime R = c.bmax.is_zero() ? make_regime("beta > 0, gamma > 1", {{0, 1}}, {{1, 0}, {0, 1}})
                                : make_regime("0 < beta < " + ex_to_string(c.bmax) + ", gamma > 1",
                                              {{0, 1}, {c.bmax, 1}}, {{0, 1}});
    Wave n = clip(wave(c.w), g, R);
    Result r = run(n, b, R);
    print_run(c.label, r, R);
    ex nmin, slope_pred = gap_prediction(n, R, nmin);
    ex psi0 = normal(r.Red.subs(b == 0));
    ck.ok(!normal(denom(normal(r.Red)).subs(b == 0)).is_zero(), "Psi_" + c.w + " is a rational function regular at beta = 0 (so the limit is the value)");
    ck.zero(psi0 - (r.In - nmin), "Psi_" + c.w + "(0+) = int n - min n");
    ck.zero(psi0 - 1, "Psi_" + c.w + "(0+) = 1 (mean 0, min -1)");
    ex slope = normal(diff(r.Red, B()).subs(b == 0));
    ck.zero(slope - slope_pred, "dPsi_" + c.w + "/dbeta(0+) = " + ex_to_string(slope) +
                                    " = -(1/2) sum gap^2 (prediction " + ex_to_string(slope_pred) + ")");
    if (!normal(slope + numeric(1, 2)).is_zero())
      ck.nonzero(slope + numeric(1, 2), "universal slope -1/2 for " + c.w);
    ck.nonzero(psi0 - 1 - numeric(1, 2), "Psi(0+) = 3/2 for " + c.w);
  }
  print_conditions();
  return ck.finish("proof.psi_small_beta");
}
