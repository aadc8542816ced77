// Certified enclosures for the harmonic wave (enclosure.hpp).
#include "vibrofric/core/enclosure.hpp"

#include <string>

namespace vibrofric::certified {

namespace {

Interval of(const exact::Rational& x, mpfr_prec_t bits) { return Interval::rational(x.backend().data(), bits); }

// The certain sign of x, or Undecided naming the comparison.
Sign decide(const Interval& x, const char* what) {
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

// The rising flank r(t), t ∈ [−1/4, 1/4], of a wave with the sine's symmetries (enclosure.hpp).
// Arguments are intervals inside [−1/4, 1/4]; an interval may straddle 0.
class Flank {
 public:
  explicit Flank(mpfr_prec_t bits) : bits_(bits) {}
  virtual ~Flank() = default;
  virtual Interval r(const Interval& t) const = 0;
  virtual Interval dr(const Interval& t) const = 0;
  virtual Interval R(const Interval& t) const = 0;       // ∫₀ᵗ r, even
  virtual Interval inverse(const Interval& y) const = 0;  // r(t) = y, −1 < y < 1
  virtual Interval top(const Interval& b) const = 0;      // t ∈ (0, 1/4): r'(t) = b < r'(0)
  virtual Interval steepest() const = 0;                  // r'(0)
  mpfr_prec_t bits() const { return bits_; }

 protected:
  mpfr_prec_t bits_;
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

 private:
  Interval two_pi_;
};

// power:p: r(t) = 1 − (1 − 4t)^p for t ≥ 0, odd (model.md).
class PowerFlank final : public Flank {
 public:
  PowerFlank(const Interval& p, mpfr_prec_t bits) : Flank(bits), p_(p) {}
  Interval r(const Interval& t) const override {
    return split(t, [&](const Interval& a) { return one() - pw(one() - a * 4, p_); }, true);
  }
  Interval dr(const Interval& t) const override { return p_ * 4 * pw(one() - abs(t) * 4, p_ - one()); }
  Interval R(const Interval& t) const override {
    const Interval a = abs(t);
    return a - (one() - pw(one() - a * 4, p_ + one())) / ((p_ + one()) * 4);
  }
  Interval inverse(const Interval& y) const override {
    return split(y, [&](const Interval& v) { return (one() - pw(one() - v, one() / p_)) / Interval::integer(4, bits_); }, true);
  }
  Interval top(const Interval& b) const override {
    return (one() - pw(b / (p_ * 4), one() / (p_ - one()))) / Interval::integer(4, bits_);
  }
  Interval steepest() const override { return p_ * 4; }

 private:
  Interval one() const { return Interval::integer(1, bits_); }
  // x^q for x ≥ 0 (the part of x below 0 is rounding: dropped), q > 0: increasing in x.
  Interval pw(const Interval& x, const Interval& q) const {
    const mpfr hi = x.upper();
    if (hi <= 0) return Interval(bits_);
    if (x.lower() > 0) return exp(q * log(x));
    return Interval::hull(mpfr(0), exp(q * log(Interval::exact(hi, bits_))).upper(), bits_);
  }
  // f on |x| with x's sign restored (an odd function from its positive half), over each sign of x.
  template <class F>
  Interval split(const Interval& x, F f, bool odd) const {
    std::optional<Interval> out;
    const mpfr zero = 0;
    if (x.upper() > 0) out = f(Interval::hull(std::max(x.lower(), zero), x.upper(), bits_));
    if (x.lower() < 0) {
      Interval neg = f(Interval::hull(std::max(mpfr(-x.upper()), zero), mpfr(-x.lower()), bits_));
      if (odd) neg = -neg;
      out = out ? hull(*out, neg) : neg;
    }
    return out ? *out : Interval(bits_);
  }
  Interval p_;
};

// The wave over one period from φ = −1/4, from its flank: r on [−1/4, 1/4], r(1/2 − φ) on
// [1/4, 3/4], r(φ − 1) on [3/4, 5/4]; an interval is split at 1/4 and 3/4 and the parts hulled.
class Wave {
 public:
  explicit Wave(const Flank& f) : f_(f) {}
  Interval w(const Interval& x) const {
    return over(x, [&](const Interval& t) { return f_.r(t); }, [&](const Interval& t) { return f_.r(t); },
                [&](const Interval& t) { return f_.r(t); });
  }
  Interval dw(const Interval& x) const {
    return over(x, [&](const Interval& t) { return f_.dr(t); }, [&](const Interval& t) { return -f_.dr(t); },
                [&](const Interval& t) { return f_.dr(t); });
  }
  // A continuous antiderivative of w: R, then 2R(1/4) − R(1/2 − φ), then R(φ − 1).
  Interval W(const Interval& x) const {
    const Interval quarter = f_.R(at(0.25));
    return over(x, [&](const Interval& t) { return f_.R(t); }, [&](const Interval& t) { return quarter * 2 - f_.R(t); },
                [&](const Interval& t) { return f_.R(t); });
  }

 private:
  Interval at(double v) const { return Interval::exact(mpfr(v), f_.bits()); }
  // first(t) on x ∩ [−1/4, 1/4] with t = φ, second on x ∩ [1/4, 3/4] with t = 1/2 − φ, third on
  // x ∩ [3/4, 5/4] with t = φ − 1, each t clipped to [−1/4, 1/4] (beyond it only by rounding).
  template <class A, class B, class C>
  Interval over(const Interval& x, A first, B second, C third) const {
    std::optional<Interval> out;
    const Interval flank = Interval::hull(mpfr(-0.25), mpfr(0.25), f_.bits());
    auto add = [&](double a, double b, const Interval& shift, bool reflect, auto f) {
      const auto part = intersection(x, Interval::hull(mpfr(a), mpfr(b), f_.bits()));
      if (!part) return;
      const auto t = intersection(reflect ? shift - *part : *part - shift, flank);
      if (!t) return;
      const Interval v = f(*t);
      out = out ? hull(*out, v) : v;
    };
    add(-0.25, 0.25, at(0), false, first);
    add(0.25, 0.75, at(0.5), true, second);
    add(0.75, 1.25, at(1), false, third);
    if (!out) throw SolverError("enclosure: a phase outside [-1/4, 5/4] (a bug)");
    return *out;
  }
  const Flank& f_;
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
  const Wave wave(flank);
  const Interval B = of(beta, bits), G = of(gamma, bits), one = Interval::integer(1, bits), half = one / Interval::integer(2, bits);
  e.jumping = gamma < 1;
  // First contact on the rising flank (jumping): r(t_c) = −γ, t_c ∈ (−1/4, 1/4).
  const std::optional<Interval> contact = e.jumping ? std::optional<Interval>(flank.inverse(-G)) : std::nullopt;
  e.beta_c = gamma >= 0 ? flank.steepest() : flank.dr(*contact);
  if (e.jumping) {
    e.normal_area = G * (half - *contact * 2) + (flank.R(Interval::exact(mpfr(0.25), bits)) - flank.R(*contact)) * 2;
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
      gamma < 0 || (e.jumping && slope_sign(flank.dr(*contact), exact::Rational(1 - gamma), "beta against n' at first contact") ==
                                     Sign::negative);
  const Interval phi1 = e.onset_at_contact ? *contact : -top;
  const Interval level = e.onset_at_contact ? Interval(bits) : G - flank.r(top);
  // F falls from `top` to the end of contact (jumping) or to 1 − top (where it is −β).
  const Interval right = e.jumping ? half - *contact : one - top;
  auto F = [&](const Interval& x) { return G + wave.w(x) - level - B * (x - phi1); };
  auto dF = [&](const Interval& x) { return wave.dw(x) - B; };
  mpfr lo = top.upper(), hi = right.lower();
  if (decide(F(point(lo, bits)), "n above the ramp after the onset") != Sign::positive ||
      decide(F(point(hi, bits)), "n below the ramp at the bracket's end") != Sign::negative)
    throw SolverError(where + ": the stick end has no sign change in its bracket");
  // Bisection until F' < 0 certainly on the bracket (at `top` it is 0), then interval Newton.
  for (int k = 0;; ++k) {
    if (k > static_cast<int>(bits) + 64)
      throw Undecided(where + ": the stick end's bracket does not separate from n's turning point");
    if (dF(Interval::hull(lo, hi, bits)).sign() == Sign::negative) break;
    const mpfr mid = midpoint(lo, hi, bits);
    if (decide(F(point(mid, bits)), "n against the ramp inside the stick end's bracket") == Sign::positive)
      lo = mid;
    else
      hi = mid;
  }
  Interval X = Interval::hull(lo, hi, bits);
  for (int k = 0; k < 200; ++k) {
    const Interval m = point(X.midpoint(), bits);
    const Interval N = m - F(m) / dF(X);
    std::optional<Interval> next = intersection(X, N);
    if (!next) throw SolverError(where + ": interval Newton lost the stick end (a bug)");
    const bool shrank = next->width() < X.width() / 2;
    X = *next;
    if (!shrank) break;
  }
  e.onset = phi1;
  e.end = X;
  e.level = level;
  // lost = ∫_{φ1}^{φ2} (n − ramp) = A(φ2) − A(φ1) − level·L − β L²/2, L = φ2 − φ1, A = γφ + W.
  auto A = [&](const Interval& x) { return G * x + wave.W(x); };
  const Interval L = X - phi1;
  e.lost_area = A(X) - A(phi1) - level * L - B * sqr(L) / Interval::integer(2, bits);
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

}  // namespace vibrofric::certified
