// Interval (core/certified/interval.hpp) tested adversarially, as the certificates' foundation:
// every function's enclosure over [lo, hi] must hold the point function's value at lo, at hi, at
// interior points and at the extrema inside, each bracketed by MPFR's roundings down and up at
// four times the bits (an enclosure one ulp narrower than the truth fails: the truth then lies
// outside it, and so does one of its two brackets). The arguments are drawn where a one-line slip
// in the layer would show:
//  - intervals of two to four adjacent numbers: the midpoint is a rounding tie, so the radius
//    about the rounded midpoint differs from side to side by an ulp;
//  - intervals about the branch points of argument reduction (multiples of π/2, small and large)
//    and about the zeros of sin and cos (the result's binades shrink to nothing);
//  - intervals about 1 for log, about 0 and ln 2 for exp, about powers of 4 for sqrt and about 0
//    and ±1 for asin and acos, where the result crosses a binade or its slope blows up;
//  - random intervals over sixty binades, narrow (one MPFR call at the midpoint, then widened) and
//    wide (MPFI's two calls).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/core/certified/interval.hpp"

namespace {

using vibrofric::Interval;
using vibrofric::mpfr;

constexpr mpfr_prec_t kBits = 64;
constexpr mpfr_prec_t kReference = 4 * kBits;

// A number at kBits: an mpfr of exactly that precision (Interval::hull takes its ends exactly).
struct Number {
  Number() { mpfr_init2(v, kBits); }
  explicit Number(double x) : Number() { mpfr_set_d(v, x, MPFR_RNDN); }
  Number(const Number& o) : Number() { mpfr_set(v, o.v, MPFR_RNDN); }
  Number& operator=(const Number& o) {
    mpfr_set(v, o.v, MPFR_RNDN);
    return *this;
  }
  ~Number() { mpfr_clear(v); }
  mpfr value() const {
    mpfr x;
    mpfr_set_prec(x.backend().data(), kBits);
    mpfr_set(x.backend().data(), v, MPFR_RNDN);
    return x;
  }
  Number stepped(int ulps) const {
    Number n(*this);
    for (int i = 0; i < ulps; ++i) mpfr_nextabove(n.v);
    for (int i = 0; i > ulps; --i) mpfr_nextbelow(n.v);
    return n;
  }
  std::string text() const {
    char* s = nullptr;
    mpfr_asprintf(&s, "%.25Rg", v);
    std::string out(s);
    mpfr_free_str(s);
    return out;
  }
  mpfr_t v;
};

struct Argument {
  Number lo, hi;
  std::string how;  // for the failure message
};

Interval enclose(const Argument& a) { return Interval::hull(a.lo.value(), a.hi.value(), kBits); }

using PointFunction = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);

// The points of [lo, hi] whose values an enclosure must hold: the ends, seven interior points
// (exact at kReference: the ends have kBits and lie within a few binades of each other, or the
// point is clamped into [lo, hi]) and, for sin and cos, every multiple of π/2 inside, rounded to
// kReference (its value is ±1 or 0 to 2^−200).
void each_point(const Argument& a, bool extrema, const std::function<void(mpfr_srcptr)>& at) {
  mpfr_t x, w;
  mpfr_inits2(kReference, x, w, static_cast<mpfr_ptr>(nullptr));
  mpfr_set(x, a.lo.v, MPFR_RNDN);
  at(x);
  mpfr_set(x, a.hi.v, MPFR_RNDN);
  at(x);
  mpfr_sub(w, a.hi.v, a.lo.v, MPFR_RNDN);
  for (int k = 1; k < 8; ++k) {
    mpfr_mul_ui(x, w, static_cast<unsigned long>(k), MPFR_RNDN);
    mpfr_div_2ui(x, x, 3, MPFR_RNDN);
    mpfr_add(x, x, a.lo.v, MPFR_RNDN);
    if (mpfr_cmp(x, a.lo.v) < 0) mpfr_set(x, a.lo.v, MPFR_RNDN);
    if (mpfr_cmp(x, a.hi.v) > 0) mpfr_set(x, a.hi.v, MPFR_RNDN);
    at(x);
  }
  if (extrema) {
    mpfr_t half_pi;
    mpfr_init2(half_pi, kReference);
    mpfr_const_pi(half_pi, MPFR_RNDN);
    mpfr_div_2ui(half_pi, half_pi, 1, MPFR_RNDN);
    const double first = std::ceil(mpfr_get_d(a.lo.v, MPFR_RNDD) / (M_PI / 2)) - 1;
    const double last = std::floor(mpfr_get_d(a.hi.v, MPFR_RNDU) / (M_PI / 2)) + 1;
    for (double m = first; m <= last && last - first < 64; ++m) {
      mpfr_mul_d(x, half_pi, m, MPFR_RNDN);
      if (mpfr_cmp(x, a.lo.v) >= 0 && mpfr_cmp(x, a.hi.v) <= 0) at(x);
    }
    mpfr_clear(half_pi);
  }
  mpfr_clears(x, w, static_cast<mpfr_ptr>(nullptr));
}

// out holds f(x): both of MPFR's roundings of f(x) at kReference lie inside.
::testing::AssertionResult holds(const Interval& out, PointFunction f, mpfr_srcptr x) {
  mpfr_t down, up;
  mpfr_inits2(kReference, down, up, static_cast<mpfr_ptr>(nullptr));
  f(down, x, MPFR_RNDD);
  f(up, x, MPFR_RNDU);
  const bool inside = mpfi_is_inside_fr(down, out.data()) > 0 && mpfi_is_inside_fr(up, out.data()) > 0;
  ::testing::AssertionResult r = inside ? ::testing::AssertionSuccess() : ::testing::AssertionFailure();
  if (!inside) {
    char* s = nullptr;
    mpfr_asprintf(&s, "f(%.30Rg) in [%.30Rg, %.30Rg], enclosure [%.30Rg, %.30Rg]", x, down, up, &out.data()->left,
                  &out.data()->right);
    r << s;
    mpfr_free_str(s);
  }
  mpfr_clears(down, up, static_cast<mpfr_ptr>(nullptr));
  return r;
}

struct Unary {
  const char* name;
  PointFunction point;
  std::function<Interval(const Interval&)> f;
  bool extrema;  // sin, cos: ±1 inside
};

const std::vector<Unary>& trigonometric() {
  static const std::vector<Unary> fs = {
      {"sin", mpfr_sin, [](const Interval& x) { return sin(x); }, true},
      {"cos", mpfr_cos, [](const Interval& x) { return cos(x); }, true},
      {"sin of sin_cos", mpfr_sin, [](const Interval& x) { return sin_cos(x).first; }, true},
      {"cos of sin_cos", mpfr_cos, [](const Interval& x) { return sin_cos(x).second; }, true},
      {"sqr", mpfr_sqr, [](const Interval& x) { return sqr(x); }, false},
      {"abs", mpfr_abs, [](const Interval& x) { return abs(x); }, false},
      {"negation", mpfr_neg, [](const Interval& x) { return -x; }, false},
  };
  return fs;
}

void expect_sound(const Unary& u, const Argument& a) {
  const Interval out = u.f(enclose(a));
  each_point(a, u.extrema, [&](mpfr_srcptr x) { EXPECT_TRUE(holds(out, u.point, x)) << u.name << " over " << a.how; });
  // sqr and abs reach 0 where the argument holds it.
  if (!u.extrema && mpfr_sgn(a.lo.v) < 0 && mpfr_sgn(a.hi.v) > 0) {
    mpfr_t zero;
    mpfr_init2(zero, kReference);
    mpfr_set_zero(zero, 1);
    EXPECT_TRUE(holds(out, u.point, zero)) << u.name << " over " << a.how;
    mpfr_clear(zero);
  }
}

// [c + below ulps, c + above ulps] for every pair of steps in {−2 … 2} with below ≤ above: among
// them the intervals of two to five adjacent numbers, whose midpoints are ties.
std::vector<Argument> about(const Number& c, const std::string& what) {
  std::vector<Argument> out;
  for (int below = -2; below <= 2; ++below)
    for (int above = below; above <= 2; ++above) {
      std::ostringstream how;
      how << "[" << what << " " << std::showpos << below << " ulp, " << what << " " << above << " ulp] (" << c.text()
          << ")";
      out.push_back({c.stepped(below), c.stepped(above), how.str()});
    }
  return out;
}

// [c − 2^−k, c + 2^−k] and its halves for the widths a narrow enclosure (radius ≤ 2^−32) and a
// wide one see.
std::vector<Argument> widths(const Number& c, const std::string& what) {
  std::vector<Argument> out;
  for (const int k : {2, 8, 20, 31, 33, 40, 60}) {
    Number d;
    mpfr_set_ui_2exp(d.v, 1, -k, MPFR_RNDN);
    Number lo, hi;
    mpfr_sub(lo.v, c.v, d.v, MPFR_RNDD);
    mpfr_add(hi.v, c.v, d.v, MPFR_RNDU);
    const std::string how = what + " ± 2^-" + std::to_string(k) + " (" + c.text() + ")";
    out.push_back({lo, hi, how});
    out.push_back({lo, c, how + ", lower half"});
    out.push_back({c, hi, how + ", upper half"});
  }
  return out;
}

std::vector<Argument> about_and_widths(const Number& c, const std::string& what) {
  std::vector<Argument> out = about(c, what), more = widths(c, what);
  out.insert(out.end(), more.begin(), more.end());
  return out;
}

// m·π/2 rounded to kBits: the branch points of sin's and cos's argument reduction, and their zeros.
Number half_pi_times(double m) {
  mpfr_t p;
  mpfr_init2(p, kReference);
  mpfr_const_pi(p, MPFR_RNDN);
  mpfr_mul_d(p, p, m / 2, MPFR_RNDN);
  Number n;
  mpfr_set(n.v, p, MPFR_RNDN);
  mpfr_clear(p);
  return n;
}

// Random intervals: a centre of random sign and 64 random bits over 2^−40 … 2^20 (2^−40 … 2^9 for
// exp; in (−1, 1) for asin and acos; positive for sqrt and log) and a width from one ulp to the
// centre's size.
std::vector<Argument> random_arguments(int count, int min_exponent, int max_exponent, bool positive, bool unit,
                                       std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> exponent(min_exponent, max_exponent), shift(0, 70), ulps(1, 4);
  std::vector<Argument> out;
  for (int i = 0; i < count; ++i) {
    Number c;
    mpfr_set_ui(c.v, static_cast<unsigned long>(rng() | 1ULL << 63), MPFR_RNDN);  // 64 random bits, top set
    mpfr_mul_2si(c.v, c.v, unit ? -64 - (exponent(rng) - min_exponent) % 30 : exponent(rng) - 64, MPFR_RNDN);
    if (!positive && (rng() & 1)) mpfr_neg(c.v, c.v, MPFR_RNDN);
    Number lo(c), hi(c);
    const int s = shift(rng);
    if (s >= 66) {  // adjacent numbers
      hi = c.stepped(ulps(rng));
    } else {
      Number d;
      mpfr_mul_2si(d.v, c.v, -s, MPFR_RNDN);
      mpfr_abs(d.v, d.v, MPFR_RNDN);
      mpfr_sub(lo.v, c.v, d.v, MPFR_RNDD);
      mpfr_add(hi.v, c.v, d.v, MPFR_RNDU);
      if (positive && mpfr_sgn(lo.v) <= 0) lo = c;
      if (unit) {
        if (mpfr_cmp_si(lo.v, -1) < 0) mpfr_set_si(lo.v, -1, MPFR_RNDN);
        if (mpfr_cmp_si(hi.v, 1) > 0) mpfr_set_si(hi.v, 1, MPFR_RNDN);
      }
    }
    out.push_back({lo, hi, "random interval " + std::to_string(i) + " [" + lo.text() + ", " + hi.text() + "]"});
  }
  return out;
}

TEST(IntervalSoundness, SinCosSqrAbsAboutBranchPointsZerosAndTies) {
  std::vector<Argument> args;
  for (const double m : {0.0, 1.0, 2.0, 3.0, 4.0, -1.0, -2.0, 7.0, 1000.0, 1001.0, 123456789.0, 1099511627776.0})
    for (const Argument& a : about_and_widths(half_pi_times(m), std::to_string(static_cast<long long>(m)) + " pi/2"))
      args.push_back(a);
  for (const Argument& a : random_arguments(400, -40, 20, false, false, 20261206)) args.push_back(a);
  for (const Unary& u : trigonometric())
    for (const Argument& a : args) expect_sound(u, a);
}

TEST(IntervalSoundness, ExpLogSqrtAboutBinadeEdgesAndTies) {
  const std::vector<Unary> monotone = {
      {"exp", mpfr_exp, [](const Interval& x) { return exp(x); }, false},
      {"log", mpfr_log, [](const Interval& x) { return log(x); }, false},
      {"sqrt", mpfr_sqrt, [](const Interval& x) { return sqrt(x); }, false},
  };
  std::vector<Argument> exp_args, positive_args;
  Number ln2;
  mpfr_const_log2(ln2.v, MPFR_RNDN);
  for (const Number& c : {Number(0.0), Number(1e-30), Number(-1e-30), ln2, Number(700.0), Number(-700.0)})
    for (const Argument& a : about_and_widths(c, "c")) exp_args.push_back(a);
  for (const Argument& a : random_arguments(400, -40, 9, false, false, 11)) exp_args.push_back(a);
  for (const double c : {1.0, 4.0, 0.25, 2.0, 1e-20, 1e20})
    for (const Argument& a : about_and_widths(Number(c), "c"))
      if (mpfr_sgn(a.lo.v) > 0) positive_args.push_back(a);
  for (const Argument& a : random_arguments(400, -40, 20, true, false, 12)) positive_args.push_back(a);
  for (const Argument& a : exp_args) expect_sound(monotone[0], a);
  for (const Argument& a : positive_args) {
    expect_sound(monotone[1], a);
    expect_sound(monotone[2], a);
  }
}

TEST(IntervalSoundness, AsinAcosAboutTheirEndsZeroAndTies) {
  const std::vector<Unary> arcs = {
      {"asin", mpfr_asin, [](const Interval& x) { return asin(x); }, false},
      {"acos", mpfr_acos, [](const Interval& x) { return acos(x); }, false},
  };
  std::vector<Argument> args;
  for (const double c : {0.0, 0.5, -0.5, 0.999, -0.999, 1e-25})
    for (const Argument& a : about_and_widths(Number(c), "c"))
      if (mpfr_cmp_si(a.lo.v, -1) >= 0 && mpfr_cmp_si(a.hi.v, 1) <= 0) args.push_back(a);
  for (const double end : {1.0, -1.0})
    for (const Argument& a : about_and_widths(Number(end), "c"))
      if (mpfr_cmp_si(a.lo.v, -1) >= 0 && mpfr_cmp_si(a.hi.v, 1) <= 0) args.push_back(a);
  for (const Argument& a : random_arguments(400, -40, 20, false, true, 13)) args.push_back(a);
  for (const Unary& u : arcs)
    for (const Argument& a : args) expect_sound(u, a);
}

// The four operations over boxes: the exact result at every corner and at interior points (the
// extremes of a·b and a/b lie at corners) inside, rounded down and up at kReference.
TEST(IntervalSoundness, FourOperationsOverBoxesWithTiedMidpoints) {
  std::vector<Argument> args = random_arguments(150, -30, 30, false, false, 14);
  for (const double c : {1.0, -1.0, 3.0, 1e-10})
    for (const Argument& a : about(Number(c), "c")) args.push_back(a);
  using Op = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);
  struct Binary {
    const char* name;
    Op point;
    Interval (*f)(const Interval&, const Interval&);
  };
  const Binary ops[] = {{"+", mpfr_add, [](const Interval& a, const Interval& b) { return a + b; }},
                        {"-", mpfr_sub, [](const Interval& a, const Interval& b) { return a - b; }},
                        {"*", mpfr_mul, [](const Interval& a, const Interval& b) { return a * b; }},
                        {"/", mpfr_div, [](const Interval& a, const Interval& b) { return a / b; }}};
  std::mt19937_64 rng(15);
  std::uniform_int_distribution<std::size_t> pick(0, args.size() - 1);
  mpfr_t x, y, down, up;
  mpfr_inits2(kReference, x, y, down, up, static_cast<mpfr_ptr>(nullptr));
  for (int k = 0; k < 1500; ++k) {
    const Argument &a = args[pick(rng)], &b = args[pick(rng)];
    for (const Binary& op : ops) {
      if (op.point == mpfr_div && mpfr_sgn(b.lo.v) <= 0 && mpfr_sgn(b.hi.v) >= 0) continue;
      const Interval out = op.f(enclose(a), enclose(b));
      each_point(a, false, [&](mpfr_srcptr xa) {
        mpfr_set(x, xa, MPFR_RNDN);
        for (const mpfr_srcptr yb : {static_cast<mpfr_srcptr>(b.lo.v), static_cast<mpfr_srcptr>(b.hi.v)}) {
          mpfr_set(y, yb, MPFR_RNDN);
          op.point(down, x, y, MPFR_RNDD);
          op.point(up, x, y, MPFR_RNDU);
          EXPECT_TRUE(mpfi_is_inside_fr(down, out.data()) > 0 && mpfi_is_inside_fr(up, out.data()) > 0)
              << a.how << " " << op.name << " " << b.how;
        }
      });
    }
  }
  mpfr_clears(x, y, down, up, static_cast<mpfr_ptr>(nullptr));
}

// The fused c ± a·b and c + a/d of the Taylor series' convolutions (their own sign cases, not
// MPFI's): every corner value c_k ± a_i b_j, bracketed at four times the bits, inside the result,
// over boxes of every sign pattern (positive, negative, straddling 0, ends at 0) with tied midpoints.
TEST(IntervalSoundness, FusedProductsOverEverySignPattern) {
  std::vector<Argument> base = random_arguments(60, -20, 20, false, false, 16);
  for (const double c : {1.0, 3.0, 1e-10})
    for (const Argument& a : about(Number(c), "c")) base.push_back(a);
  std::vector<Argument> args;
  for (std::size_t i = 0; i < base.size(); ++i) {
    const Argument& a = base[i];
    const Argument& other = base[(i * 7 + 3) % base.size()];  // another size: an asymmetric straddle
    Number nlo, nhi, nother;
    mpfr_neg(nlo.v, a.hi.v, MPFR_RNDN);
    mpfr_neg(nhi.v, a.lo.v, MPFR_RNDN);
    mpfr_neg(nother.v, other.hi.v, MPFR_RNDN);
    args.push_back(a);                                                    // positive
    args.push_back({nlo, nhi, "-(" + a.how + ")"});                       // negative
    args.push_back({nlo, a.hi, "straddling " + a.how});                   // across 0, symmetric
    args.push_back({nother, a.hi, "straddling " + other.how + " to " + a.how});  // across 0, not
    args.push_back({Number(0.0), a.hi, "from 0 " + a.how});
    args.push_back({nlo, Number(0.0), "to 0 " + a.how});
  }
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<std::size_t> pick(0, args.size() - 1);
  mpfr_t p, q;
  mpfr_inits2(kReference, p, q, static_cast<mpfr_ptr>(nullptr));
  const auto holds = [&](const Interval& out, mpfr_srcptr c, mpfr_srcptr x, mpfr_srcptr y, int sign, const std::string& how) {
    for (const mpfr_rnd_t r : {MPFR_RNDD, MPFR_RNDU}) {
      mpfr_mul(p, x, y, r == MPFR_RNDD ? (sign > 0 ? MPFR_RNDD : MPFR_RNDU) : (sign > 0 ? MPFR_RNDU : MPFR_RNDD));
      (sign > 0 ? mpfr_add : mpfr_sub)(q, c, p, r);
      EXPECT_GT(mpfi_is_inside_fr(q, out.data()), 0) << how;
    }
  };
  for (int k = 0; k < 3000; ++k) {
    const Argument &a = args[pick(rng)], &b = args[pick(rng)], &c = args[pick(rng)];
    const std::string how = c.how + " ± (" + a.how + ")(" + b.how + ")";
    Interval plus = enclose(c), minus = enclose(c);
    plus.add_mul(enclose(a), enclose(b));
    minus.sub_mul(enclose(a), enclose(b));
    for (const mpfr_srcptr cc : {static_cast<mpfr_srcptr>(c.lo.v), static_cast<mpfr_srcptr>(c.hi.v)})
      for (const mpfr_srcptr x : {static_cast<mpfr_srcptr>(a.lo.v), static_cast<mpfr_srcptr>(a.hi.v)})
        for (const mpfr_srcptr y : {static_cast<mpfr_srcptr>(b.lo.v), static_cast<mpfr_srcptr>(b.hi.v)}) {
          holds(plus, cc, x, y, 1, "+ " + how);
          holds(minus, cc, x, y, -1, "- " + how);
        }
    const unsigned long d = 1 + static_cast<unsigned long>(k % 40);
    Interval quotient = enclose(c);
    quotient.add_quotient(enclose(a), d);
    for (const mpfr_srcptr cc : {static_cast<mpfr_srcptr>(c.lo.v), static_cast<mpfr_srcptr>(c.hi.v)})
      for (const mpfr_srcptr x : {static_cast<mpfr_srcptr>(a.lo.v), static_cast<mpfr_srcptr>(a.hi.v)})
        for (const mpfr_rnd_t r : {MPFR_RNDD, MPFR_RNDU}) {
          mpfr_div_ui(p, x, d, r);
          mpfr_add(q, cc, p, r);
          EXPECT_GT(mpfi_is_inside_fr(q, quotient.data()), 0) << c.how << " + (" << a.how << ")/" << d;
        }
  }
  mpfr_clears(p, q, static_cast<mpfr_ptr>(nullptr));
}

// π and the bisection's halves: π inside its enclosure at kReference; each half within the whole,
// the halves meeting, and together the whole.
TEST(IntervalSoundness, PiAndBisection) {
  mpfr_t p, q;
  mpfr_inits2(kReference, p, q, static_cast<mpfr_ptr>(nullptr));
  mpfr_const_pi(p, MPFR_RNDD);
  mpfr_const_pi(q, MPFR_RNDU);
  const Interval pi = Interval::pi(kBits);
  EXPECT_TRUE(mpfi_is_inside_fr(p, pi.data()) > 0 && mpfi_is_inside_fr(q, pi.data()) > 0);
  mpfr_clears(p, q, static_cast<mpfr_ptr>(nullptr));
  for (const Argument& a : random_arguments(200, -40, 20, false, false, 16)) {
    const Interval whole = enclose(a);
    const auto [left, right] = whole.bisect();
    EXPECT_TRUE(whole.contains(left) && whole.contains(right)) << a.how;
    EXPECT_EQ(left.lower(), whole.lower()) << a.how;
    EXPECT_EQ(right.upper(), whole.upper()) << a.how;
    EXPECT_EQ(left.upper(), right.lower()) << a.how;
  }
}

}  // namespace
