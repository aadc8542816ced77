// mu and psi: one point, in text, CSV or JSON, with --certify's proof or, with --kappa/--omega,
// the rig dynamics' fractions and sizes.
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"

namespace vibrofric::tool {
namespace {

std::string rounding_name(const Precision& p) {
  return p.type == NumberType::mpfr ? "to " + std::to_string(p.digits) + " significant digits"
                                    : "to the nearest " + number_type_name(p.type);
}

// One point's record as CSV (a header and a row) or JSON (an object); status 0.
int write_record(const std::vector<std::string>& names, const std::vector<std::string>& values, Format format) {
  if (format == Format::csv) {
    write_csv_row(names);
    write_csv_row(values);
  } else {
    std::cout << json_record(names, values).dump(1) << '\n';
  }
  return 0;
}

// mu with --kappa/--omega: the value, then the periodic state's fractions and sizes.
int print_rig(const WaveSpec& wave, const Point& p, const BatchOptions& opt, const Precision& precision, Format format,
              bool certify) {
  const auto certificate = [&](const std::string& printed) {
    try {
      return certify_rig(wave, p, *opt.rig, precision, printed, opt.profile, opt.solver);
    } catch (const InputError& e) {
      throw InputError(std::string("--certify: ") + e.what());
    }
  };
  // --certify's refusal of a wave without a proven rig state, before the solve
  if (certify) {
    try {
      rig_wave_input(wave);
    } catch (const InputError& e) {
      throw InputError(std::string("--certify: ") + e.what());
    }
  }
  const RigReport r = evaluate_rig(wave, p, *opt.rig, precision, opt.solver, opt.profile);
  std::optional<RigCertificate> cert;
  if (certify) {
    cert = certificate(r.mu);
    if (!cert->mu.correctly_rounded)
      throw SolverError("--certify: the printed " + r.mu + " is not the correct rounding of the rig's proven value (that is " +
                        cert->mu.nearest.front() + "): a solver bug, please report it");
  }
  char floquet[32];
  std::snprintf(floquet, sizeof floquet, "%.6g", r.floquet);
  const std::vector<std::pair<std::string, std::string>> fields{
      {"stick_fraction", r.stick_fraction.text()}, {"slip_fraction", r.slip_fraction.text()},
      {"backward_slip_fraction", r.backward_fraction.text()}, {"flight_fraction", r.flight_fraction.text()},
      {"amplitude", r.amplitude.text()}, {"largest_backward_slip", r.largest_backward_slip.text()},
      {"floquet_multiplier", floquet}, {"relative_error_estimate", r.relative_error.text()},
      {"quasi_static_mu_over_mu0", r.quasi_static_mu}};
  // a curved contact: its profile, and the row's springs (mu has the digits two sizes agree on)
  std::vector<std::pair<std::string, std::string>> row;
  if (opt.profile.kind != ProfileKind::flat) row = {{"profile", opt.profile.name}, {"springs", std::to_string(r.springs)}};
  if (!r.resonance_note.empty()) pending_diagnostics += "vibrofric: warning: " + r.resonance_note + "\n";
  // --certify: the proof's fields (the enclosure of mu and of the fractions, the state's box, stability)
  std::vector<std::pair<std::string, std::string>> proof;
  if (cert) {
    proof = {{"lower", cert->mu.lower_text}, {"upper", cert->mu.upper_text}, {"cite", cert->mu.cite},
             {"correctly_rounded", "proven"}};
    for (auto& field : rig_certificate_fields(*cert)) proof.push_back(std::move(field));
  }
  if (format == Format::text) {
    std::cout << r.mu << '\n';
    for (const auto& [name, value] : fields) std::cout << name << ": " << value << '\n';
    for (const auto& [name, value] : row) std::cout << name << ": " << value << '\n';
    for (const auto& [name, value] : proof) std::cout << name << ": " << value << '\n';
    return 0;
  }
  std::vector<std::string> names{"wave", "beta", "gamma", "kappa", "omega", "zeta", "mu_over_mu0"};
  std::vector<std::string> values{wave.name,         p.beta.text(),      p.gamma.text(), opt.rig->kappa.text(),
                                  opt.rig->omega.text(), opt.rig->zeta.text(), r.mu};
  for (const auto& [name, value] : fields) {
    names.push_back(name);
    values.push_back(value);
  }
  for (const auto& [name, value] : row) {
    names.push_back(name);
    values.push_back(value);
  }
  for (const auto& [name, value] : proof) {
    names.push_back(name);
    values.push_back(value);
  }
  return write_record(names, values, format);
}

// mu with --longitudinal (or --wave constant): the value, then the periodic state's fractions.
int print_inplane(const Flags& f, const InPlaneSpec& spec, const Precision& precision, Format format) {
  const WaveSpec wave = normal_wave(f, spec);
  if (spec.constant_normal && f.gamma.given())
    throw InputError("--gamma " + detail::visible(f.gamma.text()) + " with --wave constant: the normal force is constant (give no --gamma)");
  const Point p{need(f, f.beta, "beta"), spec.constant_normal ? InputValue() : need(f, f.gamma, "gamma")};
  // --certify's refusals before the value is computed (a transverse value costs seconds).
  const auto certify_error = [](const InputError& e) { return InputError(std::string("--certify: ") + e.what()); };
  if (f.certify) {
    try {
      check_certifiable(wave, spec);
    } catch (const InputError& e) {
      throw certify_error(e);
    }
  }
  const InPlaneReport r = evaluate_inplane(wave, p, spec, precision, f.solver, f.profile, f.free_velocity);
  // A transverse drive slips in every direction: backward slip is the longitudinal drive's alone.
  std::vector<std::pair<std::string, std::string>> fields{
      {"mean_lateral", r.mean_lateral.text()},     {"stick_fraction", r.stick_fraction.text()},
      {"slip_fraction", r.slip_fraction.text()},   {"backward_slip_fraction", r.backward_fraction.text()},
      {"flight_fraction", r.flight_fraction.text()}, {"relative_error_estimate", r.relative_error.text()}};
  if (r.planar) fields.erase(fields.begin() + 3);
  // A curved contact's springs each have their own fractions: the row reports none.
  if (r.curved) fields.erase(fields.begin() + 1, fields.end() - 1);
  // Combined normal and longitudinal oscillation: the ratchet's free velocity, or none.
  if (r.free_velocity_searched) fields.emplace_back("free_velocity", r.free_velocity ? r.free_velocity->text() : "none");
  // --certify: the exact rationals of the longitudinal drive, and the proof of the printed value.
  std::optional<InPlaneCertificate> cert;
  if (f.certify) {
    try {
      cert = certify_inplane(wave, p, spec, precision, r.mu);
    } catch (const InputError& e) {
      throw certify_error(e);
    }
    if (!cert->mu.correctly_rounded)
      throw SolverError("--certify: the printed " + r.mu + " is not the correct rounding of the exact value " + cert->mu.exact +
                        " (that is " + cert->mu.nearest.front() + "): a solver bug, please report it");
    fields.insert(fields.end(), {{"exact", cert->mu.exact},
                                 {"exact_stick_fraction", cert->stick_fraction},
                                 {"exact_slip_fraction", cert->slip_fraction},
                                 {"exact_backward_slip_fraction", cert->backward_fraction},
                                 {"exact_flight_fraction", cert->flight_fraction}});
  }
  if (format == Format::text) {
    std::cout << r.mu << '\n';
    for (const auto& [name, value] : fields) std::cout << name << ": " << value << '\n';
    if (cert) std::cout << "proven: " << r.mu << " is the exact value rounded " << rounding_name(precision) << '\n';
    return 0;
  }
  if (cert) fields.emplace_back("correctly_rounded", "proven");
  std::vector<std::string> names{"wave",  "beta",          "gamma", "longitudinal", "transverse",
                                 "phase", "in_plane_wave", "mu_over_mu0"};
  std::vector<std::string> values{wave.name,
                                  p.beta.text(),
                                  spec.constant_normal ? std::string() : p.gamma.text(),
                                  spec.longitudinal.text(),
                                  spec.transverse.text(),
                                  spec.phase.text(),
                                  spec.wave.name,
                                  r.mu};
  for (const auto& [name, value] : fields) {
    names.push_back(name);
    values.push_back(value);
  }
  return write_record(names, values, format);
}

int run_point(const Flags& f, Quantity q) {
  if (const auto spec = inplane_options(f)) {
    if (q == Quantity::psi)
      throw InputError("--longitudinal does not apply to psi: Psi (Eq. 12) belongs to the normal oscillation alone (use mu)");
    return print_inplane(f, *spec, precision_of(f), f.format.value_or(Format::text));
  }
  if (f.free_velocity)
    throw InputError("--free-velocity without --longitudinal: the free velocity is the ratchet's, of normal and "
                     "longitudinal oscillation together");
  const WaveSpec wave = read_wave(f);
  const Point p{need(f, f.beta, "beta"), q == Quantity::mu ? need(f, f.gamma, "gamma") : InputValue()};
  const BatchOptions opt = batch_options(f);
  if (q == Quantity::psi && opt.profile.kind != ProfileKind::flat)
    throw InputError("psi --profile " + detail::visible(*f.profile_text) +
                     ": Psi (Eq. 12) exists for the flat punch only; in a curved contact the outer springs always jump, "
                     "so Eq. 13's separation does not exist (use mu)");
  const Format format = f.format.value_or(Format::text);
  const Precision precision = precision_of(f);
  if (opt.rig) return print_rig(wave, p, opt, precision, format, f.certify);
  const std::optional<Certifier> certifier = certifier_of(f, wave, opt);
  const std::string value = evaluate(wave, q, {p}, precision, opt).front();
  std::optional<Certificate> cert;
  if (certifier) cert = certified(*certifier, q, p, precision, value);
  if (format == Format::text) {
    std::cout << value << '\n';
    if (cert)
      std::cout << (cert->exact.empty() ? "enclosure: [" + cert->lower_text + ", " + cert->upper_text + "]" : "exact: " + cert->exact)
                << (cert->cite.empty() ? std::string()
                                       : "\ncite: " + cert->cite + " (the exact value to " + std::to_string(cert->cite_digits) +
                                             " digits, correctly rounded: the whole enclosure rounds to it)")
                << "\nproven: " << value << " is the exact value rounded " << rounding_name(precision)
                << (cert->nearest.size() > 1 ? " (a tie: it lies midway between " + cert->nearest[0] + " and " + cert->nearest[1] + ")" : "")
                << '\n';
    return 0;
  }
  std::vector<std::string> names{"wave"}, values{wave.name};
  if (opt.profile.kind != ProfileKind::flat) {
    names.push_back("profile");
    values.push_back(opt.profile.name);
  }
  names.push_back("beta");
  values.push_back(p.beta.text());
  if (q == Quantity::mu) {
    names.push_back("gamma");
    values.push_back(p.gamma.text());
  }
  names.push_back(q == Quantity::mu ? "mu_over_mu0" : "psi");
  values.push_back(value);
  if (cert) {
    for (const auto& [name, v] : certificate_fields(*cert, cert->exact.empty())) {
      names.push_back(name);
      values.push_back(v);
    }
  }
  return write_record(names, values, format);
}

}  // namespace

int run_mu(const Flags& f) { return run_point(f, Quantity::mu); }
int run_psi(const Flags& f) { return run_point(f, Quantity::psi); }

}  // namespace vibrofric::tool
