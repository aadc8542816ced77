// The mpfr rung of the precision ladder (README, "Precision"; model.md, "The paper's claims that
// the suite verifies": decided to working precision): a computation is
// repeated at a rising working precision until its own error bound meets the target. Every caller
// shares this loop: evaluate's mpfr rung, the claim checks and their curved contacts.
#pragma once
#include <cmath>
#include <optional>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/escalate.hpp"
#include "vibrofric/core/numbers.hpp"

namespace vibrofric {

// How far an attempt fell short of its target: not at all, by a number of decimal digits, or by
// an unknown amount (the error bound is not finite: the areas were lost entirely).
struct Shortfall {
  bool met = false;
  std::optional<int> digits;
};

// The shortfall of a relative error bound `error` against `target`: ⌈log10(error/target)⌉ digits.
template <class Real>
Shortfall shortfall(const Real& error, const Real& target) {
  using std::isfinite;
  using std::log10;
  if (error <= target) return {true, {}};
  if (!isfinite(error)) return {false, {}};
  return {false, static_cast<int>(std::ceil(static_cast<double>(log10(error / target))))};
}

// Extra digits carried beyond the request before the solver's own rounding bound is consulted
// (and the precision raised if it says the request is not met): every rung's first working
// precision is digits + guard_digits(digits). Fewer guard digits were measured slower: more points
// then need the second pass.
inline int guard_digits(int digits) { return 10 + digits / 20; }

struct RaisePolicy {
  int guard = 10;         // digits added beyond those missing
  int max_work = 0;       // working digits not to go beyond (0: no limit but the attempts)
  int solver_retries = 0; // SolverErrors retried at 1.5 times the digits before one is rethrown
  int attempts = 8;
  bool double_on_precision_error = true;  // false: a PrecisionError is rethrown at once
  void (*on_solver_retry)() = nullptr;  // told of each such retry (a claim check reports them)
};

// Runs compute() under PrecisionScope(work) until judge(result) is met, and returns that result.
// Between attempts the working precision grows by the digits missing plus policy.guard, and
// doubles where the shortfall is unknown or the wave needs more digits than the scope has
// (PrecisionError; rethrown at the last attempt or past max_work). std::nullopt when the attempts
// or max_work run out: the caller names its case in the error it raises.
template <class Compute, class Judge>
auto raise_precision(int work, const RaisePolicy& policy, Compute compute, Judge judge)
    -> std::optional<decltype(compute())> {
  using Result = decltype(compute());
  int failures = 0, attempts = 0;
  long following = 0;  // the precision the last attempt asks for next; 0: stop
  const auto attempt = [&](long w) -> std::optional<Result> {
    ++attempts;
    following = 0;
    PrecisionScope scope(static_cast<unsigned>(w));
    std::optional<Result> r;
    try {
      r.emplace(compute());
    } catch (const PrecisionError&) {
      if (!policy.double_on_precision_error || attempts == policy.attempts ||
          (policy.max_work > 0 && 2 * w > policy.max_work))
        throw;
      following = 2 * w;
      return std::nullopt;
    } catch (const SolverError&) {
      if (++failures > policy.solver_retries) throw;
      if (policy.on_solver_retry) policy.on_solver_retry();
      following = w * 3 / 2;
      return std::nullopt;
    }
    const Shortfall s = judge(*r);
    if (s.met) return r;
    following = w + (s.digits ? *s.digits + policy.guard : w);
    if (policy.max_work > 0 && following > policy.max_work) following = 0;
    return std::nullopt;
  };
  return escalate(work, attempt, [&](long) -> std::optional<long> {
    if (following == 0 || attempts >= policy.attempts) return std::nullopt;
    return following;
  });
}

}  // namespace vibrofric
