// vibrofric: the command-line tool. μ̄/μ0 (Eq. 15), Ψ_w (Eq. 12), sweeps, physical inputs
// (Eqs. 1, 5, 14) and the claims check. Bad input: one line on stderr, exit 2; solver failure: 1.
#include <unistd.h>

#include <boost/math/tools/roots.hpp>
#include <boost/version.hpp>
#include <csv.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "vibrofric/catalogue.hpp"
#include "vibrofric/claims.hpp"
#include "vibrofric/curved.hpp"
#include "vibrofric/detail/evaluate_impl.hpp"
#include "vibrofric/evaluate.hpp"
#include "vibrofric/physical.hpp"
#include "vibrofric/profile.hpp"

namespace {

using namespace vibrofric;

const char* const kUsage =
    "usage: vibrofric COMMAND [OPTIONS]\n"
    "\n"
    "Sliding friction under normal oscillation (M. Popov, large amplitudes): the macroscopic\n"
    "coefficient of friction mu/mu0 = g_w(beta, gamma) and the reduction function Psi_w(beta).\n"
    "\n"
    "commands:\n"
    "  mu        mu/mu0 at one point:        --wave W --beta B --gamma G [--profile P]\n"
    "  psi       Psi_w(beta), non-jumping:   --wave W --beta B\n"
    "  sweep     CSV over beta and gamma:    --wave W --beta FROM:TO:N --gamma G1,G2,... [--profile P]\n"
    "            ranges FROM:TO:N (linear, ends included) or log:FROM:TO:N (geometric); --gamma also\n"
    "            as a range (FROM > TO allowed); --quantity psi: Psi_w(beta) over beta, no --gamma\n"
    "  physical  from physical inputs (SI):  see 'vibrofric physical --help'\n"
    "  verify    decide every claim of the paper (model.md's list: Eqs. 6-24, Secs. 3-3.2, Figs. 2-4),\n"
    "            then model.md's own (beta_c table, curved contacts), at --digits D (10 to 300,\n"
    "            default 50; the same verdicts over the range); --claim KEY for one (e.g. eq24);\n"
    "            --format json for the report generator\n"
    "  trace     CSV phi,n,s over one period (Fig. 2): --wave W --beta B --gamma G [--points N]\n"
    "            (default 1000, plus the ends of every stick phase and the contact boundaries,\n"
    "            where n = 0 exactly; --digits D, default 17)\n"
    "  version   versions of vibrofric, the compiler, Boost, MPFR and GMP\n"
    "\n"
    "precision (mu, psi, sweep, physical):\n"
    "  --digits D   significant digits, 1 to 10000 (default 50), mpfr with guard digits\n"
    "  --type T     double | long-double | cpp_bin_float_50 | cpp_bin_float_100 | mpfr\n"
    "  --format F   mu, psi, physical: text (default), csv or json; sweep: csv (default) or json\n"
    "  --no-escalate    fixed types: print the value computed in the type even where its\n"
    "               rounding bound exceeds the type's epsilon (default: recompute with mpfr)\n"
    "\n"
    "profiles P (mu, sweep; model.md MDR): flat (default: the flat punch), sphere, cone, power:N\n"
    "  (N >= 1, sigma = x^N), wearflat:LAMBDA (sphere with a wear flat, LAMBDA = b^2/(R A) > 0),\n"
    "  profile:FILE (lines 'r f', f(0) = 0, f non-decreasing, heights in units of the amplitude A).\n"
    "  psi is flat-punch only: the outer springs of a curved contact always jump.\n"
    "\n"
    "waves W: sine (harmonic), triangle (tri), sawtooth-right (str), sawtooth-left (stl),\n"
    "  square (sqr), power:P (P >= 1), fourier:FILE, samples:FILE\n"
    "  fourier FILE: lines 'k a_k b_k' for w = sum a_k cos(2 pi k phi) + b_k sin(2 pi k phi)\n"
    "  samples FILE: one period of values y_j at phi = j/N (one column, or one line), linear\n"
    "  between; or two columns under a header naming one 'time' ('time,value'), the last line\n"
    "  repeating the first value one period later. Fields: whitespace, or ',' / ';' where a\n"
    "  line has them; '#' starts a comment (README, \"File formats\"). User waves are\n"
    "  normalised to zero mean and max - min = 2.\n"
    "\n"
    "solver controls (mu, psi, sweep):\n"
    "  --area auto|exact|quadrature  areas from antiderivatives (auto: where the wave has one) or\n"
    "               tanh-sinh with every event a breakpoint\n"
    "  --max-iterations N  root-finder budget per event (default 200 + working bits)\n"
    "  --max-levels N      tanh-sinh halvings, 4 to 30 (default 15); --quadrature-tolerance T\n"
    "               (default sqrt(eps) of the working precision)\n"
    "  A budget the solver cannot meet is an error (exit 1), never a value.\n"
    "\n"
    "exit status: 0 success, 1 solver failure, 2 bad input.\n";

const char* const kPhysicalUsage =
    "usage: vibrofric physical --wave W --E1 PA --nu1 NU --E2 PA --nu2 NU [--G1 PA --G2 PA]\n"
    "                          --v0 M/S --f HZ --A M (--u-mean M | --F-N N) --mu0 MU\n"
    "                          [--shape S GEOMETRY] [--digits D | --type T]\n"
    "\n"
    "1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 and 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) (Eq. 1);\n"
    "G defaults to E/(2(1 + nu)), -1 < nu <= 0.5. beta = G* v0/(mu0 E* A f) (Eq. 5), gamma = u_mean/A\n"
    "(Eq. 14); A is the zero-to-peak amplitude, u_mean the mean indentation of the indenter's tip.\n"
    "--F-N N sets the mean normal load instead of u_mean: gamma is solved from <F_N>(gamma) = N\n"
    "(<F_N> rises strictly with gamma) and u_mean_m is printed after gamma.\n"
    "Also printed: beta_c (Eq. 6, of the clipped n; curved: the central spring's) and, for the\n"
    "flat punch, the fractions of the period in contact and in stick.\n"
    "shapes S and their GEOMETRY (metres, degrees):\n"
    "  flat (default) --radius a          flat-ended cylinder: k_z = 2 E* a, k_x = 2 G* a (Eq. 1)\n"
    "  sphere --R R                       MDR (model.md), sigma = x^2/(R A)\n"
    "  cone --half-angle THETA            angle between axis and flank, in degrees\n"
    "  wearflat --R R --flat-radius b     sphere with a wear flat, lambda = b^2/(R A)\n"
    "  profile:FILE                       measured profile, lines 'r f' in metres, f(0) = 0\n"
    "Prints one 'name = value' a line: shape, E*, G*, k_z and k_x (flat) or the largest contact\n"
    "radius (curved), lambda (wearflat), beta, gamma, mu/mu0, mu, and the mean normal and friction\n"
    "forces <F_N>, <F_x> in newtons.\n";

struct Args {
  std::string command;
  std::map<std::string, std::string> flags;
  bool help = false;
};

// Flags that take no value (--no-escalate), or a validated one (--no-escalate=false).
bool is_switch(const std::string& name) { return name == "no-escalate"; }

// A switch's state: absent is off; present alone, or =1/true/yes, on; =0/false/no, off; else bad input.
bool switch_on(const Args& a, const std::string& name) {
  const auto it = a.flags.find(name);
  if (it == a.flags.end()) return false;
  const std::string& v = it->second;
  if (v == "1" || v == "true" || v == "yes") return true;
  if (v == "0" || v == "false" || v == "no") return false;
  throw InputError("--" + name + " = '" + v + "': expected no value, or one of true, false, yes, no, 1, 0");
}

// --name value, --name=value; values may start with '-' (negative numbers).
Args parse_args(int argc, char** argv, const std::map<std::string, std::set<std::string>>& allowed) {
  Args a;
  if (argc < 2) throw InputError("missing command: expected mu, psi, sweep, physical, verify, trace or version (see --help)");
  a.command = argv[1];
  if (a.command == "--help" || a.command == "-h" || a.command == "help") {
    a.help = true;
    a.command.clear();
    return a;
  }
  const auto it = allowed.find(a.command);
  if (it == allowed.end())
    throw InputError("unknown command '" + a.command + "': expected mu, psi, sweep, physical, verify, trace or version");
  for (int i = 2; i < argc; ++i) {
    std::string tok = argv[i];
    if (tok == "--help" || tok == "-h") {
      a.help = true;
      continue;
    }
    if (tok.rfind("--", 0) != 0) throw InputError("unexpected argument '" + tok + "': expected --flag value");
    std::string name = tok.substr(2), value;
    bool has_value = false;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      has_value = true;
    }
    if (!it->second.count(name)) throw InputError("unknown flag --" + name + " for '" + a.command + "'");
    if (!has_value && is_switch(name)) {
      value = "true";  // a switch takes no value; --name=VALUE is checked by switch_on
      has_value = true;
    }
    if (!has_value) {
      if (i + 1 >= argc) throw InputError("flag --" + name + " needs a value");
      value = argv[++i];
    }
    if (a.flags.count(name)) throw InputError("flag --" + name + " given twice");
    a.flags[name] = value;
  }
  return a;
}

const std::string& need(const Args& a, const std::string& name) {
  const auto it = a.flags.find(name);
  if (it == a.flags.end()) throw InputError("missing --" + name + " for '" + a.command + "'");
  return it->second;
}

int parse_int(const std::string& text, const std::string& what, long lo, long hi) {
  if (!std::regex_match(text, std::regex("[+-]?[0-9]{1,9}")))
    throw InputError(what + " = '" + text + "': expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  const long v = std::stol(text);
  if (v < lo || v > hi)
    throw InputError(what + " = " + text + ": expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  return static_cast<int>(v);
}

Precision parse_precision(const Args& a) {
  Precision p;
  const bool has_digits = a.flags.count("digits"), has_type = a.flags.count("type");
  if (has_type) p.type = parse_number_type(a.flags.at("type"));
  if (has_digits) {
    if (has_type && p.type != NumberType::mpfr)
      throw InputError("--digits goes with mpfr only: --type " + a.flags.at("type") + " has fixed precision");
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
  if (parts.size() != 3) throw InputError(flag + " '" + spec + "': expected FROM:TO:N or log:FROM:TO:N");
  check_decimal(parts[0], flag + " FROM");
  check_decimal(parts[1], flag + " TO");
  const int n = parse_int(parts[2], flag + " N", 1, 1000000);
  PrecisionScope scope(40);
  const mpfr from(parts[0]), to(parts[1]);
  if (!descending && to < from) throw InputError(flag + " '" + spec + "': empty range, expected FROM <= TO");
  if (n > 1 && from == to) throw InputError(flag + " '" + spec + "': empty range for N > 1, expected FROM != TO");
  if (log && !(from > 0 && to > 0))
    throw InputError(flag + " '" + spec + "': a log range needs FROM > 0 and TO > 0");
  std::vector<std::string> out;
  for (int i = 0; i < n; ++i) {
    const mpfr t = n == 1 ? mpfr(0) : mpfr(mpfr(i) / (n - 1));
    const mpfr v = i == n - 1 ? to : log ? mpfr(from * pow(to / from, t)) : mpfr(from + (to - from) * t);
    std::string str = format_significant(i == 0 ? from : v, 17);
    if (str.find('.') != std::string::npos && str.find('e') == std::string::npos) {
      while (str.back() == '0') str.pop_back();
      if (str.back() == '.') str.pop_back();
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
      throw InputError("--area '" + m + "': expected auto, exact or quadrature");
  }
  if (a.flags.count("max-iterations"))
    o.max_root_iterations = static_cast<std::uintmax_t>(parse_int(a.flags.at("max-iterations"), "--max-iterations", 1, 100000));
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
  throw InputError("--format '" + f + "': expected text, csv or json");
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

int run_mu_psi(const Args& a, Quantity q) {
  const WaveSpec wave = parse_wave(need(a, "wave"));
  Point p{need(a, "beta"), q == Quantity::mu ? need(a, "gamma") : std::string()};
  check_decimal(p.beta, "--beta");
  if (q == Quantity::mu) check_decimal(p.gamma, "--gamma");
  BatchOptions opt;
  opt.profile = parse_profile_flag(a);
  if (q == Quantity::psi && opt.profile.kind != ProfileKind::flat)
    throw InputError("psi --profile " + a.flags.at("profile") +
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
  const WaveSpec wave = parse_wave(need(a, "wave"));
  const auto betas = value_range(need(a, "beta"), "--beta", false);
  // --quantity psi: Ψ_w(β) (Eq. 12), which has no γ.
  const std::string quantity = a.flags.count("quantity") ? a.flags.at("quantity") : "mu";
  if (quantity != "mu" && quantity != "psi") throw InputError("--quantity '" + quantity + "': expected mu or psi");
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
  std::vector<Point> points;
  for (const auto& g : gammas)
    for (const auto& b : betas) points.push_back({b, g});
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
      const bool last = done == points.size();
      if (!last && now < next_draw_ns.load(std::memory_order_relaxed)) return;
      std::lock_guard<std::mutex> lock(m);
      if (done <= shown || (!last && now < next_draw_ns.load(std::memory_order_relaxed))) return;
      next_draw_ns.store(now + 100'000'000, std::memory_order_relaxed);
      shown = done;
      const double seconds = static_cast<double>(now) / 1e9;
      const double left = seconds * static_cast<double>(points.size() - done) / static_cast<double>(done);
      std::fprintf(stderr, "\rsweep: %zu/%zu (%.1f %%), %.0f s left   ", done, points.size(),
                   100.0 * static_cast<double>(done) / static_cast<double>(points.size()), left);
      if (last) std::fprintf(stderr, "\n");
    };
  const auto values = evaluate(wave, q, points, prec, opt);
  const bool curved = opt.profile.kind != ProfileKind::flat;
  std::vector<std::string> names{"wave"};
  if (curved) names.push_back("profile");
  names.push_back("beta");
  if (q == Quantity::mu) names.push_back("gamma");
  names.push_back(q == Quantity::mu ? "mu_over_mu0" : "psi");
  auto record = [&](std::size_t i) {
    std::vector<std::string> r{wave.name};
    if (curved) r.push_back(opt.profile.name);
    r.push_back(points[i].beta);
    if (q == Quantity::mu) r.push_back(points[i].gamma);
    r.push_back(values[i]);
    return r;
  };
  if (format == Format::json) {
    std::cout << "[";
    for (std::size_t i = 0; i < points.size(); ++i) std::cout << (i ? ",\n " : "\n ") << json_record(names, record(i)).dump();
    std::cout << "\n]\n";
  } else {
    write_csv_row(names);
    for (std::size_t i = 0; i < points.size(); ++i) write_csv_row(record(i));
  }
  return 0;
}

int run_physical(const Args& a) {
  const WaveSpec wave = parse_wave(need(a, "wave"));
  const Precision prec = parse_precision(a);
  const Format format = parse_format(a);
  const int digits = output_digits(prec);
  PrecisionScope scope(static_cast<unsigned>(digits + 20));
  auto get = [&](const char* name) { return parse_real<mpfr>(need(a, name), std::string("--") + name); };
  auto opt = [&](const char* name) {
    return a.flags.count(name) ? parse_real<mpfr>(a.flags.at(name), std::string("--") + name) : mpfr(0);
  };
  auto positive = [&](const char* name) {
    const mpfr v = get(name);
    if (!(v > 0)) throw InputError(std::string("--") + name + " = " + a.flags.at(name) + ": expected a value > 0");
    return v;
  };
  // The indenter (model.md MDR): which geometry flags it takes, its profile and length unit L.
  const std::string shape = a.flags.count("shape") ? a.flags.at("shape") : "flat";
  const std::map<std::string, std::set<std::string>> geometry{
      {"flat", {"radius"}}, {"sphere", {"R"}}, {"cone", {"half-angle"}}, {"wearflat", {"R", "flat-radius"}}, {"profile", {}}};
  const std::string kind = shape.rfind("profile:", 0) == 0 ? "profile" : shape;
  if (!geometry.count(kind))
    throw InputError("--shape '" + shape + "': expected flat, sphere, cone, wearflat or profile:FILE");
  for (const char* g : {"radius", "R", "half-angle", "flat-radius"})
    if (a.flags.count(g) && !geometry.at(kind).count(g))
      throw InputError(std::string("--") + g + " does not apply to --shape " + shape);
  const mpfr A = positive("A");
  // The mean indentation, or the mean normal load an experimenter sets (then γ solves ⟨F_N⟩(γ) = F_N).
  const bool by_load = a.flags.count("F-N") > 0;
  if (by_load && a.flags.count("u-mean")) throw InputError("--u-mean and --F-N both given: expected one of them");
  if (!by_load && !a.flags.count("u-mean")) throw InputError("missing --u-mean (mean indentation) or --F-N (mean normal load) for 'physical'");
  // Checked here with the values as typed (physical_groups checks them again, for library users).
  auto poisson = [&](const char* name) {
    const mpfr v = get(name);
    if (!(v > -1 && v <= mpfr("0.5")))
      throw InputError(std::string("--") + name + " = " + a.flags.at(name) + ": expected -1 < nu <= 0.5");
    return v;
  };
  PhysicalInput<mpfr> in{positive("E1"), poisson("nu1"), positive("E2"), poisson("nu2"), opt("G1"), opt("G2"),
                         kind == "flat" ? positive("radius") : mpfr(0), positive("v0"), positive("f"), A,
                         by_load ? mpfr(0) : get("u-mean"), positive("mu0")};
  if (a.flags.count("G1") && !(in.G1 > 0)) throw InputError("--G1 = " + a.flags.at("G1") + ": expected a value > 0");
  if (a.flags.count("G2") && !(in.G2 > 0)) throw InputError("--G2 = " + a.flags.at("G2") + ": expected a value > 0");
  auto g = physical_groups(in);
  BatchOptions options;
  mpfr length = 1;
  std::string lambda;
  if (kind == "sphere") {
    options.profile = parse_profile("sphere");
    length = sphere_length(positive("R"), A);
  } else if (kind == "cone") {
    const mpfr theta = positive("half-angle");
    if (!(theta < 90)) throw InputError("--half-angle = " + a.flags.at("half-angle") + ": expected degrees in (0, 90)");
    options.profile = parse_profile("cone");
    length = cone_length(theta, A);
  } else if (kind == "wearflat") {
    const mpfr R = positive("R"), b = positive("flat-radius");
    lambda = format_significant(mpfr(b * b / (R * A)), digits + 15);
    options.profile = parse_profile("wearflat:" + lambda);
    length = b;
  } else if (kind == "profile") {
    options.profile = parse_profile(shape);
    options.profile.height_unit = a.flags.at("A");  // heights in metres, the library's in units of A
  }
  options.escalate = !switch_on(a, "no-escalate");
  options.solver = parse_solver_options(a);
  // ⟨F_N⟩(γ) = 2 E* A L ∫N dx (punch: k_z A N_w(γ)), at the working precision of this scope: N does
  // not depend on β. Also the largest contact radius (curved) in units of L.
  const auto w = make_waveform<mpfr>(wave);
  const auto p = kind == "flat" ? nullptr : make_profile<mpfr>(options.profile);
  auto load = [&](const mpfr& gam, mpfr* edge_out) {
    if (!(gam + w->maximum() > 0)) return mpfr(0);  // no contact, no load
    mpfr normal;
    if (kind == "flat") {
      normal = solve(*w, g.beta, gam, options.solver).normal_area;
    } else {
      const auto r = solve_curved(*w, *p, g.beta, gam, options.solver, mpfr(pow(mpfr(10), -digits - 5)));
      normal = r.normal_integral;
      if (edge_out) *edge_out = r.contact_radius;
    }
    return kind == "flat" ? mpfr(g.k_z * A * normal) : mpfr(2 * g.E_star * A * length * normal);
  };
  if (by_load) {
    const mpfr F_N = positive("F-N");
    // ⟨F_N⟩ rises strictly with γ from 0 at γ = −max w: bracket by doubling, then TOMS 748.
    mpfr lo = -w->maximum(), hi = lo + 1;
    for (int k = 0; load(hi, nullptr) < F_N; ++k) {
      if (k == 200) throw InputError("--F-N = " + a.flags.at("F-N") + ": expected a load the contact can carry");
      lo = hi;
      hi = lo + pow(mpfr(2), k + 1);
    }
    std::uintmax_t iterations = 400;
    const auto bracket = boost::math::tools::toms748_solve(
        [&](const mpfr& gam) { return mpfr(load(gam, nullptr) - F_N); }, lo, hi,
        boost::math::tools::eps_tolerance<mpfr>(std::numeric_limits<mpfr>::digits - 10), iterations);
    if (iterations >= 400) throw SolverError("--F-N = " + a.flags.at("F-N") + ": the mean indentation did not converge");
    g.gamma = (bracket.first + bracket.second) / 2;
  }
  const std::string beta = format_significant(g.beta, digits + 15), gamma = format_significant(g.gamma, digits + 15);
  // μ = μ0·(μ̄/μ0) from the ratio at 10 more digits, then rounded once to the requested digits.
  Precision fine = prec;
  if (fine.type == NumberType::mpfr) fine.digits = std::min(prec.digits + 10, max_digits);
  const std::string ratio_fine = evaluate(wave, Quantity::mu, {{beta, gamma}}, fine, options).front();
  const std::string mu_ratio = fine.type == NumberType::mpfr ? format_significant(mpfr(ratio_fine), digits) : ratio_fine;
  const mpfr mu = mpfr(ratio_fine) * in.mu0;
  mpfr edge;
  const mpfr force = load(mpfr(gamma), &edge);
  // β_c (Eq. 6, of the clipped n; a curved contact's is its central spring's) and, for the punch,
  // the fractions of the period in contact and in stick.
  mpfr beta_c, contact_fraction, stick_fraction;
  if (kind == "flat") {
    const Contact<mpfr> c = make_contact(*w, mpfr(gamma), options.solver);
    const auto r = solve(c, mpfr(beta), options.solver);
    beta_c = r.beta_c;
    for (const auto& seg : c.segments())
      if (seg.contact) contact_fraction += seg.v - seg.u;
    for (const auto& st : r.stick_phases) stick_fraction += st.end - st.begin;
  } else {
    beta_c = make_contact(*w, mpfr(gamma), options.solver).beta_c();
  }
  std::vector<std::string> names, values;
  auto field = [&](const char* name, const std::string& v) {
    names.push_back(name);
    values.push_back(v);
  };
  auto line = [&](const char* name, const mpfr& v) { field(name, format_significant(v, digits)); };
  field("shape", kind == "profile" ? shape : kind);
  line("E_star_Pa", g.E_star);
  line("G_star_Pa", g.G_star);
  if (kind == "flat") {
    line("k_z_N_per_m", g.k_z);
    line("k_x_N_per_m", g.k_x);
  } else {
    line("contact_radius_max_m", mpfr(length * edge));
  }
  if (!lambda.empty()) line("lambda", mpfr(lambda));
  line("beta", g.beta);
  line("gamma", g.gamma);
  if (by_load) line("u_mean_m", mpfr(g.gamma * A));
  field("mu_over_mu0", mu_ratio);
  line("mu", mu);
  line("F_N_mean_N", force);
  line("F_x_mean_N", mpfr(mu * force));
  using std::isfinite;
  if (isfinite(beta_c))
    line("beta_c", beta_c);
  else
    field("beta_c", "inf");  // an upward jump of n: stick at every beta
  if (kind == "flat") {
    line("contact_fraction", contact_fraction);
    line("stick_fraction", stick_fraction);
  }
  if (format == Format::csv) {
    write_csv_row(names);
    write_csv_row(values);
  } else if (format == Format::json) {
    std::cout << json_record(names, values).dump(1) << '\n';
  } else {
    for (std::size_t i = 0; i < names.size(); ++i) std::cout << names[i] << " = " << values[i] << '\n';
  }
  return 0;
}

// s(φ) and n(φ) over one period (the paper's Fig. 2): N equally spaced phases plus both ends of
// every stick phase, so that a plot shows the kinks where they are.
int run_trace(const Args& a) {
  const WaveSpec wave = parse_wave(need(a, "wave"));
  const std::string beta_text = need(a, "beta"), gamma_text = need(a, "gamma");
  check_decimal(beta_text, "--beta");
  check_decimal(gamma_text, "--gamma");
  const int digits = a.flags.count("digits") ? parse_int(a.flags.at("digits"), "--digits", min_digits, max_digits) : 17;
  const int n_points = a.flags.count("points") ? parse_int(a.flags.at("points"), "--points", 2, 1000000) : 1000;
  PrecisionScope scope(static_cast<unsigned>(digits + detail::guard_digits(digits)));
  const auto w = make_waveform<mpfr>(wave);
  const mpfr beta = parse_real<mpfr>(beta_text, "--beta"), gamma = parse_real<mpfr>(gamma_text, "--gamma");
  const Contact<mpfr> contact = make_contact(*w, gamma);
  const auto r = solve(contact, beta);
  // The contact boundaries, where n = 0 by definition (its computed value is a rounding, ~1e-32).
  std::vector<mpfr> edges;
  for (const auto& g : contact.segments())
    if (g.contact) {
      if (g.nu == 0) edges.push_back(g.u);
      if (g.nv == 0) edges.push_back(g.v);
    }
  std::vector<mpfr> phis(edges);
  for (int i = 0; i <= n_points; ++i) phis.push_back(mpfr(i) / n_points);
  for (const auto& st : r.stick_phases)
    for (const mpfr& x : {st.begin, st.end}) phis.push_back(x - floor(x));
  std::sort(phis.begin(), phis.end());
  phis.erase(std::unique(phis.begin(), phis.end()), phis.end());
  std::cout << "phi,n,s\n";
  for (const mpfr& phi : phis) {
    const bool edge = std::find(edges.begin(), edges.end(), phi) != edges.end();
    const mpfr v = edge ? mpfr(0) : mpfr(gamma + (*w)(phi - floor(phi)));
    const mpfr s = edge ? mpfr(0) : tangential_force(*w, r, beta, gamma, phi == 1 ? mpfr(0) : phi);
    std::cout << format_significant(phi, digits) << ',' << format_significant(v > 0 ? v : mpfr(0), digits) << ','
              << format_significant(s, digits) << '\n';
  }
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

// The catalogue's results for the report generator (reports/generate.py). Deviations are decimal
// strings at the working precision (a JSON number would pass through a double and underflow
// beyond 300 digits); null where a claim has no corrected statement.
void print_claims_json(const std::vector<ClaimCheck>& checks, int digits) {
  nlohmann::ordered_json doc;
  doc["digits"] = digits;
  doc["claims"] = nlohmann::json::array();
  for (const auto& c : checks) {
    nlohmann::ordered_json j;
    j["key"] = c.key;
    j["id"] = c.id;
    j["source"] = c.source;
    j["statement"] = c.statement;
    j["method"] = c.method;
    j["how"] = c.how;
    j["criterion"] = c.criterion;
    j["proof"] = c.proof;
    j["worst"] = c.worst;
    j["verdict"] = verdict_name(c.verdict);
    j["scope"] = c.scope;
    j["fails_where"] = c.fails_where;
    j["corrected"] = c.corrected;
    j["cases"] = c.cases;
    j["deviation"] = c.deviation_text;
    j["deviation_unit"] = c.deviation_unit;
    j["corrected_deviation"] = c.corrected_deviation ? nlohmann::json(c.corrected_deviation_text) : nlohmann::json(nullptr);
    j["measured"] = nlohmann::json::array();
    for (const auto& m : c.measured) j["measured"].push_back({m.name, m.value});
    doc["claims"].push_back(std::move(j));
  }
  std::cout << doc.dump(1) << '\n';
}

int run_verify(const Args& a) {
  const int digits = a.flags.count("digits") ? parse_int(a.flags.at("digits"), "--digits", 10, 300) : 50;
  if (a.flags.count("format") && a.flags.at("format") != "json" && a.flags.at("format") != "text")
    throw InputError("--format '" + a.flags.at("format") + "': expected text or json");
  std::vector<ClaimCheck> checks;
  if (a.flags.count("claim"))
    checks.push_back(check_claim(a.flags.at("claim"), digits));
  else
    checks = verify_claims(digits);
  if (a.flags.count("format") && a.flags.at("format") == "json") {
    print_claims_json(checks, digits);
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

}  // namespace

int main(int argc, char** argv) {
  const std::set<std::string> prec{"digits", "type", "no-escalate", "area", "max-iterations", "max-levels",
                                   "quadrature-tolerance"};
  auto with = [&](std::set<std::string> s) {
    s.insert(prec.begin(), prec.end());
    return s;
  };
  const std::map<std::string, std::set<std::string>> allowed{
      {"mu", with({"wave", "beta", "gamma", "profile", "format"})},
      {"psi", with({"wave", "beta", "profile", "format"})},
      {"sweep", with({"wave", "beta", "gamma", "threads", "profile", "quantity", "format"})},
      {"physical", with({"wave", "E1", "nu1", "E2", "nu2", "G1", "G2", "radius", "v0", "f", "A", "u-mean", "F-N", "mu0", "shape",
                         "R", "flat-radius", "half-angle", "format"})},
      {"verify", {"digits", "claim", "format"}},
      {"trace", {"wave", "beta", "gamma", "points", "digits"}},
      {"version", {}},
  };
  try {
    const Args a = parse_args(argc, argv, allowed);
    if (a.help) {
      std::cout << (a.command == "physical" ? kPhysicalUsage : kUsage);
      return 0;
    }
    if (a.command == "mu") return run_mu_psi(a, Quantity::mu);
    if (a.command == "psi") return run_mu_psi(a, Quantity::psi);
    if (a.command == "sweep") return run_sweep(a);
    if (a.command == "physical") return run_physical(a);
    if (a.command == "trace") return run_trace(a);
    if (a.command == "version") return run_version();
    return run_verify(a);
  } catch (const InputError& e) {
    std::cerr << "vibrofric: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "vibrofric: error: " << e.what() << '\n';
    return 1;
  }
}
