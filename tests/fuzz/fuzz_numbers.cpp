// Fuzz target: the number and name grammars the tool reads its arguments with — check_decimal,
// parse_real<T> for every number type, parse_wave (catalogue names and power:P), number_type_named
// — and the input used as β and as γ of an evaluation in double and at 20 digits.
//
// Checks beyond "a value or a clean error": check_decimal accepts exactly the strings of an
// independent hand-written grammar whose value is within double's range; an accepted number is
// finite in every type and the types agree on it; an accepted wave evaluates (or is a clean
// error) and double agrees with 20-digit mpfr to 4 ulp; μ is finite and in [0, 1].
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>

#include "fuzz_common.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/evaluate.hpp"

namespace {

using namespace vibrofric;

// [+-]? ( digits (. digits?)? | . digits ) ( [eE] [+-]? digit{1,9} )?   — the documented grammar.
bool grammar(const std::string& s) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i - from;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t whole = digits();
  std::size_t frac = 0;
  if (i < s.size() && s[i] == '.') {
    ++i;
    frac = digits();
  }
  if (whole == 0 && frac == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t e = digits();
    if (e == 0 || e > 9) return false;
  }
  return i == s.size();
}

void check_value(const std::string& input, const std::string& v, const char* what) {
  const double x = std::strtod(v.c_str(), nullptr);
  if (!std::isfinite(x) || x < 0 || x > 1) fuzz::finding(std::string(what) + " gave " + v, input);
}

void check_agree(const std::string& input, const std::string& d, const std::string& m, const char* what) {
  const double x = std::strtod(d.c_str(), nullptr), y = std::strtod(m.c_str(), nullptr);
  const double ulp = std::nextafter(std::abs(y), INFINITY) - std::abs(y);
  if (!(std::abs(x - y) <= 4 * ulp + 1e-300))
    fuzz::finding(std::string(what) + ": double " + d + " and 20-digit mpfr " + m + " differ", input);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string s(reinterpret_cast<const char*>(data), size);

  // Numbers.
  bool accepted = false;
  fuzz::clean(s, "check_decimal", [&] {
    check_decimal(s, "x");
    accepted = true;
  });
  const bool in_grammar = grammar(s);
  if (accepted && !in_grammar) fuzz::finding("check_decimal accepted a string outside the grammar", s);
  if (in_grammar && !accepted) {
    const long double v = std::strtold(s.c_str(), nullptr);
    if (!(std::fabs(v) > static_cast<long double>(DBL_MAX))) fuzz::finding("check_decimal rejected a number within range", s);
  }
  if (accepted) {
    const double d = parse_real<double>(s, "x");
    const long double ld = parse_real<long double>(s, "x");
    if (!std::isfinite(d) || !std::isfinite(ld)) fuzz::finding("an accepted number is not finite", s);
    if (d != std::strtod(s.c_str(), nullptr)) fuzz::finding("parse_real<double> differs from strtod", s);
    PrecisionScope digits(30);
    const mpfr m = parse_real<mpfr>(s, "x");
    if (!isfinite(m)) fuzz::finding("an accepted number is not finite in mpfr", s);
    const bin50 b = parse_real<bin50>(s, "x");
    if (!boost::multiprecision::isfinite(b)) fuzz::finding("an accepted number is not finite in cpp_bin_float_50", s);
    // Same sign and, where double is normal, the same value to double's precision.
    if ((m > 0) != (d > 0) && d != 0) fuzz::finding("mpfr and double disagree on the sign", s);
    if (std::abs(d) >= DBL_MIN && abs(m - mpfr(d)) > abs(m) * mpfr(2 * DBL_EPSILON))
      fuzz::finding("mpfr and double disagree on the value", s);

    // As β and as γ (sine, triangle): a value in [0, 1] or a clean error.
    for (const char* wave : {"sine", "triangle"}) {
      const WaveSpec spec = parse_wave(wave);
      for (const Point& p : {Point{s, "0.5"}, Point{"1.5", s}}) {
        std::string vd, vm;
        const auto od = fuzz::clean(s, "evaluate double", [&] { vd = evaluate(spec, Quantity::mu, {p}, {NumberType::float64, 17}).front(); });
        const auto om = fuzz::clean(s, "evaluate mpfr", [&] { vm = evaluate(spec, Quantity::mu, {p}, {NumberType::mpfr, 20}).front(); });
        if (od == fuzz::Outcome::value) check_value(s, vd, "double");
        if (om == fuzz::Outcome::value) check_value(s, vm, "mpfr");
        if (od == fuzz::Outcome::value && om == fuzz::Outcome::value) check_agree(s, vd, vm, wave);
      }
    }
  }

  // Names: catalogue and power:P (file waves are the other targets' business).
  if (s.rfind("fourier:", 0) != 0 && s.rfind("samples:", 0) != 0) {
    WaveSpec spec;
    if (fuzz::clean(s, "parse_wave", [&] { spec = parse_wave(s); }) == fuzz::Outcome::value) {
      for (const Point& p : {Point{"1", "0.5"}, Point{"0.25", "-0.5"}, Point{"3", "2"}}) {
        std::string vd, vm;
        const auto od = fuzz::clean(s, "evaluate wave double", [&] { vd = evaluate(spec, Quantity::mu, {p}, {NumberType::float64, 17}).front(); });
        const auto om = fuzz::clean(s, "evaluate wave mpfr", [&] { vm = evaluate(spec, Quantity::mu, {p}, {NumberType::mpfr, 20}).front(); });
        if (od == fuzz::Outcome::value) check_value(s, vd, "wave double");
        if (om == fuzz::Outcome::value) check_value(s, vm, "wave mpfr");
        if (od == fuzz::Outcome::value && om == fuzz::Outcome::value) check_agree(s, vd, vm, "wave");
        if ((od == fuzz::Outcome::value) != (om == fuzz::Outcome::value))
          fuzz::finding("double and mpfr disagree on accepting the point", s);
      }
    }
  }

  fuzz::clean(s, "number_type_named", [&] { number_type_named(s); });
  return 0;
}
