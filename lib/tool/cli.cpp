// The command line: help texts, the command table, parsing with CLI11 into Flags and run_tool, the
// tool's main (bad input: one line on stderr, exit 2; solver failure: 1).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli.hpp"
#include "vibrofric/verification/claims.hpp"

namespace vibrofric::tool {
namespace {

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
    "  between; or columns under a header, one named 'time', 't', 'timestamp', 'Zeit', 'temps',\n"
    "  'tiempo' or 'tempo' (any case, a unit allowed: 'time [s]', 'time_s', 't/s') or with a unit\n"
    "  of time ('Messzeit [s]') giving the time stamps (the last line repeats the first value one\n"
    "  period later); --column picks the value column. Fields: ',' / ';' where a line has them\n"
    "  (between ';' a decimal comma is a point), else tabs, else spaces; '#' starts a comment;\n"
    "  UTF-8 or Windows-1252; --skip-rows N skips a preamble (README,\n"
    "  \"File formats\"). User waves are normalised to zero mean and max - min = 2\n"
    "  (--diagnostics shows how).\n";

const char* const kRig =
    "tangential (in-plane) rig dynamics (model.md): --kappa K --omega W [--zeta Z] replace the\n"
    "  paper's quasi-static spring by a body of mass m on a system spring k_s (damper c), moving along\n"
    "  the sliding direction; the normal indentation follows the wave as prescribed (no normal\n"
    "  dynamics): K = k_s/k_x, W = sqrt(k_x/m)/(2 pi f),\n"
    "  Z = c/(2 sqrt(m k_s)); sine, Fourier and piecewise-linear waves. With --profile the body\n"
    "  carries the whole MDR row (k_x: k_x,max = 2 a_max G*, every spring touching; any gamma), the\n"
    "  row solved at n and 2n springs and printed to the digits they agree on. mu prints the\n"
    "  stick, slip and flight fractions (they add to 1; backward_slip_fraction is the part of the\n"
    "  slip that goes backward), the body's amplitude, the largest backward slip and the largest\n"
    "  Floquet multiplier (0: below what difference quotients resolve) after the value.\n";

const char* const kInPlane =
    "in-plane oscillation (model.md): --longitudinal A [--transverse B] [--phase P] [--in-plane-wave W]\n"
    "  move the spring's far end along D = (beta phi + A w_p(phi + P), B w_p(phi + P)) while the normal\n"
    "  indentation oscillates (--wave constant: a constant normal force, no --gamma; A, B in units of\n"
    "  mu0 F_N/k_x); beta >= 0. mu prints mean_lateral (the force across the sliding direction)\n"
    "  and the stick, slip and flight fractions after the value; a negative mu means the\n"
    "  oscillation pushes the body forward. --profile P (mu, sweep; with the normal oscillation):\n"
    "  the MDR row, each spring driven alike; then no fractions (each spring has its own).\n";

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
    "In-plane oscillation (model.md): --u-x and --u-y give a_l = G* u_x/(mu0 E* A), a_t likewise\n"
    "(printed as longitudinal and transverse); mu is then the in-plane model's, and F_y_mean_N and\n"
    "its stick, slip and flight fractions (flat punch) are printed. --wave constant (flat punch, no\n"
    "--A, --u-mean) is a constant normal load --F-N: beta = k_x v0/(mu0 F_N f), a = k_x u/(mu0 F_N).\n"
    "shapes S and their GEOMETRY (metres, degrees):\n"
    "  flat (default) --radius a          flat-ended cylinder: k_z = 2 E* a, k_x = 2 G* a (Eq. 1)\n"
    "  sphere --R R                       MDR (model.md), sigma = x^2/(R A)\n"
    "  cone --half-angle THETA            angle between axis and flank, in degrees\n"
    "  wearflat --R R --flat-radius b     sphere with a wear flat, lambda = b^2/(R A)\n"
    "  profile:FILE                       measured profile, lines 'r f' in metres, f(0) = 0\n";

}  // namespace

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> specs{
      {"mu", "mu --wave W --beta B --gamma G [--profile P]: mu/mu0 = g_w(beta, gamma) (Eq. 15)",
       {{"beta", "B", "beta (Eq. 5), a decimal > 0 (required)", "", decimal_beta},
        {"gamma", "G", "gamma = u_mean/A (Eq. 14), a decimal with contact, gamma > -max w (required)", "",
         [](Flags& f, const std::string& t) { f.gamma = InputValue::read(t, "--gamma"); }},
        {"profile", "P", "the indenter (model.md MDR)", "flat", profile_named},
        {"format", "F", "text | csv | json", "text", format_of_point},
        kCertifyFlag,
        {"free-velocity", "", "with --longitudinal and a contact lost once a period: also search the ratchet's free "
                              "velocity with --transverse or a curved --profile (about 30 solves: seconds to minutes; "
                              "the flat punch's longitudinal drive prints it unasked) (=true/false/yes/no/1/0)", "",
         [](Flags& f, const std::string& t) { f.free_velocity = switch_value(t, "free-velocity"); }}},
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags, &kRigFlags, &kInPlaneFlags},
       std::string(kWaves) + kProfiles + kRig + kInPlane,
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
         [](Flags& f, const std::string& t) { f.betas = read_all(value_range(t, "--beta", false), "--beta"); }},
        {"gamma", "G", "a list G1,G2,... or a range FROM:TO:N (FROM > TO allowed); not with --quantity psi", "",
         [](Flags& f, const std::string& t) {
           f.gammas = read_all(t.find(':') != std::string::npos ? value_range(t, "--gamma", true) : split(t, ','), "--gamma value");
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
       {&kWaveFlags, &kPrecisionFlags, &kSolverFlags, &kRigFlags, &kInPlaneFlags},
       std::string(kWaves) + kProfiles + kRig + kInPlane,
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
        {"mass", "KG", "tangential (in-plane) rig dynamics: the body's mass, > 0 (with --k-system)", "", nullptr},
        {"k-system", "N/M", "rig dynamics: the apparatus' stiffness between drive and body, > 0 (with --mass)", "", nullptr},
        {"damping", "NS/M", "rig dynamics: a damper parallel to the apparatus' spring, >= 0", "0", nullptr},
        {"u-x", "M", "in-plane oscillation along the sliding direction: zero-to-peak amplitude, >= 0", "none", nullptr},
        {"u-y", "M", "in-plane oscillation across the sliding direction: zero-to-peak amplitude, >= 0", "none", nullptr},
        {"phase", "P", "lag of the in-plane oscillation behind the normal one, in periods (with --u-x or --u-y)", "0", nullptr},
        {"in-plane-wave", "W", "the in-plane oscillation's wave: a catalogue wave (with --u-x or --u-y)", "sine", nullptr},
        {"radius", "M", "flat: punch radius (required for flat)", "", nullptr},
        {"R", "M", "sphere, wearflat: radius of curvature", "", nullptr},
        {"half-angle", "DEG", "cone: angle between axis and flank, in (0, 90)", "", nullptr},
        {"flat-radius", "M", "wearflat: radius of the wear flat", "", nullptr},
        {"format", "F", "text | csv | json (a sweep: csv | json)", "text (a sweep: csv)", format_of_point},
        {"trace", "", "one period in SI instead: CSV t_s,F_N_N,F_x_N,u_m (u_m: the tip's indentation, < 0 off the surface); with --mass also "
         "x_m,F_s_N (the body's position, the drive at v0 t; the holder's force on the body)", "",
         [](Flags& f, const std::string& t) { f.trace = switch_value(t, "trace"); }},
        {"points", "N", "with --trace: N + 1 equally spaced times (0 and 1/f both), N from 2 to 1000000, plus every stick "
                        "phase's ends and the contact boundaries", "1000",
         [](Flags& f, const std::string& t) { f.points = integer(t, "--points", min_trace_points, max_trace_points); }}},
       {&kWaveFlags, &kPhysicalPrecisionFlags, &kSolverFlags},
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
       {&kWaveFlags, &kRigFlags, &kInPlaneFlags},
       std::string(kWaves) + kRig + kInPlane +
           "  trace with --longitudinal or --transverse prints phi,n,s_x,s_y,mode: the tangential force\n"
           "  along and across the sliding direction (s_y = 0 for a longitudinal drive) and the mode.\n" +
           "  trace with them prints phi,n,s,lag,lag_rate,mode: the body's lag Y = X - beta phi behind the\n"
           "  drive and Y' (units mu0 k_z A/k_x), the mode (stick, slip, backward, flight), at the phases\n"
           "  and both ends of every span (two rows at one phi where a mode ends: left and right values).\n" +
           "  With --profile too (the rig on the MDR row): phi,n,s,lag,lag_rate,stick,slip,backward,flight,\n"
           "  n and s summed over the half-row, the lag in units mu0 E* A/G*, and the row's shares in each\n"
           "  mode, at the phases and where the body lands and lifts off; each number to the digits the\n"
           "  row's two sizes agree on.\n",
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

namespace {

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
        read_physical(flags, name, text);
    });
    options[f.name] = o;
  };
  for (const auto& f : spec->flags) add(f, "Options");
  for (const auto* g : spec->groups)
    for (const auto& f : *g) add(f, g == &kWaveFlags ? "Wave" : g == &kPrecisionFlags || g == &kPhysicalPrecisionFlags ? "Precision" : "Solver controls");
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

int run_tool(int argc, char** argv) {
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

}  // namespace vibrofric::tool
