// vibrofric_bench_compare: is a new benchmark run slower or less accurate than a saved one?
//
//   vibrofric_bench_compare BASELINE.json NEW.json [--time-threshold=R] [--ulp-threshold=R]
//                           [--real-time] [--allow-missing] [--noise-control=REGEX]
//
// Both files are Google Benchmark JSON (--benchmark_out_format=json), or bench/run's
// results file, which is the same JSON with extra keys. Per benchmark name:
//  - time: the median aggregate if the run has repetitions, else the median of the runs of that
//    name; CPU time in ns (--real-time: wall time, which on a shared machine includes time spent
//    descheduled). "slower" if new > old·(1 + R), R = --time-threshold, default 0.25
//    (this VM is shared and noisy; bench/README.md). Benchmarks carrying max_ulp are accuracy
//    benchmarks: their time is not compared.
//  - noise control: the benchmarks whose names match REGEX (default "closed_form_double$", code
//    that no library change touches) give the machine factor f, the median of their new/old
//    times. Every other time is judged against old·f: a machine phase that slows everything alike
//    moves f, not the verdicts. --noise-control= (empty) sets f = 1.
//  - accuracy (counters max_ulp, rms_ulp, failures): "less accurate" if max_ulp or rms_ulp grows
//    beyond old·(1 + R) + 1e-9, R = --ulp-threshold, default 0 (the values are deterministic),
//    or if failures grow.
//  - names are compared without the settings Google Benchmark appends (/min_time:…, /repeats:…,
//    /iterations:…), so a --quick run and a full run match benchmark by benchmark.
//  - a benchmark of the baseline missing from the new run is a regression unless --allow-missing.
// Exit status: 0 nothing worse, 1 something slower, less accurate or missing, 2 bad usage or
// unreadable JSON.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

using nlohmann::json;

double median(std::vector<double> t) {
  if (t.empty()) return NAN;  // an entry with no time: never "slower", never a machine factor
  std::sort(t.begin(), t.end());
  const std::size_t n = t.size();
  return n % 2 ? t[n / 2] : (t[n / 2 - 1] + t[n / 2]) / 2;
}

struct Entry {
  std::vector<double> times_ns;        // per-run times (CPU or real)
  std::optional<double> median_ns;     // the median aggregate, if any
  std::optional<double> max_ulp, rms_ulp, failures;
  std::string label;
  double time_ns() const {
    return median_ns ? *median_ns : median(times_ns);
  }
  bool accuracy() const { return max_ulp.has_value(); }
};

// The benchmark's name without the run settings Google Benchmark appends to it.
std::string base_name(const std::string& name) {
  static const std::regex settings("/(min_time|min_warmup_time|repeats|iterations):[^/]*");
  return std::regex_replace(name, settings, "");
}

double to_ns(double value, const std::string& unit) {
  if (unit == "ns") return value;
  if (unit == "us") return value * 1e3;
  if (unit == "ms") return value * 1e6;
  if (unit == "s") return value * 1e9;
  throw std::runtime_error("unknown time_unit '" + unit + "'");
}

std::map<std::string, Entry> load(const std::string& file, const char* time_key) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file);
  std::stringstream text;
  text << in.rdbuf();
  // Google Benchmark writes NaN for undefined statistics (the cv of a counter that is 0 in every
  // repetition), which strict JSON does not allow: read it as null.
  static const std::regex non_finite(R"((:\s*)-?(NaN|nan|Infinity|inf)(\s*[,}\]]))");
  json doc;
  try {
    doc = json::parse(std::regex_replace(text.str(), non_finite, "$1null$3"));
  } catch (const json::exception& e) {
    throw std::runtime_error(file + ": not JSON (" + e.what() + ")");
  }
  if (!doc.contains("benchmarks") || !doc["benchmarks"].is_array())
    throw std::runtime_error(file + ": no \"benchmarks\" array (not Google Benchmark JSON)");
  std::map<std::string, Entry> out;
  for (const json& b : doc["benchmarks"]) {
    if (b.value("error_occurred", false)) continue;
    const std::string name = base_name(b.value("run_name", b.value("name", std::string())));
    if (name.empty() || !b.contains(time_key)) continue;
    Entry& e = out[name];
    const std::string run_type = b.value("run_type", std::string("iteration"));
    if (!b[time_key].is_number()) continue;
    const double t = to_ns(b[time_key].get<double>(), b.value("time_unit", std::string("ns")));
    if (run_type == "aggregate") {
      if (b.value("aggregate_name", std::string()) != "median") continue;
      e.median_ns = t;
    } else {
      e.times_ns.push_back(t);
    }
    for (const auto& [key, slot] : {std::pair{"max_ulp", &e.max_ulp}, {"rms_ulp", &e.rms_ulp}, {"failures", &e.failures}})
      if (b.contains(key) && b[key].is_number()) *slot = b[key].get<double>();
    if (b.contains("label")) e.label = b["label"].get<std::string>();
  }
  return out;
}

bool parse_ratio(const char* arg, const char* flag, double& value) {
  const std::size_t n = std::strlen(flag);
  if (std::strncmp(arg, flag, n) != 0) return false;
  char* end = nullptr;
  value = std::strtod(arg + n, &end);
  if (end == arg + n || *end != '\0' || !(value >= 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(arg) + ": expected a finite number >= 0");
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  double time_threshold = 0.25, ulp_threshold = 0;
  bool allow_missing = false, real_time = false;
  std::string control_pattern = "closed_form_double$";
  std::vector<std::string> files;
  try {
    for (int i = 1; i < argc; ++i) {
      if (parse_ratio(argv[i], "--time-threshold=", time_threshold) || parse_ratio(argv[i], "--ulp-threshold=", ulp_threshold))
        continue;
      if (std::strcmp(argv[i], "--allow-missing") == 0) {
        allow_missing = true;
      } else if (std::strcmp(argv[i], "--real-time") == 0) {
        real_time = true;
      } else if (std::strncmp(argv[i], "--noise-control=", 16) == 0) {
        control_pattern = argv[i] + 16;
      } else if (argv[i][0] == '-') {
        throw std::invalid_argument(std::string("unknown option ") + argv[i]);
      } else {
        files.push_back(argv[i]);
      }
    }
    if (files.size() != 2)
      throw std::invalid_argument("usage: vibrofric_bench_compare BASELINE.json NEW.json [--time-threshold=R] "
                                  "[--ulp-threshold=R] [--real-time] [--allow-missing] [--noise-control=REGEX]");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vibrofric_bench_compare: %s\n", e.what());
    return 2;
  }
  std::optional<std::regex> control;
  try {
    if (!control_pattern.empty()) control.emplace(control_pattern);
  } catch (const std::regex_error&) {
    std::fprintf(stderr, "vibrofric_bench_compare: --noise-control=%s: expected a regular expression\n",
                 control_pattern.c_str());
    return 2;
  }
  std::map<std::string, Entry> old_run, new_run;
  try {
    const char* key = real_time ? "real_time" : "cpu_time";
    old_run = load(files[0], key);
    new_run = load(files[1], key);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vibrofric_bench_compare: %s\n", e.what());
    return 2;
  }

  std::printf("%s time, threshold %.0f%%; ulp threshold %.0f%%\n", real_time ? "real" : "CPU", 100 * time_threshold,
              100 * ulp_threshold);
  // The machine factor: the median new/old time of the noise-control benchmarks in both runs.
  std::vector<double> ratios;
  for (const auto& [name, o] : old_run) {
    const auto it = new_run.find(name);
    if (control && std::regex_search(name, *control) && it != new_run.end() && !o.accuracy() &&
        !it->second.accuracy() && o.time_ns() > 0 && it->second.time_ns() > 0)
      ratios.push_back(it->second.time_ns() / o.time_ns());
  }
  double factor = 1;
  if (!ratios.empty()) {
    factor = median(ratios);
    const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
    std::printf("noise control: %zu benchmarks matching '%s', new/old %.3g to %.3g; machine factor %.3f%s\n",
                ratios.size(), control_pattern.c_str(), *lo, *hi, factor,
                std::abs(factor - 1) > time_threshold ? " (the machine ran at another speed: times are judged against old x factor)"
                                                       : "");
  } else {
    std::printf("noise control: %s; machine factor 1\n",
                control ? ("no benchmark matching '" + control_pattern + "' in both runs").c_str() : "off");
  }
  std::printf("%-52s %14s %14s %9s  %s\n", "benchmark", "old", "new", "change", "verdict");
  if (factor != 1) std::printf("(times: old x %.3f, the machine factor)\n", factor);
  int worse = 0, better = 0, same = 0;
  auto row = [](const std::string& name, const std::string& what, double a, double b, const char* verdict) {
    const double change = a > 0 ? 100 * (b - a) / a : (b > 0 ? INFINITY : 0.0);
    std::printf("%-52s %14.6g %14.6g %+8.3g%%  %s\n", (name + what).c_str(), a, b, change, verdict);
  };
  for (const auto& [name, o] : old_run) {
    const auto it = new_run.find(name);
    if (it == new_run.end()) {
      std::printf("%-52s %14s %14s %9s  %s\n", name.c_str(), "", "", "", allow_missing ? "missing (allowed)" : "MISSING");
      if (!allow_missing) ++worse;
      continue;
    }
    const Entry& n = it->second;
    if (o.accuracy() || n.accuracy()) {
      bool bad = false;
      for (const auto& [what, a, b] : {std::tuple{" max_ulp", o.max_ulp, n.max_ulp}, {" rms_ulp", o.rms_ulp, n.rms_ulp}}) {
        const double x = a.value_or(0), y = b.value_or(INFINITY);
        const bool less_accurate = !(y <= x * (1 + ulp_threshold) + 1e-9);
        const bool more_accurate = y < x * (1 - ulp_threshold) - 1e-9;
        row(name, what, x, y, less_accurate ? "LESS ACCURATE" : more_accurate ? "more accurate" : "same");
        bad = bad || less_accurate;
        if (more_accurate) ++better;
      }
      const double fo = o.failures.value_or(0), fn = n.failures.value_or(0);
      if (fn > fo) {
        row(name, " failures", fo, fn, "MORE FAILURES");
        bad = true;
      }
      if (bad) ++worse; else ++same;
      continue;
    }
    const double a = o.time_ns() * factor, b = n.time_ns();
    const bool slower = b > a * (1 + time_threshold);
    const bool faster = b * (1 + time_threshold) < a;
    row(name, " ns", a, b, slower ? "SLOWER" : faster ? "faster" : "same (within noise)");
    if (slower) ++worse; else if (faster) ++better; else ++same;
  }
  for (const auto& [name, n] : new_run)
    if (!old_run.count(name)) std::printf("%-52s %14s %14s %9s  new\n", name.c_str(), "", "", "");
  std::printf("%d worse, %d better, %d unchanged\n", worse, better, same);
  return worse ? 1 : 0;
}
