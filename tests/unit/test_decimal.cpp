// Decimal (api/decimal_value.hpp), the one reader of decimal text: its grammar accepts and refuses
// what README "Numbers" says, its parts, exact rational, comparison and exact sum against values
// computed here another way (GMP's own reader of "N/10^k", MPFR at many digits), and each number
// type's value against the C library's and MPFR's correctly rounded readers.
#include <gtest/gtest.h>

#include <gmp.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "vibrofric/api/exact_input.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/decimal_value.hpp"
#include "vibrofric/api/input_value.hpp"
#include "vibrofric/api/number_type.hpp"
#include "vibrofric/api/rig.hpp"
#include "vibrofric/core/escalate.hpp"
#include "vibrofric/core/errors.hpp"

namespace vibrofric {
namespace {

TEST(Decimal, GrammarAcceptsAndRefuses) {
  for (const char* t : {"0", "-0", "+1", "1.", ".5", "-.5", "1.25e-3", "1E9", "1e+999999999", "007.500", "0.000e-5",
                        "123456789012345678901234567890"})
    EXPECT_TRUE(Decimal::read(t).has_value()) << t;
  for (const char* t : {"", "+", "-", ".", "e5", ".e5", "1e", "1e+", "1e1234567890", "1.2.3", "1,5", " 1", "1 ",
                        "0x10", "inf", "nan", "1e5.0", "--1", "1-", "١"})
    EXPECT_FALSE(Decimal::read(t).has_value()) << t;
}

TEST(Decimal, PartsAreSignDigitsAndPowerOfTen) {
  const auto d = *Decimal::read("-007.500e-2");
  EXPECT_TRUE(d.negative());
  EXPECT_EQ(d.digits(), "7500");
  EXPECT_EQ(d.exponent(), -5);
  EXPECT_EQ(d.text(), "-007.500e-2");
  EXPECT_TRUE(Decimal::read("-0.000e7")->is_zero());
  EXPECT_EQ(Decimal::read("-0.000e7")->exponent(), 4);
}

// "N/10^k" or "N·10^k" read by GMP's own rational reader.
exact::Rational gmp_rational(const std::string& n, long k) {
  mpq_t q;
  mpq_init(q);
  std::string text = n;
  if (k < 0) text += "/1" + std::string(static_cast<std::size_t>(-k), '0');
  else text += std::string(static_cast<std::size_t>(k), '0');
  EXPECT_EQ(mpq_set_str(q, text.c_str(), 10), 0) << text;
  mpq_canonicalize(q);
  exact::Rational r(q);
  mpq_clear(q);
  return r;
}

TEST(Decimal, RationalIsExact) {
  EXPECT_EQ(rational(*Decimal::read("-007.500e-2"), "x"), gmp_rational("-75", -3));
  EXPECT_EQ(rational(*Decimal::read("1.25e3"), "x"), gmp_rational("125", 1));
  EXPECT_EQ(rational(*Decimal::read("0.1"), "x"), gmp_rational("1", -1));
  EXPECT_EQ(rational(*Decimal::read("-0"), "x"), 0);
  EXPECT_EQ(rational(*Decimal::read("1e100000"), "x"), gmp_rational("1", 100000));
  EXPECT_THROW(rational(*Decimal::read("1e100001"), "x"), InputError);
  // The limit counts the significand's digits on the small side: 10^-100001 is one digit past it
  // and still taken, 10^-100002 is not.
  EXPECT_EQ(rational(*Decimal::read("1e-100001"), "x"), gmp_rational("1", -100001));
  EXPECT_THROW(rational(*Decimal::read("1e-100002"), "x"), InputError);
  EXPECT_THROW(exact_decimal("1,5", "beta"), InputError);  // the reader's refusal, with check_decimal's message
}

TEST(Decimal, CompareIsExactBeyondAnyFixedPrecision) {
  // 500 digits apart in the last place: 400-digit arithmetic would call them equal.
  const std::string a = "1." + std::string(499, '0') + "1", b = "1." + std::string(500, '0');
  EXPECT_EQ(compare(*Decimal::read(a), *Decimal::read(b)), 1);
  EXPECT_EQ(compare(*Decimal::read(b), *Decimal::read(a)), -1);
  EXPECT_EQ(compare(*Decimal::read("1.0"), *Decimal::read("0.1e1")), 0);
  EXPECT_EQ(compare(*Decimal::read("-0"), *Decimal::read("0.00")), 0);
  EXPECT_EQ(compare(*Decimal::read("-2"), *Decimal::read("1")), -1);
  EXPECT_EQ(compare(*Decimal::read("-2"), *Decimal::read("-10")), 1);
  // Random decimals against MPFR at 200 digits (every one holds exactly at that precision).
  std::mt19937 gen(7);
  std::uniform_int_distribution<int> digit(0, 9), len(1, 30), exp10(-40, 40), sign(0, 1);
  PrecisionScope scope(200);
  for (int i = 0; i < 2000; ++i) {
    auto make = [&] {
      std::string s = sign(gen) ? "-" : "";
      const int n = len(gen), dot = std::uniform_int_distribution<int>(0, n)(gen);
      for (int k = 0; k < n; ++k) s += static_cast<char>('0' + digit(gen)), s += k + 1 == dot && k + 1 < n ? "." : "";
      return s + "e" + std::to_string(exp10(gen) / (i % 3 == 0 ? 40 : 1));
    };
    const std::string x = make(), y = i % 5 == 0 ? x : make();
    const mpfr mx(x), my(y);
    EXPECT_EQ(compare(*Decimal::read(x), *Decimal::read(y)), mx < my ? -1 : (mx > my ? 1 : 0)) << x << " " << y;
  }
}

TEST(Decimal, ExactSumOfManyTerms) {
  const std::vector<std::string> texts{"0.1", "-0.30", "2e-5", "7", "-0.0000"};
  std::vector<Decimal> values;
  for (const auto& t : texts) values.push_back(*Decimal::read(t));
  std::vector<const Decimal*> terms;
  for (const auto& d : values) terms.push_back(&d);
  // 0.1 − 0.3 + 0.00002 + 7 − 0 = 6.80002, written at the smallest power of ten (10^-5)
  EXPECT_EQ(exact_sum_text(terms), "680002e-5");
}

TEST(Decimal, EachTypeTakesTheCorrectlyRoundedValue) {
  std::mt19937 gen(11);
  std::uniform_int_distribution<int> digit(0, 9), len(1, 40), exp10(-320, 300);
  for (int i = 0; i < 3000; ++i) {
    std::string s = digit(gen) < 5 ? "-" : "";
    const int n = len(gen);
    for (int k = 0; k < n; ++k) s += static_cast<char>('0' + digit(gen));
    s += "e" + std::to_string(exp10(gen));
    const Decimal d = *Decimal::read(s);
    // MPFR's reader, correctly rounded at the type's bits (normal results: a subnormal would be
    // rounded twice this way).
    mpfr_t x;
    mpfr_init2(x, 53);
    mpfr_strtofr(x, s.c_str(), nullptr, 10, MPFR_RNDN);
    const double expected = mpfr_get_d(x, MPFR_RNDN);
    mpfr_set_prec(x, 64);
    mpfr_strtofr(x, s.c_str(), nullptr, 10, MPFR_RNDN);
    const long double expected_ld = mpfr_get_ld(x, MPFR_RNDN);
    mpfr_clear(x);
    if (std::fabs(expected) >= 0x1p-1022 || expected == 0) {
      EXPECT_EQ(d.to<double>(), expected) << s;
    }
    EXPECT_EQ(d.to<long double>(), expected_ld) << s;
    // cpp_bin_float_50 and _100 (Boost's reader): MPFR's rounding at their bits, converted exactly.
    for (const int bits : {std::numeric_limits<bin50>::digits, std::numeric_limits<bin100>::digits}) {
      PrecisionScope wide(200);
      mpfr r;
      mpfr_set_prec(r.backend().data(), bits);
      mpfr_strtofr(r.backend().data(), s.c_str(), nullptr, 10, MPFR_RNDN);
      if (bits == std::numeric_limits<bin50>::digits)
        EXPECT_EQ(mpfr(d.to<bin50>()), r) << s << " in cpp_bin_float_50";
      else
        EXPECT_EQ(mpfr(d.to<bin100>()), r) << s << " in cpp_bin_float_100";
    }
    PrecisionScope scope(60);
    mpfr reference;
    mpfr_strtofr(reference.backend().data(), s.c_str(), nullptr, 10, MPFR_RNDN);
    EXPECT_EQ(d.to<mpfr>(), reference) << s;
  }
}

// escalate() (core/escalate.hpp), the one loop that raises a precision: it returns the first
// precision's answer that is decided and tries no other, and stops undecided, without passing
// the limit, where next() says so.
TEST(Escalate, ReturnsTheFirstDecidedAnswer) {
  std::vector<long> tried;
  const auto r = escalate(
      10, [&](long work) -> std::optional<long> {
        tried.push_back(work);
        if (work >= 80) return work * 3;
        return std::nullopt;
      },
      doubling_up_to(1000));
  ASSERT_TRUE(r);
  EXPECT_EQ(*r, 240);
  EXPECT_EQ(tried, (std::vector<long>{10, 20, 40, 80}));
}

TEST(Escalate, StopsUndecidedAtTheLimit) {
  std::vector<long> tried;
  const auto never = [&](long work) -> std::optional<int> {
    tried.push_back(work);
    return std::nullopt;
  };
  EXPECT_FALSE(escalate(10, never, doubling_up_to(160)));
  EXPECT_EQ(tried, (std::vector<long>{10, 20, 40, 80, 160}));  // the limit itself is tried
  tried.clear();
  EXPECT_FALSE(escalate(10, never, doubling_up_to(159)));
  EXPECT_EQ(tried, (std::vector<long>{10, 20, 40, 80}));
}

// InputValue (api/input_value.hpp): a decimal keeps its text and is rounded correctly in each
// type; a computed value keeps its label and is rounded once; the grammar's refusal names the
// input and quotes the text.
TEST(InputValue, DecimalKeepsItsTextAndRoundsCorrectly) {
  const InputValue v = InputValue::read("0.1", "beta");
  ASSERT_TRUE(v.given());
  ASSERT_NE(v.decimal(), nullptr);
  EXPECT_EQ(v.computed_value(), nullptr);
  EXPECT_EQ(v.text(), "0.1");
  EXPECT_EQ(v.to<double>(), 0.1);
  EXPECT_EQ(v.to<long double>(), 0.1L);
  PrecisionScope scope(100);
  mpfr reference;
  mpfr_strtofr(reference.backend().data(), "0.1", nullptr, 10, MPFR_RNDN);
  EXPECT_EQ(v.to<mpfr>(), reference);
}

TEST(InputValue, RefusalQuotesTheTextAndNamesTheInput) {
  for (const std::string text : {"0.1x", "nan", "1e400", "0x1p3", "1,5"}) {
    try {
      (void)InputValue::read(text, "--beta");
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("--beta"), std::string::npos) << m;
      EXPECT_NE(m.find("'" + text + "'"), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
  EXPECT_THROW((void)InputValue::read("", "--beta"), InputError);  // "--beta is empty: …"
}

TEST(InputValue, ComputedKeepsItsLabelAndRoundsOnce) {
  PrecisionScope scope(60);
  const mpfr third = mpfr(1) / 3;
  const InputValue v = InputValue::computed(third, "beta from --v0 and --F_N");
  EXPECT_EQ(v.decimal(), nullptr);
  ASSERT_NE(v.computed_value(), nullptr);
  EXPECT_EQ(*v.computed_value(), third);
  EXPECT_EQ(v.text(), "beta from --v0 and --F_N");
  EXPECT_EQ(v.to<double>(), 1.0 / 3.0);
  EXPECT_EQ(v.to<long double>(), 1.0L / 3.0L);
  const InputValue none;
  EXPECT_FALSE(none.given());
  EXPECT_EQ(none.text(), "");
  EXPECT_EQ(none.to<double>(), 0.0);
}

// same_significant (api/decimal.hpp) decides on the rounded values, across a decade and by sign.
TEST(Significant, SameSignificantDecidesOnRoundedValues) {
  PrecisionScope scope(60);
  const auto m = [](const char* s) {
    mpfr x;
    mpfr_strtofr(x.backend().data(), s, nullptr, 10, MPFR_RNDN);
    return x;
  };
  EXPECT_TRUE(same_significant(m("0.12344"), m("0.12341"), 4));
  EXPECT_FALSE(same_significant(m("0.12344"), m("0.12341"), 5));
  EXPECT_FALSE(same_significant(m("0.12344"), m("0.12346"), 4));
  EXPECT_TRUE(same_significant(m("0.99996"), m("1.0000"), 4));  // both 1.000
  EXPECT_FALSE(same_significant(m("0.5"), m("-0.5"), 10));
  EXPECT_TRUE(same_significant(m("0"), m("0"), 3));
  EXPECT_FALSE(same_significant(m("0"), m("1e-30"), 3));
}

TEST(Significant, TextIsTheCorrectlyRoundedDigits) {
  PrecisionScope scope(60);
  mpfr x;
  mpfr_strtofr(x.backend().data(), "1234.5678", nullptr, 10, MPFR_RNDN);
  EXPECT_EQ((Significant{x, 6}.text()), "1234.57");
  EXPECT_EQ((Significant{mpfr(1), 3}.text()), "1.00");
  EXPECT_EQ((Significant{mpfr(-0.25), 1}.text()), "-0.2");  // a tie, to even
  EXPECT_EQ((Significant{mpfr(std::numeric_limits<double>::quiet_NaN()), 5}.text()), "nan");
  EXPECT_EQ((Significant{mpfr(-std::numeric_limits<double>::infinity()), 5}.text()), "-inf");
}

// type_significant: the value rounded to the type with the digits printed for it; mpfr as it is.
TEST(Significant, TypeSignificantRoundsToTheType) {
  PrecisionScope scope(200);
  const mpfr third = mpfr(1) / 3;
  const Significant d = detail::type_significant(third, Precision{NumberType::float64, 0});
  EXPECT_EQ(d.value, mpfr(1.0 / 3.0));
  EXPECT_EQ(d.digits, 17);
  EXPECT_EQ(d.text(), "0.33333333333333331");  // 1/3 in double is 0.333333333333333314829…
  const Significant m = detail::type_significant(third, Precision{NumberType::mpfr, 30});
  EXPECT_EQ(m.value, third);
  EXPECT_EQ(m.digits, 30);
  EXPECT_EQ(m.text(), "0.333333333333333333333333333333");
}

}  // namespace
}  // namespace vibrofric
