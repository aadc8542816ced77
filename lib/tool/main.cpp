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
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/fit.hpp"
#include "vibrofric/api/profile_spec.hpp"
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
    "Printed: shape, E*, G*, k_z and k_x (flat) or the largest contact radius (curved), lambda\n"
    "(wearflat), beta, gamma, mu/mu0, mu, the mean normal and friction forces <F_N>, <F_x> in\n"
    "newtons, beta_c (Eq. 6, of the clipped n; curved: the central spring's) and, for the flat\n"
    "punch, the fractions of the period in contact and in stick.\n"
    "shapes S and their GEOMETRY (metres, degrees):\n"
    "  flat (default) --radius a          flat-ended cylinder: k_z = 2 E* a, k_x = 2 G* a (Eq. 1)\n"
    "  sphere --R R                       MDR (model.md), sigma = x^2/(R A)\n"
    "  cone --half-angle THETA            angle between axis and flank, in degrees\n"
    "  wearflat --R R --flat-radius b     sphere with a wear flat, lambda = b^2/(R A)\n"
    "  profile:FILE                       measured profile, lines 'r f' in metres, f(0) = 0\n";

struct Args {
  std::string command;
  std::map<std::string, std::string> flags;  // the flags given, with their values as typed
  bool help = false;
};

// One flag of a command: its name, the value's placeholder (empty: a switch), the help line and
// the default shown by --help (empty: none).
struct FlagSpec {
  const char* name;
  const char* value;
  const char* help;
  const char* fallback;
};

const std::vector<FlagSpec> kWaveFlags{
    {"wave", "W", "the wave (required): catalogue name, power:P, fourier:FILE or samples:FILE", ""},
    {"column", "C", "samples FILE: the value column, by header name or 1-based index", "the one value column"},
    {"diagnostics", "", "print on stderr the normalisation of a user wave: raw mean, min, max, scale, period, end point", ""},
};
const std::vector<FlagSpec> kPrecisionFlags{
    {"digits", "D", "significant digits, 1 to 10000 (mpfr, with guard digits)", "50"},
    {"type", "T", "double | long-double | cpp_bin_float_50 | cpp_bin_float_100 | mpfr", "mpfr"},
    {"no-escalate", "", "fixed types: print the value computed in the type even where its rounding bound "
                        "exceeds the type's epsilon (=true/false/yes/no/1/0; default off: recompute with mpfr)", ""},
};
const std::vector<FlagSpec> kSolverFlags{
    {"area", "M", "auto | exact | quadrature: areas from antiderivatives or tanh-sinh, every event a breakpoint",
     "auto"},
    {"max-iterations", "N", "root-finder budget per event, 1 to 100000", "200 + working bits"},
    {"max-levels", "N", "tanh-sinh halvings, 4 to 30", "15"},
    {"quadrature-tolerance", "T", "tanh-sinh tolerance, in (0, 1)", "sqrt(eps) of the working precision"},
};

struct CommandSpec {
  const char* name;
  const char* synopsis;
  std::vector<FlagSpec> flags;
  std::vector<const std::vector<FlagSpec>*> groups;
  std::string footer;
};

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> specs{
      {"mu", "mu --wave W --beta B --gamma G [--profile P]: mu/mu0 = g_w(beta, gamma) (Eq. 15)",
       {{"beta", "B", "beta (Eq. 5), a decimal > 0 (required)", ""},
        {"gamma", "G", "gamma = u_mean/A (Eq. 14), a decimal with contact, gamma > -max w (required)", ""},
        {"profile", "P", "the indenter (model.md MDR)", "flat"},
        {"format", "F", "text | csv | json", "text"}},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags},
       std::string(kWaves) + kProfiles},
      {"psi", "psi --wave W --beta B: Psi_w(beta) (Eq. 12), flat punch, non-jumping",
       {{"beta", "B", "beta (Eq. 5), a decimal > 0 (required)", ""},
        {"profile", "P", "flat only: in a curved contact the outer springs always jump", "flat"},
        {"format", "F", "text | csv | json", "text"}},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags},
       kWaves},
      {"sweep", "sweep --wave W --beta RANGE --gamma G1,G2,...|RANGE [--profile P]: rows streamed in order",
       {{"beta", "RANGE", "FROM:TO:N (linear, ends included) or log:FROM:TO:N (geometric) (required)", ""},
        {"gamma", "G", "a list G1,G2,... or a range FROM:TO:N (FROM > TO allowed); not with --quantity psi", ""},
        {"quantity", "Q", "mu | psi", "mu"},
        {"profile", "P", "the indenter (model.md MDR)", "flat"},
        {"threads", "N", "worker threads, 0 for every core", "0"},
        {"format", "F", "csv | json", "csv"}},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags},
       std::string(kWaves) + kProfiles},
      {"physical", "physical --wave W --E1 PA --nu1 NU --E2 PA --nu2 NU [--G1 PA --G2 PA] --v0 M/S --f HZ\n"
                   "                          --A M (--u-mean M | --F-N N) --mu0 MU [--shape S GEOMETRY]",
       {{"E1", "PA", "Young's modulus of body 1, > 0 (required)", ""},
        {"nu1", "NU", "Poisson's ratio of body 1, -1 < nu <= 0.5 (required)", ""},
        {"E2", "PA", "Young's modulus of body 2, > 0 (required)", ""},
        {"nu2", "NU", "Poisson's ratio of body 2 (required)", ""},
        {"G1", "PA", "shear modulus of body 1", "E1/(2(1 + nu1))"},
        {"G2", "PA", "shear modulus of body 2", "E2/(2(1 + nu2))"},
        {"v0", "M/S", "sliding velocity, > 0 (required; or a range)", ""},
        {"f", "HZ", "oscillation frequency, > 0 (required; or a range)", ""},
        {"A", "M", "zero-to-peak amplitude of the normal oscillation, > 0 (required; or a range)", ""},
        {"u-mean", "M", "mean indentation (or a range); or give --F-N", ""},
        {"F-N", "N", "mean normal load, > 0 (or a range); or give --u-mean", ""},
        {"mu0", "MU", "local coefficient of friction, > 0 (required)", ""},
        {"shape", "S", "flat | sphere | cone | wearflat | profile:FILE", "flat"},
        {"radius", "M", "flat: punch radius (required for flat)", ""},
        {"R", "M", "sphere, wearflat: radius of curvature", ""},
        {"half-angle", "DEG", "cone: angle between axis and flank, in (0, 90)", ""},
        {"flat-radius", "M", "wearflat: radius of the wear flat", ""},
        {"format", "F", "text | csv | json (a sweep: csv | json)", "text (a sweep: csv)"}},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags},
       std::string(kPhysicalAbout) + kWaves},
      {"trace", "trace --wave W --beta B --gamma G: CSV phi,n,s over one period (Fig. 2)",
       {{"beta", "B", "beta (Eq. 5), a decimal > 0 (required)", ""},
        {"gamma", "G", "gamma = u_mean/A (Eq. 14), with contact (required)", ""},
        {"points", "N", "N + 1 equally spaced phases i/N (0 and 1 both), N from 2 to 1000000, plus every stick phase's ends and the contact "
                        "boundaries (where n = 0 exactly)", "1000"},
        {"digits", "D", "significant digits, 1 to 10000", "17"}},
       {&kWaveFlags},
       kWaves},
      {"fit", "fit --wave samples:FILE --harmonics K [--output FILE]: a fourier file from samples",
       {{"harmonics", "K", "harmonics of the fit, 1 to 10000, 2K < samples (required)", ""},
        {"output", "FILE", "write the fourier file here", "stdout"}},
       {&kWaveFlags},
       "--wave takes a samples:FILE (--column for a table). The fit is the DFT for uniform phases and\n"
       "linear least squares (QR) on t/period for time stamps; the file's comments give the rms and\n"
       "largest residual. Use the fit when the signal is noisy (samples:FILE follows every wiggle:\n"
       "slopes enter beta_c, Eq. 6) and the samples when its kinks are real (a clipped or triangular\n"
       "drive).\n"},
      {"verify", "verify [--digits D] [--claim KEY] [--format json]: every claim of the paper and model.md",
       {{"digits", "D", "working digits, 10 to 300 (the same verdicts over the range)", "50"},
        {"claim", "KEY", "one claim (e.g. eq24)", "all"},
        {"format", "F", "text | json (for the report generator)", "text"}},
       {},
       ""},
      {"version", "version: versions of vibrofric, the compiler, Boost, MPFR and GMP", {}, {}, ""},
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

bool is_switch(const std::string& name) { return name == "no-escalate" || name == "diagnostics"; }

// A switch's state: absent is off; present alone, or =1/true/yes, on; =0/false/no, off; else bad input.
bool switch_on(const Args& a, const std::string& name) {
  const auto it = a.flags.find(name);
  if (it == a.flags.end()) return false;
  const std::string& v = it->second;
  if (v == "1" || v == "true" || v == "yes") return true;
  if (v == "0" || v == "false" || v == "no") return false;
  throw InputError("--" + name + " = '" + detail::visible(v) + "': expected no value, or one of true, false, yes, no, 1, 0");
}

std::vector<FlagSpec> flags_of(const CommandSpec& c) {
  std::vector<FlagSpec> all = c.flags;
  for (const auto* g : c.groups) all.insert(all.end(), g->begin(), g->end());
  return all;
}

// Parsed by CLI11; checked first for what CLI11 would misread: a value flag followed by another
// flag (`--beta --gamma 0` would take '--gamma' as beta), an empty `--beta=`, unknown names.
Args parse_args(int argc, char** argv) {
  Args a;
  std::string names;
  for (const auto& c : commands()) names += (names.empty() ? "" : ", ") + std::string(c.name);
  if (argc < 2) throw InputError("missing command: expected one of " + names + " (see --help)");
  a.command = argv[1];
  if (a.command == "--help" || a.command == "-h" || a.command == "help") {
    std::cout << "usage: vibrofric COMMAND [OPTIONS]\n\n" << kAbout;
    a.help = true;
    return a;
  }
  CLI::App app("vibrofric");
  app.formatter(std::make_shared<HelpFormatter>());
  const auto spec = std::find_if(commands().begin(), commands().end(), [&](const CommandSpec& c) { return a.command == c.name; });
  if (spec == commands().end())
    throw InputError("unknown command '" + detail::visible(a.command) + "': expected one of " + names);
  const std::vector<FlagSpec> flags = flags_of(*spec);
  auto find = [&](const std::string& n) {
    return std::find_if(flags.begin(), flags.end(), [&](const FlagSpec& f) { return n == f.name; });
  };
  std::set<std::string> seen;
  for (int i = 2; i < argc; ++i) {
    const std::string tok = argv[i];
    if (tok == "--help" || tok == "-h") continue;
    if (tok.rfind("--", 0) != 0) throw InputError("unexpected argument '" + detail::visible(tok) + "': expected --flag value");
    const auto eq = tok.find('=');
    const std::string name = tok.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
    if (find(name) == flags.end()) throw InputError("unknown flag --" + detail::visible(name) + " for '" + a.command + "'");
    if (!seen.insert(name).second) throw InputError("flag --" + name + " given twice");
    if (is_switch(name)) {
      // CLI11 would read an empty `--no-escalate=` as the switch alone.
      if (eq + 1 == tok.size()) switch_on(Args{a.command, {{name, ""}}, false}, name);
      continue;
    }
    // The next token is a value unless it is a flag by name ('--' alone is a value, and bad).
    const auto is_flag = [](const std::string& t) { return t.size() > 2 && t.rfind("--", 0) == 0 && std::isalpha(t[2]); };
    if (eq + 1 == tok.size()) throw InputError("--" + name + "= is empty: --" + name + " needs a value");
    if (eq == std::string::npos && (i + 1 >= argc || is_flag(argv[i + 1])))
      throw InputError("--" + name + " needs a value");
    if (eq == std::string::npos) ++i;
  }
  CLI::App* sub = app.add_subcommand(spec->name, spec->synopsis);
  std::map<std::string, std::string> values;
  std::vector<std::pair<std::string, CLI::Option*>> options;
  auto add = [&](const FlagSpec& f, const char* group) {
    CLI::Option* o = f.value[0] == '\0' ? sub->add_flag(std::string("--") + f.name, values[f.name], f.help)
                                        : sub->add_option(std::string("--") + f.name, values[f.name], f.help)
                                              ->type_name(f.value);
    if (f.fallback[0] != '\0') o->default_str(f.fallback);
    o->group(group);
    options.emplace_back(f.name, o);
  };
  for (const auto& f : spec->flags) add(f, "Options");
  for (const auto* g : spec->groups)
    for (const auto& f : *g)
      add(f, g == &kWaveFlags ? "Wave" : g == &kPrecisionFlags ? "Precision" : "Solver controls");
  if (!spec->footer.empty()) sub->footer(spec->footer);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << sub->help();
    a.help = true;
    return a;
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    if (const auto nl = what.find('\n'); nl != std::string::npos) what.resize(nl);
    throw InputError(a.command + ": " + what);
  }
  for (const auto& [name, o] : options)
    if (o->count() > 0) a.flags[name] = values[name];
  return a;
}

const std::string& need(const Args& a, const std::string& name) {
  const auto it = a.flags.find(name);
  if (it == a.flags.end()) throw InputError("missing --" + name + " for '" + a.command + "'");
  return it->second;
}

int parse_int(const std::string& text, const std::string& what, long lo, long hi) {
  if (!std::regex_match(text, std::regex("[+-]?[0-9]{1,9}")))
    throw InputError(what + " = '" + detail::visible(text) + "': expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  const long v = std::stol(text);
  if (v < lo || v > hi)
    throw InputError(what + " = " + detail::visible(text) + ": expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  return static_cast<int>(v);
}

Precision parse_precision(const Args& a) {
  Precision p;
  const bool has_digits = a.flags.count("digits"), has_type = a.flags.count("type");
  if (has_type) {
    const auto type = number_type_named(a.flags.at("type"));
    if (!type) throw InputError("--type '" + a.flags.at("type") + "': expected " + number_type_choices);
    p.type = *type;
  }
  if (has_digits) {
    if (has_type && p.type != NumberType::mpfr)
      throw InputError("--digits goes with mpfr only: --type " + detail::visible(a.flags.at("type")) + " has fixed precision");
    p.digits = parse_int(a.flags.at("digits"), "--digits", min_digits, max_digits);
  }
  return p;
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

// β_i = FROM + i (TO − FROM)/(N − 1), as decimal strings of 17 significant digits computed at
// 40 digits: the printed β is exactly the β evaluated.
// FROM:TO:N, N values with both ends (linear), or log:FROM:TO:N (geometric, FROM and TO > 0). As
// decimals of 17 significant digits, trailing zeros dropped. `flag` names the flag in messages;
// `descending` allows TO < FROM (γ from 1 down to −1, as the paper's figures).
std::vector<std::string> value_range(const std::string& spec, const std::string& flag, bool descending) {
  const bool log = spec.rfind("log:", 0) == 0;
  const auto parts = split(log ? spec.substr(4) : spec, ':');
  if (parts.size() != 3) throw InputError(flag + " '" + detail::visible(spec) + "': expected FROM:TO:N or log:FROM:TO:N");
  check_decimal(parts[0], flag + " FROM");
  check_decimal(parts[1], flag + " TO");
  const int n = parse_int(parts[2], flag + " N", 1, max_range_points);
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

// Solver controls (solver.hpp Options): a budget the solver cannot meet is an error, never a value.
Options parse_solver_options(const Args& a) {
  Options o;
  if (a.flags.count("area")) {
    const std::string& m = a.flags.at("area");
    if (m == "auto")
      o.area = AreaMethod::automatic;
    else if (m == "exact")
      o.area = AreaMethod::exact;
    else if (m == "quadrature")
      o.area = AreaMethod::quadrature;
    else
      throw InputError("--area '" + detail::visible(m) + "': expected auto, exact or quadrature");
  }
  if (a.flags.count("max-iterations"))
    o.max_root_iterations = static_cast<std::uintmax_t>(parse_int(a.flags.at("max-iterations"), "--max-iterations", 1, root_iterations_limit));
  if (a.flags.count("max-levels"))
    o.max_quadrature_levels = static_cast<std::size_t>(parse_int(a.flags.at("max-levels"), "--max-levels", 4, 30));
  if (a.flags.count("quadrature-tolerance")) {
    const std::string& t = a.flags.at("quadrature-tolerance");
    check_decimal(t, "--quadrature-tolerance");
    const double v = std::strtod(t.c_str(), nullptr);
    if (!(v > 0 && v < 1)) throw InputError("--quadrature-tolerance = " + t + ": expected a number in (0, 1)");
    o.quadrature_tolerance = v;
  }
  return o;
}

ProfileSpec parse_profile_flag(const Args& a) {
  return a.flags.count("profile") ? parse_profile(a.flags.at("profile")) : ProfileSpec{};
}

// Output formats of mu, psi, sweep and physical: their plain text, CSV (RFC 4180: a field with a
// comma, a quote or a line break is quoted by libcsv) or JSON (nlohmann; values as decimal strings,
// which keep every digit). One record is a JSON object, several are an array of objects.
enum class Format { text, csv, json };

Format parse_format(const Args& a) {
  if (!a.flags.count("format")) return Format::text;
  const std::string& f = a.flags.at("format");
  if (f == "text") return Format::text;
  if (f == "csv") return Format::csv;
  if (f == "json") return Format::json;
  throw InputError("--format '" + detail::visible(f) + "': expected text, csv or json");
}

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
WaveSpec read_wave(const Args& a) {
  WaveReadOptions options;
  options.column_name = "--column";
  if (a.flags.count("column")) options.column = a.flags.at("column");
  WaveSpec wave = parse_wave(need(a, "wave"), options);
  if (switch_on(a, "diagnostics"))
    for (const auto& [name, value] : describe_normalisation(wave, 17))
      pending_diagnostics += "normalisation: " + name + " = " + value + "\n";
  return wave;
}

int run_mu_psi(const Args& a, Quantity q) {
  const WaveSpec wave = read_wave(a);
  Point p{need(a, "beta"), q == Quantity::mu ? need(a, "gamma") : std::string()};
  check_decimal(p.beta, "--beta");
  if (q == Quantity::mu) check_decimal(p.gamma, "--gamma");
  BatchOptions opt;
  opt.profile = parse_profile_flag(a);
  if (q == Quantity::psi && opt.profile.kind != ProfileKind::flat)
    throw InputError("psi --profile " + detail::visible(a.flags.at("profile")) +
                     ": Psi (Eq. 12) exists for the flat punch only; in a curved contact the outer springs always jump, "
                     "so Eq. 13's separation does not exist (use mu)");
  opt.escalate = !switch_on(a, "no-escalate");
  opt.solver = parse_solver_options(a);
  const Format format = parse_format(a);
  const std::string value = evaluate(wave, q, {p}, parse_precision(a), opt).front();
  if (format == Format::text) {
    std::cout << value << '\n';
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
  if (format == Format::csv) {
    write_csv_row(names);
    write_csv_row(values);
  } else {
    std::cout << json_record(names, values).dump(1) << '\n';
  }
  return 0;
}

int run_sweep(const Args& a) {
  const WaveSpec wave = read_wave(a);
  const auto betas = value_range(need(a, "beta"), "--beta", false);
  // --quantity psi: Ψ_w(β) (Eq. 12), which has no γ.
  const std::string quantity = a.flags.count("quantity") ? a.flags.at("quantity") : "mu";
  if (quantity != "mu" && quantity != "psi") throw InputError("--quantity '" + detail::visible(quantity) + "': expected mu or psi");
  const Quantity q = quantity == "psi" ? Quantity::psi : Quantity::mu;
  std::vector<std::string> gammas;
  if (q == Quantity::psi) {
    if (a.flags.count("gamma")) throw InputError("--gamma does not apply to --quantity psi: Psi_w(beta) has no gamma (Eq. 12)");
    gammas.push_back("");
  } else {
    const std::string& gs = need(a, "gamma");
    gammas = gs.find(':') != std::string::npos ? value_range(gs, "--gamma", true) : split(gs, ',');
    for (const auto& g : gammas) check_decimal(g, "--gamma value");
  }
  const Precision prec = parse_precision(a);
  const Format format = a.flags.count("format") ? parse_format(a) : Format::csv;
  if (format == Format::text) throw InputError("--format text: sweep writes csv (the default) or json");
  // Points made on demand, γ-major as the rows (a 3000 × 3000 map holds no vector of points).
  const std::size_t count = betas.size() * gammas.size();
  const auto point = [&](std::size_t i) { return Point{betas[i % betas.size()], gammas[i / betas.size()]}; };
  BatchOptions opt;
  opt.profile = parse_profile_flag(a);
  opt.escalate = !switch_on(a, "no-escalate");
  opt.solver = parse_solver_options(a);
  opt.threads = a.flags.count("threads") ? static_cast<unsigned>(parse_int(a.flags.at("threads"), "--threads", 0, 1024)) : 0;
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
  names.push_back(q == Quantity::mu ? "mu_over_mu0" : "psi");
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
  evaluate_stream(wave, q, count, point, prec, opt, [&](std::size_t i, const std::string& value) {
    const Point pt = point(i);
    std::vector<std::string> r{wave.name};
    if (curved) r.push_back(opt.profile.name);
    r.push_back(pt.beta);
    if (q == Quantity::mu) r.push_back(pt.gamma);
    r.push_back(value);
    if (format == Format::json)
      std::cout << (i ? ",\n " : "\n ") << json_record(names, r).dump();
    else
      write_csv_row(r);
  });
  if (format == Format::json) std::cout << (count ? "\n]\n" : "]\n");
  return 0;
}

// `physical`'s inputs as typed, each named by its flag (the input u_mean is --u-mean), and its controls.
PhysicalOutputs physical_record(const Args& a, const WaveSpec& wave) {
  BatchOptions options;
  options.escalate = !switch_on(a, "no-escalate");
  options.solver = parse_solver_options(a);
  PhysicalRequest request;
  for (auto& [member, input] : request.inputs()) {
    std::string flag = member;
    std::replace(flag.begin(), flag.end(), '_', '-');
    input->name = "--" + flag;
    if (a.flags.count(flag)) input->text = a.flags.at(flag);
  }
  return physical_point(wave, request, parse_precision(a), options);
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
int run_physical(const Args& a) {
  const WaveSpec wave = read_wave(a);
  std::string swept;
  for (const char* name : {"v0", "A", "f", "F-N", "u-mean"})
    if (a.flags.count(name) && a.flags.at(name).find(':') != std::string::npos) {
      if (!swept.empty())
        throw InputError("--" + swept + " and --" + name + " are both ranges: expected one swept input at a time");
      swept = name;
    }
  if (swept.empty()) {
    const Format format = parse_format(a);
    const PhysicalOutputs rec = physical_record(a, wave);
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
  const Format format = a.flags.count("format") ? parse_format(a) : Format::csv;
  if (format == Format::text) throw InputError("--format text: a physical sweep writes csv (the default) or json");
  // A range of u_mean may start below contact (gamma < -1 for the sine): such rows are errors, as at one point.
  const auto range = value_range(a.flags.at(swept), "--" + swept, swept == "u-mean");
  // Every input's domain is monotone along a range: its two ends decide it before the first row.
  Args point = a;
  auto at = [&](std::size_t i) {
    point.flags[swept] = range[i];
    return physical_record(point, wave);
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
int run_trace(const Args& a) {
  const WaveSpec wave = read_wave(a);
  TraceRequest request;
  request.beta = {need(a, "beta"), "--beta"};
  request.gamma = {need(a, "gamma"), "--gamma"};
  request.points_name = "--points";
  request.digits_name = "--digits";
  if (a.flags.count("digits")) request.digits = parse_int(a.flags.at("digits"), "--digits", min_digits, max_digits);
  if (a.flags.count("points"))
    request.points = parse_int(a.flags.at("points"), "--points", min_trace_points, max_trace_points);
  const auto rows = trace_rows(wave, request);
  std::cout << "phi,n,s\n";
  for (const auto& r : rows) std::cout << r[0] << ',' << r[1] << ',' << r[2] << '\n';
  return 0;
}

// A samples file fitted by K harmonics (DFT for uniform phases, least squares for time stamps),
// written as a fourier file that --wave fourier:FILE reads.
int run_fit(const Args& a) {
  const WaveSpec wave = read_wave(a);
  const int harmonics = parse_int(need(a, "harmonics"), "--harmonics", 1, max_fit_harmonics);
  const FourierFit fit = fit_fourier(wave, static_cast<unsigned>(harmonics));
  const std::string text = fourier_file_text(fit, need(a, "wave"));
  if (!a.flags.count("output")) {
    std::cout << text;
    return 0;
  }
  const std::string& path = a.flags.at("output");
  if (std::filesystem::is_directory(path))
    throw InputError("--output '" + detail::visible(path) + "' is a directory: expected a file name");
  std::ofstream out(path);
  if (!(out << text) || !(out.close(), out))
    throw InputError("--output '" + detail::visible(path) + "': cannot write the file");
  std::cerr << "fit: K = " << harmonics << " harmonics (" << fit.method << "), rms residual "
            << fit.rms_residual << ", written to " << path << '\n';
  return 0;
}

int run_version() {
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

int run_verify(const Args& a) {
  const int digits = a.flags.count("digits") ? parse_int(a.flags.at("digits"), "--digits", min_verify_digits, max_verify_digits) : 50;
  if (a.flags.count("format") && a.flags.at("format") != "json" && a.flags.at("format") != "text")
    throw InputError("--format '" + detail::visible(a.flags.at("format")) + "': expected text or json");
  std::vector<ClaimCheck> checks;
  if (a.flags.count("claim"))
    checks.push_back(check_claim(a.flags.at("claim"), digits));
  else
    checks = verify_claims(digits);
  if (a.flags.count("format") && a.flags.at("format") == "json") {
    std::cout << claims_json(checks, digits) << '\n';
    return 0;
  }
  std::printf("%-28s %-8s %-20s %-9s %s\n", "claim", "cases", "verdict", "deviation", "statement");
  for (const auto& c : checks) {
    std::printf("%-28s %-8zu %-20s %-9s %s\n", c.id.c_str(), c.cases, verdict_name(c.verdict).c_str(),
                c.deviation_text.c_str(), c.statement.c_str());
  }
  std::printf("\nrequested precision: %d digits\n", digits);
  for (const auto& c : checks) {
    std::printf("\n%s (%s, %s) — %s\n", c.id.c_str(), c.key.c_str(), c.source.c_str(), verdict_name(c.verdict).c_str());
    std::printf("  method:    %s%s\n", c.method.c_str(), c.proof.empty() ? "" : (" (" + c.proof + ")").c_str());
    std::printf("  checked:   %s\n", c.how.c_str());
    std::printf("  criterion: %s\n", c.criterion.c_str());
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
    const Args a = parse_args(argc, argv);
    if (a.help) return 0;
    int rc = 0;
    if (a.command == "mu")
      rc = run_mu_psi(a, Quantity::mu);
    else if (a.command == "psi")
      rc = run_mu_psi(a, Quantity::psi);
    else if (a.command == "sweep")
      rc = run_sweep(a);
    else if (a.command == "physical")
      rc = run_physical(a);
    else if (a.command == "trace")
      rc = run_trace(a);
    else if (a.command == "fit")
      rc = run_fit(a);
    else if (a.command == "version")
      rc = run_version();
    else
      rc = run_verify(a);
    std::cerr << pending_diagnostics;
    return rc;
  } catch (const InputError& e) {
    std::cerr << "vibrofric: " << one_line(e.what()) << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "vibrofric: error: " << one_line(e.what()) << '\n';
    return 1;
  }
}
