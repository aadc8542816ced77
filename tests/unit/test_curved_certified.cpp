// The curved enclosure (core/certified/curved_enclosure.hpp; model.md, "Curved contacts (MDR)"):
// every field against the curved solver (curved.hpp: flat-punch solves spring by spring, adaptive
// quadrature in x between its own breakpoints, a different algorithm) at 60 digits, with the
// widths the issue asks for; the exact values (μ̄ = μ0 where no spring sticks); the refusals; and
// the Taylor arithmetic (src/certified/taylor.hpp) against the functions it expands.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../../lib/core/src/certified/taylor.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/certified/curved_enclosure.hpp"
#include "vibrofric/core/curved/curved.hpp"

namespace {

using namespace vibrofric;
using certified::CurvedProfile;
using exact::Rational;

constexpr mpfr_prec_t kBits25 = 123;  // the Certifier's first bits at 25 digits (83 + 40)

// A decimal as typed ("-0.9") as the exact rational it denotes.
Rational R(const std::string& text) {
  const std::size_t dot = text.find('.');
  if (dot == std::string::npos) return Rational(text);
  const std::string digits = text.substr(0, dot) + text.substr(dot + 1);
  return Rational(digits + "/1" + std::string(text.size() - dot - 1, '0'));
}

CurvedProfile profile_of(const std::string& text) {
  const ProfileSpec s = parse_profile(text);
  CurvedProfile p;
  p.kind = s.kind == ProfileKind::wearflat ? CurvedProfile::Kind::wearflat : CurvedProfile::Kind::power;
  p.parameter = R(s.parameter.text());
  return p;
}

// the curved solver's value at 60 digits, its error far below the 1e-25 compared
CurvedResult<mpfr> reference(const std::string& profile, const char* beta, const char* gamma) {
  PrecisionScope scope(60);
  const auto w = make_waveform<mpfr>(parse_wave("sine"));
  const auto p = make_profile<mpfr>(parse_profile(profile));
  return solve_curved(*w, *p, mpfr(beta), mpfr(gamma));
}

// x within [lo − δ, hi + δ], δ = 1e-40 |x|: the reference's own error (60 digits, its estimate
// below 1e-50) with room; the enclosure itself is not widened.
void expect_holds(const Interval& e, const mpfr& x, const std::string& what) {
  PrecisionScope scope(60);
  const mpfr delta = abs(x) * mpfr("1e-40");
  EXPECT_LE(e.lower() - delta, x) << what << ": " << e.lower() << " > " << x;
  EXPECT_GE(e.upper() + delta, x) << what << ": " << e.upper() << " < " << x;
}

struct Case {
  const char* profile;
  const char* beta;
  const char* gamma;
};

// Every range of γ' (curved_enclosure.hpp): the row's top in slip, in a stick from touch-down,
// in a stick from n' = β, at γ = 1 and above; small and large β; each profile kind.
const std::vector<Case> kCases{
    {"sphere", "1", "0.5"},    {"sphere", "1", "1"},       {"sphere", "1", "2"},          {"sphere", "1", "-0.9"},
    {"sphere", "6", "0.5"},    {"sphere", "0.01", "3"},    {"cone", "1", "0.5"},          {"cone", "3", "1"},
    {"power:1.5", "2", "0.2"}, {"power:3", "0.5", "1.5"}, {"wearflat:0.5", "1", "0.5"}, {"wearflat:7", "2", "-0.5"},
};

TEST(CurvedEnclosure, HoldsTheCurvedSolversValuesAt25Digits) {
  for (const Case& c : kCases) {
    const std::string what = std::string(c.profile) + " beta " + c.beta + " gamma " + c.gamma;
    const certified::CurvedEnclosure e =
        certified::enclose_curved_sine(profile_of(c.profile), R(c.beta), R(c.gamma), kBits25);
    const CurvedResult<mpfr> r = reference(c.profile, c.beta, c.gamma);
    expect_holds(e.mu, r.mu, what + ": mu");
    expect_holds(e.retained_area, r.friction_integral, what + ": retained area");
    expect_holds(e.normal_area, r.normal_integral, what + ": normal area");
    EXPECT_TRUE(e.stick) << what;
    EXPECT_GT(e.pieces, 0u) << what;
    // the bar is 1e-20 relative; the bisection's target is 2^-(bits - 24) ≈ 6e-31
    PrecisionScope scope(30);
    EXPECT_LT(e.mu.width() / abs(e.mu.lower()), mpfr("1e-28")) << what << ": width " << e.mu.width();
  }
}

// No spring sticks: β ≥ 2π (every γ'), or γ < −g (every spring's γ' below −g): μ̄ = μ0 exactly.
TEST(CurvedEnclosure, ExactlyOneWhereNoSpringSticks) {
  for (const Case& c : std::vector<Case>{{"sphere", "6.3", "0.5"}, {"cone", "100", "3"}, {"sphere", "1", "-0.99"},
                                         {"wearflat:2", "6", "-0.3"}}) {
    const certified::CurvedEnclosure e =
        certified::enclose_curved_sine(profile_of(c.profile), R(c.beta), R(c.gamma), kBits25);
    EXPECT_FALSE(e.stick) << c.profile << " " << c.beta << " " << c.gamma;
    EXPECT_EQ(e.mu.lower(), 1);
    EXPECT_EQ(e.mu.upper(), 1);
    EXPECT_EQ(reference(c.profile, c.beta, c.gamma).mu, 1) << "the solver agrees";
  }
}

TEST(CurvedEnclosure, BadInputIsAnError) {
  EXPECT_THROW(certified::enclose_curved_sine(profile_of("sphere"), Rational(1), Rational(-1), kBits25), DomainError);
  EXPECT_THROW(certified::enclose_curved_sine(profile_of("sphere"), Rational(0), Rational(1), kBits25), InputError);
  CurvedProfile low{CurvedProfile::Kind::power, Rational(1, 2)};
  EXPECT_THROW(certified::enclose_curved_sine(low, Rational(1), Rational(1), kBits25), InputError);
  CurvedProfile flat{CurvedProfile::Kind::wearflat, Rational(0)};
  EXPECT_THROW(certified::enclose_curved_sine(flat, Rational(1), Rational(1), kBits25), InputError);
}

// At 64 bits, where the bisection stops at 2^-40 relative and the remainder terms carry the width:
// every case, and a wear flat of small λ (the weight's branch points λ/2 off the real axis, so the
// Taylor models near the row's centre converge slowly and the remainder bounds the error).
TEST(CurvedEnclosure, HoldsTheValuesAtFewBits) {
  std::vector<Case> cases = kCases;
  cases.push_back({"wearflat:0.05", "5.85", "0.2"});
  cases.push_back({"wearflat:0.05", "1.92", "0.02"});
  for (const Case& c : cases) {
    const std::string what = std::string(c.profile) + " beta " + c.beta + " gamma " + c.gamma;
    const certified::CurvedEnclosure e = certified::enclose_curved_sine(profile_of(c.profile), R(c.beta), R(c.gamma), 64);
    const CurvedResult<mpfr> r = reference(c.profile, c.beta, c.gamma);
    expect_holds(e.mu, r.mu, what + ": mu at 64 bits");
    expect_holds(e.retained_area, r.friction_integral, what + ": retained area at 64 bits");
    expect_holds(e.normal_area, r.normal_integral, what + ": normal area at 64 bits");
  }
}

// More bits, a narrower enclosure that still holds the value: the width follows the bits.
TEST(CurvedEnclosure, NarrowsWithTheBits) {
  const CurvedResult<mpfr> r = reference("sphere", "1", "0.5");
  mpfr previous = 1;
  for (const mpfr_prec_t bits : {64L, 123L, 180L}) {
    const certified::CurvedEnclosure e = certified::enclose_curved_sine(profile_of("sphere"), Rational(1), Rational(1, 2), bits);
    expect_holds(e.mu, r.mu, "bits " + std::to_string(bits));
    const mpfr w = e.mu.width();
    EXPECT_LT(w, previous * mpfr("1e-10")) << bits;
    previous = w;
  }
}

// A series' coefficients at x0 summed at x0 + h hold the function there (h = 1/16, 40 terms: the
// truncation is below 1e-45 for each function's radius of convergence here, at least 1/2).
TEST(TaylorSeries, CoefficientsSumToTheFunction) {
  const mpfr_prec_t bits = 200;
  PrecisionScope scope(70);
  const auto at = [&](const char* x) { return Interval::exact(mpfr(x), bits); };
  const Interval one = Interval::integer(1, bits);
  const std::size_t n = 40;
  const mpfr h("0.0625");
  const auto sum = [&](const certified::taylor::Series& s) {
    mpfr total = 0, power = 1;
    for (std::size_t k = 0; k < s.size(); ++k) {
      total += s[k].midpoint() * power;
      power *= h;
    }
    return total;
  };
  const mpfr tol("1e-45");
  for (const char* x0 : {"0", "0.3", "1.7", "-0.4"}) {
    const mpfr x = mpfr(x0), y = x + h;
    const certified::taylor::Series X = certified::taylor::Series::line(at(x0), one, n);
    EXPECT_LT(abs(sum(sin_cos(X).first) - sin(y)), tol) << x0;
    EXPECT_LT(abs(sum(sin_cos(X).second) - cos(y)), tol) << x0;
    EXPECT_LT(abs(sum(certified::taylor::sinc(at(x0), one, n)) - (y == 0 ? mpfr(1) : sin(y) / y)), tol) << x0;
    const certified::taylor::Series Xp = X + at("2");  // positive, for pow and sqrt
    EXPECT_LT(abs(sum(pow(Xp, at("-0.5"))) - pow(y + 2, mpfr("-0.5"))), tol) << x0;
    EXPECT_LT(abs(sum(sqrt(Xp)) - sqrt(y + 2)), tol) << x0;
    EXPECT_LT(abs(sum(certified::taylor::Series::constant(one, n) / Xp) - 1 / (y + 2)), tol) << x0;
    const certified::taylor::Series Xs = X * at("0.25");  // |x| < 1/2, for asin
    EXPECT_LT(abs(sum(asin(Xs)) - asin(y / 4)), tol) << x0;
  }
}

}  // namespace
