// Gauss–Legendre rules on [0, 1] at the working precision, for the spring integral of a curved
// contact (curved.hpp; model.md, "Curved contacts (MDR)"), whose integrand the u-map makes
// analytic on each segment: there the n-point rule converges geometrically (sphere + sine,
// measured: 1e-17 at n = 20, 1e-25 at 30, 1e-30 to 1e-36 at 40), where tanh-sinh, which spends
// its nodes on endpoint singularities that are no longer there, needs 260 nodes for 1e-25.
//
// Nodes and weights are computed in MPFR with 20 guard digits and rounded once to Real, kept per
// thread, precision and n; so are the Gauss–Kronrod pairs below, which give a segment's first
// estimate. Boost's gauss and gauss_kronrod keep runtime-precision nodes from the first call's
// precision (toolchain.md), so they are not used.
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
  // The roots x ≥ 0 on [−1, 1], descending, and P_n' there, at the working digits plus 20, as
  // computed before rounding: gauss_kronrod's Gauss nodes.
  std::vector<mpfr> work_roots, work_slopes;
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

// The precisions below `bits` on which a node's first Newton steps run, descending: bits/2 + 64,
// then halving + 16, above 64 bits (gauss_legendre and gauss_kronrod).
inline std::vector<mpfr_prec_t> newton_ladder(mpfr_prec_t bits) {
  std::vector<mpfr_prec_t> ladder;
  for (mpfr_prec_t prec = bits / 2 + 64; prec < bits && prec > 64; prec = prec / 2 + 16) ladder.push_back(prec);
  return ladder;
}

// N MPFR numbers at `bits`, a rule's scratch, cleared on every way out.
template <std::size_t N>
struct MpfrScratch {
  mpfr_t v[N];
  explicit MpfrScratch(mpfr_prec_t bits) {
    for (auto& e : v) mpfr_init2(e, bits);
  }
  ~MpfrScratch() {
    for (auto& e : v) mpfr_clear(e);
  }
  MpfrScratch(const MpfrScratch&) = delete;
  MpfrScratch& operator=(const MpfrScratch&) = delete;
};

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
  std::vector<mpfr> x_hi, w_hi, d_hi;
  {
    PrecisionScope scope(work);
    MpfrScratch<6> scratch(bits);
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
    const std::vector<mpfr_prec_t> ladder = newton_ladder(bits);  // the same for every node
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
      mpfr xv, wv, dv;
      mpfr_set(xv.backend().data(), x, MPFR_RNDN);
      mpfr_set(dv.backend().data(), d, MPFR_RNDN);
      // 2/((1 − x²) P'²), halved for [0, 1]
      mpfr_sqr(t, x, MPFR_RNDN);
      mpfr_ui_sub(t, 1, t, MPFR_RNDN);
      mpfr_mul(t, t, d, MPFR_RNDN);
      mpfr_mul(t, t, d, MPFR_RNDN);
      mpfr_ui_div(wv.backend().data(), 1, t, MPFR_RNDN);
      x_hi.push_back(xv);
      w_hi.push_back(wv);
      d_hi.push_back(dv);
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
  rule.work_roots = std::move(x_hi);
  rule.work_slopes = std::move(d_hi);
  return cache.emplace(std::make_pair(digits, n), std::move(rule)).first->second;
}

}  // namespace vibrofric::detail

namespace vibrofric::detail {

// The Gauss–Kronrod pair of order n on [0, 1] (Kronrod 1965): the n Gauss nodes, bit for bit
// gauss_legendre's, and the n + 1 zeros of the Stieltjes polynomial E_{n+1} between them,
// ascending; the Kronrod weights (the rule is exact to degree 3n + 1) and the Gauss weights (zero
// at the added nodes). One pass of 2n + 1 springs gives the n-point value and a far better one,
// where two Gauss rules of n and 3n/2 points cost 5n/2 for the same two (curved.hpp,
// gauss_segment). For the Legendre weight the zeros of E_{n+1} are real, simple and interlace with
// the Gauss nodes for every n (Szegő 1935), and the weights are positive (Monegato 1978).
template <class Real>
struct KronrodRule {
  std::vector<Real> nodes, weights, gauss_weights;  // 2n + 1 each; each set of weights sums to 1
};

// E_{n+1} = Σ_{i=1}^{r} a_i P_{k_i} in Legendre polynomials of the parity of n + 1, its
// coefficients by Patterson's recurrence (Math. Comp. 22 (1968) 847–856, as Boost's
// legendre_stieltjes, whose evaluation of E' costs O(n²) and is not used), a_r = 1; and E, E' at x
// by the recurrences P_{k+1} = ((2k + 1) x P_k − k P_{k−1})/(k + 1), P'_{k+1} = P'_{k−1} + (2k + 1) P_k.
struct Stieltjes {
  explicit Stieltjes(std::size_t n) : odd_((n + 1) % 2 == 1) {
    const std::ptrdiff_t nn = static_cast<std::ptrdiff_t>(n);
    const std::ptrdiff_t q = nn % 2, r = q ? (nn - 1) / 2 + 2 : nn / 2 + 1;
    a.assign(static_cast<std::size_t>(r + 1), mpfr(0));
    a[static_cast<std::size_t>(r)] = 1;
    // Products of four integers below 4n + 4 (below 2^72 for every n a rule reaches) at the
    // working precision (at least 116 bits: digits + 20): exact. Raw MPFR, the same operations as
    // ratio *= num/den, a −= ratio·a_i: O(n²) of them, and number temporaries would allocate each.
    MpfrScratch<4> s(mpfr_get_prec(a[0].backend().data()));
    mpfr_t &ratio = s.v[0], &num = s.v[1], &den = s.v[2], &t = s.v[3];
    const auto product = [](mpfr_t out, long f0, long f1, long f2, long f3) {
      mpfr_set_si(out, f0, MPFR_RNDN);
      mpfr_mul_si(out, out, f1, MPFR_RNDN);
      mpfr_mul_si(out, out, f2, MPFR_RNDN);
      mpfr_mul_si(out, out, f3, MPFR_RNDN);
    };
    for (std::ptrdiff_t k = 1; k < r; ++k) {
      mpfr_set_ui(ratio, 1, MPFR_RNDN);
      for (std::ptrdiff_t i = r + 1 - k; i <= r; ++i) {
        product(num, nn - q + 2 * (i + k - 1), nn + q + 2 * (k - i + 1), nn - 1 - q + 2 * (i - k), 2 * (k + i - 1) - 1 - q - nn);
        product(den, nn - q + 2 * (i - k), 2 * (k + i - 1) - q - nn, nn + 1 + q + 2 * (k - i), nn - 1 - q + 2 * (i + k));
        mpfr_div(t, num, den, MPFR_RNDN);
        mpfr_mul(ratio, ratio, t, MPFR_RNDN);
        mpfr_mul(t, ratio, a[static_cast<std::size_t>(i)].backend().data(), MPFR_RNDN);
        mpfr_ptr out = a[static_cast<std::size_t>(r - k)].backend().data();
        mpfr_sub(out, out, t, MPFR_RNDN);
      }
    }
    degree = odd_ ? 2 * static_cast<std::size_t>(r) - 1 : 2 * static_cast<std::size_t>(r) - 2;
  }
  template <class U>
  void at(const U& x, U& e, U& de, const std::vector<U>& coeff) const {
    U p0 = 1, p1 = x, d0 = 0, d1 = 1;
    e = odd_ ? U(coeff[1] * p1) : U(coeff[1] * p0);
    de = odd_ ? U(coeff[1]) : U(0);
    for (std::size_t k = 1; k < degree; ++k) {
      const U p2 = (U(2 * k + 1) * x * p1 - U(k) * p0) / U(k + 1), d2 = d0 + U(2 * k + 1) * p1;
      p0 = p1;
      p1 = p2;
      d0 = d1;
      d1 = d2;
      if ((k + 1) % 2 == (odd_ ? 1u : 0u)) {
        const U& c = coeff[odd_ ? (k + 2) / 2 : (k + 1) / 2 + 1];
        e += c * p1;
        de += c * d1;
      }
    }
  }
  std::vector<mpfr> a;  // a[0] unused
  std::size_t degree = 0;

 private:
  bool odd_;
};

// E(x) into e and E'(x) into de in raw MPFR at e's precision, from the coefficients a (a[0]
// unused) of a Stieltjes; s: five scratch numbers. The recurrences are the whole cost of a
// rule (O(n) per evaluation), and et_off temporaries would allocate at every step.
// With `more` (seven scratch numbers then): also E''(x) into more->dde, and P_n(x), P_n'(x) of the
// Gauss rule (n = degree − 1, passed on the way) into more->pn, more->dpn, by
// P''_{k+1} = P''_{k−1} + (2k + 1) P'_k.
struct StieltjesMore {
  mpfr_ptr dde, pn, dpn;
};
inline void stieltjes_mpfr(mpfr_t e, mpfr_t de, const Stieltjes& E, const mpfr_t x, mpfr_t* s,
                           const StieltjesMore* more = nullptr) {
  mpfr_t &p0 = s[0], &p1 = s[1], &d0 = s[2], &d1 = s[3], &t = s[4];
  const bool odd = E.degree % 2 == 1;
  const mpfr_srcptr a1 = E.a[1].backend().data();
  mpfr_set_ui(p0, 1, MPFR_RNDN);
  mpfr_set(p1, x, MPFR_RNDN);
  mpfr_set_ui(d0, 0, MPFR_RNDN);
  mpfr_set_ui(d1, 1, MPFR_RNDN);
  if (odd) {
    mpfr_mul(e, a1, x, MPFR_RNDN);
    mpfr_set(de, a1, MPFR_RNDN);
  } else {
    mpfr_set(e, a1, MPFR_RNDN);
    mpfr_set_ui(de, 0, MPFR_RNDN);
  }
  if (more) {
    mpfr_set_ui(s[5], 0, MPFR_RNDN);  // P''_0, P''_1
    mpfr_set_ui(s[6], 0, MPFR_RNDN);
    mpfr_set_ui(more->dde, 0, MPFR_RNDN);
    if (E.degree == 2) {  // n = 1: P_1 = x
      mpfr_set(more->pn, x, MPFR_RNDN);
      mpfr_set_ui(more->dpn, 1, MPFR_RNDN);
    }
  }
  for (unsigned long k = 1; k < E.degree; ++k) {
    if (more) {  // P''_{k+1} = P''_{k−1} + (2k + 1) P'_k into s[5], before P'_k moves
      mpfr_mul_ui(t, d1, 2 * k + 1, MPFR_RNDN);
      mpfr_add(s[5], s[5], t, MPFR_RNDN);
      mpfr_swap(s[5], s[6]);
    }
    mpfr_mul(t, x, p1, MPFR_RNDN);  // P_{k+1} = ((2k + 1) x P_k − k P_{k−1})/(k + 1) into p0
    mpfr_mul_ui(t, t, 2 * k + 1, MPFR_RNDN);
    mpfr_mul_ui(p0, p0, k, MPFR_RNDN);
    mpfr_sub(t, t, p0, MPFR_RNDN);
    mpfr_div_ui(p0, t, k + 1, MPFR_RNDN);
    mpfr_mul_ui(t, p1, 2 * k + 1, MPFR_RNDN);  // P'_{k+1} = P'_{k−1} + (2k + 1) P_k into d0
    mpfr_add(d0, d0, t, MPFR_RNDN);
    mpfr_swap(p0, p1);
    mpfr_swap(d0, d1);
    if ((k + 1) % 2 == (odd ? 1u : 0u)) {
      const mpfr_srcptr c = E.a[odd ? (k + 2) / 2 : (k + 1) / 2 + 1].backend().data();
      mpfr_fma(e, c, p1, e, MPFR_RNDN);
      mpfr_fma(de, c, d1, de, MPFR_RNDN);
      if (more) mpfr_fma(more->dde, c, s[6], more->dde, MPFR_RNDN);
    }
    if (more && k + 2 == E.degree) {
      mpfr_set(more->pn, p1, MPFR_RNDN);
      mpfr_set(more->dpn, d1, MPFR_RNDN);
    }
  }
}

// Nodes and weights in MPFR at the working digits plus 20, rounded once to Real, kept per thread,
// precision and n; the nodes x < 0 on [−1, 1] computed, the others by symmetry. The Gauss nodes
// and P_n' there are gauss_legendre's before rounding (GaussRule::work_roots, work_slopes). Each
// added node by Newton on E from a double guess, first on gauss_legendre's ladder of precisions,
// then at the full precision kept inside its bracket between two Gauss nodes (E changes sign
// there), until a step at the full precision is below 2^-(bits/2 + 48) relative: the node before
// that step was exact to about that, the node after it is exact (quadratic convergence). That
// last evaluation also gives E'' and P_n, P_n' (StieltjesMore), so E' and P_n at the new node are
// corrected to first order, as gauss_legendre corrects P_n' (the neglected terms are below
// 2^-bits). Kronrod weights, halved for [0, 1]: 2/((n + 1) P_n(x) E'(x)) at an added node,
// 2/((1 − x²) P_n'(x)²) + 2/((n + 1) P_n'(x) E(x)) at a Gauss node. A node that does not converge,
// or weights that do not sum to 1, throw SolverError. The ladder and the corrections leave every
// rule bitwise as without them (checked on 602 rules and their Gauss rules, in double, long double,
// cpp_bin_float_50 and mpfr at 12 to 300 digits), and rules of order 40 to 271 are built in 0.75 of
// the instructions at 50 digits, 0.65 at 200.
template <class Real>
const KronrodRule<Real>& gauss_kronrod(std::size_t n) {
  thread_local std::map<std::pair<int, std::size_t>, KronrodRule<Real>> cache;
  const int digits = working_digits10<Real>();
  if (const auto hit = cache.find({digits, n}); hit != cache.end()) return hit->second;
  const GaussRule<Real>& gauss = gauss_legendre<Real>(n);
  const unsigned work = static_cast<unsigned>(digits + 20);
  const std::size_t half = n / 2;  // Gauss nodes x < 0: j < half; added nodes x < 0: j <= half − (n odd ? 0 : 1)
  std::vector<mpfr> gx, gw, ax, aw;  // Gauss and added nodes x ≤ 0 on [−1, 1]; Kronrod weights on [0, 1]
  {
    PrecisionScope scope(work);
    const mpfr_prec_t bits = mpfr_get_prec(mpfr(0).backend().data());
    const Stieltjes E(n);
    std::vector<double> a_double;
    for (const mpfr& c : E.a) a_double.push_back(static_cast<double>(c));
    MpfrScratch<14> scratch(bits);
    // The rungs of gauss_legendre's ladder, with E's coefficients rounded to each: a step at a
    // rung then costs a product at that precision, where a full-precision coefficient in the fma
    // would cost a full one.
    const std::vector<mpfr_prec_t> ladder = newton_ladder(bits);
    std::vector<Stieltjes> rungs(ladder.size(), E);
    for (std::size_t r = 0; r < ladder.size(); ++r)
      for (mpfr& c : rungs[r].a) mpfr_prec_round(c.backend().data(), ladder[r], MPFR_RNDN);
    MpfrScratch<10> low(bits);
    mpfr_t &lx = low.v[5], &lf = low.v[6], &ldf = low.v[7], &lstep = low.v[8], &lprev = low.v[9];
    mpfr_t &x = scratch.v[7], &f = scratch.v[8], &df = scratch.v[9], &step = scratch.v[10], &dde = scratch.v[11],
           &pn = scratch.v[12], &dpn = scratch.v[13];
    const StieltjesMore more{dde, pn, dpn};
    const auto small = [&] { return mpfr_zero_p(step) || mpfr_get_exp(step) - mpfr_get_exp(x) < -(bits / 2 + 48); };
    const auto fail = [&](const char* what, std::size_t j) {
      return SolverError(std::string("Gauss-Kronrod rule of order ") + std::to_string(n) + ": " + what + " " + std::to_string(j) + " did not converge");
    };
    // Gauss nodes x ≤ 0 (the middle one of an odd rule is 0), with E there: the brackets. The
    // roots and slopes gauss_legendre computed before rounding its rule (x ≥ 0, descending):
    // x = −root, P_n'(−root) = (−1)^(n−1) P_n'(root).
    std::vector<mpfr> ge;
    for (std::size_t j = 0; j < n - half; ++j) {
      mpfr xv = -gauss.work_roots[j], d = n % 2 == 1 ? gauss.work_slopes[j] : mpfr(-gauss.work_slopes[j]), e, wv;
      if (n % 2 == 1 && j == half) xv = 0;
      stieltjes_mpfr(e.backend().data(), scratch.v[4], E, xv.backend().data(), scratch.v);  // E(x); E' unused
      wv = 1 / ((1 - xv * xv) * d * d) + 1 / (mpfr(n + 1) * d * e);
      gx.push_back(xv);
      gw.push_back(wv);
      ge.push_back(e);
    }
    // Added nodes x ≤ 0: bracket j is (gx[j − 1], gx[j]), with −1 for j = 0; the middle one of an
    // even rule is 0 (E is odd).
    for (std::size_t j = 0; j <= half; ++j) {
      mpfr lo = j == 0 ? mpfr(-1) : gx[j - 1], up = j < gx.size() ? gx[j] : mpfr(0), flo, fup;
      if (n % 2 == 0 && j == half) {
        mpfr_set_ui(x, 0, MPFR_RNDN);
        stieltjes_mpfr(f, df, E, x, scratch.v, &more);
        mpfr_set_ui(step, 0, MPFR_RNDN);
      } else {
        if (j == 0) {
          stieltjes_mpfr(flo.backend().data(), scratch.v[4], E, lo.backend().data(), scratch.v);
        } else {
          flo = ge[j - 1];
        }
        fup = ge[j];
        if (!((flo < 0 && fup > 0) || (flo > 0 && fup < 0)))
          throw SolverError("Gauss-Kronrod rule of order " + std::to_string(n) + ": E does not change sign about added node " + std::to_string(j));
        // A double guess by bisection on E in double, then Newton at the working precision.
        double l = static_cast<double>(lo), h = static_cast<double>(up), fl = static_cast<double>(flo);
        for (int k = 0; k < 60 && h - l > 1e-15; ++k) {
          const double m = (l + h) / 2;
          double e, de;
          E.at(m, e, de, a_double);
          if ((e < 0) == (fl < 0)) {
            l = m;
            fl = e;
          } else {
            h = m;
          }
        }
        mpfr_set_d(x, (l + h) / 2, MPFR_RNDN);
        if (!(mpfr_greater_p(x, lo.backend().data()) && mpfr_less_p(x, up.backend().data()))) {
          mpfr_add(x, lo.backend().data(), up.backend().data(), MPFR_RNDN);
          mpfr_div_2ui(x, x, 1, MPFR_RNDN);
        }
        // Newton on the ladder: each rung's steps until one is below 2^-(prec/2 + 8) relative,
        // or stops halving (rounding at that precision); a step out of the bracket ends the
        // ladder there. Only a start for the steps at the full precision below, which alone move
        // the bracket and decide convergence.
        for (std::size_t r = rungs.size(); r-- > 0;) {
          const mpfr_prec_t prec = ladder[r];
          for (auto& v : low.v) mpfr_set_prec(v, prec);
          mpfr_set(lx, x, MPFR_RNDN);
          bool left = false;
          for (int k = 0; k < 16; ++k) {
            stieltjes_mpfr(lf, ldf, rungs[r], lx, low.v);
            if (mpfr_zero_p(lf)) break;
            mpfr_div(lstep, lf, ldf, MPFR_RNDN);
            const bool shrinking = k == 0 || mpfr_get_exp(lstep) < mpfr_get_exp(lprev);
            mpfr_sub(lx, lx, lstep, MPFR_RNDN);
            if (!(mpfr_greater_p(lx, lo.backend().data()) && mpfr_less_p(lx, up.backend().data()))) {
              left = true;
              break;
            }
            mpfr_set(x, lx, MPFR_RNDN);
            if (!shrinking || mpfr_zero_p(lstep) || mpfr_get_exp(lstep) - mpfr_get_exp(lx) < -(prec / 2 + 8)) break;
            mpfr_swap(lprev, lstep);
          }
          if (left) break;
        }
        bool converged = false;
        for (int k = 0; k < 200 && !converged; ++k) {
          stieltjes_mpfr(f, df, E, x, scratch.v, &more);
          mpfr_set_ui(step, 0, MPFR_RNDN);
          if (mpfr_zero_p(f)) break;
          mpfr_div(step, f, df, MPFR_RNDN);
          converged = small();
          if ((mpfr_sgn(f) < 0) == (flo < 0))
            mpfr_set(lo.backend().data(), x, MPFR_RNDN);
          else
            mpfr_set(up.backend().data(), x, MPFR_RNDN);
          mpfr_sub(x, x, step, MPFR_RNDN);
          // Newton leaving the bracket far from the root: bisect. (Converged, x − step may round
          // onto the bracket's end, the old x itself.)
          if (!converged && !(mpfr_greater_p(x, lo.backend().data()) && mpfr_less_p(x, up.backend().data()))) {
            mpfr_add(x, lo.backend().data(), up.backend().data(), MPFR_RNDN);
            mpfr_div_2ui(x, x, 1, MPFR_RNDN);
          }
        }
        if (!converged && !mpfr_zero_p(f)) throw fail("added node", j);
      }
      // E' and P_n at the node x = y − step from their values and slopes at y, the last
      // evaluation (as gauss_legendre corrects P_n': the step is below 2^-(bits/2 + 48)).
      mpfr_mul(f, dde, step, MPFR_RNDN);
      mpfr_sub(df, df, f, MPFR_RNDN);
      mpfr_mul(f, dpn, step, MPFR_RNDN);
      mpfr_sub(pn, pn, f, MPFR_RNDN);
      mpfr xv, wv;
      mpfr_set(xv.backend().data(), x, MPFR_RNDN);
      wv = 1 / (mpfr(n + 1) * mpfr(pn) * mpfr(df));
      ax.push_back(xv);
      aw.push_back(wv);
    }
    mpfr sum = 0;
    for (std::size_t j = 0; j < gx.size(); ++j) sum += (gx[j] == 0 ? 1 : 2) * gw[j];
    for (std::size_t j = 0; j < ax.size(); ++j) sum += (ax[j] == 0 ? 1 : 2) * aw[j];
    if (!(abs(sum - 1) <= pow(mpfr(10), -(digits + 10))))
      throw SolverError("Gauss-Kronrod rule of order " + std::to_string(n) + ": the weights do not sum to 1");
  }
  // All 2n + 1 nodes ascending on [0, 1]: u = (1 + x)/2 for x ≤ 0, then the mirror images.
  KronrodRule<Real> rule;
  auto add = [&](const mpfr& x, const mpfr& w, bool mirror, const Real* gauss_node, const Real* gauss_weight) {
    PrecisionScope scope(work);
    rule.nodes.push_back(gauss_node ? *gauss_node : rounded<Real>(mpfr(mirror ? (1 - x) / 2 : (1 + x) / 2), static_cast<unsigned>(digits)));
    rule.weights.push_back(rounded<Real>(w, static_cast<unsigned>(digits)));
    rule.gauss_weights.push_back(gauss_weight ? *gauss_weight : Real(0));
  };
  for (std::size_t j = 0; j < ax.size(); ++j) {
    add(ax[j], aw[j], false, nullptr, nullptr);
    if (j < gx.size()) add(gx[j], gw[j], false, &gauss.nodes[j], &gauss.weights[j]);
  }
  for (std::size_t j = ax.size(); j-- > 0;) {
    if (ax[j] == 0) continue;
    // the Gauss node after added node j, mirrored: Gauss node n − 1 − j
    if (j < gx.size() && !(gx[j] == 0)) add(gx[j], gw[j], true, &gauss.nodes[n - 1 - j], &gauss.weights[n - 1 - j]);
    add(ax[j], aw[j], true, nullptr, nullptr);
  }
  if (rule.nodes.size() != 2 * n + 1) throw SolverError("Gauss-Kronrod rule of order " + std::to_string(n) + ": " + std::to_string(rule.nodes.size()) + " nodes");
  return cache.emplace(std::make_pair(digits, n), std::move(rule)).first->second;
}

}  // namespace vibrofric::detail
