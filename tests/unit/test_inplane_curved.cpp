// In-plane oscillation of a curved contact (core/inplane/inplane_curved.hpp; model.md, "Curved
// contacts (MDR)" with "In-plane and combined oscillation"): the row integral and its search for
// structure changes against a closed form, the paper's model on a sphere and a cone (a_l = 0)
// against solve_curved (the flat solver's row with its own breakpoints: a second algorithm), and
// a transverse drive against an independent spring-row simulation.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/inplane/inplane_curved.hpp"

namespace vibrofric {
namespace {

// A made-up spring with one structure change at γ' = c: Φ = max(γ' − c, 0) (a kink there),
// Λ = γ'², N = γ' + 1. On σ = x² at γ = 0 with the sine (contact edge x = 1):
// ∫₀¹ Φ dx = (2/3)(−c)^{3/2}, ∫ Λ = 1/5, ∫ N = 2/3.
TEST(InPlaneCurved, RowIntegralFindsTheStructureChange) {
  PrecisionScope scope(30);
  const Sine<mpfr> w;
  const PowerProfile<mpfr> sphere(mpfr(2), "power:2");
  for (const char* c_text : {"-0.3", "-0.05", "-0.9"}) {
    const mpfr c(c_text);
    std::size_t calls = 0;
    const auto spring = [&](const mpfr& g) {
      ++calls;
      InPlaneSpring<mpfr> v;
      v.retained_area = g > c ? mpfr(g - c) : mpfr(0);
      v.lateral_area = g * g;
      v.normal_area = g + 1;
      v.structure = {g > c ? std::size_t(1) : std::size_t(0)};
      return v;
    };
    const mpfr tol("1e-27");
    const auto r = solve_inplane_curved<mpfr>(w, sphere, mpfr(0), spring, tol);
    const mpfr mu = pow(mpfr(-c), mpfr(1.5));  // (2/3)(−c)^{3/2} / (2/3)
    SCOPED_TRACE(c_text);
    EXPECT_LE(abs(mpfr(r.mu - mu)), 100 * tol) << r.mu << " against " << mu;
    EXPECT_LE(abs(mpfr(r.mean_lateral - mpfr(3) / 10)), 100 * tol) << r.mean_lateral;
    EXPECT_LE(abs(mpfr(r.normal_integral - mpfr(2) / 3)), 100 * tol);
    ASSERT_EQ(r.structure_breaks.size(), 1u);
    // Located to t within (tol)^(2/3) of the width: γ' = −x² within 2x of that.
    EXPECT_LE(abs(mpfr(r.structure_breaks[0] - c)), mpfr("1e-17")) << r.structure_breaks[0];
    EXPECT_EQ(r.springs, calls);
    EXPECT_EQ(r.contact_radius, 1);
  }
}

// No structure change: nothing found, and Λ's integral without one.
TEST(InPlaneCurved, SmoothRowHasNoBreaks) {
  const Sine<double> w;
  const PowerProfile<double> cone(1.0, "power:1");
  const auto spring = [](const double& g) {
    InPlaneSpring<double> v;
    v.retained_area = (g + 1) * (g + 1);
    v.normal_area = g + 1;
    v.structure = {7};
    return v;
  };
  // σ = x at γ = 0.5: x from 0 to 1.5, g = 0.5 − x; ∫(1.5 − x)² = 1.125, ∫(1.5 − x) = 1.125.
  const auto r = solve_inplane_curved<double>(w, cone, 0.5, spring, 1e-14);
  EXPECT_NEAR(r.mu, 1.0, 1e-13);
  EXPECT_EQ(r.mean_lateral, 0);
  EXPECT_TRUE(r.structure_breaks.empty());
  EXPECT_NEAR(r.contact_radius, 1.5, 1e-15);
}

std::unique_ptr<Waveform<mpfr>> wave_named(const std::string& name) {
  if (name == "sine") return std::make_unique<Sine<mpfr>>();
  if (name == "triangle") return make_triangle<mpfr>();
  return make_square<mpfr>();
}

// a_l = 0 is the paper's model spring by spring: the row of in-plane springs, whose kinks the
// structure search must find, equals solve_curved's row, whose breakpoints come from the flat
// solver's event structure (gamma_breakpoints). At 30 digits both integrate to ~1e-27. The wear
// flat adds the flat part's spring, its own term of every area (the lateral one 0 like the rest).
TEST(InPlaneCurved, ZeroAmplitudeIsThePapersCurvedModel) {
  PrecisionScope scope(30);
  struct Case {
    const char* wave;
    const char* profile;  // power:N or wearflat:λ
    const char *beta, *gamma;
  };
  for (const Case& c : {Case{"sine", "power:2", "0.5", "0.2"}, Case{"sine", "power:2", "0.3", "-0.3"},
                        Case{"sine", "power:1", "0.5", "0.2"}, Case{"triangle", "power:2", "0.4", "0"},
                        Case{"square", "power:2", "0.7", "-0.5"}, Case{"sine", "wearflat:0.5", "0.5", "0.2"},
                        Case{"triangle", "wearflat:2", "0.4", "-0.3"}}) {
    SCOPED_TRACE(std::string(c.wave) + " " + c.profile + " beta " + c.beta + " gamma " + c.gamma);
    const auto w = wave_named(c.wave);
    const auto p = wave_named("sine");
    const std::string name(c.profile);
    const mpfr parameter(name.substr(name.find(':') + 1));
    std::unique_ptr<Profile<mpfr>> profile;
    if (name.rfind("wearflat:", 0) == 0)
      profile = std::make_unique<WearFlatProfile<mpfr>>(parameter, name);
    else
      profile = std::make_unique<PowerProfile<mpfr>>(parameter, name);
    const mpfr beta(c.beta), gamma(c.gamma);
    const PlanarDrive<mpfr> drive{mpfr(0), mpfr(0), mpfr(0)};
    const auto row = solve_inplane_curved<mpfr>(
        *w, *profile, gamma, [&](const mpfr& g) { return inplane_spring<mpfr>(*w, g, *p, beta, drive); }, mpfr("1e-27"));
    const auto paper = solve_curved(*w, *profile, beta, gamma, Options{}, mpfr("1e-28"));
    EXPECT_LE(abs(mpfr(row.mu - paper.mu)), mpfr("1e-24")) << row.mu << " against " << paper.mu;
    EXPECT_LE(abs(mpfr(row.normal_integral - paper.normal_integral)), mpfr("1e-24"));
    EXPECT_EQ(row.mean_lateral, 0);
    EXPECT_LE(abs(mpfr(row.contact_radius - paper.contact_radius)), mpfr("1e-28"));
  }
}

// A drive whose springs change their event structure where an event crosses a segment's end (the
// triangle's kinks, the square in-plane wave's jumps at P = 0.3) without changing their sequence of
// modes: each such change a breakpoint of the row integral, found by the structure search from the
// spans' modes and segments. At 30 digits (1e-27) against the same row at 40 (1e-37); without
// those breakpoints the quadrature cannot converge over the kinks.
TEST(InPlaneCurved, EventsCrossingSegmentEndsAreBreakpoints) {
  const auto integrate = [](unsigned digits, const char* tol) {
    PrecisionScope scope(digits);
    const auto w = wave_named("triangle");
    const auto p = wave_named("square");
    const PowerProfile<mpfr> sphere{mpfr(2), "power:2"};
    const mpfr beta("0.4"), gamma("0.2");
    const PlanarDrive<mpfr> drive{mpfr("0.7"), mpfr(0), mpfr("0.3")};
    return solve_inplane_curved<mpfr>(
        *w, sphere, gamma, [&](const mpfr& g) { return inplane_spring<mpfr>(*w, g, *p, beta, drive); }, mpfr(tol));
  };
  const auto coarse = integrate(30, "1e-27");
  const auto fine = integrate(40, "1e-37");
  PrecisionScope scope(40);
  EXPECT_LE(abs(mpfr(coarse.mu - fine.mu)), mpfr("1e-25")) << coarse.mu << " against " << fine.mu;
  EXPECT_LE(abs(mpfr(coarse.normal_integral - fine.normal_integral)), mpfr("1e-25"));
}

// A transverse drive on the sphere against the row of catching-up springs (reference/row_catchup.py,
// written from model.md alone: 512 springs, Richardson in the phase step; mu 0.17947517378 and
// mean_lateral 0.96655729112, each within 6e-11). Double: the planar springs to ~1e-12, the row to 1e-10.
TEST(InPlaneCurved, TransverseRowAgainstTheSpringRowReference) {
  const Sine<double> w;
  const PowerProfile<double> sphere(2.0, "power:2");
  const PlanarDrive<double> drive{0.0, 1.0, 0.0};
  const auto row = solve_inplane_curved<double>(
      w, sphere, 0.2, [&](const double& g) { return inplane_spring<double>(w, g, w, 0.5, drive); }, 1e-10);
  EXPECT_NEAR(row.mu, 0.17947517378, 2e-10);
  EXPECT_NEAR(row.mean_lateral, 0.96655729112, 2e-10);
}

}  // namespace
}  // namespace vibrofric
