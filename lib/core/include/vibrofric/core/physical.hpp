// Physical inputs to the dimensionless groups: Eq. 1 (stiffness of a flat-ended cylinder),
// Eq. 5 (α, β), Eq. 14 (γ = 1/α), and for curved indenters the MDR scales of model.md ("Curved
// contacts"): each spring of the row has stiffnesses E* dx and G* dx, so β = G* v0/(μ0 E* A f) as
// for the punch, and ⟨F_N⟩ = 2 E* A L ∫N dx over the half-row in the profile's units, x = L·x'.
// SI units throughout.
#pragma once
#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <string>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/errors.hpp"

namespace vibrofric {

template <class Real>
struct PhysicalInput {
  Real E1, nu1, E2, nu2;  // Young's moduli [Pa] and Poisson ratios [1] of both bodies
  Real G1 = 0, G2 = 0;    // shear moduli [Pa]; 0 means E/(2(1 + ν)) (isotropic)
  Real radius;            // punch radius a [m]
  Real v0;                // sliding velocity [m/s]
  Real f;                 // oscillation frequency [Hz]
  Real A;                 // normal amplitude A_z [m]
  Real u_mean;            // mean indentation ū_z [m] (negative: mean position off the surface)
  Real mu0;               // intrinsic coefficient of friction [1]
};

template <class Real>
struct PhysicalGroups {
  Real E_star, G_star;  // effective moduli [Pa] (Eq. 1)
  Real k_z, k_x;        // contact stiffnesses [N/m] (Eq. 1)
  Real beta;            // k_x v0 / (μ0 k_z A f) (Eq. 5)
  Real gamma;           // ū_z / A (Eq. 14)
};

// Preconditions: moduli, radius, v0, f, A, μ0 > 0; −1 < ν ≤ 1/2 (1/2: incompressible, rubber).
// Throws InputError naming the offending quantity otherwise.
template <class Real>
PhysicalGroups<Real> physical_groups(const PhysicalInput<Real>& in) {
  auto positive = [](const Real& x, const char* what) {
    if (!(x > 0)) throw InputError(std::string(what) + " = " + detail::short_str(x) + ": expected a value > 0");
  };
  auto poisson = [](const Real& x, const char* what) {
    if (!(x > -1 && x <= Real(1) / 2))
      throw InputError(std::string(what) + " = " + detail::short_str(x) + ": expected -1 < nu <= 0.5");
  };
  positive(in.E1, "E1");
  positive(in.E2, "E2");
  poisson(in.nu1, "nu1");
  poisson(in.nu2, "nu2");
  if (in.G1 < 0) positive(in.G1, "G1");
  if (in.G2 < 0) positive(in.G2, "G2");
  if (in.radius != 0) positive(in.radius, "radius");  // 0: a curved indenter, no punch stiffness
  positive(in.v0, "v0");
  positive(in.f, "f");
  positive(in.A, "A");
  positive(in.mu0, "mu0");
  const Real G1 = in.G1 > 0 ? in.G1 : Real(in.E1 / (2 * (1 + in.nu1)));
  const Real G2 = in.G2 > 0 ? in.G2 : Real(in.E2 / (2 * (1 + in.nu2)));
  PhysicalGroups<Real> g;
  g.E_star = 1 / ((1 - in.nu1 * in.nu1) / in.E1 + (1 - in.nu2 * in.nu2) / in.E2);
  g.G_star = 1 / ((2 - in.nu1) / (4 * G1) + (2 - in.nu2) / (4 * G2));
  g.k_z = 2 * g.E_star * in.radius;
  g.k_x = 2 * g.G_star * in.radius;
  g.beta = g.G_star * in.v0 / (in.mu0 * g.E_star * in.A * in.f);  // = k_x v0/(μ0 k_z A f): the radius cancels
  g.gamma = in.u_mean / in.A;
  return g;
}

// The MDR length unit L of a curved indenter (x = L·x', x' the profile's coordinate of
// profile.hpp), for amplitude A: sphere of radius R (σ = x²/(R A), L = √(R A)); cone of half-angle
// θ between axis and flank (f = r cot θ, g = (π/2) cot θ |x|, L = 2 A tan θ/π); wear-flat sphere
// (x in units of the flat radius b: L = b, λ = b²/(R A)); measured profile in metres (L = 1).
template <class Real>
Real sphere_length(const Real& R, const Real& A) {
  using std::sqrt;
  return sqrt(R * A);
}
template <class Real>
Real cone_length(const Real& half_angle_degrees, const Real& A) {
  using std::tan;
  const Real pi = boost::math::constants::pi<Real>();
  return 2 * A * tan(half_angle_degrees * pi / 180) / pi;
}

}  // namespace vibrofric
