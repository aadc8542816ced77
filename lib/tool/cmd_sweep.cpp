// sweep: mu/mu0 or Psi over ranges of beta and gamma, rows streamed in order as CSV or JSON, with a
// progress line on a terminal.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "cli.hpp"

namespace vibrofric::tool {

int run_sweep(const Flags& f) {
  const std::optional<InPlaneSpec> inplane = inplane_options(f);
  const WaveSpec wave = normal_wave(f, inplane);
  if (f.betas.empty()) throw InputError("missing --beta for 'sweep'");
  // --quantity psi: Ψ_w(β) (Eq. 12), which has no γ; nor has a constant normal force.
  const Quantity q = f.quantity;
  const bool constant = inplane && inplane->constant_normal;
  if (inplane && q == Quantity::psi)
    throw InputError("--longitudinal does not apply to --quantity psi: Psi (Eq. 12) belongs to the normal oscillation alone");
  std::vector<InputValue> gammas;
  if (constant) {
    if (!f.gammas.empty()) throw InputError("--gamma with --wave constant: the normal force is constant (give no --gamma)");
    gammas.emplace_back();
  } else if (q == Quantity::psi) {
    if (!f.gammas.empty()) throw InputError("--gamma does not apply to --quantity psi: Psi_w(beta) has no gamma (Eq. 12)");
    gammas.emplace_back();
  } else {
    if (f.gammas.empty()) throw InputError("missing --gamma for 'sweep'");
    gammas = f.gammas;
  }
  const std::vector<InputValue>& betas = f.betas;
  const Precision prec = precision_of(f);
  const Format format = f.format.value_or(Format::csv);
  // Points made on demand, γ-major as the rows (a 3000 × 3000 map holds no vector of points).
  const std::size_t count = betas.size() * gammas.size();
  const auto point = [&](std::size_t i) { return Point{betas[i % betas.size()], gammas[i / betas.size()]}; };
  BatchOptions opt = batch_options(f);
  opt.threads = f.threads;
  // The progress line on a terminal: at most ten redraws a second, never backwards (workers report
  // out of order), with the percentage and the remaining time; the callback costs an atomic load
  // and a clock read per point between redraws.
  std::mutex m;
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  std::atomic<long long> next_draw_ns{0};
  std::size_t shown = 0;
  if (isatty(2))
    opt.progress = [&](std::size_t done) {
      const long long now = std::chrono::duration_cast<std::chrono::nanoseconds>(clock::now() - start).count();
      const bool last = done == count;
      if (!last && now < next_draw_ns.load(std::memory_order_relaxed)) return;
      std::lock_guard<std::mutex> lock(m);
      if (done <= shown || (!last && now < next_draw_ns.load(std::memory_order_relaxed))) return;
      next_draw_ns.store(now + 100'000'000, std::memory_order_relaxed);
      shown = done;
      const double seconds = static_cast<double>(now) / 1e9;
      const double left = seconds * static_cast<double>(count - done) / static_cast<double>(done);
      std::fprintf(stderr, "\rsweep: %zu/%zu (%.1f %%), %.0f s left   ", done, count,
                   100.0 * static_cast<double>(done) / static_cast<double>(count), left);
      if (last) std::fprintf(stderr, "\n");
    };
  const bool curved = opt.profile.kind != ProfileKind::flat;
  std::vector<std::string> names{"wave"};
  if (curved) names.push_back("profile");
  names.push_back("beta");
  if (q == Quantity::mu && !constant) names.push_back("gamma");
  if (opt.rig) names.insert(names.end(), {"kappa", "omega", "zeta"});
  if (inplane) names.insert(names.end(), {"longitudinal", "transverse", "phase", "in_plane_wave"});
  names.push_back(q == Quantity::mu ? "mu_over_mu0" : "psi");
  const std::optional<Certifier> certifier = certifier_of(f, wave, opt);
  if (certifier)
    for (const auto& field : certificate_fields(Certificate{}, certifier->encloses())) names.push_back(field.first);
  // Rows in their deterministic order as they complete; memory bounded whatever the count. The
  // domain (β ≥ 0 and representable, contact at the smallest γ, a profile's extent at the largest)
  // is monotone in β and γ, so the four corners decide it before any row is written.
  if (count > 0) {
    auto extreme = [](const std::vector<InputValue>& v, bool largest) {
      std::size_t k = 0;
      for (std::size_t i = 1; i < v.size(); ++i)
        if (compare(*v[i].decimal(), *v[k].decimal()) == (largest ? 1 : -1)) k = i;
      return v[k];
    };
    std::vector<Point> corners;
    for (bool big_beta : {false, true})
      for (bool big_gamma : {false, true})
        corners.push_back({extreme(betas, big_beta), q == Quantity::mu && !constant ? extreme(gammas, big_gamma) : InputValue()});
    BatchOptions quiet = opt;
    quiet.progress = nullptr;
    evaluate(wave, q, corners, prec, quiet);
  }
  if (format == Format::json)
    std::cout << "[";
  else
    write_csv_row(names);
  evaluate_stream(wave, q, count, point, prec, opt, [&](std::size_t i, const StreamValue& value) {
    const Point pt = point(i);
    std::vector<std::string> r{wave.name};
    if (curved) r.push_back(opt.profile.name);
    r.push_back(pt.beta.text());
    if (q == Quantity::mu && !constant) r.push_back(pt.gamma.text());
    if (opt.rig) r.insert(r.end(), {opt.rig->kappa.text(), opt.rig->omega.text(), opt.rig->zeta.text()});
    if (inplane)
      r.insert(r.end(), {inplane->longitudinal.text(), inplane->transverse.text(), inplane->phase.text(),
                         inplane->wave.name});
    r.push_back(value.text);
    if (certifier)
      for (const auto& field : certificate_fields(certified(*certifier, q, pt, prec, value.text), certifier->encloses()))
        r.push_back(field.second);
    if (format == Format::json)
      std::cout << (i ? ",\n " : "\n ") << json_record(names, r).dump();
    else
      write_csv_row(r);
  });
  if (format == Format::json) std::cout << (count ? "\n]\n" : "]\n");
  return 0;
}

}  // namespace vibrofric::tool
