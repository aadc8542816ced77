// physical: from physical inputs in SI units (Eqs. 1, 5, 14), one point or a sweep of one input.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cli.hpp"
#include "vibrofric/api/commands.hpp"

namespace vibrofric::tool {
namespace {

// `physical`'s inputs (`values`: one per number input, the swept one's value of this row), each named
// by its flag (the input u_mean is --u-mean), and its controls.
PhysicalRequest request_of(const Flags& f, const std::map<std::string, InputValue>& values) {
  PhysicalRequest request;
  for (const auto& input : request.inputs()) {
    std::string flag = input.member;
    std::replace(flag.begin(), flag.end(), '_', '-');
    input.name() = "--" + flag;
    if (input.number) {
      if (const auto it = values.find(flag); it != values.end()) input.number->value = it->second;
    } else if (const auto it = f.physical_texts.find(flag); it != f.physical_texts.end()) {
      input.text->text = it->second;
    }
  }
  request.constant_normal = f.wave && *f.wave == "constant";
  return request;
}

PhysicalOutputs physical_record(const Flags& f, const std::map<std::string, InputValue>& values, const WaveSpec& wave) {
  const PhysicalRequest request = request_of(f, values);
  std::vector<std::string> warnings;
  // A guaranteed double unless --digits or --type says otherwise.
  Precision precision = precision_of(f);
  if (!f.type && !f.digits) precision.type = NumberType::float64;
  PhysicalOutputs out = physical_point(wave, request, precision, batch_options(f), &warnings);
  // Each warning once (a sweep repeats them), on stderr after the output, as the diagnostics.
  static std::set<std::string> said;
  for (const auto& w : warnings)
    if (said.insert(w).second) pending_diagnostics += "vibrofric: warning: " + w + "\n";
  return out;
}

// Names and values of output records, for CSV and JSON.
std::vector<std::string> names_of(const PhysicalOutputs& r) {
  std::vector<std::string> out;
  for (const auto& output : r) out.push_back(output.name);
  return out;
}
std::vector<std::string> values_of(const PhysicalOutputs& r) {
  std::vector<std::string> out;
  for (const auto& output : r) out.push_back(output.text());
  return out;
}

}  // namespace

// `physical` at one point, or over a range of one input (--v0, --A, --f, --F-N or --u-mean as
// FROM:TO:N or log:FROM:TO:N): one row per value, streamed as it is computed.
int run_physical(const Flags& f) {
  // --wave constant: no normal oscillation (physical_constant); the wave is not read.
  WaveSpec constant;
  constant.name = "constant";
  const WaveSpec wave = f.wave && *f.wave == "constant" ? constant : read_wave(f);
  std::string swept;
  std::map<std::string, InputValue> values;
  for (const auto& [name, read] : f.physical) values[name] = read.front();
  for (const std::string& name : kSweptPhysical)
    if (f.physical_ranges.count(name)) {
      if (!swept.empty())
        throw InputError("--" + swept + " and --" + name + " are both ranges: expected one swept input at a time");
      swept = name;
    }
  if (f.trace) {
    // One period in SI: t_s,F_N_N,F_x_N,u_m (with a rig also x_m,F_s_N), each to --digits (17 by
    // default) or the fewer its inputs carry.
    if (!swept.empty()) throw InputError("--trace with a range of --" + swept + ": expected one point");
    if (f.format && *f.format != Format::csv) throw InputError("--trace writes csv: expected no --format or --format csv");
    if (f.type) throw InputError("--trace prints --digits significant digits (17 by default): expected no --type");
    const auto rows = physical_trace(wave, request_of(f, values), f.points.value_or(1000), f.digits.value_or(17),
                                     batch_options(f));
    const bool body = !rows.empty() && rows.front().x_m;
    std::cout << (body ? "t_s,F_N_N,F_x_N,u_m,x_m,F_s_N\n" : "t_s,F_N_N,F_x_N,u_m\n");
    for (const auto& r : rows) {
      std::cout << r.t_s.text() << ',' << r.F_N_N.text() << ',' << r.F_x_N.text() << ',' << r.u_m.text();
      if (body) std::cout << ',' << r.x_m->text() << ',' << r.F_s_N->text();
      std::cout << '\n';
    }
    return 0;
  }
  if (f.points) throw InputError("--points goes with --trace: expected --trace");
  if (swept.empty()) {
    const Format format = f.format.value_or(Format::text);
    const PhysicalOutputs rec = physical_record(f, values, wave);
    if (format == Format::csv) {
      write_csv_row(names_of(rec));
      write_csv_row(values_of(rec));
    } else if (format == Format::json) {
      std::cout << json_record(names_of(rec), values_of(rec)).dump(1) << '\n';
    } else {
      for (const auto& output : rec) std::cout << output.name << " = " << output.text() << '\n';
    }
    return 0;
  }
  const Format format = f.format.value_or(Format::csv);
  if (format == Format::text) throw InputError("--format text: a physical sweep writes csv (the default) or json");
  const std::vector<InputValue>& range = f.physical.at(swept);
  // Every input's domain is monotone along a range: its two ends decide it before the first row.
  auto at = [&](std::size_t i) {
    values[swept] = range[i];
    return physical_record(f, values, wave);
  };
  const PhysicalOutputs first = at(0), last = at(range.size() - 1);
  // A progress line on a terminal, as sweep's: at most ten redraws a second.
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto next_draw = start;
  const auto progress = [&](std::size_t done) {
    const auto now = clock::now();
    if (!isatty(2) || (done < range.size() && now < next_draw)) return;
    next_draw = now + std::chrono::milliseconds(100);
    const double seconds = std::chrono::duration<double>(now - start).count();
    std::fprintf(stderr, "\rphysical: %zu/%zu (%.1f %%), %.0f s left   %s", done, range.size(),
                 100.0 * static_cast<double>(done) / static_cast<double>(range.size()),
                 seconds * static_cast<double>(range.size() - done) / static_cast<double>(done),
                 done == range.size() ? "\n" : "");
  };
  for (std::size_t i = 0; i < range.size(); ++i) {
    const PhysicalOutputs rec = i == 0 ? first : i + 1 == range.size() ? last : at(i);
    std::vector<std::string> names = names_of(rec), values = values_of(rec);
    names.insert(names.begin(), swept);  // the swept input leads each row, under its flag's name
    values.insert(values.begin(), range[i].text());
    if (format == Format::csv) {
      if (i == 0) write_csv_row(names);
      write_csv_row(values);
    } else {
      std::cout << (i ? ",\n " : "[\n ") << json_record(names, values).dump();
    }
    std::cout.flush();
    progress(i + 1);
  }
  if (format == Format::json) std::cout << "\n]\n";
  return 0;
}

}  // namespace vibrofric::tool
