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

}  // namespace

SineEnclosure enclose_sine(const exact::Rational& beta, const exact::Rational& gamma, mpfr_prec_t bits) {
  if (!(beta > 0)) throw InputError("beta = " + beta.str() + ": expected a number > 0");
  if (!(gamma > -1)) throw DomainError("gamma = " + gamma.str() + " gives no contact for wave sine: expected gamma > -1");
  SineEnclosure e(bits);
  const Interval B = of(beta, bits), G = of(gamma, bits), one = Interval::integer(1, bits);
  const Interval two_pi = Interval::pi(bits) * 2;
  e.jumping = gamma < 1;
  // 1 − γ² > 0 in the jumping range; contact begins at φ_c = asin(−γ)/2π ∈ (−1/4, 1/4).
  const std::optional<Interval> root = e.jumping ? std::optional<Interval>(sqrt(one - G * G)) : std::nullopt;
  e.beta_c = gamma >= 0 ? two_pi : two_pi * *root;
  if (e.jumping) {
    const Interval contact = asin(-G) / two_pi;
    e.normal_area = G * (one / Interval::integer(2, bits) - contact * 2) + *root / Interval::pi(bits);
  } else {
    e.normal_area = G;
  }
  if (decide(B - e.beta_c, "beta against beta_c (Eq. 6)") == Sign::positive) {  // never 0: β_c is irrational
    e.mu = one;
    e.retained_area = e.normal_area;
    e.lost_area = Interval(bits);
    return e;
  }
  e.stick = true;
  // Where n' = β on the far side of n's steepest point: φ = acos(β/2π)/2π ∈ (0, 1/4).
  const Interval c = B / two_pi;
  const Interval top = acos(c) / two_pi;
  e.onset_at_contact = gamma < 0 || (e.jumping && decide(B - two_pi * *root, "beta against n' at first contact") == Sign::negative);
  const Interval phi1 = e.onset_at_contact ? asin(-G) / two_pi : -top;
  const Interval level = e.onset_at_contact ? Interval(bits) : G - sqrt(one - c * c);
  // F = n − ramp is largest at `top` and falls to the end of contact (jumping) or to 1 − top
  // (where it is −β): the end's bracket.
  const Interval right = e.jumping ? one / Interval::integer(2, bits) - asin(-G) / two_pi : one - top;
  auto F = [&](const Interval& x) { return G + sin(two_pi * x) - level - B * (x - phi1); };
  auto dF = [&](const Interval& x) { return two_pi * cos(two_pi * x) - B; };
  mpfr lo = top.upper(), hi = right.lower();
  if (decide(F(point(lo, bits)), "n above the ramp after the onset") != Sign::positive ||
      decide(F(point(hi, bits)), "n below the ramp at the bracket's end") != Sign::negative)
    throw SolverError("sine, beta = " + beta.str() + ", gamma = " + gamma.str() + ": the stick end has no sign change in its bracket");
  // Bisection until F' < 0 certainly on the bracket (near `top` it is 0), then interval Newton.
  for (int k = 0;; ++k) {
    if (k > static_cast<int>(bits) + 64)
      throw Undecided("sine: the stick end's bracket does not separate from n's turning point");
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
    if (!next) throw SolverError("sine: interval Newton lost the stick end (a bug)");
    const bool shrank = next->width() < X.width() / 2;
    X = *next;
    if (!shrank) break;
  }
  e.onset = phi1;
  e.end = X;
  e.level = level;
  // lost = ∫_{φ1}^{φ2} (n − ramp) = A(φ2) − A(φ1) − level·L − β L²/2, L = φ2 − φ1, A = γφ − cos(2πφ)/2π.
  auto A = [&](const Interval& x) { return G * x - cos(two_pi * x) / two_pi; };
  const Interval L = X - phi1;
  e.lost_area = A(X) - A(phi1) - level * L - B * sqr(L) / Interval::integer(2, bits);
  e.retained_area = e.normal_area - e.lost_area;
  e.mu = e.retained_area / e.normal_area;
  return e;
}

}  // namespace vibrofric::certified
