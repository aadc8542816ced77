// Bracketed root finding at the working precision (Eqs. 4 and 8 are solved through this).
// A root that is not bracketed, or a solver that runs out of iterations, is a SolverError.
#pragma once
#include <boost/math/tools/precision.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <charconv>
#include <cstdint>
#include <ios>
#include <limits>
#include <string>
#include <type_traits>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric::detail {

struct RootStats {
  std::size_t solves = 0;
  std::size_t iterations = 0;
  std::uintmax_t max_iterations = 200;
};

// x for messages: enough digits to tell it from a nearby value (the type's round-trip digits,
// at most 40), shortest form.
// As a stream with that precision would print it (printf's %g; Boost's str with a stream's
// default flags), without a stream: the core reads and writes no text streams.
template <class Real>
std::string short_str(const Real& x) {
  const int max = std::numeric_limits<Real>::max_digits10;
  const int d = max > 0 && max < 40 ? max : 40;
  if constexpr (std::is_floating_point_v<Real>) {
    char buf[80];
    const auto end = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, d).ptr;
    return std::string(buf, end);
  } else {
    return x.str(d, std::ios_base::skipws | std::ios_base::dec);
  }
}

// Root of f in [a, b] given fa = f(a), fb = f(b) of opposite signs (a zero end is the root),
// to within 4 ulp of the working type: toms748, stopping on |b − a| ≤ 2^(2−digits)·min(|a|,|b|),
// or ≤ 2^(2−digits)·scale where a positive `scale` is the size of x that f's rounding is relative
// to (a phase of the period: 1). Without it a root within rounding of x = 0, where f is noise,
// asks for a bracket a few ulp of the root wide and never gets one.
template <class Real, class F>
Real bracketed_root(F f, const Real& a, const Real& b, const Real& fa, const Real& fb,
                    const char* what, RootStats& stats, const Real& scale = Real(0)) {
  if (fa == 0) return a;
  if (fb == 0) return b;
  if ((fa > 0) == (fb > 0))
    throw SolverError(std::string(what) + ": no sign change on [" + short_str(a) + ", " +
                      short_str(b) + "] (f = " + short_str(fa) + ", " + short_str(fb) + ")");
  const int bits = boost::math::tools::digits<Real>();
  boost::math::tools::eps_tolerance<Real> relative(static_cast<unsigned>(bits > 3 ? bits - 2 : 1));
  using std::ldexp;
  const Real floor = scale * ldexp(Real(1), 2 - bits);
  auto tol = [&](const Real& x, const Real& y) {
    using std::abs;
    return relative(x, y) || abs(x - y) <= floor;
  };
  std::uintmax_t iterations = stats.max_iterations;
  std::pair<Real, Real> r;
  try {
    r = boost::math::tools::toms748_solve(f, a, b, fa, fb, tol, iterations);
  } catch (const std::exception& e) {
    throw SolverError(std::string(what) + ": root finder failed on [" + short_str(a) + ", " +
                      short_str(b) + "]: " + e.what());
  }
  ++stats.solves;
  stats.iterations += iterations;
  if (iterations >= stats.max_iterations && !tol(r.first, r.second))
    throw SolverError(std::string(what) + ": root finder did not converge in " +
                      std::to_string(stats.max_iterations) + " iterations on [" +
                      short_str(a) + ", " + short_str(b) + "]");
  return (r.first + r.second) / 2;
}

// Root of a smooth monotone f in [a, b] (fa, fb of opposite signs) from a close guess: Newton
// with f' = df, safeguarded as in rtsafe (Numerical Recipes §9.4): a step that leaves the bracket,
// or is not half the step before last, bisects instead — so a flat f (a stick end where the ramp
// is nearly tangent to n, β → β_c) or rounding noise still shrinks the bracket. Stops once a
// Newton step is below sqrt(eps)/64 relative (4 eps in long double; quadratic convergence then leaves ~eps) or the
// bracket is 4 eps wide, or |f| is below `noise`, the rounding level of f's evaluation (a flat,
// noisy f has no better root). Running out of iterations is a SolverError.
template <class Real, class F, class DF>
Real polished_root(F f, DF df, Real a, Real b, Real fa, const Real& fb, Real x, const Real& noise, const char* what,
                   RootStats& stats) {
  using std::abs;
  using std::sqrt;
  using std::swap;
  // A root at a bracket end (e.g. a stick that ends exactly at a peak, sine β = 3, γ = −1/2)
  // leaves f there at the rounding level: Newton would step past the end and bisect ~100 times.
  if (abs_le(fb, noise)) return b;
  if (abs_le(fa, noise)) return a;
  if ((fa > 0) == (fb > 0))
    throw SolverError(std::string(what) + ": no sign change on [" + short_str(a) + ", " + short_str(b) + "]");
  // In long double (the widest type whose guess comes from double, solver.hpp) the step itself
  // must come down to 4 eps: a steep flank (power:p at the type's edge, p = 2^53) makes a step
  // of sqrt(eps)/64 no proof of quadratic convergence (measured: μ̄ off by 4.5 times its bound).
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real small = std::numeric_limits<Real>::digits <= std::numeric_limits<long double>::digits ? Real(4 * eps)
                                                                                                    : Real(sqrt(eps) / 64);
  if (!(x > a && x < b)) x = (a + b) / 2;
  Real dx_old = b - a, dx = dx_old;
  // The iteration's numbers, made once: each step below is the expression in its comment,
  // evaluated in place with the same roundings (an mpfr temporary is an allocation).
  Real next, trial, t, u, scale;
  const Real four_eps = 4 * eps;
  ++stats.solves;
  for (std::uintmax_t it = 1; it <= stats.max_iterations; ++it) {
    ++stats.iterations;
    const Real fx = f(x);
    if (abs_le(fx, noise)) return x;
    if ((fx > 0) == (fa > 0)) {
      a = x;
      fa = fx;
    } else {
      b = x;
    }
    const Real d = df(x);
    midpoint(next, a, b);  // (a + b) / 2
    bool newton = false;
    if (d != 0) {
      trial = fx;
      trial /= d;
      difference(trial, x, trial);  // x − fx / d
      if (trial == x) return x;     // the step is below the last bit
      if (trial >= a && trial <= b) {
        difference(t, trial, x);
        u = dx_old;
        if (u < 0) negate(u);
        u /= 2;
        newton = abs_le(t, u);  // |trial − x| ≤ |dx_old| / 2
      }
      if (newton) swap(next, trial);
    }
    swap(dx_old, dx);
    difference(dx, next, x);  // dx = next − x
    swap(x, next);
    scale = x;  // |x| > 0 ? |x| : 1
    if (scale < 0) negate(scale);
    if (!(scale > 0)) scale = 1;
    t = small;
    t *= scale;
    if (newton && abs_le(dx, t)) return x;  // |dx| ≤ small·scale
    // Phases are absolute: w(φ) near φ = 0 carries rounding of order ε (e.g. 1 − (1 − 4φ)^p), so
    // a root there is not determined beyond ε·1.
    t = four_eps;  // 4ε·max(scale, 1)
    if (scale > 1) t *= scale;
    difference(u, b, a);
    if (u <= t) {
      midpoint(u, a, b);
      return u;
    }
  }
  throw SolverError(std::string(what) + ": Newton iteration did not converge in " +
                    std::to_string(stats.max_iterations) + " iterations on [" + short_str(a) + ", " + short_str(b) + "]");
}

}  // namespace vibrofric::detail
