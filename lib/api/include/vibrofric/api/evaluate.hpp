// Evaluation at a requested precision, from decimal strings to decimal strings: the layer under
// the `vibrofric` tool. μ̄/μ0 (Eq. 15; curved profiles by MDR, model.md) or Ψ_w(β) (Eq. 12) for a
// batch of points, in parallel.
//
// For mpfr the working precision is the requested digits plus guard digits, raised
// automatically while the solver's error estimate says the requested digits are not reached.
#pragma once
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/inplane.hpp"
#include "vibrofric/api/input_value.hpp"
#include "vibrofric/api/limits.hpp"
#include "vibrofric/api/number_type.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/api/rig.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric {

enum class Quantity { mu, psi };

// A point: β and γ each a decimal as written or a computed value (InputValue). Text is read where
// it enters: Point{"0.5", "-0.2"} reads both (InputError naming beta or gamma outside the grammar).
struct Point {
  Point() = default;
  Point(InputValue beta_value, InputValue gamma_value = {}) : beta(std::move(beta_value)), gamma(std::move(gamma_value)) {}
  Point(const std::string& beta_text, const std::string& gamma_text = {})
      : beta(InputValue::read(beta_text, "beta")),
        gamma(gamma_text.empty() ? InputValue() : InputValue::read(gamma_text, "gamma")) {}
  Point(const char* beta_text, const char* gamma_text = "") : Point(std::string(beta_text), std::string(gamma_text)) {}
  InputValue beta;
  InputValue gamma;  // none for Quantity::psi
};

// Which rung of the fixed types' ladder (detail::evaluate_fixed) answered each point: the value
// computed in the type itself, the long double value (double only), or mpfr rounded to the type.
// Points computed without escalation count as `own`.
struct LadderCounts {
  std::atomic<std::size_t> own{0}, long_double{0}, mpfr{0};
};

struct BatchOptions {
  Options solver;
  // The indenter (model.md, MDR): flat (the paper's flat punch) or a curved profile, whose μ̄
  // integrates flat-punch springs (curved.hpp). Ψ exists for the flat punch only.
  ProfileSpec profile;
  // Hardware and fixed types: where the solver's rounding bound exceeds the type's epsilon
  // (β → 0, γ → −min w), recompute with mpfr and round to the type (like Boost.Math's
  // promote_double). Off: the value computed in the type, whatever its error.
  bool escalate = true;
  unsigned threads = 1;                               // 0: all cores
  LadderCounts* ladder = nullptr;                     // counted where non-null (fixed types)
  std::function<void(std::size_t done)> progress;     // called from worker threads, may be empty
  // evaluate_stream: a point's error (bad input, no contact, the solver's) goes to the sink in
  // StreamValue::error, and the points after it are computed, instead of ending the stream.
  bool deliver_errors = false;
  // Rig dynamics (rig.hpp, model.md): μ̄/μ0 of a body of mass m on a system spring instead of the
  // paper's quasi-static model (none: the paper's model, unchanged). Flat punch and μ only.
  std::optional<RigSpec> rig;
  // In-plane oscillation (inplane.hpp, model.md): the drive's longitudinal oscillation (none, or
  // the paper's model: the paper's solver, unchanged). Flat punch and μ only.
  std::optional<InPlaneSpec> inplane;
};

// Formatted values, in the order of `points`. Throws the error of the first failing point
// (InputError for bad input or domain, SolverError if the solver failed). Holds every value until
// the end: for large batches use evaluate_stream. A catalogue or power:p wave, and its Contacts
// for the last 8 γ, stay on the calling (or worker) thread for the next call, per number type and
// precision (at most 64 waves): a loop of one-point calls does not rebuild them.
std::vector<std::string> evaluate(const WaveSpec& wave, Quantity q, const std::vector<Point>& points,
                                  const Precision& precision, const BatchOptions& options = {});

// One point's result as evaluate_stream delivers it: the printed digits (evaluate()'s string) and,
// for double and long double, the value itself, held exactly, so that a front end storing numbers
// does not parse the text back. The other types' result is their decimal text (D correct digits).
struct StreamValue {
  std::string text;
  std::optional<long double> number;  // double and long double only
  std::exception_ptr error;           // with BatchOptions::deliver_errors: the point's error (no text)
};

// The values of points 0 … count − 1, each passed to the sink as soon as it and every point before
// it are done, with memory bounded independently of count (evaluate() is this with a vector).
//  - point(i) makes point i on demand. With options.threads other than 1 it is called from the
//    worker threads, concurrently: it must be thread-safe. Each index is asked for once.
//  - sink(i, value) is called on the calling thread for i = 0, 1, …, count − 1 in that order.
//  - Memory: a window of options threads × stream_chunk points is in flight (points claimed
//    ahead of the oldest undelivered one wait for it), plus each worker's waveform caches, which
//    live for the whole stream.
//  - Texts are identical, string for string, to evaluate()'s for the same point and options.
//  - Errors (without options.deliver_errors, which hands each point's to the sink instead): the
//    error of the first failing point by index (as evaluate(); an exception thrown by
//    point(i) or by options.progress after point i counts as point i's) is thrown after the rows
//    before it were delivered, and no row after it is. An exception thrown by the sink stops the
//    stream and propagates. Either way the workers are joined before evaluate_stream returns.
//  - options.progress is called once per point computed (from the workers), with a count of
//    points done that grows by one per call; calls from different workers may arrive out of order.
void evaluate_stream(const WaveSpec& wave, Quantity q, std::size_t count,
                     const std::function<Point(std::size_t)>& point, const Precision& precision,
                     const BatchOptions& options, const std::function<void(std::size_t, const StreamValue&)>& sink);

// One point's printed value and the value itself, for a caller that computes on with it (physical's
// μ = μ0 · μ̄/μ0) instead of parsing the text: the fixed types' value held exactly, mpfr's at the
// working precision that decided its digits. The same checks, ladder and text as evaluate().
struct Evaluated {
  std::string text;
  mpfr value;
};
Evaluated evaluate_one(const WaveSpec& wave, Quantity q, const Point& point, const Precision& precision,
                       const BatchOptions& options = {});

// Points in flight per worker thread in evaluate_stream (the memory bound's chunk).
inline constexpr std::size_t stream_chunk = 4096;

namespace detail {
// One instantiation per number type, each in its own translation unit (compile cost).
template <class Real>
void evaluate_stream_typed(const WaveSpec& wave, Quantity q, std::size_t count,
                           const std::function<Point(std::size_t)>& point, int digits, const BatchOptions& options,
                           const std::function<void(std::size_t, const StreamValue&)>& sink);
template <class Real>
Evaluated evaluate_one_typed(const WaveSpec& wave, Quantity q, const Point& point, int digits, const BatchOptions& options);
}  // namespace detail

}  // namespace vibrofric
