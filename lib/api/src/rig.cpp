// Rig dynamics from decimal text (rig.hpp): the core's RigSolver in mpfr at two working
// precisions, printed where they agree.
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/rig.hpp"

#include <algorithm>
#include <cmath>

#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/detail/evaluate_impl.hpp"
#include "vibrofric/core/dynamics.hpp"
#include "vibrofric/core/exact.hpp"

namespace vibrofric {

namespace {

exact::Rational rig_number(const std::string& text, const char* name, bool zero_allowed) {
  const exact::Rational v = exact_decimal(text, name);
  if (zero_allowed ? v < 0 : v <= 0)
    throw InputError(std::string(name) + " = " + detail::visible(text) + ": expected a decimal " +
                     (zero_allowed ? ">= 0" : "> 0"));
  return v;
}

// k with Ω²κ = k² exactly (the undamped slip resonance of harmonic k), else 0.
unsigned resonance(const RigSpec& rig) {
  if (rig.kappa_value || rig.omega_value || rig.zeta_value) return 0;
  const exact::Rational q = rig_number(rig.omega, "omega", false) * rig_number(rig.omega, "omega", false) *
                            rig_number(rig.kappa, "kappa", false);
  if (rig_number(rig.zeta, "zeta", true) != 0) return 0;
  if (denominator(q) != 1) return 0;
  const boost::multiprecision::mpz_int n = numerator(q);
  const boost::multiprecision::mpz_int k = sqrt(n);
  if (k * k != n || k > 1000000) return 0;
  return static_cast<unsigned>(k);
}

// "wave W, beta = B, gamma = G, kappa = K, omega = O, zeta = Z: ", as typed (computed values by their texts).
std::string rig_context(const WaveSpec& wave, const Point& p, const RigSpec& rig) {
  return "wave " + wave.name + ", beta = " + p.beta + ", gamma = " + p.gamma + ", kappa = " + rig.kappa +
         ", omega = " + rig.omega + ", zeta = " + rig.zeta + ": ";
}

// κ, Ω, ζ at the working precision: the computed values, else the texts.
RigParameters<mpfr> parameters(const RigSpec& rig, unsigned resonant) {
  const auto value = [](const std::optional<mpfr>& v, const std::string& text) { return v ? mpfr(*v) : mpfr(text); };
  return {value(rig.kappa_value, rig.kappa), value(rig.omega_value, rig.omega), value(rig.zeta_value, rig.zeta), resonant};
}

struct Solved {
  RigResult<mpfr> r;
  int digits;
};

// The rig at `digits` digits: both starts (seed null), or from a lower precision's state.
Solved solve_at(const WaveSpec& wave, const Point& p, const RigSpec& rig, unsigned resonant, int digits,
                const Options& opt, const Solved* seed) {
  PrecisionScope scope(static_cast<unsigned>(digits));
  const auto w = make_waveform<mpfr>(wave);
  const mpfr beta = p.beta_value ? mpfr(*p.beta_value) : parse_real<mpfr>(p.beta, "beta");
  const mpfr gamma = p.gamma_value ? mpfr(*p.gamma_value) : parse_real<mpfr>(p.gamma, "gamma");
  const RigParameters<mpfr> params = parameters(rig, resonant);
  try {
    if (seed) return {solve_rig(*w, beta, gamma, params, seed->r, opt), digits};
    return {solve_rig(*w, beta, gamma, params, opt), digits};
  } catch (const SolverError& e) {
    // The point as typed, the rig's parameters too (the core names β and γ by their binary values).
    const std::string what = e.what();
    const auto at = what.find("rig dynamics");
    throw SolverError(rig_context(wave, p, rig) + (at == std::string::npos ? what : what.substr(at)));
  }
}

// The digits of x (at most `most`) on which a and b agree.
std::string agreed(const mpfr& a, const mpfr& b, int most) {
  if (a == 0 && b == 0) return "0";
  for (int d = most; d > 1; --d)
    if (format_significant(a, d) == format_significant(b, d)) return format_significant(b, d);
  return format_significant(b, 1);
}

// Whether every value of [lo, hi] prints (or rounds to the type) alike.
bool decides(const mpfr& lo, const mpfr& hi, const Precision& precision, int digits) {
  return visit_number_type(precision.type, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    if constexpr (is_runtime_precision_v<Real>)
      return format_significant(lo, digits) == format_significant(hi, digits);
    else
      return detail::rounded<Real>(lo) == detail::rounded<Real>(hi);
  });
}

}  // namespace

void check_rig(const RigSpec& rig) {
  if (rig.kappa_value || rig.omega_value || rig.zeta_value) {
    if (!(rig.kappa_value && *rig.kappa_value > 0) || !(rig.omega_value && *rig.omega_value > 0) ||
        !(rig.zeta_value && *rig.zeta_value >= 0))
      throw InputError("rig dynamics: expected kappa > 0, omega > 0 and zeta >= 0 (kappa = " + rig.kappa +
                       ", omega = " + rig.omega + ", zeta = " + rig.zeta + ")");
    return;
  }
  rig_number(rig.kappa, "kappa", false);
  rig_number(rig.omega, "omega", false);
  rig_number(rig.zeta, "zeta", true);
}

namespace detail {

mpfr rig_value(const WaveSpec& wave, const Point& p, const RigSpec& rig, const Precision& precision,
               const Options& opt, RigReport* report) {
  check_rig(rig);
  const unsigned resonant = resonance(rig);
  const int digits = output_digits(precision);
  // Two precisions: the lower's difference from the higher estimates the higher's error.
  int low = digits + 10, high = digits + 22;
  Solved a = solve_at(wave, p, rig, resonant, low, opt, nullptr);
  for (int attempt = 0; attempt < 4; ++attempt) {
    Solved b = solve_at(wave, p, rig, resonant, high, opt, &a);
    PrecisionScope scope(static_cast<unsigned>(high));
    using std::abs;
    const mpfr delta = 2 * (abs(mpfr(a.r.mu - b.r.mu)) + abs(mpfr(b.r.relative_error * b.r.mu)));
    const mpfr lo = b.r.mu - delta, hi = b.r.mu + delta;
    if (decides(lo, hi, precision, digits)) {
      if (report) {
        const int most = std::min(digits, 17);
        report->mu = format_significant(b.r.mu, digits);
        report->stick_fraction = agreed(a.r.stick_fraction, b.r.stick_fraction, most);
        report->slip_fraction = agreed(a.r.slip_fraction, b.r.slip_fraction, most);
        report->backward_fraction = agreed(a.r.backward_fraction, b.r.backward_fraction, most);
        report->flight_fraction = agreed(a.r.flight_fraction, b.r.flight_fraction, most);
        report->amplitude = agreed(a.r.amplitude, b.r.amplitude, most);
        report->largest_backward_slip = agreed(a.r.largest_backward_slip, b.r.largest_backward_slip, most);
        report->relative_error = format_significant(mpfr(b.r.mu == 0 ? delta : mpfr(delta / abs(b.r.mu))), 2);
        report->floquet = a.r.floquet;
        report->working_digits = high;
      }
      return b.r.mu;
    }
    if (attempt == 3)
      throw SolverError(rig_context(wave, p, rig) + "rig dynamics: mu did not settle to " + std::to_string(digits) + " digits (" +
                        format_significant(a.r.mu, digits + 2) + " at " + std::to_string(low) + " digits, " +
                        format_significant(b.r.mu, digits + 2) + " at " + std::to_string(high) + ")");
    a = std::move(b);
    low = high;
    high += std::max(12, high / 2);
  }
  return mpfr(0);
}

}  // namespace detail

RigReport evaluate_rig(const WaveSpec& wave, const Point& point, const RigSpec& rig, const Precision& precision,
                       const Options& solver) {
  if (precision.type == NumberType::mpfr && (precision.digits < min_digits || precision.digits > max_digits))
    throw InputError("digits = " + std::to_string(precision.digits) + ": expected " + std::to_string(min_digits) +
                     " to " + std::to_string(max_digits));
  detail::ContactCheck check(wave, Quantity::mu);
  check(point);
  RigReport report;
  report.mu = detail::rig_text(detail::rig_value(wave, point, rig, precision, solver, &report), precision);
  return report;
}

std::vector<RigTraceRow> rig_trace_rows(const WaveSpec& wave, const TraceRequest& request, const RigSpec& rig,
                                        const Options& opt) {
  check_trace_request(request);
  check_rig(rig);
  if (request.profile.kind != ProfileKind::flat)
    throw InputError("rig dynamics with profile " + request.profile.name +
                     ": the springs of a curved contact share the body, so the MDR row does not decouple "
                     "(rig dynamics: the flat punch only)");
  const Point p{*request.beta.text, *request.gamma.text};
  detail::ContactCheck check(wave, Quantity::mu);
  check(p);
  const unsigned resonant = resonance(rig);
  const int digits = request.digits;
  int low = digits + 10, high = digits + 22;
  Solved a = solve_at(wave, p, rig, resonant, low, opt, nullptr);
  Solved b = solve_at(wave, p, rig, resonant, high, opt, &a);
  for (int attempt = 1; format_significant(a.r.mu, digits) != format_significant(b.r.mu, digits); ++attempt) {
    if (attempt == 4)
      throw SolverError(rig_context(wave, p, rig) + "rig dynamics: mu did not settle to " + std::to_string(digits) +
                        " digits (" + format_significant(a.r.mu, digits + 2) + " at " + std::to_string(low) + " digits, " +
                        format_significant(b.r.mu, digits + 2) + " at " + std::to_string(high) + ")");
    a = std::move(b);
    low = high;
    high += std::max(12, high / 2);
    b = solve_at(wave, p, rig, resonant, high, opt, &a);
  }
  // The spans' closed forms at the higher precision, evaluated by a solver built as solve_at built it.
  PrecisionScope scope(static_cast<unsigned>(high));
  const auto w = make_waveform<mpfr>(wave);
  const mpfr beta = parse_real<mpfr>(p.beta, "beta"), gamma = parse_real<mpfr>(p.gamma, "gamma");
  const RigSolver<mpfr> solver(*w, beta, gamma, parameters(rig, resonant), opt);
  std::vector<RigTraceRow> rows;
  const auto add = [&](const RigSpan<mpfr>& span, const mpfr& phi) {
    auto y = solver.at(span, phi);
    mpfr n = solver.normal(span, phi)[0];
    // At a contact boundary n = 0 by definition, and so s (its computed value is a rounding, ~1e-31).
    const auto& g = solver.contact().segments()[span.segment];
    if ((phi == g.u && g.nu == 0) || (phi == g.v && g.nv == 0)) n = y[2] = 0;
    static const char* const names[] = {"stick", "slip", "backward", "flight"};
    RigTraceRow row{format_significant(phi, digits), format_significant(n > 0 ? n : mpfr(0), digits),
                    format_significant(y[2], digits), format_significant(y[0], digits), format_significant(y[1], digits),
                    names[static_cast<int>(span.mode)]};
    // one row where a span ends and the next begins in the same mode with the same values
    if (!rows.empty() && rows.back().phi == row.phi && rows.back().mode == row.mode && rows.back().n == row.n &&
        rows.back().s == row.s && rows.back().lag == row.lag && rows.back().lag_rate == row.lag_rate)
      return;
    rows.push_back(std::move(row));
  };
  const int points = request.points;
  int next = 0;  // the next equally spaced phase next/points
  for (const auto& span : b.r.spans) {
    if (!(span.end > span.begin)) continue;
    add(span, span.begin);
    for (; next <= points && mpfr(next) / points < span.end; ++next)
      if (mpfr(next) / points > span.begin) add(span, mpfr(next) / points);
    add(span, span.end);
  }
  return rows;
}

std::string detail::rig_text(const mpfr& v, const Precision& precision) {
  const int digits = output_digits(precision);
  return visit_number_type(precision.type, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    if constexpr (is_runtime_precision_v<Real>)
      return format_significant(v, digits);
    else
      return format_significant(detail::rounded<Real>(v), digits);
  });
}

}  // namespace vibrofric
