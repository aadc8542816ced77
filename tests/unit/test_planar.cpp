// In-plane oscillation, the two-dimensional drive (model.md, "In-plane and combined oscillation";
// core/inplane/planar.hpp): a longitudinal drive against the stop operator (inplane.hpp, a second
// algorithm), the catching-up scheme written here with Richardson extrapolation, the rigid
// transverse limit (2/π) ξ/√(1+ξ²) K(1/√(1+ξ²)) with its order, the symmetries of the drive, the
// spans and fractions, the number types against each other, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include <boost/math/special_functions/ellint_1.hpp>

#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/core/inplane/inplane.hpp"
#include "vibrofric/core/inplane/planar.hpp"

namespace vibrofric {
namespace {

template <class Real>
std::unique_ptr<Waveform<Real>> wave_named(const std::string& name) {
  if (name == "sine") return std::make_unique<Sine<Real>>();
  if (name == "triangle") return make_triangle<Real>();
  if (name == "square") return make_square<Real>();
  if (name == "sawtooth-right") return make_sawtooth_right<Real>();
  return make_sawtooth_left<Real>();
}

struct Case {
  std::string w, p;  // w empty: constant normal force
  double gamma, beta, al, at, phase;
};

std::string describe(const Case& c) {
  return (c.w.empty() ? std::string("constant") : c.w + " gamma " + std::to_string(c.gamma)) + ", p " + c.p +
         ", beta " + std::to_string(c.beta) + ", a_l " + std::to_string(c.al) + ", a_t " + std::to_string(c.at) +
         ", P " + std::to_string(c.phase);
}

template <class Real>
PlanarResult<Real> solve_case(const Case& c) {
  const auto w = c.w.empty() ? nullptr : wave_named<Real>(c.w);
  const auto p = wave_named<Real>(c.p);
  return solve_planar<Real>(w.get(), Real(c.gamma), *p, Real(c.beta), PlanarDrive<Real>{Real(c.al), Real(c.at), Real(c.phase)});
}

// The combined cases of the tests: both drives, each normal force, jumps of p and n.
const std::vector<Case> kCases{
    {"", "sine", 0, 1, 0, 1, 0},          {"", "sine", 0, 0.5, 0.3, 0.7, 0.1},   {"sine", "sine", 0.5, 1, 0, 1, 0},
    {"sine", "sine", 1.5, 2, 0, 0.5, 0.25}, {"triangle", "triangle", 0.5, 1, 0.5, 0.5, 0.3},
    {"square", "sine", 0.5, 0.7, 0.2, 0.6, 0.4}, {"", "square", 0, 0.8, 0.4, 0.9, 0.15}};

// Moreau's catching-up scheme in the plane, s ← proj(s + ΔD) onto the disc of radius n, at N steps
// a period from s = (n(0), 0) until a period changes s by less than 1e-13; (μ̄, ∫s_y/∫n) of the last
// period by the rectangle rule.
std::array<double, 2> catching_up(const Case& c, long N) {
  const auto w = c.w.empty() ? nullptr : wave_named<double>(c.w);
  const auto p = wave_named<double>(c.p);
  const auto n = [&](double phi) {
    if (!w) return 1.0;
    const double v = c.gamma + (*w)(phi);
    return v > 0 ? v : 0.0;
  };
  std::complex<double> s(n(0), 0);
  double Sx = 0, Sy = 0, Nn = 0;
  for (int k = 0; k < 5000; ++k) {
    const std::complex<double> start = s;
    Sx = Sy = Nn = 0;
    double q_prev = (*p)(c.phase);
    for (long j = 1; j <= N; ++j) {
      const double phi = static_cast<double>(j) / N;
      const double q = (*p)(phi + c.phase), nn = n(phi);
      s += std::complex<double>(c.beta / N + c.al * (q - q_prev), c.at * (q - q_prev));
      q_prev = q;
      const double r = std::abs(s);
      if (r > nn) s = nn == 0 ? std::complex<double>(0, 0) : s * (nn / r);
      Sx += s.real();
      Sy += s.imag();
      Nn += nn;
    }
    if (std::abs(s - start) < 1e-13) break;
  }
  return {Sx / Nn, Sy / Nn};
}

// With a_t = 0 the sweeping process is the stop operator: the Gauss–Legendre integration of the
// slip angle (which stays at 0 or π) and the two-dimensional event searches against the exact
// one-dimensional solver. Tolerance 10^-24 at 30 digits: the integration's noise (2^20 ulps of the
// state, planar.hpp) over the periods, six orders above the working precision.
TEST(Planar, LongitudinalDriveIsTheStopOperator) {
  PrecisionScope scope(30);
  const std::vector<Case> cases{{"", "sine", 0, 1, 1, 0, 0},          {"sine", "sine", 0.5, 0, 1, 0, 0.25},
                                {"sine", "triangle", 1.5, 1, 0.7, 0, 0.6}, {"triangle", "sine", 0.5, 2, 0.3, 0, 0.1},
                                {"square", "square", 0.5, 0.5, 0.4, 0, 0.3}, {"", "sawtooth-right", 0, 0.3, 0.5, 0, 0}};
  for (const Case& c : cases) {
    const auto w = c.w.empty() ? nullptr : wave_named<mpfr>(c.w);
    const auto p = wave_named<mpfr>(c.p);
    const auto line = solve_inplane<mpfr>(w.get(), mpfr(c.gamma), *p, mpfr(c.beta), InPlaneDrive<mpfr>{mpfr(c.al), mpfr(c.phase)});
    const auto plane = solve_case<mpfr>(c);
    const mpfr tol("1e-24");
    EXPECT_LE(abs(plane.mu - line.mu), tol) << describe(c) << ": " << plane.mu << " vs " << line.mu;
    EXPECT_LE(abs(plane.mean_lateral), tol) << describe(c);
    EXPECT_LE(abs(plane.stick_fraction - line.stick_fraction), tol) << describe(c);
    EXPECT_LE(abs(plane.slip_fraction - line.slip_fraction), tol) << describe(c);
    EXPECT_LE(abs(plane.flight_fraction - line.flight_fraction), tol) << describe(c);
    EXPECT_LE(abs(plane.normal_area - line.normal_area), tol) << describe(c);
    EXPECT_LE(abs(plane.state[0] - line.state_s), mpfr("1e-20")) << describe(c);
  }
}

// The catching-up scheme converges at first order (its error is O(1/N), model.md); Richardson's
// 2 m(2N) − m(N) removes that term, and what is left is far below |m(2N) − m(N)|, the first-order
// error itself: the solver must lie within a quarter of it. The order is measured as well.
TEST(Planar, CatchingUpAgreesAfterRichardson) {
  PrecisionScope scope(25);
  for (const Case& c : kCases) {
    const long N = 1L << 15;
    const auto m1 = catching_up(c, N), m2 = catching_up(c, 2 * N), m3 = catching_up(c, 4 * N);
    const auto r = solve_case<mpfr>(c);
    const double exact[2] = {static_cast<double>(r.mu), static_cast<double>(r.mean_lateral)};
    for (int k = 0; k < 2; ++k) {
      const double first = std::abs(m3[k] - m2[k]), extrapolated = 2 * m3[k] - m2[k];
      EXPECT_LE(std::abs(exact[k] - extrapolated), first / 4 + 1e-12)
          << describe(c) << (k ? ": mean_lateral " : ": mu ") << exact[k] << " vs " << extrapolated;
      if (std::abs(m2[k] - m1[k]) > 1e-9) {  // the order, where the differences are above the rounding
        const double order = std::log2(std::abs(m2[k] - m1[k]) / first);
        EXPECT_GT(order, 0.8) << describe(c);
        EXPECT_LT(order, 1.2) << describe(c);
      }
    }
  }
}

// n ≡ 1, sine drive across the sliding direction at ξ = β/(2πa) = 1/2: the rigid limit
// (2/π) ξ/√(1+ξ²) K(1/√(1+ξ²)) (model.md, K of modulus k), approached from above at order 2 in 1/a.
TEST(Planar, RigidTransverseLimitWithItsOrder) {
  PrecisionScope scope(25);
  const mpfr xi("0.5"), pi = boost::math::constants::pi<mpfr>();
  const mpfr k = 1 / sqrt(1 + xi * xi);
  const mpfr limit = 2 / pi * xi * k * boost::math::ellint_1(k);
  EXPECT_LT(abs(limit - mpfr("0.642637682")), mpfr("1e-9"));  // model.md's 9 digits
  std::vector<double> d;
  for (int a : {10, 20, 40}) {
    const auto p = std::make_unique<Sine<mpfr>>();
    const auto r = solve_planar<mpfr>(nullptr, mpfr(0), *p, 2 * pi * a * xi, PlanarDrive<mpfr>{mpfr(0), mpfr(a), mpfr(0)});
    EXPECT_GT(r.mu, limit) << "a = " << a;
    EXPECT_EQ(r.stick_fraction, 0) << "a = " << a;  // rigid: it slips throughout
    d.push_back(static_cast<double>(r.mu - limit));
  }
  for (std::size_t i = 1; i < d.size(); ++i) {
    const double order = std::log2(d[i - 1] / d[i]);
    EXPECT_GT(order, 1.8) << "a = " << (10 << i);
    EXPECT_LT(order, 2.2) << "a = " << (10 << i);
  }
}

// The same limit from a = 10^4 to 10^6, where slip is stiff (|D'|/n ≈ 2πa√(ξ² + cos²)): the angle
// relaxes onto D''s within 10^-7 of a period, and the distance still falls as 1/a² (a² D ≈ 0.766 at
// ξ = 1/2, the catching-up reference's 0.764 at a = 100 being the same law), up to ξ = 4.
TEST(Planar, RigidTransverseLimitAtLargeAmplitudes) {
  PrecisionScope scope(25);
  const mpfr pi = boost::math::constants::pi<mpfr>();
  for (const char* xi_text : {"0.5", "4"}) {
    const mpfr xi(xi_text);
    const mpfr k = 1 / sqrt(1 + xi * xi);
    const mpfr limit = 2 / pi * xi * k * boost::math::ellint_1(k);
    std::vector<mpfr> d;
    for (const char* a_text : {"1e4", "1e5", "1e6"}) {
      const mpfr a(a_text);
      const auto p = std::make_unique<Sine<mpfr>>();
      const auto r = solve_planar<mpfr>(nullptr, mpfr(0), *p, 2 * pi * a * xi, PlanarDrive<mpfr>{mpfr(0), a, mpfr(0)});
      EXPECT_GT(r.mu, limit) << "xi " << xi_text << ", a = " << a_text;
      EXPECT_EQ(r.stick_fraction, 0) << "xi " << xi_text << ", a = " << a_text;
      d.push_back(mpfr(r.mu - limit));
    }
    for (std::size_t i = 1; i < d.size(); ++i) {
      const double order = static_cast<double>(log10(mpfr(d[i - 1] / d[i])));
      EXPECT_NEAR(order, 2.0, 0.01) << "xi " << xi_text << ", decade " << i;
    }
    EXPECT_LT(d.back(), mpfr("1e-11")) << "xi " << xi_text << ": a = 1e6";
  }
}

// n ≡ 1 and a wave with p(φ + 1/2) = −p(φ): the lateral force's mean vanishes; and with a_l = 0,
// shifting the drive by half a period mirrors it across the sliding direction (s_y → −s_y).
TEST(Planar, SymmetriesOfTheDrive) {
  PrecisionScope scope(30);
  for (const char* p : {"sine", "triangle", "square"}) {
    const auto r = solve_case<mpfr>({"", p, 0, 0.7, 0, 1.3, 0});
    EXPECT_LE(abs(r.mean_lateral), mpfr("1e-24")) << p;
  }
  for (const Case& c : {Case{"sine", "sine", 0.5, 1, 0, 1, 0}, Case{"triangle", "triangle", 1.2, 0.5, 0, 0.8, 0.25}}) {
    Case shifted = c;
    shifted.phase += 0.5;
    const auto a = solve_case<mpfr>(c), b = solve_case<mpfr>(shifted);
    EXPECT_LE(abs(a.mu - b.mu), mpfr("1e-24")) << describe(c);
    EXPECT_LE(abs(a.mean_lateral + b.mean_lateral), mpfr("1e-24")) << describe(c);
    EXPECT_GT(abs(a.mean_lateral), mpfr("0.01")) << describe(c);  // the mirror is not the trivial 0 = 0
  }
}

// The recorded period: spans cover [0, 1) in order, the fractions are theirs and add to 1, stick
// starts inside the disc and slip on its circle, and at(span, φ) keeps |s| ≤ n.
TEST(Planar, SpansObeyTheModel) {
  for (const Case& c : kCases) {
    const auto w = c.w.empty() ? nullptr : wave_named<double>(c.w);
    const auto p = wave_named<double>(c.p);
    const PlanarSolver<double> solver(w.get(), c.gamma, *p, c.beta, PlanarDrive<double>{c.al, c.at, c.phase});
    const auto r = solver.solve();
    double at = 0, stick = 0, slip = 0, flight = 0;
    for (const auto& s : r.spans) {
      EXPECT_NEAR(s.begin, at, 1e-12) << describe(c);
      at = s.end;
      const double len = s.end - s.begin;
      (s.mode == PlanarMode::stick ? stick : s.mode == PlanarMode::slip ? slip : flight) += len;
      const auto v0 = solver.at(s, s.begin), vm = solver.at(s, (s.begin + s.end) / 2);
      EXPECT_LE(std::hypot(vm[1], vm[2]), vm[0] * (1 + 1e-12)) << describe(c);
      if (s.mode == PlanarMode::slip && v0[0] > 1e-6) {
        EXPECT_NEAR(std::hypot(v0[1], v0[2]), v0[0], 1e-12) << describe(c);
      }
      if (s.mode == PlanarMode::flight) {
        EXPECT_EQ(vm[0], 0) << describe(c);
      }
    }
    EXPECT_NEAR(at, 1, 1e-12) << describe(c);
    EXPECT_NEAR(stick, r.stick_fraction, 1e-14) << describe(c);
    EXPECT_NEAR(slip, r.slip_fraction, 1e-14) << describe(c);
    EXPECT_NEAR(flight, r.flight_fraction, 1e-14) << describe(c);
    EXPECT_NEAR(r.stick_fraction + r.slip_fraction + r.flight_fraction, 1, 1e-14) << describe(c);
  }
}

// double and long double against mpfr at 40 digits: within 2^18 eps of each type. The exception to
// the library's few-ulp rule is the method's: the fixed point stops where a period changes the state
// by less than 2^24 ulps (the noise of 2^12 ulps a step over the steps, planar.hpp), and that much of
// the state reaches μ̄ (measured: up to 2^16 eps; the tool computes in mpfr at two precisions).
TEST(Planar, NumberTypesAgree) {
  for (const Case& c : kCases) {
    const auto rd = solve_case<double>(c);
    const auto rl = solve_case<long double>(c);
    PrecisionScope scope(40);
    const auto rm = solve_case<mpfr>(c);
    const long double ref = static_cast<long double>(rm.mu), lat = static_cast<long double>(rm.mean_lateral);
    const double ed = std::ldexp(std::numeric_limits<double>::epsilon(), 18);
    const long double el = std::ldexp(std::numeric_limits<long double>::epsilon(), 18);
    EXPECT_LE(std::abs(rd.mu - ref), ed) << describe(c);
    EXPECT_LE(std::abs(rd.mean_lateral - lat), ed) << describe(c);
    EXPECT_LE(std::abs(rl.mu - ref), el) << describe(c);
    EXPECT_LE(std::abs(rl.mean_lateral - lat), el) << describe(c);
  }
}

// A small transverse drive (n ≡ 1, sine) slips throughout with a small angle: linearised,
// θ' = −βθ + 2πa cos 2πφ, so θ = Re C e^{2πiφ} with |C| = 2πa/√(β² + 4π²), and μ̄ = ⟨cos θ⟩ =
// 1 − π²a²/(β² + 4π²) + O(a⁴) (the O(a³) part of θ has no mean forcing: its coefficient is below 1,
// 0.08 measured at a = 1e-3). At β = πa the angle relaxes by only βφ a period: the one-period map
// contracts by 1 − β, and from the opposite start the state is first reached across the disc.
TEST(Planar, SmallAmplitudeSlipsAtTheLinearisedAngle) {
  struct Point {
    int digits;  // 27 and 39: the API's two precisions for a double
    const char* a;
    bool slow;
  };
  for (const Point& c : {Point{27, "1e-3", true}, Point{27, "1e-5", true}, Point{39, "1e-4", true}, Point{27, "1e-3", false}}) {
    PrecisionScope scope(c.digits);
    // The wave at the working precision, as the API makes it (its 2π at 20 digits rounds D' there).
    const auto p = std::make_unique<Sine<mpfr>>();
    const mpfr a(c.a), pi = boost::math::constants::pi<mpfr>();
    const mpfr beta = c.slow ? mpfr(pi * a) : mpfr(1);
    const auto r = solve_planar<mpfr>(nullptr, mpfr(0), *p, beta, PlanarDrive<mpfr>{mpfr(0), a, mpfr(0)});
    const mpfr linear = 1 - pi * pi * a * a / (beta * beta + 4 * pi * pi);
    EXPECT_LE(mpfr(abs(mpfr(r.mu - linear))), mpfr(a * a * a * a)) << c.digits << " digits, a " << c.a << ", beta " << beta;
    EXPECT_EQ(r.stick_fraction, 0) << c.digits << " digits, a " << c.a;
    // 0 by the drive's symmetry, to the state's accuracy: the solver's noise 2^(24 − bits) over the
    // map's contraction 1 − e^−β ≈ β.
    const mpfr noise = ldexp(mpfr(1), 24 - static_cast<int>(mpfr_get_default_prec()));
    EXPECT_LE(mpfr(abs(r.mean_lateral)), mpfr(64 * noise / beta)) << c.digits << " digits, a " << c.a;
  }
}

// β = 0 and the in-plane wave the normal one in phase, from touch-down: D − D(touch-down) = a n with
// a = (a_l, a_t), so s = a n inside the disc for |a| < 1 (stick), and on its edge for |a| = 1, where
// the slip rate |D'| − n' = (|a| − 1) n' is 0 throughout: slip (λ ≥ 0, model.md), as the stop operator
// decides at a_t = 0. So μ̄ = a_l, ∫s_y/∫n = a_t, and the contact's fraction (2/3 for the sine at
// γ = 1/2, 3/4 for the triangle) is slip or stick. Before, the tie stopped the solver ("cannot be
// separated"): the slip rate's enclosure took n' and p' as independent.
TEST(Planar, ForceRidingTheCircleAtATie) {
  PrecisionScope scope(30);
  struct Tie {
    const char* wave;
    const char *al, *at;
    int num, den;  // the contact's fraction
    bool edge;     // |a| = 1
  };
  for (const Tie& t : {Tie{"sine", "0", "1", 2, 3, true}, Tie{"sine", "0.6", "0.8", 2, 3, true},
                       Tie{"sine", "0", "0.8", 2, 3, false}, Tie{"triangle", "0.6", "0.8", 3, 4, true},
                       Tie{"triangle", "0", "1", 3, 4, true}}) {
    const Case c{t.wave, t.wave, 0.5, 0, std::stod(t.al), std::stod(t.at), 0};
    const auto check = [&](const auto& r, const mpfr& tol, const char* type) {
      const std::string where = describe(c) + ", " + type;
      const mpfr contact = mpfr(t.num) / t.den;
      // in double the amplitudes are the doubles nearest a_l and a_t (|a| = 1 to their rounding)
      const bool dbl = std::string(type) == "double";
      const mpfr al = dbl ? mpfr(c.al) : mpfr(t.al), at = dbl ? mpfr(c.at) : mpfr(t.at);
      EXPECT_LE(abs(mpfr(r.mu) - al), tol) << where;
      EXPECT_LE(abs(mpfr(r.mean_lateral) - at), tol) << where;
      EXPECT_LE(abs(mpfr(t.edge ? r.slip_fraction : r.stick_fraction) - contact), tol) << where;
      EXPECT_LE(abs(mpfr(r.flight_fraction) - (1 - contact)), tol) << where;
    };
    try {
      // the decimal amplitudes at the working precision: 0.6² + 0.8² = 1 to its rounding (with the
      // doubles nearest them |a| = 1 + 2e-17, and the force rightly sticks where n falls)
      const auto w = wave_named<mpfr>(t.wave), p = wave_named<mpfr>(t.wave);
      check(solve_planar<mpfr>(w.get(), mpfr("0.5"), *p, mpfr(0), PlanarDrive<mpfr>{mpfr(t.al), mpfr(t.at), mpfr(0)}),
            mpfr("1e-25"), "mpfr");
    } catch (const SolverError& e) {
      ADD_FAILURE() << describe(c) << ", mpfr: " << e.what();
    }
    try {
      check(solve_case<double>(c), mpfr("1e-13"), "double");
    } catch (const SolverError& e) {
      ADD_FAILURE() << describe(c) << ", double: " << e.what();
    }
  }
}

// No sliding and no longitudinal drive (β = 0, a_l = 0): a state that slips settles on the drive's
// axis (s_x' = −λ cos θ in slip, planar.hpp), where the one-period map's fixed point may be reached
// only algebraically. Closed forms: n ≡ 1 with a sine of amplitude 2 sticks and slips a quarter
// period each half (s_y = 2 sin 2πφ ∓ 1 in stick, ±1 in slip: ∫s_y = 0); of amplitude 1 a quarter
// period late, s_y = cos 2πφ touches the circle twice and sticks throughout; the square normal
// wave at γ = 3/2 (n = 5/2, then 1/2) with a_t = 1/2 a quarter period late fits s_y = cos(2πφ)/2
// into the narrow half exactly. Before, the last three stopped with an error (periods or bisections
// run out, or a band of states reported). The others
// against the catching-up scheme, and the 2-D map from a start off the axis: |s_x| never grows and
// falls where the force slips.
TEST(Planar, WithoutSlidingTheForceSettlesOnTheDriveAxis) {
  PrecisionScope scope(30);
  struct Closed {
    Case c;
    double stick, slip;
  };
  for (const Closed& k : {Closed{{"", "sine", 0, 0, 0, 2, 0}, 0.5, 0.5}, Closed{{"", "sine", 0, 0, 0, 1, 0.25}, 1, 0},
                          Closed{{"", "sine", 0, 0, 0, 1, 0}, 1, 0}, Closed{{"square", "sine", 1.5, 0, 0, 0.5, 0.25}, 1, 0}}) {
    for (const int type : {0, 1}) {
      try {
        const auto r = type ? solve_case<mpfr>(k.c) : [&] {
          const auto d = solve_case<double>(k.c);
          PlanarResult<mpfr> m;
          m.mu = d.mu, m.mean_lateral = d.mean_lateral, m.stick_fraction = d.stick_fraction;
          m.slip_fraction = d.slip_fraction, m.flight_fraction = d.flight_fraction;
          return m;
        }();
        const mpfr tol = type ? mpfr("1e-25") : mpfr("1e-14");
        const std::string where = describe(k.c) + (type ? ", mpfr" : ", double");
        EXPECT_LE(abs(r.mu), tol) << where;
        EXPECT_LE(abs(r.mean_lateral), tol) << where;
        EXPECT_LE(abs(r.stick_fraction - k.stick), tol) << where;
        EXPECT_LE(abs(r.slip_fraction - k.slip), tol) << where;
        EXPECT_LE(abs(r.flight_fraction), tol) << where;
      } catch (const SolverError& e) {
        ADD_FAILURE() << describe(k.c) << ": " << e.what();
      }
    }
  }
  for (const Case& c : {Case{"sine", "triangle", -0.3, 0, 0, 0.7, 0.3}, Case{"", "sawtooth-right", 0, 0, 0, 1.5, 0.1},
                        Case{"triangle", "sine", 0.5, 0, 0, 1.2, 0.6}}) {
    // Where events fall between the scheme's steps its error is first order with a coefficient that
    // wanders with N (the triangle's: 6.1e-10, 1.1e-10, 3.3e-11, 1.2e-11, 9.3e-13 from 2^16 to 2^20
    // steps), which Richardson's step does not remove: the solver within the last two doublings' change.
    const auto m18 = catching_up(c, 1L << 18), m20 = catching_up(c, 1L << 20);
    const auto r = solve_case<mpfr>(c);
    EXPECT_EQ(r.mu, 0) << describe(c);
    EXPECT_LE(std::abs(static_cast<double>(r.mean_lateral) - m20[1]), std::abs(m20[1] - m18[1]))
        << describe(c) << ": " << r.mean_lateral << " vs " << m20[1];
    EXPECT_LE(std::abs(m20[0]), 1e-12) << describe(c);
  }
  for (const Case& c : {Case{"", "sine", 0, 0, 0, 1, 0.25}, Case{"sine", "triangle", -0.3, 0, 0, 0.7, 0.3}}) {
    const auto w = c.w.empty() ? nullptr : wave_named<double>(c.w);
    const auto p = wave_named<double>(c.p);
    const PlanarSolver<double> map(w.get(), c.gamma, *p, c.beta, PlanarDrive<double>{c.al, c.at, c.phase});
    std::array<double, 2> s{0.3, 0.5};
    const double start = s[0];
    for (int k = 0; k < 20; ++k) {
      const auto next = map.period(s, nullptr);
      EXPECT_LE(std::abs(next[0]), std::abs(s[0]) * (1 + 1e-15)) << describe(c) << ", period " << k;
      s = next;
    }
    EXPECT_LT(std::abs(s[0]), start / 2) << describe(c);
  }
}

// A sticking force that reaches the circle at a vanishing angle (n ≡ 1, s_y = cos 2πφ + c from
// s = (ε, √(1 − ε²))): |s|² − n² rises through 0 near φ = 1/2 with a slope of order ε, staying within
// its rounding over some 10^5 ulps (ε = 10^-6 in double) or touching it (ε = 0), where bisection
// cannot separate touching from leaving; the stick goes on to where it has left by more than the
// rounding (planar.hpp's stick end). Before, the bisection's budget ran out ("the end of stick
// cannot be separated"), in double at ε = 10^-6 and at 30 digits at every ε from 10^-6 to 10^-12.
// The state returns within ε of (0, 1), slipping at most a fraction ε of the period.
TEST(Planar, ForceGrazingTheCircleSticksOn) {
  const auto check = [](auto zero, std::initializer_list<const char*> starts) {
    using Real = decltype(zero);
    using std::abs;
    using std::sqrt;
    const Sine<Real> p;
    const PlanarSolver<Real> map(nullptr, Real(0), p, Real(0), PlanarDrive<Real>{Real(0), Real(1), Real(0.25)});
    const Real tol = 64 * std::numeric_limits<Real>::epsilon();
    for (const char* start : starts) {
      const Real e(std::stod(start));
      try {
        PlanarResult<Real> rec{};
        const auto s = map.period({e, Real(sqrt(1 - e * e))}, &rec);
        EXPECT_LE(abs(s[0]), e + tol) << start;
        EXPECT_LE(abs(s[1] - 1), e + tol) << start;
        EXPECT_LE(rec.slip_fraction, e + tol) << start;  // where D' = 0 (φ = 0) slip may start and end at once
        EXPECT_LE(abs(rec.retained_area), e + tol) << start;
        EXPECT_LE(abs(rec.lateral_area), e + tol) << start;  // ∫ cos 2πφ = 0
      } catch (const SolverError& ex) {
        ADD_FAILURE() << start << ": " << ex.what();
      }
    }
  };
  check(0.0, {"0", "1e-6"});
  PrecisionScope scope(30);
  check(mpfr(0), {"0", "1e-6", "1e-8", "1e-12"});
}

// A contact that begins at n = 0 and ends by a jump of n (sawtooth-right below γ = 1: n rises at
// rate 2 from touch-down, then drops to flight), under a drive whose slope is constant there (a
// triangle's rising piece over the whole contact): from touch-down s = n D'/|D'| where |D'| ≥ n' = 2,
// so μ̄ = (β + 4 a_l)/|D'| and ∫s_y/∫n = 4 a_t/|D'| with D' = (β + 4 a_l, 4 a_t), exactly. Before,
// the contact's end was cut at its start (n·(v − φ) small there too, n being 0) and no slip was
// integrated: μ̄ = 0.
TEST(Planar, ContactEndingByAJumpOfN) {
  struct Jump {
    double gamma, beta, al, at, phase;  // the contact [(1 − γ)/2, 1) inside a rising piece of p
  };
  for (const Jump& j : {Jump{-0.483, 2.731, 0.642, 0.749, 0.296}, Jump{-0.2, 0.5, 0, 1.5, 0.45},
                        Jump{-0.2, 1, 0.25, 0.5, 0.45}}) {
    const Case c{"sawtooth-right", "triangle", j.gamma, j.beta, j.al, j.at, j.phase};
    const auto check = [&](const auto& r, const mpfr& tol, const char* type) {
      // the inputs as the solve had them: the doubles, or the decimals at 30 digits
      const auto in = [&](double x) { return type[0] == 'd' ? mpfr(x) : mpfr(std::to_string(x)); };
      const mpfr gamma = in(j.gamma);
      const mpfr dx = in(j.beta) + 4 * in(j.al), dy = 4 * in(j.at), len = sqrt(dx * dx + dy * dy);
      ASSERT_GE(len, 2) << describe(c);
      const std::string where = describe(c) + ", " + type;
      EXPECT_LE(abs(mpfr(r.mu) - dx / len), tol) << where << ": " << r.mu;
      EXPECT_LE(abs(mpfr(r.mean_lateral) - dy / len), tol) << where;
      EXPECT_LE(abs(mpfr(r.slip_fraction) - (1 + gamma) / 2), tol) << where;
      EXPECT_LE(abs(mpfr(r.flight_fraction) - (1 - gamma) / 2), tol) << where;
    };
    try {
      check(solve_case<double>(c), mpfr("1e-13"), "double");
    } catch (const SolverError& e) {
      ADD_FAILURE() << describe(c) << ", double: " << e.what();
    }
    PrecisionScope scope(30);
    try {
      const auto w = wave_named<mpfr>(c.w), p = wave_named<mpfr>(c.p);
      const auto dec = [](double x) { return mpfr(std::to_string(x)); };
      check(solve_planar<mpfr>(w.get(), dec(j.gamma), *p, dec(j.beta), PlanarDrive<mpfr>{dec(j.al), dec(j.at), dec(j.phase)}),
            mpfr("1e-25"), "mpfr");
    } catch (const SolverError& e) {
      ADD_FAILURE() << describe(c) << ", mpfr: " << e.what();
    }
  }
}

// β = 0 with a drive too small to slip: every state of a band is periodic, and the two starts say so.
TEST(Planar, StickingThroughThePeriodHasNoUniqueState) {
  PrecisionScope scope(30);
  const auto p = std::make_unique<Sine<mpfr>>();
  EXPECT_THROW(solve_planar<mpfr>(nullptr, mpfr(0), *p, mpfr(0), PlanarDrive<mpfr>{mpfr("0.05"), mpfr("0.05"), mpfr(0)}),
               SolverError);
  const auto w = std::make_unique<Sine<mpfr>>();
  EXPECT_THROW(solve_planar<mpfr>(w.get(), mpfr(3), *p, mpfr(0), PlanarDrive<mpfr>{mpfr(0), mpfr("0.1"), mpfr("0.3")}),
               SolverError);
}

TEST(Planar, BadInputIsRefused) {
  const auto p = std::make_unique<Sine<double>>();
  const auto w = std::make_unique<Sine<double>>();
  PlanarDrive<double> d{0, 1, 0};
  d.transverse = -1;
  EXPECT_THROW(solve_planar<double>(w.get(), 0.5, *p, 1.0, d), InputError);
  d.transverse = std::nan("");
  EXPECT_THROW(solve_planar<double>(w.get(), 0.5, *p, 1.0, d), InputError);
  d.transverse = 1;
  d.longitudinal = -0.5;
  EXPECT_THROW(solve_planar<double>(w.get(), 0.5, *p, 1.0, d), InputError);
  d.longitudinal = 0;
  EXPECT_THROW(solve_planar<double>(w.get(), 0.5, *p, -1.0, d), InputError);
  d.phase = std::numeric_limits<double>::infinity();
  EXPECT_THROW(solve_planar<double>(w.get(), 0.5, *p, 1.0, d), InputError);
  d.phase = 0;
  EXPECT_THROW(solve_planar<double>(w.get(), -1.0, *p, 1.0, d), DomainError);
}

}  // namespace
}  // namespace vibrofric
