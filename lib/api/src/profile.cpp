#include "vibrofric/api/profile_spec.hpp"

#include <cmath>
#include <cstdlib>
#include <cerrno>
#include <fstream>
#include <sys/stat.h>

#include "vibrofric/api/catalogue.hpp"
#include "tables.hpp"
#include "vibrofric/api/suggest.hpp"

namespace vibrofric {

namespace {
std::string as_typed(const std::string& s) { return "'" + s + "'"; }

// λ of a wear flat, typed or computed: above 0 and within double's range, so that every number
// type decides it alike.
void check_wear_flat(const mpfr& lambda, const std::string& text) {
  const double in_double = static_cast<double>(lambda);
  if (!(lambda > 0) || !(in_double > 0))
    throw InputError("wear-flat LAMBDA = " + as_typed(text) + ": expected LAMBDA = b^2/(R A) > 0 (and above 1e-308)");
  if (!std::isfinite(in_double))
    throw InputError("wear-flat LAMBDA = " + as_typed(text) + " overflows: expected a magnitude below 1e308");
}

const Decimal& zero() {
  static const Decimal z = *Decimal::read("0");
  return z;
}
}  // namespace

ProfileSpec parse_profile(const std::string& text) {
  ProfileSpec s;
  s.name = text;
  if (text == "flat") return s;
  if (text == "sphere" || text == "cone") {
    s.kind = ProfileKind::power;
    s.parameter = *Decimal::read(text == "sphere" ? "2" : "1");
    s.name = "power:" + s.parameter.text();
    return s;
  }
  const auto colon = text.find(':');
  const std::string head = text.substr(0, colon), arg = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (colon != std::string::npos && head == "power") {
    s.kind = ProfileKind::power;
    s.parameter = InputValue::read(arg, "profile exponent N in " + as_typed(text));
    if (!(s.parameter.to<long double>() >= 1) || compare(*s.parameter.decimal(), *Decimal::read("1")) < 0)
      throw InputError("profile exponent N = " + as_typed(arg) + ": expected N ≥ 1 (cone 1, sphere 2)");
    return s;
  }
  if (colon != std::string::npos && head == "wearflat") {
    s.kind = ProfileKind::wearflat;
    s.parameter = InputValue::read(arg, "wear-flat LAMBDA in " + as_typed(text));
    PrecisionScope scope(400);
    check_wear_flat(s.parameter.to<mpfr>(), arg);
    return s;
  }
  if (colon != std::string::npos && head == "profile") {
    if (arg.empty()) throw InputError("profile " + as_typed(text) + ": expected profile:FILE");
    return parse_profile_file(arg, text);
  }
  const std::string hint = did_you_mean(text, {"flat", "sphere", "cone", "power:N", "wearflat:LAMBDA", "profile:FILE"});
  throw InputError("unknown profile " + as_typed(text) + ": expected flat, sphere, cone, power:N, wearflat:LAMBDA or profile:FILE" +
                   (hint.empty() ? "" : "; " + detail::visible(hint)));
}

ProfileSpec wear_flat_profile(const mpfr& lambda, const std::string& text) {
  check_wear_flat(lambda, text);
  ProfileSpec s;
  s.kind = ProfileKind::wearflat;
  s.name = "wearflat:" + text;
  s.parameter = InputValue::computed(lambda, text);
  return s;
}

ProfileSpec parse_profile_file(const std::string& path, const std::string& text) {
  struct stat st {};
  if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InputError("profile file " + as_typed(path) + " is a directory: expected a file of 'r f' lines");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (stat(path.c_str(), &st) != 0 && errno == ENOENT)
      throw MissingFileError("cannot read profile file " + as_typed(path) + ": no such file");
    throw InputError("cannot read profile file " + as_typed(path));
  }
  // Lines 'r f' in the grammar of a wave file (read_table): comments, separators, quoting, a
  // header line of names (ignored here), a byte-order mark and CR line ends alike.
  const detail::Rows rows = detail::read_table(in, detail::file_source(path, text)).rows;
  return detail::profile_from_rows(rows, detail::file_source(path, text));
}

ProfileSpec detail::profile_from_rows(const Rows& rows, const RowSource& source) {
  ProfileSpec s;
  s.kind = ProfileKind::measured;
  s.name = source.wave;
  for (const auto& [number, tok] : rows) {
    const std::string where = source.where(number);
    if (tok.size() != 2) throw InputError(where + ": expected two fields 'r f', got " + std::to_string(tok.size()));
    const Decimal r = *InputValue::read(tok[0], where + " r").decimal(), f = *InputValue::read(tok[1], where + " f").decimal();
    if (s.r.empty()) {
      if (compare(r, zero()) != 0) throw InputError(where + ": r = " + as_typed(tok[0]) + ": expected the first sample at r = 0");
      if (compare(f, zero()) != 0)
        throw InputError(where + ": f(0) = " + as_typed(tok[1]) + ": expected f(0) = 0 (heights from the profile's tip)");
    } else {
      // Distinct in double, so that every number type sees the same segments.
      if (!(r.to<double>() > s.r.back().to<double>()))
        throw InputError(where + ": r = " + as_typed(tok[0]) + ": expected r to increase (by more than double rounding) after " +
                         s.r.back().text());
      if (compare(f, s.f.back()) < 0)
        throw InputError(where + ": f = " + as_typed(tok[1]) + " is below the previous " + s.f.back().text() +
                         ": expected a non-decreasing profile (MDR needs f' >= 0)");
      // A slope that drops (a concave corner at r_j) makes g' → −∞ just beyond r_j: g is then
      // not monotone and no contact radius exists. (f2 − f1)(r1 − r0) ≥ (f1 − f0)(r2 − r1), exactly.
      if (s.r.size() >= 2) {
        PrecisionScope scope(400);
        const std::size_t k = s.r.size();
        const mpfr r0 = s.r[k - 2].to<mpfr>(), r1 = s.r[k - 1].to<mpfr>(), r2 = r.to<mpfr>();
        const mpfr f0 = s.f[k - 2].to<mpfr>(), f1 = s.f[k - 1].to<mpfr>(), f2 = f.to<mpfr>();
        if ((f2 - f1) * (r1 - r0) < (f1 - f0) * (r2 - r1))
          throw InputError(where + ": the slope drops at r = " + s.r[k - 1].text() +
                           " (a concave corner): expected a convex profile, slopes non-decreasing in r, as the MDR "
                           "transform g(x) is monotone only then (smooth or convexify the measurement)");
      }
    }
    if (s.r.size() == max_profile_samples)
      throw InputError("profile file " + as_typed(source.name) + " has more than " + std::to_string(max_profile_samples) +
                       " samples");
    s.r.push_back(r);
    s.f.push_back(f);
  }
  if (s.r.size() < 2)
    throw InputError("profile file " + as_typed(source.name) + " has " + std::to_string(s.r.size()) +
                     " sample(s): expected at least 2 lines 'r f'");
  if (compare(s.f.back(), zero()) == 0)
    throw InputError("profile file " + as_typed(source.name) + " is flat (f = 0 everywhere): expected a curved profile (this one is the flat punch)");
  return s;
}

}  // namespace vibrofric
