// The curved contact over one period and the row's stick share (curved_trace.hpp; model.md,
// "Curved contacts (MDR)") against the naive spring row (spring_row.hpp: time stepping, no
// events, no breakpoints, never calls solve()), and against solve_curved's integrals.
//
// The row's per-phase bound. At a step φ_k the row tabulates n exactly; its s differs from the
// exact s of the same spring only where a stick is anchored up to one step early (spring_row.hpp:
// lag ≤ (β + K_w) h, K_w the largest one-sided |w'| at a kink or jump of w, 0 for the sine and
// the square, 4 for the triangle, 2 for the sawtooths): the ramp is then ahead by at most that,
// and so is a stick's end. Summed over the half-row of length X, |S_row − S| ≤ X (β + K_w) h,
// plus the midpoint rule in x (order 2 and more for power laws, 3/2 for the wear flat: measured
// ≤ 3e-6 X at M = 256), allowed for by X h² (1.5e-5 X there). The square's stick out of zero at
// its jump meets the bound (one whole step's ramp at φ = 0, measured ratio 1.00).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/core/curved/curved_trace.hpp"
#include "vibrofric/verification/spring_row.hpp"

namespace {

using namespace vibrofric;

struct Case {
  const char* wave;
  double kink_slope;  // K_w
};
const std::vector<Case> kWaves{{"sine", 0}, {"triangle", 4}, {"square", 0}, {"sawtooth-right", 2}};
const std::vector<const char*> kProfiles{"sphere", "cone", "power:3", "wearflat:10"};
const std::vector<std::pair<double, double>> kPoints{{0.5, 0.2}, {0.5, -0.5}, {2, 0.5}, {0.1, 1.5}, {3, -0.3}};

// f(case, w, profile, β, γ) on every wave × profile × point, in double.
template <class F>
void for_each_case(F f) {
  for (const Case& c : kWaves)
    for (const char* profile : kProfiles)
      for (const auto& [beta, gamma] : kPoints) {
        SCOPED_TRACE(std::string(c.wave) + " " + profile + " beta " + std::to_string(beta) + " gamma " + std::to_string(gamma));
        const auto w = make_waveform<double>(parse_wave(c.wave));
        const auto p = make_profile<double>(parse_profile(profile));
        f(c, *w, *p, beta, gamma);
      }
}

TEST(CurvedTrace, AgreesWithTheSpringRowAtEveryStep) {
  double total[2] = {0, 0};  // the largest |S_row − S| summed over the cases, M = 256 and 1024
  for_each_case([&](const Case& c, const Waveform<double>& w, const Profile<double>& p, double beta, double gamma) {
    for (const std::size_t M : {256u, 1024u}) {
      SpringRowOptions o;
      o.springs = o.steps = M;
      o.trace = true;
      const auto row = simulate_spring_row(w, p, beta, gamma, o);
      std::vector<double> phases;
      for (std::size_t k = 0; k < M; ++k) phases.push_back(static_cast<double>(k) / M);
      const auto tr = curved_trace(w, p, beta, gamma, phases, 1e-13);
      const double X = row.contact_radius, h = 1.0 / M;
      double worst_s = 0;
      for (std::size_t k = 0; k < M; ++k) {
        EXPECT_LE(tr[k].s, tr[k].n);
        EXPECT_GE(tr[k].s, 0);
        // n: the closed form against the row's midpoint sum (x-rule only).
        EXPECT_NEAR(tr[k].n, row.trace_n[k], 4 * X * h * h) << k;
        worst_s = std::max(worst_s, std::abs(tr[k].s - row.trace_s[k]));
      }
      EXPECT_LE(worst_s, X * ((beta + c.kink_slope) * h + h * h));
      total[M == 1024u] += worst_s;
    }
  });
  // First order over the cases (one case alone may stall where the grid meets a kink): four
  // times the steps, at least 2.5 times closer (measured 4.3; the stick integral 4.1).
  EXPECT_LE(2.5 * total[1], total[0]);
}

// The stick integral against the row's count of stick steps. A stick's ends are off by the lag
// and the grid: measured ≤ 1.4 h X over the cases at M = 512; checked at 2 h X, and first order
// over the cases from M = 256 to 1024.
TEST(CurvedTrace, StickIntegralAgreesWithTheSpringRow) {
  double total[2] = {0, 0};
  for_each_case([&](const Case&, const Waveform<double>& w, const Profile<double>& p, double beta, double gamma) {
    double err = 0;
    const double stick = curved_stick_integral(w, p, beta, gamma, 1e-12, err);
    EXPECT_LE(err, 1e-10 * stick + 1e-15);
    for (const std::size_t M : {256u, 1024u}) {
      SpringRowOptions o;
      o.springs = o.steps = M;
      const auto row = simulate_spring_row(w, p, beta, gamma, o);
      const double d = std::abs(stick - row.stick_integral), X = row.contact_radius;
      EXPECT_LE(d, 2.0 * X / M);
      EXPECT_LE(stick, X);
      total[M == 1024u] += d;
    }
  });
  EXPECT_LE(2.5 * total[1], total[0]);
}

// ∫₀¹ N dφ and ∫₀¹ S dφ are solve_curved's normal and friction integrals. The trapezoid rule on
// K phases of a periodic f with f' of bounded variation V errs by at most h²V/8 (a kink of f'
// with jump J between two nodes: J h²/8; smooth stretches: h²/12 ∫|f''|). V is measured from
// the trace's own second differences and doubled. Waves whose n jumps (square, sawtooth) make
// N and S jump, the rule then first order: not here.
TEST(CurvedTrace, PeriodMeansAreTheIntegralsOfMu) {
  const int K = 4096;
  const double h = 1.0 / K;
  for (const char* wave : {"sine", "triangle"})
    for (const char* profile : {"sphere", "cone", "wearflat:2"})
      for (const auto& [beta, gamma] : std::vector<std::pair<double, double>>{{0.5, 0.2}, {0.3, -0.6}, {4, 1}, {0.05, 1.5}}) {
        SCOPED_TRACE(std::string(wave) + " " + profile + " beta " + std::to_string(beta) + " gamma " + std::to_string(gamma));
        const auto w = make_waveform<double>(parse_wave(wave));
        const auto p = make_profile<double>(parse_profile(profile));
        const auto r = solve_curved(*w, *p, beta, gamma);
        std::vector<double> phases;
        for (int k = 0; k < K; ++k) phases.push_back(static_cast<double>(k) / K);
        const auto tr = curved_trace(*w, *p, beta, gamma, phases, 1e-13);
        double s = 0, n = 0, vs = 0, vn = 0;
        for (int k = 0; k < K; ++k) {
          const auto &prev = tr[(k + K - 1) % K], &here = tr[k], &next = tr[(k + 1) % K];
          s += here.s * h;
          n += here.n * h;
          vs += std::abs(next.s - 2 * here.s + prev.s) / h;
          vn += std::abs(next.n - 2 * here.n + prev.n) / h;
        }
        EXPECT_LE(std::abs(s - r.friction_integral), h * h * vs / 4 + 1e-13 * r.friction_integral);
        EXPECT_LE(std::abs(n - r.normal_integral), h * h * vn / 4 + 1e-13 * r.normal_integral);
        EXPECT_GT(h * h * vs / 4, 0.0);
      }
}

// Where β ≥ β_c of the centre no spring sticks (Eq. 6): S = N at every phase, and no stick.
TEST(CurvedTrace, AllSlipAboveBetaC) {
  const auto w = make_waveform<double>(parse_wave("sine"));
  const auto p = make_profile<double>(parse_profile("sphere"));
  const double beta = 7, gamma = 0.5;  // β_c = 2π
  std::vector<double> phases;
  for (int k = 0; k <= 100; ++k) phases.push_back(k / 100.0);
  for (const auto& row : curved_trace(*w, *p, beta, gamma, phases, 1e-13)) EXPECT_NEAR(row.s, row.n, 1e-15 * (row.n + 1));
  double err = 1;
  EXPECT_EQ(curved_stick_integral(*w, *p, beta, gamma, 1e-12, err), 0.0);
  EXPECT_EQ(err, 0.0);
}

// A flat punch is the row's limit: the wear flat of λ = 10^6 (the curved rim adds 1e-6 of the
// flat's length) gives the punch's s and stick fraction within that, and the same in mpfr at 30
// digits, a spring of the same γ solved alone.
TEST(CurvedTrace, WideWearFlatIsThePunch) {
  PrecisionScope scope(30);
  const auto w = make_waveform<mpfr>(parse_wave("sine"));
  const auto p = make_profile<mpfr>(parse_profile("wearflat:1e6"));
  const mpfr beta("0.5"), gamma("-0.4");
  const Result<mpfr> punch = solve(*w, beta, gamma);
  std::vector<mpfr> phases;
  for (int k = 0; k < 20; ++k) phases.push_back(mpfr(k) / 20);
  const auto tr = curved_trace(*w, *p, beta, gamma, phases, mpfr("1e-25"));
  for (std::size_t k = 0; k < phases.size(); ++k) {
    const mpfr s = tangential_force(*w, punch, beta, gamma, phases[k]);
    EXPECT_LE(abs(tr[k].s - s), mpfr("2e-6") * (s + 1e-3)) << k;
  }
  mpfr err;
  const mpfr stick = curved_stick_integral(*w, *p, beta, gamma, mpfr("1e-25"), err);
  mpfr punch_stick = 0;
  for (const auto& st : punch.stick_phases) punch_stick += st.end - st.begin;
  const mpfr X = p->x_at_sigma(mpfr(gamma + 1));
  EXPECT_LE(abs(stick / X - punch_stick), mpfr("2e-6"));
}

}  // namespace

namespace {

// A Fourier wave's rising piece ends at φ = 1 (not at a maximum): a quadrature node next to the
// γ' breakpoint −w(1) maps back through σ ↔ t a rounding beyond it, and the first-contact onset
// there was a bracket without a sign change ("contact boundary (γ + w = 0): no sign change on
// [0.974, 1]", f = −1.2e-15 at 1), 8 of 400 random cases. The onset is now that end of the piece.
// Every phase of a fine grid answers, within the double/long double agreement of the random runs.
TEST(CurvedTrace, FourierOnsetAtThePeriodsEnd) {
  const std::string path = ::testing::TempDir() + "three_harmonics.txt";
  std::ofstream(path) << "1 0 1\n2 0.3 0.1\n3 0 0.2\n";
  const WaveSpec spec = parse_wave("fourier:" + path);
  const auto w = make_waveform<double>(spec);
  const auto wl = make_waveform<long double>(spec);
  for (const auto& [profile, beta, gamma] : std::vector<std::tuple<const char*, double, double>>{
           {"power:3", 2.1406640831784598, 0.32905444515730831},
           {"power:6", 0.15756659236921366, 0.80863381664491674},
           {"power:1.5", 0.034834017330599779, 1.3638115147146863}}) {
    SCOPED_TRACE(std::string(profile) + " beta " + std::to_string(beta) + " gamma " + std::to_string(gamma));
    const auto p = make_profile<double>(parse_profile(profile));
    const auto pl = make_profile<long double>(parse_profile(profile));
    std::vector<double> phases;
    std::vector<long double> phases_l;
    for (int k = 0; k < 400; ++k) {
      phases.push_back(k / 400.0);
      phases_l.push_back(k / 400.0L);
    }
    const auto a = curved_trace(*w, *p, beta, gamma, phases, 1e-13);
    const auto b = curved_trace(*wl, *pl, static_cast<long double>(beta), static_cast<long double>(gamma), phases_l, 1e-16L);
    for (std::size_t k = 0; k < phases.size(); ++k)
      EXPECT_NEAR(a[k].s, static_cast<double>(b[k].s), 1e-12 * static_cast<double>(b[k].n) + 1e-300) << phases[k];
  }
}

}  // namespace

namespace {

// The returned error estimates against the same algorithm at much higher precision: at 30 digits,
// asked for 1e-25 of itself, each S(φ) and the stick integral lie within their own estimate plus
// the rounding of the working precision (1000 eps of n) of the 60-digit values, and within the
// 1e-25 asked for; N, a closed form, within that rounding.
TEST(CurvedTrace, ErrorEstimatesHoldAgainstSixtyDigits) {
  for (const auto& [wave, profile, beta, gamma] : std::vector<std::tuple<const char*, const char*, const char*, const char*>>{
           {"sine", "sphere", "0.5", "-0.3"}, {"triangle", "wearflat:2", "0.3", "0.5"}, {"power:3", "cone", "2", "1.2"}}) {
    SCOPED_TRACE(std::string(wave) + " " + profile + " beta " + beta + " gamma " + gamma);
    std::vector<CurvedTraceRow<mpfr>> fine;
    mpfr fine_stick, fine_err;
    {
      PrecisionScope scope(60);
      const auto w = make_waveform<mpfr>(parse_wave(wave));
      const auto p = make_profile<mpfr>(parse_profile(profile));
      std::vector<mpfr> phases;
      for (int k = 0; k < 40; ++k) phases.push_back(mpfr(k) / 40);
      fine = curved_trace(*w, *p, mpfr(beta), mpfr(gamma), phases, mpfr("1e-55"));
      fine_stick = curved_stick_integral(*w, *p, mpfr(beta), mpfr(gamma), mpfr("1e-55"), fine_err);
    }
    PrecisionScope scope(30);
    const auto w = make_waveform<mpfr>(parse_wave(wave));
    const auto p = make_profile<mpfr>(parse_profile(profile));
    std::vector<mpfr> phases;
    for (int k = 0; k < 40; ++k) phases.push_back(mpfr(k) / 40);
    const auto tr = curved_trace(*w, *p, mpfr(beta), mpfr(gamma), phases, mpfr("1e-25"));
    const mpfr eps = std::numeric_limits<mpfr>::epsilon();
    for (std::size_t k = 0; k < tr.size(); ++k) {
      PrecisionScope wide(60);
      const mpfr rounding = 1000 * eps * fine[k].n;
      EXPECT_LE(abs(mpfr(tr[k].s) - fine[k].s), mpfr(tr[k].error) + rounding) << k;
      EXPECT_LE(abs(mpfr(tr[k].s) - fine[k].s), mpfr("1e-25") * fine[k].s + rounding) << k;
      EXPECT_LE(abs(mpfr(tr[k].n) - fine[k].n), rounding) << k;
    }
    mpfr err;
    const mpfr stick = curved_stick_integral(*w, *p, mpfr(beta), mpfr(gamma), mpfr("1e-25"), err);
    PrecisionScope wide(60);
    EXPECT_GT(fine_stick, 0);
    EXPECT_LE(abs(mpfr(stick) - fine_stick), mpfr(err) + 1000 * eps * fine_stick);
    EXPECT_LE(abs(mpfr(stick) - fine_stick), mpfr("1e-25") * fine_stick + 1000 * eps * fine_stick);
  }
}

}  // namespace
