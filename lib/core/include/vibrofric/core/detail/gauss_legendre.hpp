// Gauss–Legendre rules on [0, 1] at the working precision, for the spring integral of a curved
// contact (curved.hpp; model.md, "Curved contacts (MDR)"), whose integrand the u-map makes
// analytic on each segment: there the n-point rule converges geometrically (sphere + sine,
// measured: 1e-17 at n = 20, 1e-25 at 30, 1e-30 to 1e-36 at 40), where tanh-sinh, which spends
// its nodes on endpoint singularities that are no longer there, needs 260 nodes for 1e-25.
//
// Nodes and weights are computed in MPFR with 20 guard digits and rounded once to Real, kept per
// thread, precision and n. Boost's gauss and gauss_kronrod keep runtime-precision nodes from the
// first call's precision (toolchain.md), so they are not used.
#pragma once
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric::detail {

template <class Real>
struct GaussRule {
  std::vector<Real> nodes, weights;  // on [0, 1]; the weights sum to 1
};

// P_n(x) into p, P_{n−1}(x) into q, by the three-term recurrence at x's precision; t is scratch.
// Raw MPFR: the recurrence is the whole cost of a rule (O(n) per node), and et_off temporaries
// would allocate five numbers per step.
inline void legendre_mpfr(mpfr_t p, mpfr_t q, mpfr_t t, const mpfr_t x, std::size_t n) {
  mpfr_set_ui(q, 1, MPFR_RNDN);
  mpfr_set(p, x, MPFR_RNDN);
  for (unsigned long k = 1; k < n; ++k) {
    mpfr_mul(t, x, p, MPFR_RNDN);
    mpfr_mul_ui(t, t, 2 * k + 1, MPFR_RNDN);
    mpfr_mul_ui(q, q, k, MPFR_RNDN);
    mpfr_sub(t, t, q, MPFR_RNDN);
    mpfr_div_ui(t, t, k + 1, MPFR_RNDN);
    mpfr_swap(q, p);
    mpfr_swap(p, t);
  }
}

// P_n'(x) = n (x P_n − P_{n−1}) / (x² − 1) into d; t scratch.
inline void legendre_slope_mpfr(mpfr_t d, mpfr_t t, const mpfr_t x, const mpfr_t p, const mpfr_t q, std::size_t n) {
  mpfr_mul(d, x, p, MPFR_RNDN);
  mpfr_sub(d, d, q, MPFR_RNDN);
  mpfr_mul_ui(d, d, static_cast<unsigned long>(n), MPFR_RNDN);
  mpfr_sqr(t, x, MPFR_RNDN);
  mpfr_sub_ui(t, t, 1, MPFR_RNDN);
  mpfr_div(d, d, t, MPFR_RNDN);
}

// The n-point rule: the roots x of P_n by Newton's method, first in double from the classical
// guess cos(π(i + 3/4)/(n + 1/2)), then in MPFR on a ladder of precisions below the working
// digits plus 20 (`bits`), each step repeated until it is below the square root of its precision.
// The top of the ladder, bits/2 + 64, leaves the node exact to about that: one step at `bits`
// then makes it exact to the precision (quadratic convergence), and P_n' at the new node is
// P_n' + P_n''·δ at the old one, with P_n'' from Legendre's equation (1 − x²)P'' = 2xP' − n(n+1)P;
// the neglected term, of order n⁴δ² relative (each derivative gains at most n², Markov), is below
// 2^-(bits+96)·n⁴, under 2^-bits for every n below 2^24. A node so costs one
// recurrence at the full precision, where it cost three (a step, one more, and the weight): the
// rules are bitwise the same, built 1.2–1.6× faster (measured at 30 to 300 digits, n = 40 to 400;
// the lower rungs of the ladder remain). A full step that is not that small is repeated until it is. Weights 2/((1 − x²) P_n'(x)²), halved
// for [0, 1]; all rounded once to Real.
template <class Real>
const GaussRule<Real>& gauss_legendre(std::size_t n) {
  thread_local std::map<std::pair<int, std::size_t>, GaussRule<Real>> cache;
  const int digits = working_digits10<Real>();
  if (const auto hit = cache.find({digits, n}); hit != cache.end()) return hit->second;
  GaussRule<Real> rule;  // kept only once complete: a node that fails to converge throws
  const unsigned work = static_cast<unsigned>(digits + 20);
  const mpfr_prec_t bits = static_cast<mpfr_prec_t>(std::ceil(work * 3.3219280948873623)) + 8;
  std::vector<mpfr> x_hi, w_hi;
  {
    PrecisionScope scope(work);
    struct Scratch {  // cleared on every way out
      mpfr_t v[6];
      explicit Scratch(mpfr_prec_t bits) {
        for (auto& e : v) mpfr_init2(e, bits);
      }
      ~Scratch() {
        for (auto& e : v) mpfr_clear(e);
      }
    } scratch(bits);
    mpfr_t &x = scratch.v[0], &p = scratch.v[1], &q = scratch.v[2], &t = scratch.v[3], &d = scratch.v[4], &y = scratch.v[5];
    const auto newton_step = [&](mpfr_prec_t prec) {  // x −= P_n/P_n' at prec bits; |step| relative to x in t
      for (mpfr_t* v : {&p, &q, &t, &d}) mpfr_set_prec(*v, prec);
      mpfr_prec_round(x, prec, MPFR_RNDN);
      legendre_mpfr(p, q, t, x, n);
      legendre_slope_mpfr(d, t, x, p, q, n);
      mpfr_div(t, p, d, MPFR_RNDN);
      mpfr_sub(x, x, t, MPFR_RNDN);
    };
    // The last step, t relative to x, below 2^-limit.
    const auto small = [&](mpfr_prec_t limit) { return mpfr_zero_p(t) || mpfr_get_exp(t) - mpfr_get_exp(x) < -limit; };
    std::vector<mpfr_prec_t> ladder;  // descending; the same for every node
    for (mpfr_prec_t prec = bits / 2 + 64; prec < bits && prec > 64; prec = prec / 2 + 16) ladder.push_back(prec);
    for (std::size_t i = 0; i < n / 2 + n % 2; ++i) {
      if (n % 2 == 1 && i == n / 2) {  // the middle node 0 of an odd rule, P_n'(0) from the recurrence
        mpfr_set_prec(x, bits);
        mpfr_set_ui(x, 0, MPFR_RNDN);
        for (mpfr_t* v : {&p, &q, &t, &d}) mpfr_set_prec(*v, bits);
        legendre_mpfr(p, q, t, x, n);
        legendre_slope_mpfr(d, t, x, p, q, n);
      } else {
        double g = std::cos(3.14159265358979323846 * (static_cast<double>(i) + 0.75) / (static_cast<double>(n) + 0.5));
        for (int k = 0; k < 100; ++k) {
          double p0 = 1, p1 = g;
          for (std::size_t j = 1; j < n; ++j) {
            const double p2 = ((2.0 * j + 1) * g * p1 - static_cast<double>(j) * p0) / (static_cast<double>(j) + 1);
            p0 = p1;
            p1 = p2;
          }
          const double step = p1 / (static_cast<double>(n) * (g * p1 - p0) / (g * g - 1));
          g -= step;
          if (std::abs(step) <= 1e-15) break;
        }
        mpfr_set_prec(x, 53);
        mpfr_set_d(x, g, MPFR_RNDN);
        for (auto it = ladder.rbegin(); it != ladder.rend(); ++it)
          for (int k = 0; k < 64; ++k) {
            newton_step(*it);
            if (small(*it / 2 + 8)) break;
          }
        // At the full precision, until a step is below 2^-(bits/2 + 48): the node before it was
        // exact to that, the node after it is exact.
        bool converged = false;
        for (int k = 0; k < 64 && !converged; ++k) {
          newton_step(bits);
          converged = small(bits / 2 + 48);
        }
        if (!converged)
          throw SolverError("Gauss-Legendre node " + std::to_string(i) + " of " + std::to_string(n) + " did not converge");
        // p, d: P_n and P_n' at the old node y = x + t. d −= P_n''(y)·t, P_n'' from Legendre's equation.
        mpfr_add(y, x, t, MPFR_RNDN);
        mpfr_mul_ui(p, p, static_cast<unsigned long>(n) * static_cast<unsigned long>(n + 1), MPFR_RNDN);
        mpfr_mul(q, y, d, MPFR_RNDN);
        mpfr_mul_2ui(q, q, 1, MPFR_RNDN);
        mpfr_sub(q, q, p, MPFR_RNDN);
        mpfr_sqr(y, y, MPFR_RNDN);
        mpfr_ui_sub(y, 1, y, MPFR_RNDN);
        mpfr_div(q, q, y, MPFR_RNDN);
        mpfr_mul(q, q, t, MPFR_RNDN);
        mpfr_sub(d, d, q, MPFR_RNDN);
      }
      mpfr xv, wv;
      mpfr_set(xv.backend().data(), x, MPFR_RNDN);
      // 2/((1 − x²) P'²), halved for [0, 1]
      mpfr_sqr(t, x, MPFR_RNDN);
      mpfr_ui_sub(t, 1, t, MPFR_RNDN);
      mpfr_mul(t, t, d, MPFR_RNDN);
      mpfr_mul(t, t, d, MPFR_RNDN);
      mpfr_ui_div(wv.backend().data(), 1, t, MPFR_RNDN);
      x_hi.push_back(xv);
      w_hi.push_back(wv);
    }
  }
  // u = (1 ∓ x)/2, ascending; the middle node of an odd rule once.
  const std::size_t m = x_hi.size();
  for (std::size_t i = 0; i < m; ++i) {
    PrecisionScope scope(work);
    rule.nodes.push_back(rounded<Real>(mpfr((1 - x_hi[i]) / 2), static_cast<unsigned>(digits)));
    rule.weights.push_back(rounded<Real>(w_hi[i], static_cast<unsigned>(digits)));
  }
  for (std::size_t i = m; i-- > 0;) {
    if (n % 2 == 1 && i == m - 1) continue;
    PrecisionScope scope(work);
    rule.nodes.push_back(rounded<Real>(mpfr((1 + x_hi[i]) / 2), static_cast<unsigned>(digits)));
    rule.weights.push_back(rounded<Real>(w_hi[i], static_cast<unsigned>(digits)));
  }
  return cache.emplace(std::make_pair(digits, n), std::move(rule)).first->second;
}

}  // namespace vibrofric::detail
