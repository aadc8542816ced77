// vibrofric: the command-line tool. μ̄/μ0 (Eq. 15), Ψ_w (Eq. 12), sweeps, physical inputs
// (Eqs. 1, 5, 14) and the claims check. Bad input: one line on stderr, exit 2; solver failure: 1.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/version.hpp>
#include <csv.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/fit.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/api/suggest.hpp"
#include "vibrofric/verification/claims.hpp"

namespace {

using namespace vibrofric;

// The help texts quote the limits of limits.hpp as literals.
static_assert(max_digits == 10000 && root_iterations_limit == 100000 && max_trace_points == 1000000 &&
                  min_trace_points == 2 && max_fit_harmonics == 10000,
              "update the help texts below");

// Help texts: a synopsis per command (CLI11 lists every flag with its default below it) and
// footers on waves, profiles and file formats.
const char* const kAbout =
    "Sliding friction under normal oscillation (M. Popov, large amplitudes): the macroscopic\n"
    "coefficient of friction mu/mu0 = g_w(beta, gamma) (Eq. 15) and the reduction function\n"
    "Psi_w(beta) (Eq. 12).\n"
    "\n"
    "commands:\n"
    "  mu        mu/mu0 at one point\n"
    "  psi       Psi_w(beta) (non-jumping, flat punch)\n"
    "  sweep     mu/mu0 or Psi over ranges of beta and gamma, rows streamed as CSV or JSON\n"
    "  physical  from physical inputs in SI units (Eqs. 1, 5, 14), one point or a sweep of one input\n"
    "  trace     n(phi) and s(phi) over one period (Fig. 2)\n"
    "  fit       a samples file to a fourier file with K harmonics\n"
    "  verify    decide every claim of the paper and of model.md\n"
    "  version   versions of vibrofric, the compiler, Boost, MPFR and GMP\n"
    "\n"
    "\n"
    "'vibrofric COMMAND --help' lists every flag of a command with its default.\n"
    "exit status: 0 success, 1 solver failure, 2 bad input.\n";

const char* const kWaves =
    "waves W: sine (harmonic), triangle (tri), sawtooth-right (str), sawtooth-left (stl),\n"
    "  square (sqr), power:P (P >= 1), fourier:FILE, samples:FILE\n"
    "  fourier FILE: lines 'k a_k b_k' for w = sum a_k cos(2 pi k phi) + b_k sin(2 pi k phi)\n"
    "  samples FILE: one period of values y_j at phi = j/N (one column, or one line), linear\n"
    "  between; or columns under a header, one named 'time', 't' or 'timestamp' (any case, a unit\n"
    "  allowed: 'time [s]', 'time_s', 't/s') giving the time stamps (the last line repeats the\n"
    "  first value one period later); --column picks the value column. Fields: ',' / ';' where a\n"
    "  line has them, else tabs, else spaces; '#' starts a comment (README,\n"
    "  \"File formats\"). User waves are normalised to zero mean and max - min = 2\n"
    "  (--diagnostics shows how).\n";

const char* const kRig =
    "rig dynamics (model.md): --kappa K --omega W [--zeta Z] replace the paper's quasi-static spring by\n"
    "  a body of mass m on a system spring k_s (damper c): K = k_s/k_x, W = sqrt(k_x/m)/(2 pi f),\n"
    "  Z = c/(2 sqrt(m k_s)); flat punch; sine, Fourier and piecewise-linear waves. mu prints the\n"
    "  stick, slip and flight fractions (they add to 1; backward_slip_fraction is the part of the\n"
    "  slip that goes backward), the body's amplitude, the largest backward slip and the largest\n"
    "  Floquet multiplier (0: below what difference quotients resolve) after the value.\n";

const char* const kProfiles =
    "profiles P (model.md MDR): flat (the flat punch), sphere, cone, power:N (N >= 1, sigma = x^N),\n"
    "  wearflat:LAMBDA (sphere with a wear flat, LAMBDA = b^2/(R A) > 0), profile:FILE (lines\n"
    "  'r f', f(0) = 0, f non-decreasing, heights in units of the amplitude A).\n";

const char* const kPhysicalAbout =
    "1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 and 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) (Eq. 1);\n"
    "G defaults to E/(2(1 + nu)), -1 < nu <= 0.5. beta = G* v0/(mu0 E* A f) (Eq. 5), gamma = u_mean/A\n"
    "(Eq. 14); A is the zero-to-peak amplitude, u_mean the mean indentation of the indenter's tip.\n"
    "--F-N N sets the mean normal load instead of u_mean: gamma is solved from <F_N>(gamma) = N\n"
    "(<F_N> rises strictly with gamma) and u_mean_m is printed after gamma.\n"
    "Sweep: one of --v0, --A, --f, --F-N, --u-mean given as FROM:TO:N or log:FROM:TO:N writes one\n"
    "row per value (CSV, or --format json).\n"
    "A samples wave's values may give A: --unit um takes A as half their peak-to-peak (A_m printed).\n"
    "Printed: shape, E*, G*, k_z and k_x (flat) or the largest contact radius (curved), lambda\n"
    "(wearflat), beta, gamma, mu/mu0, mu, the mean normal and friction forces <F_N>, <F_x> in\n"
    "newtons, at the deepest instant the normal force, the mean contact pressure and the largest\n"
    "(Hertz on the sphere; inf at the punch's rim, the cone's tip, a profile's kink), beta_c (Eq. 6,\n"
    "of the clipped n; curved: the central spring's), the fraction of the period in contact and, for\n"
    "the flat punch, in stick.\n"
    "shapes S and their GEOMETRY (metres, degrees):\n"
    "  flat (default) --radius a          flat-ended cylinder: k_z = 2 E* a, k_x = 2 G* a (Eq. 1)\n"
    "  sphere --R R                       MDR (model.md), sigma = x^2/(R A)\n"
    "  cone --half-angle THETA            angle between axis and flank, in degrees\n"
    "  wearflat --R R --flat-radius b     sphere with a wear flat, lambda = b^2/(R A)\n"
    "  profile:FILE                       measured profile, lines 'r f' in metres, f(0) = 0\n";

enum class Format { text, csv, json };

// A command's flags as typed values. CLI11 fills them while it parses: each flag's reader checks
// the text as typed (our decimal and integer grammars, the names of choices) and throws InputError
// quoting it. What is not given keeps its default.
struct Flags {
  std::string command;
  // Wave
  std::optional<std::string> wave;
  WaveReadOptions read;
  bool diagnostics = false;
  // Precision
  std::optional<NumberType> type;
  std::string type_text;
  std::optional<int> digits;
  bool no_escalate = false;
  bool certify = false;
  // Solver controls (solver.hpp Options): a budget the solver cannot meet is an error, never a value.
  Options solver;
  // mu, psi, trace: β and γ as typed; sweep: their values, and γ's text
  std::optional<std::string> beta, gamma;
  std::vector<std::string> betas, gammas;
  std::optional<std::string> profile_text;
  ProfileSpec profile;
  std::optional<Format> format;
  Quantity quantity = Quantity::mu;
  unsigned threads = 0;
  std::optional<int> points, harmonics;
  std::optional<std::string> output, claim;
  // Rig dynamics (model.md): κ, Ω, ζ as typed
  std::optional<std::string> kappa, omega, zeta;
  std::map<std::string, std::string> texts;  // as typed, by flag name: the flags without a reader
};

using Reader = void (*)(Flags&, const std::string& text);

// One flag of a command: its name, the value's placeholder (empty: a switch), the help line, the
// default shown by --help (empty: none) and the reader of its text (none: kept in Flags::texts
// for the library to check, as physical's inputs are by physical_point).
struct FlagSpec {
  const char* name;
  const char* value;
  const char* help;
  const char* fallback;
  Reader read;
};

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

void decimal_beta(Flags& f, const std::string& t) {
  check_decimal(t, "--beta");
  f.beta = t;
}
void profile_named(Flags& f, const std::string& t) {
  f.profile = parse_profile(t);
  f.profile_text = t;
}
void format_of_point(Flags& f, const std::string& t) { f.format = format_named(t); }
// Rig dynamics (model.md, "Rig dynamics"): the body's mass and the apparatus' stiffness.
const std::vector<FlagSpec> kRigFlags{
    {"kappa", "K", "rig dynamics: system stiffness over contact stiffness, k_s/k_x > 0 (with --omega)", "quasi-static (none)",
     [](Flags& f, const std::string& t) {
       check_decimal(t, "--kappa");
       f.kappa = t;
     }},
    {"omega", "W", "rig dynamics: contact frequency over excitation frequency, sqrt(k_x/m)/(2 pi f) > 0 (with --kappa)", "",
     [](Flags& f, const std::string& t) {
       check_decimal(t, "--omega");
       f.omega = t;
     }},
    {"zeta", "Z", "rig dynamics: damping ratio of the system spring, c/(2 sqrt(m k_s)) >= 0", "0",
     [](Flags& f, const std::string& t) {
       check_decimal(t, "--zeta");
       f.zeta = t;
     }},
};

const FlagSpec kCertifyFlag{
    "certify", "", "flat punch: print the exact value (piecewise-linear waves) or an enclosure (sine, "
                   "power:P, Fourier series) and prove that the printed value is its correct rounding "
                   "(=true/false/yes/no/1/0)", "",
    [](Flags& f, const std::string& t) { f.certify = switch_value(t, "certify"); }};
// A sweep writes rows: csv (its default) or json.
void format_of_rows(Flags& f, const std::string& t) {
  f.format = format_named(t);
  if (f.format == Format::text) throw InputError("--format text: sweep writes csv (the default) or json");
}
void text_beta(Flags& f, const std::string& t) { f.beta = t; }
void text_gamma(Flags& f, const std::string& t) { f.gamma = t; }

struct CommandSpec {
  const char* name;
  const char* synopsis;
  std::vector<FlagSpec> flags;
  std::vector<const std::vector<FlagSpec>*> groups;
  std::string footer;
  int (*run)(const Flags&);
};

int run_mu(const Flags& f);
int run_psi(const Flags& f);
int run_sweep(const Flags& f);
int run_physical(const Flags& f);
int run_trace(const Flags& f);
int run_fit(const Flags& f);
int run_verify(const Flags& f);
int run_version(const Flags& f);

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> specs{
      {"mu", "mu --wave W --beta B --gamma G [--profile P]: mu/mu0 = g_w(beta, gamma) (Eq. 15)",
       {{"beta", "B", "beta (Eq. 5), a decimal > 0 (required)", "", decimal_beta},
        {"gamma", "G", "gamma = u_mean/A (Eq. 14), a decimal with contact, gamma > -max w (required)", "",
         [](Flags& f, const std::string& t) {
           check_decimal(t, "--gamma");
           f.gamma = t;
         }},
        {"profile", "P", "the indenter (model.md MDR)", "flat", profile_named},
        {"format", "F", "text | csv | json", "text", format_of_point},
        kCertifyFlag},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags, &kRigFlags},
       std::string(kWaves) + kProfiles + kRig,
       run_mu},
      {"psi", "psi --wave W --beta B: Psi_w(beta) (Eq. 12), flat punch, non-jumping",
       {{"beta", "B", "beta (Eq. 5), a decimal > 0 (required)", "", decimal_beta},
        {"profile", "P", "flat only: in a curved contact the outer springs always jump", "flat", profile_named},
        {"format", "F", "text | csv | json", "text", format_of_point},
        kCertifyFlag},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags, &kRigFlags},
       kWaves,
       run_psi},
      {"sweep", "sweep --wave W --beta RANGE --gamma G1,G2,...|RANGE [--profile P]: rows streamed in order",
       {{"beta", "RANGE", "FROM:TO:N (linear, ends included) or log:FROM:TO:N (geometric) (required)", "",
         [](Flags& f, const std::string& t) { f.betas = value_range(t, "--beta", false); }},
        {"gamma", "G", "a list G1,G2,... or a range FROM:TO:N (FROM > TO allowed); not with --quantity psi", "",
         [](Flags& f, const std::string& t) {
           f.gamma = t;
           f.gammas = t.find(':') != std::string::npos ? value_range(t, "--gamma", true) : split(t, ',');
           for (const auto& g : f.gammas) check_decimal(g, "--gamma value");
         }},
        {"quantity", "Q", "mu | psi", "mu",
         [](Flags& f, const std::string& t) {
           if (t != "mu" && t != "psi") throw InputError("--quantity '" + detail::visible(t) + "': expected mu or psi" + hint(t, {"mu", "psi"}));
           f.quantity = t == "psi" ? Quantity::psi : Quantity::mu;
         }},
        {"profile", "P", "the indenter (model.md MDR)", "flat", profile_named},
        {"threads", "N", "worker threads, 0 for every core", "0",
         [](Flags& f, const std::string& t) { f.threads = static_cast<unsigned>(integer(t, "--threads", 0, max_threads)); }},
        {"format", "F", "csv | json", "csv", format_of_rows},
        kCertifyFlag},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags, &kRigFlags},
       std::string(kWaves) + kProfiles + kRig,
       run_sweep},
      {"physical", "physical --wave W --E1 PA --nu1 NU --E2 PA --nu2 NU [--G1 PA --G2 PA] --v0 M/S --f HZ\n"
                   "                          (--A M | --unit U) (--u-mean M | --F-N N) --mu0 MU [--shape S GEOMETRY]",
       {{"E1", "PA", "Young's modulus of body 1, > 0 (required)", "", nullptr},
        {"nu1", "NU", "Poisson's ratio of body 1, -1 < nu <= 0.5 (required)", "", nullptr},
        {"E2", "PA", "Young's modulus of body 2, > 0 (required)", "", nullptr},
        {"nu2", "NU", "Poisson's ratio of body 2 (required)", "", nullptr},
        {"G1", "PA", "shear modulus of body 1", "E1/(2(1 + nu1))", nullptr},
        {"G2", "PA", "shear modulus of body 2", "E2/(2(1 + nu2))", nullptr},
        {"v0", "M/S", "sliding velocity, > 0 (required; or a range)", "", nullptr},
        {"f", "HZ", "oscillation frequency, > 0 (required; or a range)", "", nullptr},
        {"A", "M", "zero-to-peak amplitude of the normal oscillation, > 0 (required, or --unit; or a range)", "", nullptr},
        {"unit", "U", "samples wave: its values' unit (m, mm, um or µm, nm); A is then half their peak-to-peak, printed as A_m",
         "", nullptr},
        {"u-mean", "M", "mean indentation (or a range); or give --F-N", "", nullptr},
        {"F-N", "N", "mean normal load, > 0 (or a range); or give --u-mean", "", nullptr},
        {"mu0", "MU", "local coefficient of friction, > 0 (required)", "", nullptr},
        {"shape", "S", "flat | sphere | cone | wearflat | profile:FILE", "flat", nullptr},
        {"mass", "KG", "rig dynamics (flat): the body's mass, > 0 (with --k-system)", "", nullptr},
        {"k-system", "N/M", "rig dynamics: the apparatus' stiffness between drive and body, > 0 (with --mass)", "", nullptr},
        {"damping", "NS/M", "rig dynamics: a damper parallel to the apparatus' spring, >= 0", "0", nullptr},
        {"radius", "M", "flat: punch radius (required for flat)", "", nullptr},
        {"R", "M", "sphere, wearflat: radius of curvature", "", nullptr},
        {"half-angle", "DEG", "cone: angle between axis and flank, in (0, 90)", "", nullptr},
        {"flat-radius", "M", "wearflat: radius of the wear flat", "", nullptr},
        {"format", "F", "text | csv | json (a sweep: csv | json)", "text (a sweep: csv)", format_of_point}},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags},
       std::string(kPhysicalAbout) + kWaves,
       run_physical},
      {"trace", "trace --wave W --beta B --gamma G: CSV phi,n,s over one period (Fig. 2)",
       {{"beta", "B", "beta (Eq. 5), a decimal > 0 (required)", "", text_beta},
        {"gamma", "G", "gamma = u_mean/A (Eq. 14), with contact (required)", "", text_gamma},
        {"points", "N", "N + 1 equally spaced phases i/N (0 and 1 both), N from 2 to 1000000, plus every stick phase's ends and the contact "
                        "boundaries (where n = 0 exactly)", "1000",
         [](Flags& f, const std::string& t) { f.points = integer(t, "--points", min_trace_points, max_trace_points); }},
        {"digits", "D", "significant digits, 1 to 10000", "17",
         [](Flags& f, const std::string& t) { f.digits = integer(t, "--digits", min_digits, max_digits); }},
        {"profile", "P", "the indenter (model.md MDR): n and s summed over the half-row (their ratio's mean is mu)", "flat",
         profile_named}},
       {&kWaveFlags, &kRigFlags},
       std::string(kWaves) + kRig +
           "  trace with them prints phi,n,s,lag,lag_rate,mode: the body's lag Y = X - beta phi behind the\n"
           "  drive and Y' (units mu0 k_z A/k_x), the mode (stick, slip, backward, flight), at the phases\n"
           "  and both ends of every span (two rows at one phi where a mode ends: left and right values).\n",
       run_trace},
      {"fit", "fit --wave samples:FILE --harmonics K [--output FILE]: a fourier file from samples",
       {{"harmonics", "K", "harmonics of the fit, 1 to 10000, 2K < samples (required)", "",
         [](Flags& f, const std::string& t) { f.harmonics = integer(t, "--harmonics", 1, max_fit_harmonics); }},
        {"output", "FILE", "write the fourier file here", "stdout", [](Flags& f, const std::string& t) { f.output = t; }}},
       {&kWaveFlags},
       "--wave takes a samples:FILE (--column for a table). The fit is the DFT for uniform phases and\n"
       "linear least squares (QR) on t/period for time stamps; the file's comments give the rms and\n"
       "largest residual. Use the fit when the signal is noisy (samples:FILE follows every wiggle:\n"
       "slopes enter beta_c, Eq. 6) and the samples when its kinks are real (a clipped or triangular\n"
       "drive).\n",
       run_fit},
      {"verify", "verify [--digits D] [--claim KEY] [--format json]: every claim of the paper and model.md",
       {{"digits", "D", "working digits, 10 to 300 (the same verdicts over the range)", "50",
         [](Flags& f, const std::string& t) { f.digits = integer(t, "--digits", min_verify_digits, max_verify_digits); }},
        {"claim", "KEY", "one claim (e.g. eq24)", "all", [](Flags& f, const std::string& t) { f.claim = t; }},
        {"format", "F", "text | json (for the report generator)", "text",
         [](Flags& f, const std::string& t) {
           if (t != "json" && t != "text") throw InputError("--format '" + detail::visible(t) + "': expected text or json" + hint(t, {"text", "json"}));
           f.format = format_named(t);
         }}},
       {},
       "",
       run_verify},
      {"version", "version: versions of vibrofric, the compiler, Boost, MPFR and GMP", {}, {}, "", run_version},
  };
  return specs;
}

// CLI11's help with our synopsis as its usage line.
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_usage(const CLI::App* app, std::string) const override {
    for (const auto& c : commands())
      if (app->get_name() == c.name) return std::string("usage: vibrofric ") + c.synopsis + "\n";
    return "usage: vibrofric COMMAND [OPTIONS]\n";
  }
  std::string make_description(const CLI::App*) const override { return ""; }
};

const std::string& need(const Flags& f, const std::optional<std::string>& value, const std::string& name) {
  if (!value) throw InputError("missing --" + name + " for '" + f.command + "'");
  return *value;
}

// The command's exit status, or none after --help. CLI11 parses into Flags and runs the command
// as its callback. Checked before CLI11 sees the arguments, for what CLI11 2.1 reads wrongly:
// - a value flag followed by a flag: `--beta --gamma 0` becomes "argument not expected: 0";
// - an empty value: `--beta= --gamma 0` the same, and `--no-escalate=` is taken as the switch alone;
// - a bare `--` ends CLI11's flags and turns the rest into positional arguments;
// - --help anywhere: CLI11 checks every value before it looks for --help.
std::optional<int> run_command(int argc, char** argv) {
  std::string names;
  std::vector<std::string> command_names;
  for (const auto& c : commands()) {
    names += (names.empty() ? "" : ", ") + std::string(c.name);
    command_names.emplace_back(c.name);
  }
  if (argc < 2) throw InputError("missing command: expected one of " + names + " (see --help)");
  Flags flags;
  flags.command = argv[1];
  if (flags.command == "--help" || flags.command == "-h" || flags.command == "help") {
    std::cout << "usage: vibrofric COMMAND [OPTIONS]\n\n" << kAbout;
    return std::nullopt;
  }
  const auto spec = std::find_if(commands().begin(), commands().end(), [&](const CommandSpec& c) { return flags.command == c.name; });
  if (spec == commands().end())
    throw InputError("unknown command '" + detail::visible(flags.command) + "': expected one of " + names + hint(flags.command, command_names));
  CLI::App app("vibrofric");
  app.formatter(std::make_shared<HelpFormatter>());
  CLI::App* sub = app.add_subcommand(spec->name, spec->synopsis);
  sub->allow_extras();
  std::map<std::string, CLI::Option*> options;
  auto add = [&](const FlagSpec& f, const char* group) {
    const std::string name = std::string("--") + f.name;
    CLI::Option* o = f.value[0] == '\0' ? sub->add_flag(name, f.help) : sub->add_option(name, f.help)->type_name(f.value);
    if (f.fallback[0] != '\0') o->default_str(f.fallback);
    o->group(group)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    o->each([&flags, read = f.read, name = std::string(f.name)](const std::string& text) {
      if (read)
        read(flags, text);
      else
        flags.texts[name] = text;
    });
    options[f.name] = o;
  };
  for (const auto& f : spec->flags) add(f, "Options");
  for (const auto* g : spec->groups)
    for (const auto& f : *g) add(f, g == &kWaveFlags ? "Wave" : g == &kPrecisionFlags ? "Precision" : "Solver controls");
  if (!spec->footer.empty()) sub->footer(spec->footer);
  for (int i = 2; i < argc; ++i) {
    const std::string tok = argv[i];
    if (tok == "--help" || tok == "-h") {
      std::cout << sub->help();
      return std::nullopt;
    }
  }
  const auto is_flag = [](const std::string& t) { return t.size() > 2 && t.rfind("--", 0) == 0 && std::isalpha(static_cast<unsigned char>(t[2])); };
  for (int i = 2; i < argc; ++i) {
    const std::string tok = argv[i];
    if (tok == "--") throw InputError("unknown flag -- for '" + flags.command + "'");
    if (!is_flag(tok)) continue;
    const auto eq = tok.find('=');
    const std::string name = tok.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
    const auto o = options.find(name);
    if (o == options.end()) continue;  // CLI11 leaves it over, refused below
    if (o->second->get_expected_max() == 0) {
      if (eq + 1 == tok.size()) switch_value("", name);
      continue;
    }
    if (eq + 1 == tok.size()) throw InputError("--" + name + "= is empty: --" + name + " needs a value");
    if (eq == std::string::npos && (i + 1 >= argc || is_flag(argv[i + 1]))) throw InputError("--" + name + " needs a value");
    if (eq == std::string::npos) ++i;
  }
  int status = 0;
  sub->callback([&] {
    for (const std::string& extra : sub->remaining()) {
      if (extra.rfind("--", 0) == 0) {
        const std::string name = extra.substr(2, extra.find('=') - 2);
        std::vector<std::string> known;
        for (const auto& [k, o] : options) known.push_back("--" + k);
        throw InputError("unknown flag --" + detail::visible(name) + " for '" + flags.command + "'" + hint("--" + name, known));
      }
      throw InputError("unexpected argument '" + detail::visible(extra) + "': expected --flag value");
    }
    for (const auto& [name, o] : options)
      if (o->count() > 1) throw InputError("flag --" + name + " given twice");
    status = spec->run(flags);
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    if (const auto nl = what.find('\n'); nl != std::string::npos) what.resize(nl);
    throw InputError(flags.command + ": " + what);
  }
  return status;
}

Precision precision_of(const Flags& f) {
  Precision p;
  if (f.type) p.type = *f.type;
  if (f.digits) {
    if (f.type && *f.type != NumberType::mpfr)
      throw InputError("--digits goes with mpfr only: --type " + detail::visible(f.type_text) + " has fixed precision");
    p.digits = *f.digits;
  }
  return p;
}

BatchOptions batch_options(const Flags& f) {
  BatchOptions o;
  o.profile = f.profile;
  o.escalate = !f.no_escalate;
  o.solver = f.solver;
  if (f.kappa || f.omega || f.zeta) {
    if (f.command == "psi")
      throw InputError("--kappa, --omega, --zeta do not apply to psi: Psi (Eq. 12) belongs to the quasi-static model (use mu)");
    if (!f.kappa || !f.omega)
      throw InputError(std::string("missing --") + (f.kappa ? "omega" : "kappa") +
                       ": rig dynamics needs --kappa and --omega (--zeta is optional)");
    if (f.certify) throw InputError("--certify: certified values exist for the quasi-static model only, not with --kappa/--omega");
    if (f.no_escalate) throw InputError("--no-escalate: rig dynamics is always computed in mpfr at two precisions");
    o.rig.emplace();
    o.rig->kappa = *f.kappa;
    o.rig->omega = *f.omega;
    o.rig->zeta = f.zeta.value_or("0");
    check_rig(*o.rig);
    if (o.profile.kind != ProfileKind::flat)
      throw InputError("--kappa/--omega with --profile " + detail::visible(f.profile_text.value_or("")) +
                       ": the springs of a curved contact share the body, so the MDR row does not decouple "
                       "(rig dynamics: the flat punch only)");
  }
  return o;
}

// Output formats of mu, psi, sweep and physical: their plain text, CSV (RFC 4180: a field with a
// comma, a quote or a line break is quoted by libcsv) or JSON (nlohmann; values as decimal strings,
// which keep every digit). One record is a JSON object, several are an array of objects.
std::string csv_field(const std::string& f) {
  if (f.find_first_of(",\"\r\n") == std::string::npos) return f;
  std::string out(2 * f.size() + 3, '\0');
  out.resize(csv_write(out.data(), out.size(), f.data(), f.size()));
  return out;
}

void write_csv_row(const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i) std::cout << (i ? "," : "") << csv_field(fields[i]);
  std::cout << '\n';
}

nlohmann::ordered_json json_record(const std::vector<std::string>& names, const std::vector<std::string>& values) {
  nlohmann::ordered_json j;
  for (std::size_t i = 0; i < names.size(); ++i) j[names[i]] = values[i];
  return j;
}

// --diagnostics lines, written to stderr only when the command succeeds: bad input after the wave
// was read stays one line.
std::string pending_diagnostics;

// The wave of --wave, its value column (--column) and, with --diagnostics, the normalisation a
// user wave went through (model.md, user waveforms), for stderr so that stdout stays data.
WaveSpec read_wave(const Flags& f) {
  WaveReadOptions options = f.read;
  options.column_name = "--column";
  options.periods_name = "--periods";
  WaveSpec wave = parse_wave(need(f, f.wave, "wave"), options);
  const unsigned k = wave.periods_averaged;
  if (!wave.period_from_stamps.empty())  // a period the file did not state: always said
    pending_diagnostics += "vibrofric: note: " + detail::visible(wave.name) + " has no end point; its " +
                           std::to_string(wave.samples.size() * k) + " time stamps are uniform, so the samples sit at phi = j/N "
                           "and the period is N dt" + (k > 1 ? "/" + std::to_string(k) : std::string()) + " = " +
                           format_significant(mpfr(wave.period_from_stamps), 6) + "\n";
  if (f.diagnostics)
    for (const auto& [name, value] : describe_normalisation(wave, 17))
      pending_diagnostics += "normalisation: " + name + " = " + value + "\n";
  return wave;
}

// --certify (README, "Precision"): the exact value of a piecewise-linear wave's point and the proof
// that the printed value is its correct rounding. A printed value that is not would be a solver
// bug: an error, and the value is not printed.
std::optional<Certifier> certifier_of(const Flags& f, const WaveSpec& wave, const BatchOptions& opt) {
  if (!f.certify) return std::nullopt;
  if (f.no_escalate)
    throw InputError("--certify proves the guaranteed value, --no-escalate prints one that is not guaranteed: give one of them");
  if (opt.profile.kind != ProfileKind::flat)
    throw InputError("--certify --profile " + detail::visible(f.profile_text.value_or("")) +
                     ": certified values exist for the flat punch only (a curved contact integrates over springs)");
  try {
    return Certifier(wave, opt.profile);
  } catch (const InputError& e) {
    throw InputError("--certify --wave " + detail::visible(f.wave.value_or("")) + ": " + e.what());
  }
}

Certificate certified(const Certifier& certifier, Quantity q, const Point& p, const Precision& precision,
                      const std::string& printed) {
  Certificate c = certifier(q, p, precision, printed);
  if (!c.correctly_rounded)
    throw SolverError("--certify: the printed " + printed + " is not the correct rounding of the exact value " + c.exact +
                      " (that is " + c.nearest.front() + "): a solver bug, please report it");
  return c;
}

// CSV and JSON fields of a certificate: the exact value, or an enclosure's ends.
std::vector<std::pair<std::string, std::string>> certificate_fields(const Certificate& c, bool enclosure) {
  if (enclosure) return {{"lower", c.lower_text}, {"upper", c.upper_text}, {"correctly_rounded", "proven"}};
  return {{"exact", c.exact}, {"correctly_rounded", "proven"}};
}

std::string rounding_name(const Precision& p) {
  return p.type == NumberType::mpfr ? "to " + std::to_string(p.digits) + " significant digits"
                                    : "to the nearest " + number_type_name(p.type);
}

// One point's record as CSV (a header and a row) or JSON (an object); status 0.
int write_record(const std::vector<std::string>& names, const std::vector<std::string>& values, Format format) {
  if (format == Format::csv) {
    write_csv_row(names);
    write_csv_row(values);
  } else {
    std::cout << json_record(names, values).dump(1) << '\n';
  }
  return 0;
}

// mu with --kappa/--omega: the value, then the periodic state's fractions and sizes.
int print_rig(const WaveSpec& wave, const Point& p, const BatchOptions& opt, const Precision& precision, Format format) {
  const RigReport r = evaluate_rig(wave, p, *opt.rig, precision, opt.solver);
  char floquet[32];
  std::snprintf(floquet, sizeof floquet, "%.6g", r.floquet);
  const std::vector<std::pair<std::string, std::string>> fields{
      {"stick_fraction", r.stick_fraction}, {"slip_fraction", r.slip_fraction},
      {"backward_slip_fraction", r.backward_fraction}, {"flight_fraction", r.flight_fraction},
      {"amplitude", r.amplitude}, {"largest_backward_slip", r.largest_backward_slip},
      {"floquet_multiplier", floquet}, {"relative_error_estimate", r.relative_error}};
  if (format == Format::text) {
    std::cout << r.mu << '\n';
    for (const auto& [name, value] : fields) std::cout << name << ": " << value << '\n';
    return 0;
  }
  std::vector<std::string> names{"wave", "beta", "gamma", "kappa", "omega", "zeta", "mu_over_mu0"};
  std::vector<std::string> values{wave.name, p.beta, p.gamma, opt.rig->kappa, opt.rig->omega, opt.rig->zeta, r.mu};
  for (const auto& [name, value] : fields) {
    names.push_back(name);
    values.push_back(value);
  }
  return write_record(names, values, format);
}

int run_point(const Flags& f, Quantity q) {
  const WaveSpec wave = read_wave(f);
  const Point p{need(f, f.beta, "beta"), q == Quantity::mu ? need(f, f.gamma, "gamma") : std::string()};
  const BatchOptions opt = batch_options(f);
  if (q == Quantity::psi && opt.profile.kind != ProfileKind::flat)
    throw InputError("psi --profile " + detail::visible(*f.profile_text) +
                     ": Psi (Eq. 12) exists for the flat punch only; in a curved contact the outer springs always jump, "
                     "so Eq. 13's separation does not exist (use mu)");
  const Format format = f.format.value_or(Format::text);
  const std::optional<Certifier> certifier = certifier_of(f, wave, opt);
  const Precision precision = precision_of(f);
  if (opt.rig) return print_rig(wave, p, opt, precision, format);
  const std::string value = evaluate(wave, q, {p}, precision, opt).front();
  std::optional<Certificate> cert;
  if (certifier) cert = certified(*certifier, q, p, precision, value);
  if (format == Format::text) {
    std::cout << value << '\n';
    if (cert)
      std::cout << (cert->exact.empty() ? "enclosure: [" + cert->lower_text + ", " + cert->upper_text + "]" : "exact: " + cert->exact)
                << "\nproven: " << value << " is the exact value rounded " << rounding_name(precision)
                << (cert->nearest.size() > 1 ? " (a tie: it lies midway between " + cert->nearest[0] + " and " + cert->nearest[1] + ")" : "")
                << '\n';
    return 0;
  }
  std::vector<std::string> names{"wave"}, values{wave.name};
  if (opt.profile.kind != ProfileKind::flat) {
    names.push_back("profile");
    values.push_back(opt.profile.name);
  }
  names.push_back("beta");
  values.push_back(p.beta);
  if (q == Quantity::mu) {
    names.push_back("gamma");
    values.push_back(p.gamma);
  }
  names.push_back(q == Quantity::mu ? "mu_over_mu0" : "psi");
  values.push_back(value);
  if (cert) {
    for (const auto& [name, v] : certificate_fields(*cert, cert->exact.empty())) {
      names.push_back(name);
      values.push_back(v);
    }
  }
  return write_record(names, values, format);
}

int run_mu(const Flags& f) { return run_point(f, Quantity::mu); }
int run_psi(const Flags& f) { return run_point(f, Quantity::psi); }

int run_sweep(const Flags& f) {
  const WaveSpec wave = read_wave(f);
  if (f.betas.empty()) throw InputError("missing --beta for 'sweep'");
  // --quantity psi: Ψ_w(β) (Eq. 12), which has no γ.
  const Quantity q = f.quantity;
  std::vector<std::string> gammas;
  if (q == Quantity::psi) {
    if (f.gamma) throw InputError("--gamma does not apply to --quantity psi: Psi_w(beta) has no gamma (Eq. 12)");
    gammas.push_back("");
  } else {
    need(f, f.gamma, "gamma");
    gammas = f.gammas;
  }
  const std::vector<std::string>& betas = f.betas;
  const Precision prec = precision_of(f);
  const Format format = f.format.value_or(Format::csv);
  // Points made on demand, γ-major as the rows (a 3000 × 3000 map holds no vector of points).
  const std::size_t count = betas.size() * gammas.size();
  const auto point = [&](std::size_t i) { return Point{betas[i % betas.size()], gammas[i / betas.size()]}; };
  BatchOptions opt = batch_options(f);
  opt.threads = f.threads;
  // The progress line on a terminal: at most ten redraws a second, never backwards (workers report
  // out of order), with the percentage and the remaining time; the callback costs an atomic load
  // and a clock read per point between redraws.
  std::mutex m;
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  std::atomic<long long> next_draw_ns{0};
  std::size_t shown = 0;
  if (isatty(2))
    opt.progress = [&](std::size_t done) {
      const long long now = std::chrono::duration_cast<std::chrono::nanoseconds>(clock::now() - start).count();
      const bool last = done == count;
      if (!last && now < next_draw_ns.load(std::memory_order_relaxed)) return;
      std::lock_guard<std::mutex> lock(m);
      if (done <= shown || (!last && now < next_draw_ns.load(std::memory_order_relaxed))) return;
      next_draw_ns.store(now + 100'000'000, std::memory_order_relaxed);
      shown = done;
      const double seconds = static_cast<double>(now) / 1e9;
      const double left = seconds * static_cast<double>(count - done) / static_cast<double>(done);
      std::fprintf(stderr, "\rsweep: %zu/%zu (%.1f %%), %.0f s left   ", done, count,
                   100.0 * static_cast<double>(done) / static_cast<double>(count), left);
      if (last) std::fprintf(stderr, "\n");
    };
  const bool curved = opt.profile.kind != ProfileKind::flat;
  std::vector<std::string> names{"wave"};
  if (curved) names.push_back("profile");
  names.push_back("beta");
  if (q == Quantity::mu) names.push_back("gamma");
  if (opt.rig) names.insert(names.end(), {"kappa", "omega", "zeta"});
  names.push_back(q == Quantity::mu ? "mu_over_mu0" : "psi");
  const std::optional<Certifier> certifier = certifier_of(f, wave, opt);
  if (certifier)
    for (const auto& field : certificate_fields(Certificate{}, certifier->encloses())) names.push_back(field.first);
  // Rows in their deterministic order as they complete; memory bounded whatever the count. The
  // domain (β ≥ 0 and representable, contact at the smallest γ, a profile's extent at the largest)
  // is monotone in β and γ, so the four corners decide it before any row is written.
  if (count > 0) {
    auto extreme = [](const std::vector<std::string>& v, bool largest) {
      PrecisionScope scope(40);
      std::size_t k = 0;
      for (std::size_t i = 1; i < v.size(); ++i)
        if (largest ? mpfr(v[i]) > mpfr(v[k]) : mpfr(v[i]) < mpfr(v[k])) k = i;
      return v[k];
    };
    std::vector<Point> corners;
    for (bool big_beta : {false, true})
      for (bool big_gamma : {false, true})
        corners.push_back({extreme(betas, big_beta), q == Quantity::mu ? extreme(gammas, big_gamma) : std::string()});
    BatchOptions quiet = opt;
    quiet.progress = nullptr;
    evaluate(wave, q, corners, prec, quiet);
  }
  if (format == Format::json)
    std::cout << "[";
  else
    write_csv_row(names);
  evaluate_stream(wave, q, count, point, prec, opt, [&](std::size_t i, const StreamValue& value) {
    const Point pt = point(i);
    std::vector<std::string> r{wave.name};
    if (curved) r.push_back(opt.profile.name);
    r.push_back(pt.beta);
    if (q == Quantity::mu) r.push_back(pt.gamma);
    if (opt.rig) r.insert(r.end(), {opt.rig->kappa, opt.rig->omega, opt.rig->zeta});
    r.push_back(value.text);
    if (certifier)
      for (const auto& field : certificate_fields(certified(*certifier, q, pt, prec, value.text), certifier->encloses()))
        r.push_back(field.second);
    if (format == Format::json)
      std::cout << (i ? ",\n " : "\n ") << json_record(names, r).dump();
    else
      write_csv_row(r);
  });
  if (format == Format::json) std::cout << (count ? "\n]\n" : "]\n");
  return 0;
}

// `physical`'s inputs as typed (`texts`, swept or not), each named by its flag (the input u_mean is
// --u-mean), and its controls.
PhysicalOutputs physical_record(const Flags& f, const std::map<std::string, std::string>& texts, const WaveSpec& wave) {
  PhysicalRequest request;
  for (auto& [member, input] : request.inputs()) {
    std::string flag = member;
    std::replace(flag.begin(), flag.end(), '_', '-');
    input->name = "--" + flag;
    if (const auto it = texts.find(flag); it != texts.end()) input->text = it->second;
  }
  std::vector<std::string> warnings;
  PhysicalOutputs out = physical_point(wave, request, precision_of(f), batch_options(f), &warnings);
  // Each warning once (a sweep repeats them), on stderr after the output, as the diagnostics.
  static std::set<std::string> said;
  for (const auto& w : warnings)
    if (said.insert(w).second) pending_diagnostics += "vibrofric: warning: " + w + "\n";
  return out;
}

// Names and values of output records, for CSV and JSON.
std::vector<std::string> names_of(const PhysicalOutputs& r) {
  std::vector<std::string> out;
  for (const auto& [name, value] : r) out.push_back(name);
  return out;
}
std::vector<std::string> values_of(const PhysicalOutputs& r) {
  std::vector<std::string> out;
  for (const auto& [name, value] : r) out.push_back(value);
  return out;
}

// `physical` at one point, or over a range of one input (--v0, --A, --f, --F-N or --u-mean as
// FROM:TO:N or log:FROM:TO:N): one row per value, streamed as it is computed.
int run_physical(const Flags& f) {
  const WaveSpec wave = read_wave(f);
  std::string swept;
  for (const char* name : {"v0", "A", "f", "F-N", "u-mean"})
    if (f.texts.count(name) && f.texts.at(name).find(':') != std::string::npos) {
      if (!swept.empty())
        throw InputError("--" + swept + " and --" + name + " are both ranges: expected one swept input at a time");
      swept = name;
    }
  if (swept.empty()) {
    const Format format = f.format.value_or(Format::text);
    const PhysicalOutputs rec = physical_record(f, f.texts, wave);
    if (format == Format::csv) {
      write_csv_row(names_of(rec));
      write_csv_row(values_of(rec));
    } else if (format == Format::json) {
      std::cout << json_record(names_of(rec), values_of(rec)).dump(1) << '\n';
    } else {
      for (const auto& [name, value] : rec) std::cout << name << " = " << value << '\n';
    }
    return 0;
  }
  const Format format = f.format.value_or(Format::csv);
  if (format == Format::text) throw InputError("--format text: a physical sweep writes csv (the default) or json");
  // A range of u_mean may start below contact (gamma < -1 for the sine): such rows are errors, as at one point.
  const auto range = value_range(f.texts.at(swept), "--" + swept, swept == "u-mean");
  // Every input's domain is monotone along a range: its two ends decide it before the first row.
  std::map<std::string, std::string> texts = f.texts;
  auto at = [&](std::size_t i) {
    texts[swept] = range[i];
    return physical_record(f, texts, wave);
  };
  const PhysicalOutputs first = at(0), last = at(range.size() - 1);
  for (std::size_t i = 0; i < range.size(); ++i) {
    PhysicalOutputs rec = i == 0 ? first : i + 1 == range.size() ? last : at(i);
    rec.insert(rec.begin(), {swept, range[i]});  // the swept input leads each row, under its flag's name
    if (format == Format::csv) {
      if (i == 0) write_csv_row(names_of(rec));
      write_csv_row(values_of(rec));
    } else {
      std::cout << (i ? ",\n " : "[\n ") << json_record(names_of(rec), values_of(rec)).dump();
    }
    std::cout.flush();
  }
  if (format == Format::json) std::cout << "\n]\n";
  return 0;
}

// s(φ) and n(φ) over one period (the paper's Fig. 2): N equally spaced phases plus both ends of
// every stick phase, so that a plot shows the kinks where they are.
int run_trace(const Flags& f) {
  const WaveSpec wave = read_wave(f);
  TraceRequest request;
  request.beta = {need(f, f.beta, "beta"), "--beta"};
  request.gamma = {need(f, f.gamma, "gamma"), "--gamma"};
  request.points_name = "--points";
  request.digits_name = "--digits";
  if (f.digits) request.digits = *f.digits;
  if (f.points) request.points = *f.points;
  request.profile = f.profile;
  const BatchOptions o = batch_options(f);
  if (o.rig) {
    const auto rows = rig_trace_rows(wave, request, *o.rig, o.solver);
    std::cout << "phi,n,s,lag,lag_rate,mode\n";
    for (const auto& r : rows)
      std::cout << r.phi << ',' << r.n << ',' << r.s << ',' << r.lag << ',' << r.lag_rate << ',' << r.mode << '\n';
    return 0;
  }
  const auto rows = trace_rows(wave, request);
  std::cout << "phi,n,s\n";
  for (const auto& r : rows) std::cout << r[0] << ',' << r[1] << ',' << r[2] << '\n';
  return 0;
}

// A samples file fitted by K harmonics (DFT for uniform phases, least squares for time stamps),
// written as a fourier file that --wave fourier:FILE reads.
int run_fit(const Flags& f) {
  const WaveSpec wave = read_wave(f);
  if (!f.harmonics) throw InputError("missing --harmonics for 'fit'");
  const int harmonics = *f.harmonics;
  const FourierFit fit = fit_fourier(wave, static_cast<unsigned>(harmonics));
  const std::string text = fourier_file_text(fit, *f.wave);
  if (!f.output) {
    std::cout << text;
    return 0;
  }
  const std::string& path = *f.output;
  if (std::filesystem::is_directory(path))
    throw InputError("--output '" + detail::visible(path) + "' is a directory: expected a file name");
  std::ofstream out(path);
  if (!(out << text) || !(out.close(), out))
    throw InputError("--output '" + detail::visible(path) + "': cannot write the file");
  std::cerr << "fit: K = " << harmonics << " harmonics (" << fit.method << "), rms residual "
            << fit.rms_residual << ", written to " << path << '\n';
  return 0;
}

int run_version(const Flags&) {
  std::printf("vibrofric %s\n", VIBROFRIC_VERSION);
#if defined(__clang__)
  std::printf("compiler clang %s\n", __clang_version__);
#elif defined(__GNUC__)
  std::printf("compiler gcc %s\n", __VERSION__);
#else
  std::printf("compiler unknown\n");
#endif
  std::printf("boost %d.%d.%d\n", BOOST_VERSION / 100000, BOOST_VERSION / 100 % 1000, BOOST_VERSION % 100);
  std::printf("mpfr %s\n", mpfr_get_version());
  std::printf("gmp %s\n", gmp_version);
  return 0;
}

int run_verify(const Flags& f) {
  const int digits = f.digits.value_or(50);
  std::vector<ClaimCheck> checks;
  if (f.claim)
    checks.push_back(check_claim(*f.claim, digits));
  else
    checks = verify_claims(digits);
  if (f.format == Format::json) {
    std::cout << claims_json(checks, digits) << '\n';
    return 0;
  }
  std::printf("%-28s %-8s %-20s %-9s %s\n", "claim", "cases", "verdict", "deviation", "statement");
  for (const auto& c : checks) {
    std::printf("%-28s %-8zu %-20s %-9s %s\n", c.id.c_str(), c.cases, verdict_text(c).c_str(),
                c.deviation_text.c_str(), c.statement.c_str());
  }
  std::printf("\nrequested precision: %d digits\n", digits);
  for (const auto& c : checks) {
    std::printf("\n%s (%s, %s) — %s\n", c.id.c_str(), c.key.c_str(), c.source.c_str(), verdict_text(c).c_str());
    std::printf("  method:    %s%s\n", c.method.c_str(), c.proof.empty() ? "" : (" (" + c.proof + ")").c_str());
    std::printf("  checked:   %s\n", c.how.c_str());
    std::printf("  criterion: %s\n", c.criterion.c_str());
    std::printf("  %-10s %s\n", (c.certification + ":").c_str(), c.certification_note.c_str());
    std::printf("  deviation: %s (%s)\n", c.deviation_text.c_str(), c.deviation_unit.c_str());
    std::printf("  worst:     %s\n", c.worst.c_str());
    if (!c.scope.empty()) std::printf("  scope:     %s\n", c.scope.c_str());
    if (!c.fails_where.empty()) std::printf("  fails:     %s\n", c.fails_where.c_str());
    if (!c.corrected.empty()) {
      std::printf("  corrected: %s\n", c.corrected.c_str());
      if (c.corrected_deviation) std::printf("             largest deviation %s\n", c.corrected_deviation_text.c_str());
    }
    for (const auto& m : c.measured) std::printf("  measured:  %s: %s\n", m.name.c_str(), m.value.c_str());
  }
  return 0;
}

// A message on one line whatever a library put in it: control characters escaped (values quoted
// in messages went through detail::visible() already, which also escapes non-ASCII bytes).
std::string one_line(const std::string& message) {
  std::string out;
  for (const char ch : message) {
    const auto u = static_cast<unsigned char>(ch);
    out += u < 0x20 || u == 0x7F ? detail::visible(std::string(1, ch)) : std::string(1, ch);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  pending_diagnostics.clear();
  try {
    const std::optional<int> status = run_command(argc, argv);
    if (!status) return 0;  // --help
    std::cerr << pending_diagnostics;
    return *status;
  } catch (const InputError& e) {
    std::cerr << "vibrofric: " << one_line(e.what()) << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "vibrofric: error: " << one_line(e.what()) << '\n';
    return 1;
  }
}
