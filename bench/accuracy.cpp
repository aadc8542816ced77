// Accuracy of the double and long double paths, in ULP of the path's type, against the mpfr
// solver at more than twice the type's digits, on a fixed (β, γ) grid per wave with the hard
// corners: β → 0, β just below (and just above) β_c(γ), γ → −1, γ = 1, γ ≫ 1, and the square
// wave's threshold β = 2(1 + γ) (β = 4, the kink of Ψ_sqr, for γ ≥ 1).
//
// Reference values: μ̄/μ0 from solve<mpfr> at the exact binary (β, γ) of the grid point, with the
// working precision raised until the solver's rounding bound is below 10^−D (D = 40 for double,
// 60 for long double), then recomputed the same way at D + 30 digits; the two must agree to
// 1e-6 ULP of the type or the run stops with a message naming the point. Nothing is typed in.
//
// ULP: |x − ref| / ulp(ref), ulp(ref) = 2^(e − p) for ref = m·2^e, 1/2 ≤ m < 1, p the type's
// significand bits, all in mpfr at 200 digits: a correctly rounded x scores at most 0.5.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common.hpp"
#include "ladder.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/verification/baseline.hpp"
#include "vibrofric/verification/grid_envelope.hpp"

namespace vibrofric::bench {
namespace {

constexpr int ref_digits_double = 40;
constexpr int ref_digits_long_double = 60;
constexpr int check_extra_digits = 30;
constexpr double max_reference_disagreement_ulp = 1e-6;
// The baseline needs about 3 + n_min/β periods of `baseline_steps` steps (s climbs from 0 by β a
// period); points needing more are skipped (counter `skipped`).
constexpr double max_baseline_periods = 1000;

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "vibrofric_bench: %s\n", message.c_str());
  std::exit(3);
}

std::string show(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

struct GridPoint {
  double beta, gamma;
  std::string tags;  // corner classes joined by '+', "interior" if none
};

struct Reference {
  GridPoint at;
  std::string for_double;       // μ̄/μ0 to ref_digits_double + 5 digits
  std::string for_long_double;  // μ̄/μ0 to ref_digits_long_double + 5 digits
};

// μ̄/μ0 at the exact binary (β, γ), to `digits` significant digits by the solver's own bound.
std::string reference_mu(const WaveSpec& spec, double beta, double gamma, int digits) {
  int work = digits + 10;
  for (int attempt = 0; attempt < 10; ++attempt) {
    PrecisionScope scope(static_cast<unsigned>(work));
    const auto w = make_waveform<mpfr>(spec);
    const Result<mpfr> r = solve(*w, mpfr(beta), mpfr(gamma));
    const mpfr target = pow(mpfr(10), -digits);
    if (r.relative_error <= target) return format_significant(r.mu, digits + 5);
    if (isfinite(r.relative_error))
      work += static_cast<int>(std::ceil(static_cast<double>(log10(r.relative_error / target)))) + 10;
    else
      work *= 2;
  }
  fail("reference for " + spec.name + " at beta = " + show(beta) + ", gamma = " + show(gamma) + ": " +
       std::to_string(digits) + " digits not reached");
}

// |x − ref| in ULP of a type with `bits` significand bits.
double ulp_error(long double x, const std::string& ref, int bits) {
  PrecisionScope scope(200);
  const mpfr r(ref);
  const mpfr d = abs(mpfr(x) - r);
  const long e = mpfr_get_exp(r.backend().data());
  return static_cast<double>(d / ldexp(mpfr(1), static_cast<int>(e - bits)));
}

// β_c(γ), the largest rising slope of the clipped n (README "Waves"), from its formula at the
// current precision; none for the waves with an upward jump.
std::optional<mpfr> beta_c_formula(const WaveSpec& spec, const mpfr& gamma) {
  const mpfr two_pi = 2 * boost::math::constants::pi<mpfr>();
  switch (spec.kind) {
    case WaveKind::sine: return gamma >= 0 ? two_pi : mpfr(two_pi * sqrt(1 - gamma * gamma));
    case WaveKind::triangle: return mpfr(4);
    case WaveKind::sawtooth_right: return mpfr(2);
    case WaveKind::power: {
      const mpfr p(spec.exponent.text());
      return gamma >= 0 ? mpfr(4 * p) : mpfr(4 * p * pow(1 + gamma, (p - 1) / p));
    }
    default: return std::nullopt;
  }
}

std::vector<GridPoint> accuracy_grid(const WaveSpec& spec) {
  const bool quick = config().quick;
  const std::vector<double> gammas =
      quick ? std::vector<double>{-0.99999, -0.5, 1, 1000}
            : std::vector<double>{-0.99999, -0.999, -0.9, -0.5, -0.3, 0, 0.3, 0.7, 1, 2, 10, 1000};
  const std::vector<double> betas =
      quick ? std::vector<double>{1e-6, 1e-3, 0.7, 3.5}
            : std::vector<double>{1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 0.3, 0.7, 1, 1.5, 2.5, 3.5, 5, 8};
  std::vector<GridPoint> grid;
  for (double gamma : gammas) {
    std::map<double, std::set<std::string>> at;
    for (double b : betas) {
      auto& t = at[b];
      if (b <= 1e-3) t.insert("beta_small");
    }
    PrecisionScope scope(40);
    const mpfr g(gamma);
    if (const auto bc = beta_c_formula(spec, g)) {
      // The solver's β_c (Contact) must agree with the formula: the corner is where we think.
      const auto w = make_waveform<mpfr>(spec);
      const mpfr solver_bc = make_contact(*w, g).beta_c();
      if (abs(solver_bc - *bc) > *bc * pow(mpfr(10), -30))
        fail(spec.name + ", gamma = " + show(gamma) + ": beta_c formula " + format_significant(*bc, 20) +
             " != solver's " + format_significant(solver_bc, 20));
      double lo = mpfr_get_d(bc->backend().data(), MPFR_RNDD);  // largest double below β_c
      if (mpfr(lo) == *bc) lo = std::nextafter(lo, 0.0);
      double hi = mpfr_get_d(bc->backend().data(), MPFR_RNDU);  // smallest double above
      if (mpfr(hi) == *bc) hi = std::nextafter(hi, 1e300);
      std::vector<double> below = {lo * (1 - 1e-8), lo};
      if (!quick) {
        for (double d : {1e-2, 1e-4, 1e-12}) below.push_back(lo * (1 - d));
        below.push_back(std::nextafter(lo, 0.0));
      }
      for (double b : below) at[b].insert("below_beta_c");
      at[hi].insert("above_beta_c");
    }
    if (spec.kind == WaveKind::square) {
      // Eq. 22's switch at β = 2(1 + γ) in the jumping range; Ψ_sqr's kink at β = 4 for γ ≥ 1.
      const mpfr t = gamma < 1 ? mpfr(2 * (1 + g)) : mpfr(4);
      const double td = mpfr_get_d(t.backend().data(), MPFR_RNDN);
      std::vector<double> near = {td};
      if (!quick)
        for (double b : {std::nextafter(td, 0.0), std::nextafter(td, 1e300), td * (1 - 1e-6), td * (1 + 1e-6)})
          near.push_back(b);
      for (double b : near) at[b].insert("square_threshold");
    }
    for (auto& [b, t] : at) {
      if (gamma <= -0.999) t.insert("gamma_near_-1");
      if (gamma == 1) t.insert("gamma_1");
      if (gamma >= 1000) t.insert("gamma_large");
      std::string tags;
      for (const auto& s : t) tags += (tags.empty() ? "" : "+") + s;
      grid.push_back({b, gamma, tags.empty() ? "interior" : tags});
    }
  }
  return grid;
}

// The references of a wave, computed on first use and kept for the other paths.
const std::vector<Reference>& references(const std::string& wave) {
  static std::map<std::string, std::vector<Reference>> cache;
  auto it = cache.find(wave);
  if (it != cache.end()) return it->second;
  const WaveSpec spec = parse_wave(wave);
  std::vector<Reference> refs;
  for (const GridPoint& p : accuracy_grid(spec)) {
    Reference r{p, reference_mu(spec, p.beta, p.gamma, ref_digits_double),
                reference_mu(spec, p.beta, p.gamma, ref_digits_long_double)};
    const std::pair<const std::string*, int> checks[] = {{&r.for_double, ref_digits_double}, {&r.for_long_double, ref_digits_long_double}};
    for (const auto& [value, digits] : checks) {
      const std::string check = reference_mu(spec, p.beta, p.gamma, digits + check_extra_digits);
      const int bits = digits == ref_digits_double ? std::numeric_limits<double>::digits : std::numeric_limits<long double>::digits;
      PrecisionScope scope(200);
      const mpfr a(*value), b(check);
      const long e = mpfr_get_exp(b.backend().data());
      const double disagreement = static_cast<double>(abs(a - b) / ldexp(mpfr(1), static_cast<int>(e - bits)));
      if (!(disagreement <= max_reference_disagreement_ulp))
        fail("reference check failed for " + wave + " at beta = " + show(p.beta) + ", gamma = " + show(p.gamma) + ": " +
             std::to_string(digits) + " digits give " + *value + ", " + std::to_string(digits + check_extra_digits) +
             " digits give " + check + " (" + std::to_string(disagreement) + " ulp apart)");
    }
    refs.push_back(std::move(r));
  }
  return cache.emplace(wave, std::move(refs)).first->second;
}

enum class Path { solver_double, guaranteed_double, solver_long_double, closed_form_double, grid_envelope_double, baseline_double };

struct PathInfo {
  Path path;
  const char* name;
  int bits;
};

const std::vector<PathInfo>& paths() {
  static const std::vector<PathInfo> p = {
      {Path::solver_double, "solver_double", std::numeric_limits<double>::digits},
      {Path::guaranteed_double, "guaranteed_double", std::numeric_limits<double>::digits},
      {Path::solver_long_double, "solver_long_double", std::numeric_limits<long double>::digits},
      {Path::closed_form_double, "closed_form_double", std::numeric_limits<double>::digits},
      {Path::grid_envelope_double, "grid_envelope_double", std::numeric_limits<double>::digits},
      {Path::baseline_double, "baseline_double", std::numeric_limits<double>::digits},
  };
  return p;
}

struct Evaluator {
  explicit Evaluator(const WaveSpec& s)
      : spec(s), wd(make_waveform<double>(s)), wld(make_waveform<long double>(s)) {
    precision.type = NumberType::float64;
    options.threads = 1;
  }
  // nullopt: skipped (baseline too long).
  std::optional<long double> operator()(Path path, const GridPoint& p) const {
    switch (path) {
      case Path::solver_double: return solve(*wd, p.beta, p.gamma).mu;
      case Path::guaranteed_double: {
        const auto out = evaluate(spec, Quantity::mu, {Point{exact_decimal(p.beta), exact_decimal(p.gamma)}}, precision, options);
        return std::strtod(out.at(0).c_str(), nullptr);
      }
      case Path::solver_long_double:
        return solve(*wld, static_cast<long double>(p.beta), static_cast<long double>(p.gamma)).mu;
      case Path::closed_form_double: return closed_form_mu(spec.kind, p.beta, p.gamma);
      case Path::grid_envelope_double: return grid_envelope(*wd, p.beta, p.gamma, grid_points).mu;
      case Path::baseline_double: {
        const double n_min = std::max(0.0, p.gamma + wd->minimum());
        if (3 + n_min / p.beta > max_baseline_periods) return std::nullopt;
        BaselineOptions opt;
        opt.steps = baseline_steps;
        return simulate_spring(*wd, p.beta, p.gamma, opt).mu;
      }
    }
    return std::nullopt;
  }
  WaveSpec spec;
  std::unique_ptr<Waveform<double>> wd;
  std::unique_ptr<Waveform<long double>> wld;
  Precision precision;
  BatchOptions options;
};

void BM_accuracy(benchmark::State& state, const std::string& wave, const PathInfo& info) {
  const std::vector<Reference>& refs = references(wave);
  const Evaluator eval(parse_wave(wave));
  double max_ulp = 0, max_interior = 0, sum_sq = 0;
  std::size_t n = 0, over_2 = 0, failures = 0, skipped = 0, above_one = 0;
  const Reference* worst = nullptr;
  std::string first_failure;
  for (auto _ : state) {
    for (const Reference& r : refs) {
      const GridPoint& p = r.at;
      const std::string& ref = info.bits == std::numeric_limits<double>::digits ? r.for_double : r.for_long_double;
      std::string status = "ok", value_text;
      double e = std::numeric_limits<double>::quiet_NaN();
      try {
        const std::optional<long double> v = eval(info.path, p);
        if (!v) {
          ++skipped;
          status = "skipped";
        } else if (!std::isfinite(*v)) {
          throw std::runtime_error("non-finite value");
        } else {
          char buf[48];
          std::snprintf(buf, sizeof buf, "%.21Lg", *v);
          value_text = buf;
          e = ulp_error(*v, ref, info.bits);
          ++n;
          if (*v > 1) ++above_one;  // μ̄ ≤ μ0 always (s ≤ n): a value above 1 is unphysical
          sum_sq += e * e;
          if (e > 2) ++over_2;
          if (!worst || e > max_ulp) {
            max_ulp = e;
            worst = &r;
          }
          if (p.tags == "interior" && e > max_interior) max_interior = e;
        }
      } catch (const std::exception& ex) {
        ++failures;
        status = "failed";
        if (first_failure.empty())
          first_failure = "beta=" + show(p.beta) + " gamma=" + show(p.gamma) + ": " + ex.what();
      }
      if (config().points)
        std::fprintf(config().points, "%s,%s,%s,%s,%s,%s,%s,%.6g,%s\n", wave.c_str(), info.name, show(p.beta).c_str(),
                     show(p.gamma).c_str(), p.tags.c_str(), value_text.c_str(), ref.c_str(), e, status.c_str());
    }
  }
  state.counters["max_ulp"] = max_ulp;
  state.counters["rms_ulp"] = n ? std::sqrt(sum_sq / double(n)) : 0.0;
  state.counters["max_ulp_interior"] = max_interior;
  state.counters["points"] = double(n);
  state.counters["over_2ulp"] = double(over_2);
  state.counters["failures"] = double(failures);
  state.counters["skipped"] = double(skipped);
  state.counters["mu_above_1"] = double(above_one);
  state.counters["reference_digits"] = info.bits == std::numeric_limits<double>::digits ? ref_digits_double : ref_digits_long_double;
  char buf[160];
  std::string label;
  if (worst) {
    std::snprintf(buf, sizeof buf, "worst beta=%s gamma=%s [%s] %.3g ulp", show(worst->at.beta).c_str(),
                  show(worst->at.gamma).c_str(), worst->at.tags.c_str(), max_ulp);
    label = buf;
  }
  if (failures) label += "; " + std::to_string(failures) + " failed, first " + first_failure;
  state.SetLabel(label);
  if (info.path == Path::guaranteed_double) {
    std::vector<Point> grid;
    for (const Reference& r : refs) grid.push_back({exact_decimal(r.at.beta), exact_decimal(r.at.gamma)});
    rung_counters(state, wave, grid);
    // The estimate against the proof (api/certify.hpp): the double printed at every grid point,
    // corners included, is the proven correct rounding of the exact value. A miss, or a point the
    // certificate cannot decide, is a bug: the benchmark stops with an error naming it.
    const Certifier certifier(eval.spec, ProfileSpec{});
    std::size_t proven = 0;
    for (const Point& q : grid) {
      std::string what;
      try {
        const std::string printed = evaluate(eval.spec, Quantity::mu, {q}, eval.precision, eval.options).at(0);
        const Certificate c = certifier(Quantity::mu, q, eval.precision, printed);
        if (c.correctly_rounded)
          ++proven;
        else
          what = "printed " + printed + ", proven " + c.nearest.front();
      } catch (const std::exception& ex) {
        what = ex.what();
      }
      if (!what.empty()) {
        state.SkipWithError(("not proven correctly rounded at beta = " + q.beta.text() + ", gamma = " + q.gamma.text() + ": " + what).c_str());
        break;
      }
    }
    state.counters["certified_proven"] = double(proven);
  }
}

}  // namespace

void register_accuracy() {
  for (const auto& wave : waves()) {
    const WaveKind kind = parse_wave(wave).kind;
    for (const PathInfo& info : paths()) {
      if (info.path == Path::closed_form_double && !has_closed_form(kind)) continue;
      const std::string name = "accuracy/" + wave + "/" + info.name;
      benchmark::RegisterBenchmark(name.c_str(), BM_accuracy, wave, info)
          ->Iterations(1)
          ->Repetitions(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace vibrofric::bench
