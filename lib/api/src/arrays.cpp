#include "vibrofric/api/arrays.hpp"

#include <charconv>

#include "tables.hpp"

namespace vibrofric {

namespace {

// The label as the file readers quote a file's name (their messages name an array by its label).
std::string quoted_label(const std::string& label) { return "'" + detail::visible(label) + "'"; }

void check_all(const std::vector<std::string>& values, const std::string& name) {
  for (std::size_t j = 0; j < values.size(); ++j) check_decimal(values[j], name + "[" + std::to_string(j) + "]");
}

}  // namespace

std::string decimal_text(double x) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, r.ptr);
}

WaveSpec samples_wave(const std::vector<std::string>& y, const std::vector<std::string>& t, const std::string& label,
                      int periods) {
  if (!t.empty() && t.size() != y.size())
    throw InputError(label + ": t has " + std::to_string(t.size()) + " values and y " + std::to_string(y.size()) +
                     ": expected one time stamp per value (one period with its end point)");
  if (y.size() + (t.empty() ? 0 : 1) > max_table_lines)
    throw InputError("file " + quoted_label(label) + " has more than " + std::to_string(max_table_lines) +
                     " lines: expected fewer");
  check_all(y, label + " y");
  check_all(t, label + " t");
  // The rows a file 'time,value' (header on line 1) or of one value per line would give.
  detail::Table table;
  if (!t.empty()) table.header = {"time", "value"};
  for (std::size_t j = 0; j < y.size(); ++j)
    table.rows.emplace_back(static_cast<int>(j) + (t.empty() ? 1 : 2),
                            t.empty() ? std::vector<std::string>{y[j]} : std::vector<std::string>{t[j], y[j]});
  WaveReadOptions options;
  options.periods = periods;
  WaveSpec spec = detail::samples_from_table(table, detail::array_source(label, t.empty() ? 0 : 1), options);
  spec.name = label;
  return spec;
}

WaveSpec fourier_wave(const std::vector<std::string>& a, const std::vector<std::string>& b, const std::string& a0,
                      const std::string& label) {
  if (a.size() != b.size())
    throw InputError(label + ": a has " + std::to_string(a.size()) + " coefficients and b " + std::to_string(b.size()) +
                     ": expected a_k and b_k for the same k = 1 … K");
  if (!a0.empty()) check_decimal(a0, label + " a0");
  check_all(a, label + " a");  // a[j] is a_{j+1}
  check_all(b, label + " b");
  // The rows of a file 'k a_k b_k' (a line '0 a0 0' first when a0 is given).
  detail::Table table;
  if (!a0.empty()) table.rows.push_back({1, {"0", a0, "0"}});
  const int first = a0.empty() ? 1 : 2;
  for (std::size_t j = 0; j < a.size(); ++j)
    table.rows.push_back({first + static_cast<int>(j), {std::to_string(j + 1), a[j], b[j]}});
  WaveSpec spec = detail::fourier_from_table(table, detail::array_source(label, a0.empty() ? 0 : 1));
  spec.name = label;
  return spec;
}

WaveSpec fitted_wave(const FourierFit& fit, const std::string& label) {
  // The rows 'k a_k b_k' of the fit's fourier file, from its coefficients as stated (17 digits),
  // not from the file's text: row k + 1 is label[k].
  detail::Table table;
  for (const auto& h : fit.harmonics)
    table.rows.push_back({static_cast<int>(h.k) + 1, {std::to_string(h.k), h.a.text(), h.b.text()}});
  WaveSpec spec = detail::fourier_from_table(table, detail::array_source(label, 1));
  spec.name = label;
  return spec;
}

ProfileSpec profile_arrays(const std::vector<std::string>& r, const std::vector<std::string>& f, const std::string& label) {
  if (r.size() != f.size())
    throw InputError(label + ": r has " + std::to_string(r.size()) + " values and f " + std::to_string(f.size()) +
                     ": expected one height per radius");
  check_all(r, label + " r");
  check_all(f, label + " f");
  detail::Rows rows;
  for (std::size_t j = 0; j < r.size(); ++j) rows.push_back({static_cast<int>(j) + 1, {r[j], f[j]}});
  ProfileSpec spec = detail::profile_from_rows(rows, detail::array_source(label, 0));
  spec.name = label;
  return spec;
}

}  // namespace vibrofric
