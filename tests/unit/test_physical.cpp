// Physical inputs to dimensionless groups (Eqs. 1, 5, 14), against the same formulas evaluated
// at 50 digits from the double inputs exactly (independent of the double arithmetic under test).
#include <gtest/gtest.h>

#include <limits>

#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/physical.hpp"

namespace {

using namespace vibrofric;

// Each group is at most 16 double operations from the inputs (Eq. 1: ν², 1 − ν², two quotients,
// a sum and a reciprocal per modulus; Eq. 5 four more), each rounded by at most half an ulp: a
// relative error of 16 half-ulps, bounded here by 8 eps.
constexpr double kRoundings = 8;

void expect_eps(double x, const mpfr& ref, const char* what) {
  PrecisionScope scope(50);
  EXPECT_LE(static_cast<double>(mpfr(abs(mpfr(x) - ref) / abs(ref))), kRoundings * std::numeric_limits<double>::epsilon())
      << what << ": " << x << " against " << ref.str(20);
}

// Eq. 1 and Eq. 5 at 50 digits from the inputs' exact double values.
struct Reference {
  mpfr E_star, G_star, k_z, k_x, beta, gamma;
};
Reference reference(const PhysicalInput<double>& in) {
  PrecisionScope scope(50);
  const mpfr E1(in.E1), E2(in.E2), nu1(in.nu1), nu2(in.nu2), a(in.radius);
  const mpfr G1 = in.G1 != 0 ? mpfr(in.G1) : mpfr(E1 / (2 * (1 + nu1)));
  const mpfr G2 = in.G2 != 0 ? mpfr(in.G2) : mpfr(E2 / (2 * (1 + nu2)));
  Reference r;
  r.E_star = 1 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
  r.G_star = 1 / ((2 - nu1) / (4 * G1) + (2 - nu2) / (4 * G2));
  r.k_z = 2 * r.E_star * a;
  r.k_x = 2 * r.G_star * a;
  r.beta = r.k_x * mpfr(in.v0) / (mpfr(in.mu0) * r.k_z * mpfr(in.A) * mpfr(in.f));
  r.gamma = mpfr(in.u_mean) / mpfr(in.A);
  return r;
}

void expect_groups(const PhysicalInput<double>& in) {
  const auto g = physical_groups(in);
  const Reference r = reference(in);
  expect_eps(g.E_star, r.E_star, "E*");
  expect_eps(g.G_star, r.G_star, "G*");
  expect_eps(g.k_z, r.k_z, "k_z");
  expect_eps(g.k_x, r.k_x, "k_x");
  expect_eps(g.beta, r.beta, "beta");
  expect_eps(g.gamma, r.gamma, "gamma");
}

TEST(Physical, SteelOnSteelFlatPunch) {
  // E = 210 GPa, ν = 0.3, G = E/2.6; a = 1 mm; v0 = 1 mm/s, f = 100 Hz, A = 1 µm, ū = 0.5 µm, μ0 = 0.5.
  PhysicalInput<double> in{210e9, 0.3, 210e9, 0.3, 0, 0, 1e-3, 1e-3, 100, 1e-6, 0.5e-6, 0.5};
  expect_groups(in);
  EXPECT_EQ(physical_groups(in).gamma, 0.5);  // 0.5e-6/1e-6 rounds to 0.5 exactly
}

TEST(Physical, ExplicitShearModuliAndBadInput) {
  PhysicalInput<double> in{100e9, 0.25, 200e9, 0.2, 30e9, 70e9, 2e-3, 0.01, 50, 2e-6, -1e-6, 0.3};
  expect_groups(in);
  EXPECT_EQ(physical_groups(in).gamma, -0.5);
  auto bad = in;
  bad.radius = -1;
  EXPECT_THROW(physical_groups(bad), InputError);
  bad = in;
  bad.nu1 = 0.5000001;
  EXPECT_THROW(physical_groups(bad), InputError);
  auto rubber = in;  // incompressible: nu = 1/2 is a material, E* = E/(1 - 1/4) for that body
  rubber.nu1 = 0.5;
  expect_groups(rubber);
  bad = in;
  bad.mu0 = 0;
  EXPECT_THROW(physical_groups(bad), InputError);
}

}  // namespace
