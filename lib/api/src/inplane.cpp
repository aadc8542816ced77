// In-plane and combined oscillation from decimal text (inplane.hpp): the core's InPlaneSolver in
// mpfr at two working precisions, printed where they agree.
#include "vibrofric/api/inplane.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <optional>

#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/ladder.hpp"
#include "vibrofric/api/rig.hpp"
#include "evaluate_impl.hpp"
#include "two_precisions.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/inplane/inplane.hpp"
#include "vibrofric/core/inplane/inplane_curved.hpp"
#include "vibrofric/core/inplane/planar.hpp"

namespace vibrofric {

namespace {

// A typed decimal: InputError quoting it where it is missing, not finite or below `least`.
void check_decimal(const InputValue& in, const char* name, bool nonnegative) {
  if (!in.given()) throw InputError(std::string(name) + " is empty: expected a decimal number");
  const mpfr v = in.to<mpfr>();
  using std::isfinite;
  if (!isfinite(v) || (nonnegative && v < 0))
    throw InputError(std::string(name) + " = " + detail::visible(in.text()) + ": expected a finite decimal" +
                     (nonnegative ? " >= 0" : ""));
}

// A transverse amplitude: the two-dimensional solver; else the longitudinal stop operator.
bool planar(const InPlaneSpec& spec) { return spec.transverse.given() && spec.transverse.to<mpfr>() != 0; }

// "wave W, beta = B, gamma = G, longitudinal = A, phase = P, in-plane wave V: ", as typed.
std::string inplane_context(const WaveSpec& normal, const Point& p, const InPlaneSpec& spec,
                            const ProfileSpec& profile = {}) {
  return (profile.kind == ProfileKind::flat ? std::string() : "profile " + profile.name + ", ") + "wave " + (spec.constant_normal ? std::string("constant") : normal.name) + ", beta = " + p.beta.text() +
         (spec.constant_normal ? std::string() : ", gamma = " + p.gamma.text()) + ", longitudinal = " +
         spec.longitudinal.text() +
         (planar(spec) ? ", transverse = " + spec.transverse.text() : std::string()) + ", phase = " + spec.phase.text() + ", in-plane wave " + spec.wave.name + ": ";
}

// The planar solver's result in the longitudinal one's fields (backward slip is not defined in 2-D).
InPlaneResult<mpfr> as_inplane(const PlanarResult<mpfr>& q) {
  InPlaneResult<mpfr> r;
  r.mu = q.mu;
  r.mean_lateral = q.mean_lateral;
  r.retained_area = q.retained_area;
  r.normal_area = q.normal_area;
  r.stick_fraction = q.stick_fraction;
  r.slip_fraction = q.slip_fraction;
  r.flight_fraction = q.flight_fraction;
  r.backward_fraction = 0;
  r.state_s = q.state[0];
  r.events = q.events;
  r.periods = q.periods;
  return r;
}

struct Solved {
  InPlaneResult<mpfr> r;
  int digits;
};

// The curved contact's row (inplane_curved.hpp) at this precision: each integral to 10^(3 − digits)
// of ∫N, so that the two precisions' difference also measures the quadrature's error.
InPlaneResult<mpfr> curved_at(const Waveform<mpfr>& w, const ProfileSpec& profile, const Point& p, const mpfr& beta,
                              const Waveform<mpfr>& p_wave, const PlanarDrive<mpfr>& drive, int digits,
                              const Options& opt) {
  const auto shape = make_profile<mpfr>(profile);
  const auto row = solve_inplane_curved<mpfr>(
      w, *shape, p.gamma.to<mpfr>(),
      [&](const mpfr& g) { return inplane_spring<mpfr>(w, g, p_wave, beta, drive, opt); },
      mpfr(pow(mpfr(10), 3 - digits)), opt);
  InPlaneResult<mpfr> r;
  r.mu = row.mu;
  r.mean_lateral = row.mean_lateral;
  r.retained_area = row.friction_integral;
  r.normal_area = row.normal_integral;
  return r;
}

// At `digits` working digits; at β = *beta_at (a number of that precision) where given, else p's.
Solved solve_at(const WaveSpec& normal, const Point& p, const InPlaneSpec& spec, int digits, const Options& opt,
                const ProfileSpec& profile = {}, const mpfr* beta_at = nullptr) {
  PrecisionScope scope(static_cast<unsigned>(digits));
  const mpfr beta = beta_at ? *beta_at : p.beta.to<mpfr>();
  const auto p_wave = make_waveform<mpfr>(spec.wave);
  std::unique_ptr<Waveform<mpfr>> w;
  if (!spec.constant_normal) w = make_waveform<mpfr>(normal);
  const InPlaneDrive<mpfr> drive{spec.longitudinal.to<mpfr>(), spec.phase.to<mpfr>()};
  try {
    if (profile.kind != ProfileKind::flat)
      return {curved_at(*w, profile, p, beta, *p_wave,
                        PlanarDrive<mpfr>{drive.longitudinal, spec.transverse.to<mpfr>(), drive.phase}, digits, opt),
              digits};
    if (planar(spec))
      return {as_inplane(solve_planar<mpfr>(
                  w.get(), spec.constant_normal ? mpfr(0) : p.gamma.to<mpfr>(), *p_wave, beta,
                  PlanarDrive<mpfr>{drive.longitudinal, spec.transverse.to<mpfr>(), drive.phase}, opt)),
              digits};
    return {solve_inplane<mpfr>(w.get(), spec.constant_normal ? mpfr(0) : p.gamma.to<mpfr>(), *p_wave,
                                beta, drive, opt),
            digits};
  } catch (const SolverError& e) {
    throw SolverError(inplane_context(normal, p, spec, profile) + e.what());
  }
}

// The free velocity at `digits` working digits: μ̄(0) < 0, then β doubled from 1 until μ̄ ≥ 0 (at
// most 2^40), then TOMS 748 on the last doubling to all but 8 bits; none where μ̄(0) ≥ 0. A root of
// even multiplicity, or a pair between two doublings, is not seen. `near`: the root found at a
// lower precision, whose first sign change this one confirms in near·(1 ± 10^-(digits − 20)) (a
// few solves instead of the doublings; the whole search where μ̄ does not change sign there).
std::optional<mpfr> free_velocity_at(const WaveSpec& normal, const Point& p, const InPlaneSpec& spec, int digits,
                                     const Options& opt, const ProfileSpec& profile,
                                     const std::optional<mpfr>& near = std::nullopt) {
  PrecisionScope scope(static_cast<unsigned>(digits));
  const auto mu = [&](const mpfr& beta) { return solve_at(normal, p, spec, digits, opt, profile, &beta).r.mu; };
  const mpfr f0 = mu(mpfr(0));
  if (!(f0 < 0)) return std::nullopt;
  mpfr lo = 0, hi = 1, f_lo = f0, f_hi = 0;
  bool bracketed = false;
  if (near && *near > 0) {
    const mpfr d = mpfr(*near * pow(mpfr(10), 20 - digits));
    lo = *near - d;
    hi = *near + d;
    f_lo = mu(lo);
    f_hi = f_lo < 0 ? mu(hi) : mpfr(0);
    bracketed = f_lo < 0 && f_hi >= 0;
  }
  if (!bracketed) {
    lo = 0;
    f_lo = f0;
    hi = 1;
    f_hi = mu(hi);
    for (int k = 0; f_hi < 0; ++k) {
      if (k == 40) throw SolverError("the mean force stays negative up to beta = 2^40: no free velocity found");
      lo = hi;
      f_lo = f_hi;
      hi *= 2;
      f_hi = mu(hi);
    }
  }
  if (f_hi == 0) return hi;
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      mu, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<mpfr>(std::numeric_limits<mpfr>::digits - 8), iterations);
  if (iterations >= 200) throw SolverError("the free velocity did not converge in 200 iterations");
  return mpfr((bracket.first + bracket.second) / 2);
}

}  // namespace

void check_inplane(const InPlaneSpec& spec) {
  check_decimal(spec.longitudinal, "longitudinal", true);
  check_decimal(spec.transverse, "transverse", true);
  check_decimal(spec.phase, "phase", false);
  if (spec.wave.kind == WaveKind::fourier || spec.wave.kind == WaveKind::samples)
    throw InputError("in-plane wave " + detail::visible(spec.wave.name) +
                     ": expected a catalogue wave (sine, triangle, sawtooth-right, sawtooth-left, square, power:p)");
}

bool detail::papers_model(const InPlaneSpec& spec) {
  return !spec.constant_normal && spec.longitudinal.to<mpfr>() == 0 && !planar(spec);
}

mpfr detail::inplane_value(const WaveSpec& normal, const Point& p, const InPlaneSpec& spec,
                           const Precision& precision, const Options& opt, const ProfileSpec& profile,
                           InPlaneReport* report) {
  check_inplane(spec);
  check_decimal(p.beta, "beta", true);
  if (spec.constant_normal && p.gamma.given())
    throw InputError("gamma = " + detail::visible(p.gamma.text()) +
                     " with a constant normal force: the normal force is the unit (give no gamma)");
  if (!spec.constant_normal && !p.gamma.given()) throw InputError("gamma is empty: expected a decimal number");
  if (spec.constant_normal && profile.kind != ProfileKind::flat)
    throw InputError("profile " + profile.name +
                     " with a constant normal force: a curved contact is solved with the normal oscillation "
                     "(the row's springs then share one amplitude)");
  const int digits = output_digits(precision);
  // Two precisions; the higher raised until their difference decides the printed digits.
  bool zero = false;
  const auto delta = [](const InPlaneResult<mpfr>& lower, const InPlaneResult<mpfr>& higher) {
    using std::abs;
    return mpfr(2 * abs(mpfr(lower.mu - higher.mu)));
  };
  const auto [a, b] = two_precisions<Solved>(
      digits, [&](int d, const Solved*) { return solve_at(normal, p, spec, d, opt, profile); },
      [&](const Solved& lower, const Solved& higher) {
        // |μ̄| ≤ 1 (|s| ≤ n), so both values within 10^(10 − digits) of 0 at the lower precision are
        // a mean force that vanishes (a symmetric drive at β = 0): 0, which no rounding test decides.
        PrecisionScope low(static_cast<unsigned>(lower.digits));
        const mpfr noise = pow(mpfr(10), 10 - lower.digits);
        using std::abs;
        zero = abs(lower.r.mu) <= noise && abs(higher.r.mu) <= noise;
        if (zero) return true;
        const mpfr d = delta(lower.r, higher.r);
        return decides(mpfr(higher.r.mu - d), mpfr(higher.r.mu + d), precision, digits);
      },
      inplane_context(normal, p, spec, profile), "in-plane oscillation");
  PrecisionScope scope(static_cast<unsigned>(b.digits));
  if (report) {
    report->curved = profile.kind != ProfileKind::flat;
    const int most = std::min(digits, 17);
    const mpfr d = delta(a.r, b.r);
    // Both within the lower precision's noise of 0 (a symmetric transverse drive): 0, as for μ̄.
    const mpfr noise = pow(mpfr(10), 10 - a.digits);
    using std::abs;
    report->mean_lateral = abs(a.r.mean_lateral) <= noise && abs(b.r.mean_lateral) <= noise
                               ? Significant{mpfr(0), 1}
                               : agreed(a.r.mean_lateral, b.r.mean_lateral, most);
    report->stick_fraction = agreed(a.r.stick_fraction, b.r.stick_fraction, most);
    report->slip_fraction = agreed(a.r.slip_fraction, b.r.slip_fraction, most);
    report->backward_fraction = agreed(a.r.backward_fraction, b.r.backward_fraction, most);
    report->flight_fraction = agreed(a.r.flight_fraction, b.r.flight_fraction, most);
    report->relative_error = {mpfr(zero || b.r.mu == 0 ? d : mpfr(d / abs(b.r.mu))), 2};
    report->working_digits = b.digits;
    report->planar = planar(spec);
  }
  return zero ? mpfr(0) : b.r.mu;
}

InPlaneReport evaluate_inplane(const WaveSpec& normal, const Point& p, const InPlaneSpec& spec,
                               const Precision& precision, const Options& opt, const ProfileSpec& profile,
                               bool free_velocity) {
  if (precision.type == NumberType::mpfr && (precision.digits < min_digits || precision.digits > max_digits))
    throw InputError("digits = " + std::to_string(precision.digits) + ": expected " + std::to_string(min_digits) +
                     " to " + std::to_string(max_digits));
  check_inplane(spec);
  if (!spec.constant_normal && p.gamma.given()) {
    detail::ContactCheck check(normal, Quantity::mu);
    check(p);
  }
  // The ratchet's free velocity: of combined normal and longitudinal oscillation, where the contact
  // is lost once a period (γ + min w < 0; on a curved contact every spring's γ' ≤ γ then lifts
  // too): each period then starts from s = 0, and the state at β = 0 is unique (a contact that
  // never lifts may stick through the period there). Searched unasked on the flat punch's
  // longitudinal drive (milliseconds); with a transverse drive or on a curved contact only when
  // asked (about 30 solves: seconds to many minutes), not on a curved transverse row (minutes a point).
  const auto lifts = [&] {
    PrecisionScope scope(static_cast<unsigned>(output_digits(precision) + 10));
    return mpfr(p.gamma.to<mpfr>() + make_waveform<mpfr>(normal)->minimum()) < 0;
  };
  const bool curved = profile.kind != ProfileKind::flat;
  const bool combined = !spec.constant_normal && spec.longitudinal.to<mpfr>() != 0;
  if (free_velocity) {
    const std::string what = "free velocity asked for ";
    if (spec.constant_normal)
      throw InputError(what + "a constant normal force: expected normal and longitudinal oscillation together (the ratchet)");
    if (!combined)
      throw InputError(what + "longitudinal = " + detail::visible(spec.longitudinal.text()) +
                       ": expected a longitudinal amplitude > 0 (the ratchet pushes along the sliding direction)");
    if (!lifts())
      throw InputError(what + "gamma = " + detail::visible(p.gamma.text()) +
                       ": expected a contact lost once a period (gamma + min w < 0); a contact that never lifts "
                       "may stick through the period at beta = 0, where the state is then not unique");
    if (planar(spec) && curved)
      throw InputError(what + "a transverse drive on a curved profile: not searched (a curved transverse row "
                       "costs minutes a point; expected the flat punch, or no transverse drive)");
  }
  InPlaneReport report;
  const mpfr v = detail::inplane_value(normal, p, spec, precision, opt, profile, &report);
  if (combined && (free_velocity || (!planar(spec) && !curved)) && lifts()) {
    report.free_velocity_searched = true;
    const int digits = output_digits(precision);
    try {
      const auto a = free_velocity_at(normal, p, spec, digits + 10, opt, profile);
      const auto b = free_velocity_at(normal, p, spec, digits + 22, opt, profile, a);
      if (a.has_value() != b.has_value())
        throw SolverError("the sign of the mean force at beta = 0 differs between two precisions");
      if (a) {
        PrecisionScope scope(static_cast<unsigned>(digits + 22));
        report.free_velocity = detail::agreed(*a, *b, std::min(digits, 17));
      }
    } catch (const SolverError& e) {
      throw SolverError(inplane_context(normal, p, spec, profile) + "free velocity: " + e.what());
    }
  }
  // A zero amplitude is the paper's model: its value exactly as `mu` prints it.
  if (detail::papers_model(spec)) {
    BatchOptions batch;
    batch.solver = opt;
    batch.profile = profile;
    report.mu = evaluate(normal, Quantity::mu, {p}, precision, batch).front();
  } else {
    report.mu = detail::rig_text(v, precision);
  }
  return report;
}

const char* inplane_mode_name(InPlaneMode mode) {
  static const char* const names[] = {"stick", "slip", "backward", "flight"};
  return names[static_cast<int>(mode)];
}

namespace {

// Rows at both ends of every span and at the equally spaced phases k/points inside it; a row that
// repeats the last one (a span going on alike in the next) is left out.
template <class Span, class Row>
std::vector<InPlaneTraceRow> trace_rows(const std::vector<Span>& spans, int points, int digits, const Row& row_at) {
  std::vector<InPlaneTraceRow> rows;
  const auto add = [&](const Span& span, const mpfr& phi) {
    InPlaneTraceRow row = row_at(span, phi);
    const auto same = [&](const InPlaneTraceRow& r) {
      return r.mode == row.mode && same_significant(r.phi, row.phi, digits) && same_significant(r.n, row.n, digits) &&
             same_significant(r.s_x, row.s_x, digits) && same_significant(r.s_y, row.s_y, digits);
    };
    if (!rows.empty() && same(rows.back())) return;
    rows.push_back(std::move(row));
  };
  int next = 0;  // the next equally spaced phase next/points
  for (const auto& span : spans) {
    if (!(span.end > span.begin)) continue;
    add(span, span.begin);
    for (; next <= points && mpfr(next) / points < span.end; ++next)
      if (mpfr(next) / points > span.begin) add(span, mpfr(next) / points);
    add(span, span.end);
  }
  return rows;
}

}  // namespace

std::vector<InPlaneTraceRow> inplane_trace_rows(const WaveSpec& normal, const TraceRequest& request,
                                                const InPlaneSpec& spec, const Options& opt) {
  check_inplane(spec);
  if (spec.constant_normal && request.gamma.given())
    throw InputError(request.gamma.name + " " + detail::visible(request.gamma.value.text()) +
                     " with a constant normal force: the normal force is the unit (give no gamma)");
  TraceRequest checked = request;  // the ranges and β as for every trace; no γ for n ≡ 1
  if (spec.constant_normal) checked.gamma.value = InputValue(*Decimal::read("1"));
  check_trace_request(checked);
  if (request.profile.kind != ProfileKind::flat)
    throw InputError("in-plane oscillation with profile " + request.profile.name + ": the flat punch only");
  const Point p{request.beta.value, spec.constant_normal ? InputValue() : request.gamma.value};
  if (!spec.constant_normal) {
    detail::ContactCheck check(normal, Quantity::mu);
    check(p);
  }
  const int digits = request.digits;
  const auto [a, b] = detail::two_precisions<Solved>(
      digits, [&](int d, const Solved*) { return solve_at(normal, p, spec, d, opt); },
      [&](const Solved& lower, const Solved& higher) { return same_significant(lower.r.mu, higher.r.mu, digits); },
      inplane_context(normal, p, spec), "in-plane oscillation");
  // The spans' values at the higher precision, from a solver built as solve_at built it.
  PrecisionScope scope(static_cast<unsigned>(b.digits));
  const auto p_wave = make_waveform<mpfr>(spec.wave);
  std::unique_ptr<Waveform<mpfr>> w;
  if (!spec.constant_normal) w = make_waveform<mpfr>(normal);
  const mpfr gamma = spec.constant_normal ? mpfr(0) : p.gamma.to<mpfr>();
  if (planar(spec)) {
    const PlanarSolver<mpfr> solver(
        w.get(), gamma, *p_wave, p.beta.to<mpfr>(),
        PlanarDrive<mpfr>{spec.longitudinal.to<mpfr>(), spec.transverse.to<mpfr>(), spec.phase.to<mpfr>()}, opt);
    const PlanarResult<mpfr> r = solver.solve();
    static const InPlaneMode modes[] = {InPlaneMode::stick, InPlaneMode::forward_slip, InPlaneMode::flight};
    return trace_rows(r.spans, request.points, digits, [&](const PlanarSpan<mpfr>& span, const mpfr& phi) {
      const auto v = solver.at(span, phi);  // n, s_x, s_y
      return InPlaneTraceRow{phi, v[0], v[1], v[2], modes[static_cast<int>(span.mode)]};
    });
  }
  const InPlaneSolver<mpfr> solver(w.get(), gamma, *p_wave, p.beta.to<mpfr>(),
                                   InPlaneDrive<mpfr>{spec.longitudinal.to<mpfr>(), spec.phase.to<mpfr>()}, opt);
  return trace_rows(b.r.spans, request.points, digits, [&](const InPlaneSpan<mpfr>& span, const mpfr& phi) {
    const auto v = solver.at(span, phi);  // n, D, s
    return InPlaneTraceRow{phi, v[0], v[2], mpfr(0), span.mode};
  });
}

}  // namespace vibrofric
