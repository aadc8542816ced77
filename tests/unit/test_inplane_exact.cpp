// The exact longitudinal drive (core/inplane/inplane_exact.hpp): two periodic states worked out by
// hand from model.md's rules, a zero amplitude against the paper's exact solver (a running
// minimum, exact.hpp: another algorithm), and every field against the floating-point engine
// (inplane.hpp) at 60 digits on random rational inputs, including the decisions it refuses.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "vibrofric/core/exact.hpp"
#include "vibrofric/core/inplane/inplane.hpp"
#include "vibrofric/core/inplane/inplane_exact.hpp"

namespace vibrofric {
namespace {

using exact::Rational;

Rational q(long a, long b = 1) { return Rational(a, b); }

// n ≡ 1, the triangle p (slope ±4) at a_l = 1/2, β = 1. Over the half period where D' = β − 4a = −1
// s sticks from 1 down by δ = (4a − β)/2 = 1/2; where D' = β + 4a = 3 it sticks back up for
// τ = δ/3 = 1/6, then slips at s = 1. ∫s = (1/2)(1 − δ/2) + τ(1 − δ/2) + (1/2 − τ) = 5/6.
TEST(InPlaneExact, ConstantForceByHand) {
  const auto r = exact::solve_inplane(nullptr, 0, exact::triangle(), q(1), q(1, 2), q(3, 10));
  EXPECT_EQ(r.mu, q(5, 6));
  EXPECT_EQ(r.normal_area, 1);
  EXPECT_EQ(r.stick_fraction, q(2, 3));
  EXPECT_EQ(r.slip_fraction, q(1, 3));
  EXPECT_EQ(r.backward_fraction, 0);
  EXPECT_EQ(r.flight_fraction, 0);
  // a_l = 2: D' = −7 carries s from 1 to −1 in 2/7, then it slips backward for 3/14; D' = 9 carries
  // it back in 2/9, then it slips forward for 5/18. ∫s = 5/18 − 3/14 = 4/63.
  const auto b = exact::solve_inplane(nullptr, 0, exact::triangle(), q(1), q(2), q(0));
  EXPECT_EQ(b.mu, q(4, 63));
  EXPECT_EQ(b.stick_fraction, q(32, 63));
  EXPECT_EQ(b.slip_fraction, q(31, 63));
  EXPECT_EQ(b.backward_fraction, q(3, 14));
}

// The ratchet on triangles: n = max(1/2 + w, 0) (contact on [1/8, 7/8], peak 3/2 at 1/2), D = p(φ + 1/4),
// β = 0. Slip at λ_f = 0 on [1/8, 1/4]; stick with s + n = 1 on [1/4, 1/2]; stick until s = −n at
// 5/8; backward slip to 7/8 (λ_b = −8, then 0). ∫s = 1/32 − 3/32 − 1/8 = −3/16, ∫n = 9/16.
TEST(InPlaneExact, RatchetByHand) {
  const exact::Wave w = exact::triangle();
  const auto r = exact::solve_inplane(&w, q(1, 2), exact::triangle(), q(0), q(1), q(1, 4));
  EXPECT_EQ(r.mu, q(-1, 3));
  EXPECT_EQ(r.retained_area, q(-3, 16));
  EXPECT_EQ(r.normal_area, q(9, 16));
  EXPECT_EQ(r.stick_fraction, q(3, 8));
  EXPECT_EQ(r.slip_fraction, q(3, 8));
  EXPECT_EQ(r.backward_fraction, q(1, 4));
  EXPECT_EQ(r.flight_fraction, q(1, 4));
  EXPECT_EQ(r.state_s, 0);
  ASSERT_EQ(r.spans.size(), 7u);  // flight, slip, stick (two segments), slip (two segments), flight
  EXPECT_EQ(r.spans[3].end, q(5, 8));
  EXPECT_EQ(r.spans[3].mode, InPlaneMode::stick);
}

std::vector<exact::Wave> waves() {
  return {exact::triangle(), exact::square(), exact::sawtooth_right(), exact::sawtooth_left(), exact::power_one()};
}

// a_l = 0 is the paper's model: the running minimum of exact.hpp gives the same rationals.
TEST(InPlaneExact, ZeroAmplitudeIsThePapersExactValue) {
  for (const exact::Wave& w : waves())
    for (const Rational& gamma : {q(-3, 5), q(0), q(3, 10), q(1), q(5, 2)})
      for (const Rational& beta : {q(1, 5), q(1), q(3), q(15, 2)}) {
        const auto r = exact::solve_inplane(&w, gamma, exact::triangle(), beta, 0, q(3, 10));
        const auto flat = exact::solve(w, beta, gamma);
        EXPECT_EQ(r.mu, flat.mu) << w.name << " " << gamma << " " << beta;
        EXPECT_EQ(r.retained_area, flat.retained_area);
        EXPECT_EQ(r.normal_area, flat.normal_area);
        EXPECT_EQ(r.backward_fraction, 0);
      }
}

template <class Real>
std::unique_ptr<Waveform<Real>> engine_wave(const std::string& name) {
  if (name == "triangle") return make_triangle<Real>();
  if (name == "square") return make_square<Real>();
  if (name == "sawtooth-right") return make_sawtooth_right<Real>();
  if (name == "sawtooth-left") return make_sawtooth_left<Real>();
  return nullptr;
}

mpfr real(const Rational& x) {
  return mpfr(mpfr(numerator(x).str().c_str()) / mpfr(denominator(x).str().c_str()));
}

// Every field of the engine in mpfr at 60 digits against the exact walk, on rationals with small
// denominators (so that slip rates of exactly zero and events at vertices occur), or both refuse.
TEST(InPlaneExact, EngineAgreesOnEveryField) {
  PrecisionScope scope(60);
  const mpfr tol("1e-50");
  const char* const names[] = {"triangle", "square", "sawtooth-right", "sawtooth-left"};
  std::mt19937_64 rng(20261207);
  int refused = 0, compared = 0;
  for (int i = 0; i < 300; ++i) {
    const std::string wn = i % 5 == 4 ? "" : names[rng() % 4];
    const std::string pn = names[rng() % 4];
    const Rational gamma = q(static_cast<long>(rng() % 33) - 8, 8);   // −1 … 3
    const Rational beta = i % 4 == 0 ? q(0) : q(static_cast<long>(rng() % 40), 8);
    const Rational a = q(static_cast<long>(rng() % 25), 8);
    const Rational phase = q(static_cast<long>(rng() % 49) - 16, 16);
    const std::unique_ptr<Waveform<mpfr>> w = wn.empty() ? nullptr : engine_wave<mpfr>(wn);
    const auto p = engine_wave<mpfr>(pn);
    const std::optional<exact::Wave> ew = wn.empty() ? std::nullopt : std::optional<exact::Wave>(
        wn == "triangle" ? exact::triangle() : wn == "square" ? exact::square()
        : wn == "sawtooth-right" ? exact::sawtooth_right() : exact::sawtooth_left());
    const exact::Wave ep = pn == "triangle" ? exact::triangle() : pn == "square" ? exact::square()
                           : pn == "sawtooth-right" ? exact::sawtooth_right() : exact::sawtooth_left();
    const std::string at = (wn.empty() ? std::string("constant") : wn) + " gamma " + gamma.str() + ", p " + pn +
                           ", beta " + beta.str() + ", a " + a.str() + ", P " + phase.str();
    if (w && !(gamma + 1 > 0)) continue;  // no contact: both refuse it before solving
    InPlaneDrive<mpfr> d;
    d.longitudinal = real(a);
    d.phase = real(phase);
    std::optional<InPlaneResult<mpfr>> e;
    std::optional<exact::InPlaneResult> x;
    try {
      e = solve_inplane<mpfr>(w.get(), real(gamma), *p, real(beta), d);
    } catch (const SolverError&) {
    }
    try {
      x = exact::solve_inplane(ew ? &*ew : nullptr, gamma, ep, beta, a, phase);
    } catch (const SolverError&) {
    }
    ASSERT_EQ(e.has_value(), x.has_value()) << at << ": one of them finds no unique state";
    if (!x) {
      ++refused;
      continue;
    }
    ++compared;
    const auto near = [&](const mpfr& v, const Rational& r, const char* field) {
      EXPECT_LE(mpfr(abs(mpfr(v - real(r)))), tol) << at << ": " << field << " " << v << " against " << r;
    };
    near(e->mu, x->mu, "mu");
    near(e->retained_area, x->retained_area, "retained_area");
    near(e->normal_area, x->normal_area, "normal_area");
    near(e->stick_fraction, x->stick_fraction, "stick_fraction");
    near(e->slip_fraction, x->slip_fraction, "slip_fraction");
    near(e->backward_fraction, x->backward_fraction, "backward_fraction");
    near(e->flight_fraction, x->flight_fraction, "flight_fraction");
    near(e->state_s, x->state_s, "state_s");
    EXPECT_EQ(x->stick_fraction + x->slip_fraction + x->flight_fraction, 1) << at;
  }
  std::printf("compared %d, refused %d\n", compared, refused);
  EXPECT_GE(compared, 150);
  EXPECT_GE(refused, 5) << "beta = 0 with a closed contact must include states that are not unique";
}

TEST(InPlaneExact, BadInputIsRefused) {
  const exact::Wave w = exact::triangle();
  EXPECT_THROW(exact::solve_inplane(&w, 0, w, q(-1), 1, 0), InputError);
  EXPECT_THROW(exact::solve_inplane(&w, 0, w, 1, q(-1, 2), 0), InputError);
  EXPECT_THROW(exact::solve_inplane(&w, q(-1), w, 1, 1, 0), DomainError);
  // β = 0, a small drive on a closed contact: every s in a band is periodic.
  EXPECT_THROW(exact::solve_inplane(&w, q(2), w, 0, q(1, 10), 0), SolverError);
}

}  // namespace
}  // namespace vibrofric
