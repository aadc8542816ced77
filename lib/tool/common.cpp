// Helpers of the commands: required flags, the precision and batch options of the flags, CSV and
// JSON output, the wave of --wave with its diagnostics, and --certify's certifier.
#include <csv.h>

#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"

namespace vibrofric::tool {

const std::string& need(const Flags& f, const std::optional<std::string>& value, const std::string& name) {
  if (!value) throw InputError("missing --" + name + " for '" + f.command + "'");
  return *value;
}

const InputValue& need(const Flags& f, const InputValue& value, const std::string& name) {
  if (!value.given()) throw InputError("missing --" + name + " for '" + f.command + "'");
  return value;
}

Precision precision_of(const Flags& f) {
  Precision p;
  if (f.type) p.type = *f.type;
  if (f.digits) {
    if (f.type && *f.type != NumberType::mpfr)
      throw InputError("--digits goes with mpfr only: --type " + detail::visible(f.type_text) + " has fixed precision");
    p.digits = *f.digits;
  }
  return p;
}

BatchOptions batch_options(const Flags& f) {
  BatchOptions o;
  o.profile = f.profile;
  o.escalate = !f.no_escalate;
  o.solver = f.solver;
  if (f.kappa.given() || f.omega.given() || f.zeta.given()) {
    if (f.command == "psi")
      throw InputError("--kappa, --omega, --zeta do not apply to psi: Psi (Eq. 12) belongs to the quasi-static model (use mu)");
    if (!f.kappa.given() || !f.omega.given())
      throw InputError(std::string("missing --") + (f.kappa.given() ? "omega" : "kappa") +
                       ": rig dynamics needs --kappa and --omega (--zeta is optional)");
    if (f.certify && f.command != "mu")
      throw InputError("--certify with --kappa/--omega: a proven rig state is given point by point, by mu");
    if (f.certify && f.profile.kind != ProfileKind::flat)
      throw InputError("--certify --profile " + detail::visible(f.profile_text.value_or("")) +
                       " with --kappa/--omega: a proven rig state exists for the flat punch (a curved contact's row "
                       "shares one body)");
    if (f.no_escalate) throw InputError("--no-escalate: rig dynamics is always computed in mpfr at two precisions");
    o.rig.emplace();
    o.rig->kappa = f.kappa;
    o.rig->omega = f.omega;
    if (f.zeta.given()) o.rig->zeta = f.zeta;
    check_rig(*o.rig);
  }
  o.inplane = inplane_options(f);
  return o;
}

WaveSpec normal_wave(const Flags& f, const std::optional<InPlaneSpec>& inplane) {
  if (!inplane || !inplane->constant_normal) return read_wave(f);
  WaveSpec constant;
  constant.name = "constant";
  return constant;
}

std::optional<InPlaneSpec> inplane_options(const Flags& f) {
  const bool constant = f.wave && *f.wave == "constant";
  const bool amplitude = f.longitudinal.given() || f.transverse.given();
  if (!constant && !amplitude && !f.phase.given() && !f.in_plane_wave) return std::nullopt;
  if (!amplitude && (f.phase.given() || f.in_plane_wave))
    throw InputError(std::string(f.phase.given() ? "--phase" : "--in-plane-wave") +
                     " without --longitudinal or --transverse: give the in-plane amplitude");
  if (f.kappa.given() || f.omega.given() || f.zeta.given())
    throw InputError("--kappa/--omega with an in-plane oscillation: rig dynamics with an in-plane drive is not modelled");
  if (f.certify && f.command != "mu")
    throw InputError("--certify with an in-plane drive: certified values are given point by point, by mu");
  if (f.certify && f.profile.kind != ProfileKind::flat)
    throw InputError("--certify --profile " + detail::visible(f.profile_text.value_or("")) +
                     ": certified values exist for the flat punch only (a curved contact integrates over springs)");
  if (f.no_escalate) throw InputError("--no-escalate: in-plane oscillation is always computed in mpfr at two precisions");
  if (f.profile.kind != ProfileKind::flat && constant)
    throw InputError("--wave constant with --profile " + detail::visible(f.profile_text.value_or("")) +
                     ": a curved contact is solved with the normal oscillation (give --wave and --gamma)");
  InPlaneSpec s;
  s.constant_normal = constant;
  s.longitudinal = f.longitudinal.given() ? f.longitudinal : InputValue(*Decimal::read("0"));
  if (f.transverse.given()) s.transverse = f.transverse;
  if (f.phase.given()) s.phase = f.phase;
  if (f.in_plane_wave) s.wave = parse_wave(*f.in_plane_wave);
  check_inplane(s);
  // A zero drive under the normal oscillation is the paper's model: its output, line for line (psi
  // is still refused below, as for any in-plane flag).
  const bool psi = f.command == "psi" || f.quantity == Quantity::psi;
  if (detail::papers_model(s) && !psi) return std::nullopt;
  return s;
}

namespace {

// Output formats of mu, psi, sweep and physical: their plain text, CSV (RFC 4180: a field with a
// comma, a quote or a line break is quoted by libcsv) or JSON (nlohmann; values as decimal strings,
// which keep every digit). One record is a JSON object, several are an array of objects.
std::string csv_field(const std::string& f) {
  if (f.find_first_of(",\"\r\n") == std::string::npos) return f;
  std::string out(2 * f.size() + 3, '\0');
  out.resize(csv_write(out.data(), out.size(), f.data(), f.size()));
  return out;
}

}  // namespace

void write_csv_row(const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i) std::cout << (i ? "," : "") << csv_field(fields[i]);
  std::cout << '\n';
}

nlohmann::ordered_json json_record(const std::vector<std::string>& names, const std::vector<std::string>& values) {
  nlohmann::ordered_json j;
  for (std::size_t i = 0; i < names.size(); ++i) j[names[i]] = values[i];
  return j;
}

// --diagnostics lines, written to stderr only when the command succeeds: bad input after the wave
// was read stays one line.
std::string pending_diagnostics;

// The wave of --wave, its value column (--column) and, with --diagnostics, the normalisation a
// user wave went through (model.md, user waveforms), for stderr so that stdout stays data.
WaveSpec read_wave(const Flags& f) {
  WaveReadOptions options = f.read;
  options.column_name = "--column";
  options.periods_name = "--periods";
  options.skip_rows_name = "--skip-rows";
  WaveSpec wave = parse_wave(need(f, f.wave, "wave"), options);
  const unsigned k = wave.periods_averaged;
  if (wave.period_from_stamps)  // a period the file did not state: always said
    pending_diagnostics += "vibrofric: note: " + detail::visible(wave.name) + " has no end point; its " +
                           std::to_string(wave.samples.size() * k) + " time stamps are uniform, so the samples sit at phi = j/N "
                           "and the period is N dt" + (k > 1 ? "/" + std::to_string(k) : std::string()) + " = " +
                           format_significant(wave.period_from_stamps->to<mpfr>(), 6) + "\n";
  if (f.diagnostics)
    for (const auto& [name, value] : describe_normalisation(wave, 17))
      pending_diagnostics += "normalisation: " + name + " = " + value + "\n";
  return wave;
}

// --certify (README, "Precision"): the exact value of a piecewise-linear wave's point and the proof
// that the printed value is its correct rounding. A printed value that is not would be a solver
// bug: an error, and the value is not printed.
std::optional<Certifier> certifier_of(const Flags& f, const WaveSpec& wave, const BatchOptions& opt) {
  if (!f.certify) return std::nullopt;
  if (f.no_escalate)
    throw InputError("--certify proves the guaranteed value, --no-escalate prints one that is not guaranteed: give one of them");
  try {
    return Certifier(wave, opt.profile);
  } catch (const InputError& e) {
    if (opt.profile.kind != ProfileKind::flat)
      throw InputError("--certify --profile " + detail::visible(f.profile_text.value_or("")) + ": " + e.what());
    throw InputError("--certify --wave " + detail::visible(f.wave.value_or("")) + ": " + e.what());
  }
}

Certificate certified(const Certifier& certifier, Quantity q, const Point& p, const Precision& precision,
                      const std::string& printed) {
  Certificate c = certifier(q, p, precision, printed);
  if (!c.correctly_rounded)
    throw SolverError("--certify: the printed " + printed + " is not the correct rounding of the exact value " + c.exact +
                      " (that is " + c.nearest.front() + "): a solver bug, please report it");
  return c;
}

// CSV and JSON fields of a certificate: the exact value, or an enclosure's ends.
std::vector<std::pair<std::string, std::string>> certificate_fields(const Certificate& c, bool enclosure) {
  if (enclosure) return {{"lower", c.lower_text}, {"upper", c.upper_text}, {"cite", c.cite}, {"correctly_rounded", "proven"}};
  return {{"exact", c.exact}, {"correctly_rounded", "proven"}};
}

}  // namespace vibrofric::tool
