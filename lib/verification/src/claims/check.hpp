// Shared machinery of the claim checks (claims.hpp): a precision-guaranteed solver handle and the
// running record of deviations that a check turns into a verdict.
#pragma once
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/ladder.hpp"
#include "vibrofric/core/certified/enclosure.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/numbers.hpp"
#include "vibrofric/core/flat/solver.hpp"
#include "vibrofric/verification/claims.hpp"

namespace vibrofric::claims {

using Real = mpfr;

inline Real num(const char* s) { return Real(s); }
inline std::string str(const Real& x, int digits = 12) { return format_significant(x, digits); }
inline std::string sci(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", x);
  return b;
}

// μ̄ and Ψ of one wave with a relative error below 10^−(digits + 2), by the solver's own rounding
// bound: the working precision is raised (and the wave rebuilt at it) until the bound is met.
// Never a silently inaccurate number: SolverError if 8 raises do not suffice.
class Solver {
 public:
  Solver(const std::string& wave, int digits) : spec_(parse_wave(wave)), digits_(digits) {}

  Real mu(const Real& beta, const Real& gamma) { return run(beta, &gamma).mu; }
  Real psi(const Real& beta) { return run(beta, nullptr).lost_area; }
  Result<Real> result(const Real& beta, const Real& gamma) { return run(beta, &gamma); }
  Real beta_c(const Real& gamma) { return contact(gamma).beta_c(); }
  const Waveform<Real>& wave() {
    auto& slot = waves_[working_digits10<Real>()];
    if (!slot) slot = make_waveform<Real>(spec_);
    return *slot;
  }
  const std::string& name() const { return spec_.name; }

 private:
  const Contact<Real>& contact(const Real& gamma) {
    const int d = working_digits10<Real>();
    if (!contact_ || contact_digits_ != d || contact_gamma_ != gamma) {
      contact_.reset();
      contact_ = std::make_unique<Contact<Real>>(make_contact(wave(), gamma));
      contact_digits_ = d;
      contact_gamma_ = gamma;
    }
    return *contact_;
  }

  Result<Real> run(const Real& beta, const Real* gamma) {
    const Real target = pow(Real(10), -(digits_ + 2));
    RaisePolicy policy;
    policy.double_on_precision_error = false;  // as before the one ladder: a wave beyond its type is an error
    const auto r = raise_precision(
        working_digits10<Real>(), policy, [&] { return gamma ? solve(contact(*gamma), beta) : psi_at(beta); },
        [&](const Result<Real>& x) { return shortfall(gamma ? x.relative_error : x.lost_relative_error, target); });
    if (r) return *r;
    throw SolverError("claims: wave " + spec_.name + ", beta = " + str(beta, 20) +
                      (gamma ? ", gamma = " + str(*gamma, 20) : std::string()) + ": could not reach " +
                      std::to_string(digits_ + 2) + " digits");
  }
  Result<Real> psi_at(const Real& beta) { return solve(contact(Real(-wave().minimum())), beta); }

  WaveSpec spec_;
  int digits_;
  std::map<int, std::unique_ptr<Waveform<Real>>> waves_;
  std::unique_ptr<Contact<Real>> contact_;
  int contact_digits_ = -1;
  Real contact_gamma_;
};

// The running record of one check: the largest deviation of the statement as made, and of a
// corrected statement where there is one, both kept at the working precision (a double would
// underflow beyond 300 digits).
class Check {
 public:
  explicit Check(const ClaimEntry& e, int digits) {
    c_.key = e.key;
    c_.id = e.id;
    c_.source = e.source;
    c_.statement = e.statement;
    c_.method = e.method;
    c_.proof = e.proof;
    c_.digits = digits;
    c_.deviation_unit = "relative";
  }
  ClaimCheck& out() { return c_; }
  // What the deviation measures, when it is not the relative deviation of compare().
  void unit(std::string u) { c_.deviation_unit = std::move(u); }

  // Relative deviation |got − want|/|want| (absolute where want = 0) of the claim at `where`.
  void compare(const Real& got, const Real& want, const std::string& where) {
    record(deviation_real(got, want), where + ": solver " + str(got, 20) + ", claim " + str(want, 20));
  }
  // A deviation measured by the caller (e.g. a boolean property: 0 or 1).
  void record(const Real& d, const std::string& where) {
    ++c_.cases;
    if (c_.cases == 1 || d > dev_) {
      dev_ = d;
      c_.worst = where;
    }
  }
  void record(double d, const std::string& where) { record(Real(d), where); }
  // The deviation of the statement when the check measures it as one number (not a running maximum).
  void set_deviation(const Real& d) { dev_ = d; }
  const Real& largest() const { return dev_; }
  bool within_digits() const { return dev_ <= pow(Real(10), -c_.digits); }
  void compare_corrected(const Real& got, const Real& want) {
    const Real d = deviation_real(got, want);
    if (!corrected_ || d > corrected_dev_) corrected_dev_ = d;
    corrected_ = true;
  }
  // One number or word: its one field is "value".
  void measure(std::string name, std::string value) {
    c_.measured.push_back({std::move(name), value, {{"value", value}}});
  }
  // A printed value made of parts, each a named field.
  void measure(std::string name, std::string printed, std::vector<std::pair<std::string, std::string>> fields) {
    c_.measured.push_back({std::move(name), std::move(printed), std::move(fields)});
  }
  // "lo to hi", fields lo and hi.
  void measure_range(std::string name, std::string lo, std::string hi) {
    measure(std::move(name), lo + " to " + hi, {{"lo", lo}, {"hi", hi}});
  }

  // Exact claims: holds within 10^−digits; holds approximately up to 1e-3 (a deviation visible in
  // no figure of the paper, reported with its size); fails beyond.
  ClaimCheck finish_exact() {
    const std::string crit = "exact claim: holds if the deviation is <= 1e-" + std::to_string(c_.digits) +
                             ", holds approximately if <= 1e-3, else fails";
    if (within_digits()) return finish(Verdict::holds, crit);
    return finish(dev_ <= Real("1e-3") ? Verdict::holds_approximately : Verdict::fails, crit);
  }
  // The verdict is proven on the claim's grid by a certified computation (claims.hpp), `how`.
  void certified(std::string how) {
    c_.certification = "certified";
    c_.certification_note = std::move(how);
  }
  // What keeps the claim numerical.
  void numerical(std::string why) {
    c_.certification = "numerical";
    c_.certification_note = std::move(why);
  }
  ClaimCheck finish(Verdict v, std::string criterion) {
    c_.verdict = v;
    if (c_.certification_note.empty())
      c_.certification_note = v == Verdict::holds_approximately
                                  ? "an approximate statement: its verdict is a measured size, not an identity an enclosure could prove"
                                  : "decided by the high-precision solver and its error estimate; no certified check of it yet";
    c_.criterion = std::move(criterion);
    c_.deviation = static_cast<double>(dev_);
    c_.deviation_text = text(dev_);
    if (corrected_) {
      c_.corrected_deviation = static_cast<double>(corrected_dev_);
      c_.corrected_deviation_text = text(corrected_dev_);
    }
    return c_;
  }

  static Real deviation_real(const Real& got, const Real& want) {
    using std::abs;
    return want == 0 ? Real(abs(got)) : Real(abs(got - want) / abs(want));
  }
  static double deviation(const Real& got, const Real& want) { return static_cast<double>(deviation_real(got, want)); }
  // Three significant digits with the exponent of the working precision ("1.23e-402", "0").
  static std::string text(const Real& x) {
    if (x == 0) return "0";
    mpfr_exp_t e10 = 0;
    char* raw = mpfr_get_str(nullptr, &e10, 10, 3, x.backend().data(), MPFR_RNDN);
    std::string ds(raw);
    mpfr_free_str(raw);
    std::string sign;
    if (ds[0] == '-') {
      sign = "-";
      ds.erase(0, 1);
    }
    const long e = static_cast<long>(e10) - 1;
    char tail[32];
    std::snprintf(tail, sizeof tail, "e%c%02ld", e < 0 ? '-' : '+', e < 0 ? -e : e);
    return sign + ds.substr(0, 1) + "." + ds.substr(1) + tail;
  }

 private:
  ClaimCheck c_;
  Real dev_ = 0, corrected_dev_ = 0;
  bool corrected_ = false;
};

inline std::string at(const std::string& wave, const Real& beta, const Real* gamma = nullptr) {
  std::string s = wave + ", beta = " + str(beta);
  if (gamma) s += ", gamma = " + str(*gamma);
  return s;
}

// The relative step below a threshold β_c at which a stick phase must show: 10^-ceil(D/4). Just
// below β_c the lost area shrinks like the cube of the step (the stick is a chord of slope β under
// a smooth rise), so the step has to scale with D for the stick to stay resolved at D digits (a
// fixed 1e-8 made μ̄ round to 1 at D = 10 to 13).
inline int below_exponent(int digits) { return (digits + 3) / 4; }
inline Real below_step(int digits) { return pow(Real(10), -below_exponent(digits)); }
inline std::string below_text(int digits) { return "beta_c (1 - 1e-" + std::to_string(below_exponent(digits)) + ")"; }

inline std::vector<Real> reals(const std::vector<const char*>& l) {
  std::vector<Real> out;
  for (const char* s : l) out.push_back(num(s));
  return out;
}

// β over (0, 100] with the catalogue's thresholds (2, 4) on both sides.
inline const std::vector<const char*>& beta_texts_wide() {
  static const std::vector<const char*> t{"0.001", "0.01", "0.1", "0.5", "1", "1.5", "1.999",
                                                    "2",     "2.5",  "3.9", "4",   "5", "10",  "100"};
  return t;
}
inline std::vector<Real> betas_wide() { return reals(beta_texts_wide()); }
// The jumping range (−1, 1], both ends approached.
inline const std::vector<const char*>& gamma_texts_jumping() {
  static const std::vector<const char*> t{"-0.999", "-0.9", "-0.5", "-0.3", "0", "0.25", "0.5", "0.9", "0.999", "1"};
  return t;
}
inline std::vector<Real> gammas_jumping() { return reals(gamma_texts_jumping()); }
// The paper's 11 values of γ for Figs. 3 and 4, from 1 to −1 in steps of 0.2. γ = −1 itself has no
// contact (model.md: a domain error), so the last curve is taken at −1 + 10^-3.
inline std::vector<Real> gammas_figure() {
  return reals({"1", "0.8", "0.6", "0.4", "0.2", "0", "-0.2", "-0.4", "-0.6", "-0.8", "-0.999"});
}

// The claims' enclosed waves (sine, power:p): at rational β, γ, with the bits of `digits` plus 40,
// doubled where a comparison is undecided (enclosure.hpp).
struct Enclosed {
  const char* name;
  std::optional<exact::Rational> p;  // power:p; none: the sine
  mpfr_prec_t bits;
  certified::SineEnclosure at(const exact::Rational& beta, const exact::Rational& gamma) const {
    const auto attempt = [&](long b) -> std::optional<certified::SineEnclosure> {
      try {
        return p ? certified::enclose_power(*p, beta, gamma, b) : certified::enclose_sine(beta, gamma, b);
      } catch (const certified::Undecided&) {
        return std::nullopt;
      }
    };
    if (bits <= max_certify_bits)
      if (auto e = escalate(bits, attempt, doubling_up_to(max_certify_bits))) return std::move(*e);
    throw SolverError(std::string(name) + ", beta = " + beta.str() + ", gamma = " + gamma.str() + ": no enclosure decides it");
  }
};
inline std::vector<Enclosed> enclosed_waves(int digits) {
  const auto bits = static_cast<mpfr_prec_t>(digits * 3.3219280948873623) + 40;
  return {{"sine", std::nullopt, bits}, {"power:2", exact::Rational(2), bits}, {"power:3", exact::Rational(3), bits}};
}
// x ∈ a and x ∈ b for some x, both narrower than 10^−digits relative to max(1, |a|): the enclosures
// prove |a − b| below 2·10^−digits.
inline bool overlap_within(const Interval& a, const Interval& b, int digits) {
  const mpfr tol = pow(mpfr(10), -digits) * std::max(mpfr(1), abs(a.upper()));
  return intersection(a, b).has_value() && a.width() < tol && b.width() < tol;
}

inline exact::Rational rational_of(const mpfr& x) {
  exact::Rational q;
  mpfr_get_q(q.backend().data(), x.backend().data());
  return q;
}
// Check functions, one per catalogue entry (exact.cpp, power.cpp, harmonic.cpp, static.cpp, curved.cpp).
ClaimCheck eq6(int digits);
ClaimCheck eq13(int digits);
ClaimCheck eq17(int digits);
ClaimCheck eq18(int digits);
ClaimCheck eq19(int digits);
ClaimCheck eq20_21(int digits);
ClaimCheck eq22(int digits);
ClaimCheck eq23(int digits);
ClaimCheck eq24(int digits);
ClaimCheck sec3(int digits);
ClaimCheck fig3(int digits);
ClaimCheck fig4_bunching(int digits);
ClaimCheck fig4_minimum(int digits);
ClaimCheck fig4_scaling(int digits);
ClaimCheck beta_c_table(int digits);
// Curved contacts (curved.cpp).
ClaimCheck scope_wearflat(int digits);
ClaimCheck scope_numerics(int digits);
ClaimCheck curved_eq6_sec3(int digits);
ClaimCheck curved_power_flat(int digits);
// Rig dynamics and Part II (rig.cpp).
ClaimCheck rig_limits(int digits);
ClaimCheck part2_limits(int digits);
ClaimCheck part2_resonance(int digits);
ClaimCheck inplane_rigid(int digits);
ClaimCheck inplane_ratchet(int digits);
ClaimCheck inplane_combined(int digits);
ClaimCheck inplane_transverse(int digits);

// The paper's remaining statements (statements.cpp).
ClaimCheck eqs7_13(int digits);
ClaimCheck eq6_jumping(int digits);
ClaimCheck entanglement(int digits);
ClaimCheck continuity(int digits);
ClaimCheck uniqueness(int digits);
ClaimCheck convexity(int digits);
ClaimCheck eq23_range(int digits);
ClaimCheck fig2(int digits);

const ClaimEntry& entry(const std::string& key);

}  // namespace vibrofric::claims
