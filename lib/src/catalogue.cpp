#include "vibrofric/catalogue.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace vibrofric {

namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// Lines of a user waveform file with comments (#…) and blank lines removed, as token lists.
std::vector<std::pair<int, std::vector<std::string>>> read_tokens(const std::string& path,
                                                                 const std::string& wave) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read file " + quoted(path) + " for wave " + quoted(wave));
  std::vector<std::pair<int, std::vector<std::string>>> lines;
  std::string line;
  int number = 0;
  constexpr std::size_t max_lines = 10'000'000;
  while (std::getline(in, line)) {
    ++number;
    if (static_cast<std::size_t>(number) > max_lines)
      throw InputError("file " + quoted(path) + " has more than " + std::to_string(max_lines) + " lines: expected fewer");
    if (auto h = line.find('#'); h != std::string::npos) line.erase(h);
    std::istringstream ls(line);
    std::vector<std::string> tokens;
    for (std::string t; ls >> t;) {
      if (t.back() == ',') t.pop_back();
      if (!t.empty()) tokens.push_back(t);
    }
    if (!tokens.empty()) lines.emplace_back(number, std::move(tokens));
  }
  return lines;
}

}  // namespace

const std::vector<std::string>& catalogue_names() {
  static const std::vector<std::string> names{"sine", "triangle", "sawtooth-right", "sawtooth-left", "square"};
  return names;
}

// [+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]{1,9})?, scanned by hand: std::regex cost several
// µs per 60-digit number, more than a double evaluation (bench/README.md).
static bool is_decimal(const std::string& t) {
  std::size_t i = 0, n = t.size();
  auto digits = [&] {
    const std::size_t start = i;
    while (i < n && t[i] >= '0' && t[i] <= '9') ++i;
    return i - start;
  };
  if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < n && t[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < n && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
    // At most 9 exponent digits: Boost's cpp_bin_float parser overflows a 64-bit integer (and
    // crashed the tool) from 15 on, and no value of the model needs |exponent| ≥ 10^9.
    const std::size_t e = digits();
    if (e == 0 || e > 9) return false;
  }
  return i == n;
}

void check_decimal(const std::string& text, const std::string& what) {
  if (text.empty()) throw InputError(what + " is empty: expected a decimal number");
  if (!is_decimal(text))
    throw InputError(what + " = " + quoted(text) + ": expected a finite decimal number such as 0.5 or -3e-2 (exponent below 1e9)");
  errno = 0;
  const long double v = std::strtold(text.c_str(), nullptr);
  if (errno == ERANGE && std::fabs(v) > 1) 
    throw InputError(what + " = " + quoted(text) + " overflows: expected a magnitude below 1e308");
  if (std::fabs(v) > static_cast<long double>(std::numeric_limits<double>::max()))
    throw InputError(what + " = " + quoted(text) + " overflows: expected a magnitude below 1e308");
}

WaveSpec parse_wave(const std::string& text) {
  WaveSpec s;
  s.name = text;
  if (text == "sine" || text == "harmonic") { s.kind = WaveKind::sine; s.name = "sine"; return s; }
  if (text == "triangle" || text == "tri") { s.kind = WaveKind::triangle; s.name = "triangle"; return s; }
  if (text == "sawtooth-right" || text == "str") { s.kind = WaveKind::sawtooth_right; s.name = "sawtooth-right"; return s; }
  if (text == "sawtooth-left" || text == "stl") { s.kind = WaveKind::sawtooth_left; s.name = "sawtooth-left"; return s; }
  if (text == "square" || text == "sqr") { s.kind = WaveKind::square; s.name = "square"; return s; }
  const auto colon = text.find(':');
  const std::string head = text.substr(0, colon), arg = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (colon != std::string::npos && head == "power") {
    s.kind = WaveKind::power;
    s.exponent = arg;
    check_decimal(arg, "power exponent p in " + quoted(text));
    // strtold, not stold: an exponent that underflows (power:1e-5000) is 0 here, not an exception.
    if (!(std::strtold(arg.c_str(), nullptr) >= 1))
      throw InputError("power exponent p = " + quoted(arg) + ": expected p ≥ 1");
    return s;
  }
  if (colon != std::string::npos && head == "fourier") {
    if (arg.empty()) throw InputError("wave " + quoted(text) + ": expected fourier:FILE");
    s.kind = WaveKind::fourier;
    std::set<unsigned> seen;
    for (const auto& [line, tok] : read_tokens(arg, text)) {
      const std::string where = arg + ":" + std::to_string(line);
      if (tok.size() != 3)
        throw InputError(where + ": expected three fields 'k a_k b_k', got " + std::to_string(tok.size()));
      if (!std::regex_match(tok[0], std::regex("[0-9]{1,6}")))
        throw InputError(where + ": harmonic k = " + quoted(tok[0]) + ": expected an integer 0 ≤ k ≤ 999999");
      const auto k = static_cast<unsigned>(std::stoul(tok[0]));
      if (k > 100000) throw InputError(where + ": harmonic k = " + tok[0] + ": expected k ≤ 100000");
      if (!seen.insert(k).second) throw InputError(where + ": harmonic k = " + tok[0] + " given twice");
      check_decimal(tok[1], where + " a_" + tok[0]);
      check_decimal(tok[2], where + " b_" + tok[0]);
      s.harmonics.push_back({k, tok[1], tok[2]});
    }
    if (s.harmonics.empty()) throw InputError("file " + quoted(arg) + " has no coefficients: expected lines 'k a_k b_k'");
    return s;
  }
  if (colon != std::string::npos && head == "samples") {
    if (arg.empty()) throw InputError("wave " + quoted(text) + ": expected samples:FILE");
    s.kind = WaveKind::samples;
    for (const auto& [line, tok] : read_tokens(arg, text)) {
      for (const auto& t : tok) {
        check_decimal(t, arg + ":" + std::to_string(line) + " sample");
        s.samples.push_back(t);
      }
    }
    if (s.samples.size() < 2)
      throw InputError("file " + quoted(arg) + " has " + std::to_string(s.samples.size()) + " sample(s): expected at least 2");
    return s;
  }
  throw InputError("unknown wave " + quoted(text) +
                   ": expected sine, triangle, sawtooth-right, sawtooth-left, square, power:P, fourier:FILE or samples:FILE");
}

}  // namespace vibrofric
