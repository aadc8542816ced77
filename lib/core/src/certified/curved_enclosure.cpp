// The curved enclosure (curved_enclosure.hpp): the row's integral by Taylor models in intervals.
#include "vibrofric/core/certified/curved_enclosure.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "newton.hpp"
#include "taylor.hpp"

namespace vibrofric::certified {

namespace {

using taylor::Series;

Interval of(const exact::Rational& x, mpfr_prec_t bits) { return Interval::rational(x.backend().data(), bits); }

Sign decide(const Interval& x, const std::string& what) {
  const Sign s = x.sign();
  if (s == Sign::undecided) throw Undecided("undecided at this precision: " + what);
  return s;
}

// How the spring's mean indentation γ' depends on a piece's parameter p.
enum class Param {
  t,        // γ' = γ − t
  u_minus,  // γ' = −1 + u²
  u_plus,   // γ' = 1 − u²
  tau,      // the stick's length: γ' = −sin θ(τ), a stick from touch-down
};
enum class Regime { slip, contact_onset, fixed_onset, no_jump };

// p = anchor + dir·h, h ∈ [0, length]; the Taylor model is taken at h = 0, where t = γ − γ' may
// vanish to order t_order (the weight's singular end) and dγ'/dh to order 1 (u = 0).
struct Piece {
  Piece(Param p, Regime r, Interval a, int d, Interval h, int t = 0, bool dv = false)
      : param(p), regime(r), anchor(std::move(a)), dir(d), length(std::move(h)), t_order(t), d_vanishes(dv) {}
  Param param;
  Regime regime;
  Interval anchor;
  int dir;
  Interval length;
  int t_order;
  bool d_vanishes;
  std::optional<Interval> num, den;  // none: not yet, or no model on this piece (bisect it)
};

class Row {
 public:
  Row(const CurvedProfile& profile, const exact::Rational& beta, const exact::Rational& gamma, mpfr_prec_t bits)
      : bits_(bits),
        order_(static_cast<std::size_t>(std::max<mpfr_prec_t>(24, bits / 6 * 2))),  // even
        pi_(Interval::pi(bits)),
        half_(Interval::integer(1, bits) / Interval::integer(2, bits)),
        half_pi_(pi_ * half_),
        b_(of(beta, bits) / (pi_ * 2L)),
        gamma_(of(gamma, bits)),
        psi_(bits),
        wearflat_(profile.kind == CurvedProfile::Kind::wearflat),
        parameter_(of(profile.parameter, bits)),
        alpha_(bits),
        root_half_(sqrt(Interval::integer(1, bits) / Interval::integer(2, bits))) {
    if (!wearflat_) {
      alpha_ = Interval::integer(1, bits) / parameter_ - Interval::integer(1, bits);
      power_one_ = profile.parameter == 1;
    }
  }

  const Interval& b() const { return b_; }
  mpfr_prec_t bits() const { return bits_; }
  void set_psi(Interval psi) { psi_ = std::move(psi); }
  const Interval& psi() const { return psi_; }

  // γ'(τ) on a stick from touch-down, with dγ'/dτ (a series of size 2 at the base X).
  std::pair<Interval, Interval> gamma_of_tau(const Interval& X) const {
    const Series g = local(Param::tau, Regime::contact_onset, Series::line(X, Interval::integer(1, bits_), 2)).gp;
    return {g[0], g[1]};
  }

  // The enclosures of ∫Φ and ∫N (the piece's share of ∫… dx), or none where this piece's model
  // fails (an interval function's argument leaves its domain over the piece: bisect it). The
  // remainder's coefficient is computed by `coarse`, the same row at fewer bits: it is multiplied
  // by h^K, so a few correct digits of it are all the sum needs.
  void model(Piece& piece, const Row& coarse) const {
    try {
      const std::size_t size = order_ + 4;
      const Interval one = Interval::integer(1, bits_);
      const Interval slope = one * static_cast<long>(piece.dir);
      const Interval far = piece.anchor + slope * piece.length;
      const Interval box = hull(piece.anchor, far).rounded(coarse.bits_);
      auto [num_box, den_box, e, orientation] =
          coarse.integrand(piece, Series::line(box, slope.rounded(coarse.bits_), size), std::nullopt);
      (void)e;
      // A piece without a singular end is expanded about its middle (h ∈ [−H/2, H/2]: the odd
      // moments vanish, and the remainder shrinks 2^K-fold against an expansion at an end).
      const bool centered = piece.t_order == 0 && !piece.d_vanishes;
      const Interval reach = centered ? piece.length * half_ : piece.length;
      const Interval base = centered ? piece.anchor + slope * reach : piece.anchor;
      auto [num_pt, den_pt, e_pt, o_pt] = integrand(piece, Series::line(base, slope, size), orientation);
      (void)o_pt;
      // ∫ h^e (Σ_{k<K} c_k h^k + r(h) h^K) dh, r(h) in the box's K-th coefficient, h^(e+K) ≥ 0
      // (K is even)
      const std::size_t K = order_;
      Interval num(bits_), den(bits_);
      const Interval log_reach = log(reach);
      for (std::size_t k = 0; k <= K; ++k) {
        if (centered && k % 2 == 1) continue;
        const Interval power = e_pt + one * static_cast<long>(k + 1);
        Interval moment = exp(power * log_reach) / power;
        if (centered) moment = moment * 2L;
        num += (k < K ? num_pt[k] : num_box[K]) * moment;
        den += (k < K ? den_pt[k] : den_box[K]) * moment;
      }
      if (!num.bounded() || !den.bounded()) return;
      piece.num = num;
      piece.den = den;
    } catch (const Undecided&) {
      throw;
    } catch (const SolverError&) {
      // an interval function outside its domain over this piece (asin, sqrt, log): bisect
    }
  }

 private:
  struct Local {
    Series gp, c, a;  // γ', √(1 − γ'²), asin γ' (the last two where |γ'| < 1)
  };

  Local local(Param param, Regime regime, const Series& p) const {
    const std::size_t n = p.size();
    const Interval one = Interval::integer(1, bits_);
    Series none(n, bits_);
    switch (param) {
      case Param::t: {
        Series gp = gamma_ - p;
        if (regime == Regime::no_jump) return {gp, none, none};  // N = γ'
        Series c = sqrt(Series::constant(one, n) - gp * gp);
        Series a = asin(gp);
        return {std::move(gp), std::move(c), std::move(a)};
      }
      case Param::u_minus:
      case Param::u_plus: {
        const bool minus = param == Param::u_minus;
        Series c = p * sqrt(Series::constant(one * 2L, n) - p * p);  // √(1 − γ'²) = u √(2 − u²)
        Series twice_asin = asin(p * root_half_) * Interval::integer(2, bits_);
        Series gp = minus ? p * p - one : one - p * p;
        Series a = minus ? twice_asin - half_pi_ : half_pi_ - twice_asin;
        return {std::move(gp), std::move(c), std::move(a)};
      }
      case Param::tau: {
        // θ + τ/2 = acos(b / sinc(τ/2)) ∈ [0, π/2): the stick's middle, after the touch-down θ
        const Series z = p * half_;
        const Series s1 = taylor::sinc(p[0] * half_, p.size() > 1 ? p[1] * half_ : Interval(bits_), n);
        const Series theta = half_pi_ - asin(Series::constant(b_, n) / s1) - z;
        auto [s, c] = sin_cos(theta);
        return {-std::move(s), std::move(c), -theta};
      }
    }
    return {none, none, none};
  }

  // The integrands of ∫Φ and ∫N over h at the base of p, as series of f with ∫ f h^e dh the
  // piece's share; the orientation (the sign of dγ'/dh) is decided at the box and passed on.
  std::tuple<Series, Series, Interval, int> integrand(const Piece& piece, const Series& p, std::optional<int> orientation) const {
    const std::size_t n = p.size();
    const Interval one = Interval::integer(1, bits_);
    const Local l = local(piece.param, piece.regime, p);
    // N and Φ (curved_enclosure.hpp's four ranges)
    Series N = piece.regime == Regime::no_jump ? l.gp : (l.c + l.gp * (half_pi_ + l.a)) * (one / pi_);
    Series Phi = N;
    if (piece.regime == Regime::fixed_onset || piece.regime == Regime::no_jump) Phi = N - psi_;
    if (piece.regime == Regime::contact_onset) {
      auto [sin_tau, cos_tau] = sin_cos(p);
      const Series lost = (l.gp * (p - sin_tau) + l.c * (Series::constant(one, n) - cos_tau) - b_ * (p * p) * half_) *
                          (one / (pi_ * 2L));
      Phi = N - lost;
    }
    // the weight dx/dt at t = γ − γ'
    Interval e(bits_);
    Series t = piece.param == Param::t ? p : gamma_ - l.gp;
    Series weight = Series::constant(one, n);
    if (wearflat_) {
      const Series q = t * (one / parameter_);
      const Series r = sqrt(Series::constant(one, n) + q * q * Interval::integer(4, bits_));
      const Series x = sqrt((r + one) * half_);
      weight = q / (x * r * parameter_);
    } else if (!power_one_) {
      if (piece.t_order > 0) {
        t = t.shifted(static_cast<std::size_t>(piece.t_order));
        e += alpha_ * static_cast<long>(piece.t_order);
      }
      weight = pow(t, alpha_) * (one / parameter_);
    }
    Series d = l.gp.derivative();
    if (piece.d_vanishes) {
      d = d.shifted(1);
      e += one;
    }
    if (!orientation) {
      const Sign s = d[0].sign();
      if (s != Sign::positive && s != Sign::negative) throw SolverError("γ' not monotone over the piece");
      orientation = s == Sign::positive ? 1 : -1;
    }
    const Series factor = weight * d * (one * static_cast<long>(*orientation));
    return {Phi * factor, N * factor, e, *orientation};
  }

  mpfr_prec_t bits_;
  std::size_t order_;
  Interval pi_, half_, half_pi_, b_, gamma_, psi_;
  bool wearflat_;
  Interval parameter_, alpha_;  // N or λ; 1/N − 1
  bool power_one_ = false;
  Interval root_half_;
};

// The root of γ'(τ) = target on a stick from touch-down, where γ' increases from −g at τ = 0 up
// to the range's end (γ' = g) and a little beyond, then falls: steps from 0 while γ' rises and
// stays below the target (a step that lands where γ' is undefined or falls is halved), bisection
// inside the step that passes it, then interval Newton, whose image inside the box proves the
// root there and unique.
Interval tau_at(const Row& row, const Interval& target, const std::string& what) {
  const mpfr_prec_t bits = row.bits();
  const auto thin = [&](double x) {
    mpfr v;
    mpfr_set_prec(v.backend().data(), bits + 8);
    mpfr_set_d(v.backend().data(), x, MPFR_RNDN);
    return v;
  };
  // γ'(τ) − target and its slope at the point τ; none past the stick lengths there are
  const auto at = [&](const mpfr& tau) -> std::optional<std::pair<Sign, Sign>> {
    try {
      auto [g, slope] = row.gamma_of_tau(Interval::exact(tau, bits));
      return std::make_pair((g - target).sign(), slope.sign());
    } catch (const Undecided&) {
      throw;
    } catch (const SolverError&) {
      return std::nullopt;
    }
  };
  const auto undecided = [&] { return Undecided(what + ": the stick's length is not isolated"); };
  mpfr lo = thin(0), hi = thin(0), step = thin(0.125);
  for (int k = 0;; ++k) {
    if (k > 64 * static_cast<int>(bits)) throw undecided();
    mpfr_add(hi.backend().data(), lo.backend().data(), step.backend().data(), MPFR_RNDN);
    const auto a = at(hi);
    if (a && a->first == Sign::positive) break;
    if (a && a->first == Sign::negative && a->second == Sign::positive) {
      lo = hi;
      continue;
    }
    if (a && (a->first == Sign::undecided || a->first == Sign::zero)) throw undecided();
    mpfr_div_2ui(step.backend().data(), step.backend().data(), 1, MPFR_RNDN);  // past the rise: smaller steps
    if (mpfr_get_exp(step.backend().data()) < -static_cast<long>(bits)) throw undecided();
  }
  for (int k = 0; k < bits / 2; ++k) {
    mpfr mid = thin(0);
    mpfr_add(mid.backend().data(), lo.backend().data(), hi.backend().data(), MPFR_RNDN);
    mpfr_div_2ui(mid.backend().data(), mid.backend().data(), 1, MPFR_RNDN);
    const auto a = at(mid);
    if (!a || (a->first != Sign::positive && a->first != Sign::negative)) throw undecided();
    (a->first == Sign::positive ? hi : lo) = mid;
  }
  // One Newton step maps the bracket into itself: the root is there and unique; then contract.
  const Interval X = Interval::hull(lo, hi, bits);
  const auto f = [&](const Interval& tau) { return row.gamma_of_tau(tau).first - target; };
  const auto df = [&](const Interval& tau) {
    const Interval slope = row.gamma_of_tau(tau).second;
    if (slope.sign() != Sign::positive) throw undecided();
    return slope;
  };
  const Interval m = Interval::exact(X.midpoint(), bits);
  const Interval N = m - f(m) / df(X);
  if (!X.contains(N)) throw undecided();
  return newton(N, f, df, bits, what);
}

}  // namespace

CurvedEnclosure enclose_curved_sine(const CurvedProfile& profile, const exact::Rational& beta, const exact::Rational& gamma,
                                    mpfr_prec_t bits) {
  if (beta <= 0) throw InputError("beta must be > 0");
  if (profile.kind == CurvedProfile::Kind::power && profile.parameter < 1)
    throw InputError("profile power:N needs N >= 1");
  if (profile.kind == CurvedProfile::Kind::wearflat && profile.parameter <= 0)
    throw InputError("profile wearflat:LAMBDA needs LAMBDA > 0");
  if (gamma <= -1) throw DomainError("gamma <= -1: no spring of the row touches (no contact)");
  CurvedEnclosure out(bits);
  Row row(profile, beta, gamma, bits);
  Row coarse(profile, beta, gamma, std::min<mpfr_prec_t>(bits, 64));
  const Interval one = Interval::integer(1, bits);
  const Interval G = of(gamma, bits);
  // β ≥ 2π: no spring sticks (Eq. 6 for every γ'), μ̄ = μ0 exactly
  const Sign beyond = decide(row.b() - one, "beta against 2 pi");
  std::vector<Piece> pieces;
  if (beyond == Sign::negative) {
    out.stick = true;
    row.set_psi(enclose_sine(beta, 1, bits).lost_area);
    coarse.set_psi(row.psi().rounded(coarse.bits()));
    const Interval g = sqrt(one - sqr(row.b()));
    // γ < −g: every spring slips (β ≥ β_c(γ') for all γ' ≤ γ), μ̄ = μ0 exactly
    if (decide(-g - G, "gamma against -g") != Sign::negative) {
      out.stick = false;
      out.mu = one;
      return out;
    }
    // the ranges' ends below γ, in order: −1, −g, g, 1, then γ
    enum What { minus_one, minus_g, plus_g, plus_one, at_gamma };
    struct End {
      Interval value;
      What what;
    };
    std::vector<End> ends{{-one, minus_one}};
    ends.push_back({-g, minus_g});  // below γ: decided above
    if (decide(g - G, "gamma against g") == Sign::negative) ends.push_back({g, plus_g});
    if (gamma > 1) ends.push_back({one, plus_one});
    ends.push_back({G, at_gamma});
    const Interval half = one / Interval::integer(2, bits);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
      const End& lo = ends[i];
      const End& hi = ends[i + 1];
      const Regime regime = lo.what == minus_one ? Regime::slip
                            : lo.what == minus_g ? Regime::contact_onset
                            : lo.what == plus_g  ? Regime::fixed_onset
                                                 : Regime::no_jump;
      const bool top_is_one = hi.what == plus_one || (hi.what == at_gamma && gamma == 1);
      const int t_order_at_top = hi.what == at_gamma ? 1 : 0;
      if (regime == Regime::contact_onset) {
        const Interval tau_hi = tau_at(row, hi.value, "the stick at the range's end");
        if (hi.what == at_gamma) {
          const Interval mid = Interval::exact(tau_hi.midpoint(), bits) * half;
          pieces.emplace_back(Param::tau, regime, Interval(bits), 1, mid);
          pieces.emplace_back(Param::tau, regime, tau_hi, -1, tau_hi - mid, 1);
        } else {
          pieces.emplace_back(Param::tau, regime, Interval(bits), 1, tau_hi);
        }
        continue;
      }
      if (regime == Regime::no_jump) {
        pieces.emplace_back(Param::t, regime, Interval(bits), 1, G - one, 1);
        continue;
      }
      // slip or a stick from n' = β: u at ±1, t elsewhere (anchored at the upper end, t = γ − γ')
      const Interval mid = (lo.value + hi.value) * half;
      Interval bottom = lo.value, top = hi.value;
      if (lo.what == minus_one) {
        pieces.emplace_back(Param::u_minus, regime, Interval(bits), 1, sqrt(mid + one), 0, true);
        bottom = mid;
      }
      if (top_is_one) {
        pieces.emplace_back(Param::u_plus, regime, Interval(bits), 1, sqrt(one - mid), gamma == 1 ? 2 : 0, true);
        top = mid;
      }
      pieces.emplace_back(Param::t, regime, G - top, 1, top - bottom, top_is_one ? 0 : t_order_at_top);
    }
  } else {
    out.mu = one;
    return out;
  }
  // Bisect the widest piece until the sums are as narrow as the bits allow.
  for (Piece& p : pieces) row.model(p, coarse);
  mpfr tolerance;
  mpfr_set_prec(tolerance.backend().data(), 32);
  mpfr_set_ui_2exp(tolerance.backend().data(), 1, -static_cast<long>(bits) + 24, MPFR_RNDN);
  const std::size_t max_pieces = 20000;
  for (;;) {
    Interval num(bits), den(bits);
    std::size_t widest = pieces.size();
    mpfr worst = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& p = pieces[i];
      if (!p.num) {
        widest = i;
        break;
      }
      num += *p.num;
      den += *p.den;
      const mpfr w = std::max(p.num->width(), p.den->width());
      if (w > worst) {
        worst = w;
        widest = i;
      }
    }
    if (widest < pieces.size() && pieces[widest].num) {
      const mpfr scale = std::min(abs(den.lower()), abs(num.lower()));
      if (num.width() <= tolerance * scale && den.width() <= tolerance * scale) {
        if (profile.kind == CurvedProfile::Kind::wearflat) {
          const SineEnclosure flat = enclose_sine(beta, gamma, bits);
          num += flat.retained_area;
          den += flat.normal_area;
        }
        out.retained_area = num;
        out.normal_area = den;
        out.mu = num / den;
        out.pieces = pieces.size();
        return out;
      }
    }
    if (pieces.size() >= max_pieces) throw Undecided("the row's Taylor models do not reach the precision");
    Piece& p = pieces[widest];
    const Interval split = Interval::exact(p.length.midpoint(), bits) / Interval::integer(2, bits);
    Piece far(p.param, p.regime, p.anchor + split * static_cast<long>(p.dir), p.dir, p.length - split);
    p.length = split;
    p.num.reset();
    p.den.reset();
    row.model(p, coarse);
    row.model(far, coarse);
    if (!p.num && !far.num && decide(split - Interval::exact(mpfr(1e-30), bits), "a piece's length") == Sign::negative)
      throw Undecided("no Taylor model on a piece of the row");
    pieces.push_back(std::move(far));
  }
}

}  // namespace vibrofric::certified
