// Solver behaviour: errors that must not pass silently, stick-phase structure, wrap-around,
// several stick phases per period.
#include <gtest/gtest.h>

#include <fstream>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/verification/closed_forms.hpp"

namespace {

using namespace vibrofric;

std::unique_ptr<Waveform<double>> wave(const std::string& name) { return make_waveform<double>(parse_wave(name)); }

TEST(Solver, BadInputIsAnInputError) {
  const auto w = wave("sine");
  EXPECT_THROW(solve(*w, 0.0, 0.5), InputError);
  EXPECT_THROW(solve(*w, -1.0, 0.5), InputError);
  EXPECT_THROW(solve(*w, std::nan(""), 0.5), InputError);
  EXPECT_THROW(solve(*w, std::numeric_limits<double>::infinity(), 0.5), InputError);
  EXPECT_THROW(solve(*w, 1.0, std::nan("")), InputError);
  EXPECT_THROW(solve(*w, 1.0, -1.0), DomainError);
  EXPECT_THROW(solve(*w, 1.0, -2.0), DomainError);
  EXPECT_NO_THROW(solve(*w, 1.0, -0.999999));
}

TEST(Solver, RootFinderBudgetExhaustedIsAnErrorNamingTheCase) {
  Options o;
  o.max_root_iterations = 1;
  try {
    solve(*wave("sine"), 1.0, 0.5, o);
    FAIL() << "expected SolverError";
  } catch (const SolverError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("sine"), std::string::npos) << m;
    EXPECT_NE(m.find("beta = 1"), std::string::npos) << m;
    EXPECT_NE(m.find("gamma = 0.5"), std::string::npos) << m;
    EXPECT_NE(m.find("did not converge"), std::string::npos) << m;
  }
}

TEST(Solver, QuadratureThatCannotConvergeIsAnError) {
  // An impossible tolerance: the levels run out before two successive levels agree that well.
  Options o;
  o.area = AreaMethod::quadrature;
  o.max_quadrature_levels = 4;
  o.quadrature_tolerance = 1e-300;
  EXPECT_THROW(solve(*wave("sine"), 1.0, 0.5, o), SolverError);
}

TEST(Solver, SquareWaveStickPhase) {
  // Stick from first contact (φ = 0) until the ramp reaches γ + 1 or contact is lost at 1/2.
  const auto r1 = solve(*wave("sqr"), 10.0, 0.0);
  ASSERT_EQ(r1.stick_phases.size(), 1u);
  EXPECT_DOUBLE_EQ(r1.stick_phases[0].begin, 0.0);
  EXPECT_DOUBLE_EQ(r1.stick_phases[0].end, 0.1);
  EXPECT_DOUBLE_EQ(r1.stick_phases[0].level, 0.0);
  const auto r2 = solve(*wave("sqr"), 1.0, 0.0);
  ASSERT_EQ(r2.stick_phases.size(), 1u);
  EXPECT_DOUBLE_EQ(r2.stick_phases[0].end, 0.5);
  EXPECT_TRUE(r2.jumping);
}

TEST(Solver, SawtoothRightSticksAllPeriodWhenSlow) {
  const auto r = solve(*wave("str"), 1.0, 2.0);
  ASSERT_EQ(r.stick_phases.size(), 1u);
  EXPECT_DOUBLE_EQ(r.stick_phases[0].begin, 0.0);
  EXPECT_DOUBLE_EQ(r.stick_phases[0].end, 1.0);
  EXPECT_FALSE(r.jumping);
}

TEST(Solver, StickPhaseWrapsThePeriodBoundary) {
  // Sine without jumping: stick from acos(β/2π)/2π before φ = 1 to beyond it.
  const double beta = 1.0;
  const auto r = solve(*wave("sine"), beta, 1.5);
  ASSERT_EQ(r.stick_phases.size(), 1u);
  EXPECT_NEAR(r.stick_phases[0].begin, 1 - std::acos(beta / (2 * M_PI)) / (2 * M_PI), 1e-15);
  EXPECT_GT(r.stick_phases[0].end, 1.0);
  // Eq. 8 at the end: β(φ2 − φ1) = w(φ2) − w(φ1).
  const double p1 = r.stick_phases[0].begin, p2 = r.stick_phases[0].end;
  EXPECT_NEAR(beta * (p2 - p1), std::sin(2 * M_PI * p2) - std::sin(2 * M_PI * p1), 1e-14);
}

TEST(Solver, SeveralStickPhasesPerPeriod) {
  // sin 2πφ + 0.5 sin 6πφ rises steeply twice per period: two stick phases at small β.
  const std::string path = ::testing::TempDir() + "two_peaks.txt";
  std::ofstream(path) << "1 0 1\n3 0 0.5\n";
  const auto w = make_waveform<double>(parse_wave("fourier:" + path));
  const auto e = solve(*w, 0.5, 2.0);
  EXPECT_EQ(e.stick_phases.size(), 2u);
  Options q;
  q.area = AreaMethod::quadrature;
  const auto r = solve(*w, 0.5, 2.0, q);
  EXPECT_NEAR(r.mu, e.mu, 64 * 2.2e-16);
  // The retained area equals the envelope integrated by quadrature, phase by phase.
  double sum = 0;
  const int n = 20000;
  for (int j = 0; j < n; ++j) sum += tangential_force(*w, e, 0.5, 2.0, (j + 0.5) / n) / n;
  EXPECT_NEAR(sum, e.retained_area, 1e-8);  // midpoint rule on a function with kinks: O(n^-2)
}

TEST(Solver, MuIsExactlyOneWithoutStick) {
  const auto r = solve(*wave("tri"), 4.0, -0.3);
  EXPECT_TRUE(r.stick_phases.empty());
  EXPECT_EQ(r.mu, 1.0);
  EXPECT_EQ(r.relative_error, 0.0);
}

// μ̄, ∫s, ∫n and ∫(n − s) of a double solve against independent values, each within the solver's
// own bound (relative_error, retained_error, normal_error, lost_relative_error: multiples of double's eps) plus
// 8 eps for the last rounding, as properties.hpp's expect_within_bound.
void expect_values_within_bounds(const Result<double>& r, const mpfr& mu, const mpfr& retained, const mpfr& normal,
                                 const mpfr& lost, const std::string& where) {
  const mpfr eps(std::numeric_limits<double>::epsilon());
  auto in_eps = [&](const mpfr& err, const mpfr& scale) { return static_cast<double>(err / (eps * scale)); };
  const mpfr e_mu = abs(mpfr(r.mu) - mu), e_ret = abs(mpfr(r.retained_area) - retained),
             e_nor = abs(mpfr(r.normal_area) - normal), e_lost = abs(mpfr(r.lost_area) - lost);
  EXPECT_LE(e_mu, (mpfr(r.relative_error) + 8 * eps) * mu)
      << where << ": mu " << in_eps(e_mu, mu) << " eps off, bound " << r.relative_error / eps.convert_to<double>() << " eps";
  EXPECT_LE(e_ret, mpfr(r.retained_error) + 8 * eps * retained)
      << where << ": retained_area " << in_eps(e_ret, retained) << " eps off, retained_error " << r.retained_error;
  EXPECT_LE(e_nor, mpfr(r.normal_error) + 8 * eps * normal)
      << where << ": normal_area " << in_eps(e_nor, normal) << " eps off, normal_error " << r.normal_error;
  EXPECT_LE(e_lost, (mpfr(r.lost_relative_error) + 8 * eps) * lost)
      << where << ": lost_area " << in_eps(e_lost, lost) << " eps off, bound " << r.lost_relative_error;
}

TEST(Solver, DiagnosticsAreReported) {
  const auto r = solve(*wave("sine"), 1.0, 0.5);
  EXPECT_GT(r.events, 0u);
  EXPECT_GT(r.root_solves, 0u);
  EXPECT_GT(r.evaluations, 0u);
  EXPECT_EQ(r.area, AreaMethod::exact);
  EXPECT_LT(r.relative_error, 1e-13);
  // No closed form for the sine: the same solver at 40 digits, the same (exact) inputs.
  PrecisionScope scope(40);
  const auto m = solve(*make_waveform<mpfr>(parse_wave("sine")), mpfr(1), mpfr("0.5"));
  ASSERT_LT(m.relative_error, mpfr("1e-30"));
  ASSERT_LT(m.area_error, mpfr("1e-30"));
  ASSERT_LT(m.lost_relative_error, mpfr("1e-30"));
  expect_values_within_bounds(r, m.mu, m.retained_area, m.normal_area, m.lost_area, "sine, beta = 1, gamma = 0.5");
}

// Without jumping (γ ≥ 1) the triangle's areas are closed: ∫n = γ (w has mean 0), ∫(n − s) = Ψ
// (Eqs. 12, 17), ∫s = γ − Ψ, μ̄ = 1 − Ψ/γ (Eq. 13).
TEST(Solver, AreasOfTheTriangleAgainstTheClosedForms) {
  const auto r = solve(*wave("tri"), 1.0, 2.0);
  PrecisionScope scope(40);
  const mpfr beta(1), gamma(2), psi = closed_form::psi_triangle(beta);
  expect_values_within_bounds(r, closed_form::mu_from_psi(psi, gamma), gamma - psi, gamma, psi,
                              "triangle, beta = 1, gamma = 2");
}

TEST(Solver, PsiDoesNotDependOnGamma) {
  const auto w = wave("sine");
  const double p = psi(*w, 2.0).lost_area;
  // At γ the lost area is ∫n − ∫ramp with n ~ γ: its rounding is ~γ·eps, not eps.
  for (double g : {1.0, 1.5, 4.0, 100.0}) EXPECT_NEAR(solve(*w, 2.0, g).lost_area, p, 16 * g * 2.2e-16) << g;
}

}  // namespace
