// The checks shared by the waveform-file targets (fuzz_fourier.cpp, fuzz_samples.cpp): a parsed
// user wave is evaluated at a few points, in double (with the tool's escalation) and at 20 digits;
// every outcome must be clean, every value finite (μ in [0, 1], Ψ ≥ 0), and double must agree with
// mpfr — on accepting the point (unless it sits within 1e-12 of the no-contact boundary, where
// rounding may decide either way), and on the value to 4 ulp plus what the rounding of the input
// to double can move it: the double path computes for the Fourier coefficients rounded to double,
// a perturbation δ ≤ 8·eps·κ of the normalised wave, κ = Σ k(|a_k| + |b_k|)/scale (the recurrence
// error grows with k); μ moves by at most (1 + μ)δ/∫n and Ψ by 2δ (grid_envelope.hpp's argument).
// Samples are normalised from their decimal text in mpfr in every type (κ = 1). A difference beyond
// that is a finding.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "fuzz_common.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/evaluate.hpp"

namespace fuzz {

inline void check_user_wave(const vibrofric::WaveSpec& spec, const std::string& input, double kappa) {
  using namespace vibrofric;
  // The wave itself at 20 digits (the reference) and in double, as the tool would build them.
  PrecisionScope digits(31);
  std::unique_ptr<Waveform<mpfr>> wm;
  std::string double_error;
  const Outcome om_wave = clean(input, "make_waveform<mpfr>", [&] { wm = make_waveform<mpfr>(spec); });
  const Outcome od_wave = clean(input, "make_waveform<double>", [&] {
    try {
      make_waveform<double>(spec);
    } catch (const InputError& e) {
      double_error = e.what();
      throw;
    }
  });
  if (om_wave != Outcome::value) {
    // Rejected at 20 digits: double must reject too (it cannot see more than mpfr).
    if (od_wave == Outcome::value) finding("double accepts a wave that mpfr rejects", input);
    return;
  }
  if (!(wm->maximum() - wm->minimum() > 0) || !isfinite(wm->maximum()) || !isfinite(wm->minimum()))
    finding("mpfr waveform with a bad range", input);
  if (od_wave != Outcome::value) {
    // Values that differ only beyond double's precision are a constant signal (zero amplitude)
    // in double: a clean, true rejection. Anything else is a finding.
    if (double_error.find("constant") != std::string::npos || double_error.find("zero amplitude") != std::string::npos)
      return;
    finding("double rejects a wave that mpfr accepts: " + double_error, input);
  }
  // The points: four of μ in one batch (the waveform is then built once per type), and Ψ. A batch
  // that fails is repeated point by point, for each point's own outcome.
  const std::vector<Point> mu_points{{"1", "0.5"}, {"0.25", "-0.5"}, {"3", "2"}, {"0.01", "0.9"}};
  auto run = [&](NumberType t, int digits, Quantity q, const std::vector<Point>& points, std::vector<Outcome>& outcomes,
                 std::vector<std::string>& values) {
    const char* stage = t == NumberType::mpfr ? "evaluate mpfr" : "evaluate double";
    outcomes.assign(points.size(), Outcome::value);
    values.assign(points.size(), "");
    if (clean(input, stage, [&] { values = evaluate(spec, q, points, {t, digits}); }) == Outcome::value) return;
    for (std::size_t i = 0; i < points.size(); ++i)
      outcomes[i] = clean(input, stage, [&] { values[i] = evaluate(spec, q, {points[i]}, {t, digits}).front(); });
  };
  // Within 1e-12 of the no-contact boundary γ = −max w, rounding may decide contact either way.
  auto near_boundary = [&](const Point& p) { return p.gamma.given() && abs(mpfr(p.gamma.text()) + wm->maximum()) <= mpfr("1e-12"); };
  for (Quantity q : {Quantity::mu, Quantity::psi}) {
    const std::vector<Point> points = q == Quantity::mu ? mu_points : std::vector<Point>{{"1", ""}};
    std::vector<Outcome> om, od;
    std::vector<std::string> vm, vd;
    run(NumberType::mpfr, 20, q, points, om, vm);
    run(NumberType::float64, 17, q, points, od, vd);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Point& p = points[i];
      const std::string at = " at beta " + p.beta.text() + " gamma " + p.gamma.text();
      for (const auto& [o, v, type] : {std::tuple{om[i], vm[i], "mpfr"}, std::tuple{od[i], vd[i], "double"}}) {
        if (o != Outcome::value) continue;
        const double x = std::strtod(v.c_str(), nullptr);
        if (!std::isfinite(x) || x < 0 || (q == Quantity::mu && x > 1)) finding(std::string(type) + " value " + v + at, input);
      }
      if (om[i] == Outcome::value && od[i] == Outcome::value) {
        const double x = std::strtod(vd[i].c_str(), nullptr), y = std::strtod(vm[i].c_str(), nullptr);
        const double ulp = std::nextafter(std::abs(y), INFINITY) - std::abs(y);
        const double delta = 8 * std::numeric_limits<double>::epsilon() * std::max(kappa, 1.0);
        double input_effect = 2 * delta;
        if (q == Quantity::mu) {
          // evaluate decides contact from the exact input, the 31-digit wave only to 31 digits: at
          // the boundary the reference solve may round the contact away (normal area 0, μ free).
          double normal = 0;
          if (clean(input, "solve mpfr", [&] { normal = static_cast<double>(solve(*wm, mpfr(p.beta.text()), mpfr(p.gamma.text())).normal_area); }) !=
                  Outcome::value &&
              !near_boundary(p))
            finding("evaluate gave a value where solve fails" + at, input);
          input_effect = (1 + y) * delta / normal;
        }
        if (!(std::abs(x - y) <= 4 * ulp + input_effect + 1e-300))
          finding("double " + vd[i] + " and 20-digit mpfr " + vm[i] + " differ" + at, input);
      } else if (om[i] != od[i]) {
        // One type accepted the point and the other did not: only at the no-contact boundary.
        if (!near_boundary(p))
          finding("double and mpfr disagree on the point" + at + ": outcomes " + std::to_string(static_cast<int>(od[i])) +
                      " and " + std::to_string(static_cast<int>(om[i])),
                  input);
      }
    }
  }
}

}  // namespace fuzz
