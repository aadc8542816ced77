// Speed of certified values (api/certify.hpp, issue targets: a certified double within 10× the
// guaranteed double, a certified 50-digit sine within 4× the uncertified one), measured beside
// the paths they certify, on the same inputs in the same run:
//   speed/<wave>/certified_double     evaluate(…, float64) of one point and its certificate
//   speed/<wave>/certified_mpfr_50    the same at 50 digits
//   speed/<wave>/uncertified_double   evaluate(…, float64) of the point alone (the same call, so the
//   speed/<wave>/uncertified_mpfr_50  ratio is the certificate's cost; the solver-level
//                                     guaranteed_* entries of speed_*.cpp leave out evaluate()'s
//                                     decimal input and output)
// for an enclosed wave (sine, power:3: MPFI), an exact one (triangle: GMP rationals) and a
// Fourier series of three harmonics (its shape, built once per precision, outside the loop after
// the first point). The sine on a sphere (core/certified/curved_enclosure.hpp; issue target: a
// certified point at 25 digits within 5× the uncertified one), on six points across the ranges
// of the row's top:
//   curved/sphere/certified_mpfr_25, curved/sphere/uncertified_mpfr_25
#include "common.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/evaluate.hpp"

namespace vibrofric::bench {
namespace {

WaveSpec certified_wave(const std::string& wave) {
  if (wave != "fourier:three") return parse_wave(wave);
  WaveSpec f;
  f.kind = WaveKind::fourier;
  f.name = wave;
  const auto d = [](const char* t) { return *Decimal::read(t); };
  f.harmonics = {{1, d("0"), d("1")}, {2, d("0.1"), d("-0.05")}, {3, d("0"), d("0.333")}};
  return f;
}

// One point per iteration, cycling through `in`: evaluate(), then its certificate where a
// certifier is given (a value not proven correctly rounded stops the benchmark).
void cycle(benchmark::State& state, const WaveSpec& spec, const Certifier* certifier,
           const std::vector<std::vector<Point>>& in, const Precision& precision, const BatchOptions& options) {
  std::size_t i = 0;
  for (auto _ : state) {
    const auto out = evaluate(spec, Quantity::mu, in[i], precision, options);
    if (certifier && !(*certifier)(Quantity::mu, in[i].front(), precision, out.front()).correctly_rounded)
      state.SkipWithError("a value not proven correctly rounded");
    benchmark::DoNotOptimize(out.data());
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

// One point per iteration, cycling through speed_inputs(): evaluate() in double (digits 0) or
// at `digits`, then its certificate (certify) or nothing (the uncertified side).
void BM_point(benchmark::State& state, const std::string& wave, int digits, bool certify) {
  const WaveSpec spec = certified_wave(wave);
  const Certifier certifier(spec, ProfileSpec{});
  std::vector<std::vector<Point>> in;
  for (const Input& p : speed_inputs()) in.push_back({Point{shortest_decimal(p.beta), shortest_decimal(p.gamma)}});
  const Precision precision{digits ? NumberType::mpfr : NumberType::float64, digits};
  BatchOptions options;
  options.threads = 1;
  cycle(state, spec, certify ? &certifier : nullptr, in, precision, options);
}

// The sphere: β ∈ {0.5, 2}, γ ∈ {−0.5, 0.5, 2} (a stick from touch-down at the centre, one from
// n' = β, no jumping there), cycled as above.
void BM_curved(benchmark::State& state, bool certify) {
  const WaveSpec spec = parse_wave("sine");
  const ProfileSpec sphere = parse_profile("sphere");
  const Certifier certifier(spec, sphere);
  std::vector<std::vector<Point>> in;
  for (const char* b : {"0.5", "2"})
    for (const char* g : {"-0.5", "0.5", "2"}) in.push_back({Point{*Decimal::read(b), *Decimal::read(g)}});
  const Precision precision{NumberType::mpfr, 25};
  BatchOptions options;
  options.threads = 1;
  options.profile = sphere;
  cycle(state, spec, certify ? &certifier : nullptr, in, precision, options);
}

}  // namespace

void register_certify() {
  for (const bool certify : {true, false}) {
    const std::string name = std::string("curved/sphere/") + (certify ? "certified" : "uncertified") + "_mpfr_25";
    // a certified point takes a tenth of a second: a fixed count, each of the six points twice
    auto* b = benchmark::RegisterBenchmark(name.c_str(), BM_curved, certify);
    if (config().quick) b->Iterations(1)->Repetitions(1)->Unit(benchmark::kMillisecond);
    else b->Iterations(12)->Repetitions(3)->ReportAggregatesOnly(true)->Unit(benchmark::kMillisecond);
  }
  for (const std::string wave : {"sine", "power:3", "triangle", "fourier:three"})
    for (int digits : {0, 50}) {
      const std::string name = "speed/" + wave + "/certified_" + (digits ? "mpfr_50" : "double");
      speed_settings(benchmark::RegisterBenchmark(name.c_str(), BM_point, wave, digits, true));
    }
  for (const std::string wave : {"sine", "power:3", "triangle", "fourier:three"})
    for (int digits : {0, 50}) {
      const std::string name = "speed/" + wave + "/uncertified_" + (digits ? "mpfr_50" : "double");
      speed_settings(benchmark::RegisterBenchmark(name.c_str(), BM_point, wave, digits, false));
    }
}

}  // namespace vibrofric::bench
