// Closed real intervals with outward-rounded endpoints (MPFI), the number type of certified
// enclosures (README, "Precision"; model.md, "The paper's claims that the suite verifies": a claim
// decided to working precision becomes one decided by an enclosure). Every operation returns an
// interval holding the exact result for every point of its arguments.
//
// There is no operator< or ==: on intervals a comparison can be undecided. sign() and compare()
// say negative, positive, zero (both ends exactly 0) or undecided, and a caller decides only on a
// certain answer (Boost 1.81's mpfi_float throws from a noexcept compare on overlap, which
// terminates the process, and calls two equal wide intervals equal).
#pragma once
#include <mpfi.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

enum class Sign { negative, zero, positive, undecided };

class Interval {
 public:
  // [0, 0] with `bits` of precision per endpoint.
  explicit Interval(mpfr_prec_t bits) {
    mpfi_init2(v_, bits);
    mpfi_set_si(v_, 0);
  }
  Interval(const Interval& other) {
    mpfi_init2(v_, mpfi_get_prec(other.v_));
    mpfi_set(v_, other.v_);
  }
  // A move takes the endpoints' limbs (no allocation: most operations return a temporary); a
  // moved-from interval may only be assigned to or destroyed.
  Interval(Interval&& other) noexcept : owns_(other.owns_) {
    *v_ = *other.v_;
    other.owns_ = false;
  }
  Interval& operator=(const Interval& other) {
    if (this != &other) {
      if (owns_) {
        mpfi_set_prec(v_, mpfi_get_prec(other.v_));
      } else {
        mpfi_init2(v_, mpfi_get_prec(other.v_));
        owns_ = true;
      }
      mpfi_set(v_, other.v_);
    }
    return *this;
  }
  Interval& operator=(Interval&& other) noexcept {
    if (this != &other) {
      if (owns_) mpfi_clear(v_);
      *v_ = *other.v_;
      owns_ = other.owns_;
      other.owns_ = false;
    }
    return *this;
  }
  ~Interval() {
    if (owns_) mpfi_clear(v_);
  }

  // The integer k, exactly.
  static Interval integer(long k, mpfr_prec_t bits) {
    Interval r(bits);
    mpfi_set_si(r.v_, k);
    return r;
  }
  // The exact value of an mpfr number (at least its own precision, so no rounding).
  static Interval exact(const mpfr& x, mpfr_prec_t bits) {
    Interval r(std::max(bits, mpfr_get_prec(x.backend().data())));
    mpfi_set_fr(r.v_, x.backend().data());
    return r;
  }
  // The decimal `text` (our grammar: check_decimal has accepted it), enclosed: its exact value
  // lies inside, with each end rounded outward.
  static Interval decimal(const std::string& text, mpfr_prec_t bits) {
    Interval r(bits);
    if (mpfi_set_str(r.v_, text.c_str(), 10) != 0 || mpfi_nan_p(r.v_))
      throw InputError("'" + text + "': not a decimal number to enclose");
    return r;
  }
  // The smallest interval holding [lo, hi] (lo ≤ hi).
  static Interval hull(const mpfr& lo, const mpfr& hi, mpfr_prec_t bits) {
    Interval r = exact(lo, bits);
    const Interval b = exact(hi, bits);
    mpfi_union(r.v_, r.v_, b.v_);
    return r;
  }
  // The rational p/q (GMP), enclosed: exact where it is dyadic and fits, else one ulp wide.
  static Interval rational(mpq_srcptr q, mpfr_prec_t bits) {
    Interval r(bits);
    mpfi_set_q(r.v_, q);
    return r;
  }
  static Interval pi(mpfr_prec_t bits) {
    Interval r(bits);
    mpfi_const_pi(r.v_);
    return r;
  }

  mpfr_prec_t precision() const { return mpfi_get_prec(v_); }
  // The same interval at `bits` per end, rounded outward (a superset where bits are fewer).
  Interval rounded(mpfr_prec_t bits) const {
    Interval r(bits);
    mpfi_set(r.v_, v_);
    return r;
  }
  mpfr lower() const { return end(mpfi_get_left); }
  mpfr upper() const { return end(mpfi_get_right); }
  mpfr midpoint() const { return end(mpfi_mid); }
  // upper − lower, rounded up.
  mpfr width() const { return end(mpfi_diam_abs); }
  bool bounded() const { return mpfi_bounded_p(v_) != 0; }
  bool contains(const mpfr& x) const { return mpfi_is_inside_fr(x.backend().data(), v_) > 0; }
  bool contains(const Interval& inner) const { return mpfi_is_inside(inner.v_, v_) > 0; }

  // The certain sign of every point, or undecided (NaN ends, or an interval holding 0 and more).
  Sign sign() const {
    const __mpfr_struct* lo = &v_->left;
    const __mpfr_struct* hi = &v_->right;
    if (mpfr_nan_p(lo) || mpfr_nan_p(hi)) return Sign::undecided;
    if (mpfr_sgn(lo) > 0) return Sign::positive;
    if (mpfr_sgn(hi) < 0) return Sign::negative;
    if (mpfr_zero_p(lo) && mpfr_zero_p(hi)) return Sign::zero;
    return Sign::undecided;
  }

  Interval& operator+=(const Interval& b) { return apply(mpfi_add, b); }
  Interval& operator-=(const Interval& b) { return apply(mpfi_sub, b); }
  Interval& operator*=(const Interval& b) { return apply(mpfi_mul, b); }
  // Division by an interval that holds 0 gives an unbounded interval (bounded() is false).
  Interval& operator/=(const Interval& b) { return apply(mpfi_div, b); }
  // this ± a·b and this + a/d without a temporary (the Taylor series' convolutions)
  Interval& add_mul(const Interval& a, const Interval& b) { return fused(a, b, false); }
  Interval& sub_mul(const Interval& a, const Interval& b) { return fused(a, b, true); }
  Interval& add_quotient(const Interval& a, unsigned long d) {
    mpfi_ptr t = product_scratch(precision());
    mpfi_div_ui(t, a.v_, d);
    mpfi_add(v_, v_, t);
    return *this;
  }
  friend Interval operator+(Interval a, const Interval& b) {
    a += b;
    return a;
  }
  friend Interval operator-(Interval a, const Interval& b) {
    a -= b;
    return a;
  }
  friend Interval operator*(Interval a, const Interval& b) {
    a *= b;
    return a;
  }
  friend Interval operator/(Interval a, const Interval& b) {
    a /= b;
    return a;
  }
  friend Interval operator-(Interval a) {
    mpfi_neg(a.v_, a.v_);
    return a;
  }
  friend Interval operator*(Interval a, long k) {
    mpfi_mul_si(a.v_, a.v_, k);
    return a;
  }

  friend Interval sqr(Interval a) { return a.unary(mpfi_sqr); }
  friend Interval abs(Interval a) { return a.unary(mpfi_abs); }
  // sin, cos, exp, log, asin and acos of a narrow interval (radius < 2^−(bits/2)) cost one MPFR
  // call at its midpoint (see narrow), mpfi's two and its argument checks on a wide one.
  friend Interval sin(Interval a) { return a.narrow(mpfr_sin, mpfi_sin, trig_spread); }
  friend Interval cos(Interval a) { return a.narrow(mpfr_cos, mpfi_cos, trig_spread); }
  friend Interval exp(Interval a) { return a.narrow(mpfr_exp, mpfi_exp, exp_spread); }
  // sin and cos together. A narrow interval (radius r < 2^−20) costs one mpfr_sin_cos at its
  // midpoint: each correctly rounded value widened by an ulp either way, then by r (both are
  // 1-Lipschitz); a wide one is mpfi_sin and mpfi_cos.
  friend std::pair<Interval, Interval> sin_cos(const Interval& a) {
    const mpfr_prec_t bits = a.precision();
    Interval s(bits), c(bits);
    mpfr_t mid, radius, sv, cv;
    mpfr_inits2(bits, mid, radius, sv, cv, static_cast<mpfr_ptr>(nullptr));
    mpfi_mid(mid, a.v_);
    mpfr_sub(radius, &a.v_->right, mid, MPFR_RNDU);
    mpfr_sub(sv, mid, &a.v_->left, MPFR_RNDU);
    mpfr_max(radius, radius, sv, MPFR_RNDU);
    const bool narrow = mpfr_number_p(radius) && (mpfr_zero_p(radius) || mpfr_get_exp(radius) < -20);
    if (narrow) {
      mpfr_sin_cos(sv, cv, mid, MPFR_RNDN);
      auto widen = [&](Interval& out, mpfr_ptr v) {
        mpfr_t lo, hi;
        mpfr_inits2(bits, lo, hi, static_cast<mpfr_ptr>(nullptr));
        mpfr_set(lo, v, MPFR_RNDN);
        mpfr_set(hi, v, MPFR_RNDN);
        mpfr_nextbelow(lo);
        mpfr_nextabove(hi);
        mpfr_sub(lo, lo, radius, MPFR_RNDD);
        mpfr_add(hi, hi, radius, MPFR_RNDU);
        mpfi_interv_fr(out.v_, lo, hi);
        mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
      };
      widen(s, sv);
      widen(c, cv);
    } else {
      mpfi_sin(s.v_, a.v_);
      mpfi_cos(c.v_, a.v_);
    }
    mpfr_clears(mid, radius, sv, cv, static_cast<mpfr_ptr>(nullptr));
    return {std::move(s), std::move(c)};
  }
  // asin and acos of an interval reaching outside [−1, 1] are an error, not a NaN end.
  friend Interval asin(Interval a) { return a.in_unit_range("asin").narrow(mpfr_asin, mpfi_asin, arc_slope); }
  friend Interval acos(Interval a) { return a.in_unit_range("acos").narrow(mpfr_acos, mpfi_acos, arc_slope); }
  // sqrt and log of an interval reaching below their domain are an error, not a NaN end.
  friend Interval sqrt(Interval a) {
    if (mpfr_sgn(&a.v_->left) < 0) throw SolverError("interval sqrt of an interval reaching below 0");
    return a.unary(mpfi_sqrt);
  }
  friend Interval log(Interval a) {
    if (mpfr_sgn(&a.v_->left) <= 0) throw SolverError("interval log of an interval reaching 0 or below");
    return a.narrow(mpfr_log, mpfi_log, log_spread);
  }
  // The smallest interval holding both; their intersection, if not empty.
  friend Interval hull(Interval a, const Interval& b) {
    a.apply(mpfi_union, b);
    return a;
  }
  friend std::optional<Interval> intersection(Interval a, const Interval& b) {
    mpfi_intersect(a.v_, a.v_, b.v_);
    if (mpfi_is_empty(a.v_)) return std::nullopt;
    return a;
  }
  // The two halves at the midpoint.
  std::pair<Interval, Interval> bisect() const {
    Interval left(precision()), right(precision());
    mpfi_bisect(left.v_, right.v_, v_);
    return {std::move(left), std::move(right)};
  }

  mpfi_srcptr data() const { return v_; }

 private:
  template <class F>
  mpfr end(F f) const {
    mpfr x;
    x.precision(static_cast<unsigned>(digits10_of(precision())));
    mpfr_set_prec(x.backend().data(), precision());
    f(x.backend().data(), v_);
    return x;
  }
  static long digits10_of(mpfr_prec_t bits) { return static_cast<long>(bits * 0.30103) + 2; }
  template <class F>
  Interval& apply(F f, const Interval& b) {
    if (mpfi_get_prec(b.v_) > precision()) mpfi_round_prec(v_, mpfi_get_prec(b.v_));
    f(v_, v_, b.v_);
    return *this;
  }
  Interval& in_unit_range(const char* f) {
    if (mpfr_cmp_si(&v_->left, -1) < 0 || mpfr_cmp_si(&v_->right, 1) > 0 || mpfr_nan_p(&v_->left) || mpfr_nan_p(&v_->right))
      throw SolverError(std::string("interval ") + f + " of an interval reaching outside [-1, 1]");
    return *this;
  }
  // f on a narrow interval (radius r < 2^−(bits/2), so that the spreads' second-order terms,
  // about r², lie below the rounding): f(mid), correctly rounded, widened by an ulp either way
  // where inexact (an exact value, as sin 0, stays a point), then by spread(v, mid, r), a bound
  // on |f(x) − f(mid)| over the interval (false where it has none); on a wide interval, one with
  // a NaN or infinite end, or without a spread, `wide` (mpfi's two calls, exact at the ends:
  // where f' vanishes at an end, as F' at a stick that barely exists, a spread about the
  // midpoint would overshoot the end's value and make Newton stall).
  template <class F, class G, class S>
  Interval narrow(F f, G wide, S spread) {
    const mpfr_prec_t bits = precision();
    mpfr_ptr mid = scratch(0, bits), radius = scratch(1, bits), lo = scratch(2, bits), hi = scratch(3, bits);
    mpfi_mid(mid, v_);
    mpfr_sub(radius, &v_->right, mid, MPFR_RNDU);
    mpfr_sub(lo, mid, &v_->left, MPFR_RNDU);
    mpfr_max(radius, radius, lo, MPFR_RNDU);
    bool done = false;
    if (mpfr_number_p(radius) && (mpfr_zero_p(radius) || mpfr_get_exp(radius) <= -bits / 2)) {
      const int inexact = f(hi, mid, MPFR_RNDN);  // hi: f(mid); lo: the spread
      if (mpfr_number_p(hi) && spread(lo, hi, mid, radius)) {
        mpfr_swap(lo, mid);
        mpfr_sub(lo, hi, mid, MPFR_RNDD);
        mpfr_add(hi, hi, mid, MPFR_RNDU);
        if (inexact != 0) {
          mpfr_nextbelow(lo);
          mpfr_nextabove(hi);
        }
        mpfi_interv_fr(v_, lo, hi);
        done = true;
      }
    }
    if (!done) wide(v_, v_);
    return std::move(*this);
  }
  // this ± a·b: the product's ends by the sign cases of a and b (two MPFR products, four where
  // both straddle 0), each rounded outward into per-thread scratch and added with the matching
  // rounding (mpfi_mul allocates temporaries on every call, and convolutions make millions).
  // Infinite or NaN ends take MPFI's own path.
  Interval& fused(const Interval& a, const Interval& b, bool subtract) {
    mpfr_srcptr al = &a.v_->left, ar = &a.v_->right, bl = &b.v_->left, br = &b.v_->right;
    if (!mpfr_number_p(al) || !mpfr_number_p(ar) || !mpfr_number_p(bl) || !mpfr_number_p(br) || !bounded()) {
      mpfi_ptr t = product_scratch(std::max(a.precision(), b.precision()));
      mpfi_mul(t, a.v_, b.v_);
      subtract ? mpfi_sub(v_, v_, t) : mpfi_add(v_, v_, t);
      return *this;
    }
    const mpfr_prec_t bits = precision();
    mpfr_ptr lo = scratch(0, bits), hi = scratch(1, bits), t = scratch(2, bits);
    const int sa = mpfr_sgn(al) >= 0 ? 1 : (mpfr_sgn(ar) <= 0 ? -1 : 0);
    const int sb = mpfr_sgn(bl) >= 0 ? 1 : (mpfr_sgn(br) <= 0 ? -1 : 0);
    const auto ends = [&](mpfr_srcptr x1, mpfr_srcptr y1, mpfr_srcptr x2, mpfr_srcptr y2) {
      mpfr_mul(lo, x1, y1, MPFR_RNDD);
      mpfr_mul(hi, x2, y2, MPFR_RNDU);
    };
    if (sa == 1) {
      if (sb == 1) ends(al, bl, ar, br);
      else if (sb == -1) ends(ar, bl, al, br);
      else ends(ar, bl, ar, br);
    } else if (sa == -1) {
      if (sb == 1) ends(al, br, ar, bl);
      else if (sb == -1) ends(ar, br, al, bl);
      else ends(al, br, al, bl);
    } else if (sb == 1) {
      ends(al, br, ar, br);
    } else if (sb == -1) {
      ends(ar, bl, al, bl);
    } else {
      ends(al, br, al, bl);
      mpfr_mul(t, ar, bl, MPFR_RNDD);
      mpfr_min(lo, lo, t, MPFR_RNDD);
      mpfr_mul(t, ar, br, MPFR_RNDU);
      mpfr_max(hi, hi, t, MPFR_RNDU);
    }
    if (subtract) {
      mpfr_sub(&v_->left, &v_->left, hi, MPFR_RNDD);
      mpfr_sub(&v_->right, &v_->right, lo, MPFR_RNDU);
    } else {
      mpfr_add(&v_->left, &v_->left, lo, MPFR_RNDD);
      mpfr_add(&v_->right, &v_->right, hi, MPFR_RNDU);
    }
    return *this;
  }
  static mpfi_ptr product_scratch(mpfr_prec_t bits) {
    struct Scratch {
      Scratch() { mpfi_init2(v, MPFR_PREC_MIN); }
      ~Scratch() { mpfi_clear(v); }
      mpfi_t v;
    };
    thread_local Scratch s;
    if (mpfi_get_prec(s.v) != bits) mpfi_set_prec(s.v, bits);
    return s.v;
  }
  // Scratch number i of four per thread at `bits` (set_prec reallocates only to grow): narrow()
  // runs for every transcendental function, and its temporaries were four allocations a call.
  static mpfr_ptr scratch(int i, mpfr_prec_t bits) {
    struct Scratch {
      Scratch() {
        for (mpfr_t& x : v) mpfr_init2(x, MPFR_PREC_MIN);
      }
      ~Scratch() {
        for (mpfr_t& x : v) mpfr_clear(x);
      }
      mpfr_t v[4];
    };
    thread_local Scratch s;
    mpfr_set_prec(s.v[i], bits);
    return s.v[i];
  }
  // The spreads:
  //  - sin, cos: r·(c + r), c = √(1 − (|v| − ulp)²) rounded up bounding |f'(mid)| (the other
  //    function's size, from v = f(mid) rounded), and |f''| ≤ 1 (Taylor: r·c + r²/2; near an
  //    extremum r alone would be far wider than the true range);
  //  - asin, acos: r/√(1 − m²), m = |mid| + r < 1 − 2^−10 (the largest slope on the interval);
  //  - exp: r·v·(1 + 2^−10), v = e^mid rounded (e^r − 1 ≤ r(1 + r), e^mid ≤ v(1 + 2^(1−bits)),
  //    bits ≥ 16);
  //  - log: r/(mid − r).
  static bool trig_spread(mpfr_ptr out, mpfr_srcptr v, mpfr_srcptr, mpfr_srcptr r) {
    mpfr_abs(out, v, MPFR_RNDD);
    mpfr_nextbelow(out);  // ≤ |f(mid)|: v is within half an ulp of it
    if (mpfr_sgn(out) > 0) {
      mpfr_sqr(out, out, MPFR_RNDD);
      mpfr_ui_sub(out, 1, out, MPFR_RNDU);
      if (mpfr_sgn(out) < 0) mpfr_set_ui(out, 0, MPFR_RNDN);
      mpfr_sqrt(out, out, MPFR_RNDU);
    } else {
      mpfr_set_ui(out, 1, MPFR_RNDN);
    }
    mpfr_mul(out, out, r, MPFR_RNDU);
    mpfr_fma(out, r, r, out, MPFR_RNDU);
    return true;
  }
  static bool arc_slope(mpfr_ptr out, mpfr_srcptr, mpfr_srcptr mid, mpfr_srcptr r) {
    mpfr_abs(out, mid, MPFR_RNDU);
    mpfr_add(out, out, r, MPFR_RNDU);
    if (mpfr_cmp_d(out, 1 - 1.0 / 1024) >= 0) return false;
    mpfr_sqr(out, out, MPFR_RNDU);
    mpfr_ui_sub(out, 1, out, MPFR_RNDD);
    mpfr_sqrt(out, out, MPFR_RNDD);
    mpfr_div(out, r, out, MPFR_RNDU);
    return true;
  }
  static bool exp_spread(mpfr_ptr out, mpfr_srcptr v, mpfr_srcptr, mpfr_srcptr r) {
    if (mpfr_get_prec(out) < 16) return false;
    mpfr_mul(out, v, r, MPFR_RNDU);
    mpfr_mul_d(out, out, 1 + 1.0 / 1024, MPFR_RNDU);
    return true;
  }
  static bool log_spread(mpfr_ptr out, mpfr_srcptr, mpfr_srcptr mid, mpfr_srcptr r) {
    mpfr_sub(out, mid, r, MPFR_RNDD);
    if (mpfr_sgn(out) <= 0) return false;
    mpfr_div(out, r, out, MPFR_RNDU);
    return true;
  }
  template <class F>
  Interval unary(F f) {
    f(v_, v_);
    return std::move(*this);
  }

  mpfi_t v_;
  bool owns_ = true;  // false once moved from
};

// The certain sign of a − b, or undecided where they overlap.
inline Sign compare(const Interval& a, const Interval& b) { return (a - b).sign(); }

}  // namespace vibrofric
