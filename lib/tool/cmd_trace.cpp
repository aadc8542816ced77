// trace: n(phi) and s(phi) over one period (Fig. 2), or with --kappa/--omega the rig's lag and mode.
#include <iostream>

#include "cli.hpp"
#include "vibrofric/api/commands.hpp"

namespace vibrofric::tool {

// s(φ) and n(φ) over one period (the paper's Fig. 2): N equally spaced phases plus both ends of
// every stick phase, so that a plot shows the kinks where they are.
int run_trace(const Flags& f) {
  const WaveSpec wave = read_wave(f);
  TraceRequest request;
  request.beta = {need(f, f.beta, "beta"), "--beta"};
  request.gamma = {need(f, f.gamma, "gamma"), "--gamma"};
  request.points_name = "--points";
  request.digits_name = "--digits";
  if (f.digits) request.digits = *f.digits;
  if (f.points) request.points = *f.points;
  request.profile = f.profile;
  const BatchOptions o = batch_options(f);
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
