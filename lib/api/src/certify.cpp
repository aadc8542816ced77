// Certified values of the piecewise-linear waves (certify.hpp).
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/exact_input.hpp"
#include "vibrofric/api/ladder.hpp"

#include <cmath>
#include <limits>

#include "vibrofric/api/decimal.hpp"
#include "vibrofric/core/certified/enclosure.hpp"
#include "vibrofric/core/certified/rig_enclosure.hpp"
#include "vibrofric/core/dynamics/dynamics.hpp"
#include "vibrofric/core/inplane/inplane_exact.hpp"

namespace vibrofric {

const char* const certified_waves = "sine, power:P, fourier:FILE, triangle, sawtooth-right, sawtooth-left, square and samples:FILE";

using exact::Rational;
using Integer = boost::multiprecision::mpz_int;

exact::Wave exact_wave(const WaveSpec& spec) {
  switch (spec.kind) {
    case WaveKind::triangle: return exact::triangle();
    case WaveKind::sawtooth_right: return exact::sawtooth_right();
    case WaveKind::sawtooth_left: return exact::sawtooth_left();
    case WaveKind::square: return exact::square();
    case WaveKind::power:
      if (rational(spec.exponent, "power exponent p") == 1) return exact::power_one();
      break;
    case WaveKind::samples: {
      std::vector<Rational> y, phases;
      for (const Decimal& t : spec.samples) y.push_back(rational(t, spec.name + " sample"));
      if (!spec.times.empty()) {  // t_0 … t_N: φ_j = (t_j − t_0)/(t_N − t_0)
        const Rational t0 = rational(spec.times.front(), spec.name + " time"),
                       period = rational(spec.times.back(), spec.name + " time") - t0;
        for (std::size_t j = 0; j < spec.samples.size(); ++j)
          phases.push_back((rational(spec.times[j], spec.name + " time") - t0) / period);
      }
      return exact::samples(spec.name, y, phases);
    }
    case WaveKind::sine:
    case WaveKind::fourier: break;
  }
  throw InputError("wave '" + detail::visible(spec.name) + "' is not piecewise linear: it has no exact rational values");
}

namespace {

std::string text_of(const Rational& x) {
  const Integer num = numerator(x), den = denominator(x);
  return den == 1 ? num.str() : num.str() + "/" + den.str();
}

Integer power(long base, long e) { return pow(Integer(base), static_cast<unsigned>(e)); }

// x · base^e, exactly (base 2 by GMP's shifts: the binary types ask for it on every point).
Rational scaled(const Rational& x, long base, long e) {
  if (base == 2) {
    Rational r;
    if (e >= 0)
      mpq_mul_2exp(r.backend().data(), x.backend().data(), static_cast<mp_bitcnt_t>(e));
    else
      mpq_div_2exp(r.backend().data(), x.backend().data(), static_cast<mp_bitcnt_t>(-e));
    return r;
  }
  return e >= 0 ? Rational(x * Rational(power(base, e))) : Rational(x / Rational(power(base, -e)));
}

// The e with base^(e−1) ≤ x < base^e, x > 0.
long exponent_of(const Rational& x, long base) {
  // A first guess from the sizes of numerator and denominator, then exact steps.
  const double bits = static_cast<double>(msb(numerator(x))) - static_cast<double>(msb(denominator(x)));
  long e = static_cast<long>(bits / std::log2(static_cast<double>(base)));
  while (scaled(x, base, -e) >= 1) ++e;
  while (scaled(x, base, -(e - 1)) < 1) --e;
  return e;
}

// The multiples k·base^q nearest x ≥ 0, as (k, q): one, or two on an exact tie. The quantum is
// base^(e − digits) for x in [base^(e−1), base^e), and at least base^min_q (subnormals).
std::vector<std::pair<Integer, long>> nearest(const Rational& x, long base, long digits, long min_q) {
  if (x == 0) return {{Integer(0), 0}};
  const long q = std::max(exponent_of(x, base) - digits, min_q);
  const Rational t = scaled(x, base, -q);
  const Integer k = numerator(t) / denominator(t);  // floor, t > 0
  const Rational rest = t - Rational(k);
  if (rest == 0) return {{k, q}};
  if (rest < Rational(1, 2)) return {{k, q}};
  if (rest > Rational(1, 2)) return {{Integer(k + 1), q}};
  return {{k, q}, {Integer(k + 1), q}};
}

template <class Real>
std::vector<std::string> nearest_in(const Rational& x, int digits_printed) {
  using L = std::numeric_limits<Real>;
  const long min_q = L::has_denorm == std::denorm_present ? L::min_exponent - L::digits : L::min_exponent - 1;
  std::vector<std::string> out;
  for (const auto& [k, q] : nearest(x, 2, L::digits, min_q)) {
    mpfr v;
    mpfr_set_prec(v.backend().data(), L::digits + 2);
    mpfr_set_z(v.backend().data(), k.backend().data(), MPFR_RNDN);  // k < 2^(digits + 1): exact
    mpfr_mul_2si(v.backend().data(), v.backend().data(), q, MPFR_RNDN);
    out.push_back(format_significant(detail::rounded<Real>(v), digits_printed));
  }
  return out;
}

std::vector<std::string> nearest_decimals(const Rational& x, int digits) {
  std::vector<std::string> out;
  for (const auto& [k, q] : nearest(x, 10, digits, std::numeric_limits<long>::min() / 2)) {
    // k·10^q to `digits` digits: through a binary value that holds it to more than those digits.
    PrecisionScope scope(static_cast<unsigned>(digits + 20));
    const mpfr v = mpfr(k.str()) * pow(mpfr(10), q);
    out.push_back(format_significant(v, digits));
  }
  return out;
}

}  // namespace

namespace {

// The texts of the correctly rounded value(s) of x at the precision.
std::vector<std::string> rounded_texts(const Rational& x, const Precision& precision) {
  // Rounding to nearest is symmetric: a negative value (an in-plane drive's) is its magnitude's, negated.
  if (x < 0) {
    std::vector<std::string> out = rounded_texts(Rational(-x), precision);
    for (std::string& t : out) t.insert(0, "-");
    return out;
  }
  const int digits = output_digits(precision);
  return visit_number_type(precision.type, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    if constexpr (is_runtime_precision_v<Real>)
      return nearest_decimals(x, digits);
    else
      return nearest_in<Real>(x, digits);
  });
}

Rational rational_of(const mpfr& x) {
  Rational q;
  mpfr_get_q(q.backend().data(), x.backend().data());
  return q;
}

// x as a decimal of `digits` significant digits, rounded down or up.
std::string directed(const mpfr& x, int digits, mpfr_rnd_t rounding) {
  char* text = nullptr;
  mpfr_asprintf(&text, "%.*R*e", digits - 1, rounding, x.backend().data());
  std::string out(text);
  mpfr_free_str(text);
  return out;
}

// Bits to start from: the precision's, and some to spare for the enclosure's width.
mpfr_prec_t first_bits(const Precision& p) {
  return visit_number_type(p.type, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    if constexpr (is_runtime_precision_v<Real>)
      return static_cast<mpfr_prec_t>(p.digits * 3.3219280948873623) + 40;
    else
      return static_cast<mpfr_prec_t>(std::numeric_limits<Real>::digits) + 40;
  });
}

}  // namespace

Certifier::Certifier(const WaveSpec& wave, const ProfileSpec& profile) {
  // The sine, power:P (P ≠ 1) and Fourier series are enclosed per point (core/certified/enclosure.hpp);
  // the others exactly.
  if (wave.kind == WaveKind::power) {
    const Rational p = rational(wave.exponent, "power exponent p");
    if (p != 1) power_ = p;
  }
  if (wave.kind == WaveKind::fourier) {
    fourier_.emplace();
    for (const WaveSpec::Harmonic& h : wave.harmonics)
      fourier_->push_back({h.k, rational(h.a, wave.name + " coefficient a_" + std::to_string(h.k)),
                           rational(h.b, wave.name + " coefficient b_" + std::to_string(h.k))});
  }
  name_ = detail::visible(wave.name);
  if (wave.kind != WaveKind::sine && !power_ && !fourier_) {
    try {
      wave_ = exact_wave(wave);
    } catch (const InputError&) {
      throw InputError("wave '" + detail::visible(wave.name) + "' has no certified values: they exist for " + certified_waves +
                       " (piecewise linear: exact rationals; the others: enclosures)");
    }
  }
  if (profile.kind == ProfileKind::flat) return;
  // A curved contact: the row's integral enclosed by Taylor models (curved_enclosure.hpp), for the
  // sine on the closed-form profiles.
  if (wave.kind != WaveKind::sine)
    throw InputError("curved contacts are certified for the sine only (wave '" + name_ + "' is certified on the flat punch)");
  if (profile.kind != ProfileKind::power && profile.kind != ProfileKind::wearflat)
    throw InputError("curved contacts are certified for power:N, sphere, cone and wearflat:LAMBDA (a measured profile's row "
                     "is not in closed form)");
  if (!profile.parameter.decimal())
    throw InputError("the profile's parameter " + profile.parameter.text() + " is computed: it has no exact value to certify");
  curved_.emplace();
  curved_->kind = profile.kind == ProfileKind::power ? certified::CurvedProfile::Kind::power : certified::CurvedProfile::Kind::wearflat;
  curved_->parameter = rational(*profile.parameter.decimal(), profile.kind == ProfileKind::power ? "profile exponent N" : "wear-flat LAMBDA");
}

std::shared_ptr<const certified::FourierShape> Certifier::shape(mpfr_prec_t bits) const {
  const std::lock_guard<std::mutex> lock(shapes_->mutex);
  auto& s = shapes_->at[bits];
  if (!s) s = std::make_shared<const certified::FourierShape>(*fourier_, bits);
  return s;
}

Certificate Certifier::operator()(Quantity q, const Point& point, const Precision& precision, const std::string& printed) const {
  const auto exact_input = [&](const InputValue& in, const char* name) {
    if (!in.given()) throw InputError(std::string(name) + " is empty: expected a decimal number");
    if (!in.decimal()) throw InputError("a computed point (beta " + point.beta.text() + ") has no exact inputs to certify");
    return rational(*in.decimal(), name);
  };
  const Rational beta = exact_input(point.beta, "beta");
  if (curved_ && q == Quantity::psi) throw InputError("Psi (Eq. 12) exists for the flat punch only");
  const Rational gamma = q == Quantity::psi ? Rational(1) : exact_input(point.gamma, "gamma");
  Certificate c;
  if (wave_) {
    c.lower = q == Quantity::psi ? exact::psi(*wave_, beta).lost_area : exact::solve(*wave_, beta, gamma).mu;
    c.upper = c.lower;
    c.exact = text_of(c.lower);
    c.nearest = rounded_texts(c.lower, precision);
  } else {
    // Ψ at a γ without jumping (Eq. 12): 1 = −min w for the sine and power:P, 2 > −min w for any
    // normalised series (max w − min w = 2, max w > 0). Double the bits until both ends of the
    // enclosure round alike (no tie: the value is transcendental unless it is exactly 1 or 0).
    const Rational at_gamma = q == Quantity::psi ? Rational(fourier_ ? 2 : 1) : gamma;
    // A series' enclosure isolates its events by bisection to 2^−bits/2, and a curved one's
    // Taylor models grow with the bits (order bits/3): four times the first bits at most (an
    // inherent undecided case would else take minutes or hours); the others up to max_certify_bits.
    const mpfr_prec_t cap =
        fourier_ || curved_ ? std::min(max_certify_bits, 4 * first_bits(precision)) : max_certify_bits;
    const auto undecided = [&] {
      return SolverError(name_ + ", beta = " + point.beta.text() +
                         (q == Quantity::mu ? ", gamma = " + point.gamma.text() : std::string()) +
                         ": the enclosure does not decide the rounding at " + std::to_string(cap) + " bits");
    };
    if (first_bits(precision) > cap) throw undecided();
    const auto attempt = [&](long bits) -> std::optional<Interval> {
      std::optional<Interval> value;
      try {
        if (curved_) {
          value = certified::enclose_curved_sine(*curved_, beta, gamma, bits).mu;
        } else if (fourier_) {
          const certified::FourierEnclosure e = certified::enclose_fourier(*shape(bits), beta, at_gamma);
          value = q == Quantity::psi ? e.lost_area : e.mu;
        } else {
          const certified::SineEnclosure e =
              power_ ? certified::enclose_power(*power_, beta, at_gamma, bits) : certified::enclose_sine(beta, at_gamma, bits);
          value = q == Quantity::psi ? e.lost_area : e.mu;
        }
      } catch (const certified::Undecided&) {
        return std::nullopt;
      }
      const Interval& v = *value;
      const Rational lo = rational_of(v.lower()), hi = rational_of(v.upper());
      std::vector<std::string> at_lo = rounded_texts(lo, precision), at_hi = rounded_texts(hi, precision);
      if (at_lo.size() != 1 || at_lo != at_hi) return std::nullopt;
      c.lower = lo;
      c.upper = hi;
      c.nearest = at_lo;
      c.bits = bits;
      return value;
    };
    const std::optional<Interval> v = escalate(first_bits(precision), attempt, doubling_up_to(cap));
    if (!v) throw undecided();
    const int digits = output_digits(precision) + 3;
    c.lower_text = directed(v->lower(), digits, MPFR_RNDD);
    c.upper_text = directed(v->upper(), digits, MPFR_RNDU);
    // Rounding to nearest is monotone: where both ends round to one decimal, so does every point between.
    for (int d = digits; d >= 1 && c.cite.empty(); --d)
      if (same_significant(v->lower(), v->upper(), d)) {
        c.cite = format_significant(v->lower(), d);
        c.cite_digits = d;
      }
  }
  for (const std::string& t : c.nearest) c.correctly_rounded = c.correctly_rounded || t == printed;
  return c;
}

namespace {

// The drive's waves as exact piecewise-linear waves; InputError for a transverse drive or another wave.
std::pair<std::optional<exact::Wave>, exact::Wave> inplane_waves(const WaveSpec& normal, const InPlaneSpec& spec) {
  if (!spec.transverse.decimal() || rational(*spec.transverse.decimal(), "transverse amplitude") != 0)
    throw InputError("transverse amplitude " + spec.transverse.text() +
                     ": certified in-plane values exist for the longitudinal drive only (a transverse drive slips on a "
                     "circle: its events are not roots of linear functions)");
  const auto piecewise_linear = [](const WaveSpec& w, const char* role, const char* waves) {
    try {
      return exact_wave(w);
    } catch (const InputError&) {
      throw InputError(std::string(role) + " '" + detail::visible(w.name) +
                       "' has no certified in-plane values: they exist for the piecewise-linear waves (" + waves + ")");
    }
  };
  std::optional<exact::Wave> w;
  if (!spec.constant_normal)
    w = piecewise_linear(normal, "normal wave", "triangle, sawtooth-right, sawtooth-left, square, power:1, samples:FILE");
  return {std::move(w), piecewise_linear(spec.wave, "in-plane wave", "triangle, sawtooth-right, sawtooth-left, square, power:1")};
}

}  // namespace

void check_certifiable(const WaveSpec& normal, const InPlaneSpec& spec) { inplane_waves(normal, spec); }

InPlaneCertificate certify_inplane(const WaveSpec& normal, const Point& point, const InPlaneSpec& spec,
                                   const Precision& precision, const std::string& printed) {
  const auto [w, p] = inplane_waves(normal, spec);
  const auto exact_input = [](const InputValue& in, const char* name) {
    if (!in.decimal()) throw InputError(std::string(name) + " " + in.text() + " is computed: it has no exact value to certify");
    return rational(*in.decimal(), name);
  };
  const Rational gamma = spec.constant_normal ? Rational(0) : exact_input(point.gamma, "gamma");
  const exact::InPlaneResult r =
      exact::solve_inplane(w ? &*w : nullptr, gamma, p, exact_input(point.beta, "beta"),
                           exact_input(spec.longitudinal, "longitudinal amplitude"), exact_input(spec.phase, "phase"));
  InPlaneCertificate c;
  c.mu.lower = c.mu.upper = r.mu;
  c.mu.exact = text_of(r.mu);
  c.mu.nearest = rounded_texts(r.mu, precision);
  for (const std::string& t : c.mu.nearest) c.mu.correctly_rounded = c.mu.correctly_rounded || t == printed;
  c.stick_fraction = text_of(r.stick_fraction);
  c.slip_fraction = text_of(r.slip_fraction);
  c.backward_fraction = text_of(r.backward_fraction);
  c.flight_fraction = text_of(r.flight_fraction);
  return c;
}

namespace {

// The rig's approximate periodic state at about `bits` (RigSolver, both starts) at the middle of
// its longest span of slip or flight: where the proof's section lies.
certified::RigSeed rig_seed(const WaveSpec& wave, const Point& p, const RigSpec& rig, mpfr_prec_t bits,
                            const Options& opt, RigMode* section_mode) {
  PrecisionScope scope(static_cast<unsigned>(bits * 0.30103) + 10);
  const auto w = make_waveform<mpfr>(wave);
  // the exact undamped resonance (the solver's secular closed form), as evaluate_rig decides it
  const RigParameters<mpfr> params{rig.kappa.to<mpfr>(), rig.omega.to<mpfr>(), rig.zeta.to<mpfr>(), exact_resonance(rig)};
  const RigSolver<mpfr> solver(*w, p.beta.to<mpfr>(), p.gamma.to<mpfr>(), params, opt);
  const RigResult<mpfr> r = solver.solve();
  const RigSpan<mpfr>* best = nullptr;
  for (const auto& s : r.spans)
    if (s.mode != RigMode::stick && (!best || s.end - s.begin > best->end - best->begin)) best = &s;
  if (!best) throw SolverError("rig certificate: the periodic state has no span of slip or flight");
  // a short binary phase (32 bits) near the middle: the section enters the intervals exactly
  const mpfr mid = ldexp(round(ldexp(mpfr((best->begin + best->end) / 2), 32)), -32);
  const auto st = solver.at(*best, mid);
  if (section_mode) *section_mode = best->mode;
  const certified::ContactMode mode = best->mode == RigMode::forward_slip    ? certified::ContactMode::forward_slip
                                      : best->mode == RigMode::backward_slip ? certified::ContactMode::backward_slip
                                                                             : certified::ContactMode::flight;
  return {mid, mode, st[0], st[1]};
}

// "[lo, hi]" to 20 digits, rounded outward; an exact 0 (a mode that does not occur) as 0.
std::string enclosure_text(const Interval& x) {
  const auto end = [](const mpfr& v, mpfr_rnd_t r) { return v == 0 ? std::string("0") : directed(v, 20, r); };
  return "[" + end(x.lower(), MPFR_RNDD) + ", " + end(x.upper(), MPFR_RNDU) + "]";
}


}  // namespace

certified::RigWaveInput rig_wave_input(const WaveSpec& wave) {
  using Kind = certified::RigWaveInput::Kind;
  if (wave.kind == WaveKind::sine) return {Kind::sine, {}, {}};
  if (wave.kind == WaveKind::fourier) {
    certified::RigWaveInput in{Kind::fourier, {}, {}};
    for (const WaveSpec::Harmonic& h : wave.harmonics)
      in.series.push_back({h.k, rational(h.a, wave.name + " coefficient a_" + std::to_string(h.k)),
                           rational(h.b, wave.name + " coefficient b_" + std::to_string(h.k))});
    return in;
  }
  try {
    return {Kind::piecewise_linear, exact_wave(wave), {}};
  } catch (const InputError&) {
    throw InputError("wave '" + detail::visible(wave.name) +
                     "' has no proven rig state: it exists for the sine, Fourier series and piecewise-linear waves "
                     "(triangle, sawtooth-right, sawtooth-left, square, power:1, samples:FILE)");
  }
}

namespace {

// The point's exact inputs and its wave; InputError for a computed input or the sine at γ = 1.
std::pair<certified::RigWaveInput, certified::RigPoint> rig_inputs(const WaveSpec& wave, const Point& point, const RigSpec& rig) {
  certified::RigWaveInput input = rig_wave_input(wave);
  const auto exact_input = [](const InputValue& in, const char* name) {
    if (!in.given()) throw InputError(std::string(name) + " is empty: expected a decimal number");
    if (!in.decimal()) throw InputError(std::string(name) + " " + in.text() + " is computed: it has no exact value to certify");
    return rational(*in.decimal(), name);
  };
  const certified::RigPoint q{exact_input(point.beta, "beta"), exact_input(point.gamma, "gamma"),
                              exact_input(rig.kappa, "kappa"), exact_input(rig.omega, "omega"),
                              exact_input(rig.zeta, "zeta")};
  if (input.kind == certified::RigWaveInput::Kind::sine && q.gamma == 1)
    throw InputError("gamma = 1: n touches zero at one instant of the period; no proven rig state there");
  return {std::move(input), q};
}

}  // namespace

ProvenRig prove_rig(const WaveSpec& wave, const Point& point, const RigSpec& rig, mpfr_prec_t bits, const Options& solver) {
  const auto [input, q] = rig_inputs(wave, point, rig);
  RigMode mode = RigMode::flight;
  certified::RigSeed seed = rig_seed(wave, point, rig, bits, solver, &mode);
  return {certified::enclose_rig(input, q, seed, bits), std::move(seed), mode};
}

std::vector<std::pair<std::string, std::string>> rig_certificate_fields(const RigCertificate& c) {
  return {{"periodic_state", "proven to exist, unique in its box (Krawczyk test of the one-period map)"},
          {"section_phase", c.section},
          {"section_mode", c.section_mode},
          {"state_lag_box", c.state_y},
          {"state_lag_rate_box", c.state_v},
          {"stick_fraction_enclosure", c.stick_fraction},
          {"slip_fraction_enclosure", c.slip_fraction},
          {"backward_slip_fraction_enclosure", c.backward_fraction},
          {"flight_fraction_enclosure", c.flight_fraction},
          {"floquet_multiplier_enclosure", c.multiplier},
          {"stability", c.stable ? "proven stable (both multipliers inside the unit circle)" : "not proven"}};
}

RigCertificate certify_rig(const WaveSpec& wave, const Point& point, const RigSpec& rig, const Precision& precision,
                           const std::string& printed, const ProfileSpec& profile, const Options& solver) {
  if (profile.kind != ProfileKind::flat)
    throw InputError("profile " + detail::visible(profile.name) +
                     " has no proven rig state: it exists for the flat punch (a curved contact's row shares one body)");
  rig_inputs(wave, point, rig);  // the refusals, before any solve
  const mpfr_prec_t first = first_bits(precision) + 24, cap = 4 * first;
  std::string open;
  RigCertificate c;
  const auto attempt = [&](long bits) -> std::optional<certified::RigEnclosure> {
    try {
      ProvenRig proven = prove_rig(wave, point, rig, bits, solver);
      const certified::RigSeed& seed = proven.seed;
      certified::RigEnclosure& e = proven.enclosure;
      const Rational lo = rational_of(e.mu.lower()), hi = rational_of(e.mu.upper());
      const std::vector<std::string> at_lo = rounded_texts(lo, precision), at_hi = rounded_texts(hi, precision);
      if (at_lo.size() != 1 || at_lo != at_hi) {
        open = "the enclosure of mu does not decide its rounding";
        return std::nullopt;
      }
      c.mu.lower = lo;
      c.mu.upper = hi;
      c.mu.nearest = at_lo;
      c.mu.bits = bits;
      c.section = format_significant(seed.section, 12);
      c.section_mode = rig_mode_name(proven.section_mode);
      return std::move(e);
    } catch (const certified::Undecided& e) {
      open = e.what();
      return std::nullopt;
    }
  };
  const std::optional<certified::RigEnclosure> e = escalate(first, attempt, doubling_up_to(cap));
  if (!e)
    throw SolverError("wave " + wave.name + ", beta = " + point.beta.text() + ", gamma = " + point.gamma.text() +
                      ", kappa = " + rig.kappa.text() + ", omega = " + rig.omega.text() + ", zeta = " + rig.zeta.text() +
                      ": no proven rig state up to " + std::to_string(cap) + " bits (" + open + ")");
  const int digits = output_digits(precision) + 3;
  c.mu.lower_text = directed(e->mu.lower(), digits, MPFR_RNDD);
  c.mu.upper_text = directed(e->mu.upper(), digits, MPFR_RNDU);
  for (int d = digits; d >= 1 && c.mu.cite.empty(); --d)
    if (same_significant(e->mu.lower(), e->mu.upper(), d)) {
      c.mu.cite = format_significant(e->mu.lower(), d);
      c.mu.cite_digits = d;
    }
  for (const std::string& t : c.mu.nearest) c.mu.correctly_rounded = c.mu.correctly_rounded || t == printed;
  c.stick_fraction = enclosure_text(e->stick_fraction);
  c.slip_fraction = enclosure_text(e->slip_fraction);
  c.backward_fraction = enclosure_text(e->backward_fraction);
  c.flight_fraction = enclosure_text(e->flight_fraction);
  c.multiplier = enclosure_text(e->multiplier);
  c.stable = e->stable;
  c.state_y = enclosure_text(e->y);
  c.state_v = enclosure_text(e->v);
  return c;
}

}  // namespace vibrofric
