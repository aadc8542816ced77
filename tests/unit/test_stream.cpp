// evaluate_stream (evaluate.hpp): the same strings as evaluate() for every number type, profile,
// quantity and thread count; rows in index order on the calling thread; at most a window of
// threads × stream_chunk points made ahead of the rows delivered; the first failing point's error
// after exactly the rows before it. Timing is never asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdio>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <typeinfo>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "evaluate_impl.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/flat/solver.hpp"

#include <gmp.h>

namespace {

using namespace vibrofric;

// A decimal as a user types it ("%.*g"), from a seeded generator: random-ish, the same every run.
std::string decimal(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

// n points: β in (lo_beta, hi_beta), γ in (lo_gamma, hi_gamma); runs of equal γ (as a sweep gives,
// where the contact cache matters) mixed with single ones, and a few where double escalates
// (β → 0, γ → −1 for the catalogue waves).
std::vector<Point> grid(std::size_t n, unsigned seed, bool corners = true) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> beta(0.05, 3), gamma(-0.95, 1.5), u(0, 1);
  std::vector<Point> out;
  std::string g = decimal(gamma(gen), 6);
  for (std::size_t i = 0; i < n; ++i) {
    if (u(gen) < 0.2) g = decimal(gamma(gen), 1 + static_cast<int>(u(gen) * 16));
    std::string b = decimal(beta(gen), 1 + static_cast<int>(u(gen) * 16));
    if (corners && i % 7 == 3) b = "1e-6";
    out.push_back({b, corners && i % 11 == 5 ? "-0.9999999" : g});
  }
  return out;
}

struct Row {
  std::size_t index;
  std::string value;
};

// A delivered value's number is the value its text prints: for double and long double, the text
// (max_digits10 digits, which read back exactly) read by from_chars is the number to the bit; the
// other types deliver no number.
void expect_number_is_text(const StreamValue& v, const Precision& p) {
  if (p.type == NumberType::float64 || p.type == NumberType::float80) {
    ASSERT_TRUE(v.number.has_value()) << v.text;
    if (p.type == NumberType::float64) {
      double x = 0;
      ASSERT_EQ(std::from_chars(v.text.data(), v.text.data() + v.text.size(), x).ec, std::errc()) << v.text;
      EXPECT_EQ(static_cast<long double>(x), *v.number) << v.text;
      EXPECT_EQ(static_cast<long double>(static_cast<double>(*v.number)), *v.number) << "not a double: " << v.text;
    } else {
      long double x = 0;
      ASSERT_EQ(std::from_chars(v.text.data(), v.text.data() + v.text.size(), x).ec, std::errc()) << v.text;
      EXPECT_EQ(x, *v.number) << v.text;
    }
  } else {
    EXPECT_FALSE(v.number.has_value()) << v.text;
  }
}

// evaluate_stream's rows, checking order and the calling thread as they come.
std::vector<std::string> stream(const WaveSpec& wave, Quantity q, const std::vector<Point>& points, const Precision& p,
                                const BatchOptions& o, std::vector<Row>* rows = nullptr) {
  std::vector<std::string> out;
  const auto caller = std::this_thread::get_id();
  evaluate_stream(
      wave, q, points.size(), [&](std::size_t i) { return points.at(i); }, p, o,
      [&](std::size_t i, const StreamValue& v) {
        EXPECT_EQ(i, out.size()) << "rows out of order";
        EXPECT_EQ(std::this_thread::get_id(), caller) << "sink called from a worker";
        expect_number_is_text(v, p);
        out.push_back(v.text);
        if (rows) rows->push_back({i, v.text});
      });
  return out;
}

struct TypeCase {
  Precision precision;
  std::size_t flat_points;    // per quantity, flat punch
  std::size_t curved_points;  // sphere: a spring integral per point (cpp_bin_float_100: ~17 s a point, none)
};

std::vector<TypeCase> type_cases() {
  return {
      {{NumberType::float64, 17}, 1000, 12},
      {{NumberType::float80, 21}, 500, 4},
      {{NumberType::bin50, 50}, 200, 2},
      {{NumberType::bin100, 100}, 100, 0},
      {{NumberType::mpfr, 30}, 200, 4},
  };
}

// `text` is `value` correctly rounded (to nearest, ties to even) to `digits` significant digits,
// decided apart from format_significant in exact rationals: the text's significand D and power
// of ten E (text = D·10^E, D of exactly `digits` digits, trailing zeros kept) against the binary
// value m·2^k, |m·2^k − D·10^E| < 10^E/2, or equal to it with D even.
void expect_correct_decimal(const mpfr& value, const std::string& text, int digits, const std::string& where) {
  std::string t = text;
  const bool negative = !t.empty() && t[0] == '-';
  if (negative) t.erase(0, 1);
  long e10 = 0;
  if (const auto e = t.find_first_of("eE"); e != std::string::npos) {
    e10 = std::stol(t.substr(e + 1));
    t.resize(e);
  }
  std::string d;
  for (const char ch : t) {
    if (ch == '.') continue;
    ASSERT_TRUE(ch >= '0' && ch <= '9') << where << ": '" << text << "' is not a decimal";
    d += ch;
  }
  if (const auto dot = t.find('.'); dot != std::string::npos) e10 -= static_cast<long>(t.size() - dot - 1);
  const auto first = d.find_first_not_of('0');
  ASSERT_NE(first, std::string::npos) << where << ": '" << text << "' is zero";
  d.erase(0, first);
  ASSERT_EQ(static_cast<int>(d.size()), digits) << where << ": '" << text << "' has " << d.size() << " significant digits";
  mpq_t v, w, ten, half;
  mpz_t m, p;
  mpq_inits(v, w, ten, half, nullptr);
  mpz_inits(m, p, nullptr);
  const mpfr_exp_t k = mpfr_get_z_2exp(m, value.backend().data());  // value = m·2^k exactly
  mpq_set_z(v, m);
  if (k >= 0) mpq_mul_2exp(v, v, static_cast<mp_bitcnt_t>(k)); else mpq_div_2exp(v, v, static_cast<mp_bitcnt_t>(-k));
  mpz_set_str(m, d.c_str(), 10);
  if (negative) mpz_neg(m, m);
  mpz_ui_pow_ui(p, 10, static_cast<unsigned long>(e10 < 0 ? -e10 : e10));
  mpq_set_z(ten, p);                                  // 10^|E|
  if (e10 < 0) mpq_inv(ten, ten);                     // 10^E
  mpq_set_z(w, m);
  mpq_mul(w, w, ten);                                 // D·10^E
  mpq_sub(v, v, w);
  mpq_abs(v, v);                                      // |value − D·10^E|
  mpq_div_2exp(half, ten, 1);                         // 10^E/2
  const int c = mpq_cmp(v, half);
  EXPECT_TRUE(c < 0 || (c == 0 && mpz_even_p(m))) << where << ": '" << text << "' is not " << value.str(digits + 10)
                                                   << " rounded to " << digits << " digits";
  mpq_clears(v, w, ten, half, nullptr);
  mpz_clears(m, p, nullptr);
}

// μ̄/μ0 or Ψ of the sine at a point, by the core at `digits` decimal digits from the decimal text
// (the same algorithm at much higher precision than the type under test; no API, no ladder).
mpfr reference(Quantity q, const Point& pt, bool sphere, unsigned digits) {
  PrecisionScope scope(digits);
  const Sine<mpfr> sine;
  const mpfr beta(pt.beta.text()), gamma(q == Quantity::psi ? "0" : pt.gamma.text());
  // Its own error bound must leave 15 of the 40 extra digits (β → 0 with γ → −1 spends about 10).
  const mpfr bound = pow(mpfr(10), -static_cast<int>(digits) + 25);
  if (sphere) {
    const auto r = solve_curved<mpfr>(sine, *make_profile<mpfr>(parse_profile("sphere")), beta, gamma);
    EXPECT_LE(r.relative_error, bound) << "reference at beta " << pt.beta;
    return r.mu;
  }
  if (q == Quantity::psi) {
    const auto r = psi<mpfr>(sine, beta);
    EXPECT_LE(r.lost_relative_error, bound) << "reference at beta " << pt.beta;
    return r.lost_area;
  }
  const auto r = solve<mpfr>(sine, beta, gamma);
  EXPECT_LE(r.relative_error, bound) << "reference at beta " << pt.beta << " gamma " << pt.gamma;
  return r.mu;
}

// Each delivered text against the reference: the correctly rounded value of the type (double,
// long double, cpp_bin_float: the reference rounded to the type, then to the printed digits) or
// of the digits asked for (mpfr).
void expect_rounding_of_reference(const std::string& text, const mpfr& ref, const Precision& p, const std::string& where) {
  const int digits = output_digits(p);
  PrecisionScope scope(static_cast<unsigned>(2 * digits + 40));  // converts cpp_bin_float to mpfr exactly
  switch (p.type) {
    case NumberType::float64: {
      EXPECT_EQ(std::stod(text), static_cast<double>(ref)) << where;
      break;
    }
    case NumberType::float80:
      EXPECT_EQ(std::stold(text), static_cast<long double>(ref)) << where;
      break;
    case NumberType::bin50:
      expect_correct_decimal(mpfr(detail::rounded<bin50>(ref)), text, digits, where);
      break;
    case NumberType::bin100:
      expect_correct_decimal(mpfr(detail::rounded<bin100>(ref)), text, digits, where);
      break;
    case NumberType::mpfr:
      expect_correct_decimal(ref, text, digits, where);
      break;
  }
}

// The same strings as evaluate() for each type, flat (μ and Ψ) and sphere (μ), threads 1 and 2, each
// the correct rounding of the core's value at 40 more digits than the type has.
TEST(evaluate_stream, SameStringsAsEvaluateInEveryType) {
  const WaveSpec sine = parse_wave("sine");
  unsigned seed = 1;
  for (const TypeCase& c : type_cases()) {
    for (const std::string profile : {"flat", "sphere"}) {
      for (const Quantity q : {Quantity::mu, Quantity::psi}) {
        if (profile != "flat" && q == Quantity::psi) continue;
        const std::size_t n = profile == "flat" ? c.flat_points : c.curved_points;
        if (n == 0) continue;
        const std::vector<Point> points = grid(n, seed++, profile == "flat");
        BatchOptions o;
        o.profile = parse_profile(profile);
        o.threads = 1;
        const std::vector<std::string> want = evaluate(sine, q, points, c.precision, o);
        ASSERT_EQ(want.size(), n);
        const unsigned ref_digits = static_cast<unsigned>(output_digits(c.precision)) + 40;
        for (std::size_t i = 0; i < n; ++i)
          expect_rounding_of_reference(want[i], reference(q, points[i], profile == "sphere", ref_digits), c.precision,
                                       number_type_name(c.precision.type) + " " + profile + " beta " + points[i].beta.text() +
                                           " gamma " + points[i].gamma.text());
        for (const unsigned threads : {1u, 2u}) {
          o.threads = threads;
          const std::string where = number_type_name(c.precision.type) + " " + profile +
                                    (q == Quantity::mu ? " mu" : " psi") + " threads " + std::to_string(threads);
          EXPECT_EQ(stream(sine, q, points, c.precision, o), want) << where;
          if (profile == "flat") {
            EXPECT_EQ(evaluate(sine, q, points, c.precision, o), want) << where;
          }
        }
      }
    }
  }
}

// detail::rounded<T> (a computed point's β and γ in each type) is the nearest T: the same as the type's
// own parsing of the value's first 120 decimal digits, an independent rounding (the values carry
// 80 digits, so no midpoint of T lies between the two at any seed of this run).
template <class T>
void expect_rounded_is_nearest(const char* type) {
  PrecisionScope scope(80);
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-6, 6);
  for (int k = 0; k < 500; ++k) {
    mpfr x = mpfr(mantissa(gen)) / 3 + mpfr(mantissa(gen)) * pow(mpfr(10), -20) / 7;
    x *= pow(mpfr(10), exponent(gen));
    const std::string decimal120 = x.str(120, std::ios_base::scientific);
    if constexpr (is_runtime_precision_v<T>) {
      PrecisionScope at(30);
      EXPECT_EQ(detail::rounded<T>(x).str(40, std::ios_base::scientific),
                parse_real<T>(decimal120, "x").str(40, std::ios_base::scientific))
          << type << " " << decimal120;
    } else {
      EXPECT_EQ(detail::rounded<T>(x), parse_real<T>(decimal120, "x")) << type << " " << decimal120;
    }
  }
}

// Next to a midpoint of cpp_bin_float_50 (within 1e-110 of it, either side): the nearest, judged
// against both neighbours with every value converted to MPFR exactly (an integer mantissa).
TEST(evaluate_stream, ComputedValuesNextToMidpointsRoundToTheNearestBin50) {
  const auto exact = [](const bin50& b) {
    int e = 0;
    const int bits = std::numeric_limits<bin50>::digits;
    std::string m = bin50(ldexp(frexp(b, &e), bits)).str(0, std::ios_base::fixed);
    m = m.substr(0, m.find('.'));
    mpfr r;
    mpfr_set_prec(r.backend().data(), 400);
    mpfr_set_str(r.backend().data(), m.c_str(), 10, MPFR_RNDN);
    mpfr_mul_2si(r.backend().data(), r.backend().data(), e - bits, MPFR_RNDN);
    return r;
  };
  PrecisionScope scope(120);
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> u(0.1, 1);
  for (int k = 0; k < 2000; ++k) {
    const bin50 b = bin50(u(gen)) / 3;
    const mpfr x = (exact(b) + exact(boost::math::float_next(b))) / 2 + (k % 2 ? 1 : -1) * pow(mpfr(10), -110);
    const bin50 c = detail::rounded<bin50>(x);
    const mpfr d = abs(x - exact(c));
    EXPECT_LT(d, abs(x - exact(boost::math::float_next(c)))) << x.str(60);
    EXPECT_LT(d, abs(x - exact(boost::math::float_prior(c)))) << x.str(60);
  }
}

TEST(evaluate_stream, ComputedValuesRoundToTheNearestOfEachType) {
  expect_rounded_is_nearest<double>("double");
  expect_rounded_is_nearest<long double>("long double");
  expect_rounded_is_nearest<bin50>("cpp_bin_float_50");
  expect_rounded_is_nearest<bin100>("cpp_bin_float_100");
  expect_rounded_is_nearest<mpfr>("mpfr 30");
}

// A point given by value (physical_point's β and γ) answers as its decimal does: exactly for
// binary fractions, and for 1/3, -1/7, 5/3 and 1/7 (at 130 digits) as their 130-digit decimals, in
// every type (cpp_bin_float_100 resolves 1e-100: the two differ by 1e-130).
TEST(evaluate_stream, PointByValueAnswersAsItsDecimal) {
  const WaveSpec sine = parse_wave("sine");
  PrecisionScope scope(130);
  const std::vector<std::pair<mpfr, mpfr>> values{{mpfr("0.75"), mpfr("-0.25")}, {mpfr(1) / 3, mpfr(-1) / 7},
                                                   {mpfr(5) / 3, mpfr(1) / 7}};
  for (const TypeCase& c : type_cases()) {
    for (const auto& [beta, gamma] : values) {
      Point by_text(beta.str(130, std::ios_base::scientific), gamma.str(130, std::ios_base::scientific));
      const Point by_value{InputValue::computed(beta, "beta"), InputValue::computed(gamma, "gamma")};
      const std::string where = number_type_name(c.precision.type) + " beta " + by_text.beta.text();
      EXPECT_EQ(evaluate(sine, Quantity::mu, {by_value}, c.precision).front(),
                evaluate(sine, Quantity::mu, {by_text}, c.precision).front())
          << where;
    }
  }
  // No contact by value is refused as by text, naming the text.
  const Point none{InputValue::computed(mpfr("0.5"), "0.5"),
                   InputValue::computed(mpfr(mpfr(-1) - pow(mpfr(10), -40)), "gamma -1 - 1e-40")};
  for (const TypeCase& c : type_cases()) {
    try {
      evaluate(sine, Quantity::mu, {none}, c.precision);
      ADD_FAILURE() << number_type_name(c.precision.type) << ": no contact was not refused";
    } catch (const DomainError& e) {
      EXPECT_NE(std::string(e.what()).find("gamma -1 - 1e-40"), std::string::npos) << e.what();
    }
  }
}

// A wear flat whose λ is computed (physical's b²/(R A)) acts as its 130-digit decimal does.
TEST(evaluate_stream, ComputedWearFlatLambdaActsAsItsDecimal) {
  const WaveSpec sine = parse_wave("sine");
  PrecisionScope scope(130);
  const mpfr lambda = mpfr(10) / 3;
  BatchOptions by_text, by_value;
  by_text.profile = parse_profile("wearflat:" + lambda.str(130, std::ios_base::scientific));
  by_value.profile = parse_profile("wearflat:3.3");  // the name only
  by_value.profile.parameter = InputValue::computed(lambda, "3.3");
  for (const Precision& p : {Precision{NumberType::float64, 17}, Precision{NumberType::mpfr, 30}})
    for (const char* gamma : {"0.5", "-0.3"})
      EXPECT_EQ(evaluate(sine, Quantity::mu, {{"1", gamma}}, p, by_value), evaluate(sine, Quantity::mu, {{"1", gamma}}, p, by_text))
          << number_type_name(p.type) << " gamma " << gamma;
}

// evaluate_one's value is the value it prints: for double and long double the value its
// round-trip digits name (parsed independently); for cpp_bin_float a value of the type within half
// a unit of the printed last digit that prints as the text; for mpfr within half a unit of the
// last digit, with more bits than the digits need. Points from every rung of double's ladder
// (own, long double, mpfr: β = 1e-6 and γ near −1 escalate), Ψ, and a sphere.
TEST(evaluate_stream, EvaluateOneGivesTheValueItPrints) {
  const WaveSpec sine = parse_wave("sine"), triangle = parse_wave("triangle");
  BatchOptions sphere;
  sphere.profile = parse_profile("sphere");
  struct Case {
    const WaveSpec* wave;
    Quantity q;
    Point point;
    const BatchOptions* options;
  };
  const BatchOptions flat;
  const std::vector<Case> cases{{&sine, Quantity::mu, {"0.5", "0.2"}, &flat},     {&sine, Quantity::mu, {"1e-6", "0.5"}, &flat},
                                {&sine, Quantity::mu, {"0.3", "-0.9999999"}, &flat}, {&triangle, Quantity::mu, {"2", "1.5"}, &flat},
                                {&sine, Quantity::psi, {"0.7"}, &flat},           {&sine, Quantity::mu, {"1", "0.5"}, &sphere}};
  for (const TypeCase& c : type_cases()) {
    const int digits = output_digits(c.precision);
    for (const Case& k : cases) {
      if (k.options == &sphere && c.curved_points == 0) continue;
      const Evaluated e = evaluate_one(*k.wave, k.q, k.point, c.precision, *k.options);
      const std::string where = number_type_name(c.precision.type) + " " + k.wave->name + " beta " + k.point.beta.text() + " gamma " + k.point.gamma.text();
      EXPECT_EQ(e.text, evaluate(*k.wave, k.q, {k.point}, c.precision, *k.options).front()) << where;
      PrecisionScope scope(static_cast<unsigned>(digits + 40));
      const mpfr printed(e.text);
      const mpfr half_unit = abs(printed) * pow(mpfr(10), 1 - digits) / 2;
      switch (c.precision.type) {
        case NumberType::float64:
          EXPECT_EQ(e.value, mpfr(std::stod(e.text))) << where;
          break;
        case NumberType::float80:
          EXPECT_EQ(e.value, mpfr(std::stold(e.text))) << where;
          break;
        case NumberType::bin50:
          EXPECT_EQ(e.value, mpfr(detail::rounded<bin50>(e.value))) << where;
          expect_correct_decimal(e.value, e.text, digits, where);
          EXPECT_LE(abs(e.value - printed), half_unit) << where;
          break;
        case NumberType::bin100:
          EXPECT_EQ(e.value, mpfr(detail::rounded<bin100>(e.value))) << where;
          expect_correct_decimal(e.value, e.text, digits, where);
          EXPECT_LE(abs(e.value - printed), half_unit) << where;
          break;
        case NumberType::mpfr:
          EXPECT_GT(e.value.precision(), static_cast<unsigned>(digits)) << where;
          expect_correct_decimal(e.value, e.text, digits, where);
          EXPECT_LE(abs(e.value - printed), half_unit) << where;
          break;
      }
    }
  }
}

// Several ring laps (count not a multiple of the chunk) in double, with progress and the window.
TEST(evaluate_stream, ManyPointsInOrderWithinTheWindow) {
  const WaveSpec wave = parse_wave("tri");
  const std::size_t n = 5 * stream_chunk + 123;
  std::vector<Point> points = grid(n, 99, true);
  const Precision p{NumberType::float64, 17};
  BatchOptions o;
  o.threads = 1;
  const std::vector<std::string> want = evaluate(wave, Quantity::mu, points, p, o);
  for (const unsigned threads : {1u, 2u}) {
    o.threads = threads;
    std::atomic<std::size_t> progress_calls{0}, progress_max{0}, delivered{0}, window_violations{0};
    o.progress = [&](std::size_t d) {
      ++progress_calls;
      for (std::size_t m = progress_max.load(); d > m && !progress_max.compare_exchange_weak(m, d);) {
      }
    };
    std::vector<std::unique_ptr<std::atomic<int>>> asked(n);
    for (auto& a : asked) a = std::make_unique<std::atomic<int>>(0);
    std::vector<std::string> got;
    evaluate_stream(
        wave, Quantity::mu, n,
        [&](std::size_t i) {
          ++*asked.at(i);
          if (i >= delivered.load() + threads * stream_chunk) ++window_violations;
          return points[i];
        },
        p, o,
        [&](std::size_t i, const StreamValue& v) {
          ASSERT_EQ(i, got.size());
          got.push_back(v.text);
          delivered.store(i + 1);
        });
    EXPECT_EQ(got, want) << "threads " << threads;
    EXPECT_EQ(progress_calls.load(), n);
    EXPECT_EQ(progress_max.load(), n);
    EXPECT_EQ(window_violations.load(), 0u) << "a point was made more than threads x stream_chunk ahead";
    EXPECT_TRUE(std::all_of(asked.begin(), asked.end(), [](const auto& a) { return a->load() == 1; }))
        << "every point is asked for exactly once";
  }
}

TEST(evaluate_stream, ZeroPoints) {
  for (const unsigned threads : {0u, 1u, 2u}) {
    BatchOptions o;
    o.threads = threads;
    bool called = false;
    evaluate_stream(
        parse_wave("sine"), Quantity::mu, 0, [&](std::size_t) { called = true; return Point{"1", "0"}; },
        {NumberType::float64, 17}, o, [&](std::size_t, const StreamValue&) { called = true; });
    EXPECT_FALSE(called);
  }
  // The precision is checked whatever the count, as evaluate() does.
  EXPECT_THROW(evaluate_stream(
                   parse_wave("sine"), Quantity::mu, 0, [](std::size_t) { return Point{"1", "0"}; },
                   {NumberType::mpfr, max_digits + 1}, {}, [](std::size_t, const StreamValue&) {}),
               InputError);
}

// The exception evaluate() throws for these points, as (type, message).
std::pair<std::string, std::string> evaluate_error(const WaveSpec& wave, const std::vector<Point>& points,
                                                   const Precision& p, const BatchOptions& o) {
  try {
    evaluate(wave, Quantity::mu, points, p, o);
  } catch (const std::exception& e) {
    return {typeid(e).name(), e.what()};
  }
  ADD_FAILURE() << "evaluate did not throw";
  return {};
}

// A failing point mid-stream: exactly the rows before it, then evaluate()'s exception, whatever
// fails after it (a different error at a later index) and however many threads.
TEST(evaluate_stream, ErrorMidStreamDeliversTheRowsBeforeIt) {
  const WaveSpec sine = parse_wave("sine");
  struct Bad {
    std::size_t n, at;
    const char* beta;
    const char* gamma;
  };
  for (const TypeCase& c : type_cases()) {
    const bool fast = c.precision.type == NumberType::float64;
    const std::size_t n = fast ? 1000 : 9, k = fast ? 777 : 4;
    // (Text outside the grammar cannot make a Point: it is refused where it is read.)
    for (const Bad& bad : {Bad{fast ? 3 * stream_chunk + 7 : 9, fast ? 2 * stream_chunk + 300 : 5, "-0.25", "0.5"},
                           Bad{n, k, "1", "-2"},       // no contact: DomainError
                           Bad{n, 0, "-1e-300", "0.5"}}) {  // the first point
      std::vector<Point> points = grid(bad.n, 7, false);
      points[bad.at] = {bad.beta, bad.gamma};
      if (bad.at + 2 < bad.n) points[bad.at + 2] = {"1", "-5"};  // a later, different error
      for (const unsigned threads : {1u, 2u}) {
        BatchOptions o;
        o.threads = threads;
        const auto want = evaluate_error(sine, points, c.precision, o);
        std::vector<Row> rows;
        std::pair<std::string, std::string> got;
        try {
          stream(sine, Quantity::mu, points, c.precision, o, &rows);
          ADD_FAILURE() << "evaluate_stream did not throw";
        } catch (const std::exception& e) {
          got = {typeid(e).name(), e.what()};
        }
        const std::string where = number_type_name(c.precision.type) + " bad at " + std::to_string(bad.at) +
                                  " threads " + std::to_string(threads);
        EXPECT_EQ(got, want) << where;
        ASSERT_EQ(rows.size(), bad.at) << where;
        if (bad.at > 0) {
          const std::vector<Point> before(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(bad.at));
          const auto ok = evaluate(sine, Quantity::mu, before, c.precision, o);
          for (std::size_t i = 0; i < bad.at; ++i) ASSERT_EQ(rows[i].value, ok[i]) << where << " row " << i;
        }
      }
    }
  }
}

// A catalogue or power:p wave, and the Contacts of its last few γ, persist on a thread from one
// call to the next (ThreadWaves, evaluate_impl.hpp). A call must answer exactly as on a fresh
// thread, which has no such state: across waves, quantities, number types, more γ than are kept
// (eviction), more power exponents than are kept (the waves are dropped while Contacts built on
// them are still held: AddressSanitizer watches that run) and another root-iteration budget.
TEST(evaluate_stream, ThreadStateAnswersAsAFreshThread) {
  struct Call {
    std::string wave;
    Quantity q;
    Precision precision;
    Point p;
    std::uintmax_t budget;
  };
  std::vector<Call> calls;
  const Precision types[] = {{NumberType::float64, 0}, {NumberType::float80, 0}, {NumberType::mpfr, 30}, {NumberType::mpfr, 60}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int round = 0; round < 2; ++round)  // the second round meets what the first left behind
    for (const char* wave : {"sine", "triangle", "power:3", "square"})
      for (int g = 0; g < 12; ++g)
        calls.push_back({wave, g % 5 == 4 ? Quantity::psi : Quantity::mu, types[(g + round) % 4],
                         {decimal(0.05 + 4 * u(rng), 6), decimal(-0.9 + 0.25 * g, 3)}, 0});
  for (int k = 0; k < 70; ++k)
    calls.push_back({"power:" + std::to_string(2 + k) + ".5", Quantity::mu, types[0], {"1", "-0.25"}, 0});
  calls.push_back({"power:2.5", Quantity::mu, types[0], {"1", "-0.25"}, 0});
  calls.push_back({"sine", Quantity::mu, types[2], {"1.5", "0.25"}, 0});
  calls.push_back({"sine", Quantity::mu, types[3], {"1.5", "0.25"}, 0});  // 60 digits after 30, one γ
  calls.push_back({"sine", Quantity::mu, types[2], {"1.5", "0.25"}, 1});   // a budget too small to solve
  calls.push_back({"sine", Quantity::mu, types[2], {"1.5", "0.25"}, 0});

  const auto run = [](const Call& c) {
    BatchOptions options;
    options.threads = 1;
    options.solver.max_root_iterations = c.budget;
    try {
      return evaluate(parse_wave(c.wave), c.q, {c.p}, c.precision, options).front();
    } catch (const std::exception& e) {
      return std::string("error: ") + e.what();
    }
  };
  std::size_t errors = 0;
  for (const Call& c : calls) {
    const std::string warm = run(c);
    std::string fresh;
    std::thread([&] { fresh = run(c); }).join();
    if (c.budget == 1) {
      EXPECT_EQ(warm.rfind("error: ", 0), 0u) << warm;
    }
    EXPECT_EQ(warm, fresh) << c.wave << " beta " << c.p.beta << " gamma " << c.p.gamma << " budget " << c.budget;
    errors += c.budget == 0 && warm.rfind("error: ", 0) == 0;
  }
  EXPECT_EQ(errors, 0u);
}

// The generator's, progress's and sink's exceptions: the first two count as their point's error,
// the sink's stops the stream; every way out joins the workers (the test would hang otherwise).
TEST(evaluate_stream, CallbackExceptions) {
  const WaveSpec sine = parse_wave("sine");
  const std::vector<Point> points = grid(3000, 5, false);
  const Precision p{NumberType::float64, 17};
  for (const unsigned threads : {1u, 2u}) {
    BatchOptions o;
    o.threads = threads;
    std::size_t rows = 0;
    EXPECT_THROW(evaluate_stream(
                     sine, Quantity::mu, points.size(),
                     [&](std::size_t i) {
                       if (i == 1234) throw std::runtime_error("generator");
                       return points[i];
                     },
                     p, o, [&](std::size_t, const StreamValue&) { ++rows; }),
                 std::runtime_error);
    EXPECT_EQ(rows, 1234u);

    rows = 0;
    EXPECT_THROW(evaluate_stream(
                     sine, Quantity::mu, points.size(), [&](std::size_t i) { return points[i]; }, p, o,
                     [&](std::size_t i, const StreamValue&) {
                       if (i == 100) throw std::logic_error("sink");
                       ++rows;
                     }),
                 std::logic_error);
    EXPECT_EQ(rows, 100u);

    BatchOptions cancel = o;
    cancel.progress = [](std::size_t d) {
      if (d == 2000) throw std::runtime_error("cancelled");
    };
    rows = 0;
    EXPECT_THROW(evaluate_stream(
                     sine, Quantity::mu, points.size(), [&](std::size_t i) { return points[i]; }, p, cancel,
                     [&](std::size_t, const StreamValue&) { ++rows; }),
                 std::runtime_error);
    EXPECT_LE(rows, 2000u + threads);  // the 2000th point done: index 1999 or, with workers, a little later
  }
}

}  // namespace
