// Uses the installed library: μ̄/μ0 of the triangle in the jumping range against Eq. 19.
#include <vibrofric/api/evaluate.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace vibrofric;
  const auto w = make_waveform<double>(parse_wave("triangle"));
  const double mu = solve(*w, 1.0, -0.5).mu;
  const double want = 2 * 1.0 / (4 + 1.0);  // Eq. 19: 2β/(4 + β) for β < 4
  const std::string text = evaluate(parse_wave("tri"), Quantity::mu, {{"1", "-0.5"}}, Precision{NumberType::mpfr, 30}).front();
  std::printf("mu = %.17g (Eq. 19: %.17g), 30 digits: %s\n", mu, want, text.c_str());
  return std::fabs(mu - want) <= 4 * 2.2e-16 && text == "0.400000000000000000000000000000" ? 0 : 1;
}
