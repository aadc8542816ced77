// Concurrency (issue #7): evaluations at different mpfr precisions on several threads at once give
// exactly — byte for byte — the values of sequential runs. Boost 1.81 keeps the default mpfr
// precision per thread (toolchain.md); the solver's per-thread state (the tanh-sinh integrators,
// keyed by precision, and the Sine's sin/cos cache) must respect it.
//
// Cases: the exact-area path (sine, samples), root finding (a Fourier series: pieces from the root
// search over w' and w'', stick ends by Newton), and the quadrature area path (tanh-sinh), at 20,
// 50, 100 and 300 digits (quadrature up to 100: its 300-digit tables take seconds to build per
// thread). Three ways in: solve() on std::threads with a PrecisionScope each, one waveform per
// precision shared read-only by all threads, and evaluate(..., threads = N) called from several
// threads at once (nested pools). The reference is the same computation run sequentially first.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace {

using namespace vibrofric;
using robustness::ScratchFile;

const char* const kFourier = "1 0 1\n2 0.3 0.1\n3 0 0.2\n5 0.05 -0.02\n";
const char* const kSamples = "0 1 3 2 -1 -2 -1 0.5\n";

struct Case {
  std::string wave, beta, gamma;  // gamma "" : Ψ
  AreaMethod area;
  int max_digits;  // highest precision this case runs at
};

std::vector<Case> cases(const std::string& fourier, const std::string& samples) {
  return {{"sine", "1", "0.5", AreaMethod::automatic, 300},
          {"sine", "0.3", "2", AreaMethod::automatic, 300},
          {"sine", "1", "", AreaMethod::automatic, 300},
          {"power:2.5", "1.5", "-0.3", AreaMethod::automatic, 300},
          {"fourier:" + fourier, "1", "0.5", AreaMethod::automatic, 300},
          {"fourier:" + fourier, "2.5", "1.2", AreaMethod::automatic, 100},
          {"samples:" + samples, "1", "0.2", AreaMethod::automatic, 300},
          {"sine", "0.7", "-0.2", AreaMethod::quadrature, 100},
          {"power:2.5", "1.5", "-0.3", AreaMethod::quadrature, 100},
          {"fourier:" + fourier, "1", "0.5", AreaMethod::quadrature, 50}};
}

std::vector<int> precisions() { return robustness::kSanitized ? std::vector<int>{20, 50, 100} : std::vector<int>{20, 50, 100, 300}; }

// Every bit of an mpfr value: its precision and its exact binary digits (mpfr_get_str with 0 digits
// gives enough to round-trip, in base 16 exactly).
std::string bits(const mpfr& x) {
  mpfr_exp_t e = 0;
  char* s = mpfr_get_str(nullptr, &e, 16, 0, x.backend().data(), MPFR_RNDN);
  std::string out = std::to_string(mpfr_get_prec(x.backend().data())) + ":" + s + "@" + std::to_string(e);
  mpfr_free_str(s);
  return out;
}

// The value of one (case, precision) by solve(): μ or Ψ, its error bound and event counts.
std::string direct(const Waveform<mpfr>& w, const Case& c) {
  Options o;
  o.area = c.area;
  const mpfr beta(c.beta);
  const Result<mpfr> r = c.gamma.empty() ? psi(w, beta, o) : solve(w, beta, mpfr(c.gamma), o);
  return bits(c.gamma.empty() ? r.lost_area : r.mu) + " err " + bits(c.gamma.empty() ? r.lost_relative_error : r.relative_error) +
         " events " + std::to_string(r.events) + " roots " + std::to_string(r.root_iterations);
}

std::string through_evaluate(const Case& c, int digits, unsigned threads) {
  BatchOptions o;
  o.solver.area = c.area;
  o.threads = threads;
  return evaluate(parse_wave(c.wave), c.gamma.empty() ? Quantity::psi : Quantity::mu, {{c.beta, c.gamma}},
                  {NumberType::mpfr, digits}, o)
      .front();
}

struct Job {
  std::size_t c;
  int digits;
};

class Concurrency : public ::testing::Test {
 protected:
  // The reference, once for the suite: sequential, on the main thread.
  static void SetUpTestSuite() {
    fourier_ = new ScratchFile(kFourier);
    samples_ = new ScratchFile(kSamples);
    all_ = cases(fourier_->path(), samples_->path());
    for (std::size_t i = 0; i < all_.size(); ++i)
      for (int d : precisions())
        if (d <= all_[i].max_digits) jobs_.push_back({i, d});
    for (const Job& j : jobs_) {
      PrecisionScope scope(static_cast<unsigned>(j.digits));
      const auto w = make_waveform<mpfr>(parse_wave(all_[j.c].wave));
      direct_[key(j)] = direct(*w, all_[j.c]);
      evaluated_[key(j)] = through_evaluate(all_[j.c], j.digits, 1);
    }
  }
  static void TearDownTestSuite() {
    delete fourier_;
    delete samples_;
  }
  static std::pair<std::size_t, int> key(const Job& j) { return {j.c, j.digits}; }
  static std::string describe(const Job& j) {
    const Case& c = all_[j.c];
    return c.wave + " beta " + c.beta + " gamma " + (c.gamma.empty() ? "(psi)" : c.gamma) +
           (c.area == AreaMethod::quadrature ? " quadrature" : "") + " at " + std::to_string(j.digits) + " digits";
  }

  static inline ScratchFile* fourier_ = nullptr;
  static inline ScratchFile* samples_ = nullptr;
  static inline std::vector<Case> all_;
  static inline std::vector<Job> jobs_;
  static inline std::map<std::pair<std::size_t, int>, std::string> direct_, evaluated_;
};

// T threads, each over every (case, precision) in its own random order: solve() with the
// thread's PrecisionScope and its own waveforms, and evaluate(threads = 1).
TEST_F(Concurrency, ThreadsAtMixedPrecisionsMatchSequentialRuns) {
  const unsigned n_threads = 4;
  const int rounds = 1;
  std::atomic<long> compared{0}, mismatches{0};
  std::mutex m;
  std::vector<std::string> report;
  const unsigned global_before = mpfr::default_precision();
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < n_threads; ++t)
    pool.emplace_back([&, t] {
      std::mt19937 rng(1000 + t);
      const unsigned mine = mpfr::thread_default_precision();
      for (int round = 0; round < rounds; ++round) {
        std::vector<Job> order = jobs_;
        std::shuffle(order.begin(), order.end(), rng);
        for (const Job& j : order) {
          std::string d, e;
          {
            PrecisionScope scope(static_cast<unsigned>(j.digits));
            const auto w = make_waveform<mpfr>(parse_wave(all_[j.c].wave));
            d = direct(*w, all_[j.c]);
          }
          e = through_evaluate(all_[j.c], j.digits, 1);
          compared += 2;
          if (d != direct_.at(key(j)) || e != evaluated_.at(key(j))) {
            ++mismatches;
            std::lock_guard<std::mutex> lock(m);
            report.push_back(describe(j) + " on thread " + std::to_string(t) + ":\n  solve    " + d + "\n  expected " +
                             direct_.at(key(j)) + "\n  evaluate " + e + "\n  expected " + evaluated_.at(key(j)));
          }
          if (mpfr::thread_default_precision() != mine) {
            ++mismatches;
            std::lock_guard<std::mutex> lock(m);
            report.push_back("thread precision changed after " + describe(j));
          }
        }
      }
    });
  for (auto& t : pool) t.join();
  for (const auto& r : report) ADD_FAILURE() << r;
  std::printf("[ concurrency ] %u threads x %d rounds: %ld values compared byte for byte, %ld mismatches\n", n_threads, rounds,
              compared.load(), mismatches.load());
  EXPECT_EQ(mismatches.load(), 0);
  EXPECT_EQ(mpfr::default_precision(), global_before);
}

// One waveform per precision, built once and shared (read-only) by every thread, each thread at
// the matching precision: a const Waveform may be used concurrently.
TEST_F(Concurrency, SharedWaveformsAcrossThreads) {
  std::map<std::pair<std::size_t, int>, std::unique_ptr<Waveform<mpfr>>> shared;
  for (const Job& j : jobs_) {
    PrecisionScope scope(static_cast<unsigned>(j.digits));
    shared[key(j)] = make_waveform<mpfr>(parse_wave(all_[j.c].wave));
  }
  std::atomic<long> compared{0}, mismatches{0};
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < 4; ++t)
    pool.emplace_back([&, t] {
      std::mt19937 rng(2000 + t);
      std::vector<Job> order = jobs_;
      std::shuffle(order.begin(), order.end(), rng);
      for (const Job& j : order) {
        PrecisionScope scope(static_cast<unsigned>(j.digits));
        ++compared;
        if (direct(*shared.at(key(j)), all_[j.c]) != direct_.at(key(j))) ++mismatches;
      }
    });
  for (auto& t : pool) t.join();
  std::printf("[ concurrency ] shared waveforms, 4 threads: %ld values compared, %ld mismatches\n", compared.load(), mismatches.load());
  EXPECT_EQ(mismatches.load(), 0);
}

// evaluate() with its own pool (threads = 3), called from 4 threads at once, each at a different
// precision, on a β sweep: the same strings as evaluate(threads = 1) on one thread.
TEST_F(Concurrency, NestedEvaluatePoolsAtDifferentPrecisions) {
  std::vector<Point> points;
  for (const char* g : {"-0.5", "0.3", "1.5"})
    for (int i = 1; i <= 8; ++i) points.push_back({robustness::dyadic(7 * i, 3), g});
  struct Batch {
    std::string wave;
    AreaMethod area;
    int digits;
  };
  const std::vector<Batch> batches{{"sine", AreaMethod::automatic, 20},
                                   {"fourier:" + fourier_->path(), AreaMethod::automatic, 50},
                                   {"power:2.5", AreaMethod::quadrature, 30},
                                   {"samples:" + samples_->path(), AreaMethod::automatic, robustness::kSanitized ? 100 : 300}};
  std::vector<std::vector<std::string>> want;
  for (const Batch& b : batches) {
    BatchOptions o;
    o.solver.area = b.area;
    want.push_back(evaluate(parse_wave(b.wave), Quantity::mu, points, {NumberType::mpfr, b.digits}, o));
  }
  std::vector<std::vector<std::string>> got(batches.size());
  std::vector<std::thread> pool;
  for (std::size_t i = 0; i < batches.size(); ++i)
    pool.emplace_back([&, i] {
      BatchOptions o;
      o.solver.area = batches[i].area;
      o.threads = 3;
      got[i] = evaluate(parse_wave(batches[i].wave), Quantity::mu, points, {NumberType::mpfr, batches[i].digits}, o);
    });
  for (auto& t : pool) t.join();
  long compared = 0;
  for (std::size_t i = 0; i < batches.size(); ++i) {
    ASSERT_EQ(got[i].size(), want[i].size());
    for (std::size_t k = 0; k < points.size(); ++k, ++compared)
      EXPECT_EQ(got[i][k], want[i][k]) << batches[i].wave << " at " << batches[i].digits << " digits, beta " << points[k].beta
                                       << " gamma " << points[k].gamma;
  }
  std::printf("[ concurrency ] %zu nested evaluate pools x 3 threads: %ld values compared\n", batches.size(), compared);
}

// The fixed types too: double (escalating through long double and mpfr on worker threads),
// long double and cpp_bin_float_50 from several threads at once against one thread.
TEST_F(Concurrency, FixedTypesWithEscalationOnThreads) {
  // β → 0 and γ → −1 are where double escalates to mpfr on the worker threads (sine); the
  // Fourier series (max w ≈ 0.92) at ordinary points.
  std::vector<std::pair<WaveSpec, std::vector<Point>>> batches;
  std::vector<Point> sine_points, fourier_points;
  for (const char* b : {"0.001", "0.5", "3", "1e-7"}) {
    for (const char* g : {"-0.999999", "-0.3", "0.5", "4"}) sine_points.push_back({b, g});
    for (const char* g : {"-0.5", "0.5", "4"}) fourier_points.push_back({b, g});
  }
  batches.emplace_back(parse_wave("sine"), sine_points);
  batches.emplace_back(parse_wave("fourier:" + fourier_->path()), fourier_points);
  long compared = 0;
  for (const auto& batch : batches) {
    const WaveSpec& spec = batch.first;  // (not a structured binding: lambdas capture it, C++17)
    const std::vector<Point>& points = batch.second;
    for (NumberType t : {NumberType::float64, NumberType::float80, NumberType::bin50}) {
      const auto want = evaluate(spec, Quantity::mu, points, {t, 0});
      std::vector<std::vector<std::string>> got(3);
      std::vector<std::thread> pool;
      for (std::size_t i = 0; i < got.size(); ++i)
        pool.emplace_back([&, i] {
          BatchOptions o;
          o.threads = 2;
          got[i] = evaluate(spec, Quantity::mu, points, {t, 0}, o);
        });
      for (auto& th : pool) th.join();
      for (const auto& g : got) {
        EXPECT_EQ(g, want) << spec.name << " " << number_type_name(t);
        compared += static_cast<long>(g.size());
      }
    }
  }
  std::printf("[ concurrency ] fixed types with escalation, 3 threads x 2 workers: %ld values compared\n", compared);
}

}  // namespace
