// The paper's closed forms and the solver's cross-checks, as one property suite instantiated per
// number type (properties_<type>.cpp): Eqs. 6, 13, 17, 18, 19, 21, 22, the harmonic wave against
// its quadrature path and against the lower envelope, and the rounding bound behind escalation.
//
// Tolerances are in eps of the type under test (numeric_limits<Real>::epsilon(), the thread's
// precision for mpfr). Expected values come from closed forms, or from an independent algorithm.
#pragma once
#include <gtest/gtest.h>

#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "correct_rounding.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/verification/closed_forms.hpp"

namespace vt {

using namespace vibrofric;

template <class T>
struct Fixed {
  using Real = T;
  static constexpr unsigned digits = 0;
};
template <unsigned D>
struct Mpfr {
  using Real = mpfr;
  static constexpr unsigned digits = D;
};

template <class Tag>
class Properties : public ::testing::Test {
 protected:
  using Real = typename Tag::Real;
  void SetUp() override {
    if constexpr (is_runtime_precision_v<Real>) scope_.emplace(Tag::digits);
  }
  static Real eps() { return std::numeric_limits<Real>::epsilon(); }
  static Real num(const std::string& s) { return parse_real<Real>(s, "test value"); }
  static std::unique_ptr<Waveform<Real>> wave(const std::string& name) { return make_waveform<Real>(parse_wave(name)); }
  static bool high() { return std::numeric_limits<Real>::digits10 > 40 || (is_runtime_precision_v<Real> && Tag::digits > 40); }

  // |got − want| ≤ k·eps·|want| (absolute when want = 0).
  static void expect_close(const Real& got, const Real& want, int k, const std::string& where) {
    using std::abs;
    const Real err = abs(got - want);
    const Real scale = want == 0 ? Real(1) : Real(abs(want));
    EXPECT_LE(err, k * eps() * scale) << where << ": got " << format_significant(got, 25) << ", want "
                                      << format_significant(want, 25) << ", error "
                                      << format_significant(Real(err / (eps() * scale)), 4) << " eps (limit " << k << ")";
  }
  // In the corners the error may exceed a few eps; the solver's own rounding bound must cover
  // it (escalation relies on this), up to a few eps of unaccounted last-step rounding.
  static void expect_within_bound(const Result<Real>& r, const Real& want, const std::string& where) {
    using std::abs;
    const Real rel = abs(r.mu - want) / abs(want);
    EXPECT_LE(rel, r.relative_error + 8 * eps())
        << where << ": relative error " << format_significant(rel, 4) << " exceeds the bound "
        << format_significant(r.relative_error, 4);
  }
  static std::string at(const char* w, const Real& b, const Real& g) {
    return std::string(w) + " beta=" + format_significant(b, 10) + " gamma=" + format_significant(g, 10);
  }

  // Benign grid: no small areas, tolerance 16 eps. Corners: β → 0, γ → −1, β → β_c.
  std::vector<std::string> betas_benign() const { return {"0.5", "1", "1.5", "1.9"}; }
  std::vector<std::string> gammas_jump_benign() const { return {"-0.5", "-0.25", "0", "0.5", "0.75", "1"}; }
  std::vector<std::string> betas_corner() const { return {"1e-6", "0.001", "0.1", "1.999999", "3.999999"}; }
  std::vector<std::string> gammas_corner() const { return {"-0.999999", "-0.999", "-0.9"}; }

  std::optional<PrecisionScope> scope_;
};

TYPED_TEST_SUITE_P(Properties);

// Eq. 17: Ψ of str, stl, tri against the closed forms.
TYPED_TEST_P(Properties, Eq17PsiTriangularWaves) {
  using Real = typename TestFixture::Real;
  const auto str = this->wave("str"), stl = this->wave("stl"), tri = this->wave("tri");
  for (const auto& b : {"0.001", "0.1", "0.5", "1", "1.5", "1.9", "1.999999", "2", "3", "3.999999", "4", "10"}) {
    const Real beta = this->num(b);
    this->expect_close(psi(*str, beta).lost_area, closed_form::psi_sawtooth_right(beta), 16, std::string("str ") + b);
    this->expect_close(psi(*stl, beta).lost_area, closed_form::psi_sawtooth_left(beta), 16, std::string("stl ") + b);
    this->expect_close(psi(*tri, beta).lost_area, closed_form::psi_triangle(beta), 16, std::string("tri ") + b);
  }
}

// Eq. 19 in the benign part of the jumping range, and the rounding bound in its corners.
TYPED_TEST_P(Properties, Eq19JumpingTriangularWaves) {
  using Real = typename TestFixture::Real;
  const auto str = this->wave("str"), stl = this->wave("stl"), tri = this->wave("tri");
  for (const auto& g : this->gammas_jump_benign())
    for (const auto& b : this->betas_benign()) {
      const Real beta = this->num(b), gamma = this->num(g);
      this->expect_close(solve(*str, beta, gamma).mu, closed_form::mu_sawtooth_right_jumping(beta), 16, this->at("str", beta, gamma));
      this->expect_close(solve(*stl, beta, gamma).mu, closed_form::mu_sawtooth_left_jumping(beta), 16, this->at("stl", beta, gamma));
      this->expect_close(solve(*tri, beta, gamma).mu, closed_form::mu_triangle_jumping(beta), 16, this->at("tri", beta, gamma));
    }
  for (const auto& g : this->gammas_corner())
    for (const auto& b : this->betas_corner()) {
      const Real beta = this->num(b), gamma = this->num(g);
      this->expect_within_bound(solve(*str, beta, gamma), closed_form::mu_sawtooth_right_jumping(beta), this->at("str", beta, gamma));
      this->expect_within_bound(solve(*stl, beta, gamma), closed_form::mu_sawtooth_left_jumping(beta), this->at("stl", beta, gamma));
      this->expect_within_bound(solve(*tri, beta, gamma), closed_form::mu_triangle_jumping(beta), this->at("tri", beta, gamma));
    }
}

// Eq. 18: clipping does not change μ̄ of a triangular wave. The reference is the unclipped wave's
// μ̄ at γ = 1 from the closed forms (Eqs. 13 and 17), not the solver there: a solver that ignored γ
// would agree with itself.
TYPED_TEST_P(Properties, Eq18ClippingInvariance) {
  using Real = typename TestFixture::Real;
  for (const char* name : {"tri", "str", "stl"}) {
    const auto w = this->wave(name);
    for (const auto& b : this->betas_benign()) {
      const Real beta = this->num(b);
      const Real psi = name[0] == 't'   ? closed_form::psi_triangle(beta)
                       : name[2] == 'r' ? closed_form::psi_sawtooth_right(beta)
                                        : closed_form::psi_sawtooth_left(beta);
      const Real ref = closed_form::mu_from_psi(psi, Real(1));
      this->expect_close(solve(*w, beta, Real(1)).mu, ref, 16, this->at(name, beta, Real(1)));
      for (const auto& g : this->gammas_jump_benign()) {
        const Real gamma = this->num(g);
        this->expect_close(solve(*w, beta, gamma).mu, ref, 16, this->at(name, beta, gamma));
      }
    }
  }
}

// Eq. 22: the square wave in both regimes and at the threshold β = 2(1 + γ).
TYPED_TEST_P(Properties, Eq22SquareWave) {
  using Real = typename TestFixture::Real;
  const auto sqr = this->wave("square");
  for (const auto& g : {"-0.9", "-0.5", "0", "0.5", "1"}) {
    const Real gamma = this->num(g);
    const Real th = 2 * (1 + gamma);
    std::vector<Real> betas{this->num("0.5"), this->num("1"), this->num("3"), this->num("10"), th, Real(th / 2), Real(th * 2)};
    betas.push_back(th * (1 - 64 * this->eps()));
    betas.push_back(th * (1 + 64 * this->eps()));
    for (const Real& beta : betas)
      this->expect_close(solve(*sqr, beta, gamma).mu, closed_form::mu_square_jumping(beta, gamma), 16, this->at("sqr", beta, gamma));
  }
  for (const auto& g : this->gammas_corner())
    for (const auto& b : this->betas_corner()) {
      const Real beta = this->num(b), gamma = this->num(g);
      this->expect_within_bound(solve(*sqr, beta, gamma), closed_form::mu_square_jumping(beta, gamma), this->at("sqr", beta, gamma));
    }
}

// Eq. 21: μ̄(β, γ) = μ̄(ξ_sqr, 1), with Ψ_sqr(ξ) closed (Eq. 20).
TYPED_TEST_P(Properties, Eq21SquareRemapping) {
  using Real = typename TestFixture::Real;
  const auto sqr = this->wave("square");
  for (const auto& g : {"-0.5", "0", "0.5", "0.9"})
    for (const auto& b : {"0.5", "1", "1.5", "2", "3", "5"}) {
      const Real beta = this->num(b), gamma = this->num(g);
      const Real xi = closed_form::xi_square(beta, gamma);
      const Real at_gamma = solve(*sqr, beta, gamma).mu;
      this->expect_close(at_gamma, solve(*sqr, xi, Real(1)).mu, 16, this->at("sqr", beta, gamma));
      this->expect_close(at_gamma, Real(1 - closed_form::psi_square(xi)), 16, this->at("sqr Eq. 20", beta, gamma));
    }
}

// Eq. 13: without jumping (γ ≥ 1), μ̄/μ0 = 1 − Ψ(β)/γ with Ψ from Eq. 17 and Ψ_sqr.
TYPED_TEST_P(Properties, Eq13NonJumping) {
  using Real = typename TestFixture::Real;
  const auto str = this->wave("str"), stl = this->wave("stl"), tri = this->wave("tri"), sqr = this->wave("sqr");
  for (const auto& g : {"1", "1.5", "3", "10", "1000"})
    for (const auto& b : {"0.5", "1", "1.9", "3", "5"}) {
      const Real beta = this->num(b), gamma = this->num(g);
      this->expect_close(solve(*str, beta, gamma).mu, closed_form::mu_from_psi(closed_form::psi_sawtooth_right(beta), gamma), 16, this->at("str", beta, gamma));
      this->expect_close(solve(*stl, beta, gamma).mu, closed_form::mu_from_psi(closed_form::psi_sawtooth_left(beta), gamma), 16, this->at("stl", beta, gamma));
      this->expect_close(solve(*tri, beta, gamma).mu, closed_form::mu_from_psi(closed_form::psi_triangle(beta), gamma), 16, this->at("tri", beta, gamma));
      this->expect_close(solve(*sqr, beta, gamma).mu, closed_form::mu_from_psi(closed_form::psi_square(beta), gamma), 16, this->at("sqr", beta, gamma));
    }
  // Small β at γ = 1 (n touches zero, μ̄ → 0): within the solver's rounding bound.
  for (const auto& b : {"1e-6", "0.001", "0.01"}) {
    const Real beta = this->num(b), gamma = Real(1);
    this->expect_within_bound(solve(*str, beta, gamma), closed_form::mu_from_psi(closed_form::psi_sawtooth_right(beta), gamma), this->at("str", beta, gamma));
    this->expect_within_bound(solve(*stl, beta, gamma), closed_form::mu_from_psi(closed_form::psi_sawtooth_left(beta), gamma), this->at("stl", beta, gamma));
    this->expect_within_bound(solve(*tri, beta, gamma), closed_form::mu_from_psi(closed_form::psi_triangle(beta), gamma), this->at("tri", beta, gamma));
    this->expect_within_bound(solve(*sqr, beta, gamma), closed_form::mu_from_psi(closed_form::psi_square(beta), gamma), this->at("sqr", beta, gamma));
  }
}

// Eq. 6: at and above β_c(γ) there is no stick and μ̄ = μ0 exactly; just below, there is stick.
// β_c(γ) in closed form: sine 2π (γ ≥ 0) or 2π√(1 − γ²); power:p 4p or 4p(1 + γ)^((p−1)/p).
TYPED_TEST_P(Properties, Eq6NoStickAboveBetaC) {
  using Real = typename TestFixture::Real;
  using std::pow;
  using std::sqrt;
  const Real two_pi = boost::math::constants::two_pi<Real>();
  struct Case {
    std::string wave;
    std::function<Real(const Real&)> beta_c;
  };
  const std::vector<Case> cases{
      {"sine", [&](const Real& g) { return g >= 0 ? two_pi : Real(two_pi * sqrt(1 - g * g)); }},
      {"tri", [](const Real&) { return Real(4); }},
      {"str", [](const Real&) { return Real(2); }},
      {"power:2", [](const Real& g) { return g >= 0 ? Real(8) : Real(8 * sqrt(1 + g)); }},
      {"power:3", [](const Real& g) { return g >= 0 ? Real(12) : Real(12 * pow(1 + g, Real(2) / 3)); }},
  };
  for (const auto& c : cases) {
    const auto w = this->wave(c.wave);
    for (const auto& g : {"-0.9", "-0.5", "0", "0.5", "1", "3"}) {
      const Real gamma = this->num(g);
      const Real bc = c.beta_c(gamma);
      this->expect_close(make_contact(*w, gamma).beta_c(), bc, 16, c.wave + " beta_c at gamma " + g);
      for (const Real& f : {Real(1 + 64 * this->eps()), Real(3) / 2, Real(10)})
        EXPECT_EQ(solve(*w, Real(bc * f), gamma).mu, Real(1)) << c.wave << " gamma " << g << " beta = beta_c * " << format_significant(f, 20);
      EXPECT_LT(solve(*w, Real(bc * 999 / 1000), gamma).mu, Real(1)) << c.wave << " gamma " << g << " just below beta_c";
    }
  }
  // A jump makes β_c infinite: stick at any β.
  for (const char* name : {"square", "stl"})
    EXPECT_LT(solve(*this->wave(name), this->num("1e6"), this->num("0.5")).mu, Real(1)) << name;
}

// The harmonic wave has no closed form: its exact-area path against its tanh-sinh path, and a
// Fourier series equal to sin 2πφ (generic root finding, found pieces) against the catalogue sine.
TYPED_TEST_P(Properties, HarmonicExactVsQuadrature) {
  using Real = typename TestFixture::Real;
  const auto sine = this->wave("sine");
  const auto pw = this->wave("power:2.5");
  Options quad;
  quad.area = AreaMethod::quadrature;
  const bool slow = is_runtime_precision_v<Real> && TypeParam::digits > 200;
  std::vector<std::pair<const char*, const char*>> pts{{"1", "0.5"}, {"0.3", "-0.5"}, {"3", "1.5"}, {"5", "-0.2"}, {"0.2", "1"}};
  if (slow) pts.resize(2);  // tanh-sinh at 300 digits costs ~30 ms per segment
  for (const auto& [b, g] : pts) {
    const Real beta = this->num(b), gamma = this->num(g);
    for (const auto* w : {sine.get(), pw.get()}) {
      const auto e = solve(*w, beta, gamma);
      const auto q = solve(*w, beta, gamma, quad);
      EXPECT_EQ(q.area, AreaMethod::quadrature);
      // Quadrature stops at sqrt(eps) between levels; its error is then ~eps (doubly exponential).
      this->expect_close(q.mu, e.mu, 64, this->at(w->name().c_str(), beta, gamma));
    }
  }
  if (slow) return;
  std::vector<unsigned> k{1};
  std::vector<Real> a{Real(0)}, bcoef{Real(1)};
  const FourierSeries<Real> fourier("fourier:sin", k, a, bcoef);
  for (const auto& [b, g] : pts) {
    const Real beta = this->num(b), gamma = this->num(g);
    this->expect_close(solve(fourier, beta, gamma).mu, solve(*sine, beta, gamma).mu, 64, this->at("fourier sin", beta, gamma));
  }
}

// The lower envelope of model.md, s(φ) = min_τ n(φ − τ) + βτ, minimised directly (grid, then
// Brent on each local minimum) at sample phases, against the solver's s(φ).
TYPED_TEST_P(Properties, HarmonicAgainstLowerEnvelope) {
  using Real = typename TestFixture::Real;
  if (is_runtime_precision_v<Real> && TypeParam::digits > 100) GTEST_SKIP() << "Brent at 300 digits is slow; covered at 30 and 100";
  const auto sine = this->wave("sine");
  for (const auto& [b, g] : std::vector<std::pair<const char*, const char*>>{{"1", "1"}, {"3", "2"}, {"0.5", "1.2"}, {"2", "-0.3"}, {"1", "0.5"}}) {
    const Real beta = this->num(b), gamma = this->num(g);
    const auto r = solve(*sine, beta, gamma);
    auto n = [&](const Real& x) -> Real { const Real v = gamma + (*sine)(x); return v > 0 ? v : Real(0); };
    for (int j = 0; j < 16; ++j) {
      const Real phi = Real(j) / 16 + Real(1) / 37;
      auto f = [&](const Real& tau) -> Real { return n(phi - tau) + beta * tau; };
      Real best = f(Real(0));
      constexpr int grid = 400;
      for (int i = 1; i < grid; ++i) {
        const Real t0 = Real(i - 1) / grid, t1 = Real(i) / grid, t2 = Real(i + 1) / grid;
        if (f(t1) <= f(t0) && f(t1) <= f(t2)) {
          const int bits = std::numeric_limits<Real>::digits / 2;
          const auto m = boost::math::tools::brent_find_minima(f, t0, t2, bits);
          if (m.second < best) best = m.second;
        }
      }
      const Real s = tangential_force(*sine, r, beta, gamma, phi);
      // Brent places a smooth minimum to sqrt(eps), so its value to ~eps; where the minimum is
      // at the kink of n (first contact, γ < 1) it is only sqrt(eps)-accurate in value.
      using std::sqrt;
      const Real tol = gamma >= 1 ? Real(64 * this->eps()) : Real(64 * sqrt(this->eps()));
      using std::abs;
      EXPECT_LE(abs(s - best), tol) << this->at("sine", beta, gamma) << " phi " << format_significant(phi, 10);
    }
  }
}

// The tool's path for this type: corners included, correctly rounded (escalation) in double and
// long double, within one unit of the last printed digit otherwise, against the closed forms.
TYPED_TEST_P(Properties, EvaluatedValuesCorrectInCorners) {
  using Real = typename TestFixture::Real;
  Precision prec;
  int digits;
  if constexpr (is_runtime_precision_v<Real>) {
    prec = {NumberType::mpfr, static_cast<int>(TypeParam::digits)};
    digits = static_cast<int>(TypeParam::digits);
  } else if constexpr (std::is_same_v<Real, double>) {
    prec = {NumberType::float64, 0};
    digits = 17;
  } else if constexpr (std::is_same_v<Real, long double>) {
    prec = {NumberType::float80, 0};
    digits = 21;
  } else if constexpr (std::is_same_v<Real, bin50>) {
    prec = {NumberType::bin50, 0};
    digits = 50;
  } else {
    prec = {NumberType::bin100, 0};
    digits = 100;
  }
  std::vector<Point> pts;
  for (const auto& g : this->gammas_corner())
    for (const auto& b : this->betas_corner()) pts.push_back({b, g});
  const auto got = evaluate(parse_wave("tri"), Quantity::mu, pts, prec);
  const auto got_sqr = evaluate(parse_wave("square"), Quantity::mu, pts, prec);
  if constexpr (std::is_floating_point_v<Real>) {
    // Hardware types promise the correctly rounded value (README, "Precision"; 0 ulp, as the Python
    // tests demand): the printed round-trip digits read back as the exact closed form (rational, at
    // the decimal inputs) rounded once to the type.
    using vibrofric::testing::decimal_rational;
    using vibrofric::testing::nearest;
    const auto read = [](const std::string& text) -> Real {
      if constexpr (std::is_same_v<Real, double>)
        return std::strtod(text.c_str(), nullptr);
      else
        return std::strtold(text.c_str(), nullptr);
    };
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const auto beta = decimal_rational(pts[i].beta.text()), gamma = decimal_rational(pts[i].gamma.text());
      EXPECT_EQ(read(got[i]), nearest<Real>(closed_form::mu_triangle_jumping(beta)))
          << "triangle beta " << pts[i].beta << " gamma " << pts[i].gamma << ": " << got[i];
      EXPECT_EQ(read(got_sqr[i]), nearest<Real>(closed_form::mu_square_jumping(beta, gamma)))
          << "square beta " << pts[i].beta << " gamma " << pts[i].gamma << ": " << got_sqr[i];
    }
    return;
  }
  PrecisionScope ref(static_cast<unsigned>(2 * digits + 20));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const mpfr beta(pts[i].beta.text()), gamma(pts[i].gamma.text());
    for (const auto& [text, want] : {std::pair{got[i], closed_form::mu_triangle_jumping(beta)},
                                     std::pair{got_sqr[i], closed_form::mu_square_jumping(beta, gamma)}}) {
      using std::abs;
      const mpfr rel = abs(mpfr(text) - want) / want;
      // `digits` decimal digits, whose resolution (one unit in the last digit) is coarser than
      // cpp_bin_float's eps: within that unit.
      EXPECT_LE(rel, mpfr(pow(mpfr(10), 1 - digits))) << "beta " << pts[i].beta << " gamma " << pts[i].gamma << ": " << text;
    }
  }
}

REGISTER_TYPED_TEST_SUITE_P(Properties, Eq17PsiTriangularWaves, Eq19JumpingTriangularWaves, Eq18ClippingInvariance,
                            Eq22SquareWave, Eq21SquareRemapping, Eq13NonJumping, Eq6NoStickAboveBetaC,
                            HarmonicExactVsQuadrature, HarmonicAgainstLowerEnvelope, EvaluatedValuesCorrectInCorners);

}  // namespace vt

#define VIBROFRIC_PROPERTIES(Label, ...) INSTANTIATE_TYPED_TEST_SUITE_P(Label, Properties, ::testing::Types<__VA_ARGS__>)
