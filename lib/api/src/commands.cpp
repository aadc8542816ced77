// physical_point and trace_rows (commands.hpp): Eqs. 1, 5, 14 and MDR (model.md), and Fig. 2.
#include "vibrofric/api/commands.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <functional>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "evaluate_impl.hpp"
#include "vibrofric/api/inplane.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/api/rig.hpp"
#include "vibrofric/api/suggest.hpp"
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/curved/curved_trace.hpp"
#include "vibrofric/core/physical.hpp"

namespace vibrofric {

std::vector<PhysicalRequest::Member> PhysicalRequest::inputs() {
  const auto n = [](const char* m, NamedInput& in) { return Member{m, &in, nullptr}; };
  return {n("E1", E1),         n("nu1", nu1),       n("E2", E2),     n("nu2", nu2),
          n("G1", G1),         n("G2", G2),         n("v0", v0),     n("f", f),
          n("A", A),           n("u_mean", u_mean), n("F_N", F_N),   n("mu0", mu0),
          Member{"shape", nullptr, &shape}, n("radius", radius), n("R", R), n("half_angle", half_angle),
          n("flat_radius", flat_radius), Member{"unit", nullptr, &unit}, n("mass", mass), n("k_system", k_system),
          n("damping", damping), n("u_x", u_x), n("u_y", u_y), n("phase", phase),
          Member{"in_plane_wave", nullptr, &in_plane_wave}};
}

namespace {
// Everything that defines a wave, for a key: its name and, for a user wave, its numbers as read.
std::string wave_fingerprint(const WaveSpec& w) {
  std::string out = std::to_string(static_cast<int>(w.kind)) + " " + w.name + " " + w.exponent.text() + " " + w.column +
                    " " + (w.period_from_stamps ? w.period_from_stamps->text() : std::string());
  for (const auto& h : w.harmonics) out += "\n" + std::to_string(h.k) + " " + h.a.text() + " " + h.b.text();
  for (const auto& y : w.samples) out += "\n" + y.text();
  out += "\nt";
  for (const auto& t : w.times) out += "\n" + t.text();
  return out;
}
}  // namespace

namespace {
// Where `trace` is given, it also receives the point's rows over one period (physical_trace).
struct TraceTarget {
  int points, digits;
  std::vector<PhysicalTraceRow> rows;
};
PhysicalOutputs physical_at(const WaveSpec& wave, const PhysicalRequest& r, const Precision& prec, const BatchOptions& base,
                            std::vector<std::string>* warnings, TraceTarget* trace = nullptr);
PhysicalOutputs physical_constant(const PhysicalRequest& r, const Precision& prec, const BatchOptions& base);

// A length unit of a value column, in metres.
const std::map<std::string, const char*>& length_units() {
  static const std::map<std::string, const char*> units{{"m", "1"},     {"mm", "1e-3"},          {"um", "1e-6"},
                                                        {"\xC2\xB5m", "1e-6"}, {"\xCE\xBCm", "1e-6"}, {"nm", "1e-9"}};
  return units;
}
}  // namespace

namespace {
PhysicalOutputs physical_traced(const WaveSpec& wave, const PhysicalRequest& r, const Precision& prec,
                                const BatchOptions& base, std::vector<std::string>* warnings, TraceTarget* trace) {
  if (r.constant_normal) {
    if (trace) throw InputError("a trace in SI units with a constant normal force: expected a normal oscillation");
    return physical_constant(r, prec, base);
  }
  if (!r.unit.given()) return physical_at(wave, r, prec, base, warnings, trace);
  // The amplitude from the record (model.md: A is zero-to-peak, the wave normalised to
  // max − min = 2): half the samples' peak-to-peak, in the unit of the value column.
  const std::string& unit = *r.unit.text;
  if (wave.kind != WaveKind::samples)
    throw InputError(r.unit.name + " " + detail::visible(unit) + " given for wave " + detail::visible(wave.name) +
                     ": the amplitude is taken from a samples:FILE record only (give " + r.A.name + ")");
  if (r.A.given())
    throw InputError(r.A.name + " and " + r.unit.name + " both given: expected one (" + r.unit.name +
                     " takes the amplitude from the record)");
  const auto it = length_units().find(unit);
  if (it == length_units().end()) {
    const std::string hint = did_you_mean(unit, {"m", "mm", "um", "nm"});
    throw InputError(r.unit.name + " '" + detail::visible(unit) + "': expected m, mm, um (or µm) or nm" +
                     (hint.empty() ? "" : "; " + detail::visible(hint)));
  }
  // The value column's header, where it names a unit, must name this one (a force in N, a
  // velocity in mm/s is no displacement).
  if (const std::string said = column_unit(wave.value_column);
      !said.empty() && !(length_units().count(said) && length_units().at(said) == std::string(it->second)))
    throw InputError(r.unit.name + " " + detail::visible(unit) + ", but the value column '" + detail::visible(wave.value_column) +
                     "' of " + detail::visible(wave.name) + " is in " + detail::visible(said) +
                     (length_units().count(said) ? ": expected them to agree" : ": expected a displacement (m, mm, um, nm)"));
  mpfr amplitude;
  std::string amplitude_label;
  {
    const int digits = output_digits(prec) + 25;
    const SampleNormalisation nz = normalise_samples(
        wave.name, wave.samples.size(), [&](std::size_t j) { return detail::sample_value(wave, j); },
        detail::distinct_digits(wave), detail::sample_phase(wave), digits);
    PrecisionScope scope(nz.digits);
    amplitude = nz.scale / static_cast<long>(wave.periods_averaged) * mpfr(it->second);
    amplitude_label = format_significant(amplitude, digits);
  }
  PhysicalRequest request = r;
  request.A.value = InputValue::computed(amplitude, amplitude_label);
  request.A.name = r.A.name + " (half the peak-to-peak of " + detail::visible(wave.name) + " in " + detail::visible(unit) + ")";
  request.unit.text.reset();
  PhysicalOutputs out = physical_at(wave, request, prec, base, warnings, trace);
  const int digits = output_digits(prec);
  PrecisionScope scope(static_cast<unsigned>(digits + 20));
  out.insert(out.begin() + 1, PhysicalOutput{"A_m", {detail::rounded<mpfr>(amplitude), digits}, {}});
  return out;
}
}  // namespace

PhysicalOutputs physical_point(const WaveSpec& wave, const PhysicalRequest& r, const Precision& prec,
                               const BatchOptions& base, std::vector<std::string>* warnings) {
  return physical_traced(wave, r, prec, base, warnings, nullptr);
}

std::vector<PhysicalTraceRow> physical_trace(const WaveSpec& wave, const PhysicalRequest& request, int points, int digits,
                                             const BatchOptions& options) {
  TraceTarget target{points, digits, {}};
  physical_traced(wave, request, Precision{NumberType::mpfr, digits}, options, nullptr, &target);
  return target.rows;
}

namespace {
// evaluate_one's value and text under a rig, with the rig's report.
Evaluated rig_evaluated(const WaveSpec& wave, const Point& point, const RigSpec& rig, const Precision& precision,
                        const Options& solver, RigReport& report, const ProfileSpec& profile = {}) {
  if (profile.kind != ProfileKind::flat) {
    const Significant v = detail::row_rig_value(wave, point, rig, profile, precision, solver, &report);
    return {report.mu, v.value};
  }
  const mpfr v = detail::rig_value(wave, point, rig, precision, solver, &report);
  report.mu = detail::rig_text(v, precision);
  return {report.mu, v};
}

// The in-plane drive of physical inputs (model.md, "In-plane and combined oscillation"): each
// amplitude times `scale` (k_x over the force unit, 1/m), the phase and wave as given; none where
// no in-plane amplitude is given and the normal force oscillates.
std::optional<InPlaneSpec> physical_drive(const PhysicalRequest& r, const mpfr& scale, int digits) {
  if (!r.u_x.given() && !r.u_y.given() && !r.constant_normal) {
    for (const NamedInput* in : {&r.phase})
      if (in->given())
        throw InputError(in->name + " without " + r.u_x.name + " or " + r.u_y.name + ": give the in-plane amplitude");
    if (r.in_plane_wave.given())
      throw InputError(r.in_plane_wave.name + " without " + r.u_x.name + " or " + r.u_y.name +
                       ": give the in-plane amplitude");
    return std::nullopt;
  }
  if (r.mass.given() || r.k_system.given() || r.damping.given())
    throw InputError(std::string(r.mass.given() ? r.mass.name : r.k_system.given() ? r.k_system.name : r.damping.name) +
                     " with an in-plane oscillation: rig dynamics with an in-plane drive is not modelled");
  InPlaneSpec spec;
  spec.constant_normal = r.constant_normal;
  const auto amplitude = [&](const NamedInput& in) {
    if (!in.given()) return InputValue(*Decimal::read("0"));
    const mpfr u = in.value.to<mpfr>();
    using std::isfinite;
    if (!isfinite(u) || u < 0) throw InputError(in.name + " = " + in.text() + ": expected a length >= 0 in metres");
    const mpfr a = u * scale;
    return InputValue::computed(a, format_significant(a, digits + 15));
  };
  spec.longitudinal = amplitude(r.u_x);
  spec.transverse = amplitude(r.u_y);
  if (r.phase.given()) {
    using std::isfinite;
    if (!isfinite(r.phase.value.to<mpfr>()))
      throw InputError(r.phase.name + " = " + r.phase.text() + ": expected a finite number of periods");
    spec.phase = r.phase.value;
  }
  if (r.in_plane_wave.given()) {
    spec.wave = parse_wave(*r.in_plane_wave.text);
    if (spec.wave.kind == WaveKind::fourier || spec.wave.kind == WaveKind::samples)
      throw InputError(r.in_plane_wave.name + " " + detail::visible(*r.in_plane_wave.text) +
                       ": expected a catalogue wave (sine, triangle, sawtooth-right, sawtooth-left, square, power:p)");
  }
  check_inplane(spec);
  return spec;
}

// The in-plane value and report (inplane.hpp), as rig_evaluated gives the rig's.
Evaluated inplane_evaluated(const WaveSpec& wave, const Point& point, const InPlaneSpec& spec, const Precision& precision,
                            const Options& solver, const ProfileSpec& profile, InPlaneReport& report) {
  const mpfr v = detail::inplane_value(wave, point, spec, precision, solver, profile, &report);
  return {detail::rig_text(v, precision), v};
}

// The in-plane outputs after mu's: the mean lateral force in newtons and the fractions (the flat
// punch's; a curved row has none), each to the digits both precisions agree on.
void inplane_outputs(PhysicalOutputs& rec, const InPlaneReport& report, const mpfr& force_unit, int digits) {
  const auto number = [&](const char* name, const mpfr& v, int known) { rec.push_back({name, {v, std::min(digits, known)}, {}}); };
  number("F_y_mean_N", mpfr(report.mean_lateral.value * force_unit), report.mean_lateral.digits);
  if (report.curved) return;
  number("stick_fraction", report.stick_fraction.value, report.stick_fraction.digits);
  number("slip_fraction", report.slip_fraction.value, report.slip_fraction.digits);
  if (!report.planar) number("backward_slip_fraction", report.backward_fraction.value, report.backward_fraction.digits);
  number("flight_fraction", report.flight_fraction.value, report.flight_fraction.digits);
}

// A constant normal load F_N on the flat punch with an in-plane oscillation (model.md: the force
// unit mu0 F_N, lengths mu0 F_N/k_x).
PhysicalOutputs physical_constant(const PhysicalRequest& r, const Precision& prec, const BatchOptions& base) {
  const int digits = output_digits(prec);
  PrecisionScope scope(static_cast<unsigned>(digits + 20));
  const auto get = [&](const NamedInput& in) {
    if (!in.given()) throw InputError("missing " + in.name + " for 'physical' with a constant normal force");
    return in.value.to<mpfr>();
  };
  const auto positive = [&](const NamedInput& in) {
    const mpfr v = get(in);
    if (!(v > 0)) throw InputError(in.name + " = " + in.text() + ": expected a value > 0");
    return v;
  };
  const auto poisson = [&](const NamedInput& in) {
    const mpfr v = get(in);
    if (!(v > -1 && v <= mpfr("0.5"))) throw InputError(in.name + " = " + in.text() + ": expected -1 < nu <= 0.5");
    return v;
  };
  for (const NamedInput* in : {&r.A, &r.u_mean})
    if (in->given())
      throw InputError(in->name + " with a constant normal force: the load is " + r.F_N.name + " (the normal force does not oscillate)");
  if (r.unit.given()) throw InputError(r.unit.name + " with a constant normal force: there is no normal amplitude to read");
  if (r.shape.given() && *r.shape.text != "flat")
    throw InputError(r.shape.name + " " + detail::visible(*r.shape.text) +
                     " with a constant normal force: a curved contact is solved with the normal oscillation (the flat punch only)");
  for (const NamedInput* in : {&r.R, &r.half_angle, &r.flat_radius})
    if (in->given()) throw InputError(in->name + " does not apply to the flat punch");
  PhysicalInput<mpfr> in{positive(r.E1), poisson(r.nu1), positive(r.E2), poisson(r.nu2), r.G1.value.to<mpfr>(),
                         r.G2.value.to<mpfr>(), positive(r.radius), positive(r.v0), positive(r.f), mpfr(1), mpfr(0),
                         positive(r.mu0)};
  for (const NamedInput* G : {&r.G1, &r.G2})
    if (G->given() && !(G->value.to<mpfr>() > 0)) throw InputError(G->name + " = " + G->text() + ": expected a value > 0");
  const mpfr F_N = positive(r.F_N);
  const auto g = physical_groups(in);  // E*, G*, k_x (A = 1 only fills its β, not used)
  const mpfr unit = in.mu0 * F_N;      // the force unit
  const std::optional<InPlaneSpec> spec = physical_drive(r, mpfr(g.k_x / unit), digits);
  const mpfr beta = g.k_x * in.v0 / (unit * in.f);
  const Point point{InputValue::computed(beta, format_significant(beta, digits + 15)), InputValue()};
  Precision fine = prec;
  if (fine.type == NumberType::mpfr) fine.digits = std::min(prec.digits + 10, max_digits);
  WaveSpec constant;
  constant.name = "constant";
  InPlaneReport report;
  const Evaluated ratio = inplane_evaluated(constant, point, *spec, fine, base.solver, ProfileSpec{}, report);
  PhysicalOutputs rec;
  const auto line = [&](const char* name, const mpfr& v) { rec.push_back({name, {v, digits}, {}}); };
  rec.push_back({"shape", {}, "flat"});
  line("E_star_Pa", g.E_star);
  line("G_star_Pa", g.G_star);
  line("k_x_N_per_m", g.k_x);
  line("beta", beta);
  line("longitudinal", spec->longitudinal.to<mpfr>());
  line("transverse", spec->transverse.to<mpfr>());
  line("phase", spec->phase.to<mpfr>());
  rec.push_back({"mu_over_mu0", fine.type == NumberType::mpfr ? Significant{ratio.value, digits}
                                                               : detail::type_significant(ratio.value, prec), {}});
  line("mu", mpfr(ratio.value * in.mu0));
  line("F_N_mean_N", F_N);
  line("F_x_mean_N", mpfr(ratio.value * unit));
  inplane_outputs(rec, report, unit, digits);
  return rec;
}

PhysicalOutputs physical_at(const WaveSpec& wave, const PhysicalRequest& r, const Precision& prec, const BatchOptions& base,
                            std::vector<std::string>* warnings, TraceTarget* trace) {
  using Input = NamedInput;
  const int digits = output_digits(prec);
  PrecisionScope scope(static_cast<unsigned>(digits + 20));
  const auto get = [&](const Input& in) {
    if (!in.given()) throw InputError("missing " + in.name + " for 'physical'");
    return in.value.to<mpfr>();
  };
  const auto opt = [&](const Input& in) { return in.value.to<mpfr>(); };  // 0 where not given
  const auto positive = [&](const Input& in) {
    const mpfr v = get(in);
    if (!(v > 0)) throw InputError(in.name + " = " + in.text() + ": expected a value > 0");
    return v;
  };
  // The indenter (model.md MDR): which geometry inputs it takes, its profile and length unit L.
  const std::string shape = r.shape.given() ? *r.shape.text : "flat";
  const std::string kind = shape.rfind("profile:", 0) == 0 ? "profile" : shape;
  const std::map<std::string, std::set<const Input*>> geometry{{"flat", {&r.radius}},
                                                               {"sphere", {&r.R}},
                                                               {"cone", {&r.half_angle}},
                                                               {"wearflat", {&r.R, &r.flat_radius}},
                                                               {"profile", {}}};
  if (!geometry.count(kind)) {
    const std::string hint = did_you_mean(shape, {"flat", "sphere", "cone", "wearflat", "profile:FILE"});
    throw InputError(r.shape.name + " '" + detail::visible(shape) + "': expected flat, sphere, cone, wearflat or profile:FILE" +
                     (hint.empty() ? "" : "; " + detail::visible(hint)));
  }
  for (const Input* g : {&r.radius, &r.R, &r.half_angle, &r.flat_radius})
    if (g->given() && !geometry.at(kind).count(g))
      throw InputError(g->name + " does not apply to " + r.shape.name + " " + detail::visible(shape));
  const mpfr A = positive(r.A);
  // The mean indentation, or the mean normal load an experimenter sets (then γ solves ⟨F_N⟩(γ) = F_N).
  const bool by_load = r.F_N.given();
  if (by_load && r.u_mean.given())
    throw InputError(r.u_mean.name + " and " + r.F_N.name + " both given: expected one of them");
  if (!by_load && !r.u_mean.given())
    throw InputError("missing " + r.u_mean.name + " (mean indentation) or " + r.F_N.name +
                     " (mean normal load) for 'physical'");
  // Checked here with the values as typed (physical_groups checks them again, for library users).
  const auto poisson = [&](const Input& in) {
    const mpfr v = get(in);
    if (!(v > -1 && v <= mpfr("0.5"))) throw InputError(in.name + " = " + in.text() + ": expected -1 < nu <= 0.5");
    return v;
  };
  PhysicalInput<mpfr> in{positive(r.E1), poisson(r.nu1), positive(r.E2), poisson(r.nu2), opt(r.G1), opt(r.G2),
                         kind == "flat" ? positive(r.radius) : mpfr(0), positive(r.v0), positive(r.f), A,
                         by_load ? mpfr(0) : get(r.u_mean), positive(r.mu0)};
  for (const Input* G : {&r.G1, &r.G2})
    if (G->given() && !(opt(*G) > 0)) throw InputError(G->name + " = " + G->text() + ": expected a value > 0");
  // A samples wave with time stamps has its own period: --f must be its frequency (a record in ms
  // read as s, or of two periods, would otherwise be taken for one period at f).
  if (const auto T = stamped_period(wave)) {
    const mpfr ratio = in.f * T->seconds;
    if (abs(mpfr(ratio - 1)) > mpfr("0.01"))
      throw InputError(r.f.name + " = " + r.f.text() + " Hz, but the time column '" + detail::visible(wave.time_column) + "' of " +
                       detail::visible(wave.name) + " spans a period of " + format_significant(T->seconds, 6) + " s (" +
                       format_significant(mpfr(1 / T->seconds), 6) + " Hz" +
                       (T->assumed ? ", its header naming no unit: taken as seconds" : "") +
                       "): expected them to agree within 1 %");
  }
  auto g = physical_groups(in);
  BatchOptions options = base;
  options.profile = ProfileSpec{};
  // Rig dynamics (model.md): the body's mass and the apparatus' stiffness, on the punch (k_x, Eq. 1)
  // or on a curved contact (k_x,max = 2 a_max G*, the row's stiffness at the deepest instant).
  const bool rig = r.mass.given() || r.k_system.given() || r.damping.given();
  std::function<RigSpec(const mpfr&)> rig_of;
  mpfr k_x_max;
  if (rig) {
    if (!r.mass.given() || !r.k_system.given())
      throw InputError("missing " + (r.mass.given() ? r.k_system.name : r.mass.name) + ": rig dynamics needs " +
                       r.mass.name + " and " + r.k_system.name + " (" + r.damping.name + " is optional)");
    const mpfr m = positive(r.mass), ks = positive(r.k_system);
    const mpfr c = opt(r.damping);
    if (r.damping.given() && !(c >= 0)) throw InputError(r.damping.name + " = " + r.damping.text() + ": expected a value >= 0");
    // Values, labelled for messages by 17 digits.
    rig_of = [=, f = in.f](const mpfr& k_x) {
      const auto computed = [](const mpfr& v) { return InputValue::computed(v, format_significant(v, 17)); };
      RigSpec spec;
      spec.kappa = computed(mpfr(ks / k_x));
      spec.omega = computed(mpfr(sqrt(mpfr(k_x / m)) / (2 * boost::math::constants::pi<mpfr>() * f)));
      spec.zeta = computed(mpfr(c / (2 * sqrt(mpfr(m * ks)))));
      return spec;
    };
    // the punch's k_x now; a curved contact's k_x,max = 2 a_max G* once γ (a_max) is known
    if (kind == "flat") options.rig = rig_of(g.k_x);
  }
  // In-plane oscillation: a_l = k_x u_x/(mu0 k_z A) = G* u_x/(mu0 E* A), for the punch and the row.
  const std::optional<InPlaneSpec> drive = physical_drive(r, mpfr(g.G_star / (in.mu0 * g.E_star * A)), digits);
  const bool inplane = drive && !detail::papers_model(*drive);
  if (drive) options.inplane = *drive;
  mpfr length = 1;
  std::optional<mpfr> lambda;
  if (kind == "sphere") {
    options.profile = parse_profile("sphere");
    length = sphere_length(positive(r.R), A);
  } else if (kind == "cone") {
    const mpfr theta = positive(r.half_angle);
    if (!(theta < 90)) throw InputError(r.half_angle.name + " = " + r.half_angle.text() + ": expected degrees in (0, 90)");
    options.profile = parse_profile("cone");
    length = cone_length(theta, A);
  } else if (kind == "wearflat") {
    const mpfr R = positive(r.R), b = positive(r.flat_radius);
    // λ goes to the profile as a value; its text (wearflat:λ) only names the profile.
    lambda = mpfr(b * b / (R * A));
    options.profile = wear_flat_profile(*lambda, format_significant(*lambda, digits + 15));
    length = b;
  } else if (kind == "profile") {
    options.profile = parse_profile(shape);
    options.profile.height_unit = r.A.value;  // heights in metres, the library's in units of A
  }
  // ⟨F_N⟩(γ) = 2 E* A L ∫N dx (punch: k_z A N_w(γ)), at the working precision of this scope: N does
  // not depend on β. Also the largest contact radius (curved) in units of L.
  const auto w = make_waveform<mpfr>(wave);
  const auto p = kind == "flat" ? nullptr : make_profile<mpfr>(options.profile);
  // Contact needs gamma + max w > 0 (Eq. 14: u_mean > -A max w), said in the inputs' own terms.
  if (!by_load && !(g.gamma + w->maximum() > 0))
    throw DomainError(r.u_mean.name + " = " + r.u_mean.text() + " with " + r.A.name + " = " + r.A.text() +
                      " gives no contact for wave " +
                      wave.name + ": expected u_mean > -A max w = " + format_significant(mpfr(-A * w->maximum()), 6) +
                      " m (gamma = u_mean/A > " + format_significant(mpfr(-w->maximum()), 6) + ")");
  auto load = [&](const mpfr& gam, const mpfr& beta, mpfr* edge_out) {
    if (!(gam + w->maximum() > 0)) return mpfr(0);  // no contact, no load
    mpfr normal;
    if (kind == "flat") {
      normal = solve(*w, beta, gam, options.solver).normal_area;
    } else {
      const auto r = solve_curved(*w, *p, beta, gam, options.solver, mpfr(pow(mpfr(10), -digits - 5)));
      normal = r.normal_integral;
      if (edge_out) *edge_out = r.contact_radius;
    }
    return kind == "flat" ? mpfr(g.k_z * A * normal) : mpfr(2 * g.E_star * A * length * normal);
  };
  // Every input the load depends on, for the caches of γ (by load) and of the load (by γ).
  std::string key = std::to_string(static_cast<int>(prec.type)) + " " + std::to_string(digits) + " " +
                    std::to_string(static_cast<int>(options.solver.area)) + " " +
                    std::to_string(options.solver.max_root_iterations) + " " +
                    std::to_string(options.solver.max_quadrature_levels) + " " +
                    format_significant(mpfr(options.solver.quadrature_tolerance), 17) + "\n" + wave_fingerprint(wave) +
                    "\nprofile " + options.profile.name + " " +
                    (options.profile.height_unit.given() ? options.profile.height_unit.text() : std::string("1"));
  for (std::size_t i = 0; i < options.profile.r.size(); ++i)
    key += "\n" + options.profile.r[i].text() + " " + options.profile.f[i].text();
  for (const Input* in : {&r.E1, &r.nu1, &r.E2, &r.nu2, &r.G1, &r.G2, &r.A, &r.F_N})
    key += "\n" + (in->given() ? in->text() : std::string("-"));
  key += "\n" + (r.shape.given() ? *r.shape.text : std::string("-"));
  for (const Input* in : {&r.radius, &r.R, &r.half_angle, &r.flat_radius})
    key += "\n" + (in->given() ? in->text() : std::string("-"));
  if (by_load) {
    const mpfr F_N = positive(r.F_N);
    // ⟨F_N⟩ = 2 E* A L ∫N dx does not depend on β (N_w does not), so γ depends on neither v0 nor
    // f nor mu0: the load is computed at β_c(γ') of the central spring, where nothing sticks
    // (Eq. 6) and only ∫N is integrated, and a sweep of those inputs solves γ once (per thread).
    // With an upward jump of n (β_c = ∞) the row's β is used, and γ is solved for every row.
    bool free_of_beta = true;
    auto beta_free_load = [&](const mpfr& gam) {
      if (!(gam + w->maximum() > 0)) return mpfr(0);
      const mpfr bc = make_contact(*w, gam, options.solver).beta_c();
      using std::isfinite;
      if (isfinite(bc) && bc > 0) return load(gam, bc, nullptr);
      free_of_beta = false;
      return load(gam, g.beta, nullptr);
    };
    static thread_local std::map<std::string, mpfr> solved;  // γ of the load, by every input it depends on
    if (const auto it = solved.find(key); it != solved.end()) {
      g.gamma = it->second;
    } else {
      // ⟨F_N⟩ rises strictly with γ from 0 at γ = −max w: bracket by doubling, then TOMS 748.
      mpfr lo = -w->maximum(), hi = lo + 1;
      for (int k = 0; beta_free_load(hi) < F_N; ++k) {
        if (k == 200) throw InputError(r.F_N.name + " = " + r.F_N.text() + ": expected a load the contact can carry");
        lo = hi;
        hi = lo + pow(mpfr(2), k + 1);
      }
      std::uintmax_t iterations = 400;
      const auto bracket = boost::math::tools::toms748_solve(
          [&](const mpfr& gam) { return mpfr(beta_free_load(gam) - F_N); }, lo, hi,
          boost::math::tools::eps_tolerance<mpfr>(std::numeric_limits<mpfr>::digits - 10), iterations);
      if (iterations >= 400) throw SolverError(r.F_N.name + " = " + r.F_N.text() + ": the mean indentation did not converge");
      g.gamma = (bracket.first + bracket.second) / 2;
      if (free_of_beta) {
        if (solved.size() >= 64) solved.clear();
        solved.emplace(key, g.gamma);
      }
    }
  }
  // β and γ go to evaluate as values; the texts only name the point in its messages.
  const Point point{InputValue::computed(g.beta, format_significant(g.beta, digits + 15)),
                    InputValue::computed(g.gamma, format_significant(g.gamma, digits + 15))};
  if (rig && kind != "flat") {
    k_x_max = 2 * g.G_star * length * p->x_at_sigma(mpfr(g.gamma + w->maximum()));
    options.rig = rig_of(k_x_max);
  }
  if (trace) {
    if (inplane)
      throw InputError("a trace in SI units under an in-plane oscillation: not with " +
                       (r.u_x.given() ? r.u_x.name : r.u_y.name));
    TraceRequest request;
    request.beta.value = point.beta;
    request.gamma.value = point.gamma;
    request.points = trace->points;
    request.digits = trace->digits;
    request.profile = options.profile;
    const int d = trace->digits;
    const mpfr scale = kind == "flat" ? mpfr(g.k_z * A) : mpfr(2 * g.E_star * A * length);
    // At a contact boundary γ + w = 0 by definition: its computed value, a rounding far below
    // the digits asked of A, is 0.
    const mpfr floor_u = A * pow(mpfr(10), -d - 3);
    const auto at = [&](const mpfr& x) { return Significant{mpfr(format_significant(x, d)), d}; };
    const auto indentation = [&](const mpfr& phi) {
      const mpfr u = A * (g.gamma + (*w)(phi - floor(phi)));
      return abs(u) < floor_u ? Significant{mpfr(0), d} : at(u);
    };
    if (!options.rig) {
      for (const TraceRow& row : trace_rows(wave, request))
        trace->rows.push_back({at(mpfr(row.phi / in.f)), at(mpfr(scale * row.n)), at(mpfr(in.mu0 * scale * row.s)),
                               indentation(row.phi), std::nullopt, std::nullopt});
    } else {
      // The body: lengths in the rig's unit μ0 k_z A/k_x (μ0 E* A/G* on a curved contact), x = v0 t
      // + Y, F_s = −k_s Y − c Y' f (Y' per period). A value's digits are those its inputs carry: each
      // input uncertain by half a unit in its last printed digit.
      const mpfr unit = kind == "flat" ? mpfr(in.mu0 * g.k_z * A / g.k_x) : mpfr(in.mu0 * g.E_star * A / g.G_star);
      const mpfr ks = positive(r.k_system), c = opt(r.damping);
      const auto half_unit = [](const Significant& v) {
        if (v.value == 0) return mpfr(0);
        const long e = static_cast<long>(floor(log10(abs(v.value))));
        return mpfr(pow(mpfr(10), e - v.digits + 1) / 2);
      };
      // v to the most digits (at most d) whose half unit in the last place covers the error
      const auto with_error = [&](const mpfr& v, const mpfr& error) {
        if (v == 0 || error == 0) return at(v);
        const long e = static_cast<long>(floor(log10(abs(v))));
        int digits = d;
        while (digits > 1 && error > pow(mpfr(10), e - digits + 1) / 2) --digits;
        return Significant{mpfr(format_significant(v, digits)), digits};
      };
      const auto scaled = [&](const mpfr& k, const Significant& v) {
        return Significant{mpfr(format_significant(mpfr(k * v.value), std::min(d, v.digits))), std::min(d, v.digits)};
      };
      const auto add = [&](const mpfr& phi, const Significant& n, const Significant& s, const Significant& lag,
                           const Significant& rate) {
        const mpfr t = phi / in.f;
        const mpfr x = in.v0 * t + lag.value * unit;
        const mpfr F_s = -ks * lag.value * unit - c * rate.value * unit * in.f;
        PhysicalTraceRow row{at(t), scaled(scale, n), scaled(in.mu0 * scale, s), indentation(phi),
                             with_error(x, mpfr(half_unit(lag) * unit)),
                             with_error(F_s, mpfr(ks * half_unit(lag) * unit + c * half_unit(rate) * unit * in.f))};
        // the rig's two rows where a mode ends (left and right) are one here, with no mode column,
        // where every printed value is the same
        const auto text = [](const PhysicalTraceRow& q) {
          return q.t_s.text() + q.F_N_N.text() + q.F_x_N.text() + q.u_m.text() + q.x_m->text() + q.F_s_N->text();
        };
        if (trace->rows.empty() || text(trace->rows.back()) != text(row)) trace->rows.push_back(std::move(row));
      };
      // the body's columns from the lag and its rate at 3 guard digits (x and F_s each derive from
      // one of them, and would lose a digit to its rounding at d)
      TraceRequest body = request;
      body.digits = std::min(d + 3, max_digits);
      if (kind == "flat") {
        for (const RigTraceRow& row : rig_trace_rows(wave, body, *options.rig, options.solver))
          add(row.phi, {row.n, body.digits}, {row.s, body.digits}, {row.lag, body.digits}, {row.lag_rate, body.digits});
      } else {
        for (const RigRowTraceRow& row : rig_row_trace_rows(wave, body, *options.rig, options.solver))
          add(row.phi, row.n, row.s, row.lag, row.lag_rate);
      }
    }
  }
  // μ = μ0·(μ̄/μ0) from the ratio's value (mpfr: decided at 10 more digits), rounded once to the
  // requested digits.
  Precision fine = prec;
  if (fine.type == NumberType::mpfr) fine.digits = std::min(prec.digits + 10, max_digits);
  RigReport report;
  InPlaneReport inplane_report;
  const Evaluated ratio = options.rig ? rig_evaluated(wave, point, *options.rig, fine, options.solver, report, options.profile)
                          : inplane ? inplane_evaluated(wave, point, *drive, fine, options.solver, options.profile, inplane_report)
                                    : evaluate_one(wave, Quantity::mu, point, fine, options);
  const mpfr mu = ratio.value * in.mu0;
  // ⟨F_N⟩ and the contact radius do not depend on β (N_w does not): as for γ above, they are
  // integrated at β_c of the central spring, where nothing sticks, so that a sweep of v0, f or
  // mu0 at one γ integrates the row's normal force once (per thread), each row as its single
  // point. With an upward jump of n (β_c = ∞) the row's β.
  mpfr edge, force;
  {
    const mpfr bc = make_contact(*w, g.gamma, options.solver).beta_c();
    using std::isfinite;
    if (kind != "flat" && isfinite(bc) && bc > 0) {
      static thread_local std::map<std::string, std::pair<mpfr, mpfr>> loads;
      const std::string at = key + "\ngamma " + format_significant(g.gamma, digits + 40);
      if (const auto it = loads.find(at); it != loads.end()) {
        force = it->second.first;
        edge = it->second.second;
      } else {
        force = load(g.gamma, bc, &edge);
        if (loads.size() >= 64) loads.clear();
        loads.emplace(at, std::make_pair(force, edge));
      }
    } else {
      force = load(g.gamma, g.beta, &edge);
    }
  }
  // β_c (Eq. 6, of the clipped n; a curved contact's is its central spring's) and, for the punch,
  // the fractions of the period in contact and in stick.
  mpfr beta_c, contact_fraction, stick_fraction;
  if (kind == "flat") {
    const Contact<mpfr> c = make_contact(*w, g.gamma, options.solver);
    const auto r = solve(c, g.beta, options.solver);
    beta_c = r.beta_c;
    for (const auto& seg : c.segments())
      if (seg.contact) contact_fraction += seg.v - seg.u;
    for (const auto& st : r.stick_phases) stick_fraction += st.end - st.begin;
  } else {
    const Contact<mpfr> c = make_contact(*w, g.gamma, options.solver);
    beta_c = c.beta_c();
    for (const auto& seg : c.segments())
      if (seg.contact) contact_fraction += seg.v - seg.u;  // the body touches while the central spring does
    if (!options.rig && !inplane) {
      // The row's stick share (curved_trace.hpp), to 5 digits beyond those printed.
      mpfr err;
      stick_fraction = curved_stick_integral(*w, *p, g.beta, g.gamma, mpfr(pow(mpfr(10), -digits - 5)), err, options.solver) /
                       p->x_at_sigma(mpfr(g.gamma + w->maximum()));
    }
  }
  // The deepest instant of the period, every spring at n_max = γ + max w: the load (punch: k_z A
  // n_max; curved: 2 E* A L (n_max X − ∫₀^X σ dx), σ(X) = n_max) and the mean pressure over the
  // contact circle. The largest local pressure is Hertz's 3/2 of the mean on the sphere; on the
  // punch's rim (Boussinesq), the cone's tip (Sneddon) and a profile's kinks (the wear flat's rim,
  // a measured profile's samples) the elastic pressure is unbounded.
  const mpfr n_max = g.gamma + w->maximum();
  mpfr peak_force, peak_radius;
  if (kind == "flat") {
    peak_force = g.k_z * A * n_max;
    peak_radius = in.radius;
  } else {
    const mpfr X = p->x_at_sigma(n_max);
    peak_force = 2 * g.E_star * A * length * (n_max * X - p->sigma_integral(X));
    peak_radius = length * X;
  }
  const mpfr peak_mean_pressure = peak_force / (boost::math::constants::pi<mpfr>() * peak_radius * peak_radius);
  // Plausible ranges, wide enough for every engineering solid and rig: moduli from soft rubber
  // (1e5 Pa) to diamond (1.2e12 Pa); an amplitude from 0.1 nm to 1 mm; mu0 up to 2.
  std::vector<std::string> implausible, suspects;
  const auto outside = [&](const Input& in, const mpfr& v, const char* lo, const char* hi, const std::string& what) {
    if (in.given() && (v < mpfr(lo) || v > mpfr(hi))) {
      implausible.push_back(in.name + " = " + in.text() + " is outside " + lo + " to " + hi + " " + what);
      suspects.push_back(in.name);
    }
  };
  outside(r.E1, in.E1, "1e5", "1.2e12", "Pa, the moduli of solids (GPa written as Pa?)");
  outside(r.E2, in.E2, "1e5", "1.2e12", "Pa, the moduli of solids (GPa written as Pa?)");
  outside(r.A, A, "1e-10", "1e-3", "m, the amplitudes of a vibrated contact (um written as m?)");
  if (in.mu0 > 2) implausible.push_back(r.mu0.name + " = " + r.mu0.text() + " is above 2, no coefficient of friction of solids");
  // Hertz and the MDR take the sphere as the parabola r²/2R: at a = 0.3 R its height is 2.3 % off;
  // a contact as wide as the sphere is outside the theory, an input in the wrong unit.
  const Input* radius_of_curvature = kind == "sphere" || kind == "wearflat" ? &r.R : nullptr;
  if (radius_of_curvature) {
    const mpfr a = length * edge, ratio = a / get(*radius_of_curvature);
    const std::string said = "the contact radius " + format_significant(a, 3) + " m is " + format_significant(ratio, 2) +
                             " times " + radius_of_curvature->name + " = " + radius_of_curvature->text() + " m";
    if (ratio >= 1) {
      // Every input that sets the contact's size, or those already out of range.
      std::string check;
      for (const auto& [i, unit] : {std::pair<const Input*, const char*>{&r.E1, "Pa"}, {&r.E2, "Pa"},
                                    {radius_of_curvature, "m"}, {&r.F_N, "N"}, {&r.u_mean, "m"}, {&r.A, "m"}})
        if (i->given() && (suspects.empty() || std::count(suspects.begin(), suspects.end(), i->name)))
          check += (check.empty() ? "" : ", ") + i->name + " (" + unit + ")";
      throw InputError(said + ": a contact as wide as the sphere is outside Hertz's theory and the MDR; check the units of " +
                       check);
    }
    if (ratio > mpfr("0.3"))
      implausible.push_back(said + ": Hertz and the MDR take the sphere as a parabola, which needs the contact small against it");
  }
  if (warnings) warnings->insert(warnings->end(), implausible.begin(), implausible.end());
  PhysicalOutputs rec;
  auto field = [&](const char* name, const std::string& word) { rec.push_back({name, {}, word}); };
  auto number = [&](const char* name, const mpfr& v, int known) { rec.push_back({name, {v, known}, {}}); };
  auto line = [&](const char* name, const mpfr& v) { number(name, v, digits); };
  field("shape", kind == "profile" ? shape : kind);
  line("E_star_Pa", g.E_star);
  line("G_star_Pa", g.G_star);
  if (kind == "flat") {
    line("k_z_N_per_m", g.k_z);
    line("k_x_N_per_m", g.k_x);
  } else {
    line("contact_radius_max_m", mpfr(length * edge));
  }
  if (lambda) line("lambda", *lambda);
  line("beta", g.beta);
  line("gamma", g.gamma);
  if (by_load) line("u_mean_m", mpfr(g.gamma * A));
  if (drive) {
    line("longitudinal", drive->longitudinal.to<mpfr>());
    line("transverse", drive->transverse.to<mpfr>());
    line("phase", drive->phase.to<mpfr>());
  }
  // evaluate's text: the type's value (the rig's is computed in mpfr), or mpfr's to `digits`
  // (a curved contact's rig: the digits its row's two sizes agree on)
  const int mu_known = report.mu_digits ? std::min(digits, report.mu_digits) : digits;
  rec.push_back({"mu_over_mu0", report.mu_digits                  ? Significant{ratio.value, mu_known}
                                : fine.type == NumberType::mpfr ? Significant{ratio.value, digits}
                                                                : detail::type_significant(ratio.value, prec), {}});
  number("mu", mu, mu_known);
  line("F_N_mean_N", force);
  number("F_x_mean_N", mpfr(mu * force), mu_known);
  // The in-plane model: the lateral force and its own fractions (its β_c is not the paper's).
  if (inplane) inplane_outputs(rec, inplane_report, mpfr(in.mu0 * force), digits);
  line("F_N_peak_N", peak_force);
  line("p_mean_peak_Pa", peak_mean_pressure);
  if (kind == "sphere")
    line("p_max_peak_Pa", mpfr(3 * peak_mean_pressure / 2));
  else
    field("p_max_peak_Pa", "inf");
  using std::isfinite;
  if (!inplane) {
    if (isfinite(beta_c))
      line("beta_c", beta_c);
    else
      field("beta_c", "inf");  // an upward jump of n: stick at every beta
  }
  line("contact_fraction", contact_fraction);
  if (options.rig) {
    // the rig's periodic state: its own fractions, and the frequency ratios it was computed with
    if (kind != "flat") {
      line("k_x_max_N_per_m", k_x_max);
      field("springs", std::to_string(report.springs));  // the row's, its digits those of n and n/2 agreeing
    }
    line("kappa", *options.rig->kappa.computed_value());
    line("omega", *options.rig->omega.computed_value());
    line("zeta", *options.rig->zeta.computed_value());
    // the report's digits (those both precisions agree on, of the finer request) to the request's
    const auto fraction = [&](const char* name, const Significant& v) { number(name, v.value, std::min(digits, v.digits)); };
    fraction("stick_fraction", report.stick_fraction);
    fraction("slip_fraction", report.slip_fraction);
    fraction("backward_slip_fraction", report.backward_fraction);
    fraction("flight_fraction", report.flight_fraction);
    // lengths: the rig's unit μ0 k_z A/k_x (model.md; μ0 E* A/G* on a curved contact, k_z,max/k_x,max),
    // to the digits both precisions agree on
    const mpfr unit = kind == "flat" ? mpfr(in.mu0 * g.k_z * A / g.k_x) : mpfr(in.mu0 * g.E_star * A / g.G_star);
    const auto length_m = [&](const char* name, const Significant& v) {
      number(name, mpfr(v.value * unit), std::min(digits, v.digits));
    };
    length_m("body_amplitude_m", report.amplitude);
    length_m("largest_backward_slip_m", report.largest_backward_slip);
    char floquet[32];
    std::snprintf(floquet, sizeof floquet, "%.6g", report.floquet);
    field("floquet_multiplier", floquet);
    line("quasi_static_mu_over_mu0", mpfr(report.quasi_static_mu));
    if (warnings && !report.resonance_note.empty()) warnings->push_back(report.resonance_note);
  } else if (!inplane) {
    line("stick_fraction", stick_fraction);
  }
  return rec;
}
}  // namespace


void check_trace_request(const TraceRequest& request) {
  for (const NamedInput* in : {&request.beta, &request.gamma})
    if (!in->given()) throw InputError("missing " + in->name + " for 'trace'");
  if (request.points < min_trace_points || request.points > max_trace_points)
    throw InputError(request.points_name + " = " + std::to_string(request.points) + ": expected an integer from " +
                     std::to_string(min_trace_points) + " to " + std::to_string(max_trace_points));
  if (request.digits < min_digits || request.digits > max_digits)
    throw InputError(request.digits_name + " = " + std::to_string(request.digits) + ": expected an integer from " +
                     std::to_string(min_digits) + " to " + std::to_string(max_digits));
}

namespace {
// The curved trace (curved_trace.hpp) at the phases, each s to `digits` of itself. Rows whose s
// only reached the rounding floor (just after first contact: s tiny) are computed again at twice
// the working digits, up to three times; the contact boundaries are 0 by definition.
std::vector<TraceRow> curved_trace_rows(const WaveSpec& wave, const TraceRequest& request, const std::vector<mpfr>& phis,
                                        const std::vector<mpfr>& edges) {
  const int digits = request.digits;
  std::map<std::size_t, CurvedTraceRow<mpfr>> done;
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < phis.size(); ++i)
    if (std::find(edges.begin(), edges.end(), phis[i]) == edges.end()) todo.push_back(i);
  const long first = digits + guard_digits(digits);
  long last = first;
  const auto attempt = [&](long work) -> std::optional<bool> {
    last = work;
    PrecisionScope scope(static_cast<unsigned>(work));
    const auto w = make_waveform<mpfr>(wave);
    const auto p = make_profile<mpfr>(request.profile);
    const mpfr beta = request.beta.value.to<mpfr>(), gamma = request.gamma.value.to<mpfr>();
    const mpfr target = pow(mpfr(10), -digits);
    std::vector<mpfr> at;
    for (std::size_t i : todo) at.push_back(phis[i]);
    const auto trace = curved_trace(*w, *p, beta, gamma, at, mpfr(target / 16));
    std::vector<std::size_t> again;
    for (std::size_t k = 0; k < todo.size(); ++k) {
      done[todo[k]] = trace[k];
      if (!(trace[k].error <= target / 2 * trace[k].s)) again.push_back(todo[k]);
    }
    todo = again;
    if (todo.empty()) return true;
    return std::nullopt;
  };
  if (!todo.empty() && !escalate(first, attempt, doubling_up_to(8 * first))) {
    const auto& t = done.at(todo.front());
    throw SolverError("trace at phase " + format_significant(t.phi, 10) + ": s = " + format_significant(t.s, 10) +
                      " keeps an error estimate of " + format_significant(t.error, 3) + " at " + std::to_string(last) +
                      " working digits, not " + std::to_string(digits) + " digits of itself");
  }
  std::vector<TraceRow> rows;
  for (std::size_t i = 0; i < phis.size(); ++i) {
    const auto it = done.find(i);
    if (it == done.end())
      rows.push_back({phis[i], mpfr(0), mpfr(0)});
    else
      rows.push_back({phis[i], it->second.n, it->second.s});
  }
  return rows;
}
}  // namespace

std::vector<TraceRow> trace_rows(const WaveSpec& wave, const TraceRequest& request) {
  check_trace_request(request);
  const int n_points = request.points, digits = request.digits;
  PrecisionScope scope(static_cast<unsigned>(digits + guard_digits(digits)));
  const auto w = make_waveform<mpfr>(wave);
  const mpfr beta = request.beta.value.to<mpfr>(), gamma = request.gamma.value.to<mpfr>();
  const Contact<mpfr> contact = make_contact(*w, gamma);
  // The contact boundaries, where n = 0 by definition (its computed value is a rounding, ~1e-32);
  // of a curved contact, the central spring's (the body lifts off and lands).
  std::vector<mpfr> edges;
  for (const auto& g : contact.segments())
    if (g.contact) {
      if (g.nu == 0) edges.push_back(g.u);
      if (g.nv == 0) edges.push_back(g.v);
    }
  std::vector<mpfr> phis(edges);
  for (int i = 0; i <= n_points; ++i) phis.push_back(mpfr(i) / n_points);
  const bool curved = request.profile.kind != ProfileKind::flat;
  const auto r = curved ? Result<mpfr>{} : solve(contact, beta);
  for (const auto& st : r.stick_phases)
    for (const mpfr& x : {st.begin, st.end}) phis.push_back(x - floor(x));
  std::sort(phis.begin(), phis.end());
  phis.erase(std::unique(phis.begin(), phis.end()), phis.end());
  if (curved) return curved_trace_rows(wave, request, phis, edges);
  std::vector<TraceRow> rows;
  for (const mpfr& phi : phis) {
    const bool edge = std::find(edges.begin(), edges.end(), phi) != edges.end();
    const mpfr v = edge ? mpfr(0) : mpfr(gamma + (*w)(phi - floor(phi)));
    const mpfr s = edge ? mpfr(0) : tangential_force(*w, r, beta, gamma, phi == 1 ? mpfr(0) : phi);
    rows.push_back({phi, v > 0 ? v : mpfr(0), s});
  }
  return rows;
}

}  // namespace vibrofric
