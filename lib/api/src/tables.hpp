// The readers of user waves and profiles in two steps (README, "File formats"; model.md,
// "Waveform catalogue"): a file's text becomes rows of fields, and rows are checked and become a
// WaveSpec or ProfileSpec. A front end that holds arrays (arrays.hpp) builds the rows itself, so
// an array is checked exactly as a file holding the same numbers, with its messages naming
// label[j] where a file's name PATH:LINE.
#pragma once
#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/limits.hpp"
#include "vibrofric/api/profile_spec.hpp"

namespace vibrofric::detail {

// Where rows come from, for messages: a file (rows by PATH:LINE) or a front end's arrays (rows by
// label[j], j = line − 1 − header_lines, the array index).
struct RowSource {
  std::string name;  // the path, or the label
  std::string wave;  // the wave as messages name it: samples:PATH as typed, or the label
  bool arrays = false;
  int header_lines = 0;
  std::string where(int line) const;
};
RowSource file_source(const std::string& path, const std::string& wave);
RowSource array_source(const std::string& label, int header_lines);

using Rows = std::vector<std::pair<int, std::vector<std::string>>>;  // line number, fields

struct Table {
  std::vector<std::string> header;
  Rows rows;
  bool comma_separated = false;  // read from text, every row's fields split at ','
};

// A user wave file's text as a table: a UTF-8 byte-order mark and CR line ends are dropped, '#'
// starts a comment, blank lines are skipped; a line with ';' outside double quotes has its fields
// between the ';' (else one with ',' between the ','; libcsv, RFC 4180: a quoted field may hold
// the separator), so a header may hold spaces ('time [s], value'); a line with tabs has them
// between runs of tabs, any other line between runs of whitespace. A first line without any
// number is the header. Between ';' a number may be written with a decimal comma ('0,5'). A line
// that is not UTF-8 is read as Windows-1252. The first skip_rows lines (a preamble) are not read;
// line numbers stay the file's.
Table read_table(std::istream& in, const RowSource& source, int skip_rows = 0);
// MissingFileError where the path does not exist.
Table read_table_file(const std::string& path, const std::string& wave, int skip_rows = 0);

// The rows of a samples:FILE, or of a fourier:FILE ('k a_k b_k'), checked: the WaveSpec that
// parse_wave returns for that file.
WaveSpec samples_from_table(const Table& table, const RowSource& source, const WaveReadOptions& options);
WaveSpec fourier_from_table(const Table& table, const RowSource& source);

// The rows 'r f' of a profile:FILE, checked: r from 0 and increasing, f(0) = 0, f non-decreasing
// and convex. `wave` of the source is the profile as typed (profile:PATH), its name.
ProfileSpec profile_from_rows(const Rows& rows, const RowSource& source);

}  // namespace vibrofric::detail
