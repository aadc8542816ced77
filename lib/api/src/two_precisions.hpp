// What the two-precision evaluations (rig.cpp, inplane.cpp) print: a number's agreed digits, and
// whether an interval of values rounds alike in the requested type.
#pragma once
#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/number_type.hpp"
#include "evaluate_impl.hpp"
#include "vibrofric/api/ladder.hpp"

namespace vibrofric::detail {

// b with the significant digits (at most `most`) on which a and b agree.
inline Significant agreed(const mpfr& a, const mpfr& b, int most) {
  if (a == 0 && b == 0) return {mpfr(0), 1};
  for (int d = most; d > 1; --d)
    if (same_significant(a, b, d)) return {b, d};
  return {b, 1};
}

// Whether every value of [lo, hi] rounds alike: to the type, or to `digits` digits (mpfr).
inline bool decides(const mpfr& lo, const mpfr& hi, const Precision& precision, int digits) {
  return visit_number_type(precision.type, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    if constexpr (is_runtime_precision_v<Real>)
      return same_significant(lo, hi, digits);
    else
      return detail::rounded<Real>(lo) == detail::rounded<Real>(hi);
  });
}

// A solution at two precisions: solve(digits + 10, nullptr), then solve(D, &lower) from D = digits
// + 22 raised until settled(lower, higher) (the escalation routine's loop, ladder.hpp: 4 attempts,
// each adding max(12, half the digits)), the previous higher becoming the lower. Solved has the
// working `digits` and `r.mu`. SolverError with `context`, `what` and both values where it does
// not settle.
template <class Solved, class Solve, class Settled>
std::pair<Solved, Solved> two_precisions(int digits, Solve solve, Settled settled, const std::string& context,
                                         const char* what) {
  std::optional<Solved> a, b;
  a.emplace(solve(digits + 10, nullptr));
  RaisePolicy policy;
  policy.guard = 0;
  policy.attempts = 4;
  policy.double_on_precision_error = false;
  const auto done = raise_precision(
      digits + 22, policy,
      [&] {
        if (b) a = std::move(b);
        b.emplace(solve(working_digits10<mpfr>(), &*a));
        return true;
      },
      [&](bool) { return Shortfall{settled(*a, *b), std::max(12, b->digits / 2)}; });
  if (!done)
    throw SolverError(context + what + ": mu did not settle to " + std::to_string(digits) + " digits (" +
                      format_significant(a->r.mu, digits + 2) + " at " + std::to_string(a->digits) + " digits, " +
                      format_significant(b->r.mu, digits + 2) + " at " + std::to_string(b->digits) + ")");
  return {std::move(*a), std::move(*b)};
}

}  // namespace vibrofric::detail
