// The rig's traces through the API (api/rig.hpp rig_trace_rows, rig_row_trace_rows; api/commands.hpp
// physical_trace with a rig), each column against what model.md's "Rig dynamics" makes of the
// others and of the rig's report, not against the code that wrote it:
// - the rows: every equally spaced phase, ascending from 0 to 1, the shares adding to one;
// - the body's equation X'' = (2πΩ)² [κ(βφ − X) − ⟨s⟩] + 4πζΩ√κ (β − X') at the equally spaced
//   rows away from an event, Y = X − βφ and Y' differenced from the printed lag and rate;
// - the period's means: ⟨s⟩ = κ⟨βφ − X⟩ (the system spring carries the friction), ∫s/∫n = μ̄/μ0,
//   the shares' integrals and the lag's extremes: evaluate_rig's fields;
// - in SI: F_s = k_s (v0 t − x) + c (v0 − ẋ) and m ẍ = F_s − F_x, ẋ and ẍ from the printed x;
// - and a curved rig's report: its row's size by the doubling rule, its error estimate against a
//   row of 12800 springs.
// Each tolerance adds the printed digits' half units, carried through the formula, to the
// differences' and the trapezoid's own error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/api/rig.hpp"
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/dynamics/rig_row.hpp"
#include "vibrofric/core/waves/waveform.hpp"

namespace vibrofric {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Half a unit in the last place of a value printed to `digits` significant digits (0 for 0: the
// traces print 0 only where it is exact, off contact).
double half_unit(const mpfr& v, int digits) {
  if (v == 0) return 0;
  const double x = std::abs(static_cast<double>(v));
  return 0.5 * std::pow(10.0, std::floor(std::log10(x)) - digits + 1);
}

struct Case {
  const char* wave;
  const char* profile;  // "flat" or a curved profile's name
  const char *beta, *gamma, *kappa, *omega, *zeta;
};

// model.md's measured sphere; a sphere whose springs slip backward (a light system spring near the
// slip resonance); a sphere that never leaves the plate (γ > 1: the row carried through the
// period); the flat punch, in flight and with backward slip.
const Case kCases[] = {
    {"sine", "sphere", "1.37", "0.42", "2.6", "3.3", "0.3"},
    {"sine", "sphere", "1.37", "0.42", "0.6", "1.3", "0.05"},
    {"sine", "sphere", "0.5", "1.5", "1", "2", "0.1"},
    {"sine", "flat", "1.37", "0.42", "2.6", "3.3", "0.3"},
    {"triangle", "flat", "0.8", "0.44", "0.1", "9.3", "0.08"},
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.wave << " on " << c.profile << " beta " << c.beta << " gamma " << c.gamma << " kappa " << c.kappa
      << " omega " << c.omega << " zeta " << c.zeta;
}

RigSpec rig_of(const Case& c) {
  RigSpec rig;
  rig.kappa = InputValue::read(c.kappa, "kappa");
  rig.omega = InputValue::read(c.omega, "omega");
  rig.zeta = InputValue::read(c.zeta, "zeta");
  return rig;
}

// A trace's row in double, each column with its half unit; the flat rig's mode as shares.
struct Column {
  double v = 0, e = 0;
};
struct Row {
  double phi;
  Column n, s, lag, rate, stick, slip, backward, flight;
};

void trace_of(const Case& c, int points, std::vector<Row>& rows) {
  TraceRequest request;
  request.beta.value = InputValue::read(c.beta, "beta");
  request.gamma.value = InputValue::read(c.gamma, "gamma");
  request.points = points;
  request.digits = 17;
  const auto column = [](const Significant& x) { return Column{static_cast<double>(x.value), half_unit(x.value, x.digits)}; };
  if (std::string(c.profile) == "flat") {
    for (const RigTraceRow& r : rig_trace_rows(parse_wave(c.wave), request, rig_of(c))) {
      const auto at17 = [&](const mpfr& x) { return column({x, 17}); };
      const auto share = [&](bool in) { return Column{in ? 1.0 : 0.0, 0}; };
      rows.push_back({static_cast<double>(r.phi), at17(r.n), at17(r.s), at17(r.lag), at17(r.lag_rate),
                      share(r.mode == RigMode::stick),
                      share(r.mode == RigMode::forward_slip || r.mode == RigMode::backward_slip),
                      share(r.mode == RigMode::backward_slip), share(r.mode == RigMode::flight)});
    }
  } else {
    // n and s are the half-row's sums in the profile's own length (trace_rows' curved rows): the
    // row's means ⟨n⟩, ⟨s⟩ of the body's equation times the contact's largest radius, on the sphere
    // σ = x² at γ + max w = γ + 1
    request.profile = parse_profile(c.profile);
    ASSERT_EQ(std::string(c.profile), "sphere");
    const double radius = std::sqrt(std::stod(c.gamma) + 1);
    const auto mean = [&](const Significant& x) {
      const Column sum = column(x);
      return Column{sum.v / radius, sum.e / radius};
    };
    for (const RigRowTraceRow& r : rig_row_trace_rows(parse_wave(c.wave), request, rig_of(c)))
      rows.push_back({static_cast<double>(r.phi), mean(r.n), mean(r.s), column(r.lag), column(r.lag_rate),
                      column(r.stick), column(r.slip), column(r.backward), column(r.flight)});
  }
}

// The row at φ = i/points for each i (the first where an event's rows share that phase), and
// whether an event's row (one off the grid, or a second one at a grid phase) lies within two
// grid steps of it.
struct Grid {
  std::vector<const Row*> at;
  std::vector<bool> near_event;
};
Grid grid_of(const std::vector<Row>& rows, int points) {
  Grid g{std::vector<const Row*>(static_cast<std::size_t>(points) + 1, nullptr),
         std::vector<bool>(static_cast<std::size_t>(points) + 1, false)};
  for (const Row& r : rows) {
    const double x = r.phi * points, i = std::round(x);
    if (std::abs(x - i) < 1e-9 && g.at[static_cast<std::size_t>(i)] == nullptr) {
      g.at[static_cast<std::size_t>(i)] = &r;
      continue;
    }
    for (long j = static_cast<long>(std::floor(x)) - 2; j <= static_cast<long>(std::ceil(x)) + 2; ++j)
      if (j >= 0 && j <= points) g.near_event[static_cast<std::size_t>(j)] = true;
  }
  return g;
}

class RigTrace : public ::testing::TestWithParam<Case> {};

// Rows ascending from 0 to 1 with every equally spaced phase among them, n ≥ |s|, and the shares
// adding to one, within the printed digits.
TEST_P(RigTrace, RowsCoverThePeriodAndTheSharesAddToOne) {
  const Case& c = GetParam();
  const int points = 500;
  std::vector<Row> rows;
  trace_of(c, points, rows);
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.front().phi, 0);
  EXPECT_EQ(rows.back().phi, 1);
  for (std::size_t k = 1; k < rows.size(); ++k) EXPECT_LE(rows[k - 1].phi, rows[k].phi) << k;
  const Grid g = grid_of(rows, points);
  for (int i = 0; i <= points; ++i) EXPECT_NE(g.at[static_cast<std::size_t>(i)], nullptr) << "no row at " << i << "/" << points;
  for (const Row& r : rows) {
    const double e = r.stick.e + r.slip.e + r.flight.e + 1e-15;
    EXPECT_NEAR(r.stick.v + r.slip.v + r.flight.v, 1, e) << r.phi;
    EXPECT_LE(r.backward.v, r.slip.v + r.backward.e + r.slip.e) << r.phi;
    EXPECT_GE(r.backward.v, 0) << r.phi;
    EXPECT_LE(std::abs(r.s.v), r.n.v + r.s.e + r.n.e) << r.phi;
  }
}

// The body's equation at the equally spaced rows whose two neighbours either side are equally
// spaced too: Y' from the lag's fourth-order central difference and Y'' from the rate's. On the
// punch the motion is smooth between events (1e-6 of the terms' size, O(h⁴)); on a row ⟨s⟩ has a
// kink wherever a spring changes mode and the difference of Y' errs by O(h) there (test_rig_row:
// 7.2e-5 at 8192 intervals; 1e-3 here at 4000). The printed digits add their half units times the
// stencil's weights over 12h.
TEST_P(RigTrace, EveryRowSolvesTheBodysEquation) {
  const Case& c = GetParam();
  const int points = 4000;
  std::vector<Row> rows;
  trace_of(c, points, rows);
  ASSERT_FALSE(rows.empty());
  const Grid g = grid_of(rows, points);
  const double kappa = std::stod(c.kappa), W = 2 * kPi * std::stod(c.omega), zeta = std::stod(c.zeta);
  const double h = 1.0 / points, smooth = std::string(c.profile) == "flat" ? 1e-6 : 1e-3;
  int checked = 0;
  for (int i = 2; i + 2 <= points; ++i) {
    bool skip = false;
    for (int j = i - 2; j <= i + 2; ++j) skip = skip || g.near_event[static_cast<std::size_t>(j)];
    if (skip) continue;
    const Row* r[5] = {g.at[i - 2], g.at[i - 1], g.at[i], g.at[i + 1], g.at[i + 2]};
    const auto d = [&](Column Row::*col) {
      return (-(r[4]->*col).v + 8 * (r[3]->*col).v - 8 * (r[1]->*col).v + (r[0]->*col).v) / (12 * h);
    };
    const auto d_error = [&](Column Row::*col) {
      return ((r[4]->*col).e + 8 * (r[3]->*col).e + 8 * (r[1]->*col).e + (r[0]->*col).e) / (12 * h);
    };
    const Row& x = *r[2];
    const double spring = W * W * kappa * x.lag.v, contact = W * W * x.s.v, damper = 2 * W * zeta * std::sqrt(kappa) * x.rate.v;
    const double size = std::abs(spring) + std::abs(contact) + std::abs(damper);
    const double printed = d_error(&Row::rate) + W * W * (kappa * x.lag.e + x.s.e) + 2 * W * zeta * std::sqrt(kappa) * x.rate.e;
    EXPECT_NEAR(d(&Row::rate), -spring - contact - damper, smooth * size + printed) << "Y'' at phi " << x.phi;
    EXPECT_NEAR(d(&Row::lag), x.rate.v, 1e-6 * (W * std::abs(x.lag.v) + std::abs(x.rate.v)) + d_error(&Row::lag) + x.rate.e)
        << "Y' at phi " << x.phi;
    ++checked;
  }
  EXPECT_GT(checked, points / 4);
}

// The period's means by the trapezoidal rule over every row: the report at the same point. The rule
// errs by O(h²) on the smooth columns (1e-6 relative), and, on a row, by half a step times a
// spring's weight where it changes mode between rows (the shares: 4 steps in all); the printed
// digits add their half units.
TEST_P(RigTrace, PeriodMeansAreTheReportsFields) {
  const Case& c = GetParam();
  const int points = 4000;
  std::vector<Row> rows;
  trace_of(c, points, rows);
  ASSERT_FALSE(rows.empty());
  struct Mean {
    double v = 0, e = 0;
    void add(double h, const Column& a, const Column& b) {
      v += h * (a.v + b.v);
      e += h * (a.e + b.e);
    }
  } s, n, lag, stick, slip, backward, flight;
  double lo = rows.front().lag.v, hi = lo, extreme_error = rows.front().lag.e;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const Row &a = rows[k - 1], &b = rows[k];
    const double h = (b.phi - a.phi) / 2;
    s.add(h, a.s, b.s), n.add(h, a.n, b.n), lag.add(h, a.lag, b.lag);
    stick.add(h, a.stick, b.stick), slip.add(h, a.slip, b.slip), backward.add(h, a.backward, b.backward);
    flight.add(h, a.flight, b.flight);
    lo = std::min(lo, b.lag.v);
    hi = std::max(hi, b.lag.v);
    extreme_error = std::max(extreme_error, b.lag.e);
  }
  ProfileSpec profile;
  if (std::string(c.profile) != "flat") profile = parse_profile(c.profile);
  const RigReport report =
      evaluate_rig(parse_wave(c.wave), Point(c.beta, c.gamma), rig_of(c), {NumberType::float64, 17}, {}, profile);
  const double kappa = std::stod(c.kappa);
  EXPECT_NEAR(s.v, -kappa * lag.v, 1e-6 * std::abs(s.v) + s.e + kappa * lag.e) << "<s> = kappa <beta phi - X>";
  const double mu = std::stod(report.mu);
  EXPECT_NEAR(s.v / n.v, mu, 1e-6 * mu + (s.e + mu * n.e) / n.v);
  const double share = 4.0 / points;
  const auto fraction = [](const Significant& x) { return static_cast<double>(x.value); };
  EXPECT_NEAR(stick.v, fraction(report.stick_fraction), share + stick.e);
  EXPECT_NEAR(slip.v, fraction(report.slip_fraction), share + slip.e);
  EXPECT_NEAR(backward.v, fraction(report.backward_fraction), share + backward.e);
  EXPECT_NEAR(flight.v, fraction(report.flight_fraction), share + flight.e);
  // the lag's extremes fall between rows, each off by h²/8 of |Y''| at most: 1e-5 of the swing here
  EXPECT_NEAR((hi - lo) / 2, fraction(report.amplitude), 1e-5 * (hi - lo) + extreme_error);
}

INSTANTIATE_TEST_SUITE_P(Cases, RigTrace, ::testing::ValuesIn(kCases));

// A curved rig's relative_error_estimate (the rows of n/2 and n springs apart, rig.cpp row_pair)
// against the true error of the row of n springs (report.springs, its μ̄ recomputed here on that
// row): μ̄ on a row of 12800 springs, whose own error is about 1e-11 (the quadrature's n^-2.5 from
// 1.3e-9 at 1600). The estimate must hold the true error, and not by more than 64 times (the
// difference of n/2 and n is about five times the error of n at n^-2.5), so that neither a term
// dropped nor one inflated passes.
TEST(RigReport, CurvedErrorEstimateHoldsTheRowsErrorTightly) {
  for (const Case& c : {kCases[0], kCases[1], kCases[2]}) {
    SCOPED_TRACE(::testing::PrintToString(c));
    const RigReport report = evaluate_rig(parse_wave(c.wave), Point(c.beta, c.gamma), rig_of(c),
                                          {NumberType::float64, 17}, {}, parse_profile(c.profile));
    const PowerProfile<double> sphere(2.0, "sphere");
    const Sine<double> w;
    const double gamma = std::stod(c.gamma);
    const RigParameters<double> p{std::stod(c.kappa), std::stod(c.omega), std::stod(c.zeta), 0};
    const auto solve = [&](std::size_t n) { return solve_rig_row<double>(w, std::stod(c.beta), gamma, p, mdr_row(sphere, gamma + 1, n), {}).mu; };
    const double printed = solve(report.springs), fine = solve(12800);
    const double error = std::abs(printed - fine) / std::abs(fine);
    const double estimate = static_cast<double>(report.relative_error.value);
    EXPECT_NEAR(printed, std::stod(report.mu), half_unit(mpfr(report.mu), report.mu_digits));
    EXPECT_LE(error, estimate) << report.springs << " springs: " << printed << ", 12800: " << fine;
    EXPECT_GE(error, estimate / 64) << report.springs << " springs: " << printed << ", 12800: " << fine;
  }
}

// The row is doubled from 200 springs until the rows of n/2 and n agree to 1e-8 of μ̄ or n = 3200
// (rig.cpp row_pair): the number of springs reported is the rule's, from μ̄ on each row here. The
// cone's row converges slowest (n^-2 at its tip): it needs the largest row.
TEST(RigReport, CurvedRowDoubledUntilTwoSizesAgree) {
  struct Row {
    const char* profile;
    double exponent;
  };
  for (const Row& shape : {Row{"sphere", 2.0}, Row{"cone", 1.0}}) {
    SCOPED_TRACE(shape.profile);
    const Case c{"sine", shape.profile, "1.37", "0.42", "2.6", "3.3", "0.3"};
    const RigReport report = evaluate_rig(parse_wave(c.wave), Point(c.beta, c.gamma), rig_of(c),
                                          {NumberType::float64, 17}, {}, parse_profile(c.profile));
    const PowerProfile<double> profile(shape.exponent, shape.profile);
    const Sine<double> w;
    const RigParameters<double> p{2.6, 3.3, 0.3, 0};
    const auto mu = [&](std::size_t n) { return solve_rig_row<double>(w, 1.37, 0.42, p, mdr_row(profile, 1.42, n), {}).mu; };
    std::size_t n = 200;
    for (double lower = mu(100), higher = mu(200); n < 3200 && std::abs(lower - higher) > 1e-8 * std::abs(higher); n *= 2) {
      lower = higher;
      higher = mu(2 * n);
    }
    EXPECT_EQ(report.springs, n);
  }
}

// physical --trace with a damped rig (the damper's force c (v0 − ẋ) a few per cent of F_s), on the
// punch and on a ball: F_s = k_s (v0 t − x) + c (v0 − ẋ) at every equally spaced row away from the
// body's landing and lift-off, ẋ by the fourth-order difference of the printed x (O(h⁴): 1e-6 of
// the damper's force), and on the punch, whose x carries 17 digits, m ẍ = F_s − F_x (the ball's
// x carries the digits its row's two sizes agree on, too few for a second difference).
TEST(PhysicalRigTrace, HolderForceAndNewtonsLawInNewtons) {
  for (const char* shape : {"flat", "sphere"}) {
    SCOPED_TRACE(shape);
    PhysicalRequest r;
    const auto set = [](NamedInput& in, const char* text) { in.value = InputValue::read(text, in.name); };
    set(r.E1, "210e9"), set(r.nu1, "0.3"), set(r.E2, "70e9"), set(r.nu2, "0.33"), set(r.F_N, "10"), set(r.v0, "2e-3");
    set(r.f, "20000"), set(r.A, "1.5e-6"), set(r.mu0, "0.3"), set(r.mass, "0.05"), set(r.k_system, "2e6");
    set(r.damping, "100");
    r.shape.text = shape;
    set(std::string(shape) == "flat" ? r.radius : r.R, std::string(shape) == "flat" ? "1e-3" : "5e-3");
    const int points = 2000;
    const std::vector<PhysicalTraceRow> rows = physical_trace(parse_wave("sine"), r, points, 17);
    const double f = 20000, m = 0.05, ks = 2e6, c = 100, v0 = 2e-3, h = 1 / (f * points);
    std::vector<const PhysicalTraceRow*> at(static_cast<std::size_t>(points) + 1, nullptr);
    std::vector<bool> near_event(static_cast<std::size_t>(points) + 1, false);
    for (const PhysicalTraceRow& row : rows) {
      ASSERT_TRUE(row.x_m && row.F_s_N);
      const double x = static_cast<double>(row.t_s.value) * f * points, i = std::round(x);
      if (std::abs(x - i) < 1e-6 && at[static_cast<std::size_t>(i)] == nullptr) {
        at[static_cast<std::size_t>(i)] = &row;
        continue;
      }
      for (long j = static_cast<long>(std::floor(x)) - 2; j <= static_cast<long>(std::ceil(x)) + 2; ++j)
        if (j >= 0 && j <= points) near_event[static_cast<std::size_t>(j)] = true;
    }
    int checked = 0;
    for (int i = 2; i + 2 <= points; ++i) {
      bool skip = false;
      for (int j = i - 2; j <= i + 2; ++j) skip = skip || near_event[static_cast<std::size_t>(j)] || at[j] == nullptr;
      if (skip) continue;
      const auto x = [&](int j) { return static_cast<double>(at[j]->x_m->value); };
      const auto x_error = [&](int j) { return half_unit(at[j]->x_m->value, at[j]->x_m->digits); };
      const double t = static_cast<double>(at[i]->t_s.value);
      const double Fs = static_cast<double>(at[i]->F_s_N->value), Fx = static_cast<double>(at[i]->F_x_N.value);
      const double Fs_error = half_unit(at[i]->F_s_N->value, at[i]->F_s_N->digits);
      const double v = (-x(i + 2) + 8 * x(i + 1) - 8 * x(i - 1) + x(i - 2)) / (12 * h);
      const double v_error = (x_error(i + 2) + 8 * x_error(i + 1) + 8 * x_error(i - 1) + x_error(i - 2)) / (12 * h);
      const double damper = c * (v0 - v);
      EXPECT_NEAR(Fs, ks * (v0 * t - x(i)) + damper,
                  1e-6 * std::abs(damper) + ks * x_error(i) + c * v_error + Fs_error + 1e-15 * std::abs(Fs))
          << "F_s at t " << t;
      if (std::string(shape) == "flat") {
        const double a = (-x(i + 2) + 16 * x(i + 1) - 30 * x(i) + 16 * x(i - 1) - x(i - 2)) / (12 * h * h);
        const double a_error =
            (x_error(i + 2) + 16 * x_error(i + 1) + 30 * x_error(i) + 16 * x_error(i - 1) + x_error(i - 2)) / (12 * h * h);
        const double Fx_error = half_unit(at[i]->F_x_N.value, at[i]->F_x_N.digits);
        EXPECT_NEAR(m * a, Fs - Fx, 1e-6 * (std::abs(Fs) + std::abs(Fx)) + m * a_error + Fs_error + Fx_error)
            << "m x'' at t " << t;
      }
      ++checked;
    }
    EXPECT_GT(checked, points / 4);
  }
}

}  // namespace
}  // namespace vibrofric
