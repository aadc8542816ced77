// Curved contacts (model.md, "Curved contacts (MDR)"): the cost of μ̄/μ0 for the harmonic wave
// with a sphere and with a sphere with a wear flat (λ = 100), in every way the library offers,
// and the naive spring-row simulation (spring_row.hpp) at the accuracy it can afford:
//   curved/<case>/solver_double          solve_curved<double>, raw (the value as computed)
//   curved/<case>/guaranteed_double      evaluate(…, float64) with BatchOptions::profile: the
//                                        string API behind `vibrofric mu --profile P --type double`
//   curved/<case>/solver_mpfr_D          solve_curved<mpfr> at D + guard digits, asked for 10^−D/8
//   curved/<case>/guaranteed_mpfr_D      evaluate(…, mpfr, D): `vibrofric mu --profile P --digits D`
//   curved/sine_sphere/spring_row_K      the spring row, M = 512 springs, N = 2^K steps per period
//   curved/sine_sphere/spring_row_6digits  the spring row at M = 512, N = 2^23: 6 correct digits
//                                        (measured rel_error counter; full mode only, ~30 s)
// <case> is sine_sphere, sine_wearflat100 or sine_measured_ball (the sphere's profile f = r²/2 as a
// measured file would give it: 21 samples, r = 0, 0.12, …, 2.4, each a kink of the profile;
// double paths and 30 digits only). Counters: rel_error, the largest relative error over
// the inputs evaluated against solve_curved<mpfr> at
// 40 digits (asked for 1e-36); digits; for the wear flat and the measured ball's double paths,
// il_ratio_to_sphere (the case's time over the sphere's, the two measured alternately: see
// interleaved_sphere). The inputs (β, γ) = (1, −0.3), (2, 0.5), (0.5, 1.5): a
// jumping centre, a jumping centre near the top, a non-jumping centre. bench/README.md has the
// results and how the spring row's cost at 6 digits is obtained.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <optional>
#include <type_traits>
#include <utility>

#include "common.hpp"
#include "floor.hpp"
#include "evaluate_impl.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/verification/spring_row.hpp"

namespace vibrofric::bench {
namespace {

struct CurvedInput {
  const char *beta, *gamma;
};
const std::vector<CurvedInput>& curved_inputs() {
  static const std::vector<CurvedInput> in{{"1", "-0.3"}, {"2", "0.5"}, {"0.5", "1.5"}};
  return in;
}

// evaluate() takes a profile once BatchOptions has the field (evaluate.hpp); until then the
// guaranteed paths are not registered.
template <class T, class = void>
struct has_profile : std::false_type {};
template <class T>
struct has_profile<T, std::void_t<decltype(std::declval<T&>().profile = ProfileSpec{})>> : std::true_type {};
template <class T>
bool set_profile(T& options, const ProfileSpec& p) {
  if constexpr (has_profile<T>::value) {
    options.profile = p;
    return true;
  } else {
    (void)options;
    (void)p;
    return false;
  }
}

// μ̄ of the input at 40 digits (asked for 1e-36), once per profile and input.
double reference(const std::string& profile, const CurvedInput& in) {
  static std::map<std::pair<std::string, std::string>, double> cache;
  const auto key = std::make_pair(profile, std::string(in.beta) + "," + in.gamma);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  PrecisionScope scope(40);
  const auto w = make_waveform<mpfr>(parse_wave("sine"));
  const auto p = make_profile<mpfr>(parse_profile(profile));
  const auto r = solve_curved(*w, *p, mpfr(in.beta), mpfr(in.gamma), Options{}, mpfr("1e-36"));
  return cache[key] = static_cast<double>(r.mu);
}

double rel_error(double value, double ref) { return std::abs(value - ref) / std::abs(ref); }

// Slow paths (tens to hundreds of ms per evaluation): each repetition evaluates every input once
// (median of 3); --quick evaluates the first input once.
benchmark::internal::Benchmark* slow_settings(benchmark::internal::Benchmark* b, std::size_t inputs) {
  b->Unit(benchmark::kMillisecond);
  if (config().quick) return b->Iterations(1)->Repetitions(1);
  return b->Iterations(static_cast<benchmark::IterationCount>(inputs))->Repetitions(3)->ReportAggregatesOnly(true);
}

// The largest relative error over the inputs evaluated (NaN marks one not evaluated).
double worst_error(const std::string& profile, const std::vector<double>& got) {
  double worst = 0;
  for (std::size_t k = 0; k < got.size(); ++k)
    if (!std::isnan(got[k])) worst = std::max(worst, rel_error(got[k], reference(profile, curved_inputs()[k])));
  return worst;
}

// A profile's time over the sphere's, measured beside each other (untimed by Google Benchmark):
// `rounds` rounds, each one pass over the inputs with each profile (the order alternating between
// rounds), so that a shared host's slow and fast phases fall on both; the ratio of two rows timed
// minutes apart moved by 1.5× between runs at one commit. A pass is repeated to about 5 ms.
// Counters "il_case_ns" and "il_sphere_ns" (per evaluation, medians over the rounds) and
// "il_ratio_to_sphere" (the median of the rounds' ratios).
void interleaved_sphere(benchmark::State& state, const std::function<void()>& case_pass,
                        const std::function<void()>& sphere_pass) {
  constexpr int rounds = 9;
  const double evaluations_per_pass = static_cast<double>(curved_inputs().size());
  auto timed = [](const std::function<void()>& pass, int reps) {
    const double t0 = thread_cpu_ns();
    for (int k = 0; k < reps; ++k) pass();
    return thread_cpu_ns() - t0;
  };
  const int reps = std::max(1, static_cast<int>(5e6 / std::max(1.0, timed(sphere_pass, 1))));
  std::vector<double> case_ns, sphere_ns, ratio;
  for (int k = 0; k < rounds; ++k) {
    double c, s;
    if (k % 2 == 0) {
      c = timed(case_pass, reps);
      s = timed(sphere_pass, reps);
    } else {
      s = timed(sphere_pass, reps);
      c = timed(case_pass, reps);
    }
    case_ns.push_back(c / (reps * evaluations_per_pass));
    sphere_ns.push_back(s / (reps * evaluations_per_pass));
    ratio.push_back(c / s);
  }
  state.counters["il_case_ns"] = median(case_ns);
  state.counters["il_sphere_ns"] = median(sphere_ns);
  state.counters["il_ratio_to_sphere"] = median(ratio);
}

void BM_curved_double(benchmark::State& state, const std::string& profile) {
  const auto w = make_waveform<double>(parse_wave("sine"));
  const auto p = make_profile<double>(parse_profile(profile));
  const auto& in = curved_inputs();
  std::vector<double> got(in.size(), std::nan(""));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto r = solve_curved(*w, *p, std::strtod(in[i].beta, nullptr), std::strtod(in[i].gamma, nullptr));
    benchmark::DoNotOptimize(r.mu);
    got[i] = r.mu;
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["rel_error"] = worst_error(profile, got);
  state.counters["inputs"] = static_cast<double>(in.size());
  if (profile == "sphere") return;
  const auto sphere = make_profile<double>(parse_profile("sphere"));
  auto pass = [&](const Profile<double>& q) {
    for (const auto& x : in)
      benchmark::DoNotOptimize(solve_curved(*w, q, std::strtod(x.beta, nullptr), std::strtod(x.gamma, nullptr)).mu);
  };
  interleaved_sphere(state, [&] { pass(*p); }, [&] { pass(*sphere); });
}

void BM_curved_mpfr(benchmark::State& state, const std::string& profile, int digits) {
  PrecisionScope scope(static_cast<unsigned>(digits + guard_digits(digits)));
  const auto w = make_waveform<mpfr>(parse_wave("sine"));
  const auto p = make_profile<mpfr>(parse_profile(profile));
  const mpfr target = pow(mpfr(10), -digits) / 8;
  const auto& in = curved_inputs();
  std::vector<mpfr> beta, gamma;
  for (const auto& x : in) {
    beta.emplace_back(x.beta);
    gamma.emplace_back(x.gamma);
  }
  std::vector<double> got(in.size(), std::nan(""));
  std::size_t i = 0, springs = 0;
  for (auto _ : state) {
    const auto r = solve_curved(*w, *p, beta[i], gamma[i], Options{}, target);
    benchmark::DoNotOptimize(r.mu);
    got[i] = static_cast<double>(r.mu);
    springs += r.springs;
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["springs"] = state.iterations() ? double(springs) / double(state.iterations()) : 0.0;  // per evaluation
  state.counters["rel_error"] = worst_error(profile, got);  // in double: the value agrees with the reference to the last bit
  state.counters["digits"] = digits;
}

// evaluate(): decimal in, decimal out, the escalation ladder (double → long double → mpfr) or
// the mpfr precision ladder, one point per call. digits = 0: float64.
void BM_curved_guaranteed(benchmark::State& state, const std::string& profile, int digits) {
  const WaveSpec spec = parse_wave("sine");
  BatchOptions options;
  options.threads = 1;
  set_profile(options, parse_profile(profile));
  Precision precision;
  precision.type = digits ? NumberType::mpfr : NumberType::float64;
  if (digits) precision.digits = digits;
  const auto& in = curved_inputs();
  std::vector<std::vector<Point>> points;
  for (const auto& x : in) points.push_back({Point{x.beta, x.gamma}});
  std::vector<double> got(in.size(), std::nan(""));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto out = evaluate(spec, Quantity::mu, points[i], precision, options);
    benchmark::DoNotOptimize(out.data());
    got[i] = std::strtod(out[0].c_str(), nullptr);
    if (++i == in.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["rel_error"] = worst_error(profile, got);
  if (digits) state.counters["digits"] = digits;
  if (digits || profile == "sphere") return;
  BatchOptions sphere = options;
  set_profile(sphere, parse_profile("sphere"));
  auto pass = [&](const BatchOptions& o) {
    for (const auto& p : points) benchmark::DoNotOptimize(evaluate(spec, Quantity::mu, p, precision, o).data());
  };
  interleaved_sphere(state, [&] { pass(options); }, [&] { pass(sphere); });
}

// The spring row at (β, γ) = (1, −0.3), M springs and N steps per period.
void BM_spring_row(benchmark::State& state, const std::string& profile, std::size_t springs, std::size_t steps) {
  const auto w = make_waveform<double>(parse_wave("sine"));
  const auto p = make_profile<double>(parse_profile(profile));
  const CurvedInput& in = curved_inputs()[0];
  SpringRowOptions opt;
  opt.springs = springs;
  opt.steps = steps;
  double mu = 0;
  std::size_t periods = 0;
  for (auto _ : state) {
    const auto r = simulate_spring_row(*w, *p, std::strtod(in.beta, nullptr), std::strtod(in.gamma, nullptr), opt);
    benchmark::DoNotOptimize(r.mu);
    mu = r.mu;
    periods = r.periods;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["rel_error"] = rel_error(mu, reference(profile, in));
  state.counters["springs"] = static_cast<double>(springs);
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["periods"] = static_cast<double>(periods);
}

// The measured ball's profile file (see the top): written once, beside the system's temporary files.
std::string measured_ball() {
  const auto path = std::filesystem::temp_directory_path() / "vibrofric_bench_measured_ball.txt";
  std::ofstream out(path);
  out << "# r f: the profile f = r^2/2 sampled as a measured ball\n";
  for (int k = 0; k <= 20; ++k) {
    const double r = 0.12 * k;
    out << r << " " << r * r / 2 << "\n";
  }
  return "profile:" + path.string();
}

}  // namespace

void register_curved() {
  for (const auto& [name, profile] : std::vector<std::pair<std::string, std::string>>{{"sine_sphere", "sphere"},
                                                                                       {"sine_wearflat100", "wearflat:100"},
                                                                                       {"sine_measured_ball", measured_ball()}}) {
    const std::string prefix = "curved/" + name + "/";
    const std::size_t n = curved_inputs().size();
    speed_settings(benchmark::RegisterBenchmark((prefix + "solver_double").c_str(), BM_curved_double, profile));
    BatchOptions probe;
    const bool guaranteed = set_profile(probe, ProfileSpec{});
    if (guaranteed)
      speed_settings(benchmark::RegisterBenchmark((prefix + "guaranteed_double").c_str(), BM_curved_guaranteed, profile, 0));
    // The sphere's solver at 20 to 100 digits: the series bench/run fits (cost against digits).
    const std::vector<int> series = name == "sine_sphere"        ? std::vector<int>{20, 30, 50, 100}
                                    : name == "sine_wearflat100" ? std::vector<int>{30, 50}
                                                                 : std::vector<int>{30};
    for (int digits : series) {
      slow_settings(benchmark::RegisterBenchmark((prefix + "solver_mpfr_" + std::to_string(digits)).c_str(), BM_curved_mpfr,
                                                 profile, digits),
                    n);
      if (guaranteed && (digits == 30 || digits == 50))
        slow_settings(benchmark::RegisterBenchmark((prefix + "guaranteed_mpfr_" + std::to_string(digits)).c_str(),
                                                   BM_curved_guaranteed, profile, digits),
                      n);
    }
  }
  // The spring row (sphere only: with a wear flat the flat block dominates, and its first-order
  // error depends on where first contact falls between steps, so it does not fall steadily with N).
  const std::string profile = "sphere";
  const std::size_t springs = config().quick ? 128 : 512;
  for (int log2n : config().quick ? std::vector<int>{12, 14} : std::vector<int>{14, 16, 18}) {
    const std::size_t steps = std::size_t(1) << log2n;
    auto* b = benchmark::RegisterBenchmark(("curved/sine_sphere/spring_row_" + std::to_string(log2n)).c_str(), BM_spring_row,
                                           profile, springs, steps);
    b->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(config().quick ? 1 : 3);
    if (!config().quick) b->ReportAggregatesOnly(true);
  }
  if (!config().quick)
    benchmark::RegisterBenchmark("curved/sine_sphere/spring_row_6digits", BM_spring_row, profile, std::size_t(512),
                                 std::size_t(1) << 23)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1)
        ->Repetitions(1);
}

}  // namespace vibrofric::bench
