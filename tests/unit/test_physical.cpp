// Physical inputs to dimensionless groups (Eqs. 1, 5, 14), against hand-evaluated numbers.
#include <gtest/gtest.h>

#include "vibrofric/core/physical.hpp"

namespace {

using namespace vibrofric;

TEST(Physical, SteelOnSteelFlatPunch) {
  // E = 210 GPa, ν = 0.3, G = E/2.6; a = 1 mm; v0 = 1 mm/s, f = 100 Hz, A = 1 µm, ū = 0.5 µm, μ0 = 0.5.
  PhysicalInput<double> in{210e9, 0.3, 210e9, 0.3, 0, 0, 1e-3, 1e-3, 100, 1e-6, 0.5e-6, 0.5};
  const auto g = physical_groups(in);
  const double E_star = 210e9 / (2 * (1 - 0.09));      // 1/E* = 2(1 − ν²)/E
  const double G = 210e9 / 2.6, G_star = 4 * G / (2 * 1.7);  // 1/G* = 2(2 − ν)/(4G)
  EXPECT_NEAR(g.E_star / E_star, 1, 1e-15);
  EXPECT_NEAR(g.G_star / G_star, 1, 1e-15);
  EXPECT_NEAR(g.k_z / (2 * E_star * 1e-3), 1, 1e-15);
  EXPECT_NEAR(g.k_x / (2 * G_star * 1e-3), 1, 1e-15);
  const double beta = (2 * G_star * 1e-3) * 1e-3 / (0.5 * (2 * E_star * 1e-3) * 1e-6 * 100);
  EXPECT_NEAR(g.beta / beta, 1, 1e-14);
  EXPECT_DOUBLE_EQ(g.gamma, 0.5);
}

TEST(Physical, ExplicitShearModuliAndBadInput) {
  PhysicalInput<double> in{100e9, 0.25, 200e9, 0.2, 30e9, 70e9, 2e-3, 0.01, 50, 2e-6, -1e-6, 0.3};
  const auto g = physical_groups(in);
  EXPECT_NEAR(g.G_star, 1 / (1.75 / 120e9 + 1.8 / 280e9), 1e-3);
  EXPECT_DOUBLE_EQ(g.gamma, -0.5);
  auto bad = in;
  bad.radius = -1;
  EXPECT_THROW(physical_groups(bad), InputError);
  bad = in;
  bad.nu1 = 0.5000001;
  EXPECT_THROW(physical_groups(bad), InputError);
  auto rubber = in;  // incompressible: nu = 1/2 is a material, E* = E/(1 - 1/4) for that body
  rubber.nu1 = 0.5;
  EXPECT_NO_THROW(physical_groups(rubber));
  bad = in;
  bad.mu0 = 0;
  EXPECT_THROW(physical_groups(bad), InputError);
}

}  // namespace
