// Physical inputs to dimensionless groups (Eqs. 1, 5, 14), against the same formulas evaluated
// at 50 digits from the double inputs exactly (independent of the double arithmetic under test).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/inplane.hpp"
#include "vibrofric/api/rig.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/physical.hpp"

namespace {

using namespace vibrofric;

// Each group is at most 16 double operations from the inputs (Eq. 1: ν², 1 − ν², two quotients,
// a sum and a reciprocal per modulus; Eq. 5 four more), each rounded by at most half an ulp: a
// relative error of 16 half-ulps, bounded here by 8 eps.
constexpr double kRoundings = 8;

void expect_eps(double x, const mpfr& ref, const char* what) {
  PrecisionScope scope(50);
  EXPECT_LE(static_cast<double>(mpfr(abs(mpfr(x) - ref) / abs(ref))), kRoundings * std::numeric_limits<double>::epsilon())
      << what << ": " << x << " against " << ref.str(20);
}

// Eq. 1 and Eq. 5 at 50 digits from the inputs' exact values (double, or mpfr read at 50 digits).
struct Reference {
  mpfr E_star, G_star, k_z, k_x, beta, gamma;
};
template <class Real>
Reference reference(const PhysicalInput<Real>& in) {
  PrecisionScope scope(50);
  const mpfr E1(in.E1), E2(in.E2), nu1(in.nu1), nu2(in.nu2), a(in.radius);
  const mpfr G1 = in.G1 != 0 ? mpfr(in.G1) : mpfr(E1 / (2 * (1 + nu1)));
  const mpfr G2 = in.G2 != 0 ? mpfr(in.G2) : mpfr(E2 / (2 * (1 + nu2)));
  Reference r;
  r.E_star = 1 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
  r.G_star = 1 / ((2 - nu1) / (4 * G1) + (2 - nu2) / (4 * G2));
  r.k_z = 2 * r.E_star * a;
  r.k_x = 2 * r.G_star * a;
  r.beta = r.k_x * mpfr(in.v0) / (mpfr(in.mu0) * r.k_z * mpfr(in.A) * mpfr(in.f));
  r.gamma = mpfr(in.u_mean) / mpfr(in.A);
  return r;
}

void expect_groups(const PhysicalInput<double>& in) {
  const auto g = physical_groups(in);
  const Reference r = reference(in);
  expect_eps(g.E_star, r.E_star, "E*");
  expect_eps(g.G_star, r.G_star, "G*");
  expect_eps(g.k_z, r.k_z, "k_z");
  expect_eps(g.k_x, r.k_x, "k_x");
  expect_eps(g.beta, r.beta, "beta");
  expect_eps(g.gamma, r.gamma, "gamma");
}

// A request with the inputs named by their members (PhysicalRequest::inputs), as decimal text.
void set_inputs(PhysicalRequest& r, const std::map<std::string, std::string>& values) {
  std::size_t set = 0;
  for (const PhysicalRequest::Member& m : r.inputs())
    if (const auto v = values.find(m.member); v != values.end()) {
      if (m.number)
        m.number->value = InputValue::read(v->second, m.member);
      else
        m.text->text = v->second;
      ++set;
    }
  if (set != values.size()) ADD_FAILURE() << "an input name that is no member of PhysicalRequest";
}

TEST(Physical, SteelOnSteelFlatPunch) {
  // E = 210 GPa, ν = 0.3, G = E/2.6; a = 1 mm; v0 = 1 mm/s, f = 100 Hz, A = 1 µm, ū = 0.5 µm, μ0 = 0.5.
  PhysicalInput<double> in{210e9, 0.3, 210e9, 0.3, 0, 0, 1e-3, 1e-3, 100, 1e-6, 0.5e-6, 0.5};
  expect_groups(in);
  EXPECT_EQ(physical_groups(in).gamma, 0.5);  // 0.5e-6/1e-6 rounds to 0.5 exactly
}

TEST(Physical, ExplicitShearModuliAndBadInput) {
  PhysicalInput<double> in{100e9, 0.25, 200e9, 0.2, 30e9, 70e9, 2e-3, 0.01, 50, 2e-6, -1e-6, 0.3};
  expect_groups(in);
  EXPECT_EQ(physical_groups(in).gamma, -0.5);
  auto bad = in;
  bad.radius = -1;
  EXPECT_THROW(physical_groups(bad), InputError);
  bad = in;
  bad.nu1 = 0.5000001;
  EXPECT_THROW(physical_groups(bad), InputError);
  auto rubber = in;  // incompressible: nu = 1/2 is a material, E* = E/(1 - 1/4) for that body
  rubber.nu1 = 0.5;
  expect_groups(rubber);
  bad = in;
  bad.mu0 = 0;
  EXPECT_THROW(physical_groups(bad), InputError);
}

// physical with two record options together, --unit and --periods, on the flat punch and a
// sphere: A is half the peak-to-peak of the K periods' mean (README, "File formats"), averaged
// here by hand in integers, and every output equals that of the mean record given with that A.
TEST(Physical, AmplitudeFromAnAveragedRecordInItsUnit) {
  const int n = 64, k = 2, m = n / k;
  std::vector<long long> y(n);  // nanometres
  std::string record = "time [s],displacement [um]\n";
  for (int j = 0; j < n; ++j) {
    y[static_cast<std::size_t>(j)] = std::llround(1e3 * (1.5 * std::sin(2 * M_PI * k * j / n) + 0.04 * std::sin(0.7 * j * j)));
    const long long a = std::llabs(y[static_cast<std::size_t>(j)]);
    char line[64];
    // stamps 1.5625 µs apart: a period of 32 samples at f = 20 kHz
    std::snprintf(line, sizeof line, "%de-10,%s%lld.%03lld\n", 15625 * j, y[static_cast<std::size_t>(j)] < 0 ? "-" : "", a / 1000,
                  a % 1000);
    record += line;
  }
  long long lo = 0, hi = 0;
  std::string sums;
  for (int j = 0; j < m; ++j) {
    long long sum = 0;
    for (int p = 0; p < k; ++p) sum += y[static_cast<std::size_t>(p * m + j)];
    lo = j == 0 ? sum : std::min(lo, sum);
    hi = j == 0 ? sum : std::max(hi, sum);
    sums += std::to_string(sum) + "\n";
  }
  // A = (max − min)/2 of the mean = (hi − lo)/(2K) nm = (hi − lo)/4 · 1e-9 m: a finite decimal.
  const long long quarter_nm_times_100 = (hi - lo) * 25;  // (hi − lo)/4 in units of 0.01 nm
  char a_text[64];
  std::snprintf(a_text, sizeof a_text, "%lld.%02llde-9", quarter_nm_times_100 / 100, quarter_nm_times_100 % 100);
  const std::string dir = ::testing::TempDir();
  std::ofstream(dir + "two_periods_um.csv") << record;
  std::ofstream(dir + "mean_sums.txt") << sums;
  WaveReadOptions two;
  two.periods = k;
  const WaveSpec recorded = parse_wave("samples:" + dir + "two_periods_um.csv", two);
  const WaveSpec mean = parse_wave("samples:" + dir + "mean_sums.txt");
  for (const char* shape : {"flat", "sphere"}) {
    SCOPED_TRACE(shape);
    PhysicalRequest with_unit, with_a;
    for (PhysicalRequest* r : {&with_unit, &with_a})
      set_inputs(*r, {{"E1", "210e9"}, {"nu1", "0.3"}, {"E2", "70e9"}, {"nu2", "0.33"}, {"v0", "2e-3"}, {"f", "20000"},
                      {"u_mean", "1e-7"}, {"mu0", "0.3"}, {"shape", shape},
                      {std::string(shape) == "flat" ? "radius" : "R", "1e-3"}});
    with_unit.unit.text = "um";
    with_a.A.value = InputValue::read(a_text, "A");
    const Precision precision{NumberType::mpfr, 40};
    std::map<std::string, PhysicalOutput> by_hand;
    for (const PhysicalOutput& o : physical_point(mean, with_a, precision)) by_hand.emplace(o.name, o);
    int compared = 0;
    for (const PhysicalOutput& o : physical_point(recorded, with_unit, precision)) {
      PrecisionScope scope(60);
      if (o.name == "A_m") {
        EXPECT_LT(abs(o.number.value / mpfr(a_text) - 1), mpfr("1e-38")) << o.text() << " against " << a_text;
        ++compared;
        continue;
      }
      const auto h = by_hand.find(o.name);
      ASSERT_NE(h, by_hand.end()) << o.name;
      if (!o.word.empty() || o.number.value == 0) {
        EXPECT_EQ(o.text(), h->second.text()) << o.name;
      } else {
        EXPECT_LT(abs(o.number.value / h->second.number.value - 1), mpfr("1e-38")) << o.name << " " << o.text() << " against " << h->second.text();
      }
      ++compared;
    }
    EXPECT_EQ(compared, static_cast<int>(by_hand.size()) + 1);
  }
}

// physical's rig outputs (commands.cpp): κ = k_s/k_x, Ω = √(k_x/m)/(2πf), ζ = c/(2√(m k_s)) against
// the formulas at 50 digits from the SI inputs, and the rig's lengths in metres against the
// dimensionless rig (evaluate_rig at the same β, γ, κ, Ω, ζ) times its unit μ0 k_z A/k_x
// (model.md), with μ0 = 0.3 so that a unit without μ0 shows.
TEST(Physical, RigOutputsInSIUnits) {
  PhysicalRequest r;
  set_inputs(r, {{"E1", "210e9"}, {"nu1", "0.3"}, {"E2", "70e9"}, {"nu2", "0.33"}, {"radius", "1e-3"}, {"v0", "1e-3"},
                 {"f", "20000"}, {"A", "2e-6"}, {"u_mean", "1e-6"}, {"mu0", "0.3"}, {"mass", "0.01"}, {"k_system", "1e7"},
                 {"damping", "5"}});
  const WaveSpec sine = parse_wave("sine");
  const Precision precision{NumberType::mpfr, 20};
  std::map<std::string, PhysicalOutput> out;
  for (const PhysicalOutput& o : physical_point(sine, r, precision)) out.emplace(o.name, o);
  PrecisionScope scope(50);
  PhysicalInput<mpfr> in;
  in.E1 = mpfr("210e9"), in.nu1 = mpfr("0.3"), in.E2 = mpfr("70e9"), in.nu2 = mpfr("0.33"), in.radius = mpfr("1e-3");
  in.v0 = mpfr("1e-3"), in.f = mpfr("20000"), in.A = mpfr("2e-6"), in.u_mean = mpfr("1e-6"), in.mu0 = mpfr("0.3");
  const Reference groups = reference(in);
  const mpfr &k_z = groups.k_z, &k_x = groups.k_x, &beta = groups.beta, &gamma = groups.gamma, &f = in.f, &A = in.A,
             &mu0 = in.mu0;
  const mpfr m("0.01"), ks("1e7"), c("5");
  const mpfr kappa = ks / k_x, omega = sqrt(mpfr(k_x / m)) / (2 * boost::math::constants::pi<mpfr>() * f),
             zeta = c / (2 * sqrt(mpfr(m * ks)));
  const auto expect_close = [&](const std::string& name, const mpfr& want, int digits) {
    const auto o = out.find(name);
    ASSERT_NE(o, out.end()) << name;
    if (want == 0) {
      EXPECT_EQ(o->second.number.value, 0) << name;
      return;
    }
    EXPECT_LT(abs(o->second.number.value / want - 1), pow(mpfr(10), 1 - digits)) << name << " " << o->second.text() << " against " << want.str(25);
  };
  for (const auto& [name, value] : {std::pair<std::string, mpfr>{"kappa", kappa}, {"omega", omega}, {"zeta", zeta},
                                    {"beta", beta}, {"gamma", gamma}})
    expect_close(name, value, 20);
  const auto computed = [](const mpfr& v) { return InputValue::computed(v, format_significant(v, 17)); };
  RigSpec spec;
  spec.kappa = computed(kappa);
  spec.omega = computed(omega);
  spec.zeta = computed(zeta);
  const RigReport rig = evaluate_rig(sine, Point(computed(beta), computed(gamma)), spec, {NumberType::mpfr, 30});
  const mpfr unit = mu0 * k_z * A / k_x;
  ASSERT_GT(rig.amplitude.digits, 8);
  expect_close("body_amplitude_m", mpfr(rig.amplitude.value * unit), std::min(20, rig.amplitude.digits));
  if (rig.largest_backward_slip.value != 0)
    expect_close("largest_backward_slip_m", mpfr(rig.largest_backward_slip.value * unit),
                 std::min(20, rig.largest_backward_slip.digits));
  else
    EXPECT_EQ(out.at("largest_backward_slip_m").number.value, 0);
  expect_close("stick_fraction", rig.stick_fraction.value, std::min(20, rig.stick_fraction.digits));
  expect_close("slip_fraction", rig.slip_fraction.value, std::min(20, rig.slip_fraction.digits));
  expect_close("mu", mpfr(mu0 * mpfr(rig.mu)), 19);
  // Without a damper the rig is undamped (ζ = 0), not refused.
  PhysicalRequest undamped = r;
  undamped.damping.value = InputValue();
  std::map<std::string, PhysicalOutput> free;
  for (const PhysicalOutput& o : physical_point(sine, undamped, precision)) free.emplace(o.name, o);
  ASSERT_EQ(free.count("zeta"), 1u);
  EXPECT_EQ(free.at("zeta").number.value, 0);
  EXPECT_EQ(free.at("kappa").text(), out.at("kappa").text());
}


// In-plane oscillation from SI inputs: a_l = G* u_x/(mu0 E* A) and, with a constant load, β = k_x v0/(mu0 F_N f),
// a = k_x u/(mu0 F_N), each computed here from Eq. 1 at 50 digits; the ratio, forces and fractions against
// evaluate_inplane at those groups.
TEST(Physical, InPlaneOutputsInSIUnits) {
  const std::map<std::string, std::string> solids{{"E1", "210e9"}, {"nu1", "0.3"}, {"E2", "70e9"}, {"nu2", "0.33"},
                                                  {"radius", "1e-3"}, {"mu0", "0.3"}};
  const Precision precision{NumberType::mpfr, 20};
  PrecisionScope scope(50);
  PhysicalInput<mpfr> in;
  in.E1 = mpfr("210e9"), in.nu1 = mpfr("0.3"), in.E2 = mpfr("70e9"), in.nu2 = mpfr("0.33"), in.radius = mpfr("1e-3");
  in.v0 = mpfr("2e-3"), in.f = mpfr("20000"), in.A = mpfr("1e-6"), in.u_mean = mpfr("2e-7"), in.mu0 = mpfr("0.3");
  const Reference groups = reference(in);
  const auto computed = [](const mpfr& v) { return InputValue::computed(v, format_significant(v, 40)); };
  const auto close = [](const PhysicalOutput& o, const mpfr& want, int digits) {
    if (want == 0) return o.number.value == 0;
    return abs(mpfr(o.number.value / want - 1)) < pow(mpfr(10), 1 - digits);
  };
  const auto outputs = [&](const WaveSpec& wave, const PhysicalRequest& r) {
    std::map<std::string, PhysicalOutput> out;
    for (const PhysicalOutput& o : physical_point(wave, r, precision)) out.emplace(o.name, o);
    return out;
  };
  {  // normal and longitudinal oscillation, a quarter period apart (the ratchet: F_x < 0)
    PhysicalRequest r;
    auto values = solids;
    values.insert({{"v0", "2e-3"}, {"f", "20000"}, {"A", "1e-6"}, {"u_mean", "2e-7"}, {"u_x", "1e-6"}, {"phase", "0.25"}});
    set_inputs(r, values);
    const WaveSpec sine = parse_wave("sine");
    const auto out = outputs(sine, r);
    const mpfr a_l = groups.G_star * mpfr("1e-6") / (in.mu0 * groups.E_star * in.A);
    InPlaneSpec spec;
    spec.longitudinal = computed(a_l);
    spec.phase = InputValue::read("0.25", "phase");
    const InPlaneReport want = evaluate_inplane(sine, Point(computed(groups.beta), computed(groups.gamma)), spec, {NumberType::mpfr, 30});
    EXPECT_TRUE(close(out.at("longitudinal"), a_l, 20)) << out.at("longitudinal").text();
    EXPECT_EQ(out.at("transverse").number.value, 0);
    EXPECT_TRUE(close(out.at("mu_over_mu0"), mpfr(want.mu), 19)) << out.at("mu_over_mu0").text() << " against " << want.mu;
    EXPECT_LT(out.at("mu_over_mu0").number.value, 0);
    const mpfr F_N = out.at("F_N_mean_N").number.value;
    EXPECT_TRUE(close(out.at("F_x_mean_N"), mpfr(mpfr(want.mu) * in.mu0 * F_N), 19)) << out.at("F_x_mean_N").text();
    EXPECT_EQ(out.at("F_y_mean_N").number.value, 0);
    EXPECT_TRUE(close(out.at("stick_fraction"), want.stick_fraction.value, want.stick_fraction.digits - 1));
    EXPECT_TRUE(close(out.at("slip_fraction"), want.slip_fraction.value, want.slip_fraction.digits - 1));
    EXPECT_TRUE(close(out.at("backward_slip_fraction"), want.backward_fraction.value, want.backward_fraction.digits - 1));
    EXPECT_TRUE(close(out.at("flight_fraction"), want.flight_fraction.value, want.flight_fraction.digits - 1));
    EXPECT_EQ(out.count("beta_c"), 0u);  // the paper's β_c is not the in-plane model's
    // Zero amplitudes are the paper's model: its value and outputs, with the drive's columns.
    PhysicalRequest zero = r;
    zero.u_x.value = InputValue::read("0", "u_x");
    PhysicalRequest none = r;
    none.u_x.value = InputValue();
    none.phase.value = InputValue();
    const auto z = outputs(sine, zero), n = outputs(sine, none);
    EXPECT_EQ(z.at("mu_over_mu0").text(), n.at("mu_over_mu0").text());
    EXPECT_EQ(z.at("stick_fraction").text(), n.at("stick_fraction").text());
    EXPECT_EQ(n.count("longitudinal"), 0u);
  }
  {  // normal and transverse oscillation a quarter period apart: the lateral force μ0 F_N ∫s_y/∫n,
     // with μ0 = 0.3 apart from 1 (in double: the planar solver at 20 digits takes seconds)
    PhysicalRequest r;
    auto values = solids;
    values.insert({{"v0", "2e-3"}, {"f", "20000"}, {"A", "1e-6"}, {"u_mean", "2e-7"}, {"u_y", "1e-6"}, {"phase", "0.25"}});
    set_inputs(r, values);
    const WaveSpec sine = parse_wave("sine");
    std::map<std::string, PhysicalOutput> out;
    for (const PhysicalOutput& o : physical_point(sine, r, {NumberType::float64, 17})) out.emplace(o.name, o);
    const mpfr a_t = groups.G_star * mpfr("1e-6") / (in.mu0 * groups.E_star * in.A);
    InPlaneSpec spec;
    spec.longitudinal = InputValue::read("0", "longitudinal");
    spec.transverse = computed(a_t);
    spec.phase = InputValue::read("0.25", "phase");
    const InPlaneReport want =
        evaluate_inplane(sine, Point(computed(groups.beta), computed(groups.gamma)), spec, {NumberType::float64, 17});
    EXPECT_TRUE(close(out.at("transverse"), a_t, 15)) << out.at("transverse").text();
    const mpfr F_N = out.at("F_N_mean_N").number.value;
    ASSERT_GT(abs(want.mean_lateral.value), mpfr("0.1"));
    EXPECT_TRUE(close(out.at("F_y_mean_N"), mpfr(want.mean_lateral.value * in.mu0 * F_N), want.mean_lateral.digits - 1))
        << out.at("F_y_mean_N").text() << " against " << want.mean_lateral.text();
    EXPECT_TRUE(close(out.at("F_x_mean_N"), mpfr(mpfr(want.mu) * in.mu0 * F_N), 14)) << out.at("F_x_mean_N").text();
  }
  {  // a constant normal load with both in-plane drives
    PhysicalRequest r;
    auto values = solids;
    values.insert({{"v0", "2e-2"}, {"f", "20000"}, {"F_N", "10"}, {"u_x", "2e-7"}});
    set_inputs(r, values);
    r.constant_normal = true;
    WaveSpec constant;
    constant.name = "constant";
    const auto out = outputs(constant, r);
    const mpfr unit = in.mu0 * mpfr(10);
    const mpfr beta = groups.k_x * mpfr("2e-2") / (unit * in.f), a = groups.k_x * mpfr("2e-7") / unit;
    InPlaneSpec spec;
    spec.constant_normal = true;
    spec.longitudinal = computed(a);
    const InPlaneReport want = evaluate_inplane(constant, Point(computed(beta), InputValue()), spec, {NumberType::mpfr, 30});
    EXPECT_TRUE(close(out.at("beta"), beta, 20)) << out.at("beta").text();
    EXPECT_TRUE(close(out.at("longitudinal"), a, 20)) << out.at("longitudinal").text();
    EXPECT_TRUE(close(out.at("k_x_N_per_m"), groups.k_x, 20));
    EXPECT_TRUE(close(out.at("mu_over_mu0"), mpfr(want.mu), 19)) << out.at("mu_over_mu0").text() << " against " << want.mu;
    EXPECT_TRUE(close(out.at("F_x_mean_N"), mpfr(mpfr(want.mu) * unit), 19));
    EXPECT_TRUE(close(out.at("F_N_mean_N"), mpfr(10), 20));
    EXPECT_TRUE(close(out.at("stick_fraction"), want.stick_fraction.value, want.stick_fraction.digits - 1));
    EXPECT_EQ(out.at("flight_fraction").number.value, 0);
    // Refused: what a constant load does not have, a rig, a bad amplitude or phase.
    for (const auto& [member, text] : std::vector<std::pair<std::string, std::string>>{
             {"A", "1e-6"}, {"u_mean", "1e-7"}, {"mass", "0.01"}, {"u_x", "-1e-7"}, {"u_y", "-2e-7"}, {"shape", "sphere"}}) {
      PhysicalRequest bad = r;
      set_inputs(bad, {{member, text}});
      EXPECT_THROW(physical_point(constant, bad, precision), InputError) << member << " " << text;
    }
    PhysicalRequest fourier = r;
    fourier.in_plane_wave.text = "fourier:0,1";
    EXPECT_THROW(physical_point(constant, fourier, precision), InputError);
  }
  {  // no in-plane amplitude: the in-plane controls alone are refused
    PhysicalRequest r;
    auto values = solids;
    values.insert({{"v0", "2e-3"}, {"f", "20000"}, {"A", "1e-6"}, {"u_mean", "2e-7"}, {"phase", "0.25"}});
    set_inputs(r, values);
    EXPECT_THROW(physical_point(parse_wave("sine"), r, precision), InputError);
  }
}

}  // namespace
