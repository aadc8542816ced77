// Interval (interval.hpp): every result encloses the exact one, checked against independent
// values — exact rationals (GMP) for decimals and the four operations, MPFR's directed roundings
// at four times the bits for the transcendental functions — and is tight (a point's enclosure is
// at most two units of the last place wide). Signs and comparisons decide only when certain.
#include <gmp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "vibrofric/core/certified/interval.hpp"

namespace {

using vibrofric::Interval;
using vibrofric::Sign;
using vibrofric::mpfr;

constexpr mpfr_prec_t kBits = 64;

// The exact rational value of a decimal "±d[.d][e±k]", built from its digits (not by MPFI or MPFR).
class Rational {
 public:
  explicit Rational(const std::string& text) {
    mpq_init(q_);
    std::string digits;
    long fraction_digits = 0;
    bool point = false;
    std::size_t i = 0;
    bool negative = false;
    if (text[i] == '-' || text[i] == '+') negative = text[i++] == '-';
    for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
      if (text[i] == '.') {
        point = true;
        continue;
      }
      digits += text[i];
      if (point) ++fraction_digits;
    }
    long power = -fraction_digits;
    if (i < text.size()) power += std::stol(text.substr(i + 1));
    mpz_t n, p;
    mpz_init_set_str(n, digits.c_str(), 10);
    mpz_init(p);
    mpz_ui_pow_ui(p, 10, static_cast<unsigned long>(power < 0 ? -power : power));
    if (power >= 0) {
      mpz_mul(n, n, p);
      mpq_set_z(q_, n);
    } else {
      mpq_set_num(q_, n);
      mpq_set_den(q_, p);
      mpq_canonicalize(q_);
    }
    if (negative) mpq_neg(q_, q_);
    mpz_clear(n);
    mpz_clear(p);
  }
  explicit Rational(double x) {
    mpq_init(q_);
    mpq_set_d(q_, x);  // exact
  }
  Rational(const Rational&) = delete;
  Rational& operator=(const Rational&) = delete;
  ~Rational() { mpq_clear(q_); }
  mpq_srcptr get() const { return q_; }
  mpq_ptr get() { return q_; }

 private:
  mpq_t q_;
};

bool encloses(const Interval& i, const Rational& exact) { return mpfi_is_inside_q(exact.get(), i.data()) > 0; }

// Width in units of the last place of the lower end (its exponent at kBits).
double width_in_ulps(const Interval& i) {
  const mpfr lo = i.lower(), w = i.width();
  if (mpfr_zero_p(w.backend().data())) return 0;
  // w / 2^(exponent − bits), as a binary exponent shift (no underflow for subnormal-sized ends).
  mpfr ratio = w;
  mpfr_mul_2si(ratio.backend().data(), w.backend().data(), i.precision() - mpfr_get_exp(lo.backend().data()), MPFR_RNDU);
  return mpfr_get_d(ratio.backend().data(), MPFR_RNDU);
}

TEST(Interval, DecimalsAreEnclosedTightly) {
  for (const std::string text : {"0.1", "-0.3", "2.5", "1e-30", "-7e+40", "123456789.123456789", "0.33333333333333333333333",
                                 "1", "-0", "4.9406564584124654e-324"}) {
    const Interval i = Interval::decimal(text, kBits);
    const Rational exact(text);
    EXPECT_TRUE(encloses(i, exact)) << text;
    EXPECT_LE(width_in_ulps(i), 1.0) << text;
  }
  // Exact binary fractions are points.
  EXPECT_EQ(Interval::decimal("2.5", kBits).sign(), Sign::positive);
  EXPECT_TRUE(mpfr_zero_p(Interval::decimal("2.5", kBits).width().backend().data()));
  EXPECT_THROW(Interval::decimal("nan", kBits), vibrofric::InputError);
  EXPECT_THROW(Interval::decimal("0.1x", kBits), vibrofric::InputError);
}

TEST(Interval, FourOperationsEncloseTheExactRationalResult) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60);
  for (int k = 0; k < 2000; ++k) {
    const double a = std::ldexp(mantissa(rng), exponent(rng)), b = std::ldexp(mantissa(rng), exponent(rng));
    if (b == 0) continue;
    const Interval ia = Interval::exact(mpfr(a), kBits), ib = Interval::exact(mpfr(b), kBits);
    const Rational qa(a), qb(b);
    Rational sum(0.0), difference(0.0), product(0.0), quotient(0.0);
    mpq_add(sum.get(), qa.get(), qb.get());
    mpq_sub(difference.get(), qa.get(), qb.get());
    mpq_mul(product.get(), qa.get(), qb.get());
    mpq_div(quotient.get(), qa.get(), qb.get());
    EXPECT_TRUE(encloses(ia + ib, sum)) << a << " + " << b;
    EXPECT_TRUE(encloses(ia - ib, difference)) << a << " - " << b;
    EXPECT_TRUE(encloses(ia * ib, product)) << a << " * " << b;
    EXPECT_TRUE(encloses(ia / ib, quotient)) << a << " / " << b;
    EXPECT_LE(width_in_ulps(ia * ib), 1.0);
    EXPECT_LE(width_in_ulps(ia / ib), 1.0);
  }
}

// MPFR's value rounded down and up at 4 × kBits: an enclosure of the exact value from another
// library's correct rounding.
template <class F>
void expect_encloses_mpfr(const Interval& got, F f, double x, const char* name) {
  mpfr_t v, down, up;
  mpfr_inits2(4 * kBits, v, down, up, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(v, x, MPFR_RNDN);
  f(down, v, MPFR_RNDD);
  f(up, v, MPFR_RNDU);
  EXPECT_TRUE(mpfi_is_inside_fr(down, got.data()) > 0 && mpfi_is_inside_fr(up, got.data()) > 0) << name << "(" << x << ")";
  EXPECT_LE(width_in_ulps(got), 2.0) << name << "(" << x << ")";
  mpfr_clears(v, down, up, static_cast<mpfr_ptr>(nullptr));
}

TEST(Interval, TranscendentalFunctionsEncloseMpfrsDirectedRoundings) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-30, 30);
  for (int k = 0; k < 1000; ++k) {
    const double x = u(rng);
    const Interval i = Interval::exact(mpfr(x), kBits);
    expect_encloses_mpfr(sin(i), mpfr_sin, x, "sin");
    expect_encloses_mpfr(cos(i), mpfr_cos, x, "cos");
    expect_encloses_mpfr(sin_cos(i).first, mpfr_sin, x, "sin of sin_cos");
    expect_encloses_mpfr(sin_cos(i).second, mpfr_cos, x, "cos of sin_cos");
    expect_encloses_mpfr(exp(i), mpfr_exp, x, "exp");
    const double y = std::fabs(x) + 1e-3;
    const Interval j = Interval::exact(mpfr(y), kBits);
    expect_encloses_mpfr(log(j), mpfr_log, y, "log");
    expect_encloses_mpfr(sqrt(j), mpfr_sqrt, y, "sqrt");
    const double z = x / 30;  // in (−1, 1)
    const Interval w = Interval::exact(mpfr(z), kBits);
    expect_encloses_mpfr(asin(w), mpfr_asin, z, "asin");
    expect_encloses_mpfr(acos(w), mpfr_acos, z, "acos");
  }
}

TEST(Interval, InverseTrigonometryDomainsAndRationals) {
  EXPECT_THROW(acos(Interval::hull(mpfr(0), mpfr(1.5), kBits)), vibrofric::SolverError);
  EXPECT_THROW(asin(Interval::integer(-2, kBits)), vibrofric::SolverError);
  // 1/3 enclosed by two neighbouring kBits numbers; 3/8 exactly.
  mpq_t q;
  mpq_init(q);
  mpq_set_si(q, 1, 3);
  const Interval third = Interval::rational(q, kBits);
  EXPECT_EQ((third * 3 - Interval::integer(1, kBits)).sign(), Sign::undecided);
  EXPECT_LE(width_in_ulps(third), 1.0);
  mpq_set_si(q, 3, 8);
  const Interval eighths = Interval::rational(q, kBits);
  EXPECT_EQ((eighths * 8 - Interval::integer(3, kBits)).sign(), Sign::zero);
  mpq_clear(q);
}

TEST(Interval, WideArgumentsHoldEveryPointsValue) {
  // sin over [1, 2] reaches its maximum 1 at π/2 inside: the enclosure must hold 1 and sin(1), sin(2).
  // MPFR's sin(x) rounded down and up at 4 × kBits lies inside for every sample x of [1, 2]
  // (rounded down at more bits is never below rounded down at fewer).
  const Interval s = sin(Interval::hull(mpfr(1), mpfr(2), kBits));
  EXPECT_TRUE(s.contains(mpfr(1)));
  mpfr_t v, down, up;
  mpfr_inits2(4 * kBits, v, down, up, static_cast<mpfr_ptr>(nullptr));
  for (double x = 1; x <= 2; x += 1.0 / 64) {
    mpfr_set_d(v, x, MPFR_RNDN);
    mpfr_sin(down, v, MPFR_RNDD);
    mpfr_sin(up, v, MPFR_RNDU);
    EXPECT_TRUE(mpfi_is_inside_fr(down, s.data()) > 0 && mpfi_is_inside_fr(up, s.data()) > 0) << x;
  }
  // sin_cos over a narrow interval (its midpoint and radius) and a wide one (mpfi) alike.
  for (const double width : {0.0, 1e-30, 1e-7, 0.5}) {
    const Interval arc = Interval::hull(mpfr(1), mpfr(1) + mpfr(width), kBits);
    const auto [sn, cs] = sin_cos(arc);
    for (double t = 0; t <= 1; t += 1.0 / 16) {
      mpfr_set_d(v, 1, MPFR_RNDN);
      mpfr_set_prec(down, 4 * kBits);
      mpfr_set_d(down, width * t, MPFR_RNDN);
      mpfr_add(v, v, down, MPFR_RNDN);  // exact: 1 + a double within 4 × kBits
      using F = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
      for (const auto& [f, out, name] : {std::tuple<F, const Interval*, const char*>{mpfr_sin, &sn, "sin"},
                                          std::tuple<F, const Interval*, const char*>{mpfr_cos, &cs, "cos"}}) {
        f(down, v, MPFR_RNDD);
        f(up, v, MPFR_RNDU);
        EXPECT_TRUE(mpfi_is_inside_fr(down, out->data()) > 0 && mpfi_is_inside_fr(up, out->data()) > 0) << name << " " << width;
      }
    }
    if (width < 1e-6) {
      EXPECT_LT(width_in_ulps(sn) + width_in_ulps(cs), 8 + 2 * width * std::pow(2.0, static_cast<double>(sn.precision()))) << width;
    }
  }
  mpfr_clears(v, down, up, static_cast<mpfr_ptr>(nullptr));
  // cos over a whole period is [−1, 1].
  const Interval c = cos(Interval::hull(mpfr(0), mpfr(7), kBits));
  EXPECT_TRUE(c.contains(mpfr(-1)) && c.contains(mpfr(1)));
  // The dependency problem is there (x − x over [0, 1] is [−1, 1]), and is allowed: enclosures,
  // not exact ranges.
  const Interval x = Interval::hull(mpfr(0), mpfr(1), kBits);
  EXPECT_EQ((x - x).sign(), Sign::undecided);
}

TEST(Interval, NarrowArgumentsHoldEveryPointsValue) {
  // sin, cos (one mpfr call at the midpoint, widened by the radius), asin, acos and log (widened
  // by the radius times the largest slope) and exp on narrow intervals: MPFR's value rounded down and up at
  // 4 × kBits lies inside for every sample point, and the width is the argument's width times
  // the slope bound (just above the largest |f'| on it) plus eight ulps at most.
  using F = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
  struct Case {
    F exact;
    Interval (*f)(Interval);
    double centre, slope;  // slope: a bound on |f'| near the centre
    const char* name;
  };
  // (sin and cos: |cos 1.3| = 0.2675, |sin 2.7| = 0.4274, and at 1.5707963 (π/2 − 2.7e-8) |cos| and
  // the radius are below 1e-6: the enclosure follows the slope, not the Lipschitz constant 1.)
  const Case cases[] = {{mpfr_sin, [](Interval x) { return sin(std::move(x)); }, 1.3, 0.268, "sin"},
                        {mpfr_cos, [](Interval x) { return cos(std::move(x)); }, -2.7, 0.428, "cos"},
                        {mpfr_sin, [](Interval x) { return sin(std::move(x)); }, 1.5707963, 1e-6, "sin"},
                        {mpfr_asin, [](Interval x) { return asin(std::move(x)); }, 0.3, 1.05, "asin"},
                        {mpfr_asin, [](Interval x) { return asin(std::move(x)); }, -0.99, 7.09, "asin"},
                        {mpfr_acos, [](Interval x) { return acos(std::move(x)); }, 0.6, 1.2501, "acos"},
                        {mpfr_acos, [](Interval x) { return acos(std::move(x)); }, -0.998, 15.9, "acos"},
                        {mpfr_exp, [](Interval x) { return exp(std::move(x)); }, 2.3, 9.99, "exp"},
                        {mpfr_log, [](Interval x) { return log(std::move(x)); }, 0.7, 1.4286, "log"}};
  mpfr_t v, d, down, up;
  mpfr_inits2(4 * kBits, v, d, down, up, static_cast<mpfr_ptr>(nullptr));
  for (const Case& c : cases)
    for (const double width : {0.0, 1e-30, 1e-12, 1e-7}) {
      mpfr hi;  // centre + width exactly (4 × kBits hold it), as the sample points below
      mpfr_set_prec(hi.backend().data(), 4 * kBits);
      mpfr_set_d(hi.backend().data(), c.centre, MPFR_RNDN);
      mpfr_add_d(hi.backend().data(), hi.backend().data(), width, MPFR_RNDN);
      const Interval arg = Interval::hull(mpfr(c.centre), hi, kBits);
      const Interval out = c.f(arg);
      for (double t = 0; t <= 1; t += 1.0 / 16) {
        mpfr_set_d(v, c.centre, MPFR_RNDN);
        mpfr_set_d(d, width * t, MPFR_RNDN);
        mpfr_add(v, v, d, MPFR_RNDN);  // exact within 4 × kBits
        c.exact(down, v, MPFR_RNDD);
        c.exact(up, v, MPFR_RNDU);
        EXPECT_TRUE(mpfi_is_inside_fr(down, out.data()) > 0 && mpfi_is_inside_fr(up, out.data()) > 0)
            << c.name << " at " << c.centre << " + " << width * t;
      }
      // Four ulps of the result (f(mid)'s rounding, the spread's outward rounding), and the slope
      // times the argument's width plus its rounded midpoint and radius (an ulp of the argument
      // each way, 2^(e_arg − e_out) ulps of the result).
      const long e_out = mpfr_get_exp(out.lower().backend().data()), e_arg = mpfr_get_exp(arg.lower().backend().data());
      EXPECT_LE(width_in_ulps(out), 4 + c.slope * (width * std::pow(2.0, out.precision() - e_out) + 2 * std::ldexp(1.0, e_arg - e_out)))
          << c.name << " " << c.centre << " " << width;
    }
  mpfr_clears(v, d, down, up, static_cast<mpfr_ptr>(nullptr));
  // An exact value stays a point: sin 0 = asin 0 = 0, cos 0 = 1, acos 1 = 0.
  EXPECT_EQ(sin(Interval(kBits)).sign(), Sign::zero);
  EXPECT_EQ(asin(Interval(kBits)).sign(), Sign::zero);
  EXPECT_EQ((cos(Interval(kBits)) - Interval::integer(1, kBits)).sign(), Sign::zero);
  EXPECT_EQ(acos(Interval::integer(1, kBits)).sign(), Sign::zero);
}

TEST(Interval, MovesTakeTheEndpointsAndMovedFromOnesCanBeAssigned) {
  Interval a = Interval::integer(3, kBits);
  Interval b(std::move(a));
  EXPECT_EQ((b - Interval::integer(3, kBits)).sign(), Sign::zero);
  a = Interval::integer(5, 200);  // move-assigned into a moved-from interval
  EXPECT_EQ(a.precision(), 200);
  Interval c = std::move(b);
  b = a;  // copy-assigned into a moved-from interval
  EXPECT_EQ((b - Interval::integer(5, kBits)).sign(), Sign::zero);
  EXPECT_EQ(b.precision(), 200);
  c = std::move(b);  // replaces an owned value
  EXPECT_EQ((c - Interval::integer(5, kBits)).sign(), Sign::zero);
  const Interval sum = std::move(c) + Interval::integer(1, kBits);  // the operators take their operand
  EXPECT_EQ((sum - Interval::integer(6, kBits)).sign(), Sign::zero);
}

TEST(Interval, SignsAndComparisonsDecideOnlyWhenCertain) {
  EXPECT_EQ(Interval::hull(mpfr(1), mpfr(2), kBits).sign(), Sign::positive);
  EXPECT_EQ(Interval::hull(mpfr(-2), mpfr(-1), kBits).sign(), Sign::negative);
  EXPECT_EQ(Interval(kBits).sign(), Sign::zero);
  EXPECT_EQ(Interval::hull(mpfr(-1), mpfr(1), kBits).sign(), Sign::undecided);
  EXPECT_EQ(Interval::hull(mpfr(0), mpfr(1), kBits).sign(), Sign::undecided);
  // Two enclosures of the same decimal are not "equal": their difference holds 0 and more.
  EXPECT_EQ(compare(Interval::decimal("0.1", kBits), Interval::decimal("0.1", kBits)), Sign::undecided);
  EXPECT_EQ(compare(Interval::decimal("0.1", kBits), Interval::decimal("0.10000000000000000001", kBits)), Sign::negative);
  // 1e-25 apart is below 64 bits' resolution at 0.1: undecided, and decided at 128 bits.
  EXPECT_EQ(compare(Interval::decimal("0.1", kBits), Interval::decimal("0.1000000000000000000000001", kBits)),
            Sign::undecided);
  EXPECT_EQ(compare(Interval::decimal("0.1", 128), Interval::decimal("0.1000000000000000000000001", 128)), Sign::negative);
}

TEST(Interval, DomainErrorsAndUnboundedQuotients) {
  EXPECT_THROW(sqrt(Interval::hull(mpfr(-1), mpfr(1), kBits)), vibrofric::SolverError);
  EXPECT_THROW(log(Interval::hull(mpfr(0), mpfr(1), kBits)), vibrofric::SolverError);
  const Interval q = Interval::integer(1, kBits) / Interval::hull(mpfr(-1), mpfr(1), kBits);
  EXPECT_FALSE(q.bounded());
  EXPECT_EQ(q.sign(), Sign::undecided);
}

TEST(Interval, BisectionHullAndIntersection) {
  const Interval x = Interval::hull(mpfr(-3), mpfr(5), kBits);
  const auto [left, right] = x.bisect();
  EXPECT_EQ(mpfr_cmp_si(left.upper().backend().data(), 1), 0);
  EXPECT_EQ(mpfr_cmp_si(right.lower().backend().data(), 1), 0);
  EXPECT_TRUE(x.contains(hull(left, right)) && hull(left, right).contains(x));
  EXPECT_FALSE(intersection(Interval::hull(mpfr(0), mpfr(1), kBits), Interval::hull(mpfr(2), mpfr(3), kBits)));
  const auto both = intersection(Interval::hull(mpfr(0), mpfr(2), kBits), Interval::hull(mpfr(1), mpfr(3), kBits));
  ASSERT_TRUE(both);
  EXPECT_EQ(mpfr_cmp_si(both->lower().backend().data(), 1), 0);
  EXPECT_EQ(mpfr_cmp_si(both->upper().backend().data(), 2), 0);
  // Precision: the wider operand's wins.
  EXPECT_EQ((Interval::integer(1, 64) + Interval::integer(1, 200)).precision(), 200);
}

}  // namespace
