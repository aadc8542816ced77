#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/exact_input.hpp"
#include "vibrofric/api/input_value.hpp"

#include <csv.h>

#include "vibrofric/api/decimal_value.hpp"
#include "tables.hpp"
#include "text.hpp"
#include "vibrofric/api/limits.hpp"
#include "vibrofric/api/suggest.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

namespace vibrofric {

static bool is_decimal(const std::string& t);
bool decimal_comma(const std::string& text);

namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

using detail::visible;

// The fields of one line at `delim`, read by libcsv (RFC 4180): a field that opens with a double
// quote may hold the separator, a doubled quote in it is one quote, and spaces and tabs around a
// field go. No character ends the row (the line is one row: a stray CR stays in its field).
std::vector<std::string> separated_fields(const std::string& line, char delim) {
  struct Parser {
    csv_parser p;
    Parser() {
      if (csv_init(&p, 0) != 0) throw std::bad_alloc();
    }
    ~Parser() { csv_free(&p); }
  } parser;
  csv_set_delim(&parser.p, static_cast<unsigned char>(delim));
  csv_set_term_func(&parser.p, [](unsigned char) { return 0; });
  struct Out {
    std::vector<std::string> fields;
    bool failed = false;
  } out;
  const auto field = [](void* text, std::size_t size, void* data) {
    auto* o = static_cast<Out*>(data);
    try {  // nothing may be thrown through libcsv's C frames
      o->fields.emplace_back(text ? static_cast<const char*>(text) : "", text ? size : 0);
    } catch (...) {
      o->failed = true;
    }
  };
  const bool ok = csv_parse(&parser.p, line.data(), line.size(), field, nullptr, &out) == line.size() &&
                  csv_fini(&parser.p, field, nullptr, &out) == 0;
  if (!ok || out.failed) throw std::bad_alloc();  // libcsv fails only when out of memory (not in strict mode)
  return std::move(out.fields);
}

// The fields of a line split at ';' if libcsv finds one outside quotes (an export whose decimals
// may hold commas), else at ',' likewise; empty if the line has neither.
std::vector<std::string> fields_at_separator(const std::string& line, char* delim) {
  for (const char d : {';', ','}) {
    if (line.find(d) == std::string::npos) continue;
    auto fields = separated_fields(line, d);
    if (fields.size() > 1) {
      *delim = d;
      return fields;
    }
  }
  return {};
}

// The name of a time column, as rigs export it: "time", "t", "timestamp" or the word in German,
// French, Spanish, Italian and Portuguese (Zeit, temps, tiempo, tempo), alone, with a unit of time
// in brackets ("Time [s]", "t (ms)"; "T [°C]" is a temperature) or after "in" ("Zeit in ms"), or
// with anything after '_' or '/' ("time_s", "t/s"); or any name with a unit of time in brackets,
// after '/' or after "in" ("Messzeit [s]", "dt/ms"; "v [m/s]" is a velocity).
bool is_time_name(const std::string& name) {
  static const std::string units = "(s|sec|min|ms|us|ns|\xC2\xB5s|\xCE\xBCs)";
  static const std::regex word(R"((t|time|timestamp|zeit|temps|tiempo|tempo)(\s*[_/]\s*\S+)?)", std::regex::icase);
  static const std::regex word_unit("(t|time|timestamp|zeit|temps|tiempo|tempo)(\\s*\\[\\s*" + units + "\\s*\\]|\\s*\\(\\s*" +
                                        units + "\\s*\\)|\\s+in\\s+" + units + ")\\s*",
                                    std::regex::icase);
  static const std::regex unit(".*?(\\[\\s*" + units + "\\s*\\]|\\(\\s*" + units + "\\s*\\)|\\s+in\\s+" + units + ")\\s*");
  // "name/s" is a quantity per unit, as pandas and ISO 80000 write it; "m/s" is a velocity.
  static const std::regex per(R"(\s*([^\s/]+)\s*/\s*)" + units + "\\s*");
  static const std::regex length("(k|m|c|u|n|\xC2\xB5|\xCE\xBC)?m");
  std::smatch m;
  if (std::regex_match(name, m, per) && !std::regex_match(m[1].str(), length)) return true;
  return std::regex_match(name, word) || std::regex_match(name, word_unit) || std::regex_match(name, unit);
}

// The lines before a samples file's last run of numeric rows, where that run follows a line that
// is not numeric: a preamble (and header) that skip_rows would skip, as the file's line count.
std::optional<int> preamble_lines(const detail::Rows& rows, bool arrays) {
  if (arrays) return std::nullopt;
  const auto numeric = [](const std::vector<std::string>& fields) {
    return std::all_of(fields.begin(), fields.end(), [](const std::string& f) { return is_decimal(f); });
  };
  std::size_t k = rows.size();
  while (k > 0 && numeric(rows[k - 1].second)) --k;
  if (k == 0 || k == rows.size() || rows.size() - k < 2) return std::nullopt;
  const auto& above = rows[k - 1].second;
  const bool header = std::none_of(above.begin(), above.end(), [](const std::string& f) { return is_decimal(f); });
  return header ? rows[k - 1].first - 1 : rows[k].first - 1;
}

// The value of a decimal at 60 significant digits: decimals of up to 60 digits compare exactly.
mpfr exact_value(const Decimal& d) {
  PrecisionScope scope(60);
  return d.to<mpfr>();
}

// The unit of the last written digit of a decimal: "2.50e-07" → 1e-9, "12" → 1, "0.5" → 0.1 (the
// power of ten of its significand); 0 for a zero, which a DAQ's first stamp is exactly.
mpfr last_place(const Decimal& d) {
  PrecisionScope scope(60);
  if (d.is_zero()) return mpfr(0);
  return pow(mpfr(10), d.exponent());
}

// dt if the stamps t_0 … t_{N−1} are t_0 + j·dt, dt = (t_{N−1} − t_0)/(N − 1), else none. Each
// stamp is that to a millionth of dt (exact decimals as 0, 0.1, 0.2; j·dt computed in binary
// floating point, as numpy's, is within 1e-15 of it), or a DAQ's t_j printed rounded: within
// u_j/2 of the true stamp (u_j its last written place), and the true step within
// (u_0 + u_{N−1})/(2(N − 1)) of dt, so t_j − t_0 − j·dt is at most (u_j + 2u_0 + u_{N−1})/2;
// and the printed digits resolve the step (u_j ≤ dt/10), else 0, 1, 3 would pass as 0, 1.5, 3
// rounded.
std::optional<mpfr> uniform_step(const std::vector<Decimal>& t) {
  PrecisionScope scope(60);
  const std::size_t n = t.size();
  const mpfr t0 = exact_value(t.front()), u0 = last_place(t.front()), un = last_place(t.back());
  const mpfr dt = (exact_value(t.back()) - t0) / (n - 1);
  for (std::size_t j = 1; j + 1 < n; ++j) {
    const mpfr deviation = abs(mpfr(exact_value(t[j]) - t0 - dt * j));
    if (deviation <= dt * mpfr("1e-6")) continue;
    const mpfr uj = last_place(t[j]);
    if (std::max({uj, u0, un}) > dt / 10 || deviation > (uj + 2 * u0 + un) / 2) return std::nullopt;
  }
  return dt;
}

// The smallest p dividing n with y_j = y_{j+p} for every j (n if none), and with a time column
// also t_{j+p} − t_j the same for every j (the signal repeats, not only its values): doubles
// filter the candidates, 60 digits confirm them.
std::size_t smallest_period(const std::vector<Decimal>& y, const std::vector<Decimal>& t) {
  const std::size_t n = y.size();
  std::vector<double> v;
  v.reserve(n);
  for (const auto& x : y) v.push_back(x.to<double>());
  for (std::size_t p = 1; p < n; ++p) {
    if (n % p) continue;
    bool same = true;
    for (std::size_t j = 0; j + p < n && same; ++j) same = v[j] == v[j + p];
    if (!same) continue;
    PrecisionScope scope(60);
    for (std::size_t j = 0; j + p < n && same; ++j) same = y[j].to<mpfr>() == y[j + p].to<mpfr>();
    if (same && !t.empty()) {
      const mpfr shift = t[p].to<mpfr>() - t[0].to<mpfr>();
      for (std::size_t j = 0; j + p < n && same; ++j) same = t[j + p].to<mpfr>() - t[j].to<mpfr>() == shift;
    }
    if (same) return p;
  }
  return n;
}

// Σ terms exactly, as a decimal "Me-E": the K periods of a record summed sample by sample, which
// the normalisation makes the wave of their mean.
Decimal decimal_sum(const std::vector<const Decimal*>& terms) { return *Decimal::read(exact_sum_text(terms)); }

// How far a record of N samples (uniform phases, linear between) is from repeating after `lag`
// samples: r(L) = rms(y(x) − y(x + L)) / rms(y − ȳ) over up to 20,000 equally spaced x (every
// sample of a shorter record), y periodic over the record. A record of K noisy periods has
// r(N/K) at its noise level; one period of a signal, shifted by a fraction of itself, about √2
// (a sine by N/2: 2).
class Repetition {
 public:
  explicit Repetition(const std::vector<Decimal>& y) : n_(y.size()), m_(std::min<std::size_t>(n_, 20000)) {
    v_.reserve(n_);
    for (const auto& x : y) v_.push_back(x.to<double>());
    step_ = static_cast<double>(n_) / static_cast<double>(m_);
    double mean = 0;
    for (std::size_t i = 0; i < m_; ++i) mean += at(static_cast<double>(i) * step_) / static_cast<double>(m_);
    for (std::size_t i = 0; i < m_; ++i) variance_ += (at(static_cast<double>(i) * step_) - mean) * (at(static_cast<double>(i) * step_) - mean);
  }
  bool varies() const { return variance_ > 0; }
  double r(double lag) const {
    double sum = 0;
    for (std::size_t i = 0; i < m_; ++i) {
      const double x = static_cast<double>(i) * step_, e = at(x) - at(x + lag);
      sum += e * e;
    }
    return std::sqrt(sum / variance_);
  }

 private:
  double at(double x) const {  // the periodic piecewise-linear record at index x ≥ 0
    x = std::fmod(x, static_cast<double>(n_));
    const auto j = std::min(static_cast<std::size_t>(x), n_ - 1);
    const double t = x - static_cast<double>(j);
    return (1 - t) * v_[j] + t * v_[(j + 1) % n_];
  }
  std::size_t n_, m_;
  std::vector<double> v_;
  double step_ = 1, variance_ = 0;
};

// A record of K ≥ 2 noisy periods of one signal: r(N/K) < 0.14 (the periods differ by less than
// 14 % rms of the signal), and below a fifth of the largest r of the shorter shifts j N/(8K),
// j = 1 … 7, about √2 for any signal: one period of a smooth signal, shifted by a small N/K,
// differs little, but no less than by those. The largest K up to min(64, N/8) that passes, with
// its r; none where no K does (or N < 16).
std::optional<std::pair<std::size_t, double>> repeated_periods(const std::vector<Decimal>& y) {
  const std::size_t n = y.size();
  if (n < 16) return std::nullopt;
  const Repetition rep(y);
  if (!rep.varies()) return std::nullopt;
  std::optional<std::pair<std::size_t, double>> found;
  for (std::size_t k = 2; k <= std::min<std::size_t>(n / 8, 64); ++k) {
    const double period = static_cast<double>(n) / static_cast<double>(k), repeat = rep.r(period);
    if (!(repeat < 0.14)) continue;
    double within = 0;
    for (int j = 1; j < 8; ++j) within = std::max(within, rep.r(period * j / 8));
    if (repeat < 0.2 * within) found = std::make_pair(k, repeat);
  }
  return found;
}

// The 0-based value column chosen by `column` (README, "File formats"): a 1-based index (header
// names hold no number, so digits are never a name), or a header name matched exactly.
std::size_t choose_column(const std::string& column, const std::vector<std::string>& header, std::size_t columns,
                          const std::string& path) {
  const std::string range = columns == 1 ? std::string("1") : "1 to " + std::to_string(columns);
  if (std::all_of(column.begin(), column.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    const std::size_t index = column.size() > 9 ? 0 : static_cast<std::size_t>(std::stoul(column));
    if (index < 1 || index > columns)
      throw InputError("column " + quoted(column) + " of " + quoted(visible(path)) + " is out of range: the file has " +
                       std::to_string(columns) + (columns == 1 ? " column" : " columns") + ", expected an index " + range);
    return index - 1;
  }
  if (header.empty())
    throw InputError("column " + quoted(visible(column)) + ": " + quoted(visible(path)) +
                     " has no header line of names, expected a 1-based column index " + range);
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == column) found.push_back(i);
  if (found.size() > 1)
    throw InputError("column " + quoted(visible(column)) + " names columns " + std::to_string(found[0] + 1) + " and " +
                     std::to_string(found[1] + 1) + " of " + quoted(visible(path)) + ": expected a 1-based index to choose one");
  if (found.empty()) {
    std::string names;
    for (std::size_t i = 0; i < header.size(); ++i) names += (i ? ", " : "") + quoted(visible(header[i]));
    throw InputError("column " + quoted(visible(column)) + " is not in the header of " + quoted(visible(path)) +
                     ": expected one of " + names + " or an index " + range);
  }
  return found[0];
}

}  // namespace

std::string detail::RowSource::where(int line) const {
  return arrays ? name + "[" + std::to_string(line - 1 - header_lines) + "]" : name + ":" + std::to_string(line);
}

detail::RowSource detail::file_source(const std::string& path, const std::string& wave) { return {path, wave, false, 0}; }

detail::RowSource detail::array_source(const std::string& label, int header_lines) {
  return {label, label, true, header_lines};
}

detail::Table detail::read_table_file(const std::string& path, const std::string& wave, int skip_rows) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("file " + quoted(visible(path)) + " for wave " + quoted(visible(wave)) + " is a directory: expected a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const std::string what = "cannot read file " + quoted(visible(path)) + " for wave " + quoted(visible(wave));
    if (!std::filesystem::exists(path, ec)) throw MissingFileError(what + ": no such file");
    throw InputError(what);
  }
  return read_table(in, file_source(path, wave), skip_rows);
}

detail::Table detail::read_table(std::istream& in, const RowSource& source, int skip_rows) {
  Table t;
  std::string line;
  int number = 0;
  bool commas = true;
  while (std::getline(in, line)) {
    ++number;
    if (static_cast<std::size_t>(number) > max_table_lines)
      throw InputError("file " + quoted(visible(source.name)) + " has more than " + std::to_string(max_table_lines) +
                       " lines: expected fewer");
    if (number <= skip_rows) continue;
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    line = as_utf8(line);
    if (line.find('\0') != std::string::npos)
      throw InputError("file " + quoted(visible(source.name)) + " line " + std::to_string(number) +
                       " holds a NUL byte: expected text");
    if (auto h = line.find('#'); h != std::string::npos) line.erase(h);
    // A line with ';' or ',' outside quotes is split at that separator (fields trimmed; an empty
    // one is an error, except after a trailing separator); any other line at tabs or whitespace.
    std::vector<std::string> fields;
    char delim = 0;
    if (fields = fields_at_separator(line, &delim); delim) {
      // An empty field is an error, except after a trailing separator.
      if (!fields.empty() && fields.back().empty()) fields.pop_back();
      for (auto& f : fields) {
        if (f.empty())
          throw InputError(source.where(number) + ": empty field before " + quoted(std::string(1, delim)) +
                           ": expected a value between separators");
        // Between ';' a decimal comma is unambiguous (a European lab PC's export): read as a point.
        if (delim == ';' && !is_decimal(f) && decimal_comma(f)) f[f.find(',')] = '.';
      }
    } else if (line.find('\t') != std::string::npos) {
      // Tab-separated (a rig's export): fields between runs of tabs, so that a header name may
      // hold spaces ('time [s]<TAB>displacement [um]'); spaces around them trimmed.
      std::size_t start = 0;
      while (start < line.size()) {
        const std::size_t end = std::min(line.find('\t', start), line.size());
        std::string f = line.substr(start, end - start);
        while (!f.empty() && f.back() == ' ') f.pop_back();
        f.erase(0, std::min(f.find_first_not_of(' '), f.size()));
        if (!f.empty()) fields.push_back(f);
        start = end + 1;
      }
    } else {
      std::istringstream ls(line);
      for (std::string f; ls >> f;) fields.push_back(f);
    }
    if (fields.empty()) continue;
    bool names = true;  // a header holds no number at all
    for (const auto& f : fields) names = names && !is_decimal(f);
    if (names && t.rows.empty() && t.header.empty()) {
      t.header = fields;
      continue;
    }
    t.rows.emplace_back(number, std::move(fields));
    commas = commas && delim == ',';
  }
  t.comma_separated = commas && !t.rows.empty();
  return t;
}


int detail::distinct_digits(const WaveSpec& spec) {
  int distinct = 1;
  for (const Decimal& y : spec.samples) distinct = std::max(distinct, y.written_digits());
  return distinct;
}

mpfr detail::sample_value(const WaveSpec& spec, std::size_t j) { return spec.samples[j].to<mpfr>(); }

std::function<mpfr(std::size_t)> detail::sample_phase(const WaveSpec& spec) {
  if (spec.times.empty()) return {};
  return [&spec](std::size_t j) {
    const mpfr t0 = spec.times.front().to<mpfr>();
    return mpfr((spec.times[j].to<mpfr>() - t0) / (spec.times.back().to<mpfr>() - t0));
  };
}

const std::vector<std::string>& catalogue_names() {
  static const std::vector<std::string> names{"sine", "triangle", "sawtooth-right", "sawtooth-left", "square"};
  return names;
}

// The one grammar of decimal text (decimal_value.hpp).
static bool is_decimal(const std::string& t) { return Decimal::read(t).has_value(); }

// A number written with a decimal comma, "0,5" or "-1,25e-3" (a European spreadsheet's export):
// one comma, and a decimal of our grammar with a point in its place.
bool decimal_comma(const std::string& text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) return false;
  std::string point = text;
  point[comma] = '.';
  return is_decimal(point);
}

namespace {
// check_decimal's decision, and the Decimal it read: each text is scanned once.
Decimal checked_decimal(const std::string& text, const std::string& what) {
  if (text.empty()) throw InputError(what + " is empty: expected a decimal number");
  std::optional<Decimal> d = Decimal::read(text);
  if (!d) {
    if (decimal_comma(text)) {
      std::string point = text;
      std::replace(point.begin(), point.end(), ',', '.');
      throw InputError(what + " = " + quoted(text) + " has a decimal comma: expected a decimal point (" + point + ")");
    }
    throw InputError(what + " = " + quoted(visible(text)) + ": expected a finite decimal number such as 0.5 or -3e-2 (exponent below 1e9)");
  }
  errno = 0;
  const long double v = std::strtold(text.c_str(), nullptr);
  if (errno == ERANGE && std::fabs(v) > 1) 
    throw InputError(what + " = " + quoted(text) + " overflows: expected a magnitude below 1e308");
  if (std::fabs(v) > static_cast<long double>(std::numeric_limits<double>::max()))
    throw InputError(what + " = " + quoted(text) + " overflows: expected a magnitude below 1e308");
  return std::move(*d);
}
}  // namespace

void check_decimal(const std::string& text, const std::string& what) { (void)checked_decimal(text, what); }

std::ostream& operator<<(std::ostream& out, const InputValue& v) { return out << v.text(); }

InputValue InputValue::read(const std::string& text, const std::string& what) {
  return InputValue(checked_decimal(text, what));
}

exact::Rational exact_decimal(const std::string& text, const std::string& what) {
  const auto d = Decimal::read(text);
  if (!d) check_decimal(text, what);  // the grammar's refusal (an exact value has no overflow)
  return rational(*d, what);
}

WaveSpec detail::fourier_from_table(const Table& table, const RowSource& source) {
  WaveSpec s;
  s.name = source.wave;
  s.kind = WaveKind::fourier;
  std::set<unsigned> seen;
  if (!table.header.empty() && table.header.size() != 3)
    throw InputError(source.name + ": header " + quoted(visible(table.header[0])) + "… has " + std::to_string(table.header.size()) +
                     " fields: expected three, such as 'k a_k b_k'");
  for (const auto& [line, tok] : table.rows) {
    const std::string where = source.where(line);
    if (tok.size() != 3)
      throw InputError(where + ": expected three fields 'k a_k b_k', got " + std::to_string(tok.size()));
    if (!std::regex_match(tok[0], std::regex("[0-9]{1,6}")))
      throw InputError(where + ": harmonic k = " + quoted(visible(tok[0])) + ": expected an integer 0 ≤ k ≤ " +
                     std::to_string(max_harmonic_index));
    const auto k = static_cast<unsigned>(std::stoul(tok[0]));
    if (k > max_harmonic_index)
      throw InputError(where + ": harmonic k = " + tok[0] + ": expected k ≤ " + std::to_string(max_harmonic_index));
    if (!seen.insert(k).second) throw InputError(where + ": harmonic k = " + tok[0] + " given twice");
    s.harmonics.push_back({k, *InputValue::read(tok[1], where + " a_" + tok[0]).decimal(),
                           *InputValue::read(tok[2], where + " b_" + tok[0]).decimal()});
  }
  if (s.harmonics.empty()) throw InputError("file " + quoted(visible(source.name)) + " has no coefficients: expected lines 'k a_k b_k'");
  return s;
}

WaveSpec detail::samples_from_table(const Table& table, const RowSource& source, const WaveReadOptions& options) {
  WaveSpec s;
  s.name = source.wave;
  const bool chosen = !options.column.empty();
  s.kind = WaveKind::samples;
  const auto& rows = table.rows;
  // A header of names and nothing numeric after it, or a non-numeric field further down.
  std::vector<std::vector<Decimal>> values;  // rows' fields, each read once
  values.reserve(rows.size());
  for (const auto& [line, tok] : rows) {
    values.emplace_back();
    values.back().reserve(tok.size());
    for (const auto& t : tok) {
      try {
        values.back().push_back(checked_decimal(t, source.where(line) + " sample"));
      } catch (const InputError& e) {
        const auto skip = preamble_lines(rows, source.arrays);
        if (!skip || line > *skip) throw;
        throw InputError(std::string(e.what()) + "; lines 1 to " + std::to_string(*skip) +
                         " look like a preamble before the header and the numbers: skip them with " +
                         options.skip_rows_name + " " + std::to_string(*skip));
      }
    }
  }
  std::size_t columns = rows.empty() ? 0 : rows[0].second.size();
  if (!chosen && rows.size() == 1 && table.header.empty()) {
    s.samples = std::move(values[0]);  // one line of values: one period
  } else {
    for (const auto& [line, tok] : rows)
      if (tok.size() != columns)
        throw InputError(source.where(line) + ": " + std::to_string(tok.size()) + " fields, line " +
                         std::to_string(rows[0].first) + " has " + std::to_string(columns) +
                         ": expected the same number on every line");
    if (!table.header.empty() && !rows.empty() && table.header.size() != columns)
      throw InputError(source.name + ": the header names " + std::to_string(table.header.size()) + " columns, the data have " +
                       std::to_string(columns) + ": expected one name per column");
    const auto& header = table.header;
    std::size_t vc = 0, tc = std::string::npos;  // value and time column (npos: none)
    if (chosen && (!rows.empty() || !header.empty())) {
      if (columns == 0) columns = header.size();
      vc = choose_column(options.column, header, columns, source.name);
      std::vector<std::size_t> time_columns;
      for (std::size_t i = 0; i < header.size(); ++i)
        if (is_time_name(header[i])) time_columns.push_back(i);
      if (time_columns.size() > 1)
        throw InputError(quoted(visible(source.name)) + ": the header names " + std::to_string(time_columns.size()) + " time columns, " +
                         quoted(visible(header[time_columns[0]])) + " and " + quoted(visible(header[time_columns[1]])) +
                         ": expected at most one column named 'time' or 't'");
      if (!time_columns.empty()) tc = time_columns[0];
      if (vc == tc)
        throw InputError("column " + quoted(visible(options.column)) + " of " + quoted(visible(source.name)) + " is its time column " +
                         quoted(visible(header[tc])) + ": expected a column of values");
      if (!header.empty() && std::count(header.begin(), header.end(), header[vc]) == 1)
        s.column = header[vc];
      else
        s.column = std::to_string(vc + 1);
      s.name = source.wave + "#" + s.column;
    } else if (chosen) {
      // No rows and no header: nothing to choose from; the sample count below says so.
    } else if (columns == 2) {
      const bool t0 = !header.empty() && is_time_name(header[0]);
      const bool t1 = !header.empty() && is_time_name(header[1]);
      // Two whole numbers on every line, split at ',': one column written with decimal commas.
      const auto integer = [](const std::string& t) { return !t.empty() && std::all_of(t.begin(), t.end(), [](char ch) {
                                                                return ch >= '0' && ch <= '9';
                                                              }); };
      const bool commas = header.empty() && table.comma_separated && std::all_of(rows.begin(), rows.end(), [&](const auto& row) {
                            const std::string& a = row.second[0];
                            return integer(a.substr(a[0] == '-' || a[0] == '+' ? 1 : 0)) && integer(row.second[1]);
                          });
      if (commas)
        throw InputError(source.name + ": two columns of whole numbers and no header, as one column written with "
                         "decimal commas reads ('" + rows[0].second[0] + "," + rows[0].second[1] +
                         "'): expected decimal points (" + rows[0].second[0] + "." + rows[0].second[1] +
                         "), or a header naming one column 'time' (or 't')");
      if (header.empty() || t0 == t1)
        throw InputError(source.name + ": two columns" +
                         (header.empty() ? std::string(" and no header")
                                         : " named " + quoted(visible(header[0])) + ", " + quoted(visible(header[1]))) +
                         ": expected one column of values, or a header naming one column 'time' (or 't'), e.g. 'time,value'");
      tc = t0 ? 0 : 1;
      vc = 1 - tc;
    } else if (columns > 2) {
      std::string names;
      for (const auto& h : header) names += (names.empty() ? " (" : ", ") + quoted(visible(h));
      throw InputError(source.name + ": " + std::to_string(columns) + " columns" + (names.empty() ? "" : names + ")") +
                       ": expected one column of values, two with one named 'time', or a value column chosen by name or "
                       "1-based index (" + options.column_name + ")");
    }
    for (auto& row : values) {
      if (tc != std::string::npos) s.times.push_back(std::move(row[tc]));
      s.samples.push_back(std::move(row[vc]));
    }
    if (!header.empty() && vc < header.size()) s.value_column = header[vc];
    if (tc != std::string::npos) s.time_column = header[tc];
  }
  if (s.samples.size() < 2 + (s.times.empty() ? 0 : 1))
    throw InputError("file " + quoted(visible(source.name)) + " has " + std::to_string(s.samples.size()) + " sample(s): expected at least " +
                     (s.times.empty() ? "2" : "3 (one period and its end point)"));
  if (!s.times.empty()) {
    // One period with its end point: the time column sets the period, the last value repeats the first.
    PrecisionScope scope(60);
    for (std::size_t j = 1; j < s.times.size(); ++j)
      if (!(exact_value(s.times[j]) > exact_value(s.times[j - 1])))
        throw InputError(source.name + ": time " + quoted(visible(s.times[j].text())) + " after " + quoted(visible(s.times[j - 1].text())) +
                         ": expected strictly increasing time stamps");
    const mpfr period = exact_value(s.times.back()) - exact_value(s.times.front());
    for (std::size_t j = 1; j < s.times.size(); ++j)
      if (exact_value(s.times[j]) - exact_value(s.times[j - 1]) < period * mpfr("1e-12"))
        throw InputError(source.name + ": time stamps " + quoted(visible(s.times[j - 1].text())) + " and " + quoted(visible(s.times[j].text())) +
                         " are closer than 1e-12 of the period: expected distinct phases");
    if (exact_value(s.samples.back()) == exact_value(s.samples.front())) {
      s.samples.pop_back();  // the end point: its time stays, as the period's end
    } else if (const auto dt = uniform_step(s.times)) {
      // No end point, the stamps of a DAQ (t_j = t_0 + j·dt): the samples at φ = j/N, period N·dt.
      s.period_from_stamps = Decimal::read(format_significant(mpfr(*dt * s.samples.size()), 40));  // defined to 40 digits
      s.times.clear();
    } else {
      throw InputError(source.name + ": the last value " + quoted(visible(s.samples.back().text())) + " differs from the first " +
                       quoted(visible(s.samples.front().text())) +
                       " and the time stamps are not uniform, so the period is unknown: append the line at time t0 + "
                       "period with the first value (the end point), or give uniform stamps t_j = t0 + j dt (period N dt)");
    }
  }
  // Several periods in one record (uniform phases): averaged where the caller says how many,
  // refused where they are recognised and the caller has not said.
  const bool uniform_phases = s.times.empty() || uniform_step(s.times).has_value();
  const std::size_t n = s.samples.size();
  if (options.periods < 0 || options.periods > max_record_periods)
    throw InputError(options.periods_name + " = " + std::to_string(options.periods) + ": expected an integer from 1 to " +
                     std::to_string(max_record_periods));
  if (options.periods > 1) {
    const std::size_t k = static_cast<std::size_t>(options.periods);
    if (!uniform_phases || n % k != 0 || n / k < 2)
      throw InputError(options.periods_name + " = " + std::to_string(k) + " for " + quoted(visible(source.name)) + " (" +
                       std::to_string(n) + " samples" + (uniform_phases ? "" : ", time stamps not uniform") +
                       "): expected uniformly spaced samples, a whole number of them (at least 2) in each period");
    // The K pieces must be periods of one signal: shifted by N/K the record repeats within half
    // its rms (a K that is not the record's: about √2, its pieces shifted by a fraction of a period).
    if (const Repetition rep(s.samples); rep.varies()) {
      const double r = rep.r(static_cast<double>(n / k));
      if (!(r < 0.5)) {
        const auto seen = repeated_periods(s.samples);
        char share[32];
        std::snprintf(share, sizeof share, "%.2g", 100 * r);
        throw InputError(options.periods_name + " = " + std::to_string(k) + " for " + quoted(visible(source.name)) + ": its " +
                         std::to_string(k) + " pieces of " + std::to_string(n / k) + " samples differ by " + share +
                         " % rms of the signal: expected " + std::to_string(k) + " periods of one signal" +
                         (seen ? " (the record looks like " + std::to_string(seen->first) + ")" : ""));
      }
    }
    std::vector<Decimal> folded;
    for (std::size_t j = 0; j < n / k; ++j) {
      std::vector<const Decimal*> same_phase;
      for (std::size_t i = 0; i < k; ++i) same_phase.push_back(&s.samples[j + i * (n / k)]);
      folded.push_back(decimal_sum(same_phase));
    }
    s.samples = std::move(folded);
    if (!s.times.empty()) s.times.resize(n / k + 1);  // t_0 … t_{N/K}: uniform, the first period
    if (s.period_from_stamps) {
      PrecisionScope scope(60);
      s.period_from_stamps = Decimal::read(format_significant(mpfr(s.period_from_stamps->to<mpfr>() / static_cast<long>(k)), 40));
    }
    s.periods_averaged = static_cast<unsigned>(k);
  } else if (options.periods == 0 && uniform_phases) {
    if (const auto repeated = repeated_periods(s.samples)) {
      const auto [k, relative] = *repeated;
      char share[32];
      std::snprintf(share, sizeof share, "%.2g", 100 * relative);
      throw InputError(source.name + ": the " + std::to_string(n) + " samples look like " + std::to_string(k) +
                       " periods (shifted by N/" + std::to_string(k) + " they differ from themselves by " + share +
                       " % rms of the signal): expected one period; give " + options.periods_name + " " +
                       std::to_string(k) + " to average them" + (n % k ? " (after cutting the record to a whole number of periods)" : "") +
                       ", or " + options.periods_name + " 1 if the record is one period");
    }
  }
  const std::size_t period = smallest_period(s.samples, s.times);
  if (period == 1)
    throw InputError("sampled waveform " + quoted(visible(source.wave)) + " is constant: expected a signal with non-zero amplitude");
  if (s.times.empty() && s.samples.size() >= 3 && exact_value(s.samples.back()) == exact_value(s.samples.front())) {
    throw InputError(source.name + ": the last sample " + quoted(visible(s.samples.back().text())) +
                     " repeats the first: a one-column file holds one period without its end point (y_j at phi = j/N); "
                     "remove the last value, or add a time column (then the end point is expected)");
  }
  if (period < s.samples.size())
    throw InputError(source.name + ": the samples repeat every " + std::to_string(period) + " of " + std::to_string(s.samples.size()) +
                     ": the file holds " + std::to_string(s.samples.size() / period) +
                     " identical periods; expected one period (the frequency f is that of one period)");
  return s;
}

std::string column_unit(const std::string& header) {
  // After '_' or '/' the unit is a run of anything but spaces, '_' and '/' ("x_µm": \w is ASCII).
  static const std::regex unit_re(R"(.*?(?:[\[(]\s*(\S+?)\s*[\])]|[_/]\s*([^\s_/]+)|\s+in\s+(\S+))\s*)", std::regex::icase);
  std::smatch m;
  std::string unit;
  if (std::regex_match(header, m, unit_re))
    for (int g = 1; g <= 3; ++g)
      if (m[g].matched) unit = m[g].str();
  return unit;
}

std::optional<StampedPeriod> stamped_period(const WaveSpec& wave) {
  if (wave.kind != WaveKind::samples || (wave.times.empty() && !wave.period_from_stamps)) return std::nullopt;
  const std::string unit = column_unit(wave.time_column);
  static const std::map<std::string, const char*> seconds{{"s", "1"},     {"sec", "1"},   {"ms", "1e-3"}, {"us", "1e-6"},
                                                          {"\xC2\xB5s", "1e-6"}, {"\xCE\xBCs", "1e-6"}, {"ns", "1e-9"},
                                                          {"min", "60"}};
  StampedPeriod p;
  p.assumed = unit.empty();
  p.unit = p.assumed ? "s" : unit;
  const auto it = seconds.find(p.unit);
  if (it == seconds.end()) return std::nullopt;
  const mpfr span = wave.period_from_stamps ? wave.period_from_stamps->to<mpfr>()
                                            : mpfr(wave.times.back().to<mpfr>() - wave.times.front().to<mpfr>());
  p.seconds = span * mpfr(it->second);
  return p;
}

WaveSpec parse_wave(const std::string& text) { return parse_wave(text, WaveReadOptions{}); }

WaveSpec parse_wave(const std::string& text, const WaveReadOptions& options) {
  WaveSpec s;
  s.name = text;
  const bool chosen = !options.column.empty();
  if (chosen) {
    const auto colon = text.find(':');
    const std::string head = text.substr(0, colon);
    const bool known = std::find(catalogue_names().begin(), catalogue_names().end(), text) != catalogue_names().end() ||
                       text == "harmonic" || text == "tri" || text == "str" || text == "stl" || text == "sqr" ||
                       (colon != std::string::npos && (head == "power" || head == "fourier"));
    if (known)
      throw InputError("column " + quoted(visible(options.column)) + " given for wave " + quoted(visible(text)) +
                       ": a column applies to samples:FILE waves only, expected no column");
  }
  if (options.skip_rows < 0 || static_cast<std::size_t>(options.skip_rows) > max_table_lines)
    throw InputError(options.skip_rows_name + " = " + std::to_string(options.skip_rows) + ": expected an integer from 0 to " +
                     std::to_string(max_table_lines));
  if (options.skip_rows != 0 && text.rfind("samples:", 0) != 0 && text.rfind("fourier:", 0) != 0)
    throw InputError(options.skip_rows_name + " " + std::to_string(options.skip_rows) + " given for wave " + quoted(visible(text)) +
                     ": rows are skipped in samples:FILE and fourier:FILE waves only");
  if (options.periods != 0 && text.rfind("samples:", 0) != 0)
    throw InputError(options.periods_name + " " + std::to_string(options.periods) + " given for wave " + quoted(visible(text)) +
                     ": the periods of a record apply to samples:FILE waves only");
  if (text == "sine" || text == "harmonic") { s.kind = WaveKind::sine; s.name = "sine"; return s; }
  if (text == "triangle" || text == "tri") { s.kind = WaveKind::triangle; s.name = "triangle"; return s; }
  if (text == "sawtooth-right" || text == "str") { s.kind = WaveKind::sawtooth_right; s.name = "sawtooth-right"; return s; }
  if (text == "sawtooth-left" || text == "stl") { s.kind = WaveKind::sawtooth_left; s.name = "sawtooth-left"; return s; }
  if (text == "square" || text == "sqr") { s.kind = WaveKind::square; s.name = "square"; return s; }
  const auto colon = text.find(':');
  const std::string head = text.substr(0, colon), arg = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (colon != std::string::npos && head == "power") {
    s.kind = WaveKind::power;
    s.exponent = *InputValue::read(arg, "power exponent p in " + quoted(visible(text))).decimal();
    // An exponent that underflows (power:1e-5000) is 0 here, not an exception.
    if (!(s.exponent.to<long double>() >= 1))
      throw InputError("power exponent p = " + quoted(arg) + ": expected p ≥ 1");
    return s;
  }
  if (colon != std::string::npos && head == "fourier") {
    if (arg.empty()) throw InputError("wave " + quoted(visible(text)) + ": expected fourier:FILE");
    return detail::fourier_from_table(detail::read_table_file(arg, text, options.skip_rows), detail::file_source(arg, text));
  }
  if (colon != std::string::npos && head == "samples") {
    if (arg.empty()) throw InputError("wave " + quoted(visible(text)) + ": expected samples:FILE");
    return detail::samples_from_table(detail::read_table_file(arg, text, options.skip_rows), detail::file_source(arg, text),
                                      options);
  }
  const std::string hint = did_you_mean(text, {"sine", "triangle", "sawtooth-right", "sawtooth-left", "square", "power:P",
                                                "fourier:FILE", "samples:FILE"});
  throw InputError("unknown wave " + quoted(visible(text)) +
                   ": expected sine, triangle, sawtooth-right, sawtooth-left, square, power:P, fourier:FILE or samples:FILE" +
                   (hint.empty() ? "" : "; " + visible(hint)));
}

std::vector<std::pair<std::string, std::string>> describe_normalisation(const WaveSpec& wave, int digits) {
  if (digits < min_digits || digits > max_digits)
    throw InputError("digits = " + std::to_string(digits) + ": expected " + std::to_string(min_digits) + " to " +
                     std::to_string(max_digits) + " significant digits");
  const auto text = [&](const mpfr& x) { return format_significant(x, digits); };
  const unsigned guarded = static_cast<unsigned>(digits) + 10;
  if (wave.kind == WaveKind::fourier) {
    // The FourierSeries constructor normalises (extrema by root search): build it, 10 guard digits.
    PrecisionScope scope(guarded);
    const auto w = make_waveform<mpfr>(wave);
    const Normalisation<mpfr>& nz = w->normalisation();
    std::size_t count = 0;
    for (const auto& h : wave.harmonics) count += h.k != 0;
    return {{"harmonics", std::to_string(count)},
            {"mean_removed", text(nz.offset)},
            {"peak_to_peak", text(mpfr(2 * nz.scale))},
            {"scale", text(nz.scale)},
            {"factor", text(mpfr(1 / nz.scale))}};
  }
  if (wave.kind != WaveKind::samples)
    return {{"normalisation", "none (catalogue wave, already zero mean and max - min = 2)"}};
  const SampleNormalisation nz = normalise_samples(
      wave.name, wave.samples.size(), [&](std::size_t j) { return detail::sample_value(wave, j); },
      detail::distinct_digits(wave), detail::sample_phase(wave), static_cast<int>(guarded));
  std::string period = "1 (uniform phases)";
  if (wave.period_from_stamps) {
    period = text(wave.period_from_stamps->to<mpfr>());
  } else if (!wave.times.empty()) {
    // t_N − t_0 with the digits both stamps share cancelled: estimated at 60 digits first.
    int cancelled = 0;
    {
      PrecisionScope scope(60);
      const mpfr a = wave.times.front().to<mpfr>(), b = wave.times.back().to<mpfr>();
      cancelled = static_cast<int>(std::ceil(static_cast<double>(log10(mpfr(std::max(abs(a), abs(b)) / (b - a))))));
    }
    PrecisionScope scope(guarded + static_cast<unsigned>(std::max(cancelled, 0)));
    period = text(mpfr(wave.times.back().to<mpfr>() - wave.times.front().to<mpfr>()));
  }
  const std::string column =
      !wave.value_column.empty() ? wave.value_column : !wave.column.empty() ? wave.column : std::string("1");
  PrecisionScope scope(nz.digits);
  // The mean is accurate to about 10^-(digits − log10 N − 2)·max|y| (normalise_samples): below that
  // (a zero mean computed as ±1e-22) its significant digits would be rounding noise, shown as 0.
  const int log_n = static_cast<int>(std::ceil(std::log10(static_cast<double>(wave.samples.size()))));
  const mpfr accuracy = pow(mpfr(10), -(static_cast<int>(nz.digits) - log_n - 2)) * std::max(abs(nz.lo), abs(nz.hi));
  const mpfr mean = abs(nz.mean) <= accuracy ? mpfr(0) : nz.mean;
  // Averaged periods: the samples are sums of K values, the raw values their means.
  const long k = static_cast<long>(wave.periods_averaged);
  std::vector<std::pair<std::string, std::string>> rows{{"samples", std::to_string(wave.samples.size())}};
  if (k > 1) rows.emplace_back("periods", std::to_string(k) + " (averaged sample by sample)");
  for (auto& row : std::vector<std::pair<std::string, std::string>>{
          {"end_point", wave.period_from_stamps
                            ? "none (uniform stamps: period N dt" + (k > 1 ? "/" + std::to_string(k) : std::string()) + ")"
                        : wave.times.empty() ? "none"
                                             : "dropped"},
          {"time_column", wave.times.empty() && !wave.period_from_stamps ? "none"
                          : wave.time_column.empty()                          ? "unnamed"
                                                                              : wave.time_column},
          {"period", period},
          {"column", column},
          {"raw_mean", text(mpfr(mean / k))},
          {"raw_min", text(mpfr(nz.lo / k))},
          {"raw_max", text(mpfr(nz.hi / k))},
          {"scale", text(mpfr(nz.scale / k))},
          {"factor", text(mpfr(k / nz.scale))}})
    rows.push_back(std::move(row));
  return rows;
}

}  // namespace vibrofric
