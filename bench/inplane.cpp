// In-plane and combined oscillation (model.md, "In-plane and combined oscillation"; api/inplane.hpp):
// the cost of one point in guaranteed double against the flat punch's normal-only point at the
// same β and γ, side by side in one run (issue 61's targets: longitudinal within 5×, transverse
// within 20×):
//   inplane/<case>/normal_only_double   evaluate(…, float64): `vibrofric mu … --type double` (the
//                                       ratchet's β = 0 has no normal-only point: β = 0.3 there)
//   inplane/<case>/guaranteed_double    evaluate_inplane(…, float64): the same with the in-plane flags
//                                       (the report: μ̄, the fractions' 17 digits, the free velocity)
//   inplane/<case>/value_double         evaluate(…, float64) with options.inplane: μ̄ alone, correctly
//                                       rounded (`sweep … --type double`, Python's arrays)
// <case>: longitudinal (sine, β = 0.3, γ = −0.3, a_l = 1: full slip, μ̄ = 1), combined (sine,
// β = 0.3, γ = 0.5, a_l = 0.7, P = 0.1: stick and slip), ratchet (sine, β = 0, γ = 0.5, a_l = 1,
// P = 1/4), transverse (sine, β = 0.3, γ = −0.3, a_t = 1; the planar solver in mpfr, seconds a
// point: one iteration).
#include <string>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/inplane.hpp"

namespace vibrofric::bench {
namespace {

struct InPlaneCase {
  const char *name, *beta, *gamma, *longitudinal, *transverse, *phase;
};
const std::vector<InPlaneCase>& inplane_cases() {
  static const std::vector<InPlaneCase> c{
      {"longitudinal", "0.3", "-0.3", "1", "0", "0"},
      {"combined", "0.3", "0.5", "0.7", "0", "0.1"},
      {"ratchet", "0", "0.5", "1", "0", "0.25"},
      {"transverse", "0.3", "-0.3", "0", "1", "0"},
  };
  return c;
}

Precision float64() {
  Precision p;
  p.type = NumberType::float64;
  return p;
}

void BM_normal_only(benchmark::State& state, const InPlaneCase& c) {
  const WaveSpec wave = parse_wave("sine");
  const Point point{std::string(c.beta) == "0" ? "0.3" : c.beta, c.gamma};
  for (auto _ : state) benchmark::DoNotOptimize(evaluate(wave, Quantity::mu, {point}, float64()).front().data());
  state.SetItemsProcessed(state.iterations());
}

InPlaneSpec spec_of(const InPlaneCase& c) {
  InPlaneSpec spec;
  spec.longitudinal = InputValue::read(c.longitudinal, "longitudinal");
  spec.transverse = InputValue::read(c.transverse, "transverse");
  spec.phase = InputValue::read(c.phase, "phase");
  return spec;
}

void BM_inplane(benchmark::State& state, const InPlaneCase& c) {
  const WaveSpec wave = parse_wave("sine");
  const Point point{c.beta, c.gamma};
  for (auto _ : state) benchmark::DoNotOptimize(evaluate_inplane(wave, point, spec_of(c), float64()).mu.data());
  state.SetItemsProcessed(state.iterations());
}

void BM_inplane_value(benchmark::State& state, const InPlaneCase& c) {
  const WaveSpec wave = parse_wave("sine");
  const Point point{c.beta, c.gamma};
  BatchOptions options;
  options.inplane = spec_of(c);
  for (auto _ : state) benchmark::DoNotOptimize(evaluate(wave, Quantity::mu, {point}, float64(), options).front().data());
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

void register_inplane() {
  for (const InPlaneCase& c : inplane_cases()) {
    const bool slow = std::string(c.name) == "transverse";
    // --quick (CI): the longitudinal case only.
    if (config().quick && std::string(c.name) != "longitudinal") continue;
    const std::string prefix = std::string("inplane/") + c.name + "/";
    auto* normal = benchmark::RegisterBenchmark((prefix + "normal_only_double").c_str(), BM_normal_only, c);
    auto* inplane = benchmark::RegisterBenchmark((prefix + "guaranteed_double").c_str(), BM_inplane, c);
    auto* value = benchmark::RegisterBenchmark((prefix + "value_double").c_str(), BM_inplane_value, c);
    for (auto* b : {normal, inplane, value}) {
      b->Unit(benchmark::kMicrosecond);
      if (config().quick) {
        b->Iterations(1)->Repetitions(1);
      } else if (slow && b != normal) {
        b->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true);
      } else {
        b->MinTime(0.3)->Repetitions(3)->ReportAggregatesOnly(true);
      }
    }
  }
}

}  // namespace vibrofric::bench
