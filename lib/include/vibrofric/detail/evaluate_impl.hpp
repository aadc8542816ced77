// Implementation of evaluate_typed<Real> (evaluate.hpp); included by one .cpp per number type.
#pragma once
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>

#include "vibrofric/evaluate.hpp"

namespace vibrofric::detail {

// Extra digits carried beyond the request, before the solver's own error estimate is consulted.
inline int guard_digits(int digits) { return 10 + digits / 20; }

template <class Real>
struct PointValue {
  Real value;
  Real relative_error;
};

template <class Real>
PointValue<Real> compute_point(const Waveform<Real>& w, Quantity q, const Point& p, const Options& opt) {
  const Real beta = parse_real<Real>(p.beta, "beta");
  if (q == Quantity::psi) {
    const auto r = psi(w, beta, opt);
    return {r.lost_area, r.lost_relative_error};
  }
  const Real gamma = parse_real<Real>(p.gamma, "gamma");
  const auto r = solve(w, beta, gamma, opt);
  return {r.mu, r.relative_error};
}

// One point at `digits` significant digits: mpfr raises its working precision until the
// error estimate is below half a unit in the last requested digit.
template <class Real>
std::string evaluate_point(const WaveSpec& spec, Quantity q, const Point& p, int digits,
                           const Options& opt) {
  if constexpr (is_runtime_precision_v<Real>) {
    int work = digits + guard_digits(digits);
    for (int attempt = 0; attempt < 8; ++attempt) {
      PrecisionScope scope(static_cast<unsigned>(work));
      const auto w = make_waveform<Real>(spec);
      const auto v = compute_point(*w, q, p, opt);
      const Real target = pow(Real(10), -digits) / 2;
      if (v.relative_error <= target) return format_significant(v.value, digits);
      using std::isfinite;
      using std::log10;
      if (isfinite(v.relative_error))
        work += static_cast<int>(std::ceil(static_cast<double>(log10(v.relative_error / target)))) + guard_digits(digits);
      else
        work *= 2;  // the areas were lost entirely: no estimate of how much is missing
      if (work > 4 * max_digits) break;
    }
    throw SolverError("wave " + spec.name + ", beta = " + p.beta +
                      (q == Quantity::mu ? ", gamma = " + p.gamma : std::string()) +
                      ": could not reach " + std::to_string(digits) + " digits (ill-conditioned)");
  } else {
    const auto w = make_waveform<Real>(spec);
    return format_significant(compute_point(*w, q, p, opt).value, digits);
  }
}

// A fixed-precision type: its own value where the rounding bound allows, else the mpfr value
// at the type's round-trip digits rounded to the type.
template <class Real>
std::string evaluate_fixed(const Waveform<Real>& w, const WaveSpec& spec, Quantity q, const Point& p,
                           int digits, const BatchOptions& options) {
  const auto v = compute_point(w, q, p, options.solver);
  if (!options.escalate || v.relative_error <= std::numeric_limits<Real>::epsilon())
    return format_significant(v.value, digits);
  const std::string exact = evaluate_point<mpfr>(spec, q, p, std::numeric_limits<Real>::max_digits10 + 3, options.solver);
  return format_significant(parse_real<Real>(exact, "escalated value"), digits);
}

template <class Real>
std::vector<std::string> evaluate_typed(const WaveSpec& spec, Quantity q, const std::vector<Point>& points,
                                        int digits, const BatchOptions& options) {
  std::vector<std::string> out(points.size());
  std::vector<std::exception_ptr> errors(points.size());
  std::atomic<std::size_t> next{0}, done{0};
  auto worker = [&] {
    // Waveforms are rebuilt per point only for mpfr (precision may change per point).
    std::unique_ptr<Waveform<Real>> w;
    for (std::size_t i; (i = next++) < points.size();) {
      try {
        if constexpr (is_runtime_precision_v<Real>) {
          out[i] = evaluate_point<Real>(spec, q, points[i], digits, options.solver);
        } else {
          if (!w) w = make_waveform<Real>(spec);
          out[i] = evaluate_fixed(*w, spec, q, points[i], digits, options);
        }
      } catch (...) {
        errors[i] = std::current_exception();
      }
      const std::size_t d = ++done;
      if (options.progress) options.progress(d);
    }
  };
  unsigned threads = options.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : options.threads;
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, points.size())));
  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

}  // namespace vibrofric::detail

#define VIBROFRIC_INSTANTIATE_EVALUATE(Real)                                                     \
  template std::vector<std::string> vibrofric::detail::evaluate_typed<Real>(                    \
      const WaveSpec&, Quantity, const std::vector<Point>&, int, const BatchOptions&);
