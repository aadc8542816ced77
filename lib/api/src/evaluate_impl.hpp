// Implementation of evaluate_stream_typed<Real> (evaluate.hpp): μ̄/μ0 (Eq. 15) and Ψ (Eq. 17) of
// decimal points, correctly rounded or refused (model.md, "Domain and edge behaviour"); included
// by one .cpp per number type.
#pragma once
#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <vector>

#include <boost/math/special_functions/next.hpp>

#include "vibrofric/api/decimal.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/ladder.hpp"
#include "vibrofric/core/curved/curved.hpp"

namespace vibrofric::detail {

template <class Real>
struct PointValue {
  Real value;
  Real relative_error;
};

// β and γ of a point in Real: a decimal correctly rounded, a computed value rounded once.
template <class Real>
Real point_beta(const Point& p) {
  if (!p.beta.given()) throw InputError("beta is empty: expected a decimal number");
  return p.beta.to<Real>();
}
template <class Real>
Real point_gamma(const Point& p) {
  if (!p.gamma.given()) throw InputError("gamma is empty: expected a decimal number");
  return p.gamma.to<Real>();
}

// What names γ in the Contact caches: the text as typed, or a computed value's exact binary
// expansion (hexadecimal, never a decimal that one could take for the value).
inline std::string gamma_key(const Point& p) {
  const mpfr* v = p.gamma.computed_value();
  if (!v) return p.gamma.text();
  mpfr_exp_t exponent = 0;
  char* digits = mpfr_get_str(nullptr, &exponent, 16, 0, v->backend().data(), MPFR_RNDN);
  std::string key = std::string("0x.") + digits + "p16^" + std::to_string(exponent);
  mpfr_free_str(digits);
  return key;
}

// A wave its spec names alone (the catalogue, power:p) is the same immutable object for every
// call on a thread: built once per thread, number type and precision, with the Contacts of its
// last few γ. A caller of one point per call (the Python module, a loop over `evaluate`) then
// does not rebuild them; building them was about 28 % of a guaranteed double sine point (perf).
// Sampled and Fourier waves carry data and are built per call. Bounded: at most 64 waves and 8
// Contacts per thread and type.
template <class Real>
class ThreadWaves {
 public:
  static ThreadWaves& get() {
    thread_local ThreadWaves cache;
    return cache;
  }
  // "" for a wave built per call; else the key that names it.
  static std::string key(const WaveSpec& spec) {
    if (spec.kind == WaveKind::samples || spec.kind == WaveKind::fourier) return "";
    return spec.kind == WaveKind::power ? "power:" + spec.exponent.text() : spec.name;
  }
  std::shared_ptr<const Waveform<Real>> wave(const WaveSpec& spec, const std::string& key, int digits) {
    auto& slot = waves_[{key, digits}];
    if (!slot) {
      if (waves_.size() > 64) {  // a sweep over power:p exponents: start again rather than grow
        waves_.clear();
        return wave(spec, key, digits);
      }
      slot = make_waveform<Real>(spec);
    }
    return slot;
  }
  struct ContactEntry {
    std::string key;
    int digits;
    std::string gamma;
    std::uintmax_t budget;
    std::shared_ptr<const Contact<Real>> contact;  // owns its waveform too (WaveCache::contact)
  };
  std::shared_ptr<const Contact<Real>> find(const std::string& key, int digits, const std::string& gamma,
                                            std::uintmax_t budget) {
    for (auto it = contacts_.begin(); it != contacts_.end(); ++it)
      if (it->digits == digits && it->budget == budget && it->gamma == gamma && it->key == key) {
        if (it != contacts_.begin()) {  // most recent first
          ContactEntry e = std::move(*it);
          contacts_.erase(it);
          contacts_.push_front(std::move(e));
        }
        return contacts_.front().contact;
      }
    return nullptr;
  }
  void keep(ContactEntry e) {
    contacts_.push_front(std::move(e));
    if (contacts_.size() > 8) contacts_.pop_back();
  }

 private:
  std::map<std::pair<std::string, int>, std::shared_ptr<const Waveform<Real>>> waves_;
  std::deque<ContactEntry> contacts_;
};

// Waveforms of one call's worker, one per working precision (mpfr), built on first use or taken
// from ThreadWaves, and the Contact of the last γ (points come γ by γ, so a sweep builds each
// once).
template <class Real>
class WaveCache {
 public:
  using real_type = Real;
  explicit WaveCache(const WaveSpec& spec, const ProfileSpec& profile = {})
      : spec_(spec), profile_spec_(profile), shared_key_(ThreadWaves<Real>::key(spec)) {}
  const Waveform<Real>& get() { return *wave(); }
  // The curved profile at this precision; nullptr for the flat punch.
  const Profile<Real>* profile() {
    if (profile_spec_.kind == ProfileKind::flat) return nullptr;
    auto& slot = profiles_[working_digits10<Real>()];
    if (!slot) slot = make_profile<Real>(profile_spec_);
    return slot.get();
  }
  // The Contact at the point's γ (gamma_key); at γ = −min w, n touching zero, for Ψ (psi).
  const Contact<Real>& contact(const Point& p, bool psi, const Options& opt) {
    const std::string gamma_text = psi ? std::string() : gamma_key(p);
    const int d = working_digits10<Real>();
    if (!contact_ || digits_ != d || text_ != gamma_text || budget_ != opt.max_root_iterations) {
      contact_.reset();
      if (!shared_key_.empty())
        contact_ = ThreadWaves<Real>::get().find(shared_key_, d, gamma_text, opt.max_root_iterations);
      if (!contact_) try {
        const std::shared_ptr<const Waveform<Real>> w = wave();
        const Real gamma = psi ? Real(-w->minimum()) : point_gamma<Real>(p);
        // The Contact refers to its waveform: the pointer to it owns the waveform as well.
        struct Held {
          std::shared_ptr<const Waveform<Real>> wave;
          Contact<Real> contact;
        };
        const auto held = std::make_shared<const Held>(Held{w, make_contact(*w, gamma, opt)});
        contact_ = std::shared_ptr<const Contact<Real>>(held, &held->contact);
        if (!shared_key_.empty())
          ThreadWaves<Real>::get().keep({shared_key_, d, gamma_text, opt.max_root_iterations, contact_});
      } catch (const DomainError&) {
        // check_contact (below) found a contact from the decimal γ and the exact waveform: this
        // type's rounding of γ or of max w removed it, so a wider type must compute it.
        throw PrecisionError("gamma = " + p.gamma.text() + " leaves a contact narrower than the rounding of this number type");
      }
      digits_ = d;
      text_ = gamma_text;
      budget_ = opt.max_root_iterations;
    }
    return *contact_;
  }

 private:
  std::shared_ptr<const Waveform<Real>> wave() {
    const int d = working_digits10<Real>();
    auto& slot = by_digits_[d];
    if (!slot) {
      if (shared_key_.empty())
        slot = make_waveform<Real>(spec_);
      else
        slot = ThreadWaves<Real>::get().wave(spec_, shared_key_, d);
    }
    return slot;
  }

  const WaveSpec& spec_;
  const ProfileSpec& profile_spec_;
  std::string shared_key_;  // ThreadWaves::key: "" for a wave built per call
  std::map<int, std::shared_ptr<const Waveform<Real>>> by_digits_;
  std::map<int, std::unique_ptr<Profile<Real>>> profiles_;
  std::shared_ptr<const Contact<Real>> contact_;
  int digits_ = -1;
  std::uintmax_t budget_ = 0;
  std::string text_;
};

// A positive β that a type's range cannot hold (1e-5000 in double): bad input for that type alone.
// The ladder takes it to a wider rung, as any input the type cannot resolve, so that every type
// decides the input alike; without escalation (or in mpfr, past its exponent range) it is refused.
class UnderflowError : public InputError {
 public:
  using InputError::InputError;
};

// `target`: the relative accuracy asked of a curved contact's spring integral (0: the type's).
template <class Real>
PointValue<Real> compute_point(WaveCache<Real>& waves, Quantity q, const Point& p, const Options& opt,
                               const Real& target = Real(0)) {
  const Real beta = point_beta<Real>(p);
  // A positive β below the type's smallest number reads as 0: name what was written.
  if (const Decimal* d = p.beta.decimal(); beta == 0 && d && !d->is_zero() && !d->negative())
    throw UnderflowError("beta = '" + d->text() + "' underflows to 0 in this number type: expected a magnitude the type represents (mpfr: more digits)");
  if (const Profile<Real>* profile = waves.profile()) {
    if (q == Quantity::psi)
      throw InputError("psi with profile " + profile->name() +
                       ": Psi (Eq. 12) exists for the flat punch only; in a curved contact the outer springs always "
                       "jump, so Eq. 13's separation of alpha and beta does not exist (use mu)");
    const auto r = solve_curved(waves.get(), *profile, beta, point_gamma<Real>(p), opt, target);
    return {r.mu, r.relative_error};
  }
  const auto r = solve(waves.contact(p, q == Quantity::psi, opt), beta, opt);
  if (q == Quantity::psi) return {r.lost_area, r.lost_relative_error};
  return {r.mu, r.relative_error};
}

// One point for `digits` significant digits: mpfr raises its working precision until the error
// estimate is below half a unit in the last requested digit, and the value keeps that precision.
template <class Real>
Real evaluate_point(WaveCache<Real>& waves, const WaveSpec& spec, Quantity q, const Point& p,
                    int digits, const Options& opt) {
  if constexpr (is_runtime_precision_v<Real>) {
    RaisePolicy policy;
    policy.guard = guard_digits(digits);
    policy.max_work = 4 * max_digits;
    const auto v = raise_precision(
        digits + guard_digits(digits), policy,
        [&] { return compute_point(waves, q, p, opt, Real(pow(Real(10), -digits) / 8)); },
        [&](const PointValue<Real>& r) { return shortfall(r.relative_error, Real(pow(Real(10), -digits) / 2)); });
    if (v) return v->value;
    throw SolverError("wave " + spec.name + ", beta = " + p.beta.text() +
                      (q == Quantity::mu ? ", gamma = " + p.gamma.text() : std::string()) +
                      ": could not reach " + std::to_string(digits) + " digits (ill-conditioned)");
  } else {
    return compute_point(waves, q, p, opt).value;
  }
}

// Ziv's rounding test: x carries an absolute error of at most e; if every number in [x − e, x + e]
// rounds to the same value of T, that value is the correctly rounded result. x ± e is itself
// computed in X, so e is widened by two units of X's precision first.
template <class T, class X>
bool rounds_alike(const X& x, const X& e) {
  using std::abs;
  using std::isfinite;
  if (!isfinite(x) || !isfinite(e)) return false;
  const X wide = e + 2 * std::numeric_limits<X>::epsilon() * abs(x);
  return static_cast<T>(X(x - wide)) == static_cast<T>(X(x + wide));
}

// The first rung's test: x is itself a T, so every number within e of x rounds to x exactly when e
// is below half the gap to each neighbour of x (strictly: a midpoint rounds to even). The gaps are
// exact in T (below x they halve at a power of two); e, a product rounded once, is enlarged by
// 4 ulp of itself to cover that rounding. rounds_alike's widening by 2 ulp of x would span both
// neighbours, and no value of the type would ever be accepted as its own correct rounding.
template <class T>
bool rounds_to_itself(const T& x, const T& e) {
  using std::abs;
  using std::isfinite;
  if (!isfinite(x) || !isfinite(e) || !(abs(x) < std::numeric_limits<T>::max())) return false;
  const T up = boost::math::float_next(x) - x, down = x - boost::math::float_prior(x);
  const T bound = e * (1 + 4 * std::numeric_limits<T>::epsilon());
  return 2 * bound < up && 2 * bound < down;
}

// Whether a fixed type's own μ̄ can pass rounds_to_itself. Below β_c (Eq. 6) its bound is many eps
// (9–112 for double; hundreds for a curved contact, with its quadrature), wider than the half ulp
// the test needs; at β ≥ β_c, μ̄ = 1 is exact. The kept Contact knows β_c (a curved contact's is its
// central spring's, curved.hpp), so the solve is skipped below it (on 34,440 catalogue points in
// double and long double the own rung answered exactly those with β ≥ β_c). Anything unusual goes
// to the rung.
template <class Real>
bool own_rung_may_certify(WaveCache<Real>& waves, Quantity q, const Point& p, const Options& opt) {
  if (q != Quantity::mu) return true;
  try {
    // β that is not positive here (1e-400 underflows in double, not in long double) goes to this
    // type's rung, whose UnderflowError escalates: it is answered as in mpfr.
    const Real beta = point_beta<Real>(p);
    return !(beta > 0 && beta < waves.contact(p, false, opt).beta_c());
  } catch (const std::exception&) {
    return true;  // the rung gives the message or escalates
  }
}

// A fixed-precision type, correctly rounded: its own value where the rounding bound certifies it;
// for double next the long double value where its bound does (as Boost.Math promotes double);
// else mpfr at twice the type's digits and more, until the rounding is certified.
template <class Real>
Real evaluate_fixed(WaveCache<Real>& waves, WaveCache<long double>& wider, WaveCache<mpfr>& fallback,
                    const WaveSpec& spec, Quantity q, const Point& p, const BatchOptions& options) {
  using std::abs;
  // A rung whose precision cannot resolve the waveform (PrecisionError), or whose range cannot hold
  // β (UnderflowError), is not certified.
  auto rung = [&](auto& cache) -> std::optional<PointValue<typename std::decay_t<decltype(cache)>::real_type>> {
    try {
      return compute_point(cache, q, p, options.solver);
    } catch (const PrecisionError&) {
      if (!options.escalate) throw;
      return std::nullopt;
    } catch (const UnderflowError&) {
      if (!options.escalate) throw;
      return std::nullopt;
    }
  };
  const auto count = [&](std::atomic<std::size_t> LadderCounts::*rung_count) {
    if (options.ladder) ++(options.ladder->*rung_count);
  };
  if (!options.escalate || own_rung_may_certify(waves, q, p, options.solver))
    if (const auto v = rung(waves); v && (!options.escalate || rounds_to_itself<Real>(v->value, Real(v->relative_error * abs(v->value))))) {
      count(&LadderCounts::own);
      return v->value;
    }
  if constexpr (std::is_same_v<Real, double>) {
    const auto w = rung(wider);
    if (w && rounds_alike<double>(w->value, static_cast<long double>(w->relative_error * abs(w->value)))) {
      count(&LadderCounts::long_double);
      return static_cast<double>(w->value);
    }
  }
  count(&LadderCounts::mpfr);
  constexpr int type_digits = std::numeric_limits<Real>::max_digits10;
  if constexpr (std::is_floating_point_v<Real>) {
    // mpfr's value and bound straight into Ziv's test, no decimal in between, on the one ladder.
    // The lower rungs left a value close to a midpoint of the type, typically within 1/20 ulp: 8
    // digits beyond the type's nearly always decide it, and cost less than the 48 digits of a
    // decimal route. Ziv's test tells no shortfall, so the precision doubles, up to
    // 8·max_digits10 + 3 digits (three doublings).
    const int first = type_digits + 8;
    RaisePolicy policy;
    policy.max_work = 8 * type_digits + 3;
    policy.double_on_precision_error = false;  // rung() has taken the PrecisionErrors it may
    const auto v = raise_precision(
        first, policy, [&] { return rung(fallback); },
        [&](const auto& r) { return Shortfall{r && rounds_alike<Real>(r->value, mpfr(r->relative_error * abs(r->value))), {}}; });
    if (v) return static_cast<Real>((*v)->value);
    // Within 10^-(8·max_digits10) of a midpoint of the type, or on it: the value evaluate_point
    // gives within half a unit of its digit at the next doubling (8·first), rounded once to the type.
    return rounded<Real>(evaluate_point<mpfr>(fallback, spec, q, p, 8 * first, options.solver));
  } else {
    return rounded<Real>(evaluate_point<mpfr>(fallback, spec, q, p, 2 * type_digits + 3, options.solver));
  }
}

// Whether contact exists, γ + max w > 0 (model.md, "Domain and edge behaviour"), decided once from
// the decimal γ as written and the waveform at 60 digits or more, so that every number type gives
// the same decision (a sampled sine at γ = −1 has a contact or not by the 17th digit of its mean,
// which double rounds away). γ that is not a decimal is left to the typed path's message.
// max w at the current mpfr precision: 1 for the catalogue; for samples (hi − mean)/scale by the
// normalisation the wave itself gets (normalise_samples, streamed: a 10-million-sample file is not
// built at 60 digits); for Fourier the waveform's own maximum.
inline mpfr exact_maximum(const WaveSpec& spec) {
  if (spec.kind == WaveKind::fourier) return make_waveform<mpfr>(spec)->maximum();
  if (spec.kind != WaveKind::samples) return mpfr(1);
  const SampleNormalisation nz =
      normalise_samples(spec.name, spec.samples.size(), [&](std::size_t j) { return detail::sample_value(spec, j); },
                        detail::distinct_digits(spec), detail::sample_phase(spec), working_digits10<mpfr>());
  PrecisionScope scope(nz.digits);
  return mpfr((nz.hi - nz.mean) / nz.scale);
}

// The contact check of one worker, point by point, its state kept for the whole stream: γ checked
// last (points come γ by γ, so a sweep checks each once) and the exact max w, computed once per
// precision on first need.
class ContactCheck {
 public:
  ContactCheck(const WaveSpec& spec, Quantity q) : spec_(spec), q_(q) {}
  void operator()(const Point& p) {
    const Decimal* typed = p.gamma.decimal();
    const mpfr* computed = p.gamma.computed_value();
    if (q_ == Quantity::psi || (!typed && !computed) || (typed && typed->text() == last_)) return;
    // Clear of the boundary in double, no exact test is needed (a sweep's points stay cheap): the
    // catalogue has max w = 1, and a normalised user wave max w >= 0 (zero mean).
    const double g = p.gamma.to<double>();
    const bool catalogue = spec_.kind != WaveKind::samples && spec_.kind != WaveKind::fourier;
    if (!(g > (catalogue ? -1 + 1e-9 : 1e-9))) {
      const unsigned digits = static_cast<unsigned>(std::max<std::size_t>(60, p.gamma.text().size() + 10));
      PrecisionScope scope(digits);
      // A computed γ keeps its own precision (mpfr's sum rounds once, at the wider operand's).
      const mpfr gamma = computed ? *computed : typed->to<mpfr>();
      if (!(gamma + top() > 0))
        throw no_contact(p.gamma.text(), spec_.name, short_str(mpfr(-top())));
    }
    if (typed) last_ = typed->text();  // only a γ that passed
  }

 private:
  // max w at the current precision, computed once per precision.
  const mpfr& top() {
    if (top_digits_ != working_digits10<mpfr>()) {
      top_.reset();
      top_ = exact_maximum(spec_);
      top_digits_ = working_digits10<mpfr>();
    }
    return *top_;
  }

  const WaveSpec& spec_;
  Quantity q_;
  std::optional<mpfr> top_;
  int top_digits_ = -1;
  std::string last_;  // "" to begin with: an empty γ is left to the typed path's message
};

// One worker's state for a whole stream: the contact check and the waveform caches of every rung.
template <class Real>
class PointEvaluator {
 public:
  PointEvaluator(const WaveSpec& spec, Quantity q, int digits, const BatchOptions& options)
      : spec_(spec), q_(q), digits_(digits), options_(options), check_(spec, q), waves_(spec, options.profile),
        wider_(spec, options.profile), fallback_(spec, options.profile) {}
  // The value as a number: the type's correctly rounded value (fixed types); mpfr's at the working
  // precision that decides its `digits` digits.
  Real value(const Point& p) {
    check_(p);
    if (options_.rig) return rig(p);
    if (options_.inplane && !papers_model(*options_.inplane)) return inplane(p);
    if constexpr (is_runtime_precision_v<Real>)
      return evaluate_point<Real>(waves_, spec_, q_, p, digits_, options_.solver);
    else
      return evaluate_fixed(waves_, wider_, fallback_, spec_, q_, p, options_);
  }
  // Rig dynamics: the value decided in mpfr, rounded to the type (exactly its value for fixed types).
  Real rig(const Point& p) const {
    if (q_ == Quantity::psi)
      throw InputError("rig dynamics gives mu only: Psi (Eq. 12) belongs to the quasi-static model");
    if (options_.profile.kind != ProfileKind::flat) {
      // the row's value with the digits its two sizes agree on: printed as they are
      const Significant v = row_rig_value(spec_, p, *options_.rig, options_.profile, precision(), options_.solver);
      row_text_ = v.text();
      return decided(v.value);
    }
    return decided(rig_value(spec_, p, *options_.rig, precision(), options_.solver));
  }
  // In-plane oscillation: the same, from the in-plane solver.
  Real inplane(const Point& p) const {
    if (q_ == Quantity::psi)
      throw InputError("in-plane oscillation gives mu only: Psi (Eq. 12) belongs to the normal oscillation alone");
    return decided(inplane_value(spec_, p, *options_.inplane, precision(), options_.solver, options_.profile));
  }
  // This worker's type and digits as a Precision, and a value decided in mpfr as this type holds it.
  Precision precision() const {
    Precision precision{NumberType::mpfr, digits_};
    if constexpr (std::is_same_v<Real, double>) precision.type = NumberType::float64;
    if constexpr (std::is_same_v<Real, long double>) precision.type = NumberType::float80;
    if constexpr (std::is_same_v<Real, bin50>) precision.type = NumberType::bin50;
    if constexpr (std::is_same_v<Real, bin100>) precision.type = NumberType::bin100;
    return precision;
  }
  static Real decided(const mpfr& v) {
    if constexpr (is_runtime_precision_v<Real>) return v;
    else return rounded<Real>(v);
  }
  StreamValue operator()(const Point& p) {
    row_text_.clear();
    const Real v = value(p);
    StreamValue out{row_text_.empty() ? format_significant(v, digits_) : row_text_, std::nullopt, nullptr};
    if constexpr (std::is_same_v<Real, double> || std::is_same_v<Real, long double>) out.number = v;
    return out;
  }

 private:
  const WaveSpec& spec_;
  Quantity q_;
  int digits_;
  const BatchOptions& options_;
  ContactCheck check_;
  WaveCache<Real> waves_;
  WaveCache<long double> wider_;
  WaveCache<mpfr> fallback_;
  mutable std::string row_text_;  // the last curved rig's value as printed (its agreed digits)
};

// evaluate_one (evaluate.hpp): a fixed type's value copied into an mpfr with more bits, exactly.
template <class Real>
Evaluated evaluate_one_typed(const WaveSpec& spec, Quantity q, const Point& point, int digits, const BatchOptions& options) {
  PointEvaluator<Real> evaluator(spec, q, digits, options);
  const Real v = evaluator.value(point);
  if constexpr (is_runtime_precision_v<Real>) {
    return {format_significant(v, digits), v};
  } else {
    PrecisionScope scope(static_cast<unsigned>(std::numeric_limits<Real>::max_digits10 + 2));
    return {format_significant(v, digits), mpfr(v)};
  }
}

// The streaming core under evaluate() and evaluate_stream() (evaluate.hpp).
//
// One thread: point by point on the calling thread, each delivered before the next is computed.
// More: `threads` workers claim points one at a time from a shared counter (as the batch did) and
// write each value into a ring of threads × stream_chunk slots, slot i mod size; the calling
// thread delivers slot after slot in index order. A worker that claims a point a whole ring ahead
// of the next undelivered one waits until that slot is delivered: memory is the ring, whatever
// count is. Slots publish their index + 1 (release) once written, so the ring is never cleared.
// Not oneTBB's parallel_pipeline: as fast as this ring, but Debian ships it as a shared library
// only, and the dynamic tool measured 10-45 % slower on two-thread streams (bench/results/tbb_stream).
// Waits use one mutex and two condition variables; the fast paths are atomics only, and a side
// notifies the other only when it announced that it waits (announcement and publication are both
// sequentially consistent, so one of them sees the other).
template <class Real>
void evaluate_stream_typed(const WaveSpec& spec, Quantity q, std::size_t count,
                           const std::function<Point(std::size_t)>& point, int digits, const BatchOptions& options,
                           const std::function<void(std::size_t, const StreamValue&)>& sink) {
  if (count == 0) return;
  unsigned threads = options.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : options.threads;
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, count));
  std::atomic<std::size_t> done{0};
  // Point i's value, or its error (its own, its generator's or its progress report's).
  auto compute = [&](PointEvaluator<Real>& evaluator, std::size_t i, StreamValue& value, std::exception_ptr& error) {
    error = nullptr;
    try {
      value = evaluator(point(i));
    } catch (...) {
      if (options.deliver_errors) {
        value = StreamValue{};
        value.error = std::current_exception();
      } else {
        error = std::current_exception();
      }
    }
    const std::size_t d = ++done;
    try {
      if (options.progress) options.progress(d);
    } catch (...) {
      if (!error) error = std::current_exception();
    }
  };

  if (threads <= 1) {
    PointEvaluator<Real> evaluator(spec, q, digits, options);
    StreamValue value;
    for (std::size_t i = 0; i < count; ++i) {
      std::exception_ptr error;
      compute(evaluator, i, value, error);
      if (error) std::rethrow_exception(error);
      sink(i, value);
    }
    return;
  }

  struct Slot {
    std::atomic<std::size_t> filled{0};  // index + 1 of the point written here, 0 before any
    StreamValue value;
    std::exception_ptr error;
  };
  const std::size_t size = std::min<std::size_t>(count, std::size_t{threads} * stream_chunk);
  const std::size_t notify_step = std::max<std::size_t>(1, size / 8);
  const std::unique_ptr<Slot[]> ring(new Slot[size]);
  constexpr std::size_t nobody = static_cast<std::size_t>(-1);
  std::atomic<std::size_t> next{0};               // the next point to claim
  std::atomic<std::size_t> head{0};               // the next point to deliver
  std::atomic<std::size_t> awaited{nobody};       // the point the calling thread waits for
  std::atomic<unsigned> waiting_workers{0};       // workers waiting for a free slot
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable slot_freed, point_done;

  auto worker = [&] {
    PointEvaluator<Real> evaluator(spec, q, digits, options);
    for (;;) {
      const std::size_t i = next++;
      if (i >= count || stop.load(std::memory_order_relaxed)) return;
      if (i >= head.load() + size) {
        std::unique_lock<std::mutex> lock(mutex);
        ++waiting_workers;
        slot_freed.wait(lock, [&] { return stop.load() || i < head.load() + size; });
        --waiting_workers;
        if (stop.load()) return;
      }
      Slot& slot = ring[i % size];
      compute(evaluator, i, slot.value, slot.error);
      slot.filled.store(i + 1);
      if (awaited.load() == i) {
        std::lock_guard<std::mutex> lock(mutex);
        point_done.notify_one();
      }
    }
  };

  // Stops and joins the workers on every way out, the sink's exceptions included.
  struct Pool {
    std::vector<std::thread> threads;
    std::atomic<bool>& stop;
    std::mutex& mutex;
    std::condition_variable& slot_freed;
    ~Pool() {
      {
        std::lock_guard<std::mutex> lock(mutex);
        stop.store(true);
        slot_freed.notify_all();
      }
      for (auto& t : threads) t.join();
    }
  } pool{{}, stop, mutex, slot_freed};
  pool.threads.reserve(threads);
  for (unsigned t = 0; t < threads; ++t) pool.threads.emplace_back(worker);

  for (std::size_t h = 0; h < count; ++h) {
    Slot& slot = ring[h % size];
    if (slot.filled.load(std::memory_order_acquire) != h + 1) {
      std::unique_lock<std::mutex> lock(mutex);
      if (waiting_workers.load() > 0) slot_freed.notify_all();  // the notices skipped below
      awaited.store(h);
      point_done.wait(lock, [&] { return slot.filled.load() == h + 1; });
      awaited.store(nobody);
    }
    if (slot.error) std::rethrow_exception(slot.error);  // Pool's destructor stops and joins
    sink(h, slot.value);
    head.store(h + 1);
    if ((h + 1) % notify_step == 0 && waiting_workers.load() > 0) {
      std::lock_guard<std::mutex> lock(mutex);
      slot_freed.notify_all();
    }
  }
}

}  // namespace vibrofric::detail

#define VIBROFRIC_INSTANTIATE_EVALUATE(Real)                                                     \
  template void vibrofric::detail::evaluate_stream_typed<Real>(                                 \
      const WaveSpec&, Quantity, std::size_t, const std::function<Point(std::size_t)>&, int,    \
      const BatchOptions&, const std::function<void(std::size_t, const StreamValue&)>&);        \
  template vibrofric::Evaluated vibrofric::detail::evaluate_one_typed<Real>(                     \
      const WaveSpec&, Quantity, const Point&, int, const BatchOptions&);
