// Returned quantities besides μ̄, at the working precision: event phases (Eqs. 4 and 8) against the
// same solver at twice the digits, the sine's value and slope next to its extrema against mpfr, and
// Ziv's rounding test of the precision ladder (evaluate_impl.hpp) on values next to a midpoint.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <optional>
#include <random>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "correct_rounding.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "evaluate_impl.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace {

using namespace vibrofric;

using vibrofric::testing::rounds_to_one;  // the exact reference for Ziv's test (correct_rounding.hpp)

// rounds_alike<T, X>(x, e) against rounds_to_one: it may answer true only where every number
// within e of x rounds alike, and must answer true where that still holds with e widened by
// 4 ulp of x in X (it widens by 2 ulp and rounds x ± e in X: at most 1 ulp more). Returns the
// exact decision.
template <class T, class X>
std::optional<T> expect_rounds_alike_is_right(const X& x, const X& e, const std::string& where) {
  using std::abs;
  const bool answer = detail::rounds_alike<T, X>(x, e);
  const X eps = std::numeric_limits<X>::epsilon();  // at the caller's precision, as rounds_alike's
  PrecisionScope scope(static_cast<unsigned>(std::max(2 * working_digits10<X>(), 60)));
  const mpfr xm(x), em(e);
  const std::optional<T> exact = rounds_to_one<T>(xm, em);
  const mpfr margin = 4 * mpfr(eps) * abs(xm);
  const bool clear = rounds_to_one<T>(xm, em + margin).has_value();
  EXPECT_TRUE(!answer || exact) << where << ": rounds_alike is true, but [x - e, x + e] holds a midpoint";
  EXPECT_TRUE(answer || !clear) << where << ": rounds_alike is false, but [x - e, x + e] is clear of the midpoints by "
                                << "4 ulp of x";
  return exact;
}

struct Case {
  const char* wave;
  const char* beta;
  const char* gamma;
};

// Sticks ending on curved flanks (root finders, not closed forms): without jumping across φ = 1,
// in the jumping range, a power-law cap and the wrap of a stick past argmin w.
const Case cases[] = {{"sine", "1", "1.5"}, {"sine", "3", "-0.5"}, {"sine", "0.7", "0.2"},
                      {"power:3", "2", "0.2"}, {"power:3", "5", "-0.4"}};

// Event phases of Real against mpfr at 2·digits + 20: each stick end is a root of d = n − ramp,
// whose evaluation carries a rounding of about 8 eps (|γ| + 2 + |level| + β) (solver.hpp), so the
// root is determined to that over |d'| = |n' − β| at the end, plus a few eps of the phase itself.
// Stick begins by n' = β come from closed forms or the same root finders.
template <class Real>
void event_phases_at_working_precision() {
  const int d = working_digits10<Real>();
  for (const Case& c : cases) {
    std::vector<StickPhase<Real>> got;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real beta = parse_real<Real>(c.beta, "beta"), gamma = parse_real<Real>(c.gamma, "gamma");
    {
      const auto w = make_waveform<Real>(parse_wave(c.wave));
      got = solve(*w, beta, gamma).stick_phases;
    }
    PrecisionScope scope(static_cast<unsigned>(2 * d + 20));
    const auto w = make_waveform<mpfr>(parse_wave(c.wave));
    const mpfr b(c.beta), g(c.gamma);
    const auto ref = solve(*w, b, g).stick_phases;
    ASSERT_FALSE(ref.empty()) << c.wave << " beta " << c.beta << " gamma " << c.gamma;
    ASSERT_EQ(got.size(), ref.size()) << c.wave << " beta " << c.beta << " gamma " << c.gamma;
    for (std::size_t k = 0; k < ref.size(); ++k) {
      const mpfr e(eps);
      const mpfr end = ref[k].end;
      const mpfr at = end - floor(end);
      std::size_t piece = 0;
      while (piece + 1 < w->piece_count() && w->piece_begin(piece + 1) <= at) ++piece;
      const mpfr slope_gap = abs(w->slope(piece, at) - b);
      const mpfr noise = 16 * e * (abs(g) + 2 + abs(mpfr(ref[k].level)) + b);
      const mpfr end_tol = noise / slope_gap + 8 * e * (1 + abs(end));
      const mpfr begin_tol = 8 * e * (1 + abs(mpfr(ref[k].begin)));
      const std::string where = std::string(c.wave) + " beta " + c.beta + " gamma " + c.gamma + ", stick " +
                                std::to_string(k) + " at " + std::to_string(d) + " digits";
      EXPECT_LE(abs(mpfr(got[k].begin) - ref[k].begin), begin_tol) << where << ": begin";
      EXPECT_LE(abs(mpfr(got[k].end) - end), end_tol) << where << ": end";
      EXPECT_LE(abs(mpfr(got[k].level) - ref[k].level), 8 * e * (abs(g) + 2)) << where << ": level";
    }
  }
}

TEST(Events, StickPhasesDouble) { event_phases_at_working_precision<double>(); }
TEST(Events, StickPhasesLongDouble) { event_phases_at_working_precision<long double>(); }
TEST(Events, StickPhasesBin50) { event_phases_at_working_precision<boost::multiprecision::cpp_bin_float_50>(); }
TEST(Events, StickPhasesMpfr40) {
  PrecisionScope scope(40);
  event_phases_at_working_precision<mpfr>();
}
// From 500 bits the sine's stick ends and acos (contact boundaries, onsets) take their first
// steps at reduced precision (waveform.hpp, coarse_from_bits): the same checks at 300 and 1000
// digits, against 620 and 2020.
TEST(Events, StickPhasesMpfr300And1000) {
  for (unsigned digits : {300u, 1000u}) {
    PrecisionScope scope(digits);
    event_phases_at_working_precision<mpfr>();
  }
}

// sin 2πφ and 2π cos 2πφ of the double sine within 4 ulp (relative) at phases 2^-j from the
// quarters, where one of them is small: the reduction to the nearest quarter keeps them accurate.
TEST(Events, SineValueAndSlopeNextToTheQuarters) {
  const auto w = make_waveform<double>(parse_wave("sine"));
  PrecisionScope scope(60);
  const mpfr two_pi = 2 * boost::math::constants::pi<mpfr>();
  for (int q = 0; q < 4; ++q) {
    for (int j = 8; j <= 44; j += 4) {
      for (double side : {-1.0, 1.0}) {
        const double phi = q / 4.0 + side * std::ldexp(1.0, -j);
        if (phi < 0) continue;
        std::size_t piece = 0;
        while (piece + 1 < w->piece_count() && w->piece_begin(piece + 1) <= phi) ++piece;
        const mpfr x = two_pi * mpfr(phi);
        const mpfr v = sin(x), s = two_pi * cos(x);
        const double eps = std::numeric_limits<double>::epsilon();
        EXPECT_LE(abs(mpfr(w->value(piece, phi)) - v), 4 * eps * abs(v)) << "value at " << phi;
        EXPECT_LE(abs(mpfr(w->slope(piece, phi)) - s), 4 * eps * abs(s)) << "slope at " << phi;
      }
    }
  }
}

// The tanh-sinh path against the exact one, every area it returns, in double: within the sum of
// the two paths' own bounds. Sticks that cross φ = 1 (after the sweep wraps past argmin w) and a
// loose tolerance (1e-3: the last levels' difference, not rounding, is then the error) included.
TEST(Events, QuadratureAreasWithinTheirBoundsOfTheExactOnes) {
  const double eps = std::numeric_limits<double>::epsilon();
  for (const Case& c : cases)
    for (double tolerance : {0.0, 1e-3}) {
      const auto w = make_waveform<double>(parse_wave(c.wave));
      const double beta = std::stod(c.beta), gamma = std::stod(c.gamma);
      Options exact, quad;
      exact.area = AreaMethod::exact;
      quad.area = AreaMethod::quadrature;
      quad.quadrature_tolerance = tolerance;
      const auto e = solve(*w, beta, gamma, exact), q = solve(*w, beta, gamma, quad);
      const std::string where = std::string(c.wave) + " beta " + c.beta + " gamma " + c.gamma + ", tolerance " +
                                std::to_string(tolerance);
      ASSERT_GT(q.quadratures, 0u) << where;
      EXPECT_LE(std::abs(q.mu - e.mu), (q.relative_error + e.relative_error) * e.mu + eps) << where << ": mu";
      EXPECT_LE(std::abs(q.lost_area - e.lost_area),
                q.lost_relative_error * q.lost_area + e.lost_relative_error * e.lost_area + eps)
          << where << ": lost area";
      EXPECT_LE(std::abs(q.normal_area - e.normal_area), q.normal_error + e.normal_error + eps) << where << ": normal area";
      EXPECT_LE(std::abs(q.retained_area - e.retained_area), q.retained_error + e.retained_error + eps)
          << where << ": retained area";
    }
}

// A long double x just above the midpoint of two doubles with an error bound e reaching below it:
// the double is not decided, whichever side x itself rounds to. Clear of the midpoint it is.
TEST(Events, RoundingTestSeesBothSidesOfTheInterval) {
  using detail::rounds_alike;
  const long double mid = 1.0L + std::ldexp(1.0L, -53);  // between 1 and 1 + 2^-52
  const long double above = mid + std::ldexp(1.0L, -60), below = mid - std::ldexp(1.0L, -60);
  const long double e = std::ldexp(1.0L, -58);
  EXPECT_FALSE((rounds_alike<double, long double>(above, e)));
  EXPECT_FALSE((rounds_alike<double, long double>(below, e)));
  const long double clear = 1.0L + std::ldexp(1.0L, -55);  // a quarter ulp of double above 1
  EXPECT_TRUE((rounds_alike<double, long double>(clear, e)));
  EXPECT_TRUE((rounds_alike<double, long double>(-clear, e)));
  EXPECT_FALSE((rounds_alike<double, long double>(-above, e)));
}

// rounds_alike near the midpoints of double, where its answer matters: x = m + δ for a midpoint m
// of two doubles (above a random double, and below a power of two, where the gap halves), |δ|
// from 1/4 ulp to 2^-40 ulp, e from 1/2 |δ| to 2 |δ|; in long double (the ladder's second rung;
// |δ| ≥ 2^-8 ulp, representable) and in mpfr at 60 digits (the third). Each answer against the
// exact decision (expect_rounds_alike_is_right); both decisions occur.
template <class X>
void check_rounds_alike_near_midpoints(int finest) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(1, 2);
  std::size_t decided = 0, undecided = 0;
  for (int trial = 0; trial < 64; ++trial) {
    const double t = std::ldexp(trial % 4 == 0 ? 1.0 : u(rng), static_cast<int>(rng() % 41) - 20);
    const bool below = trial % 4 == 0;  // the midpoint under a power of two
    const double n = std::nextafter(t, below ? 0.0 : HUGE_VAL);
    const X m = (X(t) + X(n)) / 2, gap = below ? X(t) - X(n) : X(n) - X(t);
    for (int j = 2; j <= finest; j += 2)
      for (double side : {-1.0, 1.0})
        for (double f : {0.5, 0.999, 1.0, 1.001, 2.0}) {
          using std::ldexp;
          const X delta = ldexp(gap, -j) * side, x = m + delta;
          const X e = ldexp(gap, -j) * f;  // gap > 0
          const std::string where = "midpoint of " + format_significant(t, 17) + " and " + format_significant(n, 17) +
                                    (side < 0 ? " - " : " + ") + "2^-" + std::to_string(j) + " ulp, e = " +
                                    std::to_string(f) + " |delta|";
          (expect_rounds_alike_is_right<double, X>(x, e, where) ? decided : undecided)++;
        }
  }
  EXPECT_GT(decided, 0u);
  EXPECT_GT(undecided, 0u);
}

TEST(Events, RoundsAlikeNearMidpointsAgreesWithAnExactDecision) {
  check_rounds_alike_near_midpoints<long double>(8);
  PrecisionScope scope(60);
  check_rounds_alike_near_midpoints<mpfr>(40);
}

// The first rung accepts a value as its own correct rounding when its error stays strictly inside
// half the gap to each neighbour: 1.5 has gaps of 2^-52 on both sides, 1 has 2^-53 below it.
template <class T>
void check_rounds_to_itself(int bits) {
  using detail::rounds_to_itself;
  using std::ldexp;
  const T x = T(3) / 2, gap = ldexp(T(1), 1 - bits);  // the ulp of 1.5
  EXPECT_TRUE(rounds_to_itself(x, T(0)));
  EXPECT_TRUE(rounds_to_itself(-x, gap / 4));
  EXPECT_TRUE(rounds_to_itself(x, gap / 2 * (1 - ldexp(T(1), -20))));
  EXPECT_FALSE(rounds_to_itself(x, gap / 2));  // its true value may be the midpoint
  EXPECT_TRUE(rounds_to_itself(T(1), gap / 8));
  EXPECT_FALSE(rounds_to_itself(T(1), gap / 4));  // half the gap below 1
  EXPECT_TRUE(rounds_to_itself(T(1), T(0)));
  EXPECT_FALSE(rounds_to_itself(std::numeric_limits<T>::quiet_NaN(), T(0)));
  EXPECT_FALSE(rounds_to_itself(x, std::numeric_limits<T>::infinity()));
  EXPECT_FALSE(rounds_to_itself(std::numeric_limits<T>::max(), T(0)));
}

TEST(Events, RoundsToItselfWithinHalfTheGapOnEachSide) {
  check_rounds_to_itself<double>(53);
  check_rounds_to_itself<long double>(64);
  check_rounds_to_itself<boost::multiprecision::cpp_bin_float_50>(std::numeric_limits<boost::multiprecision::cpp_bin_float_50>::digits);
}

// Every rung's answer, in double and long double, for μ̄ and Ψ, against the solver at 60 digits
// correctly rounded to the type: every point is compared, the reference's rounding decided exactly
// by rounds_to_one from its own bound (at 120 digits where 60 do not decide it), and rounds_alike's
// answer on it checked against that decision. Points are random and some reach mpfr (values near
// a midpoint), whose rung starts at the type's digits + 8 and must then agree too.
template <class T>
void check_ladder_against_60_digits(NumberType type) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t points_total = 0, compared = 0, at_120 = 0;
  LadderCounts counts;
  for (const char* wave : {"sine", "power:3", "sawtooth-left"}) {
    const WaveSpec spec = parse_wave(wave);
    for (Quantity q : {Quantity::mu, Quantity::psi}) {
      std::vector<Point> points;
      for (int i = 0; i < 150; ++i) {
        char b[32], g[32];
        std::snprintf(b, sizeof b, "%.6g", 0.01 + 5 * u(rng));
        std::snprintf(g, sizeof g, "%.6g", -0.95 + 3 * u(rng));
        points.push_back({b, g});
      }
      BatchOptions options;
      options.ladder = &counts;
      const auto got = evaluate(spec, q, points, {type, 0}, options);
      points_total += points.size();
      for (std::size_t i = 0; i < points.size(); ++i) {
        const std::string where = std::string(wave) + (q == Quantity::mu ? " mu" : " psi") + " beta " + points[i].beta.text() +
                                  " gamma " + points[i].gamma.text();
        std::optional<T> want;
        for (unsigned digits : {60u, 120u}) {
          PrecisionScope scope(digits);
          const auto w = make_waveform<mpfr>(spec);
          const mpfr beta(points[i].beta.text()), gamma(points[i].gamma.text());
          const Result<mpfr> r = q == Quantity::mu ? solve(*w, beta, gamma) : psi(*w, beta);
          const mpfr value = q == Quantity::mu ? r.mu : r.lost_area;
          const mpfr error = abs(value) * (q == Quantity::mu ? r.relative_error : r.lost_relative_error);
          want = expect_rounds_alike_is_right<T, mpfr>(value, error, where + " at " + std::to_string(digits) + " digits");
          if (want) break;
          if (digits == 60) ++at_120;
        }
        if (!want) {
          ADD_FAILURE() << where << ": the reference at 120 digits does not decide the rounding";
          continue;
        }
        ++compared;
        EXPECT_EQ(got[i], format_significant(*want, std::numeric_limits<T>::max_digits10)) << where;
      }
    }
  }
  EXPECT_EQ(compared, points_total);
  std::printf("[ ladder ] %s: %zu of %zu points compared, %zu references needed 120 digits\n",
              std::is_same_v<T, double> ? "double" : "long double", compared, points_total, at_120);
  EXPECT_GT(counts.mpfr.load(), 0u);
  // double: most points end on the long double rung. long double has no rung between itself and
  // mpfr, and its own value is certified only where exact: nearly every point reaches mpfr.
  if (std::is_same_v<T, double>) {
    EXPECT_GT(counts.long_double.load(), counts.mpfr.load());
  }
}

TEST(Events, LadderAgreesWithSixtyDigitsInDoubleAndLongDouble) {
  check_ladder_against_60_digits<double>(NumberType::float64);
  check_ladder_against_60_digits<long double>(NumberType::float80);
}

// Each point is counted once, on the rung that answered it. μ̄ = 1 for β ≥ β_c is exact (bound 0):
// the double's own rung certifies it. Inside, the double bound is about 20 eps (sine, β = 1,
// γ = 0.5), far above the half ulp the first rung needs, so a wider rung answers, and the value is
// the 40-digit one correctly rounded.
TEST(Events, LadderCountsTheRungThatAnswered) {
  const WaveSpec sine = parse_wave("sine");
  Precision precision;
  precision.type = NumberType::float64;
  LadderCounts counts;
  BatchOptions options;
  options.ladder = &counts;
  EXPECT_EQ(evaluate(sine, Quantity::mu, {{"100", "0.5"}, {"7", "2"}}, precision, options),
            (std::vector<std::string>{"1.0000000000000000", "1.0000000000000000"}));
  EXPECT_EQ(counts.own, 2u);
  EXPECT_EQ(counts.long_double + counts.mpfr, 0u);
  const std::vector<Point> inside = {{"1", "0.5"}, {"0.25", "-0.5"}, {"3", "-0.5"}, {"0.25", "1"}};
  const auto got = evaluate(sine, Quantity::mu, inside, precision, options);
  EXPECT_EQ(counts.own, 2u);
  EXPECT_EQ(counts.long_double + counts.mpfr, inside.size());
  for (std::size_t i = 0; i < inside.size(); ++i) {
    PrecisionScope scope(40);
    const auto w = make_waveform<mpfr>(sine);
    const Result<mpfr> r = solve(*w, mpfr(inside[i].beta.text()), mpfr(inside[i].gamma.text()));
    const std::optional<double> want = rounds_to_one<double>(r.mu, r.mu * r.relative_error);
    ASSERT_TRUE(want) << inside[i].beta << " " << inside[i].gamma << ": 40 digits do not decide the rounding";
    EXPECT_EQ(std::stod(got[i]), *want) << inside[i].beta << " " << inside[i].gamma;
  }
  options.escalate = false;
  evaluate(sine, Quantity::mu, inside, precision, options);
  EXPECT_EQ(counts.own, 2u + inside.size());
}

}  // namespace
