// Rig dynamics from decimal text (rig.hpp): the core's RigSolver in mpfr at two working
// precisions, printed where they agree.
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/rig.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/exact_input.hpp"
#include "vibrofric/api/ladder.hpp"
#include "evaluate_impl.hpp"
#include "two_precisions.hpp"
#include "vibrofric/core/dynamics/dynamics.hpp"
#include "vibrofric/core/dynamics/rig_row.hpp"
#include "vibrofric/core/exact.hpp"

namespace vibrofric {

namespace {

// A typed κ, Ω or ζ exactly; InputError where it is missing or out of range.
exact::Rational rig_number(const InputValue& in, const char* name, bool zero_allowed) {
  if (!in.given()) throw InputError(std::string(name) + " is empty: expected a decimal number");
  const exact::Rational v = rational(*in.decimal(), name);
  if (zero_allowed ? v < 0 : v <= 0)
    throw InputError(std::string(name) + " = " + detail::visible(in.text()) + ": expected a decimal " +
                     (zero_allowed ? ">= 0" : "> 0"));
  return v;
}

bool computed(const RigSpec& rig) {
  return rig.kappa.computed_value() || rig.omega.computed_value() || rig.zeta.computed_value();
}

// k with Ω²κ = k² exactly (the undamped slip resonance of harmonic k), else 0.
unsigned resonance(const RigSpec& rig) {
  if (computed(rig)) return 0;
  const exact::Rational q = rig_number(rig.omega, "omega", false) * rig_number(rig.omega, "omega", false) *
                            rig_number(rig.kappa, "kappa", false);
  if (rig_number(rig.zeta, "zeta", true) != 0) return 0;
  if (denominator(q) != 1) return 0;
  const boost::multiprecision::mpz_int n = numerator(q);
  const boost::multiprecision::mpz_int k = sqrt(n);
  if (k * k != n || k > 1000000) return 0;
  return static_cast<unsigned>(k);
}

// Where the rig's μ̄/μ0 differs from the quasi-static one by more than 10 %, the resonance
// nearest to a whole multiple k of the drive: the stick oscillator Ω√(1+κ) or the slip
// oscillator Ω√κ, the one with the smaller |r − k|/k; else "".
std::string resonance_note(const RigSpec& rig, const mpfr& mu, const mpfr& quasi_static) {
  using std::abs;
  const mpfr change = abs(mpfr(mu - quasi_static)), scale = abs(quasi_static);
  if (!(change > scale / 10)) return "";
  const mpfr kappa = rig.kappa.to<mpfr>(), omega = rig.omega.to<mpfr>();
  struct Oscillator {
    const char* name;
    const char* formula;
    mpfr ratio;
  };
  const Oscillator oscillators[] = {{"stick", "omega sqrt(1 + kappa)", mpfr(omega * sqrt(mpfr(1 + kappa)))},
                                    {"slip", "omega sqrt(kappa)", mpfr(omega * sqrt(kappa))}};
  const Oscillator* nearest = nullptr;
  long harmonic = 1;
  mpfr distance;
  for (const auto& o : oscillators) {
    const long k = std::max(1L, std::lround(o.ratio.convert_to<double>()));
    const mpfr d = abs(mpfr(o.ratio - k)) / k;
    if (!nearest || d < distance) {
      nearest = &o;
      harmonic = k;
      distance = d;
    }
  }
  const std::string percent = format_significant(mpfr(100 * change / (scale > 0 ? scale : mpfr(1))), 2);
  const std::string which = harmonic == 1 ? "the drive's frequency"
                                          : "the drive's harmonic " + std::to_string(harmonic);
  return "the rig's mu_over_mu0 " + format_significant(mu, 6) + " is " + percent + " % away from the quasi-static " +
         format_significant(quasi_static, 6) + "; nearest resonance: the " + nearest->name + " oscillator, " +
         nearest->formula + " = " + format_significant(nearest->ratio, 3) + ", near " + std::to_string(harmonic) + " (" +
         which + ")";
}

// "wave W, beta = B, gamma = G, kappa = K, omega = O, zeta = Z: ", as typed (computed values by their labels).
std::string rig_context(const WaveSpec& wave, const Point& p, const RigSpec& rig) {
  return "wave " + wave.name + ", beta = " + p.beta.text() + ", gamma = " + p.gamma.text() + ", kappa = " +
         rig.kappa.text() + ", omega = " + rig.omega.text() + ", zeta = " + rig.zeta.text() + ": ";
}

// κ, Ω, ζ at the working precision.
RigParameters<mpfr> parameters(const RigSpec& rig, unsigned resonant) {
  return {rig.kappa.to<mpfr>(), rig.omega.to<mpfr>(), rig.zeta.to<mpfr>(), resonant};
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
  const mpfr beta = p.beta.to<mpfr>(), gamma = p.gamma.to<mpfr>();
  const RigParameters<mpfr> params = parameters(rig, resonant);
  detail::check_beta(*w, beta);
  detail::check_contact(*w, gamma);
  try {
    const RigSolver<mpfr> solver(*w, beta, gamma, params, opt);
    if (seed)
      return {solver.solve(mpfr(seed->r.state_y), mpfr(seed->r.state_v), mpfr(seed->r.state_s), seed->r.jacobian), digits};
    return {solver.solve(), digits};
  } catch (const SolverError& e) {
    throw SolverError(rig_context(wave, p, rig) + e.what());  // the point as typed, the rig's parameters too
  }
}

// The rig's periodic state at two precisions, the higher from the lower's state, until
// settled(lower, higher) (two_precisions.hpp).
template <class Settled>
std::pair<Solved, Solved> settle(const WaveSpec& wave, const Point& p, const RigSpec& rig, unsigned resonant,
                                 int digits, const Options& opt, Settled settled) {
  return detail::two_precisions<Solved>(
      digits, [&](int d, const Solved* seed) { return solve_at(wave, p, rig, resonant, d, opt, seed); },
      [&](const Solved& lower, const Solved& higher) { return settled(lower.r, higher.r); }, rig_context(wave, p, rig),
      "rig dynamics");
}

}  // namespace

unsigned exact_resonance(const RigSpec& rig) { return resonance(rig); }

void check_rig(const RigSpec& rig) {
  if (computed(rig)) {
    if (!(rig.kappa.to<mpfr>() > 0) || !(rig.omega.to<mpfr>() > 0) || !(rig.zeta.to<mpfr>() >= 0))
      throw InputError("rig dynamics: expected kappa > 0, omega > 0 and zeta >= 0 (kappa = " + rig.kappa.text() +
                       ", omega = " + rig.omega.text() + ", zeta = " + rig.zeta.text() + ")");
    return;
  }
  rig_number(rig.kappa, "kappa", false);
  rig_number(rig.omega, "omega", false);
  rig_number(rig.zeta, "zeta", true);
}

namespace {
// A curved contact's rig solved on rows of n/2 and n springs (rig_row.hpp): doubled from n = 200
// until the two agree to 1e-8 or n = 3200. Where `phases` is given, the periodic state at each on
// both rows. x_max: the row's extent (profile units), its weights' scale.
struct RowPair {
  RowRigResult<double> a, b;
  std::vector<RowRigSample<double>> sa, sb;
  double x_max = 0, largest_weight = 0;  // of b's row
};
RowPair row_pair(const WaveSpec& wave, const Point& p, const RigSpec& rig, const ProfileSpec& profile,
                 const Options& opt, const std::vector<double>* phases = nullptr) {
  using std::abs;
  check_rig(rig);
  const auto w = make_waveform<double>(wave);
  const auto shape = make_profile<double>(profile);
  const double beta = p.beta.to<double>(), gamma = p.gamma.to<double>();
  detail::check_beta(*w, beta);
  detail::check_contact(*w, gamma);
  const std::string where = rig_context(wave, p, rig) + "profile " + profile.name + ": ";
  const double sigma_max = gamma + w->maximum();
  if (sigma_max > shape->sigma_limit())
    throw DomainError(where + "the contact reaches beyond the profile's last sample");
  const RigParameters<double> params{rig.kappa.to<double>(), rig.omega.to<double>(), rig.zeta.to<double>(),
                                     resonance(rig)};
  RowPair out;
  out.x_max = shape->x_at_sigma(sigma_max);
  const auto solve = [&](std::size_t n, std::vector<RowRigSample<double>>& samples) {
    try {
      const auto row = mdr_row(*shape, sigma_max, n);
      out.largest_weight = 0;  // of the quadrature's cells (a wear flat's spring at σ = 0 is exact)
      for (const auto& sp : row)
        if (sp.sigma > 0) out.largest_weight = std::max(out.largest_weight, sp.weight);
      return phases ? solve_rig_row(*w, beta, gamma, params, row, opt, *phases, samples)
                    : solve_rig_row(*w, beta, gamma, params, row, opt);
    } catch (const SolverError& e) {
      throw SolverError(where + e.what());
    }
  };
  // The row's quadrature error shrinks about as n^-2.5 (sphere and sine: 4.3e-8, 7.2e-9, 1.3e-9
  // from n = 200 to 1600): the difference of n and 2n bounds the larger's error.
  out.a = solve(100, out.sa);
  out.b = solve(200, out.sb);
  for (std::size_t n = 400; n <= 3200 && !(abs(out.a.mu - out.b.mu) <= 1e-8 * abs(out.b.mu)); n *= 2) {
    out.a = out.b;
    out.sa = std::move(out.sb);
    out.b = solve(n, out.sb);
  }
  return out;
}
}  // namespace

namespace detail {

mpfr rig_value(const WaveSpec& wave, const Point& p, const RigSpec& rig, const Precision& precision,
               const Options& opt, RigReport* report) {
  check_rig(rig);
  const int digits = output_digits(precision);
  // Two precisions: the lower's difference from the higher estimates the higher's error.
  const auto delta = [](const RigResult<mpfr>& lower, const RigResult<mpfr>& higher) {
    using std::abs;
    return mpfr(2 * (abs(mpfr(lower.mu - higher.mu)) + abs(mpfr(higher.relative_error * higher.mu))));
  };
  const auto [a, b] = settle(wave, p, rig, resonance(rig), digits, opt, [&](const RigResult<mpfr>& lower, const RigResult<mpfr>& higher) {
    const mpfr d = delta(lower, higher);
    return decides(mpfr(higher.mu - d), mpfr(higher.mu + d), precision, digits);
  });
  PrecisionScope scope(static_cast<unsigned>(b.digits));
  if (report) {
    using std::abs;
    const mpfr d = delta(a.r, b.r);
    const int most = std::min(digits, 17);
    report->mu = format_significant(b.r.mu, digits);
    report->stick_fraction = agreed(a.r.stick_fraction, b.r.stick_fraction, most);
    report->slip_fraction = agreed(a.r.slip_fraction, b.r.slip_fraction, most);
    report->backward_fraction = agreed(a.r.backward_fraction, b.r.backward_fraction, most);
    report->flight_fraction = agreed(a.r.flight_fraction, b.r.flight_fraction, most);
    report->amplitude = agreed(a.r.amplitude, b.r.amplitude, most);
    report->largest_backward_slip = agreed(a.r.largest_backward_slip, b.r.largest_backward_slip, most);
    report->relative_error = {mpfr(b.r.mu == 0 ? d : mpfr(d / abs(b.r.mu))), 2};
    report->floquet = a.r.floquet;
    report->working_digits = b.digits;
    report->quasi_static_mu = evaluate(wave, Quantity::mu, {p}, precision).front();
    report->resonance_note = resonance_note(rig, b.r.mu, mpfr(report->quasi_static_mu));
  }
  return b.r.mu;
}

Significant row_rig_value(const WaveSpec& wave, const Point& p, const RigSpec& rig, const ProfileSpec& profile,
                          const Precision& precision, const Options& opt, RigReport* report) {
  using std::abs;
  const int most = std::min(output_digits(precision), 17);
  const RowPair pair = row_pair(wave, p, rig, profile, opt);
  const RowRigResult<double>&a = pair.a, &b = pair.b;
  const Significant mu = agreed(mpfr(a.mu), mpfr(b.mu), most);
  if (report) {
    report->mu = mu.text();
    report->mu_digits = mu.digits;
    report->springs = b.springs;
    report->stick_fraction = agreed(mpfr(a.stick_fraction), mpfr(b.stick_fraction), most);
    report->slip_fraction = agreed(mpfr(a.slip_fraction), mpfr(b.slip_fraction), most);
    report->backward_fraction = agreed(mpfr(a.backward_fraction), mpfr(b.backward_fraction), most);
    report->flight_fraction = agreed(mpfr(a.flight_fraction), mpfr(b.flight_fraction), most);
    report->amplitude = agreed(mpfr(a.amplitude), mpfr(b.amplitude), most);
    report->largest_backward_slip = agreed(mpfr(a.largest_backward_slip), mpfr(b.largest_backward_slip), most);
    const double error = abs(a.mu - b.mu) + abs(b.mu) * b.relative_error;
    report->relative_error = {mpfr(b.mu == 0 ? error : error / abs(b.mu)), 2};
    report->floquet = b.floquet;
    report->working_digits = std::numeric_limits<double>::digits10;
    BatchOptions quasi;
    quasi.profile = profile;
    quasi.solver = opt;
    report->quasi_static_mu = evaluate(wave, Quantity::mu, {p}, precision, quasi).front();
    report->resonance_note = resonance_note(rig, mpfr(b.mu), mpfr(report->quasi_static_mu));
  }
  return mu;
}

}  // namespace detail

RigReport evaluate_rig(const WaveSpec& wave, const Point& point, const RigSpec& rig, const Precision& precision,
                       const Options& solver, const ProfileSpec& profile) {
  if (precision.type == NumberType::mpfr && (precision.digits < min_digits || precision.digits > max_digits))
    throw InputError("digits = " + std::to_string(precision.digits) + ": expected " + std::to_string(min_digits) +
                     " to " + std::to_string(max_digits));
  detail::ContactCheck check(wave, Quantity::mu);
  check(point);
  RigReport report;
  if (profile.kind != ProfileKind::flat) {
    detail::row_rig_value(wave, point, rig, profile, precision, solver, &report);
    return report;
  }
  report.mu = detail::rig_text(detail::rig_value(wave, point, rig, precision, solver, &report), precision);
  return report;
}

std::vector<RigTraceRow> rig_trace_rows(const WaveSpec& wave, const TraceRequest& request, const RigSpec& rig,
                                        const Options& opt) {
  check_trace_request(request);
  check_rig(rig);
  if (request.profile.kind != ProfileKind::flat)
    throw InputError("the rig's trace rows with modes on profile " + request.profile.name +
                     ": a curved contact's row is in several modes at once (its rows: rig_row_trace_rows)");
  const Point p{request.beta.value, request.gamma.value};
  detail::ContactCheck check(wave, Quantity::mu);
  check(p);
  const int digits = request.digits;
  const unsigned resonant = resonance(rig);
  const auto [a, b] = settle(wave, p, rig, resonant, digits, opt, [&](const RigResult<mpfr>& lower, const RigResult<mpfr>& higher) {
    return same_significant(lower.mu, higher.mu, digits);
  });
  // The spans' closed forms at the higher precision, evaluated by a solver built as solve_at built it.
  PrecisionScope scope(static_cast<unsigned>(b.digits));
  const auto w = make_waveform<mpfr>(wave);
  const mpfr beta = p.beta.to<mpfr>(), gamma = p.gamma.to<mpfr>();
  const RigSolver<mpfr> solver(*w, beta, gamma, parameters(rig, resonant), opt);
  std::vector<RigTraceRow> rows;
  const auto add = [&](const RigSpan<mpfr>& span, const mpfr& phi) {
    auto y = solver.at(span, phi);
    mpfr n = solver.normal(span, phi)[0];
    // At a contact boundary n = 0 by definition, and so s (its computed value is a rounding, ~1e-31).
    const auto& g = solver.contact().segments()[span.segment];
    if ((phi == g.u && g.nu == 0) || (phi == g.v && g.nv == 0)) n = y[2] = 0;
    RigTraceRow row{phi, n > 0 ? n : mpfr(0), y[2], y[0], y[1], span.mode};
    // one row where a span ends and the next begins in the same mode with the same printed values
    const auto same = [&](const RigTraceRow& r) {
      return r.mode == row.mode && same_significant(r.phi, row.phi, digits) && same_significant(r.n, row.n, digits) &&
             same_significant(r.s, row.s, digits) && same_significant(r.lag, row.lag, digits) &&
             same_significant(r.lag_rate, row.lag_rate, digits);
    };
    if (!rows.empty() && same(rows.back())) return;
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

std::vector<RigRowTraceRow> rig_row_trace_rows(const WaveSpec& wave, const TraceRequest& request, const RigSpec& rig,
                                               const Options& opt) {
  check_trace_request(request);
  check_rig(rig);
  if (request.profile.kind == ProfileKind::flat)
    throw InputError("the row's trace on the flat punch: its rows are rig_trace_rows'");
  const Point p{request.beta.value, request.gamma.value};
  detail::ContactCheck check(wave, Quantity::mu);
  check(p);
  const int digits = request.digits, most = std::min(digits, 17);
  // The phases: equally spaced, and where the body lands and lifts off (the central spring's
  // contact boundaries, n = s = 0 there by definition), at the request's digits.
  // n is prescribed (the normal motion does not see the rig): exactly, from the profile, the
  // half-row's c X − ∫₀^X σ dx with c = γ + w(φ), σ(X) = c (as the quasi-static curved trace).
  std::vector<mpfr> phis, edges, normal;
  {
    PrecisionScope scope(static_cast<unsigned>(digits + guard_digits(digits)));
    const auto w = make_waveform<mpfr>(wave);
    const auto shape = make_profile<mpfr>(request.profile);
    const mpfr gamma = p.gamma.to<mpfr>();
    const Contact<mpfr> contact = make_contact(*w, gamma);
    for (const auto& g : contact.segments())
      if (g.contact) {
        if (g.nu == 0) edges.push_back(g.u);
        if (g.nv == 0) edges.push_back(g.v);
      }
    phis = edges;
    for (int i = 0; i <= request.points; ++i) phis.push_back(mpfr(i) / request.points);
    std::sort(phis.begin(), phis.end());
    phis.erase(std::unique(phis.begin(), phis.end()), phis.end());
    for (const mpfr& phi : phis) {
      const mpfr c = gamma + (*w)(phi - floor(phi));
      const bool edge = std::find(edges.begin(), edges.end(), phi) != edges.end();
      if (edge || !(c > 0)) {
        normal.push_back(mpfr(0));
      } else {
        const mpfr X = shape->x_at_sigma(c);
        normal.push_back(mpfr(c * X - shape->sigma_integral(X)));
      }
    }
  }
  std::vector<double> phases;
  for (const mpfr& phi : phis) phases.push_back(phi.convert_to<double>());
  const RowPair pair = row_pair(wave, p, rig, request.profile, opt, &phases);
  const auto agree = [&](double a, double b) { return detail::agreed(mpfr(a), mpfr(b), most); };
  // b with the digits above `error`.
  const auto within = [&](double b, double error) {
    using std::abs;
    if (b == 0) return Significant{mpfr(0), 1};
    if (!(error > 0)) return Significant{mpfr(b), most};
    const int d = static_cast<int>(std::floor(std::log10(abs(b) / error)));
    return Significant{mpfr(b), std::clamp(d, 1, most)};
  };
  // A sample of the row is a midpoint rule at one phase: where s has a kink or a jump across the
  // row (the contact's edge, a mode's boundary) the cell holding it errs by up to its weight times
  // the change across it, and the two rows can agree by chance; so s is uncertain by the rows'
  // difference plus two cells' weight times the largest change between neighbours. A share counts
  // whole springs: the difference plus two springs' weight.
  const auto force = [&](double a, double b, double step) {
    using std::abs;
    return within(pair.x_max * b, pair.x_max * (abs(a - b) + 2 * pair.largest_weight * step));
  };
  const auto share = [&](double a, double b) {
    using std::abs;
    return within(b, abs(a - b) + 2 * pair.largest_weight);
  };
  std::vector<RigRowTraceRow> rows;
  for (std::size_t k = 0; k < phis.size(); ++k) {
    const RowRigSample<double>&a = pair.sa[k], &b = pair.sb[k];
    const bool edge = std::find(edges.begin(), edges.end(), phis[k]) != edges.end();
    RigRowTraceRow row;
    row.phi = phis[k];
    row.n = normal[k] == 0 ? Significant{mpfr(0), 1} : Significant{normal[k], digits};
    row.s = edge ? Significant{mpfr(0), 1} : force(a.s, b.s, b.s_step);
    row.lag = agree(a.y, b.y);
    row.lag_rate = agree(a.v, b.v);
    row.stick = share(a.stick, b.stick);
    row.slip = share(a.slip, b.slip);
    row.backward = share(a.backward, b.backward);
    row.flight = share(a.flight, b.flight);
    rows.push_back(std::move(row));
  }
  return rows;
}

const char* rig_mode_name(RigMode mode) {
  static const char* const names[] = {"stick", "slip", "backward", "flight"};
  return names[static_cast<int>(mode)];
}

Significant detail::type_significant(const mpfr& v, const Precision& precision) {
  const int digits = output_digits(precision);
  return visit_number_type(precision.type, [&](auto tag) -> Significant {
    using Real = typename decltype(tag)::type;
    if constexpr (is_runtime_precision_v<Real>) {
      return {v, digits};
    } else {
      PrecisionScope exact(static_cast<unsigned>(std::numeric_limits<Real>::digits10 + 20));  // holds the type's value
      return {mpfr(detail::rounded<Real>(v)), digits};
    }
  });
}

std::string detail::rig_text(const mpfr& v, const Precision& precision) {
  return type_significant(v, precision).text();
}

}  // namespace vibrofric
