// The exact lower-envelope algorithm (envelope.hpp) against the paper's closed forms (rational
// equality), then the event-based solver against it on random piecewise-linear waveforms.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/waves/user_waveforms.hpp"
#include "vibrofric/verification/envelope.hpp"

namespace {

namespace env = vibrofric::envelope;
using env::Rational;
using vibrofric::mpfr;

Rational q(long long a, long long b = 1) { return Rational(a, b); }

const std::vector<Rational>& betas() {
  static const std::vector<Rational> b{q(1, 100), q(1, 7), q(1, 2), q(1), q(3, 2), q(199, 100), q(2),
                                       q(5, 2),   q(3),    q(4),    q(9, 2), q(7), q(100)};
  return b;
}

// ---------------- The second algorithm against closed forms, exactly. ----------------

TEST(Envelope, PsiOfCatalogueMatchesEq17Exactly) {
  for (const Rational& b : betas()) {
    SCOPED_TRACE("beta = " + b.str());
    EXPECT_EQ(env::psi(env::triangle(), b), b < 4 ? Rational((4 - b) / (4 + b)) : Rational(0));
    EXPECT_EQ(env::psi(env::sawtooth_right(), b), b < 2 ? Rational(1 - b / 2) : Rational(0));
    EXPECT_EQ(env::psi(env::sawtooth_left(), b), Rational(2 / (2 + b)));
    // Ψ_sqr (ref. [10] of the paper): 1 − β/8 up to β = 4, 2/β after.
    EXPECT_EQ(env::psi(env::square(), b), b <= 4 ? Rational(1 - b / 8) : Rational(2 / b));
  }
}

TEST(Envelope, JumpingCatalogueMatchesEqs19And22Exactly) {
  const std::vector<Rational> gammas{q(-99, 100), q(-1, 2), q(-1, 3), q(0), q(1, 5), q(2, 3), q(999, 1000)};
  for (const Rational& b : betas())
    for (const Rational& g : gammas) {
      SCOPED_TRACE("beta = " + b.str() + ", gamma = " + g.str());
      EXPECT_EQ(env::mu(env::triangle(), b, g).mu, b < 4 ? Rational(2 * b / (4 + b)) : Rational(1));
      EXPECT_EQ(env::mu(env::sawtooth_right(), b, g).mu, b < 2 ? Rational(b / 2) : Rational(1));
      EXPECT_EQ(env::mu(env::sawtooth_left(), b, g).mu, Rational(b / (2 + b)));
      EXPECT_EQ(env::mu(env::square(), b, g).mu, b < 2 * (1 + g) ? Rational(b / (4 * (1 + g))) : Rational(1 - (1 + g) / b));
    }
}

TEST(Envelope, NonJumpingCatalogueMatchesEq13Exactly) {
  for (const Rational& b : betas())
    for (const Rational& g : {q(1), q(3, 2), q(7)}) {
      SCOPED_TRACE("beta = " + b.str() + ", gamma = " + g.str());
      for (const env::Vertices& w : {env::triangle(), env::sawtooth_right(), env::sawtooth_left(), env::square()})
        EXPECT_EQ(env::mu(w, b, g).mu, 1 - env::psi(w, b) / g);
    }
}

TEST(Envelope, PhaseShiftAndVertexPlacementDoNotMatter) {
  // The triangle shifted by 1/4 (the catalogue's power:1), with its vertices off φ = 0, and the
  // triangle with redundant collinear vertices: the same n, so the same exact μ̄.
  const env::Vertices shifted{{q(1, 4), 1, 1}, {q(3, 4), -1, -1}};
  const env::Vertices padded{{0, -1, -1}, {q(1, 8), q(-1, 2), q(-1, 2)}, {q(1, 2), 1, 1}, {q(9, 10), q(-3, 5), q(-3, 5)}};
  for (const Rational& b : betas())
    for (const Rational& g : {q(-1, 2), q(0), q(1, 2), q(1), q(2)}) {
      const Rational want = env::mu(env::triangle(), b, g).mu;
      EXPECT_EQ(env::mu(shifted, b, g).mu, want);
      EXPECT_EQ(env::mu(padded, b, g).mu, want);
    }
}

// The walk over the concave envelope against brute force over all pairwise crossings.
TEST(Envelope, LowerEnvelopeIntegralMatchesBruteForce) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> small(-6, 6), count(1, 8);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<env::detail::Line> lines(count(rng));
    for (auto& l : lines) l = {q(small(rng), 3), q(small(rng), 2)};
    const Rational a = q(small(rng), 5), b = a + q(1 + (small(rng) + 6), 4);
    std::vector<Rational> cuts{a, b};
    for (const auto& p : lines)
      for (const auto& r : lines)
        if (p.m != r.m) {
          const Rational x = (r.c - p.c) / (p.m - r.m);
          if (x > a && x < b) cuts.push_back(x);
        }
    std::sort(cuts.begin(), cuts.end());
    auto low = [&](const Rational& x) {
      Rational y = lines[0].at(x);
      for (const auto& l : lines) y = std::min(y, l.at(x));
      return y;
    };
    Rational want = 0;
    for (std::size_t i = 1; i < cuts.size(); ++i) want += (cuts[i] - cuts[i - 1]) * (low(cuts[i - 1]) + low(cuts[i])) / 2;
    EXPECT_EQ(env::detail::integrate_lower_envelope(lines, a, b), want) << "trial " << trial;
  }
}

// ---------------- The solver against the exact envelope. ----------------

// 60 digits; the tolerance is 10^-(digits − 10): ten digits of slack for the solver's rounding
// and root finding, nothing for modelling error (there is none: both compute the same μ̄).
constexpr unsigned kDigits = 60;
const char* const kTolerance = "1e-50";

mpfr to_mpfr(const Rational& r) {
  return mpfr(boost::multiprecision::numerator(r).str()) / mpfr(boost::multiprecision::denominator(r).str());
}

struct Tally {
  long cases = 0;
  long failures = 0;  // beyond tolerance, or NaN
  mpfr worst = 0;
  std::string worst_case;
};

// Relative difference of the solver's value against the exact one (scale: |exact|, or `scale`
// when given, e.g. ∫n for a lost area that may be exactly 0).
void compare(Tally& t, const mpfr& got, const Rational& exact, const std::string& what, const Rational* scale = nullptr) {
  using std::abs;
  const mpfr want = to_mpfr(exact);
  const mpfr denom = scale ? to_mpfr(*scale) : abs(want);
  const mpfr rel = abs(got - want) / denom;
  ++t.cases;
  if (!(rel <= mpfr(kTolerance))) ++t.failures;
  if (rel > t.worst) {
    t.worst = rel;
    t.worst_case = what;
  }
  EXPECT_LE(rel, mpfr(kTolerance)) << what << "\n  solver: " << got.str(kDigits) << "\n  exact:  " << want.str(kDigits)
                                   << " = " << exact.str();
}

std::string list(const std::vector<Rational>& y) {
  std::string s = "{";
  for (std::size_t j = 0; j < y.size(); ++j) s += (j ? ", " : "") + y[j].str();
  return s + "}";
}

// Random rational u ∈ (0, 1].
Rational unit(std::mt19937& rng) {
  const int den = std::uniform_int_distribution<int>(1, 48)(rng);
  return q(std::uniform_int_distribution<int>(1, den)(rng), den);
}

// Integer samples in [−20, 20]: either uniform, or a few steep rises (one sample step each)
// followed by slow declines, so that n has 2–3 separate stick phases per period.
std::vector<Rational> random_samples(std::mt19937& rng, bool rises) {
  std::uniform_int_distribution<int> value(-20, 20);
  for (;;) {
    std::vector<Rational> y;
    if (!rises) {
      const int n = std::uniform_int_distribution<int>(2, 12)(rng);
      for (int j = 0; j < n; ++j) y.push_back(value(rng));
    } else {
      const int n = std::uniform_int_distribution<int>(6, 12)(rng);
      const int r = std::uniform_int_distribution<int>(2, 3)(rng);
      std::vector<int> v(n, 0);
      std::vector<bool> peak(n, false);
      for (int i = 0; i < r; ++i) peak[std::uniform_int_distribution<int>(0, n - 1)(rng)] = true;
      int level = std::uniform_int_distribution<int>(5, 20)(rng);
      for (int j = 0; j < n; ++j) {
        if (peak[j]) level = std::uniform_int_distribution<int>(0, 20)(rng);
        else level = std::max(-20, level - std::uniform_int_distribution<int>(0, 4)(rng));
        v[j] = level;
      }
      for (int x : v) y.push_back(x);
    }
    for (const Rational& x : y)
      if (x != y[0]) return y;
  }
}

TEST(EnvelopeVsSolver, RandomSampledWaveforms) {
  vibrofric::PrecisionScope precision(kDigits);
  std::mt19937 rng(20240611);
  Tally mu_tally, psi_tally;
  const auto start = std::chrono::steady_clock::now();
  long waves = 0;
  long phases[4] = {0, 0, 0, 0};  // cases by the solver's number of stick phases: 0, 1, 2, ≥ 3
  for (int trial = 0; trial < 3000; ++trial) {
    const bool rises = trial % 3 == 0;
    const std::vector<Rational> raw = random_samples(rng, rises);
    const env::NormalisedSamples norm = env::normalise_samples(raw);
    const env::Vertices w = env::samples(norm.y);
    const auto [lo, hi] = env::range(w);

    std::vector<mpfr> raw_m;
    for (const Rational& x : raw) raw_m.push_back(to_mpfr(x));
    const auto wave = vibrofric::make_samples<mpfr>("random", raw_m);
    ++waves;
    // The solver normalised the same raw samples the same way (to rounding).
    ASSERT_LE(abs(wave->normalisation().offset - to_mpfr(norm.offset)), mpfr(kTolerance) * to_mpfr(norm.scale));
    ASSERT_LE(abs(wave->normalisation().scale / to_mpfr(norm.scale) - 1), mpfr(kTolerance));
    ASSERT_LE(abs(wave->minimum() - to_mpfr(lo)), mpfr(kTolerance));
    ASSERT_LE(abs(wave->maximum() - to_mpfr(hi)), mpfr(kTolerance));

    Rational slope = 0;  // largest rising slope of w
    for (std::size_t j = 0; j < norm.y.size(); ++j)
      slope = std::max(slope, Rational((norm.y[(j + 1) % norm.y.size()] - norm.y[j]) * norm.y.size()));

    std::vector<Rational> slopes, levels;  // rising slopes of pieces; sample values below max w
    for (std::size_t j = 0; j < norm.y.size(); ++j) {
      const Rational d = (norm.y[(j + 1) % norm.y.size()] - norm.y[j]) * norm.y.size();
      if (d > 0) slopes.push_back(d);
      if (norm.y[j] < hi) levels.push_back(norm.y[j]);
    }
    auto pick = [&](const std::vector<Rational>& v) { return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)]; };

    for (int k = 0; k < 3; ++k) {
      // β in (0, 2·max slope]; every few cases exactly a piece's slope, or a hair off it (the
      // degenerate ties where a stick phase starts or ends on a whole piece).
      Rational beta = 2 * slope * unit(rng);
      if (k == 2) beta *= unit(rng);  // more weight on small β, where stick phases are long
      if (trial % 5 == 1) beta = pick(slopes) * (k == 0 ? q(1) : k == 1 ? q(999, 1000) : q(1001, 1000));
      // γ across (−max w, −min w + 1]: jumping below −min w, not above; also exactly at −min w
      // (Ψ's γ) and exactly at −w_j (n touching zero at a vertex), which only exists below max w.
      Rational gamma = -hi + (hi - lo + 1) * unit(rng);
      if (trial % 8 == 0 && k == 0) gamma = -lo;
      if (trial % 7 == 2 && k == 1 && !levels.empty()) gamma = -pick(levels);
      const std::string what = "samples " + list(raw) + ", beta = " + beta.str() + ", gamma = " + gamma.str() +
                               " (normalised samples " + list(norm.y) + ")";
      const env::Result exact = env::mu(w, beta, gamma);
      vibrofric::Result<mpfr> got;
      try {
        got = vibrofric::solve(*wave, to_mpfr(beta), to_mpfr(gamma));
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": solver threw " << e.what();
        continue;
      }
      compare(mu_tally, got.mu, exact.mu, "mu, " + what);
      ++phases[std::min<std::size_t>(got.stick_phases.size(), 3)];
      if (k == 0) {
        const Rational n_area = env::mu(w, beta, -lo).normal_area;  // scale of Ψ, which may be exactly 0
        try {
          compare(psi_tally, vibrofric::psi(*wave, to_mpfr(beta)).lost_area, env::psi(w, beta), "psi, " + what, &n_area);
        } catch (const std::exception& e) {
          ADD_FAILURE() << what << ": solver psi threw " << e.what();
        }
      }
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ envelope ] %ld sampled waveforms: %ld mu cases, %ld psi cases in %.1f s; max relative difference mu %s, psi %s\n",
              waves, mu_tally.cases, psi_tally.cases, secs, mu_tally.worst.str(3).c_str(), psi_tally.worst.str(3).c_str());
  std::printf("[ envelope ] stick phases per period: 0: %ld, 1: %ld, 2: %ld, >=3: %ld cases\n", phases[0], phases[1],
              phases[2], phases[3]);
  std::printf("[ envelope ] worst mu case: %s\n", mu_tally.worst_case.c_str());
  std::printf("[ envelope ] failures (beyond 1e-50 or NaN): mu %ld, psi %ld\n", mu_tally.failures, psi_tally.failures);
  EXPECT_GE(mu_tally.cases, 1000);
  EXPECT_GE(phases[2] + phases[3], 200);  // several stick phases are really exercised
}

TEST(EnvelopeVsSolver, CatalogueWavesWithJumps) {
  vibrofric::PrecisionScope precision(kDigits);
  std::mt19937 rng(97);
  Tally mu_tally, psi_tally;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::pair<std::string, env::Vertices>> waves{
      {"square", env::square()},
      {"sawtooth-left", env::sawtooth_left()},
      {"sawtooth-right", env::sawtooth_right()},
      {"triangle", env::triangle()}};
  for (const auto& [name, w] : waves) {
    const auto wave = vibrofric::make_waveform<mpfr>(vibrofric::parse_wave(name));
    for (int trial = 0; trial < 100; ++trial) {
      const Rational beta = 8 * unit(rng);
      const Rational gamma = -1 + 3 * unit(rng);  // (−1, 2]: jumping and not
      const std::string what = name + ", beta = " + beta.str() + ", gamma = " + gamma.str();
      try {
        compare(mu_tally, vibrofric::solve(*wave, to_mpfr(beta), to_mpfr(gamma)).mu, env::mu(w, beta, gamma).mu, "mu, " + what);
        if (trial % 4 == 0) {
          const Rational n_area = env::mu(w, beta, 1).normal_area;
          compare(psi_tally, vibrofric::psi(*wave, to_mpfr(beta)).lost_area, env::psi(w, beta), "psi, " + what, &n_area);
        }
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": solver threw " << e.what();
      }
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ envelope ] catalogue with jumps: %ld mu cases, %ld psi cases in %.1f s; max relative difference mu %s, psi %s\n",
              mu_tally.cases, psi_tally.cases, secs, mu_tally.worst.str(3).c_str(), psi_tally.worst.str(3).c_str());
  EXPECT_GE(mu_tally.cases, 400);
}

// Degenerate ties: β exactly (to rounding) the slope of a rising piece, so that a ramp can run
// along a whole piece of n. Every rising slope of every waveform, at 30, 60 and 100 digits.
TEST(EnvelopeVsSolver, BetaEqualToAPieceSlope) {
  std::mt19937 rng(4242);
  Tally tally;
  for (int trial = 0; trial < 150; ++trial) {
    const std::vector<Rational> raw = random_samples(rng, trial % 2 == 0);
    const env::NormalisedSamples norm = env::normalise_samples(raw);
    const env::Vertices w = env::samples(norm.y);
    const auto [lo, hi] = env::range(w);
    const std::size_t n = norm.y.size();
    const Rational gamma = -hi + (hi - lo + 1) * unit(rng);
    for (std::size_t j = 0; j < n; ++j) {
      const Rational beta = (norm.y[(j + 1) % n] - norm.y[j]) * n;
      if (!(beta > 0)) continue;
      const Rational exact = env::mu(w, beta, gamma).mu;
      for (unsigned digits : {30u, 60u, 100u}) {
        vibrofric::PrecisionScope precision(digits);
        std::vector<mpfr> raw_m;
        for (const Rational& x : raw) raw_m.push_back(to_mpfr(x));
        const auto wave = vibrofric::make_samples<mpfr>("random", raw_m);
        const std::string what = "mu at " + std::to_string(digits) + " digits, samples " + list(raw) + ", beta = " + beta.str() +
                                 ", gamma = " + gamma.str();
        try {
          const mpfr got = vibrofric::solve(*wave, to_mpfr(beta), to_mpfr(gamma)).mu;
          // Same 10-digit slack at every precision: 10^-(digits − 10).
          const mpfr rel = abs(got - to_mpfr(exact)) / to_mpfr(exact);
          ++tally.cases;
          if (!(rel <= pow(mpfr(10), -int(digits - 10)))) ++tally.failures;
          if (rel > tally.worst) tally.worst = rel;
          EXPECT_LE(rel, pow(mpfr(10), -int(digits - 10))) << what << "\n  solver: " << got.str(digits) << "\n  exact:  " << exact.str();
        } catch (const std::exception& e) {
          ++tally.failures;
          ADD_FAILURE() << what << ": solver threw " << e.what();
        }
      }
    }
  }
  std::printf("[ envelope ] beta = a piece's slope: %ld cases, %ld failures, max relative difference %s\n", tally.cases,
              tally.failures, tally.worst.str(3).c_str());
}

// Solver failures found by the two tests above, kept as they were found. In both, β equals (to
// rounding) the slope of a rising piece of n, and the stick ramp meets n at the start of that
// piece and runs along it: the solver returned NaN (a stick phase ending at −inf), at some
// precisions only (rounding decides which side of the tie it lands on).
//  - samples {4, 3, 0, −1, 12, 10, 8, 11, 9, 9, 9}, β = 66/13 (piece 8 → 11), γ = 313/143: the ramp
//    from φ = 3/11 meets n at 6/11 and follows it to 7/11; exact μ̄ = 283/313; NaN at 60 digits.
//  - samples {5, 6, 2, 2, 1, 1, 0, 11, 10, 7, 10}, β = 2 (piece 5 → 6), γ = 21/11: exact μ̄ = 25/33;
//    NaN at 100 digits.
TEST(EnvelopeVsSolver, RegressionRampAlongAPieceOfSlopeBeta) {
  struct Case {
    std::vector<Rational> raw;
    Rational beta, gamma, mu;
  };
  const std::vector<Case> cases{{{4, 3, 0, -1, 12, 10, 8, 11, 9, 9, 9}, q(66, 13), q(313, 143), q(283, 313)},
                                {{5, 6, 2, 2, 1, 1, 0, 11, 10, 7, 10}, q(2), q(21, 11), q(25, 33)}};
  for (const Case& c : cases) {
    const env::NormalisedSamples norm = env::normalise_samples(c.raw);
    ASSERT_EQ(env::mu(env::samples(norm.y), c.beta, c.gamma).mu, c.mu);
    for (unsigned digits : {30u, 60u, 100u}) {
      vibrofric::PrecisionScope precision(digits);
      std::vector<mpfr> raw_m;
      for (const Rational& x : c.raw) raw_m.push_back(to_mpfr(x));
      const auto wave = vibrofric::make_samples<mpfr>("regression", raw_m);
      const mpfr got = vibrofric::solve(*wave, to_mpfr(c.beta), to_mpfr(c.gamma)).mu;
      EXPECT_LE(abs(got / to_mpfr(c.mu) - 1), pow(mpfr(10), -int(digits - 10)))
          << "samples " << list(c.raw) << ", beta = " << c.beta << ", gamma = " << c.gamma << " at " << digits
          << " digits: solver " << got.str(digits) << ", exact " << c.mu;
    }
  }
}

}  // namespace
