// The flags' readers: our integer grammar, switches, formats, the ranges FROM:TO:N, and the flag
// groups that several commands share (wave, precision, solver controls, rig dynamics, --certify).
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli.hpp"
#include "vibrofric/api/limits.hpp"
#include "vibrofric/api/suggest.hpp"

namespace vibrofric::tool {

// The help texts below quote these limits (string literals, as CLI11 takes them).
static_assert(max_digits == 10000 && root_iterations_limit == 100000 && max_fit_harmonics == 10000 &&
                  detail::min_quadrature_levels == 4 && quadrature_levels_limit == 30,
              "a limit changed: update the help texts that quote it");

// Our integer grammar: an optional sign and 1 to 9 digits (CLI11's int reads 010 as 8 and 0x10 as 16).
int integer(const std::string& text, const std::string& what, long lo, long hi) {
  const std::size_t sign = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
  const bool digits = text.size() > sign && text.size() - sign <= 9 &&
                      std::all_of(text.begin() + static_cast<long>(sign), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits)
    throw InputError(what + " = '" + detail::visible(text) + "': expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  const long v = std::stol(text);
  if (v < lo || v > hi)
    throw InputError(what + " = " + detail::visible(text) + ": expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  return static_cast<int>(v);
}

// A switch's value: alone (CLI11 passes "true"), or =1/true/yes, on; =0/false/no, off; else bad input
// (CLI11 would also take on/off/enable/disable and more).
bool switch_value(const std::string& text, const std::string& name) {
  if (text == "1" || text == "true" || text == "yes") return true;
  if (text == "0" || text == "false" || text == "no") return false;
  throw InputError("--" + name + " = '" + detail::visible(text) + "': expected no value, or one of true, false, yes, no, 1, 0");
}

// "; did you mean 'X'?" after a refusal of a name near one of `known`, or "".
std::string hint(const std::string& typed, const std::vector<std::string>& known) {
  const std::string h = did_you_mean(typed, known);
  return h.empty() ? h : "; " + detail::visible(h);
}

Format format_named(const std::string& text) {
  if (text == "text") return Format::text;
  if (text == "csv") return Format::csv;
  if (text == "json") return Format::json;
  throw InputError("--format '" + detail::visible(text) + "': expected text, csv or json" + hint(text, {"text", "csv", "json"}));
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const auto pos = s.find(sep, start);
    out.push_back(s.substr(start, pos - start));
    if (pos == std::string::npos) return out;
    start = pos + 1;
  }
}

// FROM:TO:N, N values with both ends (linear), or log:FROM:TO:N (geometric, FROM and TO > 0). As
// decimals of 17 significant digits computed at 40 digits, trailing zeros dropped: the printed
// value is exactly the value evaluated. `flag` names the flag in messages; `descending` allows
// TO < FROM (γ from 1 down to −1, as the paper's figures).
std::vector<std::string> value_range(const std::string& spec, const std::string& flag, bool descending) {
  const bool log = spec.rfind("log:", 0) == 0;
  const auto parts = split(log ? spec.substr(4) : spec, ':');
  if (parts.size() != 3) throw InputError(flag + " '" + detail::visible(spec) + "': expected FROM:TO:N or log:FROM:TO:N");
  check_decimal(parts[0], flag + " FROM");
  check_decimal(parts[1], flag + " TO");
  const int n = integer(parts[2], flag + " N", 1, max_range_points);
  PrecisionScope scope(40);
  const mpfr from(parts[0]), to(parts[1]);
  if (!descending && to < from) throw InputError(flag + " '" + detail::visible(spec) + "': empty range, expected FROM <= TO");
  if (n > 1 && from == to) throw InputError(flag + " '" + detail::visible(spec) + "': empty range for N > 1, expected FROM != TO");
  if (n == 1 && from != to) throw InputError(flag + " '" + detail::visible(spec) + "': one point (N = 1) from FROM to TO, expected FROM = TO");
  if (log && !(from > 0 && to > 0))
    throw InputError(flag + " '" + detail::visible(spec) + "': a log range needs FROM > 0 and TO > 0");
  std::vector<std::string> out;
  for (int i = 0; i < n; ++i) {
    const mpfr t = n == 1 ? mpfr(0) : mpfr(mpfr(i) / (n - 1));
    const mpfr v = i == n - 1 ? to : log ? mpfr(from * pow(to / from, t)) : mpfr(from + (to - from) * t);
    std::string str = format_significant(i == 0 ? from : v, 17);
    const std::size_t e = std::min(str.find('e'), str.size());
    if (str.find('.') < e) {  // trailing zeros of the mantissa dropped: 1.0000000000000000e-06 is 1e-06
      std::size_t end = e;
      while (str[end - 1] == '0') --end;
      if (str[end - 1] == '.') --end;
      str.erase(end, e - end);
    }
    out.push_back(str);
  }
  return out;
}

const std::vector<FlagSpec> kWaveFlags{
    {"wave", "W", "the wave (required): catalogue name, power:P, fourier:FILE or samples:FILE", "",
     [](Flags& f, const std::string& t) { f.wave = t; }},
    {"column", "C", "samples FILE: the value column, by header name or 1-based index", "the one value column",
     [](Flags& f, const std::string& t) { f.read.column = t; }},
    {"periods", "K", "samples FILE: the periods the record holds, averaged sample by sample (1: one, unchecked)",
     "one; a record that looks like several is refused",
     [](Flags& f, const std::string& t) { f.read.periods = integer(t, "--periods", 1, max_record_periods); }},
    {"skip-rows", "N", "samples or fourier FILE: the lines of a preamble to skip before its header (pandas' skiprows)", "0",
     [](Flags& f, const std::string& t) {
       f.read.skip_rows = integer(t, "--skip-rows", 0, static_cast<long>(max_table_lines));
     }},
    {"diagnostics", "", "print on stderr the normalisation of a user wave: raw mean, min, max, scale, period, end point", "",
     [](Flags& f, const std::string& t) { f.diagnostics = switch_value(t, "diagnostics"); }},
};
const std::vector<FlagSpec> kPrecisionFlags{
    {"digits", "D", "significant digits, 1 to 10000 (mpfr, with guard digits)", "50",
     [](Flags& f, const std::string& t) { f.digits = integer(t, "--digits", min_digits, max_digits); }},
    {"type", "T", "double | long-double | cpp_bin_float_50 | cpp_bin_float_100 | mpfr", "mpfr",
     [](Flags& f, const std::string& t) {
       f.type = number_type_named(t);
       if (!f.type)
         throw InputError("--type '" + detail::visible(t) + "': expected " + number_type_choices +
                          hint(t, number_type_names()));
       f.type_text = t;
     }},
    {"no-escalate", "", "fixed types: print the value computed in the type even where its rounding bound "
                        "exceeds the type's epsilon (=true/false/yes/no/1/0; default off: recompute with mpfr)", "",
     [](Flags& f, const std::string& t) { f.no_escalate = switch_value(t, "no-escalate"); }},
};
// physical's: a guaranteed double by default (the correctly rounded double, as mu --type double),
// mpfr where --digits asks for it.
const std::vector<FlagSpec> kPhysicalPrecisionFlags = [] {
  std::vector<FlagSpec> flags = kPrecisionFlags;
  flags[0].fallback = "none: a guaranteed double";
  flags[1].fallback = "double (mpfr with --digits)";
  return flags;
}();
const std::vector<FlagSpec> kSolverFlags{
    {"area", "M", "auto | exact | quadrature: areas from antiderivatives or tanh-sinh, every event a breakpoint",
     "auto", [](Flags& f, const std::string& t) {
       if (t == "auto")
         f.solver.area = AreaMethod::automatic;
       else if (t == "exact")
         f.solver.area = AreaMethod::exact;
       else if (t == "quadrature")
         f.solver.area = AreaMethod::quadrature;
       else
         throw InputError("--area '" + detail::visible(t) + "': expected auto, exact or quadrature" + hint(t, {"auto", "exact", "quadrature"}));
     }},
    {"max-iterations", "N", "root-finder budget per event, 1 to 100000", "200 + working bits",
     [](Flags& f, const std::string& t) {
       f.solver.max_root_iterations = static_cast<std::uintmax_t>(integer(t, "--max-iterations", 1, root_iterations_limit));
     }},
    {"max-levels", "N", "tanh-sinh halvings, 4 to 30", "15",
     [](Flags& f, const std::string& t) {
       f.solver.max_quadrature_levels = static_cast<std::size_t>(
           integer(t, "--max-levels", static_cast<long>(detail::min_quadrature_levels), quadrature_levels_limit));
     }},
    {"quadrature-tolerance", "T", "tanh-sinh tolerance, in (0, 1)", "sqrt(eps) of the working precision",
     [](Flags& f, const std::string& t) {
       check_decimal(t, "--quadrature-tolerance");
       const double v = std::strtod(t.c_str(), nullptr);
       if (!(v > 0 && v < 1)) throw InputError("--quadrature-tolerance = " + t + ": expected a number in (0, 1)");
       f.solver.quadrature_tolerance = v;
     }},
};

void decimal_beta(Flags& f, const std::string& t) { f.beta = InputValue::read(t, "--beta"); }
void profile_named(Flags& f, const std::string& t) {
  f.profile = parse_profile(t);
  f.profile_text = t;
}
void format_of_point(Flags& f, const std::string& t) { f.format = format_named(t); }
// Rig dynamics (model.md, "Rig dynamics"): the body's mass and the apparatus' stiffness.
const std::vector<FlagSpec> kRigFlags{
    {"kappa", "K", "rig dynamics: system stiffness over contact stiffness, k_s/k_x > 0 (with --omega)", "quasi-static (none)",
     [](Flags& f, const std::string& t) {
       f.kappa = InputValue::read(t, "--kappa");
     }},
    {"omega", "W", "rig dynamics: contact frequency over excitation frequency, sqrt(k_x/m)/(2 pi f) > 0 (with --kappa)", "",
     [](Flags& f, const std::string& t) {
       f.omega = InputValue::read(t, "--omega");
     }},
    {"zeta", "Z", "rig dynamics: damping ratio of the system spring, c/(2 sqrt(m k_s)) >= 0", "0",
     [](Flags& f, const std::string& t) {
       f.zeta = InputValue::read(t, "--zeta");
     }},
};

// In-plane oscillation (model.md, "In-plane and combined oscillation"): the drive's longitudinal and
// transverse oscillation, its phase and wave.
const std::vector<FlagSpec> kInPlaneFlags{
    {"longitudinal", "A", "in-plane oscillation along the sliding direction: a_l = k_x u_x/(mu0 k_z A) >= 0 "
                          "(with --wave constant: k_x u_x/(mu0 F_N))", "none",
     [](Flags& f, const std::string& t) { f.longitudinal = InputValue::read(t, "--longitudinal"); }},
    {"transverse", "A", "in-plane oscillation across the sliding direction: a_t = k_x u_y/(mu0 k_z A) >= 0 "
                        "(with --wave constant: k_x u_y/(mu0 F_N))", "none",
     [](Flags& f, const std::string& t) { f.transverse = InputValue::read(t, "--transverse"); }},
    {"phase", "P", "lag of the in-plane oscillation behind the normal one, in periods (with --longitudinal or --transverse)", "0",
     [](Flags& f, const std::string& t) { f.phase = InputValue::read(t, "--phase"); }},
    {"in-plane-wave", "W", "the in-plane oscillation's wave: a catalogue wave (with --longitudinal or --transverse)", "sine",
     [](Flags& f, const std::string& t) { f.in_plane_wave = t; }},
};

const FlagSpec kCertifyFlag{
    "certify", "", "flat punch: print the exact value (piecewise-linear waves) or an enclosure (sine, "
                   "power:P, Fourier series) and prove that the printed value is its correct rounding; "
                   "with --longitudinal (mu), the exact value and mode fractions of piecewise-linear waves; "
                   "with --kappa/--omega (mu), the rig's periodic state proven and enclosed "
                   "(=true/false/yes/no/1/0)", "",
    [](Flags& f, const std::string& t) { f.certify = switch_value(t, "certify"); }};
// A sweep writes rows: csv (its default) or json.
void format_of_rows(Flags& f, const std::string& t) {
  f.format = format_named(t);
  if (f.format == Format::text) throw InputError("--format text: sweep writes csv (the default) or json");
}
void text_beta(Flags& f, const std::string& t) { f.beta = InputValue::read(t, "--beta"); }
void text_gamma(Flags& f, const std::string& t) { f.gamma = InputValue::read(t, "--gamma"); }

const std::vector<std::string> kSweptPhysical{"v0", "A", "f", "F-N", "u-mean"};

void read_physical(Flags& f, const std::string& name, const std::string& text) {
  if (name == "shape" || name == "unit" || name == "in-plane-wave") {
    f.physical_texts[name] = text;
    return;
  }
  const std::string flag = "--" + name;
  const bool swept = std::find(kSweptPhysical.begin(), kSweptPhysical.end(), name) != kSweptPhysical.end();
  // A range of u_mean may start below contact (gamma < -1 for the sine): such rows are errors, as at one point.
  f.physical_ranges.erase(name);  // the last of a repeated flag counts
  if (swept && text.find(':') != std::string::npos) {
    f.physical[name] = read_all(value_range(text, flag, name == "u-mean"), flag);
    f.physical_ranges.insert(name);
  } else {
    f.physical[name] = {InputValue::read(text, flag)};
  }
}

std::vector<InputValue> read_all(const std::vector<std::string>& texts, const std::string& what) {
  std::vector<InputValue> out;
  out.reserve(texts.size());
  for (const auto& t : texts) out.push_back(InputValue::read(t, what));
  return out;
}

}  // namespace vibrofric::tool
