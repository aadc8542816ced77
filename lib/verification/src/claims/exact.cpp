// The exact claims: Eqs. 6, 13, 17, 18, 19, 20–21, 22, Fig. 3 and model.md's β_c table, each
// decided by the solver at high precision against the closed form (closed_forms.hpp) or against
// the solver at the reference point the claim names; then all but the β_c table again, certified
// (claims.hpp): exactly in rationals (core/exact.hpp) and by enclosures (core/certified/enclosure.hpp).
#include "check.hpp"
#include "vibrofric/api/exact_input.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/core/exact.hpp"
#include "vibrofric/verification/closed_forms.hpp"

namespace vibrofric::claims {
namespace cf = closed_form;

namespace {
const char* const kWaves[] = {"sine", "triangle", "sawtooth-right", "sawtooth-left", "square", "power:2", "power:3"};

// Certified (README, "Precision"): the claim at the same grid, its decimals taken exactly, in GMP
// rationals (core/exact.hpp) against the closed form also in rationals. `equal(β, γ)` is one case;
// a case that is not exactly equal is a deviation of 1, so the claim fails on it.
using Q = exact::Rational;
template <class Equal>
void certify_exactly(Check& c, const std::vector<const char*>& betas, const std::vector<const char*>& gammas, Equal equal) {
  long cases = 0, equal_cases = 0;
  for (const char* b : betas)
    for (const char* g : gammas) {
      ++cases;
      const Q beta = exact_decimal(b, "beta"), gamma = exact_decimal(g, "gamma");
      if (equal(beta, gamma)) {
        ++equal_cases;
      } else {
        c.record(1.0, std::string("certified in exact rationals: beta = ") + b + ", gamma = " + g + " not equal");
      }
    }
  c.measure("certified in exact rationals (core/exact.hpp), the grid's decimals taken exactly",
            std::to_string(equal_cases) + " of " + std::to_string(cases) + " cases exactly equal",
            {{"equal", std::to_string(equal_cases)}, {"cases", std::to_string(cases)}});
  if (equal_cases == cases)
    c.certified("exact rationals (core/exact.hpp): every case of the grid, its decimals taken exactly, equals the closed form");
}

const std::pair<const char*, exact::Wave (*)()> kExactWaves[] = {
    {"triangle", exact::triangle}, {"sawtooth-right", exact::sawtooth_right}, {"sawtooth-left", exact::sawtooth_left},
    {"square", exact::square}};

}  // namespace

ClaimCheck eq6(int digits) {
  Check c(entry("eq6"), digits);
  c.unit("relative |mu - mu0|/mu0 at and above beta_c; 1 per case without stick below it");
  c.out().how = "7 waves x gamma in {3, 1, 0.5, 0, -0.5, -0.9}: mu at beta_c, 1.5 beta_c, 10 beta_c must be exactly 1; "
                "at " + below_text(digits) + " (or beta = 100, 1000 where beta_c is infinite) a stick phase and mu < 1 (deviation 1 if not); "
                "then certified: tri, str, stl, square in exact rationals, the sine and power:2, power:3 by enclosures beside beta_c";
  for (const char* name : kWaves) {
    Solver s(name, digits);
    for (const Real& gamma : reals({"3", "1", "0.5", "0", "-0.5", "-0.9"})) {
      const Real bc = s.beta_c(gamma);
      using std::isfinite;
      if (isfinite(bc)) {
        for (const Real& f : reals({"1", "1.5", "10"})) {
          const Real beta = bc * f;
          c.compare(s.mu(beta, gamma), Real(1), at(name, beta, &gamma));
        }
      }
      for (const Real& beta : isfinite(bc) ? std::vector<Real>{bc * (1 - below_step(digits))} : reals({"100", "1000"})) {
        const auto r = s.result(beta, gamma);
        c.record(!r.stick_phases.empty() && r.mu < 1 ? 0.0 : 1.0,
                 at(name, beta, &gamma) + ": stick below beta_c (mu = " + str(r.mu, 20) + ")");
      }
    }
  }
  // Certified: the piecewise-linear waves exactly at beta_c, 1.5 and 10 beta_c (beta_c rational)
  // and 1e-3 below; the sine and power:p by enclosures at rationals 1e-12 above the enclosure of
  // beta_c, 1.5 and 10 times it, and 1e-3 below (irrational beta_c: beside it, not at it).
  long cases = 0, proven = 0;
  auto decide = [&](bool ok, const std::string& where) {
    ++cases;
    if (ok) ++proven;
    else c.record(1.0, "certified: " + where + " contradicts Eq. 6");
  };
  const std::vector<const char*> gammas{"3", "1", "0.5", "0", "-0.5", "-0.9"};
  for (const auto& [name, make] : kExactWaves) {
    const exact::Wave w = make();
    for (const char* gt : gammas) {
      const Q gamma = exact_decimal(gt, "gamma");
      const std::optional<Q> bc = exact::solve(w, Q(1), gamma).beta_c;
      for (const Q& f : {Q(1), Q(3, 2), Q(10)})
        if (bc) {
          const exact::Result r = exact::solve(w, *bc * f, gamma);
          decide(r.mu == 1 && r.stick_phases.empty(), std::string(name) + " at " + (*bc * f).str() + " beta_c, gamma = " + gt);
        }
      for (const Q& beta : bc ? std::vector<Q>{*bc * Q(999, 1000)} : std::vector<Q>{Q(100), Q(1000)}) {
        const exact::Result r = exact::solve(w, beta, gamma);
        decide(r.mu < 1 && !r.stick_phases.empty(), std::string(name) + ", beta = " + beta.str() + ", gamma = " + gt);
      }
    }
  }
  for (const Enclosed& e : enclosed_waves(digits))
    for (const char* gt : gammas) {
      const Q gamma = exact_decimal(gt, "gamma");
      // beta_c enclosed (its own enclosure, at any beta), and rationals beside its ends.
      const Interval bc = e.at(Q(1), gamma).beta_c;
      const Q upper = rational_of(bc.upper()), lower = rational_of(bc.lower());
      for (const Q& f : {Q(1000000000001, 1000000000000), Q(3, 2), Q(10)}) {
        const certified::SineEnclosure r = e.at(upper * f, gamma);
        decide(!r.stick && r.mu.width() == 0 && r.mu.contains(mpfr(1)), std::string(e.name) + " at " + f.str() + " beta_c, gamma = " + gt);
      }
      const certified::SineEnclosure r = e.at(lower * Q(999, 1000), gamma);
      decide(r.stick && r.mu.upper() < 1, std::string(e.name) + " at 0.999 beta_c, gamma = " + gt);
    }
  c.measure("certified (exact rationals; enclosures for the sine, power:2, power:3)",
            std::to_string(proven) + " of " + std::to_string(cases) + " cases proven",
            {{"proven", std::to_string(proven)}, {"cases", std::to_string(cases)}});
  if (proven == cases)
    c.certified("tri, str, stl, square exactly in rationals at beta_c (rational), 1.5 and 10 beta_c, and 1e-3 below; the sine "
                "and power:2, power:3 by enclosures at rationals beside beta_c's own enclosure: 1e-12 above it, 1.5 and 10 times "
                "it (mu = 1 exactly, no stick), 1e-3 below (a stick phase, mu < 1 certainly)");
  return c.finish_exact();
}

ClaimCheck eq13(int digits) {
  Check c(entry("eq13"), digits);
  c.out().how = "7 waves x 14 beta in (0, 100] x gamma in {1, 1.5, 3, 10, 1000}: solver mu(beta, gamma) against "
                "1 - Psi(beta)/gamma with Psi from the solver at gamma = -min w; then certified: tri, str, stl, square in "
                "exact rationals, the sine and power:2, power:3 by enclosures";
  for (const char* name : kWaves) {
    Solver s(name, digits);
    for (const Real& beta : betas_wide()) {
      const Real p = s.psi(beta);
      for (const Real& gamma : reals({"1", "1.5", "3", "10", "1000"}))
        c.compare(s.mu(beta, gamma), cf::mu_from_psi(p, gamma), at(name, beta, &gamma));
    }
  }
  // Certified on the same grid: the piecewise-linear waves exactly; the sine and power:p by
  // enclosures of mu and of 1 - Psi/gamma that overlap, each narrower than 10^-digits.
  long cases = 0, proven = 0;
  const std::vector<const char*> gammas{"1", "1.5", "3", "10", "1000"};
  for (const auto& [name, make] : kExactWaves) {
    const exact::Wave w = make();
    for (const char* bt : beta_texts_wide()) {
      const Q beta = exact_decimal(bt, "beta"), psi = exact::psi(w, beta).lost_area;
      for (const char* gt : gammas) {
        const Q gamma = exact_decimal(gt, "gamma");
        ++cases;
        if (exact::solve(w, beta, gamma).mu == 1 - psi / gamma) ++proven;
        else c.record(1.0, std::string("certified: ") + name + ", beta = " + bt + ", gamma = " + gt + " not equal");
      }
    }
  }
  for (const Enclosed& e : enclosed_waves(digits))
    for (const char* bt : beta_texts_wide()) {
      const Q beta = exact_decimal(bt, "beta");
      const Interval psi = e.at(beta, Q(1)).lost_area;
      for (const char* gt : gammas) {
        const Q gamma = exact_decimal(gt, "gamma");
        ++cases;
        const Interval g = Interval::rational(gamma.backend().data(), e.bits);
        if (overlap_within(e.at(beta, gamma).mu, Interval::integer(1, e.bits) - psi / g, digits)) ++proven;
        else c.record(1.0, std::string("certified: ") + e.name + ", beta = " + bt + ", gamma = " + gt + ": enclosures apart");
      }
    }
  c.measure("certified (exact rationals; enclosures for the sine, power:2, power:3)",
            std::to_string(proven) + " of " + std::to_string(cases) + " cases proven",
            {{"proven", std::to_string(proven)}, {"cases", std::to_string(cases)}});
  if (proven == cases)
    c.certified("tri, str, stl, square exactly in rationals (mu = 1 - Psi/gamma, equal); the sine and power:2, power:3 by "
                "enclosures: mu's and 1 - Psi/gamma's overlap, each narrower than 1e-" + std::to_string(digits) +
                ", so they differ by less than 2e-" + std::to_string(digits));
  return c.finish_exact();
}

ClaimCheck eq17(int digits) {
  Check c(entry("eq17"), digits);
  c.out().how = "solver Psi of str, stl, tri against the closed forms, 14 beta in (0, 100] (below beta_c for str, tri); then certified: the same decimals exactly, in GMP rationals (core/exact.hpp), against the closed form in rationals";
  Solver str("sawtooth-right", digits), stl("sawtooth-left", digits), tri("triangle", digits);
  for (const Real& beta : betas_wide()) {
    if (beta < 2) c.compare(str.psi(beta), cf::psi_sawtooth_right(beta), at("str", beta));
    c.compare(stl.psi(beta), cf::psi_sawtooth_left(beta), at("stl", beta));
    if (beta < 4) c.compare(tri.psi(beta), cf::psi_triangle(beta), at("tri", beta));
  }
  certify_exactly(c, beta_texts_wide(), {"1"}, [](const Q& beta, const Q&) {
    return exact::psi(exact::sawtooth_right(), beta).lost_area == cf::psi_sawtooth_right(beta) &&
           exact::psi(exact::sawtooth_left(), beta).lost_area == cf::psi_sawtooth_left(beta) &&
           exact::psi(exact::triangle(), beta).lost_area == cf::psi_triangle(beta);
  });
  return c.finish_exact();
}

ClaimCheck eq18(int digits) {
  Check c(entry("eq18"), digits);
  c.out().how = "tri, str, stl x 14 beta x 10 gamma in (-1, 1]: solver mu(beta, gamma) against solver mu(beta, 1); then certified: the same decimals exactly, in GMP rationals (core/exact.hpp), mu(beta, gamma) against mu(beta, 1)";
  for (const char* name : {"triangle", "sawtooth-right", "sawtooth-left"}) {
    Solver s(name, digits);
    for (const Real& beta : betas_wide()) {
      const Real ref = s.mu(beta, Real(1));
      for (const Real& gamma : gammas_jumping()) c.compare(s.mu(beta, gamma), ref, at(name, beta, &gamma));
    }
  }
  certify_exactly(c, beta_texts_wide(), gamma_texts_jumping(), [](const Q& beta, const Q& gamma) {
    for (const exact::Wave& w : {exact::triangle(), exact::sawtooth_right(), exact::sawtooth_left()})
      if (exact::solve(w, beta, gamma).mu != exact::solve(w, beta, Q(1)).mu) return false;
    return true;
  });
  return c.finish_exact();
}

ClaimCheck eq19(int digits) {
  Check c(entry("eq19"), digits);
  c.out().how = "tri, str, stl x 14 beta x 10 gamma in (-1, 1]: solver against the closed forms (mu = mu0 beyond beta_c); then certified: the same decimals exactly, in GMP rationals (core/exact.hpp), against the closed form in rationals";
  Solver str("sawtooth-right", digits), stl("sawtooth-left", digits), tri("triangle", digits);
  for (const Real& beta : betas_wide())
    for (const Real& gamma : gammas_jumping()) {
      c.compare(str.mu(beta, gamma), cf::mu_sawtooth_right_jumping(beta), at("str", beta, &gamma));
      c.compare(stl.mu(beta, gamma), cf::mu_sawtooth_left_jumping(beta), at("stl", beta, &gamma));
      c.compare(tri.mu(beta, gamma), cf::mu_triangle_jumping(beta), at("tri", beta, &gamma));
    }
  certify_exactly(c, beta_texts_wide(), gamma_texts_jumping(), [](const Q& beta, const Q& gamma) {
    return exact::solve(exact::sawtooth_right(), beta, gamma).mu == cf::mu_sawtooth_right_jumping(beta) &&
           exact::solve(exact::sawtooth_left(), beta, gamma).mu == cf::mu_sawtooth_left_jumping(beta) &&
           exact::solve(exact::triangle(), beta, gamma).mu == cf::mu_triangle_jumping(beta);
  });
  return c.finish_exact();
}

ClaimCheck eq20_21(int digits) {
  Check c(entry("eq20-21"), digits);
  c.out().how = "square, 14 beta x 10 gamma in (-1, 1]: solver mu(beta, gamma) against solver mu(xi_sqr, 1) and "
                "against 1 - Psi_sqr(xi_sqr) with Psi_sqr (ref. [10], Eq. 36) from the solver at gamma = 1; then certified: "
                "the same decimals exactly, in GMP rationals (core/exact.hpp), against both and the closed form of Psi_sqr";
  Solver s("square", digits);
  for (const Real& beta : betas_wide())
    for (const Real& gamma : gammas_jumping()) {
      const Real xi = cf::xi_square(beta, gamma);
      const Real got = s.mu(beta, gamma);
      c.compare(got, s.mu(xi, Real(1)), at("square", beta, &gamma));
      c.compare(got, 1 - s.psi(xi), at("square", beta, &gamma) + " (Eq. 20 form)");
    }
  certify_exactly(c, beta_texts_wide(), gamma_texts_jumping(), [](const Q& beta, const Q& gamma) {
    const Q xi = cf::xi_square(beta, gamma), mu = exact::solve(exact::square(), beta, gamma).mu;
    return mu == exact::solve(exact::square(), xi, Q(1)).mu && mu == 1 - exact::psi(exact::square(), xi).lost_area &&
           mu == 1 - cf::psi_square(xi);
  });
  return c.finish_exact();
}

namespace {
// Eq. 22 at the grid, the threshold β = 2(1 + γ) and its neighbours.
void square_closed_form(Check& c, Solver& s, const std::vector<Real>& gammas, const std::vector<Real>& betas) {
  for (const Real& gamma : gammas) {
    std::vector<Real> bs = betas;
    const Real th = 2 * (1 + gamma);
    for (const Real& f : reals({"0.5", "0.999999", "1", "1.000001", "2"})) bs.push_back(th * f);
    for (const Real& beta : bs) c.compare(s.mu(beta, gamma), cf::mu_square_jumping(beta, gamma), at("square", beta, &gamma));
  }
}
}  // namespace

ClaimCheck eq22(int digits) {
  Check c(entry("eq22"), digits);
  c.out().how = "square, 10 gamma in (-1, 1] x (14 beta + 5 around the threshold 2(1+gamma)): solver against the closed form; then certified: the same decimals exactly, in GMP rationals (core/exact.hpp), against the closed form in rationals";
  Solver s("square", digits);
  square_closed_form(c, s, gammas_jumping(), betas_wide());
  certify_exactly(c, beta_texts_wide(), gamma_texts_jumping(), [](const Q& beta, const Q& gamma) {
    // The grid's β and the threshold 2(1 + γ) with its neighbours, exactly.
    for (const Q& b : {beta, Q(2 * (1 + gamma)), Q(2 * (1 + gamma) * Q(999999, 1000000)), Q(2 * (1 + gamma) * Q(1000001, 1000000))})
      if (exact::solve(exact::square(), b, gamma).mu != cf::mu_square_jumping(b, gamma)) return false;
    return true;
  });
  return c.finish_exact();
}

ClaimCheck fig3(int digits) {
  Check c(entry("fig3"), digits);
  c.out().how = "square, the figure's 11 gamma (1, 0.8, ..., -0.8, and -0.999 for -1, where there is no contact) x "
                "(beta = 0.1, 0.2, ..., 8 + 5 around the threshold): solver against Eq. 22, at the "
                "points of the figure's data (a sweep of the square wave); then certified: the same decimals exactly, in "
                "GMP rationals (core/exact.hpp), against Eq. 22 in rationals";
  Solver s("square", digits);
  std::vector<Real> betas;
  for (int k = 1; k <= 80; ++k) betas.push_back(Real(k) / 10);
  square_closed_form(c, s, gammas_figure(), betas);
  // γ → −1: every curve tends to μ0 for all β > 0 (the threshold 2(1 + γ) tends to 0).
  const Real gamma = num("-0.999999999999");
  const Real beta = num("0.001");
  c.measure("mu(beta = 0.001, gamma = -1 + 1e-12)", str(s.mu(beta, gamma), 15));
  static const std::vector<std::string> beta_texts = [] {
    std::vector<std::string> t;
    for (int k = 1; k <= 80; ++k) t.push_back(std::to_string(k / 10) + "." + std::to_string(k % 10));
    return t;
  }();
  std::vector<const char*> bt;
  for (const std::string& t : beta_texts) bt.push_back(t.c_str());
  certify_exactly(c, bt, {"1", "0.8", "0.6", "0.4", "0.2", "0", "-0.2", "-0.4", "-0.6", "-0.8", "-0.999"},
                  [](const Q& beta, const Q& gamma) {
                    for (const Q& b : {beta, Q(2 * (1 + gamma)), Q(2 * (1 + gamma) * Q(999999, 1000000)), Q(2 * (1 + gamma) * Q(1000001, 1000000))})
                      if (exact::solve(exact::square(), b, gamma).mu != cf::mu_square_jumping(b, gamma)) return false;
                    return true;
                  });
  return c.finish_exact();
}

ClaimCheck beta_c_table(int digits) {
  Check c(entry("beta-c"), digits);
  c.unit("relative |beta_c(table) - beta_c(dynamics)|/beta_c");
  c.out().how = "sine and power:p (p = 1.5, 2, 3, 8), gamma from 3 to -0.99: the tabulated beta_c against the beta_c that "
                "the dynamics shows (mu = mu0 exactly at beta_c (1 + 10^-digits), a stick phase at " + below_text(digits) + "); tri, str, stl, square likewise";
  c.out().scope = "the table holds for gamma >= 0 (and for tri, str, stl, square at every gamma > -1)";
  c.out().corrected = "beta_c(gamma) = 2 pi sqrt(1 - gamma^2) (sine) and 4p (1+gamma)^((p-1)/p) (power:p) for -1 < gamma < 0: "
                      "the steepest rise of n is then at first contact";
  const Real pi = boost::math::constants::pi<Real>();
  struct Row {
    const char* wave;
    Real table;
  };
  std::vector<Row> rows{{"sine", 2 * pi}, {"triangle", Real(4)}, {"sawtooth-right", Real(2)},
                        {"sawtooth-left", std::numeric_limits<Real>::infinity()},
                        {"square", std::numeric_limits<Real>::infinity()}};
  for (const char* p : {"1.5", "2", "3", "8"}) rows.push_back({nullptr, 4 * num(p)});
  const char* const powers[] = {"power:1.5", "power:2", "power:3", "power:8"};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string wave = rows[i].wave ? rows[i].wave : powers[i - 5];
    const Real p = rows[i].wave ? Real(0) : rows[i].table / 4;
    Solver s(wave, digits);
    for (const Real& gamma : reals({"3", "1", "0.5", "0", "-0.3", "-0.6", "-0.9", "-0.99"})) {
      // The corrected formula, derived in proofs/beta_c_sine.md: below γ = 0 the steepest rise is at first contact.
      Real corrected = rows[i].table;
      if (gamma < 0 && wave == "sine") corrected = 2 * pi * sqrt(1 - gamma * gamma);
      if (gamma < 0 && !rows[i].wave) corrected = 4 * p * pow(1 + gamma, (p - 1) / p);
      using std::isfinite;
      if (isfinite(corrected)) {
        // The dynamics decide: μ = μ0 from β_c on, a stick phase just below it. (β_c itself is
        // rounded, and either side of it by an ulp is a legitimate answer: step 10^-digits up.)
        const auto above = s.result(corrected * (1 + pow(Real(10), -digits)), gamma);
        const auto below = s.result(corrected * (1 - below_step(digits)), gamma);
        const bool ok = above.mu == 1 && above.stick_phases.empty() && !below.stick_phases.empty() && below.mu < 1;
        c.compare_corrected(Real(ok ? 0 : 1), Real(0));
        c.compare_corrected(s.beta_c(gamma), corrected);
        c.compare(corrected, rows[i].table, at(wave, corrected, &gamma) + " is beta_c (dynamics); table says " + str(rows[i].table, 20));
      } else {
        const auto r = s.result(num("1000"), gamma);
        c.compare_corrected(Real(r.stick_phases.empty() ? 1 : 0), Real(0));
        c.record(0, at(wave, num("1000"), &gamma) + ": stick at beta = 1000");
      }
    }
  }
  ClaimCheck out = c.finish_exact();
  return out;
}

}  // namespace vibrofric::claims
