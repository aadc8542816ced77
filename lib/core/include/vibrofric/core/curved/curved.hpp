// Curved contacts by the method of dimensionality reduction (model.md, "Curved contacts (MDR)"):
//
//   μ̄/μ0 = ∫ Φ_w(β, γ − σ(x)) dx / ∫ N_w(γ − σ(x)) dx,   Φ_w = ∫₀¹ s dφ,  N_w = ∫₀¹ n dφ,
//
// every spring of the row being the flat punch (solver.hpp) at the shifted mean indentation
// γ' = γ − σ(x). The x-integral runs from the centre to the contact edge σ = γ + max w, by
// Gauss–Legendre between breakpoints, graded towards close ones (graded_pieces; tanh-sinh where
// a Gauss rule does not converge soon: see gauss_segment). Φ_w(β, ·) and N_w(·) are analytic in
// γ' between the values where the flat-punch event structure changes; those are found from the
// structure itself (gamma_breakpoints below), never from a grid, and each is a breakpoint of the
// x-integral, as are the profile's own kinks. At a breakpoint the integrand behaves like a power of the
// square root of the distance (contact edge, stick appearing, σ beyond a profile's kink):
// each segment is mapped by t = a + (b − a) u²(3 − 2u), which makes that analytic in u. The
// wear-flat sphere is integrated in σ, where x(σ) is analytic.
//
// Not for: Ψ (Eq. 12). The outer springs of a curved contact always jump, so Eq. 13's
// separation of α and β does not exist there.
#pragma once
#include <algorithm>
#include <map>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "vibrofric/core/detail/gauss_legendre.hpp"
#include "vibrofric/core/curved/profile.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric {

template <class Real>
struct CurvedResult {
  Real mu;                 // μ̄/μ0 = friction_integral / normal_integral
  Real friction_integral;  // ∫₀^X Φ_w(β, γ − σ(x)) dx over the half-row (profile units; Φ_w: a spring's retained_area)
  Real normal_integral;    // ∫₀^X N_w(γ − σ(x)) dx
  Real contact_radius;     // X: σ(X) = γ + max w, the edge of the contact (profile units)
  Real beta_c;             // β_c(γ) of the central spring; β ≥ β_c gives μ̄ = μ0 exactly (Eq. 6)
  Real relative_error;     // estimate for mu: quadrature estimates plus the springs' rounding bounds
  Real quadrature_error;   // sum of the quadrature error estimates of both integrals (absolute)
  bool center_jumps = false;          // γ < −min w: every spring loses contact once a period
  std::vector<Real> gamma_breaks;     // γ' breakpoints inside (−max w, γ), ascending
  std::size_t segments = 0;           // quadrature segments
  std::size_t springs = 0;            // flat-punch solves (breakpoint search and quadrature)
  std::size_t quadratic_segments = 0; // segments of a piecewise-linear wave taken from 3 springs (QuadraticSprings)
};

namespace detail {

// ∫₀¹ f by the Gauss–Kronrod pair of order n, then Gauss–Legendre rules of 9n/4, 27n/8, …
// points (gauss_legendre.hpp), n from the digits asked for (0.75 digit per point, measured on
// sphere + sine), until two successive values differ by at most rel·L1 or abs: the more accurate
// one, with that difference as its error estimate (it is the less accurate one's error: the
// n-point Gauss value's against the Kronrod value, exact to degree 3n + 1, then each rule's
// against one of 3/2 its points). The pair costs 2n + 1 springs where the Gauss rules of n and
// 3n/2 points, used before, cost 5n/2 for an estimate of the same kind. false once
// a rule would exceed 4 points per digit + 40: the caller then integrates by tanh-sinh, which
// copes better with what slows a Gauss rule (a singularity just beyond an end, as a neighbouring
// breakpoint a few thousandths of the width away: a third of a digit per point, measured; a
// non-analytic end, as a profile σ = x^n with n not an integer). Giving up earlier, from the
// digits the first rules reached, was measured to cost more springs: 1977 against 1416 at 25
// digits on the bench's three sphere inputs.
// The Gauss–Legendre rule of `points` points on [0, 1] applied to f: Σ w_i f(x_i) into sum and
// Σ w_i |f(x_i)| into norm.
template <class Real, class F>
void gauss_apply(F& f, std::size_t points, Real& sum, Real& norm) {
  using std::abs;
  const GaussRule<Real>& rule = gauss_legendre<Real>(points);
  sum = 0;
  norm = 0;
  for (std::size_t i = 0; i < points; ++i) {
    const Real y = f(rule.nodes[i]);
    sum += rule.weights[i] * y;
    norm += rule.weights[i] * abs(y);
  }
}

template <class Real, class F>
bool gauss_segment(F f, const Real& rel, const Real& abs_tol, Real& value, Real& err, Real& l1) {
  using std::abs;
  using std::log10;
  const double digits = rel > 0 ? -static_cast<double>(log10(rel)) : static_cast<double>(working_digits10<Real>());
  const std::size_t limit = static_cast<std::size_t>(4 * digits) + 40;
  std::size_t n = std::max<std::size_t>(8, static_cast<std::size_t>(std::ceil(digits / 0.75)));
  // Two successive values agree: the more accurate one, cur, with their difference as its estimate.
  auto accepted = [&](const Real& cur, const Real& other, const Real& norm) {
    const Real diff = abs(cur - other);
    if (!(diff <= rel * norm || diff <= abs_tol)) return false;
    value = cur;
    err = diff;
    l1 = norm;
    return true;
  };
  if (n + n / 2 > limit) return false;
  // The Gauss–Kronrod pair of order n first: the n-point value and one about as accurate as the
  // 3n/2-point rule, from 2n + 1 springs.
  Real prev;
  {
    const KronrodRule<Real>& rule = gauss_kronrod<Real>(n);
    Real kronrod = 0, gauss = 0, norm = 0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      const Real y = f(rule.nodes[i]);
      kronrod += rule.weights[i] * y;
      norm += rule.weights[i] * abs(y);
      if (rule.gauss_weights[i] != 0) gauss += rule.gauss_weights[i] * y;
    }
    if (accepted(kronrod, gauss, norm)) return true;
    prev = kronrod;
    n += n / 2;
  }
  for (;;) {
    const std::size_t next = n + n / 2;
    if (next > limit) return false;
    Real cur, norm;
    gauss_apply(f, next, cur, norm);
    if (accepted(cur, prev, norm)) return true;
    prev = cur;
    n = next;
  }
}

// ∫_a^b h(t) dt over one piece of the row, through t = a + (b − a) u²(3 − 2u): dt/du vanishes
// at both ends, so the square-root behaviour there (σ beyond a profile's kink, Φ and N where
// contact or stick begins) becomes analytic in u. Gauss rules (gauss_segment) to rel·L1 or abs,
// else tanh-sinh; SolverError naming `what` if neither converges.
template <class Real, class H>
void integrate_piece(H h, const Real& a, const Real& b, const Real& rel, const Real& abs_tol, const Options& opt,
                     const char* what, Real& value, Real& err, Real& l1) {
  using std::sqrt;
  const Real width = b - a;
  const auto f = [&](const Real& u) -> Real {
    const Real t = u < Real(1) / 2 ? Real(a + width * u * u * (3 - 2 * u)) : Real(b - width * (1 - u) * (1 - u) * (1 + 2 * u));
    if (!(t > a) || !(t < b)) return Real(0);  // dt/du = 0 at the ends
    return h(t) * 6 * width * u * (1 - u);
  };
  if (gauss_segment(f, rel, abs_tol, value, err, l1)) return;
  std::size_t levels = 0;
  try {
    value = integrator<Real>(opt.max_quadrature_levels).integrate(f, Real(0), Real(1), rel, &err, &l1, &levels);
  } catch (const SolverError&) {
    throw;
  } catch (const std::exception& e) {
    throw SolverError(std::string("tanh-sinh quadrature failed: ") + e.what());
  }
  // Boost stops early where two levels stop agreeing better (the integrand's rounding):
  // accepted if half the digits were reached, the estimate then entering the error.
  const Real eps = std::numeric_limits<Real>::epsilon();
  const bool stalled = levels < opt.max_quadrature_levels && err <= sqrt(eps) * l1;
  if (!(err <= rel * l1) && !(err <= abs_tol) && !stalled && l1 > 0)
    throw SolverError(std::string("spring integral of ") + what + " did not converge on t in [" + short_str(a) + ", " +
                      short_str(b) + "]: error estimate " + short_str(err) + " after " + std::to_string(levels) + " levels");
}

// The breakpoints ts (ascending, distinct) with pieces graded towards close neighbours. The
// integrand continued beyond a segment's end is singular at the next breakpoint too. One far
// closer than the width (breakpoints that cluster, as the tangency points of a small β near the
// contact edge) lies nearer the end than the Gauss nodes do: two rules that both miss it agree,
// and their difference understates the error (measured: sine, power:3 profile, β = 0.01,
// γ = −0.3 in double, two breakpoints within 4e-6 of the edge in γ': actual error 1.04 times
// the bound). So a side whose neighbour is d < width/8 away is cut at end ± d(9^j − 1),
// j = 1, 2, …: every piece then sees its nearest outside singularity at least 1/8 of its width
// away, as an unsplit segment does. On 720 small- and large-β inputs, grading at 1/2 (3^j) cost
// 1.3–1.9× the springs with no smaller worst error ratio; at 1/16 it cost the same as at 1/8.
// A segment cut on both sides is graded from each end to its middle; the outer ends of the row
// (centre, contact edge) have no neighbour.
template <class Real>
std::vector<Real> graded_pieces(const std::vector<Real>& ts) {
  constexpr int q = 9;
  std::vector<Real> out;
  if (ts.empty()) return out;
  out.push_back(ts.front());
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const Real &a = ts[k], &b = ts[k + 1];
    const Real width = b - a;
    const bool left = k > 0 && (q - 1) * (a - ts[k - 1]) < width, right = k + 2 < ts.size() && (q - 1) * (ts[k + 2] - b) < width;
    const Real mid = left && right ? Real((a + b) / 2) : (left ? b : a);
    if (left)
      for (Real step = (q - 1) * (a - ts[k - 1]); a + step < mid; step = q * step + (q - 1) * (a - ts[k - 1]))
        if (a + step > out.back()) out.push_back(a + step);
    if (right) {
      std::vector<Real> rs;
      for (Real step = (q - 1) * (ts[k + 2] - b); b - step > mid; step = q * step + (q - 1) * (ts[k + 2] - b)) rs.push_back(b - step);
      if (left && mid > out.back()) out.push_back(mid);
      for (auto it = rs.rbegin(); it != rs.rend(); ++it)
        if (*it > out.back()) out.push_back(*it);
    }
    if (b > out.back()) out.push_back(b);
  }
  return out;
}

// One spring: Φ_w = ∫s dφ and N_w = ∫n dφ (model.md, MDR; the retained_area and normal_area of
// its flat-punch Result) and the bounds on their absolute rounding errors (Φ's is often a tenth of
// N's: a stick's ramp carries less than n); no contact gives zeros.
template <class Real>
struct SpringValue {
  Real retained_area, normal_area, retained_err, normal_err;
};

template <class Real>
class SpringRow {
 public:
  SpringRow(const Waveform<Real>& w, const Real& beta, const Options& opt) : w_(w), beta_(beta), opt_(opt) {
    stats_.max_iterations = root_budget<Real>(opt);
  }
  SpringValue<Real> at(const Real& g) {
    if (!(g + w_.maximum() > 0)) return {Real(0), Real(0), Real(0), Real(0)};
    ++solves;
    if constexpr (std::numeric_limits<Real>::digits <= std::numeric_limits<double>::digits) {
      // Continuation: the last spring's stick ends guess this one's (EventPass takes a guess only
      // inside a stick end's bracket, where Newton cannot leave the root; double only, see
      // EventPass::stick_end_root for the wider types).
      const Result<Real> r = detail::solve_near(make_contact(w_, g, opt_), beta_, opt_, ends_);
      ends_.clear();
      for (const auto& st : r.stick_phases) ends_.push_back(st.end);
      return {r.retained_area, r.normal_area, r.retained_error, r.normal_error};
    } else {
      const Result<Real> r = solve(make_contact(w_, g, opt_), beta_, opt_);
      return {r.retained_area, r.normal_area, r.retained_error, r.normal_error};
    }
  }
  Result<Real> result(const Real& g) {
    ++solves;
    return solve(make_contact(w_, g, opt_), beta_, opt_);
  }
  const Waveform<Real>& wave() const { return w_; }
  const Real& beta() const { return beta_; }
  RootStats& stats() { return stats_; }
  std::size_t solves = 0;

 private:
  const Waveform<Real>& w_;
  Real beta_;
  Options opt_;
  RootStats stats_;
  std::vector<Real> ends_;  // the last spring's stick ends (continuation)
};

// A piecewise-linear wave (triangle, sawtooth, square, samples): between two γ' breakpoints every
// event phase is affine in γ' (a contact boundary, an onset on a rising piece and the end of its
// ramp each solve a linear equation; a stick anchored at a kink starts at a fixed phase) and n is
// affine in (φ, γ') on each piece, so Φ_w(β, γ') and N_w(γ') are quadratics in γ' there. Three
// springs at the Chebyshev nodes u = 0, ±√3/2 of such an interval (u = (γ' − mid)/half) give both
// at any γ' in it, as c0 + c1·u + c2·u². Error of each (in eps, twice the unit roundoff): the
// springs' rounding bounds of that area weighted by the Lagrange basis, Σ|L_i(u)|·err_i (at most
// 5/3 of the largest on [−1, 1]), plus the quadratic's own rounding from its computed coefficients: Horner's
// 2(|c0| + |c1 u| + |c2| u²); u = (γ' − mid)/half, rounded twice, through dQ/du, |c1 + 2 c2 u|·|u|;
// c1 = (y2 − y0)/(2c) rounds twice, |c1|; c2 = (y0 + y2 − 2 y1)·2/3 three times,
// |y0 + y2|/3 + |c2| (c = √3/2 is the same rounded number in the nodes and in c1, c2); and the
// nodes mid ± c·half rounded to the type, within eps·(|mid| + half) in γ', each value off by
// at most that times max |dQ/dγ'| ≤ (|c1| + 2|c2|)/half, weighted by the Lebesgue function.
// (A fixed 48 eps of the largest value, used before, was 10–20 times that on a noisy signal.)
// Two more springs, at u = ±15/16, check the quadratic: a breakpoint the structure search did
// not find, at u_k with a jump Δ of the slope, moves a check's value by about Δ(15/16 − |u_k|)
// or more from the quadratic; one that misses a check by more than both bounds is not used (the
// interval's nodes are then each solved). Not at u = ±1, where Φ has a kink: the interval's ends
// carry the rounding of σ ↔ t, and a check an ulp beyond the kink misses by about Δ·ulp, which
// is the size of the bounds.
template <class Real>
class QuadraticSprings {
 public:
  // Springs at the nodes of (lo, hi); false if the check springs disagree with the quadratic.
  // Row: a SpringRow, or anything whose at(γ') gives a SpringValue (the tests' exact quadratics).
  template <class Row>
  bool fit(Row& row, const Real& lo, const Real& hi) {
    using std::abs;
    using std::sqrt;
    mid_ = (lo + hi) / 2;
    half_ = (hi - lo) / 2;
    const Real c = sqrt(Real(3)) / 2;  // cos(π/6)
    const Real x0 = mid_ - half_ * c, x2 = mid_ + half_ * c;
    if (!(x0 > lo) || !(x0 < mid_) || !(mid_ < x2) || !(x2 < hi)) return false;
    const SpringValue<Real> y0 = row.at(x0), y1 = row.at(mid_), y2 = row.at(x2);
    // y(u) = y1 + (y2 − y0)/(2c)·u + (y0 + y2 − 2 y1)/(2c²)·u², 2c² = 3/2.
    auto coefficients = [&](const Real& a, const Real& m, const Real& b, Real* k) {
      k[0] = m;
      k[1] = (b - a) / (2 * c);
      k[2] = (a + b - 2 * m) * 2 / 3;
    };
    coefficients(y0.retained_area, y1.retained_area, y2.retained_area, phi_);
    coefficients(y0.normal_area, y1.normal_area, y2.normal_area, n_);
    const SpringValue<Real>* ys[3] = {&y0, &y1, &y2};
    for (int i = 0; i < 3; ++i) {
      e_phi_[i] = ys[i]->retained_err;
      e_n_[i] = ys[i]->normal_err;
    }
    phi_sum_ = abs(Real(y0.retained_area + y2.retained_area)) / 3;
    n_sum_ = abs(Real(y0.normal_area + y2.normal_area)) / 3;
    node_shift_ = abs(mid_) + half_;
    if constexpr (!std::is_floating_point_v<Real>) scale_inputs();
    for (const Real& g : {Real(mid_ - half_ * 15 / 16), Real(mid_ + half_ * 15 / 16)}) {
      const SpringValue<Real> q = at(g), v = row.at(g);
      if (abs(q.retained_area - v.retained_area) > q.retained_err + v.retained_err ||
          abs(q.normal_area - v.normal_area) > q.normal_err + v.normal_err)
        return false;
    }
    return true;
  }
  SpringValue<Real> at(const Real& g) const {
    using std::abs;
    const Real u = (g - mid_) / half_;
    const Real phi = phi_[0] + u * (phi_[1] + u * phi_[2]), n = n_[0] + u * (n_[1] + u * n_[2]);
    if constexpr (!std::is_floating_point_v<Real>) {
      const auto [bound_phi, bound_n] = scaled_bounds(static_cast<double>(u));
      return {phi, n, Real(scale_ * bound_phi), Real(scale_ * bound_n)};
    }
    // The Lebesgue function Σ|L_i(u)|: L_1 = 1 − 4u²/3, L_0,2 = 2u(u ∓ c)/3, c = √3/2.
    const Real uu = u * u, l1 = abs(Real(1 - 4 * uu / 3)), side = abs(u) * 2 / 3, c = Real(0.8660254037844386468L);
    const Real l0 = side * abs(Real(u - c)), l2 = side * abs(Real(u + c));
    const Real lebesgue = l0 + l1 + l2;
    const Real au = abs(u);
    auto own = [&](const Real* k, const Real& sum) {
      const Real a0 = abs(k[0]), a1 = abs(k[1]), a2 = abs(k[2]);
      return 2 * a0 + 4 * a1 * au + (5 * a2 + sum) * uu + lebesgue * (a1 + 2 * a2) / half_ * node_shift_;
    };
    const Real eps = std::numeric_limits<Real>::epsilon();
    // 1e-3 widens the sum over the rounding of u, of c (to double), of the l_i and of the bound.
    const Real err_phi = (l0 * e_phi_[0] + l1 * e_phi_[1] + l2 * e_phi_[2] + eps * own(phi_, phi_sum_)) * Real(1.001);
    const Real err_n = (l0 * e_n_[0] + l1 * e_n_[1] + l2 * e_n_[2] + eps * own(n_, n_sum_)) * Real(1.001);
    return {phi, n, err_phi, err_n};
  }

 private:
  // A multiprecision type (mpfr, cpp_bin_float): at()'s bound computed in double, every input
  // divided by one scale of the type (the largest of the springs' bounds and of eps times the
  // quadratic's terms), so that none leaves double's range at 10^-10000; the scale multiplies
  // the result once. Each node then costs Horner's scheme and one product of the type, not 30
  // operations (40% of a 25-digit wear-flat row, measured). The terms are positive and each of
  // about 30 operations rounds by 2^-53; u rounded to double moves the Lagrange weights by 1e-16
  // of their slope, far below the 2 eps of the value that the quadratic's own term charges at
  // every u: 1.001 covers both. A ratio that underflows (below 1e-308 of the scale) is covered
  // by 1e-290.
  struct Scaled {
    double e_phi[3], e_n[3], phi[3], n[3], phi_sum, n_sum, phi_node, n_node;
  };
  void scale_inputs() {
    using std::abs;
    const Real eps = std::numeric_limits<Real>::epsilon();
    auto node = [&](const Real* k) { return Real(eps * (abs(k[1]) + 2 * abs(k[2])) / half_ * node_shift_); };
    const Real phi_node = node(phi_), n_node = node(n_);
    scale_ = std::max({e_phi_[0], e_phi_[1], e_phi_[2], e_n_[0], e_n_[1], e_n_[2], Real(eps * abs(phi_[0])), Real(eps * abs(phi_[1])), Real(eps * abs(phi_[2])),
                       Real(eps * abs(n_[0])), Real(eps * abs(n_[1])), Real(eps * abs(n_[2])), Real(eps * phi_sum_),
                       Real(eps * n_sum_), phi_node, n_node});
    if (!(scale_ > 0)) scale_ = std::numeric_limits<Real>::min();
    auto ratio = [&](const Real& x) { return static_cast<double>(Real(x / scale_)); };
    for (int i = 0; i < 3; ++i) {
      scaled_.e_phi[i] = ratio(e_phi_[i]);
      scaled_.e_n[i] = ratio(e_n_[i]);
      scaled_.phi[i] = ratio(Real(eps * abs(phi_[i])));
      scaled_.n[i] = ratio(Real(eps * abs(n_[i])));
    }
    scaled_.phi_sum = ratio(Real(eps * phi_sum_));
    scaled_.n_sum = ratio(Real(eps * n_sum_));
    scaled_.phi_node = ratio(phi_node);
    scaled_.n_node = ratio(n_node);
  }
  // The bounds of Φ and of N at u, in units of the scale.
  std::pair<double, double> scaled_bounds(double u) const {
    const double uu = u * u, l1 = std::abs(1 - 4 * uu / 3), side = std::abs(u) * 2 / 3, c = 0.8660254037844386;
    const double l0 = side * std::abs(u - c), l2 = side * std::abs(u + c);
    const double lebesgue = l0 + l1 + l2, au = std::abs(u);
    auto own = [&](const double* a, double sum, double node) {
      return 2 * a[0] + 4 * a[1] * au + (5 * a[2] + sum) * uu + lebesgue * node;
    };
    const double q_phi = own(scaled_.phi, scaled_.phi_sum, scaled_.phi_node), q_n = own(scaled_.n, scaled_.n_sum, scaled_.n_node);
    return {(l0 * scaled_.e_phi[0] + l1 * scaled_.e_phi[1] + l2 * scaled_.e_phi[2] + q_phi) * 1.001 + 1e-290,
            (l0 * scaled_.e_n[0] + l1 * scaled_.e_n[1] + l2 * scaled_.e_n[2] + q_n) * 1.001 + 1e-290};
  }

  Real mid_, half_, node_shift_, phi_sum_, n_sum_;
  Real phi_[3], n_[3], e_phi_[3], e_n_[3];
  Real scale_;
  Scaled scaled_{};
};

// The preconditions of a curved contact (solve_curved's): β > 0 finite, contact, and the contact
// within the profile (a measured profile ends at its last sample). Returns the case's name for
// messages: the flat context and the profile.
template <class Real>
std::string check_curved(const Waveform<Real>& w, const Profile<Real>& profile, const Real& beta, const Real& gamma) {
  check_beta(w, beta);
  check_contact(w, gamma);
  if (gamma + w.maximum() > profile.sigma_limit())
    throw DomainError("gamma = " + short_str(gamma) + " for profile " + profile.name() + ": the contact reaches beyond its last sample (sigma = " +
                      short_str(profile.sigma_limit()) + "): expected gamma <= " + short_str(Real(profile.sigma_limit() - w.maximum())));
  return context(w, beta, &gamma) + ", profile " + profile.name();
}

// The rising piece of w that contains phase φ ∈ [0, 1) (first contact lies on one).
template <class Real>
std::size_t rising_piece_at(const Waveform<Real>& w, const Real& phi) {
  for (std::size_t i = 0; i < w.piece_count(); ++i)
    if (w.piece_begin(i) <= phi && phi <= w.piece_end(i) && w.end_value(i) > w.begin_value(i)) return i;
  throw SolverError("first contact at phase " + short_str(phi) + " lies on no rising piece");
}

// The onset of a stick anchored at first contact (level 0) of the spring at γ' = m, as a function
// of γ' on the interval between two γ' breakpoints around m: an upward jump out of zero starts it
// at a fixed phase q; first contact on a rising piece at the γ'-dependent phase where w = −γ'.
template <class Real>
struct AnchoredOnset {
  AnchoredOnset(const Waveform<Real>& w, const StickPhase<Real>& st, const Real& m, RootStats& stats)
      : w_(w), begin_(st.begin), stats_(stats) {
    const std::size_t pieces = w.piece_count();
    for (std::size_t i = 0; i < pieces; ++i)
      if (w.jump_at(i) && w.piece_begin(i) == st.begin && !(m + w.end_value((i + pieces - 1) % pieces) > 0)) at_jump = true;
    if (!at_jump) piece = rising_piece_at(w, st.begin);
  }
  Real operator()(const Real& g) const {
    if (at_jump) return begin_;
    const std::size_t i = *piece;
    const Real lo = w_.begin_value(i) + g, hi = w_.end_value(i) + g;
    // γ' carried through σ ↔ t (a quadrature node next to the interval's end) may pass the end
    // by a rounding: the onset is then that end of the piece, not a failed bracket.
    using std::abs;
    const Real rounding = 64 * std::numeric_limits<Real>::epsilon() * (abs(g) + 1);
    if (hi < 0 && -hi <= rounding) return w_.piece_end(i);
    if (lo > 0 && lo <= rounding) return w_.piece_begin(i);
    return w_.solve_value_root(i, Real(-g), w_.piece_begin(i), w_.piece_end(i), lo, hi, stats_);
  }
  bool at_jump = false;
  std::optional<std::size_t> piece;  // the rising piece of first contact (not at_jump)

 private:
  const Waveform<Real>& w_;
  Real begin_;
  RootStats& stats_;
};

}  // namespace detail

// The γ' in (lo, hi) where Φ_w(β, γ') or N_w(γ') is not analytic, ascending. From the waveform:
// the contact boundary passes a piece end (γ' = −w at a piece end: jumping starts, a contact
// interval appears or splits, a kink of w enters), and first contact passes a point with
// w' = β (the onset switches between first contact and Eq. 4, and β = β_c(γ') there). From the
// event structure: a stick that starts at first contact (or at an upward jump from zero) has
// its ramp anchored at a γ'-dependent phase, and its end (Eq. 8) is non-decreasing in γ'; where
// it passes a kink of w or a point with w' = β (two stick phases merge), the chord from the
// onset to that point has slope β. Each such crossing is the unique root of a monotone
// function of γ' on its interval, found at the working precision.
template <class Real>
std::vector<Real> gamma_breakpoints(detail::SpringRow<Real>& row, const Real& lo, const Real& hi) {
  using detail::short_str;
  const Waveform<Real>& w = row.wave();
  const Real& beta = row.beta();
  const std::size_t pieces = w.piece_count();
  std::vector<Real> cand, tangent;
  for (std::size_t i = 0; i < pieces; ++i) {
    // A continuous join has one value, the next piece's begin_value; this piece's end_value is
    // the same number rounded another way (a sample's line at its end, an ulp or two off), and
    // as a second breakpoint it would only add pieces graded towards a neighbour ulps away.
    cand.push_back(-w.begin_value(i));
    if (w.jump_at((i + 1) % pieces)) cand.push_back(-w.end_value(i));
    const Real s0 = w.begin_slope(i) - beta, s1 = w.end_slope(i) - beta;
    if ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) {
      const auto exact = w.solve_slope(i, beta);
      const Real t = exact ? *exact
                           : detail::bracketed_root<Real>([&](const Real& x) -> Real { return w.slope(i, x) - beta; },
                                                          w.piece_begin(i), w.piece_end(i), s0, s1, "w' = beta", row.stats());
      tangent.push_back(t);
      cand.push_back(-w.value(i, t));
    }
  }
  auto inside = [&](const Real& g) { return g > lo && g < hi; };
  std::vector<Real> nodes{lo};
  for (const Real& g : cand)
    if (inside(g)) nodes.push_back(g);
  nodes.push_back(hi);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());

  // Kinks of w and tangency points, as targets a stick end can pass (with the one-sided values
  // at jumps).
  struct Target {
    Real phase, value;
  };
  std::vector<Target> targets;
  for (std::size_t i = 0; i < pieces; ++i) {
    targets.push_back({w.piece_begin(i), w.begin_value(i)});
    if (w.jump_at(i)) targets.push_back({w.piece_begin(i), w.end_value((i + pieces - 1) % pieces)});
  }
  for (const Real& t : tangent) targets.push_back({t, w(t)});
  std::stable_sort(targets.begin(), targets.end(), [](const Target& x, const Target& y) { return x.phase < y.phase; });

  std::vector<Real> out(nodes.begin() + 1, nodes.end() - 1);
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const Real &a = nodes[k], &b = nodes[k + 1];
    const Real m = (a + b) / 2;
    // No value of the type lies strictly between a and b (two candidates an ulp or two apart, as
    // a sample's value and the previous piece's end value computed from its slope): no breakpoint
    // can either, and m rounded onto a = −max w would be a spring without contact.
    if (!(m > a) || !(m < b)) continue;
    const Result<Real> rm = row.result(m);
    std::optional<Result<Real>> rb;  // at b, once per interval (a noisy signal has dozens of sticks)
    for (const auto& st : rm.stick_phases) {
      if (st.level != 0) continue;  // anchored on n: its events do not move with γ'
      const detail::AnchoredOnset<Real> onset(w, st, m, row.stats());
      const bool at_jump = onset.at_jump;
      const std::optional<std::size_t>& piece = onset.piece;
      // How far the end reaches on [a, b]: it is largest at b.
      const Real ob = onset(b);
      Real reach = st.end;
      if (!rb) rb = row.result(b);
      for (const auto& sb : rb->stick_phases) {
        Real d = sb.begin - ob;
        if (d < 0) d = -d;
        if (d < Real(1) / (4 * pieces) && sb.end > reach) reach = sb.end;
      }
      for (int shift = 0; shift <= 2; ++shift) {
        // Only the targets with ob < phase + shift ≤ reach (sorted by phase, and phase + shift
        // rounds monotonically: a signal of N samples has 2N targets and dozens of sticks).
        auto first = std::partition_point(targets.begin(), targets.end(),
                                          [&](const Target& tg) { return !(Real(tg.phase + shift) > ob); });
        for (auto it = first; it != targets.end(); ++it) {
          const Target& tg = *it;
          const Real t = tg.phase + shift;
          if (t > reach) break;
          // On the onset's own piece the ramp cannot end (n − ramp rises from the onset, or is
          // concave and ends beyond the piece): its interior points are no targets, and the
          // chord to them has only the double root at the onset itself.
          if (piece && shift == 0 && t > w.piece_begin(*piece) && t < w.piece_end(*piece)) continue;
          auto F = [&](const Real& g) -> Real { return g + tg.value - beta * (t - onset(g)); };
          if (at_jump) {
            const Real g = beta * (t - st.begin) - tg.value;
            if (inside(g) && g > a && g < b) out.push_back(g);
            continue;
          }
          const Real fa = F(a), fb = F(b);
          if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0))
            out.push_back(detail::bracketed_root<Real>(F, a, b, fa, fb, "stick end passes a kink (Eq. 8)", row.stats()));
        }
      }
    }
  }
  std::sort(out.begin(), out.end());
  // Crossings a few ulps apart (one root found from the intervals on both sides of a node, or at
  // a vertex) are one breakpoint: each is known to 4 eps (bracketed_root) plus the rounding of
  // the values it is solved from, and Φ and N are continuous in γ' (a sliver of width δ moved to
  // its neighbour's branch changes an integral by about δ^1.5). Kept apart, they only add pieces
  // graded towards a neighbour ulps away: 5,339 segments instead of 390 at 25 digits (a noisy
  // 200-sample signal on the wear flat).
  using std::abs;
  const Real eps = std::numeric_limits<Real>::epsilon();
  std::vector<Real> merged;
  for (const Real& g : out)
    if (merged.empty() || g - merged.back() > 64 * eps * std::max(Real(abs(g)), Real(1))) merged.push_back(g);
  return merged;
}

// μ̄/μ0 of a curved contact (model.md MDR), with the integrals and diagnostics. Preconditions
// as solve(): β > 0 finite, γ finite with γ + max w > 0, and the contact (σ = γ + max w) within
// the profile (a measured profile ends at its last sample: DomainError beyond). Throws
// SolverError if a spring, a breakpoint or a quadrature segment fails to converge.
template <class Real>
CurvedResult<Real> solve_curved(const Waveform<Real>& w, const Profile<Real>& profile, const Real& beta,
                                const Real& gamma, const Options& opt = {}, Real target = 0) {
  using detail::short_str;
  using std::abs;
  const std::string where = detail::check_curved(w, profile, beta, gamma);
  const Real sigma_max = gamma + w.maximum();
  const Real eps = std::numeric_limits<Real>::epsilon();
  if (!(target > 0)) target = 64 * eps;
  // Quadrature stops when two rules (levels) differ by tol·L1; rounding keeps that difference
  // above a few eps, so the tolerance is the target but never below 32 eps.
  const Real tol = opt.quadrature_tolerance > 0 ? Real(opt.quadrature_tolerance) : std::max(target, Real(32 * eps));

  detail::SpringRow<Real> row(w, beta, opt);
  CurvedResult<Real> r;
  r.center_jumps = gamma + w.minimum() < 0;
  r.contact_radius = profile.x_at_sigma(sigma_max);
  try {
    const Result<Real> center = row.result(gamma);
    r.beta_c = center.beta_c;
    r.gamma_breaks = gamma_breakpoints(row, Real(-w.maximum()), gamma);

    // Breakpoints in t: the γ' breakpoints and the profile's own kinks.
    const Real t0 = profile.t_at_sigma(Real(0)), t1 = profile.t_at_sigma(sigma_max);
    std::vector<Real> ts{t0};
    for (const Real& g : r.gamma_breaks) ts.push_back(profile.t_at_sigma(Real(gamma - g)));
    for (const Real& t : profile.t_breaks())
      if (t > t0 && t < t1) ts.push_back(t);
    ts.push_back(t1);
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    const std::vector<Real> ps = detail::graded_pieces(ts);

    // β ≥ β_c(γ) ≥ β_c(γ') for every spring (β_c grows with γ'): no stick anywhere, Φ = N (Eq. 6).
    const bool sticks = beta < center.beta_c;
    Real F = profile.flat_length() * center.retained_area, N = profile.flat_length() * center.normal_area;
    // Rounding: the springs' bounds, each area's integrated as its largest value times the segment
    // length (Φ's bound may be a tenth of N's), and a flat part's central spring's.
    Real rounding_F = profile.flat_length() * center.retained_error, rounding_N = profile.flat_length() * center.normal_error;
    // Quadrature estimates apart too: Φ's relative error is of Φ's own estimates.
    Real lF = abs(F), lN = abs(N), qerr_F = 0, qerr_N = 0;
    std::vector<std::map<Real, detail::SpringValue<Real>>> memo(ps.size());
    std::vector<Real> worst_F(ps.size(), Real(0)), worst_N(ps.size(), Real(0));
    // A piecewise-linear wave: each interval of ts (between two breakpoints), and so each graded
    // piece in it, takes its springs from one quadratic where the check springs agree.
    const bool linear = dynamic_cast<const PiecewiseLinear<Real>*>(&w) != nullptr;
    // σ = t^P with P = 1 … 4 (cone, sphere): a quadratic's segment integrates Q(γ − t^P), a
    // polynomial of degree 2P in t, which the Gauss rule of P + 1 points integrates exactly.
    std::size_t exact_points = 0;
    if (const auto* power = dynamic_cast<const PowerProfile<Real>*>(&profile))
      for (int p = 1; p <= 4; ++p)
        if (power->exponent() == p) exact_points = static_cast<std::size_t>(p) + 1;
    std::vector<std::size_t> interval(ps.size(), 0);
    for (std::size_t k = 0, j = 0; k < ps.size(); ++k) {
      while (j + 2 < ts.size() && !(ps[k] < ts[j + 1])) ++j;
      interval[k] = j;
    }
    std::vector<std::optional<detail::QuadraticSprings<Real>>> fits(ts.size());
    std::vector<bool> fitted(ts.size(), false);
    auto fitted_quadratic = [&](std::size_t k) -> const detail::QuadraticSprings<Real>* {
      if (!linear) return nullptr;
      const std::size_t j = interval[k];
      if (!fitted[j]) {
        fitted[j] = true;
        detail::QuadraticSprings<Real> q;
        const Real lo = gamma - profile.sigma_at_t(ts[j + 1]), hi = gamma - profile.sigma_at_t(ts[j]);
        if (q.fit(row, lo, hi)) {
          fits[j] = q;
          ++r.quadratic_segments;
        }
      }
      return fits[j] ? &*fits[j] : nullptr;
    };
    auto weighted = [&](std::size_t k, detail::SpringValue<Real> v, const Real& t) {
      const Real wgt = profile.dx_dt(t);
      v.retained_area *= wgt;
      v.normal_area *= wgt;
      v.retained_err *= abs(wgt);
      v.normal_err *= abs(wgt);
      if (v.retained_err > worst_F[k]) worst_F[k] = v.retained_err;
      if (v.normal_err > worst_N[k]) worst_N[k] = v.normal_err;
      return v;
    };
    auto spring = [&](std::size_t k, const Real& t) -> detail::SpringValue<Real> {
      if (const auto* q = fitted_quadratic(k)) return weighted(k, q->at(Real(gamma - profile.sigma_at_t(t))), t);
      auto it = memo[k].find(t);
      if (it != memo[k].end()) return it->second;
      return memo[k].emplace(t, weighted(k, row.at(Real(gamma - profile.sigma_at_t(t))), t)).first->second;
    };
    // The accuracy asked of a segment is relative to the whole integral (N ≥ Φ ≥ 0), estimated
    // by the midpoint rule first: a segment between two nearly equal breakpoints then needs only
    // Boost's four levels, not digits it cannot reach relative to its own tiny size.
    Real scale = N;
    for (std::size_t k = 0; k + 1 < ps.size(); ++k)
      if (ps[k + 1] > ps[k]) scale += (ps[k + 1] - ps[k]) * spring(k, Real((ps[k] + ps[k + 1]) / 2)).normal_area;
    using std::sqrt;
    for (std::size_t k = 0; k + 1 < ps.size(); ++k) {
      const Real &a = ps[k], &b = ps[k + 1];
      if (!(b > a)) continue;
      const Real size = (b - a) * spring(k, Real((a + b) / 2)).normal_area;
      // A quadratic's segment costs no springs: it is integrated to the type's own precision,
      // whatever the target. Its first rule keeps the size the digits give: σ = t^N with N = 1e6
      // changes within 1e-6 of the end, which rules of 8 and 12 points both miss (they agreed on
      // the flat punch's 11/15 for the square wave at β = 1.5, γ = −0.6; the closed form and the
      // rules from 22 points give 0.73333347).
      const bool quadratic = fitted_quadratic(k) != nullptr;
      const Real seg_target = quadratic ? Real(32 * eps) : tol;
      const Real seg_tol = size > seg_target * scale ? std::min(Real(seg_target * scale / size), Real(sqrt(eps))) : Real(sqrt(eps));
      // A quadratic's segment: the pass for N asks for the nodes the pass for Φ asked for, in the
      // same order (the same rules), and takes their values from it (at a node, a profile's σ and
      // dx/dt and the quadratic with its bound cost as much as the rest of the segment).
      std::vector<std::pair<Real, detail::SpringValue<Real>>> seen;
      for (int which = sticks ? 0 : 1; which < 2; ++which) {
        Real err = 0, l1 = 0;
        Real value = 0;
        std::size_t replayed = 0;
        const auto h = [&](const Real& t) -> Real {
          if (!quadratic) {
            const auto v = spring(k, t);
            return which == 1 ? v.normal_area : v.retained_area;
          }
          const std::size_t i = replayed++;
          if (which == 1 && i < seen.size() && seen[i].first == t) return seen[i].second.normal_area;
          auto v = spring(k, t);
          if (which == 1) return v.normal_area;
          const Real phi = v.retained_area;
          seen.emplace_back(t, std::move(v));
          return phi;
        };
        if (quadratic && exact_points > 0) {
          // No quadrature error: the values' rounding is in worst_F[k] and worst_N[k], and the
          // sum's, m + 3 ≤ 8 roundings of the unit roundoff (m ≤ 5 points, the weights, the
          // width), in 4 eps·L1.
          auto on_segment = [&](const Real& x) -> Real { return h(Real(a + (b - a) * x)); };
          detail::gauss_apply(on_segment, exact_points, value, l1);
          value *= b - a;
          l1 *= b - a;
        } else {
          detail::integrate_piece(h, a, b, seg_tol, Real(seg_target * scale), opt, which ? "N" : "Phi", value, err, l1);
        }
        (which ? qerr_N : qerr_F) += err;
        (which ? N : F) += value;
        (which ? lN : lF) += l1;
        if (!sticks) {
          F += value;
          lF += l1;
        }
      }
      rounding_F += (b - a) * worst_F[k];
      rounding_N += (b - a) * worst_N[k];
      ++r.segments;
    }
    r.friction_integral = F;
    r.normal_integral = N;
    r.quadrature_error = qerr_F + qerr_N;
    r.springs = row.solves;
    if (!sticks) {
      r.mu = 1;  // Eq. 6 exactly
      r.relative_error = 0;
      return r;
    }
    r.mu = F / N;
    if (r.mu > 1) r.mu = 1;  // s ≤ n for every spring: above 1 is rounding
    const Real unknown = std::numeric_limits<Real>::infinity();
    r.relative_error = (F > 0 && N > 0) ? Real((qerr_F + rounding_F + 4 * eps * lF) / F + (qerr_N + rounding_N + 4 * eps * lN) / N)
                                        : unknown;
  } catch (const PrecisionError&) {
    throw;
  } catch (const SolverError& e) {
    throw SolverError(where + ": " + e.what());
  }
  return r;
}

// Compiled once per number type with the flat solver (solver.hpp, VIBROFRIC_SOLVER_INSTANCES).
#define VIBROFRIC_CURVED_INSTANCES(EXTERN, Real)                                                          \
  EXTERN template std::vector<Real> gamma_breakpoints<Real>(detail::SpringRow<Real>&, const Real&, const Real&); \
  EXTERN template CurvedResult<Real> solve_curved<Real>(const Waveform<Real>&, const Profile<Real>&, const Real&, \
                                                        const Real&, const Options&, Real);

VIBROFRIC_CURVED_INSTANCES(extern, double)
VIBROFRIC_CURVED_INSTANCES(extern, long double)
VIBROFRIC_CURVED_INSTANCES(extern, bin50)
VIBROFRIC_CURVED_INSTANCES(extern, bin100)
VIBROFRIC_CURVED_INSTANCES(extern, mpfr)

}  // namespace vibrofric
