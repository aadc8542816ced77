// Fuzz target: the tool's command line, in process (run_tool of lib/tool/cli.hpp, what the tool's
// main() calls): commands, flags, --flag=value forms, numbers, the β range FROM:TO:N, γ lists,
// wave names, precisions and solver controls. The input is split at newlines into argv.
//
// The tool's contract (README "Errors"): exit 0 with output and no NaN/inf (but beta_c and
// p_max_peak_Pa, which may be inf); exit 2 for bad input,
// one line on stderr, nothing on stdout; exit 1 for a solver failure, one line naming what failed,
// nothing on stdout. Exit 1 with a message that is not one of the library's SolverError messages
// (e.g. a std::stold or std::regex what()) is a finding: a non-vibrofric exception escaped.
//
// Cost bound (legitimately slow requests, not bugs, skipped): `verify`; --digits above 200 (60
// with quadrature); more than 40 β points or 8 γ values; --points above 2000; --max-levels above
// 10; --threads above 4; a rig flag (--kappa, --omega, --zeta, --mass, --k-system, --damping) of
// 100 or more, or with --digits above 60 or a samples wave. Wave files: "@F" and "@S" in an argument stand for fourier:FILE and
// samples:FILE of two small files made at start-up; any other file name is skipped (the fuzzer
// must not read /dev/zero or the disk).
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_common.hpp"

namespace vibrofric::tool {
int run_tool(int argc, char** argv);  // lib/tool/cli.hpp
}

namespace {

std::string g_fourier, g_samples;

std::string memfile(const char* contents) {
  const int fd = memfd_create("vibrofric-fuzz-wave", 0);
  if (fd < 0 || ::write(fd, contents, std::strlen(contents)) < 0) std::abort();
  return "/proc/self/fd/" + std::to_string(fd);  // kept open for the process
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
}

// An integer the tool's parse_int would read ([+-]?[0-9]{1,9}), else -1.
long as_int(const std::string& v) {
  std::size_t i = v.size() && (v[0] == '+' || v[0] == '-') ? 1 : 0;
  if (v.size() == i || v.size() - i > 9) return -1;
  for (std::size_t j = i; j < v.size(); ++j)
    if (v[j] < '0' || v[j] > '9') return -1;
  return std::labs(std::strtol(v.c_str(), nullptr, 10));
}

// The output without the two values documented as possibly infinite (README, `physical`): beta_c
// ("inf": n jumps upward, stick at every β) and p_max_peak_Pa (the elastic pressure at a punch's
// rim, a cone's tip, a profile's kink), in text ("name = inf"), JSON ("name": "inf") and CSV (the
// field under that header name).
std::string without_documented_infinities(std::string o) {
  for (const char* name : {"beta_c", "p_max_peak_Pa"}) {
    replace_all(o, std::string(name) + " = inf", std::string(name) + " = ");
    for (const char* colon : {": ", ":"})
      replace_all(o, "\"" + std::string(name) + "\"" + colon + "\"inf\"", "\"" + std::string(name) + "\"" + colon + "\"\"");
  }
  // CSV: a header line naming the columns, then rows of as many fields.
  std::istringstream in(o);
  std::string line, out;
  std::vector<std::size_t> columns;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
    if (line.find("beta_c") != std::string::npos || line.find("p_max_peak_Pa") != std::string::npos) {
      columns.clear();
      for (std::size_t k = 0; k < fields.size(); ++k)
        if (fields[k] == "beta_c" || fields[k] == "p_max_peak_Pa") columns.push_back(k);
    } else {
      for (const std::size_t k : columns)
        if (k < fields.size() && fields[k] == "inf") fields[k].clear();
      line.clear();
      for (std::size_t k = 0; k < fields.size(); ++k) line += (k ? "," : "") + fields[k];
    }
    out += line + "\n";
  }
  return out;
}

// True if the command line asks for legitimately expensive work (see the header).
bool too_expensive(const std::vector<std::string>& args) {
  if (args.size() > 1 && args[1] == "verify") return true;
  // `fit --output FILE` writes a file: the fuzzer must not touch the disk.
  for (const auto& a : args)
    if (a.rfind("--output", 0) == 0) return true;
  bool quadrature = false, rig = false, samples = false;
  long digits = 50;
  for (std::size_t i = 2; i < args.size(); ++i) {
    if (args[i].rfind("--", 0) != 0) continue;
    std::string name = args[i].substr(2), value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    } else if (i + 1 < args.size()) {
      value = args[i + 1];
    }
    const long n = as_int(value);
    if ((name == "digits" || name == "points") && n > 2000) return true;
    if (name == "digits" && n > 200) return true;
    if (name == "digits" && n >= 0) digits = n;
    if (name == "max-levels" && n > 10) return true;
    if (name == "threads" && n > 4) return true;
    if (name == "area" && value == "quadrature") quadrature = true;
    // rig dynamics: the event grid grows with the body's frequency, omega·sqrt(1 + kappa) (and the
    // damper's rate); a measured sample of 200 pieces costs a second a point
    if (name == "kappa" || name == "omega" || name == "zeta" || name == "mass" || name == "k-system" || name == "damping") {
      rig = true;
      const double v = std::strtod(value.c_str(), nullptr);
      if (!(v < 100)) return true;  // NaN and huge values included
    }
    if (name == "wave" && value.rfind("samples:", 0) == 0) samples = true;
    if (name == "gamma" && std::count(value.begin(), value.end(), ',') > 8) return true;
    if (name == "beta") {
      const auto colon = value.rfind(':');
      if (colon != std::string::npos && as_int(value.substr(colon + 1)) > 40) return true;
    }
  }
  return (quadrature && digits > 60) || (rig && (digits > 60 || samples));
}

// SolverError messages of the library (the `what` of every throw site), after "vibrofric: error: ".
bool solver_message(const std::string& m) {
  for (const char* prefix : {"wave ", "Fourier waveform ", "extremum of the Fourier waveform", "inflection of the Fourier waveform",
                             "acos(", "waveform ", "tanh-sinh", "no progress", "claims: ", "rig dynamics: "})
    if (m.rfind(prefix, 0) == 0) return true;
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // The tool's printf output (version, verify) goes nowhere; std::cout/std::cerr are captured.
  if (!std::freopen("/dev/null", "w", stdout)) std::abort();
  g_fourier = memfile("1 0 1\n2 0.3 0.1\n3 0 0.2\n");
  g_samples = memfile("0 1 3 2 -1 -2 -1 0.5\n");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> args{"vibrofric"};
  {
    std::size_t start = 0;
    for (;;) {
      const auto nl = input.find('\n', start);
      args.push_back(input.substr(start, nl - start));
      if (nl == std::string::npos || args.size() > 24) break;
      start = nl + 1;
    }
  }
  for (auto& a : args) {
    if (a.find('\0') != std::string::npos) return 0;  // argv strings cannot hold NUL
    if (a.find("fourier:") != std::string::npos || a.find("samples:") != std::string::npos) return 0;
    replace_all(a, "@F", "fourier:" + g_fourier);
    replace_all(a, "@S", "samples:" + g_samples);
  }
  if (too_expensive(args)) return 0;
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::ostringstream out, err;
  auto* cout_buf = std::cout.rdbuf(out.rdbuf());
  auto* cerr_buf = std::cerr.rdbuf(err.rdbuf());
  const int rc = vibrofric::tool::run_tool(static_cast<int>(args.size()), argv.data());
  std::cout.rdbuf(cout_buf);
  std::cerr.rdbuf(cerr_buf);
  const std::string o = out.str(), e = err.str();

  const bool one_line = !e.empty() && e.back() == '\n' && e.find('\n') == e.size() - 1;
  switch (rc) {
    case 0: {
      if (o.rfind("usage:", 0) == 0) break;  // --help
      if (args.size() > 1 && args[1] == "version") break;
      // On success stderr holds only whole lines of three kinds: --diagnostics' 'normalisation: '
      // lines, a note (the period a DAQ file's stamps gave) and warnings (physical's implausible inputs).
      for (std::size_t at = 0; at < e.size(); at = e.find('\n', at) + 1) {
        const bool known = e.compare(at, 15, "normalisation: ") == 0 || e.compare(at, 17, "vibrofric: note: ") == 0 ||
                           e.compare(at, 20, "vibrofric: warning: ") == 0;
        if (!known || e.find('\n', at) == std::string::npos) fuzz::finding("exit 0 with stderr: " + e, input);
      }
      if (o.empty()) fuzz::finding("exit 0 without output", input);
      std::string lower = without_documented_infinities(o);
      for (auto& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      // Values only: the echoed inputs (wave names, β, γ as given) cannot hold "nan"/"inf"
      // (check_decimal rejects them), file names are the fixed /proc paths.
      if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos)
        fuzz::finding("exit 0 with nan/inf in the output:\n" + o, input);
      break;
    }
    case 2:
      if (!o.empty()) fuzz::finding("bad input (exit 2) with output on stdout: " + o, input);
      if (!one_line || e.rfind("vibrofric: ", 0) != 0 || e.rfind("vibrofric: error: ", 0) == 0)
        fuzz::finding("bad input (exit 2) without one 'vibrofric: ' line on stderr: " + e, input);
      break;
    case 1: {
      // A sweep streams its rows: a solver failure inside the grid ends it after the complete rows
      // before the failing point (the domain, bad input, is decided before the first row).
      const bool streamed = args.size() > 1 && (args[1] == "sweep" || args[1] == "physical");
      if (!o.empty() && !(streamed && o.back() == '\n'))
        fuzz::finding("solver failure (exit 1) with output on stdout: " + o, input);
      const std::string prefix = "vibrofric: error: ";
      if (!one_line || e.rfind(prefix, 0) != 0) fuzz::finding("solver failure (exit 1) without one error line: " + e, input);
      const std::string m = e.substr(prefix.size());
      if (!solver_message(m)) fuzz::finding("exit 1 with a message that is not a SolverError's: " + e, input);
      break;
    }
    default:
      fuzz::finding("exit status " + std::to_string(rc), input);
  }
  return 0;
}
