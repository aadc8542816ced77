// The one loop that raises a precision until an answer is decided (README, "Precision"): every
// escalation of vibrofric runs through escalate(), in core (a sampled wave's normalisation) and in
// the API (the point ladder's mpfr rung, raise_precision in api/ladder.hpp; the rig's two
// precisions; the curved trace's rows; certification's and the claims' bit doubling).
#pragma once
#include <optional>

namespace vibrofric {

// attempt(work) returns the answer, or none where `work` (digits or bits: the caller's unit) did not
// decide it; next(work) gives the precision to try next, or none to stop. None where it stops
// undecided: the caller names its case in the error it raises.
template <class Attempt, class Next>
auto escalate(long work, Attempt attempt, Next next) -> decltype(attempt(work)) {
  for (;;) {
    if (auto r = attempt(work)) return r;
    const std::optional<long> w = next(work);
    if (!w) return {};
    work = *w;
  }
}

// Doubling from `first` up to `most` (inclusive): escalate's most common next().
inline auto doubling_up_to(long most) {
  return [most](long work) -> std::optional<long> {
    if (2 * work > most) return std::nullopt;
    return 2 * work;
  };
}

}  // namespace vibrofric
