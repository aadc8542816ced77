// Periodic waveforms w(φ) of Eq. (2): unit period, zero mean, unit amplitude; the catalogue of
// model.md (the paper's Eq. 16 for tri, str, stl) and user waveforms (Fourier series, samples).
//
// A waveform is a list of pieces [x_i, x_{i+1}] covering [0, 1). On each piece it has one smooth
// branch, valid on the closed piece (so the ends give one-sided limits and jumps are seen), and
// on each piece both w and w' are monotone. The solver relies on this: every event of Eqs. (4)
// and (8) is then the single root of a monotone function on a known bracket.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <tuple>
#include <type_traits>
#include <string>
#include <vector>

#include "vibrofric/core/detail/roots.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

namespace detail {

template <class Real>
inline constexpr bool wider_than_hardware_v = std::numeric_limits<Real>::digits > std::numeric_limits<long double>::digits;

// sin x and cos x together (one MPFR call for mpfr).
template <class Real>
std::pair<Real, Real> sin_cos(const Real& x) {
  Real s, c;
  if constexpr (std::is_same_v<Real, boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>,
                                                                 boost::multiprecision::et_off>>) {
    mpfr_sin_cos(s.backend().data(), c.backend().data(), x.backend().data(), MPFR_RNDN);
  } else {
    using std::cos;
    using std::sin;
    s = sin(x);
    c = cos(x);
  }
  return {std::move(s), std::move(c)};
}

// Reduced-precision steps (coarse_halley, coarse_sine_newton) pay from 500 bits: below, the first
// would run at a third of the working precision or more, and its temporaries cost more than it
// saves (measured 5-8% slower at 50 digits, equal at 100). So does the trig anchor (TrigAnchor):
// below, its Taylor terms, rotation and temporaries cost about what the calls it saves do
// (measured with it everywhere: the flat sine 1.00-1.03 of the time without at 50 and 100 digits,
// the curved sphere 1.09-1.12 at 20 and 50; from 500 bits 0.88 at 300 digits, 0.77 at 1000).
inline constexpr long coarse_from_bits = 500;
template <class Real>
bool coarse_steps_pay() {
  if constexpr (is_runtime_precision_v<Real>)
    return boost::multiprecision::detail::digits10_2_2(mpfr::thread_default_precision()) >= coarse_from_bits;
  else
    return false;
}

// Halley steps on sin h = t (acos_fast) at the precision each can use: a guess with `bits`
// correct bits comes out with about 3·bits, so a step needs 3·bits + 16, not h's precision.
// Stops while a step at h's own precision is still to come; acos_fast's loop takes it there
// and decides convergence. mpfr only (raw MPFR: each step's numbers at their own precision).
// From coarse_from_bits.
inline void coarse_halley(mpfr& h, const mpfr& t) {
  const mpfr_ptr hp = h.backend().data();
  const mpfr_prec_t full = mpfr_get_prec(hp);
  if (full < coarse_from_bits) return;
  mpfr_t x, s, c, f, num, den;
  mpfr_inits2(full, x, s, c, f, num, den, static_cast<mpfr_ptr>(nullptr));
  for (mpfr_prec_t bits = 50; 3 * bits + 16 < full; bits *= 3) {
    const mpfr_prec_t q = 3 * bits + 16;
    for (mpfr_ptr v : {x, s, c, f, num, den}) mpfr_set_prec(v, q);
    mpfr_set(x, hp, MPFR_RNDN);
    mpfr_sin_cos(s, c, x, MPFR_RNDN);
    mpfr_sub(f, s, t.backend().data(), MPFR_RNDN);
    mpfr_mul(num, f, c, MPFR_RNDN);  // Δ = 2 f c / (2 c² + f s), as in acos_fast
    mpfr_mul_2ui(num, num, 1, MPFR_RNDN);
    mpfr_sqr(den, c, MPFR_RNDN);
    mpfr_mul_2ui(den, den, 1, MPFR_RNDN);
    mpfr_fma(den, f, s, den, MPFR_RNDN);
    mpfr_div(num, num, den, MPFR_RNDN);
    mpfr_sub(hp, x, num, MPFR_RNDN);
  }
  mpfr_clears(x, s, c, f, num, den, static_cast<mpfr_ptr>(nullptr));
}

// Newton steps on sin 2πx − βx + k = 0 (a sine's stick end, Eq. 8, solver.hpp) at the precision
// each can use: a guess with `bits` correct bits comes out with about 2·bits, so a step needs
// 2·bits + 16. Stops once x has a quarter of its precision: the caller's Newton takes it from
// there at full precision, with one sin_cos at its first iterate and Taylor from it after
// (TrigAnchor: terms of 2^−full/4 converge in four), which costs less than the steps at half
// and at full precision here (measured on the bench's 12 sine inputs: 0.85–0.89 of the solve's
// time at 1000 digits, 0.94–0.97 at 300). Stops too at a step not below half the one before
// (near a tangency, where the guess is not yet in Newton's quadratic range): x then keeps the
// last value before it. From coarse_from_bits.
inline void coarse_sine_newton(mpfr& x, const mpfr& beta, const mpfr& k, const mpfr& two_pi) {
  const mpfr_ptr xp = x.backend().data();
  const mpfr_prec_t full = mpfr_get_prec(xp);
  if (full < coarse_from_bits) return;
  mpfr_t y, s, c, d, dd, last;
  mpfr_inits2(full, y, s, c, d, dd, last, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_inf(last, 1);
  for (mpfr_prec_t bits = 50; 2 * bits + 16 < full && 4 * bits < full; bits *= 2) {
    const mpfr_prec_t q = 2 * bits + 16;
    for (mpfr_ptr v : {y, s, c, d, dd}) mpfr_set_prec(v, q);
    mpfr_mul(y, two_pi.backend().data(), xp, MPFR_RNDN);
    mpfr_sin_cos(s, c, y, MPFR_RNDN);
    mpfr_mul(d, beta.backend().data(), xp, MPFR_RNDN);
    mpfr_sub(d, s, d, MPFR_RNDN);
    mpfr_add(d, d, k.backend().data(), MPFR_RNDN);  // sin 2πx − βx + k
    mpfr_mul(dd, two_pi.backend().data(), c, MPFR_RNDN);
    mpfr_sub(dd, dd, beta.backend().data(), MPFR_RNDN);  // its slope 2π cos 2πx − β
    if (mpfr_zero_p(dd)) break;
    mpfr_div(d, d, dd, MPFR_RNDN);  // the step
    mpfr_abs(s, d, MPFR_RNDN);
    mpfr_mul_2si(c, s, 1, MPFR_RNDN);
    if (mpfr_cmp(c, last) > 0) break;
    mpfr_set(last, s, MPFR_RNDN);
    mpfr_sub(xp, xp, d, MPFR_RNDN);
  }
  mpfr_clears(y, s, c, d, dd, last, static_cast<mpfr_ptr>(nullptr));
}

// Sine and cosine near an anchor (mpfr). One MPFR sin_cos at an anchor phase θ, taken at
// trig_guard_bits above the working precision p, gives those of any phase x = σθ + jπ/2 + δ
// (σ = ±1, j an integer, |δ| small) by Taylor of δ and a rotation. They are rounded to p bits
// only where mpfr_can_round decides the correctly rounded value, so a result is MPFR's own
// sin_cos at x, bit for bit, or there is none and the caller makes the call. acos_fast anchors
// at its first full-precision Halley iterate h: its later iterates are near h, and the sine's
// contact boundary and onset (Eq. 4), whose 2π-phase is jπ/2 ± 2h, near 2h.
inline constexpr mpfr_prec_t trig_guard_bits = 64;

// x = σθ + jπ/2 + δ with the σ and |j| ≤ 4 that make |δ| least; sin x and cos x to the precision of
// s and c from S ≈ sin θ, C ≈ cos θ within err·2^−P absolute (P = prec(S) ≥ prec(x), prec(s) + 32).
// The error of the result before rounding, absolute (every value is at most 1 in size), in 2^−P:
//  - the anchor's, err·(|cos δ| + |sin δ|) ≤ 1.5·err;
//  - δ's: π/2 at P bits and j·π/2 (8), x − σθ (4, as |x − σθ| < 8);
//  - Taylor's: the first term left out (below 2^−(P+4)) and half an ulp per term added (m);
//  - the rotation's fmma and the roundings of S·cos δ's partial terms: 2.
// That is at most 1.5·err + 14 + m; rounding is decided against twice that. More than 24 terms
// (|δ| near 2^−P/24) cost more than the call: refused.
inline bool sin_cos_near(mpfr_srcptr x, mpfr_srcptr theta, mpfr_srcptr S, mpfr_srcptr C, int err, mpfr_ptr s,
                         mpfr_ptr c) {
  const mpfr_prec_t P = mpfr_get_prec(S), p = std::max(mpfr_get_prec(s), mpfr_get_prec(c));
  if (err < 0 || err > 64 || P < p + 32 || mpfr_get_prec(x) > P) return false;
  mpfr_t hp, d, best, t, sd, cd, u, v;
  mpfr_inits2(P, hp, d, best, t, sd, cd, u, v, static_cast<mpfr_ptr>(nullptr));
  struct Clear {
    mpfr_ptr a[8];
    ~Clear() {
      for (mpfr_ptr z : a) mpfr_clear(z);
    }
  } clear{{hp, d, best, t, sd, cd, u, v}};
  mpfr_const_pi(hp, MPFR_RNDN);
  mpfr_div_2ui(hp, hp, 1, MPFR_RNDN);
  int sigma = 0;
  long j = 0;
  for (int sg : {1, -1}) {
    (sg > 0 ? mpfr_sub : mpfr_add)(d, x, theta, MPFR_RNDN);
    const double q = std::nearbyint(mpfr_get_d(d, MPFR_RNDN) / mpfr_get_d(hp, MPFR_RNDN));
    if (!(std::abs(q) <= 4)) continue;
    mpfr_mul_si(t, hp, static_cast<long>(q), MPFR_RNDN);
    mpfr_sub(d, d, t, MPFR_RNDN);
    if (sigma == 0 || mpfr_cmpabs(d, best) < 0) {
      mpfr_swap(d, best);
      sigma = sg;
      j = static_cast<long>(q);
    }
  }
  if (sigma == 0 || (!mpfr_zero_p(best) && 24 * (1 - mpfr_get_exp(best)) < P + 4)) return false;
  // sin δ and cos δ: Taylor to terms below 2^−(P+4) (at most 24, by the test above).
  mpfr_set(sd, best, MPFR_RNDN);
  mpfr_set_ui(cd, 1, MPFR_RNDN);
  mpfr_set(t, best, MPFR_RNDN);
  int terms = 0;
  for (unsigned long n = 2; !mpfr_zero_p(t); ++n, ++terms) {
    mpfr_mul(t, t, best, MPFR_RNDN);
    mpfr_div_ui(t, t, n, MPFR_RNDN);
    if (mpfr_zero_p(t) || mpfr_get_exp(t) < -(P + 4)) break;
    switch (n % 4) {
      case 2: mpfr_sub(cd, cd, t, MPFR_RNDN); break;
      case 3: mpfr_sub(sd, sd, t, MPFR_RNDN); break;
      case 0: mpfr_add(cd, cd, t, MPFR_RNDN); break;
      default: mpfr_add(sd, sd, t, MPFR_RNDN); break;
    }
  }
  // sin(σθ + δ) = σS cos δ + C sin δ, cos(σθ + δ) = C cos δ − σS sin δ.
  if (sigma > 0) {
    mpfr_fmma(u, S, cd, C, sd, MPFR_RNDN);
    mpfr_fmms(v, C, cd, S, sd, MPFR_RNDN);
  } else {
    mpfr_fmms(u, C, sd, S, cd, MPFR_RNDN);
    mpfr_fmma(v, C, cd, S, sd, MPFR_RNDN);
  }
  // Then j quarter turns.
  switch (((j % 4) + 4) % 4) {
    case 1: mpfr_swap(u, v); mpfr_neg(v, v, MPFR_RNDN); break;
    case 2: mpfr_neg(u, u, MPFR_RNDN); mpfr_neg(v, v, MPFR_RNDN); break;
    case 3: mpfr_swap(u, v); mpfr_neg(u, u, MPFR_RNDN); break;
    default: break;
  }
  const double bound = 2 * (1.5 * err + 14 + terms);
  const auto above = static_cast<mpfr_exp_t>(std::ceil(std::log2(bound)));
  for (mpfr_srcptr z : {static_cast<mpfr_srcptr>(u), static_cast<mpfr_srcptr>(v)}) {
    if (mpfr_zero_p(z)) return false;
    const mpfr_exp_t bits = mpfr_get_exp(z) + P - above;
    if (bits <= 0 || !mpfr_can_round(z, bits, MPFR_RNDN, MPFR_RNDZ, (z == u ? mpfr_get_prec(s) : mpfr_get_prec(c)) + 1))
      return false;
  }
  mpfr_set(s, u, MPFR_RNDN);
  mpfr_set(c, v, MPFR_RNDN);
  return true;
}

// The anchor of acos_fast's Halley loop (mpfr): its first full-precision iterate h and the sine
// and cosine of h at trig_guard_bits more (from one MPFR call). Empty until set; costs nothing
// for the other types, which never set it.
class TrigAnchor {
 public:
  TrigAnchor() = default;
  TrigAnchor(const TrigAnchor&) = delete;
  TrigAnchor& operator=(const TrigAnchor&) = delete;
  ~TrigAnchor() {
    if (set_) mpfr_clears(h_, s_, c_, static_cast<mpfr_ptr>(nullptr));
  }
  bool empty() const { return !set_; }
  void set(mpfr_srcptr h) {
    if (!set_) {
      mpfr_init2(h_, mpfr_get_prec(h));
      mpfr_inits2(mpfr_get_prec(h) + trig_guard_bits, s_, c_, static_cast<mpfr_ptr>(nullptr));
      set_ = true;
    }
    mpfr_set_prec(h_, mpfr_get_prec(h));
    mpfr_set(h_, h, MPFR_RNDN);  // exact
    mpfr_set_prec(s_, mpfr_get_prec(h) + trig_guard_bits);
    mpfr_set_prec(c_, mpfr_get_prec(h) + trig_guard_bits);
    mpfr_sin_cos(s_, c_, h_, MPFR_RNDN);
  }
  // sin x, cos x near ±h + jπ/2 (a later Halley iterate; a later phase of the sine's trig).
  bool near(mpfr_srcptr x, mpfr_ptr s, mpfr_ptr c) const { return set_ && sin_cos_near(x, h_, s_, c_, 1, s, c); }
  // sin x, cos x near ±2h + jπ/2 (the acos 2h, and π − 2h): from sin 2h = 2SC, cos 2h = 1 − 2S²
  // (each within 4·2^−P: the anchor's half ulps doubled, and the products' roundings).
  bool near_twice(mpfr_srcptr x, mpfr_ptr s, mpfr_ptr c) const {
    if (!set_) return false;
    const mpfr_prec_t P = mpfr_get_prec(s_);
    mpfr_t h2, s2, c2;
    mpfr_init2(h2, mpfr_get_prec(h_));
    mpfr_inits2(P, s2, c2, static_cast<mpfr_ptr>(nullptr));
    mpfr_mul_2ui(h2, h_, 1, MPFR_RNDN);  // exact
    mpfr_mul(s2, s_, c_, MPFR_RNDN);
    mpfr_mul_2ui(s2, s2, 1, MPFR_RNDN);
    mpfr_sqr(c2, s_, MPFR_RNDN);
    mpfr_mul_2ui(c2, c2, 1, MPFR_RNDN);
    mpfr_ui_sub(c2, 1, c2, MPFR_RNDN);
    const bool ok = sin_cos_near(x, h2, s2, c2, 4, s, c);
    mpfr_clears(h2, s2, c2, static_cast<mpfr_ptr>(nullptr));
    return ok;
  }

 private:
  bool set_ = false;
  mpfr_t h_, s_, c_;
};

// cbrt(ε)/16, acos_fast's step tolerance: one cbrt per precision and thread, not one per call (at
// 1000 digits that call was a third of a sine point's full-precision calls). The same number.
template <class Real>
const Real& halley_tolerance() {
  using std::cbrt;
  if constexpr (is_runtime_precision_v<Real>) {
    thread_local unsigned digits = 0;
    thread_local Real tol;
    if (const unsigned now = mpfr::thread_default_precision(); now != digits) {
      const Real fresh = cbrt(std::numeric_limits<Real>::epsilon()) / 16;
      mpfr_set_prec(tol.backend().data(), mpfr_get_prec(fresh.backend().data()));
      mpfr_set(tol.backend().data(), fresh.backend().data(), MPFR_RNDN);
      digits = now;
    }
    return tol;
  } else {
    static const Real tol = cbrt(std::numeric_limits<Real>::epsilon()) / 16;
    return tol;
  }
}

// acos y for y ∈ [−1, 1]. Beyond long double: Halley's iteration on sin(θ/2) = √((1 − y)/2)
// from a double guess (two steps to 100 digits; θ/2 ≤ π/4 keeps it well conditioned, and small
// θ stays relatively accurate), as MPFR's acos goes through atan and costs five sin_cos. In
// mpfr from coarse_from_bits the steps before the last run at reduced precision (coarse_halley),
// and one sin_cos at the first full-precision iterate serves the later ones (TrigAnchor);
// `anchor`, if given, keeps it for the caller.
template <class Real>
Real acos_fast(const Real& y, TrigAnchor* anchor = nullptr) {
  using std::acos;
  if constexpr (!wider_than_hardware_v<Real>) {
    return acos(y);
  } else {
    using std::abs;
    using std::sqrt;
    if (y < 0) return boost::math::constants::pi<Real>() - acos_fast(Real(-y), anchor);
    if (y >= 1) return Real(0);
    const Real t = sqrt((1 - y) / 2);
    Real h = std::asin(static_cast<double>(t));
    // A guess of 0 (t below double's range) has no correct bits to triple.
    if constexpr (is_runtime_precision_v<Real>)
      if (h != 0) coarse_halley(h, t);
    const Real& tol = halley_tolerance<Real>();
    [[maybe_unused]] TrigAnchor own;
    TrigAnchor* const anchored = coarse_steps_pay<Real>() ? (anchor ? anchor : &own) : nullptr;
    // The iteration's numbers, made once; each step is the expression in its comment, in place
    // with the same roundings (an mpfr temporary is an allocation).
    Real sh, ch, f, num, den, u;
    for (int it = 0; it < 64; ++it) {
      if constexpr (is_runtime_precision_v<Real>) {
        if (anchored && anchored->empty()) anchored->set(h.backend().data());
        if (!anchored || !anchored->near(h.backend().data(), sh.backend().data(), ch.backend().data()))
          std::tie(sh, ch) = sin_cos(h);
      } else {
        std::tie(sh, ch) = sin_cos(h);
      }
      difference(f, sh, t);  // f = sin h − t
      if (f == 0) break;
      // Halley: Δ = 2 f f' / (2 f'² − f f''), with f' = cos h, f'' = −sin h:
      // Δ = 2·f·ch / (2·ch·ch + f·sh).
      num = f;
      num *= 2;
      num *= ch;
      den = ch;
      den *= 2;
      den *= ch;
      u = f;
      u *= sh;
      den += u;
      num /= den;
      h -= num;
      u = h;  // tol·|h|
      if (u < 0) negate(u);
      u *= tol;
      if (abs_le(num, u)) {
        h *= 2;
        return h;
      }
    }
    if (abs(sin_cos(h).first - t) <= 4 * std::numeric_limits<Real>::epsilon() * t) return 2 * h;
    throw SolverError("acos(" + short_str(y) + "): Halley iteration did not converge");
  }
}

}  // namespace detail

// How a user waveform was brought to zero mean and unit amplitude: w = (raw − offset) / scale,
// with scale = (max − min)/2 of the zero-mean signal, so that max w − min w = 2.
template <class Real>
struct Normalisation {
  bool applied = false;  // false for the catalogue, which is normalised by definition
  Real offset = 0;       // mean of the raw signal
  Real scale = 1;        // half the raw peak-to-peak amplitude
};

template <class Real>
class Waveform {
 public:
  virtual ~Waveform() = default;

  const std::string& name() const { return name_; }
  std::size_t piece_count() const { return begins_.size(); }
  const Real& piece_begin(std::size_t i) const { return begins_[i]; }
  const Real& piece_end(std::size_t i) const { return ends_[i]; }

  // Smooth branch of piece i at φ ∈ [x_i, x_{i+1}], its slope, and (if has_antiderivative) an
  // antiderivative; only differences within one piece are meaningful.
  virtual Real value(std::size_t i, const Real& phi) const = 0;
  virtual Real slope(std::size_t i, const Real& phi) const = 0;
  virtual bool has_antiderivative() const { return false; }
  virtual Real antiderivative(std::size_t, const Real&) const {
    throw SolverError("waveform " + name_ + " has no antiderivative");
  }
  // value and slope at one phase (a waveform may share the work, as sin and cos do).
  virtual std::pair<Real, Real> value_and_slope(std::size_t i, const Real& phi) const { return {value(i, phi), slope(i, phi)}; }
  // Double-precision shadows of value and slope, for initial guesses only (the default converts
  // through Real; waveforms override them with their own double formulas).
  virtual double approx_value(std::size_t i, double phi) const { return static_cast<double>(value(i, Real(phi))); }
  virtual double approx_slope(std::size_t i, double phi) const { return static_cast<double>(slope(i, Real(phi))); }
  // Closed-form solutions on piece i, where known: φ with value(i, φ) = y, φ with slope = b.
  // Called only when the root exists on the piece; the generic root finder is the fallback.
  virtual std::optional<Real> solve_value(std::size_t, const Real&) const { return std::nullopt; }
  virtual std::optional<Real> solve_slope(std::size_t, const Real&) const { return std::nullopt; }
  // A guess x of the root of w(x) − βx + k on piece i (a stick end, Eq. 8), good to about 50
  // bits, refined at reduced precision where the wave knows how (the sine in mpfr); the
  // caller's Newton at the working precision finishes it. Default: x as it is.
  virtual void coarse_ramp_root(std::size_t, Real&, const Real& /*beta*/, const Real& /*k*/) const {}
  // Why the current working precision cannot resolve this waveform ("" if it can): the solver's
  // rounding bounds take n' as nearly constant over a phase's rounding error.
  virtual std::string unresolved() const { return {}; }
  // Errors of the wave in this type beyond the solver's own allowances (solver.hpp: eps times
  // |γ| + max − min per value, eps·|W| per antiderivative value W), in units of eps: a bound on
  // |value(i, φ) − w(φ)| at every φ, where w is the exact wave the input defines, and on the
  // rounding of antiderivative(i, φ). They cover the wave's representation (coefficients,
  // normalisation, sample phases rounded to the type) and evaluations whose rounding is not
  // proportional to the result (a sum of harmonics; an antiderivative that cancels within its
  // piece). Near the contact edge the normal area is small and these errors dominate its
  // relative error (tests/robustness/test_stress.cpp found both). `value` is antiderivative(i, φ)
  // as the caller computed it (the bound scales with it; recomputing it cost a quarter of a solve).
  virtual Real value_error() const { return Real(0); }
  // The same bound on piece i alone (at most value_error()): an area over part of one piece needs
  // only its own (a sampled signal's steepest piece sets value_error for all the others).
  virtual Real value_error(std::size_t) const { return value_error(); }
  virtual Real antiderivative_error(std::size_t, const Real&, const Real& /*value*/) const { return Real(0); }

  // One-sided values and slopes at the piece ends, computed once.
  const Real& begin_value(std::size_t i) const { return begin_value_[i]; }
  const Real& end_value(std::size_t i) const { return end_value_[i]; }
  const Real& begin_slope(std::size_t i) const { return begin_slope_[i]; }
  const Real& end_slope(std::size_t i) const { return end_slope_[i]; }
  bool linear(std::size_t i) const { return begin_slope_[i] == end_slope_[i]; }
  bool convex(std::size_t i) const { return begin_slope_[i] <= end_slope_[i]; }

  // Right-continuous value and slope at any phase (reduced modulo 1).
  Real operator()(const Real& phi) const { return value(locate(phi), reduce(phi)); }
  Real slope_at(const Real& phi) const { return slope(locate(phi), reduce(phi)); }

  // True if w is discontinuous at breakpoint i (its one-sided limits differ by more than
  // rounding): only there can n jump. Continuous joins (samples, Fourier) are never jumps.
  bool jump_at(std::size_t i) const { return jump_[i]; }

  const Real& minimum() const { return min_; }
  const Real& maximum() const { return max_; }
  // Index of the breakpoint where the minimum is reached (as a one-sided limit).
  std::size_t argmin_break() const { return argmin_; }
  const Normalisation<Real>& normalisation() const { return norm_; }

  // Piece i reduced to where γ + w > 0: returns false if there is no contact on the piece.
  bool contact_part(std::size_t i, const Real& gamma, Real& c0, Real& c1,
                    detail::RootStats& stats) const {
    c0 = begins_[i];
    c1 = ends_[i];
    const Real g0 = gamma + begin_value_[i], g1 = gamma + end_value_[i];
    if (g0 <= 0 && g1 <= 0) return false;
    if ((g0 < 0) != (g1 < 0)) {
      const Real c = solve_value_root(i, -gamma, c0, c1, g0, g1, stats);
      (g0 < 0 ? c0 : c1) = c;
    }
    return true;
  }

  // φ in [lo, hi] ⊂ piece i with value(i, φ) = y, where g_lo = value − y at lo, g_hi at hi.
  Real solve_value_root(std::size_t i, const Real& y, const Real& lo, const Real& hi,
                        const Real& g_lo, const Real& g_hi, detail::RootStats& stats) const {
    if (auto r = solve_value(i, y)) return clamp(*r, lo, hi);
    return detail::bracketed_root<Real>(
        [&](const Real& x) -> Real { return value(i, x) - y; }, lo, hi, g_lo, g_hi,
        "contact boundary (γ + w = 0)", stats);
  }

 protected:
  explicit Waveform(std::string name) : name_(std::move(name)) {}

  // Sets the pieces (begins[0] = 0, increasing, all < 1) and the extrema from the pieces' ends.
  void set_pieces(std::vector<Real> begins) {
    begins_ = std::move(begins);
    ends_.assign(begins_.begin() + 1, begins_.end());
    ends_.push_back(Real(1));
    const std::size_t m = begins_.size();
    begin_value_.clear();
    end_value_.clear();
    begin_slope_.clear();
    end_slope_.clear();
    for (std::size_t i = 0; i < m; ++i) {
      begin_value_.push_back(value(i, begins_[i]));
      end_value_.push_back(value(i, ends_[i]));
      begin_slope_.push_back(slope(i, begins_[i]));
      end_slope_.push_back(slope(i, ends_[i]));
    }
    min_ = max_ = begin_value_[0];
    argmin_ = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const Real &a = begin_value_[i], &b = end_value_[i];
      if (a < min_) { min_ = a; argmin_ = i; }
      if (b < min_) { min_ = b; argmin_ = (i + 1) % m; }
      if (a > max_) max_ = a;
      if (b > max_) max_ = b;
    }
    jump_.assign(m, false);
    using std::abs;
    const Real tiny = 64 * std::numeric_limits<Real>::epsilon() * (max_ - min_);
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t prev = (i + m - 1) % m;
      jump_[i] = abs(end_value_[prev] - begin_value_[i]) > tiny;
    }
  }

  Normalisation<Real> norm_;

 private:
  static Real reduce(const Real& phi) {
    using std::floor;
    Real r = phi - floor(phi);
    return r >= 1 ? Real(0) : r;
  }
  std::size_t locate(const Real& phi) const {
    const Real r = reduce(phi);
    std::size_t i = begins_.size() - 1;
    while (i > 0 && r < begins_[i]) --i;
    return i;
  }
  static Real clamp(const Real& x, const Real& lo, const Real& hi) {
    return x < lo ? lo : (x > hi ? hi : x);
  }

  std::string name_;
  std::vector<Real> begins_, ends_;
  std::vector<Real> begin_value_, end_value_, begin_slope_, end_slope_;
  std::vector<bool> jump_;
  Real min_ = 0, max_ = 0;
  std::size_t argmin_ = 0;
};

// sin 2πφ. Pieces split at the extrema (1/4, 3/4) and inflections (0, 1/2).
template <class Real>
class Sine final : public Waveform<Real> {
 public:
  Sine() : Waveform<Real>("sine") {
    const Real q = Real(1) / 4;
    this->set_pieces({Real(0), q, 2 * q, 3 * q});
  }
  Real value(std::size_t, const Real& phi) const override { return trig(phi).first; }
  std::pair<Real, Real> value_and_slope(std::size_t, const Real& phi) const override {
    const auto& [s, c] = trig(phi);
    return {s, two_pi_ * c};
  }
  double approx_value(std::size_t, double phi) const override { return std::sin(2 * M_PI * phi); }
  double approx_slope(std::size_t, double phi) const override { return 2 * M_PI * std::cos(2 * M_PI * phi); }
  Real slope(std::size_t, const Real& phi) const override { return two_pi_ * trig(phi).second; }
  bool has_antiderivative() const override { return true; }
  Real antiderivative(std::size_t, const Real& phi) const override { return -trig(phi).second / two_pi_; }
  // acos keeps the distance from the nearest extremum accurate (the contact width near γ = −1).
  // In mpfr the boundary's sine and cosine come from acos's own anchor (primed into trig's cache).
  std::optional<Real> solve_value(std::size_t i, const Real& y) const override {
    detail::TrigAnchor anchor;
    auto acos = [&](const Real& v) { return detail::acos_fast(v, is_runtime_precision_v<Real> ? &anchor : nullptr); };
    const Real q = Real(1) / 4;
    Real phase;
    switch (i) {
      case 0: phase = q - acos(y) / two_pi_; break;
      case 1: phase = q + acos(y) / two_pi_; break;
      case 2: phase = 3 * q - acos(Real(-y)) / two_pi_; break;
      default: phase = 3 * q + acos(Real(-y)) / two_pi_; break;
    }
    prime(phase, anchor);
    return phase;
  }
  void coarse_ramp_root(std::size_t, Real& x, const Real& beta, const Real& k) const override {
    if constexpr (is_runtime_precision_v<Real>) detail::coarse_sine_newton(x, beta, k, two_pi_);
  }
  // Rising pieces only (0 and 3): the solver asks for positive slopes.
  std::optional<Real> solve_slope(std::size_t i, const Real& b) const override {
    if (i != 0 && i != 3) return std::nullopt;
    detail::TrigAnchor anchor;
    const Real a = detail::acos_fast(Real(b / two_pi_), is_runtime_precision_v<Real> ? &anchor : nullptr);
    const Real phase = i == 0 ? Real(a / two_pi_) : Real(1 - a / two_pi_);
    prime(phase, anchor);
    return phase;
  }

 private:
  static Real two_pi() { return boost::math::constants::two_pi<Real>(); }

  // sin and cos 2πφ of the last phases asked for on this thread (at this precision): value,
  // slope and antiderivative at one event then cost one sin_cos. Every Sine is the same
  // function, so the cache needs no owner.
  struct TrigCache {
    struct Entry {
      int digits = -1;
      Real phi;
      std::pair<Real, Real> sc;
    };
    Entry last[4];
    int next = 0;
    std::pair<Real, Real>& put(const Real& phi) {
      Entry& e = last[next];
      next = (next + 1) % 4;
      e.digits = working_digits10<Real>();
      e.phi = phi;
      return e.sc;
    }
  };
  static TrigCache& cache() {
    thread_local TrigCache c;
    return c;
  }
  const std::pair<Real, Real>& trig(const Real& phi) const {
    TrigCache& cc = cache();
    const int d = working_digits10<Real>();
    for (const auto& e : cc.last)
      if (e.digits == d && e.phi == phi) return e.sc;
    auto& sc = cc.put(phi);
    sc = sin_cos_2pi(phi);
    return sc;
  }
  // mpfr from coarse_from_bits: the last argument whose sin_cos was called, as an anchor
  // (TrigAnchor) for the next ones.
  // A Newton iteration's phases (a stick end, Eq. 8) and the value at its root are near each
  // other: one call at 64 bits more, the rest by Taylor, each decided by mpfr_can_round.
  struct ArgAnchor {
    mpfr_prec_t bits = 0;
    detail::TrigAnchor a;
  };
  static ArgAnchor& arg_anchor() {
    thread_local ArgAnchor a;
    return a;
  }
  // φ = k/4 + r with |r| ≤ 1/8 and r exact (Sterbenz); returns k, and 2πr in `arg`.
  static long quarter_split(const Real& phi, const Real& two_pi, Real& arg) {
    using std::floor;
    long k;
    if constexpr (std::is_floating_point_v<Real>) {
      // From φ rounded to double, truncated by one SSE instruction: x87 rounding of long double
      // switches the control word twice (floor, then the conversion), measured 40 % of this
      // function. k may then be one off where 4φ + 1/2 is within a double rounding of an
      // integer; r is still exact and |2πr| ≤ π/4 + 2^-50, where sin and cos are as accurate.
      const double t = 4 * static_cast<double>(phi) + 0.5;
      k = static_cast<long>(t);
      if (t < static_cast<double>(k)) --k;
    } else {
      // floor(4φ + 1/2) as floor((8φ + 1)/2), and φ − k/4 as (4φ − k)/4, in place: scaling by
      // powers of two is exact, so the roundings are those of 4φ + 1/2 and φ − k/4.
      arg = phi;
      arg *= 8;
      arg += 1;
      arg /= 2;
      k = detail::floor_to_long(arg);
    }
    if constexpr (std::is_floating_point_v<Real>) {
      const Real r = phi - Real(k) / 4;
      arg = r == 0 ? Real(0) : Real(two_pi * r);
    } else {
      arg = phi;
      arg *= 4;
      arg -= k;
      arg /= 4;
      if (arg == 0)
        arg = 0;
      else
        arg *= two_pi;
    }
    return k;
  }
  // sin and cos of 2πr rotated by k quarter turns: those of 2πφ.
  static std::pair<Real, Real> quarter_turns(long k, Real s, Real c) {
    long q = k % 4;
    if (q < 0) q += 4;
    switch (q) {
      case 0: return {std::move(s), std::move(c)};
      case 1: detail::negate(s); return {std::move(c), std::move(s)};
      case 2: detail::negate(s); detail::negate(c); return {std::move(s), std::move(c)};
      default: detail::negate(c); return {std::move(c), std::move(s)};
    }
  }
  // sin 2πφ and cos 2πφ from the nearest quarter period: exact at the quarters, accurate near the
  // extrema, and it spares MPFR the hard-to-round arguments next to multiples of π/2.
  std::pair<Real, Real> sin_cos_2pi(const Real& phi) const {
    Real arg;
    const long k = quarter_split(phi, two_pi_, arg);
    if (arg == 0) return quarter_turns(k, Real(0), Real(1));
    if constexpr (is_runtime_precision_v<Real>) {
      if (detail::coarse_steps_pay<Real>()) {
        Real s, c;
        ArgAnchor& an = arg_anchor();
        const mpfr_srcptr x = arg.backend().data();
        if (an.bits == mpfr_get_prec(x) && an.a.near(x, s.backend().data(), c.backend().data()))
          return quarter_turns(k, std::move(s), std::move(c));
        an.bits = mpfr_get_prec(x);
        an.a.set(x);
        if (an.a.near(x, s.backend().data(), c.backend().data())) return quarter_turns(k, std::move(s), std::move(c));
      }
    }
    auto [s2, c2] = detail::sin_cos(arg);
    return quarter_turns(k, std::move(s2), std::move(c2));
  }
  // A phase whose acos anchor is at hand (mpfr): its sin_cos_2pi from the anchor into trig's
  // cache, where mpfr_can_round decides it (the same bits as the call); else nothing.
  void prime(const Real& phi, const detail::TrigAnchor& anchor) const {
    if constexpr (is_runtime_precision_v<Real>) {
      if (anchor.empty()) return;
      Real arg;
      const long k = quarter_split(phi, two_pi_, arg);
      if (arg == 0) return;
      Real s, c;
      if (!anchor.near_twice(arg.backend().data(), s.backend().data(), c.backend().data())) return;
      cache().put(phi) = quarter_turns(k, std::move(s), std::move(c));
    }
  }
  Real two_pi_ = two_pi();
};

// Piecewise linear through (x_i, y_i) with slope s_i on each piece: triangle, sawteeth, square
// (Eq. 16) and sampled user signals.
template <class Real>
class PiecewiseLinear : public Waveform<Real> {
 public:
  struct Piece {
    Real begin, anchor, slope;  // value = anchor + slope·(φ − begin)
  };
  PiecewiseLinear(std::string name, std::vector<Piece> pieces)
      : Waveform<Real>(std::move(name)), pieces_(std::move(pieces)) {
    std::vector<Real> begins;
    using std::abs;
    using std::frexp;
    for (const auto& p : pieces_) {
      begins.push_back(p.begin);
      int e = 0;
      exact_.push_back({Real(p.begin / 2), Real(2 * p.begin),
                        p.slope == 0 || abs(Real(frexp(p.slope, &e))) == Real(0.5)});
    }
    this->set_pieces(std::move(begins));
  }
  Real value(std::size_t i, const Real& phi) const override {
    const Piece& p = pieces_[i];
    return p.anchor + p.slope * (phi - p.begin);
  }
  Real slope(std::size_t i, const Real&) const override { return pieces_[i].slope; }
  bool has_antiderivative() const override { return true; }
  Real antiderivative(std::size_t i, const Real& phi) const override {
    const Piece& p = pieces_[i];
    const Real d = phi - p.begin;
    return d * (p.anchor + p.slope * d / 2);
  }
  // d = φ − begin, slope·d, the sum and the outer product each round once (first order):
  // W̃ = W + slope·d²(δ1 + δ2)/2 + W(δ1 + δ3 + δ4). δ1 = 0 where Sterbenz's lemma makes the
  // subtraction exact (begin = 0, or begin/2 ≤ φ ≤ 2·begin), δ2 = 0 where slope is a power of two
  // and d is exact (the catalogue's ±4, ±2). Where anchor and slope·d/2 cancel this exceeds the
  // solver's eps·|W| by far (samples next to a steep piece).
  Real antiderivative_error(std::size_t i, const Real& phi, const Real& value) const override {
    using std::abs;
    const Piece& p = pieces_[i];
    const Exactness& x = exact_[i];
    const bool d_exact = p.begin == 0 || (p.begin > 0 && phi >= x.half_begin && phi <= x.twice_begin);
    const bool product_exact = d_exact && x.slope_power_of_two;
    const int rounded = (d_exact ? 0 : 1) + (product_exact ? 0 : 1);
    if (rounded == 0) return abs(value);
    const Real d = phi - p.begin;
    return abs(p.slope) * d * d * rounded / 2 + abs(value) * (d_exact ? 1 : 2);
  }
  const Piece& piece(std::size_t i) const { return pieces_[i]; }
  std::optional<Real> solve_value(std::size_t i, const Real& y) const override {
    const Piece& p = pieces_[i];
    if (p.slope == 0) return std::nullopt;
    return p.begin + (y - p.anchor) / p.slope;
  }

 protected:
  std::vector<Piece> pieces_;

 private:
  // Where φ − begin is exact (Sterbenz) and whether slope·d is then exact (the catalogue's ±4, ±2).
  struct Exactness {
    Real half_begin, twice_begin;
    bool slope_power_of_two;
  };
  std::vector<Exactness> exact_;
};

template <class Real>
std::unique_ptr<Waveform<Real>> make_triangle() {
  using P = typename PiecewiseLinear<Real>::Piece;
  return std::make_unique<PiecewiseLinear<Real>>(
      "triangle", std::vector<P>{{Real(0), Real(-1), Real(4)}, {Real(1) / 2, Real(1), Real(-4)}});
}
template <class Real>
std::unique_ptr<Waveform<Real>> make_sawtooth_right() {
  using P = typename PiecewiseLinear<Real>::Piece;
  return std::make_unique<PiecewiseLinear<Real>>("sawtooth-right",
                                                 std::vector<P>{{Real(0), Real(-1), Real(2)}});
}
template <class Real>
std::unique_ptr<Waveform<Real>> make_sawtooth_left() {
  using P = typename PiecewiseLinear<Real>::Piece;
  return std::make_unique<PiecewiseLinear<Real>>("sawtooth-left",
                                                 std::vector<P>{{Real(0), Real(1), Real(-2)}});
}
template <class Real>
std::unique_ptr<Waveform<Real>> make_square() {
  using P = typename PiecewiseLinear<Real>::Piece;
  return std::make_unique<PiecewiseLinear<Real>>(
      "square", std::vector<P>{{Real(0), Real(1), Real(0)}, {Real(1) / 2, Real(-1), Real(0)}});
}

// power:p — 1 − |4φ − 1|^p on [0, 1/2), −(1 − |4φ − 3|^p) on [1/2, 1), p ≥ 1 (model.md).
// Near each peak it is exactly a power-law cap of order p. With u the distance to the nearest
// peak in units of 1/4, piece i has w = ±(1 − u^p).
template <class Real>
class Power final : public Waveform<Real> {
 public:
  explicit Power(const Real& p, std::string name)
      : Waveform<Real>(std::move(name)), p_(p), pd_(static_cast<double>(p)) {
    if (!(p >= 1))
      throw InputError("power:p needs p >= 1 (got " + detail::short_str(p) + ")");
    const Real q = Real(1) / 4;
    this->set_pieces({Real(0), q, 2 * q, 3 * q});
  }
  const Real& exponent() const { return p_; }
  // Near u = 1 (the flanks at φ = 0 and 1/2) n''/n' ≈ 4p: over a phase error of a few ulp n'
  // changes by a factor exp(16·p·eps), so p·eps must stay small. Above 2^-10/eps (double: p >
  // 4.4e12) the flank is left to more digits (the ladder escalates; 50 digits: p ≤ 1.9e47).
  std::string unresolved() const override {
    if (p_ * std::numeric_limits<Real>::epsilon() * 1024 <= 1) return {};
    return "power:p with p = " + detail::short_str(p_) + " has flanks (width ~1/p) that " +
           std::to_string(working_digits10<Real>()) + " digits do not resolve: expected p ≤ 2^-10/eps";
  }
  double approx_value(std::size_t i, double phi) const override {
    const double up = std::pow(static_cast<double>(distance(i, Real(phi))), pd_);
    return i < 2 ? 1 - up : up - 1;
  }
  double approx_slope(std::size_t i, double phi) const override {
    const double d = 4 * pd_ * std::pow(static_cast<double>(distance(i, Real(phi))), pd_ - 1);
    return (i == 0 || i == 3) ? d : -d;
  }
  Real value(std::size_t i, const Real& phi) const override {
    using std::pow;
    const Real up = pow(distance(i, phi), p_);
    return i < 2 ? 1 - up : up - 1;
  }
  Real slope(std::size_t i, const Real& phi) const override {
    using std::pow;
    const Real d = 4 * p_ * pow(distance(i, phi), p_ - 1);
    return (i == 0 || i == 3) ? d : Real(-d);
  }
  bool has_antiderivative() const override { return true; }
  Real antiderivative(std::size_t i, const Real& phi) const override {
    using std::pow;
    // d/dφ [u^{p+1}/(4(p+1))] = u^p·(du/dφ)/4, with du/dφ = −4, +4, −4, +4 on pieces 0–3.
    const Real t = pow(distance(i, phi), p_ + 1) / (4 * (p_ + 1));
    switch (i) {
      case 0: return phi + t;
      case 1: return phi - t;
      case 2: return -phi - t;
      default: return -phi + t;
    }
  }
  std::optional<Real> solve_value(std::size_t i, const Real& y) const override {
    using std::pow;
    const Real u = pow(i < 2 ? Real(1 - y) : Real(1 + y), 1 / p_);
    return from_distance(i, u);
  }
  std::optional<Real> solve_slope(std::size_t i, const Real& b) const override {
    using std::pow;
    if (p_ == 1 || (i != 0 && i != 3)) return std::nullopt;
    return from_distance(i, pow(b / (4 * p_), 1 / (p_ - 1)));
  }

 private:
  // u ∈ [0, 1]: distance from the peak of the piece's half-wave, in units of 1/4.
  static Real distance(std::size_t i, const Real& phi) {
    switch (i) {
      case 0: return 1 - 4 * phi;
      case 1: return 4 * phi - 1;
      case 2: return 3 - 4 * phi;
      default: return 4 * phi - 3;
    }
  }
  static Real from_distance(std::size_t i, const Real& u) {
    switch (i) {
      case 0: return (1 - u) / 4;
      case 1: return (1 + u) / 4;
      case 2: return (3 - u) / 4;
      default: return (3 + u) / 4;
    }
  }
  Real p_;
  double pd_;
};

}  // namespace vibrofric
