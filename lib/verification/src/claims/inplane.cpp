// In-plane oscillation (model.md, "In-plane and combined oscillation"), the longitudinal case,
// decided with the in-plane solver (core/inplane/inplane.hpp) at min(D, 30) digits:
//
// - Rigid limit (model.md): n ≡ 1, sine, a → ∞ at fixed ξ = β/(2πa): μ̄ → (2/π) arcsin ξ for ξ < 1,
//   μ̄ = μ0 for ξ ≥ 1 (a critical velocity). The finite contact stiffness (finite a) raises μ̄ above
//   the rigid value by O(1/a).
// - The ratchet (model.md; Popov & Li 2018): normal and longitudinal oscillation a quarter period
//   apart push the body at β = 0 (μ̄ ≈ −0.5364); the free velocity where the mean force vanishes.
// - Combined oscillation (the review, M. Popov 2020): normal and longitudinal oscillation together
//   reduce friction more than either alone, at the right phase.
// - Transverse rigid limit (model.md): n ≡ 1, sine, μ̄ → (2/π) ξ/√(1+ξ²) K(1/√(1+ξ²)), no critical
//   velocity; decided with the planar solver (core/inplane/planar.hpp).
#include <boost/math/special_functions/ellint_1.hpp>

#include <cstdio>

#include "check.hpp"
#include "vibrofric/core/inplane/inplane.hpp"
#include "vibrofric/core/inplane/planar.hpp"

namespace vibrofric::claims {

namespace {

std::string fix(double x, int decimals = 3) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", decimals, x);
  return b;
}

// The verdicts rest on distances of 1e-7 and more and on signs: 30 digits decide them as 300 would.
constexpr int inplane_digits = 30;

// μ̄ of the longitudinal drive at max(min(D, 30), 20) + 10 digits and again 12 digits higher; SolverError
// where the two differ in min(D, 30) digits (the solver has no error bound of its own).
Real inplane_mu(const char* normal, const Real& gamma, const char* in_plane, const Real& beta, const Real& a,
                const Real& phase, int digits) {
  const int d = std::min(digits, inplane_digits);
  // At least 30 working digits: the rigid limit at a = 10^6 subtracts drive terms of size 6e6 to
  // resolve 1e-7, and at 20 digits the event search there ran out of its budget (a SolverError).
  const int work = std::max(d, 20) + 10;
  Real values[2];
  for (int k = 0; k < 2; ++k) {
    PrecisionScope scope(static_cast<unsigned>(work + 12 * k));
    const auto p = make_waveform<Real>(parse_wave(in_plane));
    std::unique_ptr<Waveform<Real>> w;
    if (normal) w = make_waveform<Real>(parse_wave(normal));
    values[k] = solve_inplane<Real>(w.get(), Real(gamma), *p, Real(beta), InPlaneDrive<Real>{Real(a), Real(phase)}).mu;
  }
  if (abs(values[0] - values[1]) > pow(Real(10), -d) * (1 + abs(values[1])))
    throw SolverError("claims: in-plane, beta = " + str(beta, 20) + ", a = " + str(a, 20) + ": " + str(values[0], d) +
                      " and " + str(values[1], d) + " at two precisions");
  return values[1];
}

// μ̄ of the transverse drive at n ≡ 1 at 20 and 32 working digits (the planar solver's cost grows
// with both the digits and a; the verdict rests on distances of 1e-6 and more); SolverError where
// the two differ beyond 1e-15.
Real planar_mu(const Real& beta, const Real& a) {
  Real values[2];
  for (int k = 0; k < 2; ++k) {
    PrecisionScope scope(static_cast<unsigned>(20 + 12 * k));
    const auto p = make_waveform<Real>(parse_wave("sine"));
    values[k] = solve_planar<Real>(nullptr, Real(0), *p, Real(beta), PlanarDrive<Real>{Real(0), Real(a), Real(0)}).mu;
  }
  if (abs(values[0] - values[1]) > Real("1e-15"))
    throw SolverError("claims: transverse, beta = " + str(beta, 20) + ", a = " + str(a, 20) + ": " + str(values[0], 17) +
                      " and " + str(values[1], 17) + " at two precisions");
  return values[1];
}

}  // namespace

ClaimCheck inplane_transverse(int digits) {
  Check c(entry("inplane-transverse"), digits);
  c.unit("absolute |mu - (2/pi) xi/sqrt(1+xi^2) K(1/sqrt(1+xi^2))|, in mu0");
  c.out().how = "n = 1 (constant normal force), sine transverse drive of amplitude a, beta = 2 pi a xi, xi = 0.25, 0.5, "
                "0.9 at a = 10, 30, 100; xi = 1 and 1.5 at a = 10; the planar solver at 20 and 32 digits";
  c.out().criterion = "limit claim: holds approximately if the distance D decreases along a with measured order in 1/a "
                      "above 1.8 and mu < mu0 at xi >= 1 (no critical velocity); fails otherwise. Deviation: the "
                      "largest D at a = 100";
  c.numerical("a limit (a -> infinity); the planar solver has no enclosure");
  const Real pi = boost::math::constants::pi<Real>();
  const auto rigid = [&](const Real& xi) {
    const Real r = sqrt(Real(1 + xi * xi));
    return Real(2 / pi * xi / r * boost::math::ellint_1(Real(1 / r)));
  };
  double order_lo = 1e9, order_hi = -1e9, last = 0;
  bool decreasing = true, above = true;
  for (const char* xi_text : {"0.25", "0.5", "0.9"}) {
    const Real xi = num(xi_text), limit = rigid(xi);
    std::vector<double> d;
    std::string row;
    for (const char* a_text : {"10", "30", "100"}) {
      const Real a = num(a_text);
      const Real mu = planar_mu(2 * pi * a * xi, a);
      above = above && mu > limit;
      d.push_back(static_cast<double>(abs(mu - limit)));
      row += (row.empty() ? "" : ", ") + sci(d.back());
      ++c.out().cases;
    }
    for (std::size_t k = 1; k < d.size(); ++k) decreasing = decreasing && d[k] < d[k - 1];
    const double order = std::log(d[d.size() - 2] / d.back()) / std::log(100.0 / 30.0);
    order_lo = std::min(order_lo, order);
    order_hi = std::max(order_hi, order);
    if (d.back() >= last) {
      last = d.back();
      c.out().worst = std::string("xi = ") + xi_text + ", a = 100";
    }
    c.measure(std::string("xi = ") + xi_text + ": D(a), a = 10, 30, 100; a^2 D at 100; order in 1/a",
              row + "; " + fix(d.back() * 1e4, 4) + "; " + fix(order),
              {{"xi", xi_text}, {"D(100)", sci(d.back())}, {"order", fix(order)}});
  }
  bool below = true;
  for (const char* xi_text : {"1", "1.5"}) {
    const Real a(10), xi = num(xi_text);
    const Real mu = planar_mu(2 * pi * a * xi, a);
    below = below && mu < 1 && rigid(xi) < 1;
    ++c.out().cases;
    c.measure(std::string("xi = ") + xi_text + ", a = 10: mu; rigid", str(mu, 12) + "; " + str(rigid(xi), 12));
  }
  c.set_deviation(Real(last));
  c.measure_range("order of D in 1/a (a = 30 -> 100)", fix(order_lo), fix(order_hi));
  c.out().scope = "mu - rigid = O(1/a^2) (measured order " + fix(order_lo) + "-" + fix(order_hi) + "), " +
                  (above ? "always above the rigid value" : "of either sign") +
                  (below ? "; below mu0 at xi = 1 and 1.5: no critical velocity" : "; mu0 reached at xi >= 1");
  c.out().corrected = "";
  return c.finish(decreasing && order_lo > 1.8 && below ? Verdict::holds_approximately : Verdict::fails,
                  c.out().criterion);
}

ClaimCheck inplane_rigid(int digits) {
  Check c(entry("inplane-rigid"), digits);
  c.unit("absolute |mu - (2/pi) arcsin xi|, in mu0");
  c.out().how = "n = 1 (constant normal force), sine drive of amplitude a, beta = 2 pi a xi, xi = 0.25, 0.5, 0.9 at "
                "a = 100, 1000, 10000, 100000, 1000000; xi = 1 and 1.5 at a = 100; the in-plane solver at min(D, 30) "
                "digits, two precisions";
  c.out().criterion = "limit claim: holds approximately if the distance D decreases along a with measured order in "
                      "1/a above 0.9 and mu = mu0 at xi >= 1; fails otherwise. Deviation: the largest D at a = 10^6";
  c.numerical("a limit (a -> infinity); the in-plane solver has no enclosure");
  double order_lo = 1e9, order_hi = -1e9, last = 0;
  bool decreasing = true, above = true;
  for (const char* xi_text : {"0.25", "0.5", "0.9"}) {
    const Real xi = num(xi_text), limit = 2 / boost::math::constants::pi<Real>() * asin(xi);
    std::vector<double> d;
    std::string row;
    for (const char* a_text : {"100", "1000", "10000", "100000", "1000000"}) {
      const Real a = num(a_text);
      const Real mu = inplane_mu(nullptr, Real(0), "sine", 2 * boost::math::constants::pi<Real>() * a * xi, a, Real(0), digits);
      above = above && mu > limit;
      d.push_back(static_cast<double>(abs(mu - limit)));
      row += (row.empty() ? "" : ", ") + sci(d.back());
      ++c.out().cases;
    }
    for (std::size_t k = 1; k < d.size(); ++k) decreasing = decreasing && d[k] < d[k - 1];
    const double order = std::log10(d[d.size() - 2] / d.back());
    order_lo = std::min(order_lo, order);
    order_hi = std::max(order_hi, order);
    if (d.back() >= last) {
      last = d.back();
      c.out().worst = std::string("xi = ") + xi_text + ", a = 1e6";
    }
    c.measure(std::string("xi = ") + xi_text + ": D(a), a = 1e2 ... 1e6; a D at 1e6; order in 1/a",
              row + "; " + fix(d.back() * 1e6, 4) + "; " + fix(order), {{"xi", xi_text}, {"D(1e6)", sci(d.back())}, {"order", fix(order)}});
  }
  bool critical = true;
  for (const char* xi_text : {"1", "1.5"}) {
    const Real a(100);
    const Real mu = inplane_mu(nullptr, Real(0), "sine", 2 * boost::math::constants::pi<Real>() * a * num(xi_text), a,
                               Real(0), digits);
    critical = critical && abs(mu - 1) <= pow(Real(10), -std::min(digits, inplane_digits));  // μ0 to the digits
    ++c.out().cases;
    c.measure(std::string("xi = ") + xi_text + ", a = 100: mu", str(mu, 20));
  }
  c.set_deviation(Real(last));
  c.measure_range("order of D in 1/a (a = 1e5 -> 1e6)", fix(order_lo), fix(order_hi));
  c.out().scope = "mu - (2/pi) arcsin xi = O(1/a) (measured order " + fix(order_lo) + "-" + fix(order_hi) + "), " +
                  (above ? "always above the rigid value: the contact's stiffness weakens the reduction" : "of either sign") +
                  "; mu = mu0 from xi = 1 on";
  c.out().corrected = "";
  return c.finish(decreasing && order_lo > 0.9 && critical ? Verdict::holds_approximately : Verdict::fails,
                  c.out().criterion);
}

ClaimCheck inplane_ratchet(int digits) {
  Check c(entry("inplane-ratchet"), digits);
  c.unit("absolute |mu - (-0.5364)|, in mu0 (model.md gives 4 digits)");
  c.out().how = "n = max(0.5 + sin 2 pi phi, 0), sine drive a = 1, P = 1/4, beta = 0; then the free velocity: the beta "
                "where mu = 0, by bisection on mu(beta) between 0 and 3 to 1e-12; the in-plane solver at min(D, 30) digits";
  c.out().criterion = "holds if mu < 0 and |mu + 0.5364| < 5e-5 (model.md's 4 digits); fails otherwise";
  c.numerical("model.md's value is a catching-up measurement to 4 digits");
  const Real gamma = num("0.5"), a(1), phase = num("0.25");
  const Real mu = inplane_mu("sine", gamma, "sine", Real(0), a, phase, digits);
  c.set_deviation(abs(mu + num("0.5364")));
  c.out().worst = "n = max(0.5 + sin 2 pi phi, 0), a = 1, P = 1/4, beta = 0";
  ++c.out().cases;
  c.measure("mu at beta = 0", str(mu, 20));
  // The free velocity: μ̄(β) rises through 0 between β = 0 and 3 (the tool's sweep shows it).
  Real lo(0), hi(3);
  bool bracketed = mu < 0 && inplane_mu("sine", gamma, "sine", hi, a, phase, digits) > 0;
  c.out().cases += 1;
  if (bracketed) {
    while (hi - lo > Real("1e-12")) {
      const Real mid = (lo + hi) / 2;
      (inplane_mu("sine", gamma, "sine", mid, a, phase, digits) < 0 ? lo : hi) = mid;
      ++c.out().cases;
    }
    c.measure("free velocity (mu = 0), beta", str((lo + hi) / 2, 12));
  }
  c.out().scope = "the body is pushed forward at beta = 0 (mu = " + str(mu, 8) + ")" +
                  (bracketed ? "; the mean force vanishes at beta = " + str((lo + hi) / 2, 10) : std::string());
  c.out().corrected = "";
  return c.finish(mu < 0 && abs(mu + num("0.5364")) < num("5e-5") ? Verdict::holds_approximately : Verdict::fails,
                  c.out().criterion);
}

ClaimCheck inplane_combined(int digits) {
  Check c(entry("inplane-combined"), digits);
  c.unit("1 where no phase reduces friction more than either oscillation alone, 0 where one does");
  c.out().how = "sine normal and sine longitudinal oscillation, beta = 1, at (gamma, a) = (1.5, 0.5), (1.5, 1), "
                "(1.5, 2), (0.5, 0.5), (0.5, 1), (0.5, 2): normal alone g_w(1, gamma); longitudinal alone with the "
                "mean normal force held constant (n = gamma: beta/gamma, a/gamma with n = 1); combined at P = k/16, "
                "k = 0 ... 15; the in-plane solver at min(D, 30) digits";
  c.out().criterion = "holds if at every (gamma, a) some phase P gives a smaller mu than either oscillation alone; "
                      "fails otherwise";
  c.numerical("a statement about a family of rigs, checked on a grid of phases");
  Real worst_margin = -1;
  std::string best_phases, worst_phases;
  for (const auto& [g_text, a_text] : {std::pair{"1.5", "0.5"}, std::pair{"1.5", "1"}, std::pair{"1.5", "2"},
                                       std::pair{"0.5", "0.5"}, std::pair{"0.5", "1"}, std::pair{"0.5", "2"}}) {
    const Real gamma = num(g_text), a = num(a_text), beta(1);
    const Real normal = inplane_mu("sine", gamma, "sine", beta, Real(0), Real(0), digits);
    const Real longitudinal = inplane_mu(nullptr, Real(0), "sine", beta / gamma, a / gamma, Real(0), digits);
    Real best(2), worst(-2);
    int best_k = 0, worst_k = 0;
    for (int k = 0; k < 16; ++k) {
      const Real mu = inplane_mu("sine", gamma, "sine", beta, a, Real(k) / 16, digits);
      if (mu < best) { best = mu; best_k = k; }
      if (mu > worst) { worst = mu; worst_k = k; }
    }
    c.out().cases += 18;
    const Real alone = normal < longitudinal ? normal : longitudinal;
    const Real margin = best - alone;
    const std::string where = std::string("gamma = ") + g_text + ", a = " + a_text;
    c.record(Real(margin < 0 ? 0 : 1), where + ": best combined minus the better alone " + str(margin, 6));
    if (margin > worst_margin) {
      worst_margin = margin;
      c.out().worst = where + ": best combined minus the better alone " + str(margin, 6);
    }
    best_phases += (best_phases.empty() ? "" : "; ") + where + ": P = " + std::to_string(best_k) + "/16";
    worst_phases += (worst_phases.empty() ? "" : "; ") + where + ": P = " + std::to_string(worst_k) + "/16 (mu " + str(worst, 4) + ")";
    c.measure(where + ": normal alone, longitudinal alone, combined at its best P (P)",
              str(normal, 6) + ", " + str(longitudinal, 6) + ", " + str(best, 6) + " (" + std::to_string(best_k) + "/16)",
              {{"gamma", g_text}, {"a", a_text}, {"normal", str(normal, 6)}, {"longitudinal", str(longitudinal, 6)},
               {"combined", str(best, 6)}, {"P", std::to_string(best_k) + "/16"}});
  }
  c.out().scope = "best phases: " + best_phases + "; the smallest gain " + str(Real(-worst_margin), 4) + " mu0";
  c.out().fails_where = "at the wrong phase the combination reduces less than either: " + worst_phases;
  c.out().corrected = "";
  return c.finish(c.largest() == 0 ? Verdict::holds : Verdict::fails, c.out().criterion);
}

}  // namespace vibrofric::claims
