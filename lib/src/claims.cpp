#include "vibrofric/claims.hpp"

#include <cmath>
#include <functional>
#include <sstream>

#include "vibrofric/catalogue.hpp"
#include "vibrofric/closed_forms.hpp"
#include "vibrofric/detail/evaluate_impl.hpp"
#include "vibrofric/solver.hpp"

namespace vibrofric {

std::string verdict_name(Verdict v) {
  switch (v) {
    case Verdict::holds: return "holds";
    case Verdict::holds_approximately: return "holds approximately";
    case Verdict::fails: return "fails";
  }
  return "?";
}

namespace {

using Real = mpfr;
namespace cf = closed_form;

Real num(const char* s) { return Real(s); }

std::vector<Real> betas_wide() {
  std::vector<Real> out;
  for (const char* b : {"0.001", "0.01", "0.1", "0.5", "1", "1.5", "1.999", "2", "2.5", "3.9", "4", "5", "10", "100"})
    out.push_back(num(b));
  return out;
}
std::vector<Real> gammas_jumping() {
  std::vector<Real> out;
  for (const char* g : {"-0.999", "-0.9", "-0.5", "-0.3", "0", "0.25", "0.5", "0.9", "0.999", "1"})
    out.push_back(num(g));
  return out;
}

class Check {
 public:
  Check(std::string id, std::string statement, std::string method, int digits) {
    c_.id = std::move(id);
    c_.statement = std::move(statement);
    c_.method = std::move(method);
    c_.digits = digits;
  }
  // Records |got − want| / |want| (absolute when want = 0) for the case described by `where`.
  void compare(const Real& got, const Real& want, const std::string& where) {
    using std::abs;
    const Real dev = want == 0 ? abs(got) : Real(abs(got - want) / abs(want));
    const double d = static_cast<double>(dev);
    ++c_.cases;
    if (c_.cases == 1 || d > c_.deviation) {
      c_.deviation = d;
      c_.worst = where + ": solver " + format_significant(got, 20) + ", claim " + format_significant(want, 20);
    }
  }
  ClaimCheck finish() {
    if (c_.deviation <= std::pow(10.0, -c_.digits))
      c_.verdict = Verdict::holds;
    else if (c_.deviation <= 1e-3)
      c_.verdict = Verdict::holds_approximately;
    else
      c_.verdict = Verdict::fails;
    return c_;
  }

 private:
  ClaimCheck c_;
};

std::string at(const std::string& wave, const Real& beta, const Real* gamma = nullptr) {
  std::string s = wave + ", beta = " + format_significant(beta, 12);
  if (gamma) s += ", gamma = " + format_significant(*gamma, 12);
  return s;
}

}  // namespace

std::vector<ClaimCheck> verify_claims(int digits) {
  PrecisionScope scope(static_cast<unsigned>(digits + detail::guard_digits(digits)));
  const auto sine = make_waveform<Real>(parse_wave("sine"));
  const auto tri = make_waveform<Real>(parse_wave("triangle"));
  const auto str = make_waveform<Real>(parse_wave("sawtooth-right"));
  const auto stl = make_waveform<Real>(parse_wave("sawtooth-left"));
  const auto sqr = make_waveform<Real>(parse_wave("square"));
  const auto pw2 = make_waveform<Real>(parse_wave("power:2"));
  const std::vector<const Waveform<Real>*> all{sine.get(), tri.get(), str.get(), stl.get(), sqr.get(), pw2.get()};
  std::vector<ClaimCheck> out;

  {
    Check c("Eq. 6", "beta >= beta_c => mu = mu0 (no stick-slip)",
            "solver at beta_c(gamma), 1.5 beta_c and 10 beta_c for every finite beta_c; exact equality", digits);
    for (const auto* w : all)
      for (const char* g : {"3", "1", "0.5", "0", "-0.5", "-0.9"}) {
        const Real gamma = num(g);
        const Real bc = make_contact(*w, gamma).beta_c();
        using std::isfinite;
        if (!isfinite(bc)) continue;
        for (const char* f : {"1", "1.5", "10"}) {
          const Real beta = bc * num(f);
          c.compare(solve(*w, beta, gamma).mu, Real(1), at(w->name(), beta, &gamma));
        }
      }
    out.push_back(c.finish());
  }
  {
    Check c("Eq. 13", "no jumping: mu/mu0 = 1 - alpha Psi_w(beta), Psi_w independent of gamma",
            "solver mu(beta, gamma) against 1 - Psi(beta)/gamma with Psi from the solver at gamma = 1", digits);
    for (const auto* w : all)
      for (const Real& beta : betas_wide()) {
        const Real p = psi(*w, beta).lost_area;
        for (const char* g : {"1", "1.5", "3", "10", "1000"}) {
          const Real gamma = num(g);
          c.compare(solve(*w, beta, gamma).mu, cf::mu_from_psi(p, gamma), at(w->name(), beta, &gamma));
        }
      }
    out.push_back(c.finish());
  }
  {
    Check c("Eq. 17", "Psi_str = 1 - beta/2, Psi_stl = 2/(2+beta), Psi_tri = (4-beta)/(4+beta)",
            "solver Psi against the closed forms, beta across (0, beta_c) and beyond", digits);
    for (const Real& beta : betas_wide()) {
      if (beta < 2) c.compare(psi(*str, beta).lost_area, cf::psi_sawtooth_right(beta), at("str", beta));
      c.compare(psi(*stl, beta).lost_area, cf::psi_sawtooth_left(beta), at("stl", beta));
      if (beta < 4) c.compare(psi(*tri, beta).lost_area, cf::psi_triangle(beta), at("tri", beta));
    }
    out.push_back(c.finish());
  }
  {
    Check c("Eq. 18", "triangular waves: mu(beta, gamma) = mu(beta, 1) for gamma in (-1, 1]",
            "solver at gamma in (-1, 1] against the solver at gamma = 1, tri/str/stl", digits);
    for (const auto* w : {tri.get(), str.get(), stl.get()})
      for (const Real& beta : betas_wide()) {
        const Real ref = solve(*w, beta, Real(1)).mu;
        for (const Real& gamma : gammas_jumping()) c.compare(solve(*w, beta, gamma).mu, ref, at(w->name(), beta, &gamma));
      }
    out.push_back(c.finish());
  }
  {
    Check c("Eq. 19", "jumping: mu_str = mu0 beta/2, mu_stl = mu0 beta/(2+beta), mu_tri = mu0 2beta/(4+beta)",
            "solver against the closed forms, gamma in (-1, 1], beta below and above beta_c", digits);
    for (const Real& beta : betas_wide())
      for (const Real& gamma : gammas_jumping()) {
        c.compare(solve(*str, beta, gamma).mu, cf::mu_sawtooth_right_jumping(beta), at("str", beta, &gamma));
        c.compare(solve(*stl, beta, gamma).mu, cf::mu_sawtooth_left_jumping(beta), at("stl", beta, &gamma));
        c.compare(solve(*tri, beta, gamma).mu, cf::mu_triangle_jumping(beta), at("tri", beta, &gamma));
      }
    out.push_back(c.finish());
  }
  {
    Check c("Eq. 21", "square wave: mu(beta, gamma) = mu0 (1 - Psi_sqr(xi)), xi_sqr = 2 beta/(1+gamma)",
            "solver mu(beta, gamma) against solver mu(xi_sqr, 1)", digits);
    for (const Real& beta : betas_wide())
      for (const Real& gamma : gammas_jumping()) {
        const Real xi = cf::xi_square(beta, gamma);
        c.compare(solve(*sqr, beta, gamma).mu, solve(*sqr, xi, Real(1)).mu, at("square", beta, &gamma));
      }
    out.push_back(c.finish());
  }
  {
    Check c("Eq. 22", "square wave: mu/mu0 = beta/(4(1+gamma)) for beta < 2(1+gamma), else 1 - (1+gamma)/beta",
            "solver against the closed form, both regimes and the threshold beta = 2(1+gamma)", digits);
    for (const Real& gamma : gammas_jumping()) {
      std::vector<Real> betas = betas_wide();
      const Real th = 2 * (1 + gamma);
      for (const char* f : {"0.5", "0.999999", "1", "1.000001", "2"}) betas.push_back(th * num(f));
      for (const Real& beta : betas) c.compare(solve(*sqr, beta, gamma).mu, cf::mu_square_jumping(beta, gamma), at("square", beta, &gamma));
    }
    out.push_back(c.finish());
  }
  return out;
}

}  // namespace vibrofric
