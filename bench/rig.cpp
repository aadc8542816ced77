// Rig dynamics (model.md, "Rig dynamics: mass and system stiffness"; core/dynamics/dynamics.hpp): the cost
// of one periodic state, in every way the library offers:
//   rig/<case>/solver_double         solve_rig<double>, raw (the value as computed)
//   rig/<case>/solver_mpfr_50        solve_rig<mpfr> at 50 + guard digits, from its two starts
//   rig/<case>/guaranteed_double     evaluate_rig(…, float64): `vibrofric mu … --kappa K --omega W
//                                    --zeta Z --type double` (two mpfr precisions, the second seeded)
//   rig/<case>/guaranteed_mpfr_30    evaluate_rig(…, mpfr, 30): the same with `--digits 30`
//   rig/<case>/guaranteed_mpfr_20    evaluate_rig(…, mpfr, 20): `--digits 20`
//   rig/<case>/certified_mpfr_20     evaluate_rig and certify_rig at 20 digits: `--digits 20 --certify`,
//                                    the proven state (core/certified/rig_enclosure.hpp), beside the above
// <case>: sine_omega2 (β = 0.5, γ = 0.3, κ = 1, Ω = 2, ζ = 0.1: a few events a period),
// triangle_omega1000 (β = 2, γ = −0.4, κ = 3, Ω = 1000, ζ = 0.1: the body rings a thousand times a
// period), square_omega1e4 (β = 1.2, γ = 1.25, κ = 0.6, Ω = 1e4, ζ = 0.05: the drop rings it ten
// thousand times), resonance_beta1000 (sine, β = 1000, γ = 0.5, κ = Ω = 1, ζ = 0: the exact undamped
// resonance far above β_c, the state 70 periods from the starts). Counter rel_error: against
// solve_rig<mpfr> at 60 digits.
#include <cmath>
#include <map>

#include "common.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/ladder.hpp"
#include "vibrofric/api/rig.hpp"
#include "vibrofric/core/dynamics/dynamics.hpp"

namespace vibrofric::bench {
namespace {

struct RigCase {
  const char *name, *wave, *beta, *gamma, *kappa, *omega, *zeta;
  unsigned resonant;  // Ω²κ = k² exactly (RigParameters::resonant_harmonic)
};
const std::vector<RigCase>& rig_cases() {
  static const std::vector<RigCase> c{
      {"sine_omega2", "sine", "0.5", "0.3", "1", "2", "0.1", 0},
      {"triangle_omega1000", "triangle", "2", "-0.4", "3", "1000", "0.1", 0},
      {"square_omega1e4", "square", "1.2", "1.25", "0.6", "10000", "0.05", 0},
      {"resonance_beta1000", "sine", "1000", "0.5", "1", "1", "0", 1},
  };
  return c;
}

template <class Real>
RigParameters<Real> parameters(const RigCase& c) {
  return {Real(c.kappa), Real(c.omega), Real(c.zeta), c.resonant};
}
template <>
RigParameters<double> parameters<double>(const RigCase& c) {
  return {std::strtod(c.kappa, nullptr), std::strtod(c.omega, nullptr), std::strtod(c.zeta, nullptr), c.resonant};
}

// μ̄ at 60 digits (the same algorithm at much higher precision), once per case.
double reference(const RigCase& c) {
  static std::map<std::string, double> cache;
  auto it = cache.find(c.name);
  if (it != cache.end()) return it->second;
  PrecisionScope scope(60);
  const auto w = make_waveform<mpfr>(parse_wave(c.wave));
  const double mu = static_cast<double>(solve_rig<mpfr>(*w, mpfr(c.beta), mpfr(c.gamma), parameters<mpfr>(c)).mu);
  return cache[c.name] = mu;
}

double rel_error(double got, double want) { return std::fabs(got - want) / std::fabs(want); }

void BM_rig_double(benchmark::State& state, const RigCase& c) {
  const auto w = make_waveform<double>(parse_wave(c.wave));
  const double beta = std::strtod(c.beta, nullptr), gamma = std::strtod(c.gamma, nullptr);
  double mu = 0;
  for (auto _ : state) {
    const auto r = solve_rig<double>(*w, beta, gamma, parameters<double>(c));
    benchmark::DoNotOptimize(r.mu);
    mu = r.mu;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["rel_error"] = rel_error(mu, reference(c));
}

void BM_rig_mpfr(benchmark::State& state, const RigCase& c, int digits) {
  PrecisionScope scope(static_cast<unsigned>(digits + guard_digits(digits)));
  const auto w = make_waveform<mpfr>(parse_wave(c.wave));
  const mpfr beta(c.beta), gamma(c.gamma);
  double mu = 0;
  for (auto _ : state) {
    const auto r = solve_rig<mpfr>(*w, beta, gamma, parameters<mpfr>(c));
    benchmark::DoNotOptimize(r.mu);
    mu = static_cast<double>(r.mu);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["rel_error"] = rel_error(mu, reference(c));
  state.counters["digits"] = digits;
}

RigSpec rig_spec(const RigCase& c) {
  RigSpec rig;
  rig.kappa = InputValue::read(c.kappa, "kappa");
  rig.omega = InputValue::read(c.omega, "omega");
  rig.zeta = InputValue::read(c.zeta, "zeta");
  return rig;
}

// digits = 0: float64.
void BM_rig_guaranteed(benchmark::State& state, const RigCase& c, int digits) {
  const WaveSpec spec = parse_wave(c.wave);
  const Point point{c.beta, c.gamma};
  const RigSpec rig = rig_spec(c);
  Precision precision;
  precision.type = digits ? NumberType::mpfr : NumberType::float64;
  if (digits) precision.digits = digits;
  double mu = 0;
  for (auto _ : state) {
    const RigReport r = evaluate_rig(spec, point, rig, precision);
    benchmark::DoNotOptimize(r.mu.data());
    mu = std::strtod(r.mu.c_str(), nullptr);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["rel_error"] = rel_error(mu, reference(c));
  if (digits) state.counters["digits"] = digits;
}

// `mu … --digits 20 --certify`: the value, then its proof (the state from a solve near the proof's
// precision, Krawczyk, the enclosures).
void BM_rig_certified(benchmark::State& state, const RigCase& c) {
  const WaveSpec spec = parse_wave(c.wave);
  const Point point{c.beta, c.gamma};
  const RigSpec rig = rig_spec(c);
  Precision precision;
  precision.type = NumberType::mpfr;
  precision.digits = 20;
  double mu = 0;
  for (auto _ : state) {
    const RigReport r = evaluate_rig(spec, point, rig, precision);
    const RigCertificate cert = certify_rig(spec, point, rig, precision, r.mu);
    if (!cert.mu.correctly_rounded) state.SkipWithError("not proven the correct rounding");
    benchmark::DoNotOptimize(cert.mu.upper);
    mu = std::strtod(r.mu.c_str(), nullptr);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["rel_error"] = rel_error(mu, reference(c));
  state.counters["digits"] = 20;
}

benchmark::internal::Benchmark* rig_settings(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond);
  if (config().quick) return b->Iterations(1)->Repetitions(1);
  return b->MinTime(0.5)->Repetitions(3)->ReportAggregatesOnly(true);
}

}  // namespace

void register_rig() {
  for (const RigCase& c : rig_cases()) {
    // --quick (CI): one case, the raw double and the tool's double path.
    if (config().quick && std::string(c.name) != "sine_omega2") continue;
    const std::string prefix = std::string("rig/") + c.name + "/";
    rig_settings(benchmark::RegisterBenchmark((prefix + "solver_double").c_str(), BM_rig_double, c));
    rig_settings(benchmark::RegisterBenchmark((prefix + "guaranteed_double").c_str(), BM_rig_guaranteed, c, 0));
    if (config().quick) continue;
    rig_settings(benchmark::RegisterBenchmark((prefix + "solver_mpfr_50").c_str(), BM_rig_mpfr, c, 50));
    rig_settings(benchmark::RegisterBenchmark((prefix + "guaranteed_mpfr_30").c_str(), BM_rig_guaranteed, c, 30));
    rig_settings(benchmark::RegisterBenchmark((prefix + "guaranteed_mpfr_20").c_str(), BM_rig_guaranteed, c, 20));
    rig_settings(benchmark::RegisterBenchmark((prefix + "certified_mpfr_20").c_str(), BM_rig_certified, c));
  }
}

}  // namespace vibrofric::bench
