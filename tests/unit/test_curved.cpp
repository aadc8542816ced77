// Curved contacts (model.md, "Curved contacts (MDR)"; curved.hpp, profile.hpp): every quantity
// solve_curved returns, against closed forms (Eq. 19 carried to every profile, Hertz and Sneddon
// mean loads), independent quadratures (the MDR transform, the phase average of the load) and the
// same algorithm at twice the precision. Tolerances are in digits of the working precision.
#include <gtest/gtest.h>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <string>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/verification/closed_forms.hpp"
#include "vibrofric/verification/curved_closed_forms.hpp"

namespace {

using namespace vibrofric;

mpfr M(const char* s) { return mpfr(s); }

template <class Real>
CurvedResult<Real> curved(const std::string& wave, const std::string& profile, const Real& beta, const Real& gamma) {
  const auto w = make_waveform<Real>(parse_wave(wave));
  const auto p = make_profile<Real>(parse_profile(profile));
  return solve_curved(*w, *p, beta, gamma);
}

std::string write_profile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const std::vector<std::string> kProfiles{"sphere", "cone", "power:3", "power:2.5", "wearflat:0.3", "wearflat:7"};

// Eq. 19 for every profile: in the jumping range every spring has the triangular waves' ratio,
// so the row has it too (the invariance under clipping carries over). At 50 digits.
TEST(CurvedClosedForm, TriangularWavesKeepEq19OnEveryProfileAt50Digits) {
  PrecisionScope scope(50);
  const mpfr eps = std::numeric_limits<mpfr>::epsilon();
  for (const auto& profile : kProfiles)
    for (const char* beta : {"0.25", "1", "3.5"})
      for (const char* gamma : {"1", "0.5", "-0.3", "-0.95"}) {
        const mpfr b = M(beta), g = M(gamma);
        const struct {
          const char* wave;
          mpfr mu;
        } cases[] = {{"triangle", closed_form::mu_triangle_jumping(b)},
                     {"sawtooth-right", closed_form::mu_sawtooth_right_jumping(b)},
                     {"sawtooth-left", closed_form::mu_sawtooth_left_jumping(b)}};
        for (const auto& c : cases) {
          const auto r = curved<mpfr>(c.wave, profile, b, g);
          const mpfr err = abs(r.mu - c.mu);
          SCOPED_TRACE(std::string(c.wave) + " " + profile + " beta " + beta + " gamma " + gamma);
          EXPECT_LE(err, r.relative_error * c.mu) << "the error estimate must cover the error";
          EXPECT_LE(err, 1e5 * eps) << "45 of 50 digits";
          EXPECT_LE(r.relative_error, 1e6 * eps);
        }
      }
}

// The closed forms of proofs/curved_closed_forms.md (curved_closed_forms.hpp) against the solver
// at 50 digits: μ̄, both integrals and the contact edge to 45 digits, on power:n and the wear flat,
// in every regime (centre jumping or not, β on both sides of the square wave's kink and of β_c).
TEST(CurvedClosedForm, SolverAgreesWithTheClosedFormsTo45Digits) {
  PrecisionScope scope(50);
  const mpfr tol = pow(mpfr(10), -45);
  using closed_form::CatalogueWave;
  const std::pair<const char*, CatalogueWave> waves[] = {{"triangle", CatalogueWave::triangle},
                                                         {"sawtooth-right", CatalogueWave::sawtooth_right},
                                                         {"sawtooth-left", CatalogueWave::sawtooth_left},
                                                         {"square", CatalogueWave::square}};
  int k = 0;
  for (const auto& [wave, cw] : waves)
    for (const char* profile : {"power:1", "power:2", "power:3", "power:2.5", "wearflat:0.4", "wearflat:30"})
      for (const char* gamma : {"3", "1.2", "0.6", "-0.4", "-0.97"}) {
        const char* beta = (++k % 3 == 0) ? "0.4" : (k % 3 == 1 ? "1.5" : "5");
        const mpfr b = M(beta), g = M(gamma);
        const auto spec = parse_profile(profile);
        const mpfr par(spec.parameter.text());
        const auto cf = spec.kind == ProfileKind::power ? closed_form::power_profile_integrals(cw, par, b, g)
                                                        : closed_form::wearflat_integrals(cw, par, b, g);
        const auto r = curved<mpfr>(wave, profile, b, g);
        SCOPED_TRACE(std::string(wave) + " " + profile + " beta " + beta + " gamma " + gamma);
        EXPECT_LE(abs(r.mu - cf.mu), tol * cf.mu);
        EXPECT_LE(abs(r.mu - cf.mu), r.relative_error * cf.mu + 4 * std::numeric_limits<mpfr>::epsilon());
        EXPECT_LE(abs(r.friction_integral - cf.friction_integral), tol * cf.friction_integral);
        EXPECT_LE(abs(r.normal_integral - cf.normal_integral), tol * cf.normal_integral);
        EXPECT_LE(abs(r.contact_radius - cf.contact_radius), tol * cf.contact_radius);
      }
}

// A steep power law, σ = x^N with N = 10^3 and 10^6, nearly a flat punch of radius 1: σ changes
// within about 1/N of the contact edge, a feature that Gauss rules of 8 and 12 points both miss
// (they agreed on the flat punch's 11/15 for the square wave at β = 1.5, γ = −0.6, where the
// closed form gives 0.73333347). In double and long double against the closed forms at 40 digits:
// the error within the solver's bound. The bound is at least 10 digits: for N = 1e3 it is 7.6e-12
// in both types (the segment at the edge ends on tanh-sinh, accepted at half the digits).
template <class Real>
void expect_steep_profile(const char* wave, closed_form::CatalogueWave cw, const char* n, const char* beta, const char* gamma) {
  const Real b = parse_real<Real>(beta, "beta"), g = parse_real<Real>(gamma, "gamma");
  const auto r = curved<Real>(wave, std::string("power:") + n, b, g);
  PrecisionScope scope(40);
  const mpfr ref = closed_form::mu_power_profile(cw, mpfr(n), mpfr(b), mpfr(g));
  SCOPED_TRACE(std::string(wave) + " power:" + n + " beta " + beta + " gamma " + gamma + " in " +
               std::to_string(std::numeric_limits<Real>::digits) + " bits");
  EXPECT_LE(abs(mpfr(r.mu) - ref), mpfr(r.relative_error) * ref);
  EXPECT_LE(r.relative_error, Real(1e-10));
}

TEST(CurvedClosedForm, SteepPowerProfilesAgreeWithTheClosedForms) {
  using closed_form::CatalogueWave;
  for (const char* n : {"1e3", "1e6"})
    for (const auto& [b, g] : std::vector<std::pair<const char*, const char*>>{{"1.5", "-0.6"}, {"0.7", "0.3"}}) {
      expect_steep_profile<double>("square", CatalogueWave::square, n, b, g);
      expect_steep_profile<long double>("square", CatalogueWave::square, n, b, g);
      expect_steep_profile<double>("triangle", CatalogueWave::triangle, n, b, g);
      expect_steep_profile<long double>("sawtooth-left", CatalogueWave::sawtooth_left, n, b, g);
    }
}

// ⟨F_N⟩ closed forms: a power-law punch pressed to depth d carries ∫₀^{d^{1/N}} (d − x^N) dx =
// d^{1+1/N} N/(N+1) on the half-row (Hertz for N = 2, Sneddon for N = 1), the wear-flat sphere
// d + d(ξ − 1) − (λ/3)(ξ² − 1)^{3/2} with λξ√(ξ² − 1) = d. The phase average of that over
// d = max(γ + w, 0) is an independent tanh-sinh quadrature in φ, split at the contact boundaries.
mpfr mean_load(const std::string& wave, const std::string& profile, const mpfr& gamma) {
  const auto spec = parse_profile(profile);
  const mpfr n = spec.kind == ProfileKind::power ? mpfr(spec.parameter.text()) : mpfr(0);
  const mpfr lambda = spec.kind == ProfileKind::wearflat ? mpfr(spec.parameter.text()) : mpfr(0);
  auto load = [&](const mpfr& d) -> mpfr {
    if (!(d > 0)) return mpfr(0);
    if (spec.kind == ProfileKind::power) return pow(d, 1 + 1 / n) * n / (n + 1);
    const mpfr q = d / lambda;
    const mpfr xi = sqrt((1 + sqrt(1 + 4 * q * q)) / 2);
    return d * xi - lambda / 3 * pow(xi * xi - 1, mpfr(3) / 2);
  };
  const auto w = make_waveform<mpfr>(parse_wave(wave));
  // Breakpoints: the pieces of w and where γ + w = 0 on them.
  std::vector<mpfr> xs;
  detail::RootStats stats;
  for (std::size_t i = 0; i < w->piece_count(); ++i) {
    xs.push_back(w->piece_begin(i));
    mpfr c0, c1;
    if (w->contact_part(i, gamma, c0, c1, stats)) {
      xs.push_back(c0);
      xs.push_back(c1);
    }
  }
  xs.push_back(mpfr(1));
  std::sort(xs.begin(), xs.end());
  boost::math::quadrature::tanh_sinh<mpfr> q(20);
  mpfr sum = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    if (!(xs[k + 1] > xs[k])) continue;
    const mpfr mid = (xs[k] + xs[k + 1]) / 2;
    const std::size_t piece = [&] {
      std::size_t i = 0;
      while (i + 1 < w->piece_count() && w->piece_begin(i + 1) <= mid) ++i;
      return i;
    }();
    sum += q.integrate([&](const mpfr& phi) -> mpfr { return load(gamma + w->value(piece, phi)); }, xs[k], xs[k + 1]);
  }
  return sum;
}

TEST(CurvedClosedForm, NormalIntegralIsTheMeanHertzSneddonAndWearFlatLoadAt40Digits) {
  PrecisionScope scope(40);
  const mpfr eps = std::numeric_limits<mpfr>::epsilon();
  for (const char* wave : {"sine", "triangle", "square", "power:3"})
    for (const char* profile : {"sphere", "cone", "power:3", "wearflat:0.5", "wearflat:20"})
      for (const char* gamma : {"2", "0.5", "-0.6"}) {
        const auto r = curved<mpfr>(wave, profile, M("0.7"), M(gamma));
        const mpfr ref = mean_load(wave, profile, M(gamma));
        SCOPED_TRACE(std::string(wave) + " " + profile + " gamma " + gamma);
        EXPECT_LE(abs(r.normal_integral - ref), 1e4 * eps * ref);
        // The contact edge: σ(X) = γ + max w; for the wear flat as the backward error of
        // X²(X² − 1) = (σ/λ)² (σ(x) is ill-conditioned next to the flat's edge).
        const auto spec = parse_profile(profile);
        const mpfr X = r.contact_radius, s = M(gamma) + 1;
        if (spec.kind == ProfileKind::power)
          EXPECT_LE(abs(pow(X, mpfr(spec.parameter.text())) - s), 16 * eps * s);
        else
          EXPECT_LE(abs(X * X * (X * X - 1) - pow(s / mpfr(spec.parameter.text()), 2)), 16 * eps * pow(X, 4));
      }
}

// The same algorithm at twice the digits: μ̄, both integrals, and that the error estimate at 30
// digits covers the difference.
TEST(CurvedPrecision, ThirtyDigitsAgreeWithSixtyWithinTheirEstimate) {
  int k = 0;
  for (const char* wave : {"sine", "square", "power:3", "sawtooth-left"})
    for (const char* profile : {"sphere", "cone", "wearflat:1", "power:3.5"})
      for (const char* gamma : {"2.5", "0.5", "-0.3", "-0.9"}) {
          const char* beta = ++k % 2 ? "0.3" : "2";
          CurvedResult<mpfr> lo, hi;
          {
            PrecisionScope scope(25);
            lo = curved<mpfr>(wave, profile, M(beta), M(gamma));
          }
          PrecisionScope scope(50);
          hi = curved<mpfr>(wave, profile, M(beta), M(gamma));
          SCOPED_TRACE(std::string(wave) + " " + profile + " beta " + beta + " gamma " + gamma);
          const mpfr eps30 = pow(mpfr(10), -24);
          EXPECT_LE(abs(lo.mu - hi.mu), lo.relative_error * hi.mu);
          // The estimate is Boost's difference of the last two tanh-sinh levels, which stalls at
          // 1e3–1e5 eps where the integrand's rounding dominates (measured): it may exceed the
          // actual error by that much, never fall below it (line above).
          EXPECT_LE(lo.relative_error, 1e6 * eps30);
          EXPECT_LE(abs(lo.friction_integral - hi.friction_integral), 1e4 * eps30 * hi.friction_integral);
          EXPECT_LE(abs(lo.normal_integral - hi.normal_integral), 1e4 * eps30 * hi.normal_integral);
          EXPECT_LE(abs(lo.contact_radius - hi.contact_radius), 10 * eps30 * hi.contact_radius);
          EXPECT_EQ(lo.gamma_breaks.size(), hi.gamma_breaks.size());
          EXPECT_EQ(lo.center_jumps, M(gamma) < 1);
        }
}

// Eq. 6 for a curved contact: β_c(γ') grows with γ', so the central spring's β_c decides.
TEST(CurvedEq6, NoStickAtOrAboveTheCentralBetaC) {
  PrecisionScope scope(30);
  for (const char* profile : {"sphere", "wearflat:2"})
    for (const char* gamma : {"0.5", "-0.5"}) {
      const mpfr g = M(gamma);
      const mpfr bc = 2 * boost::math::constants::pi<mpfr>() * (g >= 0 ? mpfr(1) : sqrt(1 - g * g));
      auto at = curved<mpfr>("sine", profile, bc, g);
      EXPECT_EQ(at.mu, 1);
      EXPECT_LE(abs(at.beta_c - bc), 1e-28);
      EXPECT_EQ(at.friction_integral, at.normal_integral);
      auto below = curved<mpfr>("sine", profile, mpfr(bc * (1 - mpfr(1e-6))), g);
      EXPECT_LT(below.mu, 1);
    }
}

// The γ' breakpoints that closed forms give: the sine's tangency points ±√(1 − (β/2π)²) (onset
// kind, β = β_c(γ')), its piece ends 0 and the square wave's kink γ' = β/2 − 1 (Eq. 22).
TEST(CurvedBreakpoints, ContainTheClosedFormKinks) {
  PrecisionScope scope(40);
  const mpfr eps = std::numeric_limits<mpfr>::epsilon();
  auto contains = [&](const std::vector<mpfr>& v, const mpfr& x) {
    for (const auto& y : v)
      if (abs(y - x) <= 16 * eps) return true;
    return false;
  };
  const mpfr beta = M("2");
  const mpfr c = sqrt(1 - pow(beta / (2 * boost::math::constants::pi<mpfr>()), 2));
  const auto s = curved<mpfr>("sine", "sphere", beta, M("1.5"));
  EXPECT_TRUE(contains(s.gamma_breaks, c));
  EXPECT_TRUE(contains(s.gamma_breaks, mpfr(-c)));
  EXPECT_TRUE(contains(s.gamma_breaks, mpfr(0)));
  EXPECT_TRUE(contains(s.gamma_breaks, mpfr(1)));
  const auto q = curved<mpfr>("square", "sphere", M("1"), M("0.5"));
  EXPECT_TRUE(contains(q.gamma_breaks, M("-0.5")));
  for (const auto& g : q.gamma_breaks) EXPECT_TRUE(g > -1 && g < M("0.5"));
}

// The Gauss–Legendre rules of the spring integral (detail/gauss_legendre.hpp): the 5-point rule
// against its closed form, and every rule exact for u^k up to k = 2n − 1, with the classical error
// (n!)^4 / ((2n)!)^2 relative for u^2n (to 1 %, where that is above rounding): a rule with wrong
// nodes fails the first, a rule of another order the second. Tolerance: the sum of n terms each
// rounded once, 8·n·eps of the working type.
template <class Real>
void check_gauss_rules() {
  using std::abs;
  using std::pow;
  const Real eps = std::numeric_limits<Real>::epsilon() > 0 ? std::numeric_limits<Real>::epsilon() : Real(pow(Real(10), -working_digits10<Real>()));
  for (std::size_t n : {1u, 2u, 5u, 12u, 40u}) {
    const auto& rule = detail::gauss_legendre<Real>(n);
    ASSERT_EQ(rule.nodes.size(), n);
    ASSERT_EQ(rule.weights.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_TRUE(rule.nodes[i] > 0 && rule.nodes[i] < 1) << n;
      if (i > 0) {
        EXPECT_TRUE(rule.nodes[i] > rule.nodes[i - 1]) << n;
      }
      EXPECT_LE(abs(rule.nodes[i] + rule.nodes[n - 1 - i] - 1), 2 * eps) << n << " " << i;  // symmetric
      EXPECT_LE(abs(rule.weights[i] - rule.weights[n - 1 - i]), 2 * eps * rule.weights[i]) << n << " " << i;
    }
    for (std::size_t k = 0; k <= 2 * n; ++k) {
      Real sum = 0;
      for (std::size_t i = 0; i < n; ++i) sum += rule.weights[i] * pow(rule.nodes[i], static_cast<int>(k));
      const Real exact = Real(1) / Real(k + 1), err = abs(sum - exact) / exact;
      if (k < 2 * n) {
        EXPECT_LE(err, 8 * n * eps) << "n = " << n << ", u^" << k;
      } else {
        const double nn = static_cast<double>(n);
        const double expected = std::exp(4 * std::lgamma(nn + 1) - 2 * std::lgamma(2 * nn + 1));
        if (expected > 1000 * 8 * nn * static_cast<double>(eps)) {
          EXPECT_NEAR(static_cast<double>(err), expected, expected / 100) << "n = " << n << ", u^" << k;
        }
      }
    }
  }
}

TEST(CurvedQuadrature, GaussRulesAreExactToDegree2nMinus1InEveryType) {
  check_gauss_rules<double>();
  check_gauss_rules<long double>();
  check_gauss_rules<bin50>();
  PrecisionScope scope(60);
  check_gauss_rules<mpfr>();
  // The 5-point rule in closed form: x = 0, ±sqrt(5 ∓ 2 sqrt(10/7))/3, weights 128/225 and
  // (322 ± 13 sqrt 70)/900 on [−1, 1]; on [0, 1] u = (1 + x)/2 and half the weights.
  const auto& r = detail::gauss_legendre<mpfr>(5);
  const mpfr s = sqrt(mpfr(10) / 7), inner = sqrt(5 - 2 * s) / 3, outer = sqrt(5 + 2 * s) / 3;
  const mpfr u[5] = {(1 - outer) / 2, (1 - inner) / 2, mpfr(1) / 2, (1 + inner) / 2, (1 + outer) / 2};
  const mpfr wo = (322 - 13 * sqrt(mpfr(70))) / 1800, wi = (322 + 13 * sqrt(mpfr(70))) / 1800;
  const mpfr w[5] = {wo, wi, mpfr(64) / 225, wi, wo};
  for (int i = 0; i < 5; ++i) {
    EXPECT_LE(abs(r.nodes[i] - u[i]), mpfr("1e-59")) << i;
    EXPECT_LE(abs(r.weights[i] - w[i]), mpfr("1e-59")) << i;
  }
}

// The Gauss–Kronrod pairs of the spring integral (detail/gauss_legendre.hpp): 2n + 1 nodes
// ascending in (0, 1), alternating added node and Gauss node, the Gauss nodes and weights bit for
// bit gauss_legendre's (the pair's n-point value is that rule's); the Kronrod weights positive,
// symmetric and exact for u^k up to k = 3n + 1, and not for the next even power about u = 1/2
// (where that is above rounding): wrong added nodes or weights fail the second, a rule of another
// degree the third. Tolerance: 2n + 1 terms each rounded once, 8(2n + 1)·eps of the working type.
// The 15-point rule of order 7 against QUADPACK's table (qk15, Piessens et al. 1983, 15 digits),
// and order 1, which is the 3-point Gauss rule, against its closed form.
template <class Real>
void check_kronrod_rules(bool beyond) {
  using std::abs;
  using std::pow;
  const Real eps = std::numeric_limits<Real>::epsilon() > 0 ? std::numeric_limits<Real>::epsilon() : Real(pow(Real(10), -working_digits10<Real>()));
  for (std::size_t n : {1u, 2u, 3u, 5u, 12u, 19u, 40u}) {
    const auto& rule = detail::gauss_kronrod<Real>(n);
    const auto& gauss = detail::gauss_legendre<Real>(n);
    const std::size_t m = 2 * n + 1;
    ASSERT_EQ(rule.nodes.size(), m);
    ASSERT_EQ(rule.weights.size(), m);
    ASSERT_EQ(rule.gauss_weights.size(), m);
    for (std::size_t i = 0; i < m; ++i) {
      EXPECT_TRUE(rule.nodes[i] > 0 && rule.nodes[i] < 1) << n;
      if (i > 0) {
        EXPECT_TRUE(rule.nodes[i] > rule.nodes[i - 1]) << n << " " << i;
      }
      EXPECT_TRUE(rule.weights[i] > 0) << n << " " << i;
      EXPECT_LE(abs(rule.nodes[i] + rule.nodes[m - 1 - i] - 1), 2 * eps) << n << " " << i;
      EXPECT_LE(abs(rule.weights[i] - rule.weights[m - 1 - i]), 2 * eps * rule.weights[i]) << n << " " << i;
      if (i % 2 == 0) {
        EXPECT_TRUE(rule.gauss_weights[i] == 0) << n << " " << i;
      } else {
        EXPECT_TRUE(rule.nodes[i] == gauss.nodes[i / 2]) << n << " " << i;
        EXPECT_TRUE(rule.gauss_weights[i] == gauss.weights[i / 2]) << n << " " << i;
      }
    }
    const Real tol = 8 * Real(m) * eps;
    for (std::size_t k = 0; k <= 3 * n + 1; ++k) {
      Real sum = 0;
      for (std::size_t i = 0; i < m; ++i) sum += rule.weights[i] * pow(rule.nodes[i], static_cast<int>(k));
      const Real exact = Real(1) / Real(k + 1);
      EXPECT_LE(abs(sum - exact) / exact, tol) << "n = " << n << ", u^" << k;
    }
    // (2u − 1)^k, k the first even power above 3n + 1: ∫ = 1/(k + 1); the rule misses it by far
    // more than rounding for small n.
    if (beyond && n <= 12) {
      const std::size_t k = (3 * n + 2) % 2 == 0 ? 3 * n + 2 : 3 * n + 3;
      Real sum = 0;
      for (std::size_t i = 0; i < m; ++i) sum += rule.weights[i] * pow(Real(2 * rule.nodes[i] - 1), static_cast<int>(k));
      const Real exact = Real(1) / Real(k + 1);
      EXPECT_GT(abs(sum - exact) / exact, 1e6 * tol) << "n = " << n << ", (2u - 1)^" << k;
    }
  }
}

TEST(CurvedQuadrature, KronrodRulesAreExactToDegree3nPlus1InEveryType) {
  check_kronrod_rules<double>(false);
  check_kronrod_rules<long double>(false);
  check_kronrod_rules<bin50>(true);
  {
    PrecisionScope scope(60);
    check_kronrod_rules<mpfr>(true);
  }
  // qk15: abscissae and weights on [−1, 1] from the centre out (xgk, wgk); here on [0, 1].
  const double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                         0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                         0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                         0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
  const double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                         0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                         0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                         0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
  const auto& k15 = detail::gauss_kronrod<double>(7);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(k15.nodes[i], (1 - xgk[i]) / 2, 1e-15) << i;
    EXPECT_NEAR(k15.nodes[14 - i], (1 + xgk[i]) / 2, 1e-15) << i;
    EXPECT_NEAR(k15.weights[i], wgk[i] / 2, 1e-15) << i;
  }
  // Order 1: the added nodes ±√(3/5) with the centre make the 3-point Gauss rule, weights 5/18, 4/9.
  PrecisionScope scope(60);
  const auto& k3 = detail::gauss_kronrod<mpfr>(1);
  const mpfr x = sqrt(mpfr(3) / 5);
  EXPECT_LE(abs(k3.nodes[0] - (1 - x) / 2), mpfr("1e-59"));
  EXPECT_LE(abs(k3.nodes[1] - mpfr(1) / 2), mpfr("1e-59"));
  EXPECT_LE(abs(k3.nodes[2] - (1 + x) / 2), mpfr("1e-59"));
  EXPECT_LE(abs(k3.weights[0] - mpfr(5) / 18), mpfr("1e-59"));
  EXPECT_LE(abs(k3.weights[1] - mpfr(4) / 9), mpfr("1e-59"));
  EXPECT_LE(abs(k3.weights[2] - mpfr(5) / 18), mpfr("1e-59"));
}

// gauss_segment either returns a value whose actual error is within its estimate, or gives up
// (false) and leaves the segment to tanh-sinh: never a value outside its estimate. Analytic
// integrands are accepted within the asked tolerance; sqrt(u), with its branch point at the end,
// and 1/(u + 1e-4), with a pole a ten-thousandth of the width away, must not come back with an
// error estimate they do not meet. 30 digits; asked for 1e-26, and for 1e-10, where the accepted
// values' errors are far above rounding, so that an estimate that understates them shows.
TEST(CurvedQuadrature, GaussSegmentReturnsOnlyValuesWithinItsEstimate) {
  PrecisionScope scope(30);
  struct Case {
    const char* name;
    std::function<mpfr(const mpfr&)> f;
    mpfr exact;
    bool analytic;
  };
  const std::vector<Case> cases{
      {"exp(u)", [](const mpfr& u) { return mpfr(exp(u)); }, mpfr(exp(mpfr(1)) - 1), true},
      {"1/(1 + 100 u^2)", [](const mpfr& u) { return mpfr(1 / (1 + 100 * u * u)); }, mpfr(atan(mpfr(10)) / 10), true},
      {"u^7 (3 - 2u)", [](const mpfr& u) { return mpfr(pow(u, 7) * (3 - 2 * u)); }, mpfr(mpfr(3) / 8 - mpfr(2) / 9), true},
      {"sqrt(u)", [](const mpfr& u) { return mpfr(sqrt(u)); }, mpfr(mpfr(2) / 3), false},
      {"1/(u + 1e-4)", [](const mpfr& u) { return mpfr(1 / (u + mpfr("1e-4"))); }, mpfr(log(mpfr("1.0001") / mpfr("1e-4"))), false},
  };
  for (const mpfr& rel : {mpfr("1e-26"), mpfr("1e-10")}) {
    for (const auto& c : cases) {
      mpfr value, err, l1;
      const bool ok = detail::gauss_segment(c.f, rel, mpfr(0), value, err, l1);
      if (c.analytic) {
        EXPECT_TRUE(ok) << c.name;
      }
      if (!ok) continue;
      // solve_curved adds the rounding of the weighted sum, 4·eps·L1, to the estimate.
      const mpfr actual = abs(value - c.exact), rounding = 4 * std::numeric_limits<mpfr>::epsilon() * l1;
      EXPECT_LE(actual, err + rounding) << c.name << " at " << rel.str(3) << ": value " << value.str(30) << ", error estimate "
                                        << err.str(3);
      EXPECT_LE(err, rel * l1) << c.name;
      EXPECT_TRUE(l1 > 0) << c.name;
    }
  }
}

// The curved solver's own bound (the quadrature estimates plus the springs' rounding bounds at
// the evaluated nodes) against 40 digits at the type's own inputs; returns the bound, and its
// margin (actual error / bound) through `margin`.
template <class Real>
Real expect_bound_holds(const char* wave, const char* profile, const char* b, const char* g, double* margin = nullptr) {
  const Real beta = parse_real<Real>(b, "beta"), gamma = parse_real<Real>(g, "gamma");
  const auto r = curved<Real>(wave, profile, beta, gamma);
  PrecisionScope scope(40);
  const auto ref = curved<mpfr>(wave, profile, mpfr(beta), mpfr(gamma));
  const mpfr actual = abs((mpfr(r.mu) - ref.mu) / ref.mu);
  EXPECT_LE(actual, mpfr(r.relative_error)) << wave << " " << profile << " " << b << " " << g << " in "
                                            << std::numeric_limits<Real>::digits << " bits";
  if (margin && r.relative_error > 0) *margin = static_cast<double>(actual / mpfr(r.relative_error));
  return r.relative_error;
}

// In long double the guaranteed double path certifies curved values on that bound. Sine and
// triangle on the sphere, the cone and the wear flat, stick-slip with and without jumping at the
// centre.
TEST(CurvedPrecision, LongDoubleBoundHoldsAgainstFortyDigits) {
  for (const char* wave : {"sine", "triangle"})
    for (const char* profile : {"sphere", "cone", "wearflat:10"})
      for (const auto& [b, g] : std::vector<std::pair<const char*, const char*>>{{"1", "-0.3"}, {"2", "0.5"}, {"0.5", "1.5"}}) {
        const long double bound = expect_bound_holds<long double>(wave, profile, b, g);
        EXPECT_TRUE(bound < 1e-16L) << wave << " " << profile << " " << b << " " << g << ": " << static_cast<double>(bound);
      }
}

// The same at small β, in double and long double: small β puts breakpoints within a few
// millionths of the contact edge (tangency points of the trough), where a segment's neighbour
// hides from its Gauss rules unless the segment is graded towards it (curved.hpp, graded_pieces:
// ungraded, sine on power:3 at β = 0.01, γ = −0.3 erred by 1.04 times its bound in double), and
// the flat springs' rounding bounds are a large part of the curved bound (without them, 2 to 3
// times exceeded here).
//
// The margin is measured, not only that the bound holds: at its tightest on this grid the actual
// error is 0.375 of the bound in double (sine, wearflat:10, β = 0.01, γ = −0.9) and 0.179 in long
// double (measured at c443ac8 and again with issue 29's continuation, 2026-11-28; the 0.068 and
// 0.079 noted here on 2026-11-26 were no longer true at c443ac8), so a bound made 3 times smaller
// would fail here. What is checked is that it stays informative: at its tightest within a factor
// 100 of the error, else the ladder escalates for nothing.
TEST(CurvedPrecision, BoundsHoldAtSmallBetaInDoubleAndLongDouble) {
  double tightest_double = 0, tightest_long_double = 0;
  for (const char* wave : {"sine", "triangle", "sawtooth-left"})
    for (const char* profile : {"sphere", "cone", "power:3", "wearflat:10"})
      for (const char* b : {"0.01", "0.05"})
        for (const char* g : {"-0.9", "-0.3", "0.2", "4"}) {
          double m = 0;
          expect_bound_holds<double>(wave, profile, b, g, &m);
          tightest_double = std::max(tightest_double, m);
          m = 0;
          expect_bound_holds<long double>(wave, profile, b, g, &m);
          tightest_long_double = std::max(tightest_long_double, m);
        }
  std::printf("[ margin ] curved bound at small beta, largest actual error / bound: double %.3g, long double %.3g\n",
              tightest_double, tightest_long_double);
  EXPECT_GE(tightest_double, 0.01) << "the curved bound is over 100 times the error everywhere on the grid in double";
  EXPECT_GE(tightest_long_double, 0.01) << "the same in long double";
}

// The bound in double and long double on a random set, apart from the grids above (issue 29: the
// double row now continues each spring's stick ends from its neighbour's, EventPass): four waves,
// the sphere, the cone, power:1.5, a wear flat and a measured convex profile, β log-uniform on
// [0.01, 10], γ uniform on (−0.95, 3), against 40 digits. Each draw is printed on failure.
TEST(CurvedPrecision, BoundsHoldOnARandomSetInDoubleAndLongDouble) {
  std::mt19937 rng(2929);
  std::uniform_real_distribution<double> u(0, 1);
  std::string table = "0 0\n";
  double r = 0, f = 0, slope = 0;
  for (int j = 0; j < 8; ++j) {
    const double dr = 0.2 + 0.6 * u(rng);
    slope += 0.3 + u(rng);  // convex
    r += dr;
    f += slope * dr;
    table += detail::short_str(r) + " " + detail::short_str(f) + "\n";
  }
  ASSERT_GT(f, 4.5) << "the measured profile must hold the contact at gamma < 3";
  const std::string measured = "profile:" + write_profile("random_set.txt", table);
  const std::vector<std::string> waves{"sine", "triangle", "power:3", "sawtooth-right"};
  double tightest_double = 0, tightest_long_double = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const std::string wave = waves[trial % waves.size()];
    const std::string profiles[] = {"sphere", "cone", "power:1.5", "wearflat:" + detail::short_str(0.1 + 5 * u(rng)), measured};
    const std::string profile = profiles[(trial / waves.size() + trial) % 5];
    const std::string b = detail::short_str(std::pow(10.0, -2 + 3 * u(rng)));
    const std::string g = detail::short_str(-0.95 + 3.95 * u(rng));
    SCOPED_TRACE(wave + " on " + profile + ", beta " + b + ", gamma " + g);
    double m = 0;
    expect_bound_holds<double>(wave.c_str(), profile.c_str(), b.c_str(), g.c_str(), &m);
    tightest_double = std::max(tightest_double, m);
    m = 0;
    expect_bound_holds<long double>(wave.c_str(), profile.c_str(), b.c_str(), g.c_str(), &m);
    tightest_long_double = std::max(tightest_long_double, m);
  }
  std::printf("[ margin ] curved bound on the random set, largest actual error / bound: double %.3g, long double %.3g\n",
              tightest_double, tightest_long_double);
}

// The flat punch's retained_error and normal_error (the springs' rounding bounds the spring
// integral adds up) bound the actual errors of retained_area and normal_area in double, against
// 40-digit mpfr; area_error is the larger.
TEST(CurvedPrecision, SpringAreaErrorBoundsTheAreasInDouble) {
  for (const char* wave : {"sine", "triangle", "square", "power:3", "sawtooth-left"})
    for (const char* gamma : {"2", "0.5", "-0.3", "-0.99"})
      for (const char* beta : {"0.01", "1", "4"}) {
        const auto wd = make_waveform<double>(parse_wave(wave));
        const auto rd = solve(*wd, std::strtod(beta, nullptr), std::strtod(gamma, nullptr));
        PrecisionScope scope(40);
        const auto wm = make_waveform<mpfr>(parse_wave(wave));
        const auto rm = solve(*wm, mpfr(std::strtod(beta, nullptr)), mpfr(std::strtod(gamma, nullptr)));
        SCOPED_TRACE(std::string(wave) + " beta " + beta + " gamma " + gamma);
        EXPECT_LE(abs(mpfr(rd.retained_area) - rm.retained_area), mpfr(rd.retained_error));
        EXPECT_LE(abs(mpfr(rd.normal_area) - rm.normal_area), mpfr(rd.normal_error));
        EXPECT_EQ(rd.area_error, std::max(rd.retained_error, rd.normal_error));
        EXPECT_LE(rd.area_error, 1e-12);
      }
}

// The measured profile's MDR transform, g(x) = x ∫₀^x f'(r)/√(x² − r²) dr, against tanh-sinh of
// that integral per segment (r = x sin θ removes the endpoint singularity), random profiles.
TEST(MeasuredProfile, TransformAgreesWithQuadratureOfTheMdrIntegral) {
  PrecisionScope scope(30);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.05, 1);
  boost::math::quadrature::tanh_sinh<mpfr> q(20);
  for (int trial = 0; trial < 20; ++trial) {
    std::string text;
    mpfr r = 0, f = 0;
    std::vector<mpfr> rs{mpfr(0)}, fs{mpfr(0)};
    text += "0 0\n";
    mpfr slope = 0;
    for (int j = 0; j < 5; ++j) {
      const mpfr dr = mpfr(u(rng));
      r += dr;
      if (!(j == 0 && trial % 2)) slope += mpfr(u(rng));  // convex; odd trials start with a flat
      f += slope * dr;
      rs.push_back(r);
      fs.push_back(f);
      text += detail::short_str(r) + " " + detail::short_str(f) + "\n";
    }
    const auto path = write_profile("mdr_" + std::to_string(trial) + ".txt", text);
    const auto p = make_profile<mpfr>(parse_profile("profile:" + path));
    for (const double frac : {0.13, 0.5, 0.77, 1.0}) {
      const mpfr x = rs.back() * mpfr(frac);
      mpfr g = 0;
      for (std::size_t j = 0; j + 1 < rs.size() && rs[j] < x; ++j) {
        const mpfr m = (fs[j + 1] - fs[j]) / (rs[j + 1] - rs[j]);
        const mpfr hi = rs[j + 1] < x ? rs[j + 1] : x;
        // ∫ dr/√(x² − r²) by tanh-sinh (the closed form is what is under test); on the segment
        // that reaches r = x, r = x − v² removes the singularity: ∫ 2 dv/√(2x − v²).
        if (hi < x)
          g += m * q.integrate([&](const mpfr& rr) -> mpfr { return 1 / sqrt((x - rr) * (x + rr)); }, rs[j], hi, mpfr(1e-28));
        else
          g += m * q.integrate([&](const mpfr& v) -> mpfr { return 2 / sqrt(2 * x - v * v); }, mpfr(0), mpfr(sqrt(x - rs[j])),
                               mpfr(1e-28));
      }
      g *= x;
      EXPECT_LE(abs(p->sigma_at_x(x) - g), 1e-25 * (1 + g)) << text << " x = " << x;
      if (g > 0) {
        EXPECT_LE(abs(p->x_at_sigma(g) - x), 1e-25);
      }
    }
  }
}

// Profile::sigma_integral (closed forms per kind; physical's load at the deepest instant) against
// tanh-sinh quadrature of σ over [0, x], split at the flat's end and a measured profile's kinks
// (σ has square-root onsets there), at 30 digits; and in double and long double within a few
// eps (16, relative: a few roundings per term, every term positive) of the 30-digit closed form.
TEST(Profile, SigmaIntegralIsTheIntegralOfSigma) {
  PrecisionScope scope(30);
  boost::math::quadrature::tanh_sinh<mpfr> q(20);
  const auto path = write_profile("sigma_integral.txt", "0 0\n0.3 0\n0.7 0.1\n1.1 0.5\n2 2.3\n");
  for (const std::string& name : std::vector<std::string>{"sphere", "cone", "power:2.5", "power:7", "wearflat:0.3", "wearflat:7", "profile:" + path}) {
    const auto p = make_profile<mpfr>(parse_profile(name));
    const auto pd = make_profile<double>(parse_profile(name));
    const auto pl = make_profile<long double>(parse_profile(name));
    for (const char* level : {"0.05", "0.4", "1", "2.5"}) {
      if (!(M(level) < p->sigma_limit())) continue;
      const mpfr x = p->x_at_sigma(M(level));
      std::vector<mpfr> cuts{mpfr(0)};
      if (p->flat_length() > 0) cuts.push_back(p->flat_length());
      for (const mpfr& t : p->t_breaks())
        if (t > cuts.back() && t < x) cuts.push_back(t);  // a measured profile's t is x
      cuts.push_back(x);
      mpfr integral = 0;
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
        integral += q.integrate([&](const mpfr& t) -> mpfr { return p->sigma_at_x(t); }, cuts[k], cuts[k + 1], mpfr(1e-28));
      const mpfr closed = p->sigma_integral(x);
      EXPECT_LE(abs(closed - integral), 1e-25 * integral) << name << " sigma = " << level;
      const double xd = static_cast<double>(x);
      EXPECT_LE(abs(mpfr(pd->sigma_integral(xd)) - p->sigma_integral(mpfr(xd))), 16 * 2.2e-16 * integral) << name;
      const long double xl = static_cast<long double>(x);
      EXPECT_LE(abs(mpfr(pl->sigma_integral(xl)) - p->sigma_integral(mpfr(xl))), 16 * 1.1e-19 * integral) << name;
    }
  }
}

// A two-sample profile is a cone: μ̄ is scale-free, so it equals the cone's.
TEST(MeasuredProfile, TwoSampleProfileIsTheCone) {
  PrecisionScope scope(40);
  const auto path = write_profile("cone.txt", "# r f\n0 0\n2, 3\n");
  for (const char* gamma : {"2", "0.3", "-0.7"}) {
    const auto a = curved<mpfr>("sine", "profile:" + path, M("1.3"), M(gamma));
    const auto b = curved<mpfr>("sine", "cone", M("1.3"), M(gamma));
    EXPECT_LE(abs(a.mu - b.mu), 1e-36);
  }
  // Beyond the last sample the profile is not known: the contact must stay inside it.
  EXPECT_THROW(curved<mpfr>("sine", "profile:" + path, M("1"), M("20")), DomainError);
}

// The sphere sampled finely converges to the sphere, at second order in the spacing.
TEST(MeasuredProfile, SampledParaboloidConvergesToTheSphere) {
  PrecisionScope scope(30);
  const auto exact = curved<mpfr>("sine", "sphere", M("1"), M("0.4"));
  double prev = 0;
  for (int n : {10, 20, 40}) {
    std::string text;
    for (int j = 0; j <= n; ++j) {
      const mpfr r = mpfr(2) * j / n;  // g = x² needs f = r²/2 (κ₂ = 2): contact edge x = √1.4
      text += detail::short_str(r) + " " + detail::short_str(mpfr(r * r / 2)) + "\n";
    }
    const auto path = write_profile("para_" + std::to_string(n) + ".txt", text);
    const auto r = curved<mpfr>("sine", "profile:" + path, M("1"), M("0.4"));
    const double err = static_cast<double>(abs(r.mu - exact.mu));
    EXPECT_LT(err, 0.05 / (n * n)) << n;
    if (prev > 0) {
      EXPECT_GT(prev / err, 3.0) << "second order: halving the spacing divides the error by ~4";
    }
    prev = err;
  }
}

// A measured profile with kinks beyond its flat (slopes 0, 1, 2, 3: g has a square-root onset at
// r = 0.5, 1 and 1.5, each a breakpoint of the spring integral): 25 digits against 50, as for the
// closed-form profiles above, with contacts that reach past one, two and all three kinks.
TEST(MeasuredProfile, KinkedProfileAt25DigitsAgreesWith50) {
  const auto path = write_profile("kinked.txt", "0 0\n0.5 0\n1 0.5\n1.5 1.5\n3 6\n");
  for (const char* wave : {"sine", "square"})
    for (const char* gamma : {"0.3", "1.5", "4"}) {
      CurvedResult<mpfr> lo, hi;
      {
        PrecisionScope scope(25);
        lo = curved<mpfr>(wave, "profile:" + path, M("0.8"), M(gamma));
      }
      PrecisionScope scope(50);
      hi = curved<mpfr>(wave, "profile:" + path, M("0.8"), M(gamma));
      SCOPED_TRACE(std::string(wave) + " gamma " + gamma);
      const mpfr eps25 = pow(mpfr(10), -24);
      EXPECT_LE(abs(lo.mu - hi.mu), lo.relative_error * hi.mu);
      EXPECT_LE(lo.relative_error, 1e6 * eps25);  // the stall of the estimate measured above
      EXPECT_LE(abs(lo.friction_integral - hi.friction_integral), 1e4 * eps25 * hi.friction_integral);
      EXPECT_LE(abs(lo.normal_integral - hi.normal_integral), 1e4 * eps25 * hi.normal_integral);
      EXPECT_LE(abs(lo.contact_radius - hi.contact_radius), 10 * eps25 * hi.contact_radius);
    }
}

// The tool's layer: correctly rounded double through the precision ladder, against 40 digits.
// The correctly rounded double of a curved μ̄ from mpfr at 40 digits, or 80 or 160 where the
// decimal lies within one unit of its last digit of a midpoint of double (that interval holds the
// value: evaluate's digits are within half a unit, and half a unit more covers its error
// estimate). None deciding it is a failure, never a reference taken anyway.
std::optional<double> correctly_rounded_double(const WaveSpec& w, const Point& p, const BatchOptions& o) {
  for (const int digits : {40, 80, 160}) {
    const std::string text = evaluate(w, Quantity::mu, {p}, {NumberType::mpfr, digits}, o).front();
    PrecisionScope scope(static_cast<unsigned>(digits + 20));
    const mpfr v(text);
    const mpfr unit = v == 0 ? mpfr(0) : mpfr(pow(mpfr(10), floor(log10(abs(v))) - (digits - 1)));
    const double lo = mpfr_get_d(mpfr(v - unit).backend().data(), MPFR_RNDN);
    const double hi = mpfr_get_d(mpfr(v + unit).backend().data(), MPFR_RNDN);
    if (lo == hi) return lo;
  }
  ADD_FAILURE() << w.name << " " << o.profile.name << " beta " << p.beta << " gamma " << p.gamma
                << ": 160 digits do not decide the correctly rounded double";
  return std::nullopt;
}

TEST(CurvedEvaluate, GuaranteedDoubleIsCorrectlyRounded) {
  BatchOptions opt;
  opt.profile = parse_profile("sphere");
  const std::vector<Point> points{{"1", "0.5"}, {"0.05", "-0.9"}, {"3", "2"}, {"6", "-0.2"}};
  const auto d = evaluate(parse_wave("sine"), Quantity::mu, points, {NumberType::float64, 17}, opt);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (const auto ref = correctly_rounded_double(parse_wave("sine"), points[i], opt)) {
      EXPECT_EQ(std::strtod(d[i].c_str(), nullptr), *ref) << points[i].beta;
    }
  // Random points (fixed seed), every catalogue wave and profile kind: the double is the
  // correctly rounded value, decided at 40 digits or more.
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> ub(0.05, 8), ug(-0.95, 3);
  const char* waves[] = {"sine", "triangle", "square", "sawtooth-right", "sawtooth-left", "power:2.5"};
  const char* profiles[] = {"sphere", "cone", "power:1.7", "wearflat:0.5", "wearflat:40"};
  for (int trial = 0; trial < 30; ++trial) {
    BatchOptions o;
    o.profile = parse_profile(profiles[trial % 5]);
    const WaveSpec w = parse_wave(waves[(trial / 5) % 6]);
    char b[32], g[32];
    std::snprintf(b, sizeof b, "%.6g", ub(rng));
    std::snprintf(g, sizeof g, "%.6g", ug(rng));
    const auto dv = evaluate(w, Quantity::mu, {{b, g}}, {NumberType::float64, 17}, o).front();
    if (const auto ref = correctly_rounded_double(w, {b, g}, o)) {
      EXPECT_EQ(std::strtod(dv.c_str(), nullptr), *ref) << w.name << " " << o.profile.name << " beta " << b << " gamma " << g;
    }
  }
  // Ψ does not exist for a curved contact.
  EXPECT_THROW(evaluate(parse_wave("sine"), Quantity::psi, {{"1", ""}}, {NumberType::float64, 17}, opt), InputError);
}

// Bad profiles: one-line InputError naming the value, in every number type alike.
TEST(CurvedBadInput, ProfilesAndFilesAreRejected) {
  for (const char* text : {"power:0.5", "power:nan", "wearflat:0", "wearflat:-1", "wearflat:", "ball", "power:", "profile:"})
    EXPECT_THROW(parse_profile(text), InputError) << text;
  const std::pair<const char*, const char*> files[] = {
      {"nan.txt", "0 0\n1 nan\n"},           {"decreasing.txt", "0 0\n1 2\n2 1\n"}, {"f0.txt", "0 0.1\n1 2\n"},
      {"r0.txt", "0.5 0\n1 2\n"},           {"one.txt", "0 0\n"},                  {"repeat.txt", "0 0\n1 1\n1 2\n"},
      {"three.txt", "0 0 0\n1 1 1\n"},      {"flat.txt", "0 0\n1 0\n"},            {"empty.txt", "# nothing\n"},
      {"concave.txt", "0 0\n1 2\n2 3\n"}};
  for (const auto& [name, text] : files) {
    const auto path = write_profile(name, text);
    EXPECT_THROW(parse_profile("profile:" + path), InputError) << name;
  }
  EXPECT_THROW(parse_profile("profile:" + ::testing::TempDir()), InputError);
  EXPECT_THROW(parse_profile("profile:/nonexistent/file"), InputError);
  // Valid: comma, semicolon, tab separators, CRLF, comments.
  const auto ok = write_profile("ok.txt", "# r f\r\n0;0\r\n0.5,\t0.25\r\n1 1 # tip region\r\n");
  EXPECT_NO_THROW(parse_profile("profile:" + ok));
  // No contact, or β out of range: the flat punch's decisions, for every type.
  EXPECT_THROW(curved<double>("sine", "sphere", 1.0, -1.0), DomainError);
  EXPECT_THROW(curved<long double>("sine", "sphere", 1.0L, -1.0L), DomainError);
  EXPECT_THROW(curved<double>("sine", "sphere", 0.0, 0.5), InputError);
  EXPECT_THROW(curved<bin50>("sine", "sphere", bin50(-1), bin50(0.5)), InputError);
}

// A root-finder budget of 1 is an error with a message, never a value.
TEST(CurvedFailure, ExhaustedBudgetsAreErrors) {
  const auto w = make_waveform<double>(parse_wave("sine"));
  const auto p = make_profile<double>(parse_profile("sphere"));
  Options opt;
  opt.max_root_iterations = 1;
  EXPECT_THROW(solve_curved(*w, *p, 1.0, 0.5, opt), SolverError);
  Options levels;
  levels.max_quadrature_levels = 4;
  levels.quadrature_tolerance = 1e-300;
  EXPECT_THROW(solve_curved(*w, *p, 1.0, 0.5, levels), SolverError);
}

}  // namespace
