// Certified enclosures of the sine, power:p and Fourier series (enclosure.hpp).
#include "vibrofric/core/certified/enclosure.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "newton.hpp"

namespace vibrofric::certified {

namespace {

Interval of(const exact::Rational& x, mpfr_prec_t bits) { return Interval::rational(x.backend().data(), bits); }

// The certain sign of x, or Undecided naming the comparison.
Sign decide(const Interval& x, const std::string& what) {
  const Sign s = x.sign();
  if (s == Sign::undecided) throw Undecided(std::string("undecided at this precision: ") + what);
  return s;
}

// A point strictly inside (lo, hi) where there is one at bits + 1 (else lo or hi: the caller's
// iteration cap then asks for more bits).
mpfr midpoint(const mpfr& lo, const mpfr& hi, mpfr_prec_t bits) {
  mpfr m;
  mpfr_set_prec(m.backend().data(), bits + 1);
  mpfr_add(m.backend().data(), lo.backend().data(), hi.backend().data(), MPFR_RNDN);
  mpfr_div_2ui(m.backend().data(), m.backend().data(), 1, MPFR_RNDN);
  return m;
}

// A thin interval at the point x.
Interval point(const mpfr& x, mpfr_prec_t bits) { return Interval::exact(x, bits); }

// The root of F between the thin points lo < hi, where F is certainly positive at lo and negative
// at hi (else SolverError: no sign change, or Undecided: a sign this precision leaves open):
// bisection until F' < 0 certainly on the bracket and interval Newton contracts there, so the
// root exists and is unique for every value of the parameters F encloses.
template <class F, class DF>
Interval bracketed_root(F f, DF df, mpfr lo, mpfr hi, mpfr_prec_t bits, const std::string& what) {
  if (decide(f(point(lo, bits)), what + ": the sign at its bracket's start") != Sign::positive ||
      decide(f(point(hi, bits)), what + ": the sign at its bracket's end") != Sign::negative)
    throw SolverError(what + " has no sign change in its bracket");
  for (int k = 0;; ++k) {
    if (k > static_cast<int>(bits) + 64) throw Undecided(what + ": its bracket does not separate from a turning point");
    if (df(Interval::hull(lo, hi, bits)).sign() == Sign::negative) {
      // Newton contracts once f' is bounded away from 0 on the bracket (near a turning point at
      // its end, f' < 0 can be certain and still as small as the rounding): else bisect on.
      Interval X = newton(Interval::hull(lo, hi, bits), f, df, bits, what);
      if (X.width() * 4 < hi - lo) return X;
    }
    // The midpoint, or beside it where the root sits on it (a dyadic root of a symmetric wave).
    mpfr mid = midpoint(lo, hi, bits);
    Sign at = f(point(mid, bits)).sign();
    for (int side = -1; side <= 1 && at != Sign::positive && at != Sign::negative; side += 2) {
      mid = midpoint(mid, side < 0 ? lo : hi, bits);
      at = f(point(mid, bits)).sign();
    }
    if (at == Sign::undecided || at == Sign::zero) throw Undecided(what + ": the sign inside its bracket");
    if (at == Sign::positive)
      lo = mid;
    else
      hi = mid;
  }
}

// The root of F in (lo, hi), where F' < 0 (so there is at most one), from a seed x0 (found in
// long double; its accuracy is not relied on): the first box X of half-width 2^−56, 2^−46,
// 2^−36 or 2^−26 about it that lies inside (lo, hi), has F' < 0 certainly on it and is mapped
// into itself by interval Newton (then X holds exactly one root, inside N(X)) is narrowed by
// Newton, and taken if that reaches within 2^20 ulps. Else nothing: the caller brackets from
// scratch. Most points take two interval steps instead of a bisection; the wider boxes serve
// seeds that lose digits where F' is small (a stick phase that barely exists, β just below β_c).
template <class F, class DF>
std::optional<Interval> seeded_root(F f, DF df, long double x0, const mpfr& lo, const mpfr& hi, mpfr_prec_t bits,
                                    const std::string& what) {
  if (!std::isfinite(x0)) return std::nullopt;
  for (const long e : {-56L, -46L, -36L, -26L}) {
    mpfr l, u;
    mpfr_set_prec(l.backend().data(), bits);
    mpfr_set_prec(u.backend().data(), bits);
    mpfr_set_ld(l.backend().data(), x0, MPFR_RNDD);
    mpfr_set_ld(u.backend().data(), x0, MPFR_RNDU);
    mpfr_sub_d(l.backend().data(), l.backend().data(), std::ldexp(1.0, e), MPFR_RNDD);
    mpfr_add_d(u.backend().data(), u.backend().data(), std::ldexp(1.0, e), MPFR_RNDU);
    if (!(l > lo && u < hi)) continue;
    const Interval X = Interval::hull(l, u, bits);
    const Interval slope = df(X);
    if (slope.sign() != Sign::negative) continue;
    const Interval m = point(X.midpoint(), bits);
    const Interval N = m - f(m) / slope;
    if (!N.bounded() || !X.contains(N)) continue;
    // Newton stalls short of the rounding where F' varies much across the box (F' near 0 at
    // one end, a stick phase that barely exists): then the bracket decides, as without a seed.
    Interval root = newton(N, f, df, bits, what);
    if (within_ulps(root, bits, 20)) return root;
    return std::nullopt;
  }
  return std::nullopt;
}

// The root of a decreasing f in (a, b) in long double: Newton, kept inside a bracket that
// shrinks by the sign of f (bisection where a step leaves it). Only a seed for seeded_root.
template <class F, class DF>
long double seed_root(F f, DF df, long double a, long double b) {
  long double x = (a + b) / 2;
  for (int k = 0; k < 100 && a < b; ++k) {
    const long double v = f(x);
    if (v > 0)
      a = x;
    else if (v < 0)
      b = x;
    else
      break;
    long double next = x - v / df(x);
    if (!(next > a && next < b)) next = a + (b - a) / 2;
    if (next == x) break;
    x = next;
  }
  return x;
}

// The rising flank r(t), t ∈ [−1/4, 1/4], of a wave with the sine's symmetries (enclosure.hpp),
// and from it the wave over one period (w, dw, W). The flank's arguments are intervals inside
// [−1/4, 1/4]; an interval may straddle 0.
class Flank {
 public:
  explicit Flank(mpfr_prec_t bits)
      : bits_(bits),
        flank_(Interval::hull(mpfr(-0.25), mpfr(0.25), bits)),
        second_(Interval::hull(mpfr(0.25), mpfr(0.75), bits)),
        third_(Interval::hull(mpfr(0.75), mpfr(1.25), bits)),
        half_(at(0.5)),
        whole_(at(1)) {}
  virtual ~Flank() = default;
  virtual Interval r(const Interval& t) const = 0;
  virtual Interval dr(const Interval& t) const = 0;
  virtual Interval R(const Interval& t) const = 0;       // ∫₀ᵗ r, even
  virtual Interval inverse(const Interval& y) const = 0;  // r(t) = y, −1 < y < 1
  virtual Interval top(const Interval& b) const = 0;      // t ∈ (0, 1/4): r'(t) = b < r'(0)
  virtual Interval steepest() const = 0;                  // r'(0)
  // r and r' in long double, only to seed the stick end's verified Newton box (enclose).
  virtual long double r_seed(long double t) const = 0;
  virtual long double dr_seed(long double t) const = 0;
  mpfr_prec_t bits() const { return bits_; }
  // Values at the points the enclosure knows more about: r' and R at t where r(t) = y (first
  // contact), r and R at t where r'(t) = b, t > 0 (the turning point), and R(1/4). By default
  // from t itself; the sine's are algebraic (a transcendental call fewer each, and tighter).
  virtual Interval dr_where_r(const Interval& t, const Interval&) const { return dr(t); }
  virtual Interval R_where_r(const Interval& t, const Interval&) const { return R(t); }
  virtual Interval r_where_dr(const Interval& t, const Interval&) const { return r(t); }
  virtual Interval R_where_dr(const Interval& t, const Interval&) const { return R(t); }
  virtual Interval R_quarter() const { return R(at(0.25)); }
  // The wave and its slope over one period from its flank, in long double (seeds only).
  long double w_seed(long double x) const {
    return x <= 0.25L ? r_seed(x) : x <= 0.75L ? r_seed(0.5L - x) : r_seed(x - 1);
  }
  long double dw_seed(long double x) const {
    return x <= 0.25L ? dr_seed(x) : x <= 0.75L ? -dr_seed(0.5L - x) : dr_seed(x - 1);
  }
  // The wave over one period from φ = −1/4, from its flank: r on [−1/4, 1/4], r(1/2 − φ) on
  // [1/4, 3/4], r(φ − 1) on [3/4, 5/4]; an interval is split at 1/4 and 3/4 and the parts hulled.
  virtual Interval w(const Interval& x) const {
    return over(x, [&](const Interval& t) { return r(t); }, [&](const Interval& t) { return r(t); },
                [&](const Interval& t) { return r(t); });
  }
  virtual Interval dw(const Interval& x) const {
    return over(x, [&](const Interval& t) { return dr(t); }, [&](const Interval& t) { return -dr(t); },
                [&](const Interval& t) { return dr(t); });
  }
  // A continuous antiderivative of w: R, then 2R(1/4) − R(1/2 − φ), then R(φ − 1).
  virtual Interval W(const Interval& x) const {
    const Interval quarter = R_quarter();
    return over(x, [&](const Interval& t) { return R(t); }, [&](const Interval& t) { return quarter * 2 - R(t); },
                [&](const Interval& t) { return R(t); });
  }

 protected:
  mpfr_prec_t bits_;
  Interval flank_, second_, third_, half_, whole_;  // [−1/4, 1/4], [1/4, 3/4], [3/4, 5/4]; 1/2, 1
  Interval at(double v) const { return Interval::exact(mpfr(v), bits_); }
  // first(t) on x ∩ [−1/4, 1/4] with t = φ, second on x ∩ [1/4, 3/4] with t = 1/2 − φ, third on
  // x ∩ [3/4, 5/4] with t = φ − 1, each t clipped to [−1/4, 1/4] (beyond it only by rounding).
  template <class A, class B, class C>
  Interval over(const Interval& x, A first, B second, C third) const {
    std::optional<Interval> out;
    auto add = [&](const Interval& piece, const Interval* shift, bool reflect, auto f) {
      // (most arguments lie in one piece: the others are passed over by their ends, no copies)
      if (mpfr_cmp(&x.data()->right, &piece.data()->left) < 0 || mpfr_cmp(&x.data()->left, &piece.data()->right) > 0) return;
      const auto part = intersection(x, piece);
      if (!part) return;
      const auto t = !shift ? intersection(*part, flank_) : intersection(reflect ? *shift - *part : *part - *shift, flank_);
      if (!t) return;
      Interval v = f(*t);
      out = out ? hull(std::move(*out), v) : std::move(v);
    };
    add(flank_, nullptr, false, first);
    add(second_, &half_, true, second);
    add(third_, &whole_, false, third);
    if (!out) throw SolverError("enclosure: a phase outside [-1/4, 5/4] (a bug)");
    return *out;
  }
};

class SineFlank final : public Flank {
 public:
  explicit SineFlank(mpfr_prec_t bits) : Flank(bits), two_pi_(Interval::pi(bits) * 2) {}
  Interval r(const Interval& t) const override { return sin(two_pi_ * t); }
  Interval dr(const Interval& t) const override { return two_pi_ * cos(two_pi_ * t); }
  Interval R(const Interval& t) const override { return (Interval::integer(1, bits_) - cos(two_pi_ * t)) / two_pi_; }
  Interval inverse(const Interval& y) const override { return asin(y) / two_pi_; }
  Interval top(const Interval& b) const override { return acos(b / two_pi_) / two_pi_; }
  Interval steepest() const override { return two_pi_; }
  // sin 2πφ on the whole period: the three pieces of the flank's are this one function.
  Interval w(const Interval& x) const override { return r(x); }
  Interval dw(const Interval& x) const override { return dr(x); }
  Interval W(const Interval& x) const override { return R(x); }
  // cos 2πt = √(1 − y²) where sin 2πt = y, |t| < 1/4; sin 2πt = √(1 − c²) and R = (1 − c)/2π
  // where cos 2πt = c = b/2π, 0 < t < 1/4; R(1/4) = 1/2π.
  Interval dr_where_r(const Interval& t, const Interval& y) const override {
    const std::optional<Interval> c = root_of_one_minus_square(y);
    return c ? two_pi_ * *c : dr(t);
  }
  Interval R_where_r(const Interval& t, const Interval& y) const override {
    const std::optional<Interval> c = root_of_one_minus_square(y);
    return c ? (Interval::integer(1, bits_) - *c) / two_pi_ : R(t);
  }
  Interval r_where_dr(const Interval& t, const Interval& b) const override {
    const std::optional<Interval> s = root_of_one_minus_square(b / two_pi_);
    return s ? *s : r(t);
  }
  Interval R_where_dr(const Interval&, const Interval& b) const override {
    return (Interval::integer(1, bits_) - b / two_pi_) / two_pi_;
  }
  Interval R_quarter() const override { return Interval::integer(1, bits_) / two_pi_; }
  // Arguments kept within ±π/4 (sinl and cosl reduce larger ones the slow way).
  long double r_seed(long double t) const override {
    if (std::fabs(t) <= 0.125L) return std::sin(two_pi_seed * t);
    const long double c = std::cos(two_pi_seed * (0.25L - std::fabs(t)));
    return t < 0 ? -c : c;
  }
  long double dr_seed(long double t) const override {
    if (std::fabs(t) <= 0.125L) return two_pi_seed * std::cos(two_pi_seed * t);
    return two_pi_seed * std::sin(two_pi_seed * (0.25L - std::fabs(t)));
  }

 private:
  static constexpr long double two_pi_seed = 6.283185307179586476925286766559L;
  // √(1 − y²) where 1 − y² > 0 certainly; else none (the caller takes the transcendental way).
  std::optional<Interval> root_of_one_minus_square(const Interval& y) const {
    Interval d = Interval::integer(1, bits_) - sqr(y);
    if (d.sign() != Sign::positive) return std::nullopt;
    return sqrt(std::move(d));
  }
  Interval two_pi_;
};

// power:p: r(t) = 1 − (1 − 4t)^p for t ≥ 0, odd (model.md).
class PowerFlank final : public Flank {
 public:
  PowerFlank(const Interval& p, mpfr_prec_t bits)
      : Flank(bits),
        one_(Interval::integer(1, bits)),
        four_(Interval::integer(4, bits)),
        p_(p),
        p_minus_one_(p - one_),
        p_plus_one_(p + one_),
        inverse_p_(one_ / p),
        inverse_p_minus_one_(one_ / (p - one_)),
        four_p_(p * 4),
        p_seed_(mpfr_get_ld(p.midpoint().backend().data(), MPFR_RNDN)) {}
  Interval r(const Interval& t) const override {
    return split(t, [&](const Interval& a) { return one_ - pw(one_ - a * 4, p_); });
  }
  Interval dr(const Interval& t) const override { return four_p_ * pw(one_ - abs(t) * 4, p_minus_one_); }
  Interval R(const Interval& t) const override {
    const Interval a = abs(t);
    return a - (one_ - pw(one_ - a * 4, p_plus_one_)) / (p_plus_one_.value * 4);
  }
  Interval inverse(const Interval& y) const override {
    return split(y, [&](const Interval& v) { return (one_ - pw(one_ - v, inverse_p_)) / four_; });
  }
  Interval top(const Interval& b) const override { return (one_ - pw(b / four_p_, inverse_p_minus_one_)) / four_; }
  Interval steepest() const override { return four_p_; }
  Interval R_quarter() const override { return p_.value / (p_plus_one_.value * 4); }  // 1/4 − 1/(4(p + 1))
  long double r_seed(long double t) const override {
    const long double v = 1 - std::pow(std::max(1 - 4 * std::fabs(t), 0.0L), p_seed_);
    return t < 0 ? -v : v;
  }
  long double dr_seed(long double t) const override {
    return 4 * p_seed_ * std::pow(std::max(1 - 4 * std::fabs(t), 0.0L), p_seed_ - 1);
  }

 private:
  // An exponent, and whether it is a whole number up to 64 (power:2, power:3 and their p ± 1):
  // then powers are products, else exp(q log x). Set once: the enclosure raises to it often.
  struct Exponent {
    explicit Exponent(Interval q) : value(std::move(q)) {
      const mpfr lo = value.lower();
      if (lo == value.upper() && mpfr_integer_p(lo.backend().data()) && lo >= 1 && lo <= 64)
        whole = lo.convert_to<unsigned long>();
    }
    Interval value;
    std::optional<unsigned long> whole;
  };
  // x^q for x ≥ 0 (the part of x below 0 is rounding: dropped), q > 0: increasing in x.
  Interval pw(const Interval& x, const Exponent& q) const {
    if (mpfr_sgn(&x.data()->right) <= 0) return Interval(bits_);
    const bool positive = mpfr_sgn(&x.data()->left) > 0;
    if (q.whole) {
      Interval base = positive ? x : Interval::hull(mpfr(0), x.upper(), bits_);
      Interval out = one_;
      for (unsigned long k = *q.whole; k != 0; k >>= 1) {
        if (k & 1) out *= base;
        if (k > 1) base = sqr(std::move(base));
      }
      return out;
    }
    if (positive) return exp(q.value * log(x));
    return Interval::hull(mpfr(0), exp(q.value * log(Interval::exact(x.upper(), bits_))).upper(), bits_);
  }
  // An odd f from its positive half: f on |x| with x's sign restored, over each sign of x.
  template <class F>
  Interval split(const Interval& x, F f) const {
    const int lo = mpfr_sgn(&x.data()->left), hi = mpfr_sgn(&x.data()->right);
    if (lo >= 0) return hi > 0 ? f(x) : Interval(bits_);
    if (hi <= 0) return -f(-x);
    const mpfr zero = 0;
    return hull(f(Interval::hull(zero, x.upper(), bits_)), -f(Interval::hull(zero, mpfr(-x.lower()), bits_)));
  }
  Interval one_, four_;
  Exponent p_, p_minus_one_, p_plus_one_, inverse_p_, inverse_p_minus_one_;
  Interval four_p_;
  long double p_seed_;
};

// The exact sign of β − r'(t) where r'(t) = s·c^e has a rational closed form (power:p with p = a/b
// of small a: β ≥ 4p c^((p−1)/p) ⟺ (β/4p)^a ≥ c^(a−b)), or none (then intervals decide).
using ExactSlopeSign = std::optional<Sign> (*)(const exact::Rational& p, const exact::Rational& beta, const exact::Rational& c);

std::optional<Sign> power_slope_sign(const exact::Rational& p, const exact::Rational& beta, const exact::Rational& c) {
  const auto a = numerator(p), b = denominator(p);
  if (a > 64) return std::nullopt;
  const unsigned ua = static_cast<unsigned>(a), ub = static_cast<unsigned>(b);
  auto power = [](const exact::Rational& x, unsigned k) {  // rational powers by hand: Boost has none
    exact::Rational r = 1;
    for (unsigned i = 0; i < k; ++i) r *= x;
    return r;
  };
  const exact::Rational lhs = power(beta / (p * 4), ua), rhs = power(c, ua - ub);
  return lhs > rhs ? Sign::positive : lhs < rhs ? Sign::negative : Sign::zero;
}

SineEnclosure enclose(const Flank& flank, const char* name, const exact::Rational& beta, const exact::Rational& gamma,
                      ExactSlopeSign exact_sign = nullptr, const exact::Rational& p = 0) {
  const mpfr_prec_t bits = flank.bits();
  const std::string where = std::string(name) + ", beta = " + beta.str() + ", gamma = " + gamma.str();
  if (!(beta > 0)) throw InputError("beta = " + beta.str() + ": expected a number > 0");
  if (!(gamma > -1)) throw DomainError("gamma = " + gamma.str() + " gives no contact for wave " + name + ": expected gamma > -1");
  SineEnclosure e(bits);
  const Interval B = of(beta, bits), G = of(gamma, bits), one = Interval::integer(1, bits), half = one / Interval::integer(2, bits);
  e.jumping = gamma < 1;
  // First contact on the rising flank (jumping): r(t_c) = −γ, t_c ∈ (−1/4, 1/4).
  const std::optional<Interval> contact = e.jumping ? std::optional<Interval>(flank.inverse(-G)) : std::nullopt;
  e.beta_c = gamma >= 0 ? flank.steepest() : flank.dr_where_r(*contact, -G);
  if (e.jumping) {
    e.normal_area = G * (half - *contact * 2) + (flank.R_quarter() - flank.R_where_r(*contact, -G)) * 2;
  } else {
    e.normal_area = G;
  }
  // β against r'(t_c), r(t_c) = −γ: exactly where the closed form allows, else by intervals.
  auto slope_sign = [&](const Interval& slope, const exact::Rational& c, const char* what) {
    if (exact_sign)
      if (const std::optional<Sign> s = exact_sign(p, beta, c)) return *s;
    return decide(B - slope, what);
  };
  // c = 1 − |γ|: r'(t_c) = 4p c^((p−1)/p) for power:p (c = 1: the steepest slope).
  const exact::Rational c_betac = gamma >= 0 ? exact::Rational(1) : exact::Rational(1 + gamma);
  if (slope_sign(e.beta_c, c_betac, "beta against beta_c (Eq. 6)") != Sign::negative) {
    e.mu = one;
    e.retained_area = e.normal_area;
    e.lost_area = Interval(bits);
    return e;
  }
  e.stick = true;
  const Interval top = flank.top(B);  // n' = β on the concave side, where F = n − ramp is largest
  e.onset_at_contact =
      gamma < 0 || (e.jumping && slope_sign(flank.dr_where_r(*contact, -G), exact::Rational(1 - gamma), "beta against n' at first contact") ==
                                     Sign::negative);
  const Interval phi1 = e.onset_at_contact ? *contact : -top;
  const Interval level = e.onset_at_contact ? Interval(bits) : G - flank.r_where_dr(top, B);
  // F falls from `top` to the end of contact (jumping) or to 1 − top (where it is −β).
  const Interval right = e.jumping ? half - *contact : one - top;
  auto F = [&](const Interval& x) { return G + flank.w(x) - level - B * (x - phi1); };
  auto dF = [&](const Interval& x) { return flank.dw(x) - B; };
  auto ld = [](const Interval& x) { return mpfr_get_ld(x.midpoint().backend().data(), MPFR_RNDN); };
  const long double g0 = ld(G), b0 = ld(B), level0 = ld(level), phi0 = ld(phi1);
  const long double seed = seed_root([&](long double x) { return g0 + flank.w_seed(x) - level0 - b0 * (x - phi0); },
                                     [&](long double x) { return flank.dw_seed(x) - b0; },
                                     mpfr_get_ld(top.upper().backend().data(), MPFR_RNDU),
                                     mpfr_get_ld(right.lower().backend().data(), MPFR_RNDD));
  std::optional<Interval> seeded = seeded_root(F, dF, seed, top.upper(), right.lower(), bits, where + ": the stick end");
  const Interval X = seeded ? *seeded : bracketed_root(F, dF, top.upper(), right.lower(), bits, where + ": the stick end");
  e.onset = phi1;
  e.end = X;
  e.level = level;
  // lost = ∫_{φ1}^{φ2} (n − ramp) = A(φ2) − A(φ1) − level·L − β L²/2, L = φ2 − φ1, A = γφ + W.
  auto A = [&](const Interval& x) { return G * x + flank.W(x); };
  const Interval L = X - phi1;
  // W(φ1) = R(φ1): φ1 lies on the rising flank (first contact, or −top, R being even).
  const Interval W1 = e.onset_at_contact ? flank.R_where_r(*contact, -G) : flank.R_where_dr(top, B);
  e.lost_area = A(X) - (G * phi1 + W1) - level * L - B * sqr(L) / Interval::integer(2, bits);
  e.retained_area = e.normal_area - e.lost_area;
  e.mu = e.retained_area / e.normal_area;
  return e;
}

}  // namespace

SineEnclosure enclose_sine(const exact::Rational& beta, const exact::Rational& gamma, mpfr_prec_t bits) {
  return enclose(SineFlank(bits), "sine", beta, gamma);
}

SineEnclosure enclose_power(const exact::Rational& p, const exact::Rational& beta, const exact::Rational& gamma,
                            mpfr_prec_t bits) {
  if (!(p > 1)) throw InputError("power:p with p = " + p.str() + ": expected p > 1 for an enclosure (power:1 is exact)");
  return enclose(PowerFlank(of(p, bits), bits), "power", beta, gamma, power_slope_sign, p);
}

namespace {

// u(φ) = Σ a_k cos 2πkφ + b_k sin 2πkφ with its derivatives and antiderivative, enclosed.
class Series {
 public:
  Series(const std::vector<RationalHarmonic>& harmonics, mpfr_prec_t bits) : bits_(bits) {
    std::map<unsigned, std::pair<exact::Rational, exact::Rational>> sum;
    for (const RationalHarmonic& h : harmonics)
      if (h.k != 0) sum[h.k].first += h.a, sum[h.k].second += h.b;
    two_pi_ = Interval::pi(bits) * 2;
    for (const auto& [k, ab] : sum)
      if (ab.first != 0 || ab.second != 0) {
        terms_.push_back({k, two_pi_ * static_cast<long>(k), of(ab.first, bits), of(ab.second, bits)});
        max_k_ = std::max(max_k_, k);
      }
    if (terms_.empty()) throw InputError("a Fourier series without a harmonic k >= 1 has zero amplitude");
    for (int o = 0; o <= 4; ++o) bounds_.push_back(bound(o));
  }
  // u^(order), order 0 to 3, and −1 (the antiderivative with zero mean: periodic). On a narrow x,
  // cos and sin of 2πkx by the angle-addition recurrence from one sin_cos; on a wide one, each
  // directly (the recurrence would compound the widths).
  Interval operator()(const Interval& x, int order) const {
    Interval out(bits_);
    const bool narrow = x.width() < mpfr(1e-9);
    std::optional<Interval> c1, s1, c, s;
    unsigned at = 0, anchor = 1;
    if (narrow) {
      auto [sn, cs] = sin_cos(two_pi_ * x);
      s1 = sn, c1 = cs, s = sn, c = cs, at = 1;
    }
    for (const Term& t : terms_) {
      if (narrow && t.k >= anchor + 16) {  // re-anchored every 16 harmonics: the widths grow
        auto [sn, cs] = sin_cos(t.omega * x);   // by up to √2 a step
        s = std::move(sn), c = std::move(cs), at = anchor = t.k;
      } else if (narrow) {
        for (; at < t.k; ++at) {
          Interval next = *c * *c1 - *s * *s1;
          s = *s * *c1 + *c * *s1;
          c = std::move(next);
        }
      } else {
        auto [sn, cs] = sin_cos(t.omega * x);
        s = std::move(sn), c = std::move(cs);
      }
      switch (order) {
        case -1: out += (t.a * *s - t.b * *c) / t.omega; break;
        case 0: out += t.a * *c + t.b * *s; break;
        case 1: out += t.omega * (t.b * *c - t.a * *s); break;
        case 2: out -= sqr(t.omega) * (t.a * *c + t.b * *s); break;
        default: out += sqr(t.omega) * t.omega * (t.a * *s - t.b * *c); break;
      }
    }
    return out;
  }
  // u^(order) over x by its centred form: the value at the midpoint and r·max|u^(order+1)|, r the
  // radius (a narrow x: as above). Cheaper than the wide form's 2K interval sines, and as tight
  // on the brackets of one root.
  Interval centred(const Interval& x, int order) const {
    if (x.width() < mpfr(1e-9)) return (*this)(x, order);
    const mpfr mid = x.midpoint();
    mpfr r;
    mpfr_set_prec(r.backend().data(), 64);
    mpfr_sub(r.backend().data(), x.upper().backend().data(), mid.backend().data(), MPFR_RNDU);
    mpfr radius_low;
    mpfr_set_prec(radius_low.backend().data(), 64);
    mpfr_sub(radius_low.backend().data(), mid.backend().data(), x.lower().backend().data(), MPFR_RNDU);
    mpfr_max(r.backend().data(), r.backend().data(), radius_low.backend().data(), MPFR_RNDU);
    const Interval spread = Interval::hull(mpfr(-r), r, bits_) * bounds_.at(static_cast<std::size_t>(order + 1));
    return (*this)(Interval::exact(mid, bits_), order) + spread;
  }
  unsigned max_k() const { return max_k_; }

 private:
  struct Term {
    unsigned k;
    Interval omega, a, b;  // ω = 2πk
  };
  Interval two_pi_{2};
  // max |u^(order)| ≤ Σ ω^order (|a| + |b|), enclosed (its upper end is the bound).
  Interval bound(int order) const {
    Interval out(bits_);
    for (const Term& t : terms_) {
      Interval power = Interval::integer(1, bits_);
      for (int o = 0; o < order; ++o) power *= t.omega;
      out += power * (abs(t.a) + abs(t.b));
    }
    return Interval::hull(mpfr(0), out.upper(), bits_);
  }
  std::vector<Term> terms_;
  std::vector<Interval> bounds_;  // bound(0) … bound(4)
  unsigned max_k_ = 0;
  mpfr_prec_t bits_;
};

struct Root {
  Interval x;
  Sign slope;  // of the function at the root; undecided: a flat (below)
};

// Every root of f on [from, from + 1], each enclosed with a certain sign change at thin ends and
// f' excluding 0 on its enclosure (one simple root), in increasing order: bisection of `cells`
// cells, a cell dropped where f excludes 0 or is monotone without a sign change. Where f does not
// separate from 0 before the cells are 2^−bits/2 wide (a double root, as u' = cos 2πφ + cos 4πφ
// at φ = 1/2, or roots closer than that) the cells are kept as a flat: a Root with an undecided
// slope, holding every root there (none, one or more).
template <class F, class DF>
std::vector<Root> isolate(F f, DF df, const mpfr& from, int cells, mpfr_prec_t bits, const std::string& what) {
  auto at = [&](long j) {  // from + j/cells, exactly (cells a power of two)
    mpfr x;
    mpfr_set_prec(x.backend().data(), bits + 64);
    mpfr_set_si(x.backend().data(), j, MPFR_RNDN);
    mpfr_div_si(x.backend().data(), x.backend().data(), cells, MPFR_RNDN);
    mpfr_add(x.backend().data(), x.backend().data(), from.backend().data(), MPFR_RNDN);
    return x;
  };
  mpfr narrowest;
  mpfr_set_prec(narrowest.backend().data(), 64);
  mpfr_set_ui_2exp(narrowest.backend().data(), 1, -static_cast<long>(bits / 2), MPFR_RNDN);
  std::vector<std::pair<mpfr, mpfr>> stack;
  for (long j = cells; j > 0; --j) stack.emplace_back(at(j - 1), at(j));
  std::vector<Root> roots;
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const Interval X = Interval::hull(a, b, bits);
    const Sign value = f(X).sign();
    if (value == Sign::positive || value == Sign::negative) continue;
    const Sign slope = df(X).sign();
    if (slope == Sign::positive || slope == Sign::negative) {
      const Sign fa = f(point(a, bits)).sign(), fb = f(point(b, bits)).sign();
      const bool certain = (fa == Sign::positive || fa == Sign::negative) && (fb == Sign::positive || fb == Sign::negative);
      if (certain && fa == fb) continue;
      if (certain) {  // one root: kept once Newton contracts (else f' is near 0 on X: bisect on)
        Interval root = newton(X, f, df, bits, what);
        if (root.width() * 4 < X.width()) {
          roots.push_back({std::move(root), slope});
          continue;
        }
      }
    }
    if (X.width() < narrowest) {
      if (!roots.empty() && roots.back().slope == Sign::undecided && !(roots.back().x.upper() < a))
        roots.back().x = hull(roots.back().x, X);
      else
        roots.push_back({X, Sign::undecided});
      continue;
    }
    const mpfr mid = midpoint(a, b, bits);
    stack.emplace_back(mid, b);
    stack.emplace_back(a, mid);
  }
  return roots;
}

// An event of h = n − βφ on the circle (enclosure.hpp): a contact boundary or a turning point.
struct Event {
  enum Kind { up, down, turn } kind;
  Interval x;  // in [cut, cut + 1)
  Interval h;  // h(x); n = 0 at a contact boundary
};

// The root of f on the monotone arc (lo, hi) of f, rising or falling (bracketed_root).
template <class F, class DF>
Interval arc_root(F f, DF df, bool rising, const mpfr& lo, const mpfr& hi, mpfr_prec_t bits, const std::string& what) {
  if (!rising) return bracketed_root(f, df, lo, hi, bits, what);
  return bracketed_root([&](const Interval& x) { return -f(x); }, [&](const Interval& x) { return -df(x); }, lo, hi, bits, what);
}

}  // namespace

// The circle is cut at a phase no event of a rational series sits on (1/π as a double), and
// split into cells of a fraction of the shortest harmonic's period.
struct FourierShape::Data {
  Data(const std::vector<RationalHarmonic>& harmonics, mpfr_prec_t b) : u(harmonics, b), cut(0.31830988618379067), bits(b) {}
  Series u;
  mpfr cut;
  mpfr_prec_t bits;
  // Roots of u' and of u'' (the extrema of u'), flats among them: between two of them u (u') is
  // monotone, and the extreme values of u lie in u over them.
  std::vector<Root> extrema, bends;
  std::vector<Interval> values, slopes;  // u at the extrema, u' at the bends
};

FourierShape::FourierShape(const std::vector<RationalHarmonic>& harmonics, mpfr_prec_t bits) {
  auto d = std::make_shared<Data>(harmonics, bits);
  int cells = 8;
  while (cells < 8 * static_cast<int>(d->u.max_k())) cells *= 2;
  const Series& u = d->u;
  auto order = [&](int o) { return [&u, o](const Interval& x) { return u(x, o); }; };
  d->extrema = isolate(order(1), order(2), d->cut, cells, bits, "an extremum of the series");
  d->bends = isolate(order(2), order(3), d->cut, cells, bits, "an extremum of the series' slope");
  if (d->extrema.size() < 2 || d->bends.size() < 2) throw SolverError("fourier: fewer than two extrema enclosed (a bug)");
  for (const Root& r : d->extrema) d->values.push_back(u(r.x, 0));
  for (const Root& r : d->bends) d->slopes.push_back(u(r.x, 1));
  data_ = std::move(d);
}

mpfr_prec_t FourierShape::bits() const { return data_->bits; }

FourierEnclosure enclose_fourier(const std::vector<RationalHarmonic>& harmonics, const exact::Rational& beta,
                                 const exact::Rational& gamma, mpfr_prec_t bits) {
  return enclose_fourier(FourierShape(harmonics, bits), beta, gamma);
}

FourierEnclosure enclose_fourier(const FourierShape& shape, const exact::Rational& beta, const exact::Rational& gamma) {
  const std::string where = "fourier, beta = " + beta.str() + ", gamma = " + gamma.str();
  if (!(beta > 0)) throw InputError("beta = " + beta.str() + ": expected a number > 0");
  const FourierShape::Data& d = *shape.data_;
  const Series& u = d.u;
  const mpfr& cut = d.cut;
  const mpfr_prec_t bits = d.bits;
  const std::vector<Root>& extrema = d.extrema;
  const std::vector<Interval>& values = d.values;
  // Slopes over a root's bracket by the centred form (its values at thin points are exact).
  auto f1 = [&](const Interval& x) { return u.centred(x, 1); };
  auto f2 = [&](const Interval& x) { return u.centred(x, 2); };

  // S = (max u − min u)/2 over the extrema (the roots of u'): max u lies between the largest lower
  // end of u over them (u at some point) and the largest upper end (u at the maximum), so does
  // every flat's.
  auto extreme = [&](bool top) {
    mpfr lo = values[0].lower(), hi = values[0].upper();
    for (const Interval& v : values) {
      lo = top ? std::max(lo, v.lower()) : std::min(lo, v.lower());
      hi = top ? std::max(hi, v.upper()) : std::min(hi, v.upper());
    }
    return Interval::hull(lo, hi, bits);
  };
  const Interval U = extreme(true), L = extreme(false), S = (U - L) / Interval::integer(2, bits);
  FourierEnclosure e(bits);
  e.scale = S;
  e.minimum = L / S;
  // In u's units: n = max(ν, 0), ν = G + u, G = γS, ramp slope B = βS.
  const Interval G = of(gamma, bits) * S, B = of(beta, bits) * S;
  auto nu = [&](const Interval& x) { return G + u(x, 0); };

  // The root on the arc from ends[j] to the next (a period on after the last), by root(lo, hi),
  // back in [cut, cut + 1).
  auto on_circle = [&](const std::vector<Root>& ends, std::size_t j, auto root) {
    const std::size_t k = (j + 1) % ends.size();
    Interval x = root(ends[j].x.upper(), (ends[k].x + Interval::integer(k == 0 ? 1 : 0, bits)).lower());
    if (k == 0 && x.lower() >= cut + 1) x = x - Interval::integer(1, bits);
    if (x.upper() >= cut + 1) throw Undecided("undecided at this precision: " + where + ": an event at the cut");
    return x;
  };

  // Contact boundaries: one on each monotone arc of u whose ends (extrema, flats) have certain
  // opposite signs of ν. A minimum with ν undecided (n touching zero, as at γ = −min w) is taken
  // as contact: max(ν, 0) − ν ≤ δ there, and δ widens the areas below. Contact exists where ν > 0
  // at one of them, none where ν < 0 at all (the maximum is among them).
  std::vector<Event> events;
  std::vector<Sign> at_extremum;
  mpfr delta = 0;
  bool any_contact = false;
  for (std::size_t j = 0; j < extrema.size(); ++j) {
    const Interval v = G + values[j];
    Sign sv = v.sign();
    if (sv == Sign::zero) sv = Sign::undecided;
    if (sv == Sign::undecided) {
      if (extrema[j].slope != Sign::positive)
        throw Undecided("undecided at this precision: " + where + ": n touches zero at a maximum or a flat");
      delta = std::max(delta, mpfr(-v.lower()));
    }
    any_contact = any_contact || sv == Sign::positive;
    at_extremum.push_back(sv);
  }
  if (!any_contact) {
    bool none = true;
    for (std::size_t j = 0; j < extrema.size(); ++j) none = none && at_extremum[j] == Sign::negative;
    if (none) throw DomainError("gamma = " + gamma.str() + " gives no contact for this Fourier series");
    throw Undecided("undecided at this precision: " + where + ": whether there is contact");
  }
  for (std::size_t j = 0; j < extrema.size(); ++j) {
    const std::size_t k = (j + 1) % extrema.size();
    const Sign a = at_extremum[j], b = at_extremum[k];
    if (a == Sign::undecided || b == Sign::undecided || a == b) continue;
    const bool rising = a == Sign::negative;
    const Interval x = on_circle(extrema, j, [&](const mpfr& lo, const mpfr& hi) {
      return arc_root(nu, f1, rising, lo, hi, bits, where + ": a contact boundary");
    });
    events.push_back({rising ? Event::up : Event::down, x, -(B * x)});
  }
  e.jumping = !events.empty();
  // Turning points of h in contact: u' = B where ν > 0, one on each monotone arc of u' whose
  // ends (the bends) have certain opposite signs of u' − B.
  for (std::size_t j = 0; j < d.bends.size(); ++j) {
    const std::size_t k = (j + 1) % d.bends.size();
    const Sign a = decide(d.slopes[j] - B, "beta against a local extremum of n'"), b = decide(d.slopes[k] - B, "beta against a local extremum of n'");
    if (a == b) continue;
    const Interval x = on_circle(d.bends, j, [&](const mpfr& lo, const mpfr& hi) {
      return arc_root([&](const Interval& y) { return u(y, 1) - B; }, f2, a == Sign::negative, lo, hi, bits,
                      where + ": a turning point (n' = beta)");
    });
    const Interval v = nu(x);
    const Sign sv = v.sign();
    if (sv == Sign::negative) continue;
    if (sv != Sign::positive) throw Undecided("undecided at this precision: " + where + ": a turning point at a contact boundary");
    events.push_back({Event::turn, x, v - B * x});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.x.lower() < b.x.lower(); });
  const std::size_t count = events.size();
  for (std::size_t j = 1; j <= count && count > 1; ++j)
    if (!(events[j - 1].x.upper() < (j < count ? events[j].x : events[0].x + Interval::integer(1, bits)).lower()))
      throw Undecided("undecided at this precision: " + where + ": two events do not separate");

  // Piece j runs from event j to event j + 1 (the last to the first, a period on): contact status
  // and the certain direction of h on it.
  std::vector<bool> in_contact(count, true);
  std::vector<Sign> direction(count);
  bool status = true;  // before the first event: the status the last contact boundary leaves
  for (const Event& ev : events)
    if (ev.kind != Event::turn) status = ev.kind == Event::up;
  const Interval one = Interval::integer(1, bits);
  auto start = [&](std::size_t j) { return events[j % count].x + one * static_cast<long>(j / count); };
  auto level = [&](std::size_t j) { return events[j % count].h - B * static_cast<long>(j / count); };
  for (std::size_t j = 0; j < count; ++j) {
    if (events[j].kind != Event::turn) status = events[j].kind == Event::up;
    in_contact[j] = status;
    const mpfr m = midpoint(start(j).upper(), start(j + 1).lower(), bits);
    const Interval slope = status ? u(point(m, bits), 1) - B : -B;
    direction[j] = decide(slope, "the direction of h between two events");
  }

  // Valleys, and where each one's level returns: walk the pieces from it (steps[i]: the piece of
  // the return, counted from the valley's event).
  struct Valley {
    std::size_t event, steps = 0;
    Interval end;
  };
  std::vector<Valley> valleys;
  for (std::size_t j = 0; j < count; ++j)
    if (direction[(j + count - 1) % count] == Sign::negative && direction[j] == Sign::positive) valleys.push_back({j, 0, one});
  for (Valley& v : valleys) {
    const Interval c = events[v.event].h;
    for (std::size_t m = 1;; ++m) {
      if (m >= count + 1) throw SolverError(where + ": a stick phase does not end within a period (a bug)");
      const std::size_t j = v.event + m;
      if (direction[j % count] == Sign::positive) continue;
      if (decide(level(j + 1) - c, "h against a valley's level") == Sign::positive) continue;
      if (!in_contact[j % count]) throw SolverError(where + ": a stick phase ends in flight (a bug)");
      v.steps = m;
      v.end = bracketed_root([&](const Interval& x) { return nu(x) - B * x - c; }, [&](const Interval& x) { return f1(x) - B; },
                             start(j).upper(), start(j + 1).lower(), bits, where + ": a stick end");
      break;
    }
  }
  // Normal area: γ without flight, else the contact arcs' integrals.
  Interval normal(bits);
  auto integral = [&](const Interval& a, const Interval& b) { return G * (b - a) + u(b, -1) - u(a, -1); };
  if (!e.jumping) {
    normal = G;
  } else {
    for (std::size_t j = 0; j < count; ++j)
      if (events[j].kind == Event::up)
        for (std::size_t m = 1; m <= count; ++m)
          if (events[(j + m) % count].kind == Event::down) {
            normal += integral(events[j].x, start(j + m));
            break;
          }
  }
  // Stick phases: the valleys inside no other's.
  Interval lost(bits);
  for (const Valley& v : valleys) {
    bool inside = false;
    for (const Valley& w : valleys)
      if (&w != &v) inside = inside || (v.event + count - w.event) % count <= w.steps;
    if (inside) continue;
    const Event& ev = events[v.event];
    const bool at_contact = ev.kind == Event::up;
    const Interval lev = at_contact ? Interval(bits) : nu(ev.x);
    const Interval length = v.end - ev.x;
    lost += integral(ev.x, v.end) - lev * length - B * sqr(length) / Interval::integer(2, bits);
    e.sticks.push_back({ev.x, v.end, lev / S, at_contact});
  }
  if (!valleys.empty() && e.sticks.empty()) throw SolverError(where + ": every valley inside another's stick phase (a bug)");
  // n lies above the n* computed on by at most δ (n touching zero): ∫n and ∫s (monotone and
  // 1-Lipschitz in n, by model.md's envelope) lie within δ above theirs, ∫(n − s) within δ.
  const Interval up = Interval::hull(mpfr(0), delta, bits), both = Interval::hull(mpfr(-delta), delta, bits);
  e.normal_area = (normal + up) / S;
  if (e.sticks.empty()) {  // μ̄ = 1 exactly (Eq. 6): no valley of h, with or without the touch
    e.retained_area = e.normal_area;
    e.lost_area = Interval(bits);
    e.mu = one;
  } else {
    e.retained_area = (normal - lost + up) / S;
    e.lost_area = (lost + both) / S;
    e.mu = (normal - lost + up) / (normal + up);
  }
  return e;
}

}  // namespace vibrofric::certified
