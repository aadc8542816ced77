// The root finders every event goes through (core/detail/roots.hpp), on their own, in every
// number type: a root to within the stated ulps of a closed form evaluated at 100 digits, and an
// unbracketed root or an exhausted budget as a SolverError, never a number. Header-only (no
// library linked): it is also the mutation smoke run's program (tests/mutation/run.py).
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "vibrofric/core/detail/roots.hpp"

namespace {

namespace bmp = boost::multiprecision;
using Ref = bmp::number<bmp::mpfr_float_backend<100>>;
using vibrofric::SolverError;
using vibrofric::detail::bracketed_root;
using vibrofric::detail::polished_root;
using vibrofric::detail::RootStats;

// The real root of x³ − x − 1 (the plastic number) by Cardano's formula, at 100 digits.
Ref plastic() {
  const Ref s = sqrt(Ref(69));
  return cbrt((9 + s) / 18) + cbrt((9 - s) / 18);
}

template <class Real>
Real ulp_distance(const Real& x, const Ref& reference) {
  // In units of eps·2^⌊log2 |reference|⌋, the spacing of the type at the reference.
  int e = 0;
  frexp(reference, &e);
  const Ref spacing = ldexp(Ref(std::numeric_limits<Real>::epsilon()), e - 1);
  return static_cast<Real>(abs(Ref(x) - reference) / spacing);
}

template <class Real>
class Roots : public ::testing::Test {};
using Types = ::testing::Types<double, long double, bmp::cpp_bin_float_50, bmp::number<bmp::mpfr_float_backend<50>>>;
TYPED_TEST_SUITE(Roots, Types);

TYPED_TEST(Roots, BracketedRootIsWithinFourUlpOfTheClosedForm) {
  using Real = TypeParam;
  RootStats stats;
  auto square = [](const Real& x) { return Real(x * x - 2); };
  const Real r2 = bracketed_root<Real>(square, Real(1), Real(2), Real(-1), Real(2), "sqrt2", stats);
  EXPECT_LE(ulp_distance(r2, sqrt(Ref(2))), 4) << r2;
  auto cubic = [](const Real& x) { return Real(x * x * x - x - 1); };
  const Real rp = bracketed_root<Real>(cubic, Real(1), Real(2), Real(-1), Real(5), "plastic", stats);
  EXPECT_LE(ulp_distance(rp, plastic()), 4) << rp;
  EXPECT_EQ(stats.solves, 2u);
  EXPECT_GT(stats.iterations, 2u);
}

TYPED_TEST(Roots, PolishedRootIsWithinFourUlpOfTheClosedForm) {
  using Real = TypeParam;
  RootStats stats;
  auto cubic = [](const Real& x) { return Real(x * x * x - x - 1); };
  auto slope = [](const Real& x) { return Real(3 * x * x - 1); };
  // From a guess good to two digits, as from a lower type, and from none (the midpoint).
  for (const Real& guess : {Real(33) / 25, Real(0)}) {
    const Real x = polished_root<Real>(cubic, slope, Real(1), Real(2), Real(-1), Real(5), guess, Real(0), "plastic",
                                       stats);
    EXPECT_LE(ulp_distance(x, plastic()), 4) << "guess " << guess << ": " << x;
  }
  EXPECT_EQ(stats.solves, 2u);
}

TYPED_TEST(Roots, ARootAtABracketEndIsThatEndExactly) {
  using Real = TypeParam;
  RootStats stats;
  auto line = [](const Real& x) { return Real(x - 1); };
  EXPECT_EQ(bracketed_root<Real>(line, Real(1), Real(2), Real(0), Real(1), "end", stats), Real(1));
  EXPECT_EQ(bracketed_root<Real>(line, Real(0), Real(1), Real(-1), Real(0), "end", stats), Real(1));
  auto one = [](const Real&) { return Real(1); };
  // polished_root takes an end whose |f| is within the evaluation noise as the root.
  EXPECT_EQ(polished_root<Real>(line, one, Real(0), Real(1.25), Real(-1), Real(0.25), Real(0.5), Real(0.5),
                                "end", stats),
            Real(1.25));
}

template <class Call>
std::string solver_error_of(Call call) {
  try {
    call();
  } catch (const SolverError& e) {
    return e.what();
  }
  return "no SolverError";
}

TYPED_TEST(Roots, NoSignChangeIsAnErrorNamingTheEvent) {
  using Real = TypeParam;
  RootStats stats;
  auto square = [](const Real& x) { return Real(x * x - 2); };
  auto slope = [](const Real& x) { return Real(2 * x); };
  const std::string b = solver_error_of(
      [&] { bracketed_root<Real>(square, Real(2), Real(3), Real(2), Real(7), "stick end", stats); });
  EXPECT_NE(b.find("stick end: no sign change on [2, 3]"), std::string::npos) << b;
  const std::string p = solver_error_of([&] {
    polished_root<Real>(square, slope, Real(2), Real(3), Real(2), Real(7), Real(2.5), Real(0), "onset", stats);
  });
  EXPECT_NE(p.find("onset: no sign change on [2, 3]"), std::string::npos) << p;
}

TYPED_TEST(Roots, AnExhaustedBudgetIsAnError) {
  using Real = TypeParam;
  RootStats stats;
  stats.max_iterations = 2;
  auto cubic = [](const Real& x) { return Real(x * x * x - x - 1); };
  auto slope = [](const Real& x) { return Real(3 * x * x - 1); };
  const std::string b =
      solver_error_of([&] { bracketed_root<Real>(cubic, Real(1), Real(2), Real(-1), Real(5), "contact", stats); });
  EXPECT_NE(b.find("contact: root finder did not converge in 2 iterations"), std::string::npos) << b;
  const std::string p = solver_error_of([&] {
    polished_root<Real>(cubic, slope, Real(1), Real(2), Real(-1), Real(5), Real(0), Real(0), "stick end", stats);
  });
  EXPECT_NE(p.find("stick end: Newton iteration did not converge in 2 iterations"), std::string::npos) << p;
}

// The in-place arithmetic of the hot paths (core/numbers.hpp) against the expressions it replaces,
// bit for bit: value, sign of zero, NaN and, for mpfr, the precision the expression's result has.
template <class Real>
bool same(const Real& x, const Real& y) {
  using std::isnan;
  using std::signbit;
  if (isnan(x) || isnan(y)) return isnan(x) && isnan(y);
  if constexpr (vibrofric::is_runtime_precision_v<Real>)
    if (mpfr_get_prec(x.backend().data()) != mpfr_get_prec(y.backend().data())) return false;
  return x == y && signbit(x) == signbit(y);
}

// Signs, zeros, exact and inexact values, tiny and huge ones; for mpfr also one operand 30 digits
// wider and one 10 digits narrower than the working precision.
template <class Real>
std::vector<Real> operands() {
  std::vector<Real> v;
  for (const char* s : {"0", "-0", "1", "-1", "0.1", "-2.5", "3", "1e-30", "-7e20", "0.75"}) {
    if constexpr (std::is_same_v<Real, double>)
      v.push_back(std::strtod(s, nullptr));
    else if constexpr (std::is_same_v<Real, long double>)
      v.push_back(std::strtold(s, nullptr));
    else
      v.emplace_back(s);
  }
  v.push_back(Real(1) / 3);
  v.push_back(Real(-2) / 7);
  v.push_back(std::numeric_limits<Real>::quiet_NaN());
  if constexpr (vibrofric::is_runtime_precision_v<Real>) {
    Real wide, narrow;
    wide.precision(Real::thread_default_precision() + 30);
    narrow.precision(Real::thread_default_precision() - 10);
    mpfr_ui_div(wide.backend().data(), 2, Real(3).backend().data(), MPFR_RNDN);
    mpfr_ui_div(narrow.backend().data(), 5, Real(7).backend().data(), MPFR_RNDN);
    v.push_back(std::move(wide));
    v.push_back(std::move(narrow));
  }
  return v;
}

template <class Real>
void check_in_place() {
  using std::abs;
  using std::floor;
  using std::signbit;
  using namespace vibrofric::detail;
  const std::vector<Real> v = operands<Real>();
  for (const Real& a : v) {
    Real n = a;
    negate(n);  // exact: the value and the sign (the precision is n's)
    EXPECT_TRUE((a != a && n != n) || (n == -a && signbit(n) != signbit(a))) << a;
    if (!(a != a) && abs(a) < 1e15) {
      EXPECT_EQ(floor_to_long(a), static_cast<long>(floor(a))) << a;
    } else if constexpr (vibrofric::is_runtime_precision_v<Real>) {
      if (a != a) {
        EXPECT_THROW(floor_to_long(a), std::runtime_error);  // as Boost's conversion
      }
    }
    for (const Real& b : v) {
      EXPECT_EQ(abs_le(a, b), abs(a) <= b) << a << " " << b;
      Real d;
      difference(d, a, b);
      EXPECT_TRUE(same(d, Real(a - b))) << a << " - " << b;
      Real alias = b;
      difference(alias, a, alias);
      EXPECT_TRUE(same(alias, Real(a - b))) << a << " - " << b << " into b";
      Real m;
      midpoint(m, a, b);
      EXPECT_TRUE(same(m, Real((a + b) / 2))) << a << " " << b;
      if (!signbit(a) || a != 0) {  // add_abs: x not −0
        Real x = a;
        add_abs(x, b);
        const Real magnitude = abs(b);  // an lvalue: a + |b| then has the larger precision
        EXPECT_TRUE(same(x, Real(a + magnitude))) << a << " + |" << b << "|";
      }
    }
  }
}

TYPED_TEST(Roots, InPlaceArithmeticIsTheExpressionBitForBit) { check_in_place<TypeParam>(); }

TEST(RootsMpfr, InPlaceArithmeticIsTheExpressionBitForBitAtAnyPrecision) {
  for (unsigned digits : {30u, 300u}) {
    vibrofric::PrecisionScope scope(digits);
    check_in_place<vibrofric::mpfr>();
  }
}

}  // namespace
