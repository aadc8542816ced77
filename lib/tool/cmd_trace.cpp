// trace: n(phi) and s(phi) over one period (Fig. 2), with --kappa/--omega the rig's lag and mode
// (with --profile the row's shares in each mode), or with --longitudinal the in-plane force's
// components and the mode.
#include <iostream>
#include <optional>

#include "cli.hpp"
#include "vibrofric/api/commands.hpp"

namespace vibrofric::tool {

// s(φ) and n(φ) over one period (the paper's Fig. 2): N equally spaced phases plus both ends of
// every stick phase, so that a plot shows the kinks where they are.
int run_trace(const Flags& f) {
  const std::optional<InPlaneSpec> inplane = inplane_options(f);
  const WaveSpec wave = normal_wave(f, inplane);
  TraceRequest request;
  request.beta = {need(f, f.beta, "beta"), "--beta"};
  if (inplane && inplane->constant_normal) {
    if (f.gamma.given())
      throw InputError("--gamma " + detail::visible(f.gamma.text()) + " with --wave constant: the normal force is constant (give no --gamma)");
  } else {
    request.gamma = {need(f, f.gamma, "gamma"), "--gamma"};
  }
  request.points_name = "--points";
  request.digits_name = "--digits";
  if (f.digits) request.digits = *f.digits;
  if (f.points) request.points = *f.points;
  request.profile = f.profile;
  const BatchOptions o = batch_options(f);
  if (inplane) {
    if (f.profile.kind != ProfileKind::flat)
      throw InputError("trace with --profile " + detail::visible(f.profile_text.value_or("")) +
                       " and an in-plane oscillation: the rows are the flat punch's only (mu and sweep take the curved row)");
    const auto rows = inplane_trace_rows(wave, request, *inplane, o.solver);
    std::cout << "phi,n,s_x,s_y,mode\n";
    const int d = request.digits;
    for (const auto& r : rows)
      std::cout << format_significant(r.phi, d) << ',' << format_significant(r.n, d) << ',' << format_significant(r.s_x, d)
                << ',' << format_significant(r.s_y, d) << ',' << inplane_mode_name(r.mode) << '\n';
    return 0;
  }
  if (o.rig && f.profile.kind != ProfileKind::flat) {
    const auto rows = rig_row_trace_rows(wave, request, *o.rig, o.solver);
    std::cout << "phi,n,s,lag,lag_rate,stick,slip,backward,flight\n";
    for (const auto& r : rows)
      std::cout << format_significant(r.phi, request.digits) << ',' << r.n.text() << ',' << r.s.text() << ','
                << r.lag.text() << ',' << r.lag_rate.text() << ',' << r.stick.text() << ',' << r.slip.text() << ','
                << r.backward.text() << ',' << r.flight.text() << '\n';
    return 0;
  }
  if (o.rig) {
    const auto rows = rig_trace_rows(wave, request, *o.rig, o.solver);
    std::cout << "phi,n,s,lag,lag_rate,mode\n";
    const int d = request.digits;
    for (const auto& r : rows)
      std::cout << format_significant(r.phi, d) << ',' << format_significant(r.n, d) << ',' << format_significant(r.s, d) << ','
                << format_significant(r.lag, d) << ',' << format_significant(r.lag_rate, d) << ',' << rig_mode_name(r.mode) << '\n';
    return 0;
  }
  const auto rows = trace_rows(wave, request);
  std::cout << "phi,n,s\n";
  const int d = request.digits;
  for (const auto& r : rows)
    std::cout << format_significant(r.phi, d) << ',' << format_significant(r.n, d) << ',' << format_significant(r.s, d) << '\n';
  return 0;
}

}  // namespace vibrofric::tool
