// The exact rung (core/exact.hpp): μ̄/μ0 and Ψ of piecewise-linear waves in GMP rationals,
// checked exactly against the paper's closed forms (Eqs. 17, 19, 22, 13 and Ψ_sqr, which the
// claims catalogue proves), exactly against the lower-envelope oracle (verification's
// envelope.hpp, a different evaluation of the characterisation), and against the event solver at
// 60 digits within its error bound: μ̄, every area, β_c and every stick phase's ends and level.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "vibrofric/api/exact_input.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/core/exact.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/waves/user_waveforms.hpp"
#include "vibrofric/verification/closed_forms.hpp"
#include "vibrofric/verification/envelope.hpp"

namespace {

namespace ex = vibrofric::exact;
namespace cf = vibrofric::closed_form;
namespace env = vibrofric::envelope;
using Q = ex::Rational;
using vibrofric::mpfr;

Q q(long n, long d = 1) { return Q(n, d); }

// Random rationals with small and large denominators: 0 < β < 8 and γ in (−1, 3).
Q random_rational(std::mt19937& rng, long lo_num, long hi_num) {
  static const long denominators[] = {1, 2, 3, 7, 10, 1000, 999983, 1000000007};
  const long d = denominators[std::uniform_int_distribution<int>(0, 7)(rng)];
  return Q(std::uniform_int_distribution<long>(lo_num * d, hi_num * d)(rng), d);
}

Q to_q(const env::Rational& x) {
  return Q(boost::multiprecision::mpz_int(numerator(x).str()), boost::multiprecision::mpz_int(denominator(x).str()));
}

mpfr to_mpfr(const Q& x) {
  mpfr r;
  mpfr_set_q(r.backend().data(), x.backend().data(), MPFR_RNDN);
  return r;
}

// Decimal text to its exact rational (api: exact_decimal, through Decimal).
TEST(Exact, DecimalsAreParsedExactly) {
  EXPECT_EQ(vibrofric::exact_decimal("0.15", "beta"), q(3, 20));
  EXPECT_EQ(vibrofric::exact_decimal("-1.5e-3", "gamma"), q(-3, 2000));
  EXPECT_EQ(vibrofric::exact_decimal("+2E2", "x"), q(200));
  EXPECT_EQ(vibrofric::exact_decimal(".5", "x"), q(1, 2));
  EXPECT_EQ(vibrofric::exact_decimal("5.", "x"), q(5));
  EXPECT_EQ(vibrofric::exact_decimal("0.000", "x"), q(0));
  EXPECT_EQ(vibrofric::exact_decimal("1e-5000", "x"), Q(1, pow(boost::multiprecision::mpz_int(10), 5000)));
  for (const char* bad : {"", "-", "e5", "1e", "1e+", "1.2.3", "abc", " 1", "1 ", "0x10", "1e1234567890", "nan"})
    EXPECT_THROW(vibrofric::exact_decimal(bad, "beta"), vibrofric::InputError) << bad;
  try {
    vibrofric::exact_decimal("1e-999999", "beta");
    ADD_FAILURE() << "an exponent past the limit was taken";
  } catch (const vibrofric::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'1e-999999'"), std::string::npos) << e.what();
  }
}

// Eq. 17 (Ψ of str, stl, tri), Ψ_sqr, Eq. 13 (μ̄ = 1 − Ψ/γ for γ ≥ 1), Eq. 19 (jumping str, stl,
// tri) and Eq. 22 (jumping square), exactly, at 2,000 random rational points, and power:1 equal to
// the triangle (a phase shift).
TEST(Exact, CatalogueEqualsTheClosedFormsExactly) {
  std::mt19937 rng(20261126);
  const ex::Wave str = ex::sawtooth_right(), stl = ex::sawtooth_left(), tri = ex::triangle(), sqr = ex::square(),
                 p1 = ex::power_one();
  for (int i = 0; i < 2000; ++i) {
    Q beta = random_rational(rng, 0, 8);
    if (beta == 0) beta = q(1, 3);
    const Q above = 1 + random_rational(rng, 0, 2);      // γ ≥ 1: no jumping
    Q below = random_rational(rng, -1, 1);               // −1 < γ < 1: jumping
    if (below == -1 || below == 1) below = q(-1, 2);
    const std::string at = "beta = " + beta.str() + ", gamma = " + above.str() + " / " + below.str();
    EXPECT_EQ(ex::psi(str, beta).lost_area, cf::psi_sawtooth_right(beta)) << at;
    EXPECT_EQ(ex::psi(stl, beta).lost_area, cf::psi_sawtooth_left(beta)) << at;
    EXPECT_EQ(ex::psi(tri, beta).lost_area, cf::psi_triangle(beta)) << at;
    EXPECT_EQ(ex::psi(sqr, beta).lost_area, cf::psi_square(beta)) << at;
    EXPECT_EQ(ex::solve(str, beta, above).mu, cf::mu_from_psi(cf::psi_sawtooth_right(beta), above)) << at;
    EXPECT_EQ(ex::solve(stl, beta, above).mu, cf::mu_from_psi(cf::psi_sawtooth_left(beta), above)) << at;
    EXPECT_EQ(ex::solve(tri, beta, above).mu, cf::mu_from_psi(cf::psi_triangle(beta), above)) << at;
    EXPECT_EQ(ex::solve(sqr, beta, above).mu, cf::mu_from_psi(cf::psi_square(beta), above)) << at;
    EXPECT_EQ(ex::solve(str, beta, below).mu, cf::mu_sawtooth_right_jumping(beta)) << at;
    EXPECT_EQ(ex::solve(stl, beta, below).mu, cf::mu_sawtooth_left_jumping(beta)) << at;
    EXPECT_EQ(ex::solve(tri, beta, below).mu, cf::mu_triangle_jumping(beta)) << at;
    EXPECT_EQ(ex::solve(sqr, beta, below).mu, cf::mu_square_jumping(beta, below)) << at;
    EXPECT_EQ(ex::solve(p1, beta, below).mu, ex::solve(tri, beta, below).mu) << at;
    EXPECT_EQ(ex::solve(p1, beta, above).mu, ex::solve(tri, beta, above).mu) << at;
    // Jumping exactly below γ = −min w = 1, not from it on.
    EXPECT_TRUE(ex::solve(tri, beta, below).jumping) << at;
    EXPECT_FALSE(ex::solve(tri, beta, above).jumping) << at;
  }
  // β_c (model.md's table): 4 for the triangle, 2 for str, ∞ (an upward jump) for stl and square;
  // and Eq. 6: μ̄ = 1 exactly from β_c on.
  EXPECT_EQ(*ex::solve(tri, q(1), q(1, 2)).beta_c, 4);
  EXPECT_EQ(*ex::solve(str, q(1), q(-1, 2)).beta_c, 2);
  EXPECT_FALSE(ex::solve(stl, q(1), q(2)).beta_c.has_value());
  EXPECT_FALSE(ex::solve(sqr, q(1), q(0)).beta_c.has_value());
  EXPECT_EQ(ex::solve(tri, q(4), q(-1, 3)).mu, 1);
  EXPECT_EQ(ex::solve(str, q(2), q(5)).mu, 1);
  EXPECT_TRUE(ex::solve(tri, q(4), q(-1, 3)).stick_phases.empty());
  EXPECT_THROW(ex::solve(tri, q(1), q(-1)), vibrofric::DomainError);
  EXPECT_THROW(ex::solve(tri, q(0), q(1)), vibrofric::InputError);
}

// Stick phases of the triangle at γ = 1, β = 1, by hand: n = 4φ on [0, 1/2], 4 − 4φ after. Stick
// from the minimum at φ = 0 (n' = 4 > β) at level 0, on the ramp s = φ, until it meets 4 − 4φ at
// φ = 4/5.
TEST(Exact, TriangleStickPhaseByHand) {
  const ex::Result r = ex::solve(ex::triangle(), q(1), q(1));
  ASSERT_EQ(r.stick_phases.size(), 1u);
  EXPECT_EQ(r.stick_phases[0].begin, 0);
  EXPECT_EQ(r.stick_phases[0].end, q(4, 5));
  EXPECT_EQ(r.stick_phases[0].level, 0);
  EXPECT_EQ(r.normal_area, 1);
  // ∫s = ∫₀^{4/5} φ dφ + ∫_{4/5}^1 (4 − 4φ) dφ = 8/25 + 2/25.
  EXPECT_EQ(r.retained_area, q(10, 25));
  EXPECT_EQ(r.lost_area, q(3, 5));
  EXPECT_EQ(r.lost_area, cf::psi_triangle(q(1)));
  // Shifted by a quarter (power:1): the same phase a quarter later, wrapping into the next period.
  const ex::Result p = ex::solve(ex::power_one(), q(1), q(1));
  ASSERT_EQ(p.stick_phases.size(), 1u);
  EXPECT_EQ(p.stick_phases[0].begin, q(3, 4));
  EXPECT_EQ(p.stick_phases[0].end, q(3, 4) + q(4, 5));
}

// Stick phases that end at a downward jump of n (the ramp rises from a vertex where s = n): the
// sawtooth-right at γ = 1/2, β = 1 (n = 0 to φ = 1/4, then 2φ − 1/2, dropping to 0 at φ = 1)
// sticks from 1/4 at level 0 to 1; the square wave at γ = 0, β = 1 (n = 1 on [0, 1/2), else 0)
// sticks from its upward jump at 0, level 0, to its downward jump at 1/2.
TEST(Exact, StickPhasesEndingAtJumpsByHand) {
  const ex::Result str = ex::solve(ex::sawtooth_right(), q(1), q(1, 2));
  ASSERT_EQ(str.stick_phases.size(), 1u);
  EXPECT_EQ(str.stick_phases[0].begin, q(1, 4));
  EXPECT_EQ(str.stick_phases[0].end, 1);
  EXPECT_EQ(str.stick_phases[0].level, 0);
  EXPECT_EQ(str.mu, q(1, 2));
  EXPECT_EQ(str.contact_boundaries, 1u);
  const ex::Result sqr = ex::solve(ex::square(), q(1), q(0));
  ASSERT_EQ(sqr.stick_phases.size(), 1u);
  EXPECT_EQ(sqr.stick_phases[0].begin, 0);
  EXPECT_EQ(sqr.stick_phases[0].end, q(1, 2));
  EXPECT_EQ(sqr.stick_phases[0].level, 0);
  EXPECT_EQ(sqr.mu, q(1, 4));
}

// Random piecewise-linear waves with jumps, against the envelope oracle: ∫s and ∫n equal exactly.
TEST(Exact, EqualsTheEnvelopeOracleExactly) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 1500; ++trial) {
    const int m = std::uniform_int_distribution<int>(1, 9)(rng);
    env::Vertices raw;
    std::vector<long> xs;
    for (int k = 0; k < m; ++k) xs.push_back(k == 0 ? 0 : std::uniform_int_distribution<long>(1, 999)(rng));
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    for (long x : xs) {
      const long l = std::uniform_int_distribution<long>(-50, 50)(rng);
      const long r = trial % 3 == 0 ? l : std::uniform_int_distribution<long>(-50, 50)(rng);
      raw.push_back({env::Rational(x, 1000), env::Rational(l, 7), env::Rational(r, 7)});
    }
    const auto [lo, hi] = env::range(raw);
    if (!(hi > lo)) continue;
    const env::Vertices w = env::normalise(raw).w;
    ex::Wave wave{"random", {}};
    for (const env::Vertex& v : w) wave.vertices.push_back({to_q(v.x), to_q(v.left), to_q(v.right)});
    for (int k = 0; k < 4; ++k) {
      const env::Rational beta(std::uniform_int_distribution<long>(1, 4000)(rng), 500);
      env::Rational gamma(std::uniform_int_distribution<long>(-990, 2000)(rng), 1000);
      if (k == 3) gamma = -env::range(w).first;
      if (!(gamma + env::range(w).second > 0)) continue;
      const env::Result e = env::mu(w, beta, gamma);
      const ex::Result x = ex::solve(wave, to_q(beta), to_q(gamma));
      const std::string at = "trial " + std::to_string(trial) + ", beta = " + beta.str() + ", gamma = " + gamma.str();
      ASSERT_EQ(x.retained_area, to_q(e.retained_area)) << at;
      ASSERT_EQ(x.normal_area, to_q(e.normal_area)) << at;
      ASSERT_EQ(x.mu, to_q(e.mu)) << at;
    }
  }
}

// Random sampled signals (integers, so that mpfr holds them exactly), uniform and with time
// stamps: the event solver at 60 digits agrees with the exact values within its own bound, stick
// phase by stick phase.
TEST(Exact, AgreesWithTheEventSolverWithinItsBound) {
  vibrofric::PrecisionScope scope(60);
  const mpfr tol("1e-50");
  std::mt19937 rng(11);
  int phases_seen = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = std::uniform_int_distribution<int>(2, 40)(rng);
    std::vector<Q> y;
    std::vector<mpfr> ym;
    for (int j = 0; j < n; ++j) {
      const long v = std::uniform_int_distribution<long>(-1000, 1000)(rng);
      y.push_back(q(v));
      ym.push_back(mpfr(v));
    }
    std::vector<Q> phases;
    std::vector<mpfr> phases_m;
    if (trial % 2 == 1) {  // stamps 0 < t_1 < … < t_{N−1} < T = 1000 n
      std::vector<long> t{0};
      for (int j = 1; j < n; ++j) t.push_back(t.back() + std::uniform_int_distribution<long>(1, 1999)(rng));
      const long period = t.back() + std::uniform_int_distribution<long>(1, 1999)(rng);
      for (long tj : t) phases.push_back(q(tj, period)), phases_m.push_back(mpfr(tj) / period);
    }
    ex::Wave w;
    try {
      w = ex::samples("random", y, phases);
    } catch (const vibrofric::InputError&) {
      continue;  // constant
    }
    std::unique_ptr<vibrofric::Waveform<mpfr>> wm =
        phases.empty() ? vibrofric::make_samples<mpfr>("random", ym)
                       : vibrofric::make_samples_from<mpfr>("random", ym.size(), [&](std::size_t j) { return ym[j]; }, 5,
                                                            [&](std::size_t j) { return phases_m[j]; });
    EXPECT_LE(abs(to_mpfr(w.minimum()) - wm->minimum()), tol);
    EXPECT_LE(abs(to_mpfr(w.maximum()) - wm->maximum()), tol);
    for (int k = 0; k < 4; ++k) {
      const Q beta(std::uniform_int_distribution<long>(1, 20000)(rng), 1000);
      Q gamma(std::uniform_int_distribution<long>(-990, 2000)(rng), 1000);
      if (k == 3) gamma = -w.minimum();
      if (!(gamma + w.maximum() > 0)) continue;
      const std::string at = "trial " + std::to_string(trial) + ", beta = " + beta.str() + ", gamma = " + gamma.str();
      const ex::Result x = ex::solve(w, beta, gamma);
      vibrofric::Result<mpfr> s = vibrofric::solve(*wm, to_mpfr(beta), to_mpfr(gamma));
      ASSERT_LE(s.relative_error, tol) << at;
      EXPECT_LE(abs(s.mu - to_mpfr(x.mu)), 2 * s.relative_error * abs(s.mu) + tol) << at;
      EXPECT_LE(abs(s.retained_area - to_mpfr(x.retained_area)), tol) << at;
      EXPECT_LE(abs(s.normal_area - to_mpfr(x.normal_area)), tol) << at;
      EXPECT_LE(abs(s.lost_area - to_mpfr(x.lost_area)), tol) << at;
      // At γ = −min w exactly n touches 0; the solver compares γ with its rounded min w there.
      if (gamma != -w.minimum()) {
        EXPECT_EQ(s.jumping, x.jumping) << at;
      }
      if (x.beta_c) {
        EXPECT_LE(abs(s.beta_c - to_mpfr(*x.beta_c)), tol * (1 + abs(s.beta_c))) << at;
      } else {
        EXPECT_TRUE(isinf(s.beta_c)) << at;
      }
      ASSERT_EQ(s.stick_phases.size(), x.stick_phases.size()) << at;
      auto by_begin = [](const auto& p, const auto& q) { return p.begin < q.begin; };
      std::sort(s.stick_phases.begin(), s.stick_phases.end(), by_begin);
      for (std::size_t i = 0; i < x.stick_phases.size(); ++i) {
        ++phases_seen;
        EXPECT_LE(abs(s.stick_phases[i].begin - to_mpfr(x.stick_phases[i].begin)), tol) << at << ", phase " << i;
        EXPECT_LE(abs(s.stick_phases[i].end - to_mpfr(x.stick_phases[i].end)), tol) << at << ", phase " << i;
        EXPECT_LE(abs(s.stick_phases[i].level - to_mpfr(x.stick_phases[i].level)), tol) << at << ", phase " << i;
      }
    }
  }
  EXPECT_GT(phases_seen, 300);  // the comparison saw stick phases, not only pure slip
}

// The catalogue's waves (jumps included) against the event solver, stick phase by stick phase.
TEST(Exact, CatalogueAgreesWithTheEventSolver) {
  vibrofric::PrecisionScope scope(60);
  const mpfr tol("1e-50");
  std::mt19937 rng(5);
  const std::vector<std::pair<ex::Wave, std::unique_ptr<vibrofric::Waveform<mpfr>>>> waves = [] {
    std::vector<std::pair<ex::Wave, std::unique_ptr<vibrofric::Waveform<mpfr>>>> v;
    v.emplace_back(ex::triangle(), vibrofric::make_triangle<mpfr>());
    v.emplace_back(ex::sawtooth_right(), vibrofric::make_sawtooth_right<mpfr>());
    v.emplace_back(ex::sawtooth_left(), vibrofric::make_sawtooth_left<mpfr>());
    v.emplace_back(ex::square(), vibrofric::make_square<mpfr>());
    return v;
  }();
  int phases_seen = 0;
  for (const auto& [w, wm] : waves) {
    for (int k = 0; k < 200; ++k) {
      const Q beta(std::uniform_int_distribution<long>(1, 6000)(rng), 1000);
      const Q gamma(std::uniform_int_distribution<long>(-999, 2500)(rng), 1000);
      const std::string at = w.name + ", beta = " + beta.str() + ", gamma = " + gamma.str();
      const ex::Result x = ex::solve(w, beta, gamma);
      vibrofric::Result<mpfr> s = vibrofric::solve(*wm, to_mpfr(beta), to_mpfr(gamma));
      EXPECT_LE(abs(s.mu - to_mpfr(x.mu)), tol) << at;
      EXPECT_LE(abs(s.lost_area - to_mpfr(x.lost_area)), tol) << at;
      EXPECT_EQ(s.jumping, x.jumping) << at;
      ASSERT_EQ(s.stick_phases.size(), x.stick_phases.size()) << at;
      std::sort(s.stick_phases.begin(), s.stick_phases.end(), [](const auto& p, const auto& r) { return p.begin < r.begin; });
      for (std::size_t i = 0; i < x.stick_phases.size(); ++i, ++phases_seen) {
        EXPECT_LE(abs(s.stick_phases[i].begin - to_mpfr(x.stick_phases[i].begin)), tol) << at;
        EXPECT_LE(abs(s.stick_phases[i].end - to_mpfr(x.stick_phases[i].end)), tol) << at;
        EXPECT_LE(abs(s.stick_phases[i].level - to_mpfr(x.stick_phases[i].level)), tol) << at;
      }
    }
  }
  EXPECT_GT(phases_seen, 400);
}

TEST(Exact, SamplesAreNormalisedExactly) {
  // 1, 2, 4 at φ = 0, 1/2, 3/4 (period 1): mean = 1·(1/2 − (−1/4))/2 + 2·(3/4 − 0)/2 + 4·(1 − 1/2)/2.
  const ex::Wave w = ex::samples("s", {q(1), q(2), q(4)}, {q(0), q(1, 2), q(3, 4)});
  const Q mean = q(3, 8) + q(3, 4) + q(1);
  ASSERT_EQ(w.vertices.size(), 3u);
  EXPECT_EQ(w.vertices[0].left, (1 - mean) / q(3, 2));
  EXPECT_EQ(w.minimum(), (1 - mean) / q(3, 2));
  EXPECT_EQ(w.maximum(), (4 - mean) / q(3, 2));
  EXPECT_EQ(w.maximum() - w.minimum(), 2);
  EXPECT_THROW(ex::samples("c", {q(3), q(3)}), vibrofric::InputError);
  EXPECT_THROW(ex::samples("one", {q(3)}), vibrofric::InputError);
}

}  // namespace
