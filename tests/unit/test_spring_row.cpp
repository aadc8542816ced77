// The naive spring-row simulation (spring_row.hpp) against the curved-contact solver
// (curved.hpp, solve_curved) and the closed forms that hold for every profile (model.md,
// "Curved contacts (MDR)"; issue: "Second algorithm: a direct time-stepping simulation of the
// row of MDR springs").
//
// The row's error bound, used by every comparison below (derived, then checked by measurement):
//
//   |μ_row − μ| ≤ B = h (β + K_w) S / ∫N dx + h²,     h = 1/N, M = N springs,
//
// S = the row's stick_integral (∫ fraction of the period in stick dx), ∫N dx = its
// normal_integral, K_w = the largest one-sided slope |w'| at a kink or jump of w (0 for sine and
// power:p > 1, 4 for the triangle, 2 for the sawtooths, 0 for the square). Why: each spring's
// time-stepped steady state is the envelope of n over the steps only (baseline.hpp), which lies
// above the true envelope, and by at most (β + K_w) h: a stick that starts at first contact or
// at a jump between two steps is anchored one step early (lag ≤ βh), one that starts at a kink
// of w is anchored at a neighbouring step (lag ≤ (β + |w'|) h), a smooth onset (w' = β, Eq. 4)
// lags by O(h²). The lag is confined to the stick phases, hence S; on a grid through the
// catalogue's kinks (φ = 0, 1/4, 1/2, 3/4, N a multiple of 4) the rectangle rule for ∫s and ∫n
// is O(h²). The h² term is an allowance for those second-order remainders. The midpoint rule
// in x (order 2 for power laws, 3/2 for the wear flat and measured profiles, whose σ has
// square-root onsets) is not bounded separately: at M = 1024 it is measured ≤ 2e-5, against B
// of order 1e-3, and lies within the measured slack below. Also one-sided: μ_row ≥ μ − h².
//
// Measured (random profiles, all catalogue waves, β ∈ (0.2, 8), γ ∈ (−0.9, 2.5), M = N = 1024):
// |μ_row − μ|/B at most 0.60, μ_row − μ never negative. Convergence with M = N refined together:
// order 0.99–1.05 (M = N = 64 … 1024, 8 grid offsets; sine, triangle, square on sphere, cone,
// wear flat, measured profile; jumping and non-jumping γ), the O(h) onset lag of the outer
// springs, which always jump, dominating. The midpoint rule in x alone (SeparateOrdersFull):
// order 2.0–2.6 for power laws, 1.4–1.7 for the wear flat and the measured profile, exact where
// every spring has the same Φ/N (triangle, γ ≤ 1).
#include <gtest/gtest.h>

#include "fitted_order.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/verification/spring_row.hpp"

namespace {

using namespace vibrofric;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A measured profile written to a scratch file ('r f' lines), removed on destruction.
class ProfileFile {
 public:
  ProfileFile(const std::vector<double>& r, const std::vector<double>& f) {
    const char* dir = std::getenv("TMPDIR");
    std::string pattern = std::string(dir && *dir ? dir : "/tmp") + "/vibrofric-spring-row-XXXXXX";
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("mkstemp failed for " + pattern);
    ::close(fd);
    path_ = pattern;
    std::ofstream out(path_);
    char line[96];
    for (std::size_t j = 0; j < r.size(); ++j) {
      std::snprintf(line, sizeof line, "%.17g %.17g\n", r[j], f[j]);
      out << line;
      text_ += line;
    }
    if (!out) throw std::runtime_error("cannot write " + path_);
  }
  ~ProfileFile() { std::remove(path_.c_str()); }
  ProfileFile(const ProfileFile&) = delete;
  ProfileFile& operator=(const ProfileFile&) = delete;
  std::string spec() const { return "profile:" + path_; }
  // The samples as one line, for reproducers.
  std::string samples() const {
    std::string s = text_;
    std::replace(s.begin(), s.end(), '\n', ';');
    return "{" + s + "}";
  }

 private:
  std::string path_, text_;
};

// The measured profile of the convergence test: a flat centre (r < 0.3), then slopes 0.125,
// 0.85, 2.29, 3.82 (convex, so σ is increasing: see RandomProfile).
ProfileFile measured_profile() { return ProfileFile({0, 0.3, 0.7, 1.23, 1.71, 2.6}, {0, 0, 0.05, 0.5, 1.6, 5}); }

// K_w: the largest one-sided |w'| at a breakpoint where w jumps or its slope does.
double kink_slope(const Waveform<double>& w) {
  double k = 0;
  const std::size_t n = w.piece_count();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = (i + n - 1) % n;
    const double left = w.end_slope(before), right = w.begin_slope(i);
    if (w.jump_at(i) || std::abs(left - right) > 1e-9 * (1 + std::abs(left)))
      k = std::max({k, std::abs(left), std::abs(right)});
  }
  return k;
}

// B of the file header.
double row_bound(const SpringRowResult<double>& r, double beta, double k_w) {
  const double h = 1.0 / r.steps;
  return h * (beta + k_w) * r.stick_integral / r.normal_integral + h * h;
}

// μ̄/μ0 by solve_curved at `digits` decimal digits, as a double.
double reference_mu(const std::string& wave, const ProfileSpec& spec, double beta, double gamma, unsigned digits) {
  PrecisionScope precision(digits);
  const auto w = make_waveform<mpfr>(parse_wave(wave));
  const auto p = make_profile<mpfr>(spec);
  return static_cast<double>(solve_curved<mpfr>(*w, *p, mpfr(beta), mpfr(gamma)).mu);
}

// A random convex measured profile: 3–8 samples, r steps in [0.2, 1], slopes sorted ascending
// (a flat centre one time in four), heights scaled so that the profile ends at σ between 1.05
// and 3 times γ + max w. Convex on purpose: a slope that decreases at a sample radius r_j makes
// σ(x) = g(x)/A decrease just beyond r_j (its square-root onset has the coefficient
// m_j − m_{j−1} < 0), and then x ↦ σ is not the monotone map the MDR row needs.
struct RandomProfile {
  std::vector<double> r, f;
};
RandomProfile random_profile(std::mt19937& rng, double sigma_max) {
  std::uniform_real_distribution<double> u(0, 1);
  const int m = 3 + static_cast<int>(rng() % 6);
  RandomProfile p;
  p.r.push_back(0);
  std::vector<double> slope;
  for (int j = 1; j < m; ++j) {
    p.r.push_back(p.r.back() + 0.2 + 0.8 * u(rng));
    slope.push_back(u(rng));
  }
  std::sort(slope.begin(), slope.end());
  if (u(rng) < 0.25) slope.front() = 0;
  if (!(slope.back() > 0)) slope.back() = 1;
  p.f.push_back(0);
  for (int j = 1; j < m; ++j) p.f.push_back(p.f.back() + slope[j - 1] * (p.r[j] - p.r[j - 1]));
  const MeasuredProfile<double> probe(p.r, p.f, "probe");
  const double scale = sigma_max * (1.05 + 1.95 * u(rng)) / probe.sigma_limit();
  for (double& v : p.f) v *= scale;
  return p;
}

std::string random_wave(std::mt19937& rng) {
  static const std::array<const char*, 6> names{"sine", "triangle", "sawtooth-right", "sawtooth-left", "square", "power"};
  const std::string w = names[rng() % names.size()];
  if (w != "power") return w;
  char text[32];
  std::snprintf(text, sizeof text, "power:%.3f", 1 + 3 * std::uniform_real_distribution<double>(0, 1)(rng));
  return text;
}

// ---------------- Bad input ----------------

TEST(SpringRow, BadInputIsAnError) {
  const Sine<double> sine;
  const auto sphere = make_profile<double>(parse_profile("sphere"));
  SpringRowOptions o;
  o.springs = 0;
  EXPECT_THROW(simulate_spring_row(sine, *sphere, 1.0, 0.5, o), InputError);
  o.springs = 16;
  o.steps = 0;
  EXPECT_THROW(simulate_spring_row(sine, *sphere, 1.0, 0.5, o), InputError);
  o.steps = 1;
  EXPECT_THROW(simulate_spring_row(sine, *sphere, 1.0, 0.5, o), InputError);
  o.steps = 64;
  o.phase = 1;
  EXPECT_THROW(simulate_spring_row(sine, *sphere, 1.0, 0.5, o), InputError);
  o.phase = 0;
  EXPECT_THROW(simulate_spring_row(sine, *sphere, 0.0, 0.5, o), InputError);
  EXPECT_THROW(simulate_spring_row(sine, *sphere, std::nan(""), 0.5, o), InputError);
  EXPECT_THROW(simulate_spring_row(sine, *sphere, 1.0, std::nan(""), o), InputError);
  EXPECT_THROW(simulate_spring_row(sine, *sphere, 1.0, -1.0, o), DomainError);
  o.steps = 6;  // sin 2πk/6 ≤ 0.87: contact at γ = −0.9, but at no step
  EXPECT_THROW(simulate_spring_row(sine, *sphere, 1.0, -0.9, o), DomainError);
  o.steps = 64;
  const ProfileFile file({0, 1}, {0, 0.5});  // σ ends at π/4: γ + 1 must stay below
  const auto short_profile = make_profile<double>(parse_profile(file.spec()));
  EXPECT_THROW(simulate_spring_row(sine, *short_profile, 1.0, 0.0, o), DomainError);
  EXPECT_NO_THROW(simulate_spring_row(sine, *short_profile, 1.0, -0.5, o));
  // Without stick (β ≥ β_c = 2π for the sine at γ ≥ 0) every spring slips: μ = 1 exactly.
  EXPECT_EQ(simulate_spring_row(sine, *sphere, 7.0, 0.5, o).mu, 1.0);
}

// ---------------- (a) Convergence ----------------

// M = N = 2^6 … 2^10 together, the error averaged over 8 offsets of the time grid (0 and seven
// fixed random ones: μ̄ does not depend on the phase, the O(h) constant of a single spring such
// as the wear flat's centre block does), against solve_curved at 30 digits. Expected order 1
// (file header). Band [0.9, 1.1]: a second-order method cannot land there, nor one with an O(1)
// bias (order → 0). The finest level must also meet B at every offset, and its mean error the
// coarsest one scaled down at the band's lower edge, (64/1024)^0.9.
TEST(SpringRow, ConvergenceOrder) {
  const ProfileFile file = measured_profile();
  const std::vector<std::string> profiles{"sphere", "cone", "wearflat:1", file.spec()};
  const std::vector<std::string> waves{"sine", "triangle", "square"};
  const std::array<double, 2> gammas{0.3, 1.5};  // jumping centre, non-jumping centre
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  std::array<double, 8> offsets{};
  for (std::size_t i = 1; i < offsets.size(); ++i) offsets[i] = u(rng);
  const double beta = 1;
  const auto start = std::chrono::steady_clock::now();
  double reference_time = 0, lo = 10, hi = 0;
  for (const std::string& ps : profiles)
    for (const std::string& ws : waves)
      for (double gamma : gammas) {
        const ProfileSpec spec = parse_profile(ps);
        const auto t0 = std::chrono::steady_clock::now();
        const double exact = reference_mu(ws, spec, beta, gamma, 30);
        reference_time += seconds_since(t0);
        const auto p = make_profile<double>(spec);
        const auto w = make_waveform<double>(parse_wave(ws));
        const double k_w = kink_slope(*w);
        std::vector<double> points, mean;
        double finest_ratio = 0;
        for (int k = 6; k <= 10; ++k) {
          SpringRowOptions o;
          o.springs = o.steps = std::size_t(1) << k;
          double e = 0;
          for (double off : offsets) {
            o.phase = off;
            const SpringRowResult<double> r = simulate_spring_row(*w, *p, beta, gamma, o);
            const double d = r.mu - exact;
            e += std::abs(d) / offsets.size();
            EXPECT_GE(d, -1.0 / (double(o.steps) * o.steps)) << ps << ", " << ws << ", gamma = " << gamma << ", N = " << o.steps;
            if (k == 10) {
              finest_ratio = std::max(finest_ratio, std::abs(d) / row_bound(r, beta, k_w));
              EXPECT_LE(std::abs(d), row_bound(r, beta, k_w)) << ps << ", " << ws << ", gamma = " << gamma << ", offset " << off;
            }
          }
          points.push_back(double(o.steps));
          mean.push_back(e);
        }
        const double order = fitted_order(points, mean);
        lo = std::min(lo, order);
        hi = std::max(hi, order);
        std::printf("[ row ] %-12s %-8s gamma = %.1f: order %.3f, mean error %.2e at M = N = 64, %.2e at 1024 (|e|/B <= %.2f)\n",
                    p->name().substr(0, 12).c_str(), ws.c_str(), gamma, order, mean.front(), mean.back(), finest_ratio);
        EXPECT_NEAR(order, 1.0, 0.1) << ps << ", " << ws << ", gamma = " << gamma;
        EXPECT_LE(mean.back(), mean.front() * std::pow(points.front() / points.back(), 0.9)) << ps << ", " << ws << ", gamma = " << gamma;
      }
  std::printf("[ row ] orders in [%.3f, %.3f]; %.1f s (solve_curved at 30 digits: %.1f s)\n", lo, hi, seconds_since(start),
              reference_time);
}

// ---------------- (b) Property tests ----------------

// Random convex measured profiles, random catalogue waves, β ∈ (0.2, 8), γ ∈ (−0.9, 2.5):
// solve_curved in double (its own relative_error allowed on top) against the row at
// M = N = 1024 on a grid through the catalogue's kinks: |difference| ≤ B, and μ_row ≥ μ − h².
TEST(SpringRow, RandomProfilesAgainstSolver) {
  constexpr int kTrials = 150;
  constexpr std::size_t kN = 1024;
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> u(0, 1);
  const auto start = std::chrono::steady_clock::now();
  int cases = 0, with_stick = 0, flats = 0, solver_errors = 0;
  double worst = 0;
  std::string worst_case;
  for (int trial = 0; trial < kTrials; ++trial) {
    const std::string ws = random_wave(rng);
    const double beta = 0.2 + 7.8 * u(rng), gamma = -0.9 + 3.4 * u(rng);
    const RandomProfile rp = random_profile(rng, gamma + 1);
    const ProfileFile file(rp.r, rp.f);
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, ", beta = %.17g, gamma = %.17g", beta, gamma);
    const std::string reproducer = "wave " + ws + ", profile samples " + file.samples() + numbers;
    const auto p = make_profile<double>(parse_profile(file.spec()));
    const auto w = make_waveform<double>(parse_wave(ws));
    CurvedResult<double> exact;
    try {
      exact = solve_curved(*w, *p, beta, gamma);
    } catch (const SolverError& e) {
      ++solver_errors;
      ADD_FAILURE() << "solve_curved failed: " << reproducer << "\n  " << e.what();
      continue;
    }
    SpringRowOptions o;
    o.springs = o.steps = kN;
    const SpringRowResult<double> r = simulate_spring_row(*w, *p, beta, gamma, o);
    const double bound = row_bound(r, beta, kink_slope(*w)) + exact.relative_error * exact.mu;
    const double d = r.mu - exact.mu;
    ++cases;
    with_stick += exact.mu < 1;
    flats += p->flat_length() > 0;
    if (std::abs(d) / bound > worst) {
      worst = std::abs(d) / bound;
      worst_case = reproducer;
    }
    EXPECT_LE(std::abs(d), bound) << reproducer << "\n  solver " << exact.mu << ", row " << r.mu;
    EXPECT_GE(d, -1.0 / (double(kN) * kN)) << reproducer << "\n  solver " << exact.mu << ", row " << r.mu;
  }
  std::printf("[ row ] %d random cases (%d with stick, %d with a flat centre) in %.1f s: max |diff|/B %.3f (%s); solver errors %d\n",
              cases, with_stick, flats, seconds_since(start), worst, worst_case.c_str(), solver_errors);
  EXPECT_EQ(solver_errors, 0);
  EXPECT_GE(with_stick, kTrials / 2);
}

// The closed forms that hold for every profile: for γ ≤ 1 every spring is in the jumping range
// (γ' = γ − σ ≤ 1) and has the same Φ/N (Eq. 19; triangle also Eq. 18), so μ̄ is that ratio:
// triangle 2β/(4+β) (β < 4, else 1), sawtooth-right β/2 (β < 2, else 1), sawtooth-left
// β/(2+β). solve_curved at 30 digits must give it to 25 digits; the row (M = N = 512) to B.
TEST(SpringRow, ClosedFormsOnRandomProfiles) {
  constexpr int kTrials = 30;
  constexpr std::size_t kN = 512;
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(0, 1);
  const std::array<const char*, 3> waves{"triangle", "sawtooth-right", "sawtooth-left"};
  const auto start = std::chrono::steady_clock::now();
  PrecisionScope precision(30);
  mpfr worst_solver = 0;
  double worst_row = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const std::string ws = waves[trial % waves.size()];
    const double beta = 0.2 + 7.8 * u(rng), gamma = -0.9 + 1.9 * u(rng);
    const RandomProfile rp = random_profile(rng, gamma + 1);
    const ProfileFile file(rp.r, rp.f);
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, ", beta = %.17g, gamma = %.17g", beta, gamma);
    const std::string reproducer = "wave " + ws + ", profile samples " + file.samples() + numbers;
    const ProfileSpec spec = parse_profile(file.spec());
    const mpfr b(beta);
    mpfr want = 1;
    if (ws == "triangle" && beta < 4) want = 2 * b / (4 + b);
    if (ws == "sawtooth-right" && beta < 2) want = b / 2;
    if (ws == "sawtooth-left") want = b / (2 + b);
    const auto w = make_waveform<mpfr>(parse_wave(ws));
    const auto p = make_profile<mpfr>(spec);
    mpfr mu;
    try {
      mu = solve_curved<mpfr>(*w, *p, b, mpfr(gamma)).mu;
    } catch (const SolverError& e) {
      ADD_FAILURE() << "solve_curved failed: " << reproducer << "\n  " << e.what();
      continue;
    }
    worst_solver = std::max(worst_solver, mpfr(abs(mu - want)));
    EXPECT_LE(abs(mu - want), mpfr("1e-25")) << reproducer << "\n  solver " << mu.str(30) << ", closed form " << want.str(30);

    const auto wd = make_waveform<double>(parse_wave(ws));
    const auto pd = make_profile<double>(spec);
    SpringRowOptions o;
    o.springs = o.steps = kN;
    const SpringRowResult<double> r = simulate_spring_row(*wd, *pd, beta, gamma, o);
    const double d = std::abs(r.mu - static_cast<double>(want)), bound = row_bound(r, beta, kink_slope(*wd));
    worst_row = std::max(worst_row, d / bound);
    EXPECT_LE(d, bound) << reproducer << "\n  row " << r.mu << ", closed form " << static_cast<double>(want);
  }
  std::printf("[ row ] closed forms, %d random profiles in %.1f s: solver (30 digits) max |diff| %s, row max |diff|/B %.3f\n",
              kTrials, seconds_since(start), worst_solver.str(3).c_str(), worst_row);
}

// ---------------- (c) Wrong rows are rejected ----------------

// Two plausible mistakes, built from the same per-spring stepping, must miss the solver by more
// than B while the right row meets it: (1) the sphere's springs spaced evenly in σ instead of x
// (weight dσ, the wrong MDR measure: dx = dσ/(2√σ)); (2) the wear-flat sphere without its flat
// centre. (For the triangle at γ ≤ 1 neither can be caught, nor need be: every spring has the
// same Φ/N there, so any weighting gives the closed form; those cases are left out.)
TEST(SpringRow, WrongRowsAreRejected) {
  constexpr std::size_t kN = 1024;
  struct Case {
    const char* wave;
    double beta, gamma;
  };
  const std::vector<Case> cases{{"sine", 1, 0.3}, {"sine", 2, 1.5}, {"square", 1, 0.3}, {"square", 0.5, 2},
                                {"triangle", 1, 1.5}, {"sawtooth-left", 3, 2}, {"power:2", 2, -0.5}};
  const auto sphere = make_profile<double>(parse_profile("sphere"));
  const auto flat = make_profile<double>(parse_profile("wearflat:1"));
  int caught_measure = 0, caught_flat = 0;
  for (const Case& c : cases) {
    const auto w = make_waveform<double>(parse_wave(c.wave));
    const double k_w = kink_slope(*w);
    const std::vector<double> table = detail::tabulate(*w, kN, 0.0);
    SpringRowOptions o;
    o.springs = o.steps = kN;

    // (1) The sphere, springs at the midpoints of M cells in σ ∈ [0, γ + 1], equal weights.
    const double mu_sphere = solve_curved(*w, *sphere, c.beta, c.gamma).mu;
    const SpringRowResult<double> right = simulate_spring_row(*w, *sphere, c.beta, c.gamma, o);
    double f = 0, n = 0;
    const double sigma_max = c.gamma + w->maximum();
    for (std::size_t i = 0; i < kN; ++i) {
      const auto s = detail::step_row_spring(table, c.beta, c.gamma - (i + 0.5) * sigma_max / kN, 0);
      f += s.retained_area;
      n += s.normal_area;
    }
    const double b1 = row_bound(right, c.beta, k_w);
    EXPECT_LE(std::abs(right.mu - mu_sphere), b1) << c.wave << ", beta = " << c.beta << ", gamma = " << c.gamma;
    EXPECT_GT(std::abs(f / n - mu_sphere), b1) << "dσ row not rejected: " << c.wave << ", beta = " << c.beta << ", gamma = " << c.gamma;
    caught_measure += std::abs(f / n - mu_sphere) > b1;

    // (2) The wear-flat sphere without its flat centre: the curved part alone.
    const double mu_flat = solve_curved(*w, *flat, c.beta, c.gamma).mu;
    const SpringRowResult<double> right2 = simulate_spring_row(*w, *flat, c.beta, c.gamma, o);
    const auto centre = detail::step_row_spring(table, c.beta, c.gamma, 0);
    const double f2 = right2.friction_integral - flat->flat_length() * centre.retained_area;
    const double n2 = right2.normal_integral - flat->flat_length() * centre.normal_area;
    const double b2 = row_bound(right2, c.beta, k_w);
    EXPECT_LE(std::abs(right2.mu - mu_flat), b2) << c.wave << ", beta = " << c.beta << ", gamma = " << c.gamma;
    EXPECT_GT(std::abs(f2 / n2 - mu_flat), b2) << "row without the flat not rejected: " << c.wave << ", beta = " << c.beta
                                               << ", gamma = " << c.gamma;
    caught_flat += std::abs(f2 / n2 - mu_flat) > b2;
    std::printf("[ row ] %-13s beta = %.1f, gamma = %.1f: B %.1e; dσ row off by %.1e, row without flat off by %.1e\n", c.wave,
                c.beta, c.gamma, std::max(b1, b2), std::abs(f / n - mu_sphere), std::abs(f2 / n2 - mu_flat));
  }
  std::printf("[ row ] wrong rows rejected: dσ measure %d of %zu, missing flat %d of %zu\n", caught_measure, cases.size(),
              caught_flat, cases.size());
}

// ---------------- Heavier measurements (VIBROFRIC_STRESS=full) ----------------

// The two parts of the error separately, for the record: the midpoint rule in x alone (the row's
// layout with each spring's exact Φ, N from solve(), M = 2^4 … 2^13), and the joint order up to
// M = N = 4096 with 8 offsets.
TEST(SpringRow, SeparateOrdersFull) {
  const char* mode = std::getenv("VIBROFRIC_STRESS");
  if (!mode || std::string(mode) != "full") GTEST_SKIP() << "set VIBROFRIC_STRESS=full";
  const ProfileFile file = measured_profile();
  const std::vector<std::string> profiles{"sphere", "cone", "wearflat:1", file.spec()};
  const std::vector<std::string> waves{"sine", "triangle", "square"};
  const double beta = 1;
  for (const std::string& ps : profiles)
    for (const std::string& ws : waves)
      for (double gamma : {0.3, 1.5}) {
        const ProfileSpec spec = parse_profile(ps);
        const double exact = reference_mu(ws, spec, beta, gamma, 30);
        const auto p = make_profile<double>(spec);
        const auto w = make_waveform<double>(parse_wave(ws));
        std::vector<double> ms, em;
        for (int k = 4; k <= 13; ++k) {
          const std::size_t m = std::size_t(1) << k;
          const double L = p->flat_length(), X = p->x_at_sigma(gamma + w->maximum()), dx = (X - L) / m;
          const Result<double> c = solve(*w, beta, gamma);
          double f = L * c.retained_area, n = L * c.normal_area;
          for (std::size_t i = 0; i < m; ++i) {
            const double g = gamma - p->sigma_at_x(L + (i + 0.5) * dx);
            if (!(g + w->maximum() > 0)) continue;
            const Result<double> s = solve(*w, beta, g);
            f += dx * s.retained_area;
            n += dx * s.normal_area;
          }
          ms.push_back(double(m));
          em.push_back(std::max(std::abs(f / n - exact), 1e-16));
        }
        std::vector<double> ns, en;
        for (int k = 6; k <= 12; ++k) {
          SpringRowOptions o;
          o.springs = o.steps = std::size_t(1) << k;
          double e = 0;
          for (int j = 0; j < 8; ++j) {
            o.phase = j / 8.0 + 0.05;
            e += std::abs(simulate_spring_row(*w, *p, beta, gamma, o).mu - exact) / 8;
          }
          ns.push_back(double(o.steps));
          en.push_back(e);
        }
        const bool exact_in_x = em.front() < 1e-14 && em.back() < 1e-14;  // the same Φ/N for every spring
        std::printf("[ row ] %-12s %-8s gamma = %.1f: midpoint rule in x: %s%.2f (error %.1e at M = 16, %.1e at 8192); "
                    "joint M = N: order %.3f (%.1e at 64, %.1e at 4096)\n",
                    p->name().substr(0, 12).c_str(), ws.c_str(), gamma, exact_in_x ? "exact, rounding only, slope " : "order ",
                    fitted_order(ms, em), em.front(), em.back(), fitted_order(ns, en), en.front(), en.back());
        EXPECT_NEAR(fitted_order(ns, en), 1.0, 0.1);
      }
}

}  // namespace
