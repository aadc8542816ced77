// The tool's shared declarations: a command's typed flags (Flags), the command table's entries and
// the readers and helpers more than one file uses. Defined in cli.cpp (the table, the command line),
// flags.cpp (the flags' readers), common.cpp (waves, precision, output) and cmd_*.cpp (the commands).
#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/inplane.hpp"
#include "vibrofric/api/profile_spec.hpp"

namespace vibrofric::tool {

enum class Format { text, csv, json };

// A command's flags as typed values. CLI11 fills them while it parses: each flag's reader checks
// the text as typed (our decimal and integer grammars, the names of choices) and throws InputError
// quoting it. What is not given keeps its default.
struct Flags {
  std::string command;
  // Wave
  std::optional<std::string> wave;
  WaveReadOptions read;
  bool diagnostics = false;
  // Precision
  std::optional<NumberType> type;
  std::string type_text;
  std::optional<int> digits;
  bool no_escalate = false;
  bool certify = false;
  bool free_velocity = false;  // mu --free-velocity: the ratchet's, for a transverse or curved drive too
  bool trace = false;  // physical --trace
  // Solver controls (solver.hpp Options): a budget the solver cannot meet is an error, never a value.
  Options solver;
  // mu, psi, trace: β and γ; sweep: their values
  InputValue beta, gamma;
  std::vector<InputValue> betas, gammas;
  std::optional<std::string> profile_text;
  ProfileSpec profile;
  std::optional<Format> format;
  Quantity quantity = Quantity::mu;
  unsigned threads = 0;
  std::optional<int> points, harmonics;
  std::optional<std::string> output, claim;
  // Rig dynamics (model.md): κ, Ω, ζ
  InputValue kappa, omega, zeta;
  // In-plane oscillation (model.md): a_l, the phase P, the in-plane wave
  InputValue longitudinal, transverse, phase;
  std::optional<std::string> in_plane_wave;
  // physical, by flag name: each number input's value, or a swept input's values (FROM:TO:N), read
  // by read_physical; shape and unit as typed.
  std::map<std::string, std::vector<InputValue>> physical;
  std::map<std::string, std::string> physical_texts;
  std::set<std::string> physical_ranges;  // the inputs given as FROM:TO:N
};

using Reader = void (*)(Flags&, const std::string& text);

// One flag of a command: its name, the value's placeholder (empty: a switch), the help line, the
// default shown by --help (empty: none) and the reader of its text (none: physical's inputs, read
// by read_physical).
struct FlagSpec {
  const char* name;
  const char* value;
  const char* help;
  const char* fallback;
  Reader read;
};

struct CommandSpec {
  const char* name;
  const char* synopsis;
  std::vector<FlagSpec> flags;
  std::vector<const std::vector<FlagSpec>*> groups;
  std::string footer;
  int (*run)(const Flags&);
};

// The command table (cli.cpp) and the commands (cmd_*.cpp).
const std::vector<CommandSpec>& commands();
int run_mu(const Flags& f);
int run_psi(const Flags& f);
int run_sweep(const Flags& f);
int run_physical(const Flags& f);
int run_trace(const Flags& f);
int run_fit(const Flags& f);
int run_verify(const Flags& f);
int run_version(const Flags& f);

// The tool as main() runs it (cli.cpp): the exit status, 0, 1 for a solver failure or 2 for bad input.
int run_tool(int argc, char** argv);

// The flags' readers and the flag groups several commands share (flags.cpp).
int integer(const std::string& text, const std::string& what, long lo, long hi);
bool switch_value(const std::string& text, const std::string& name);
std::string hint(const std::string& typed, const std::vector<std::string>& known);
Format format_named(const std::string& text);
std::vector<std::string> split(const std::string& s, char sep);
std::vector<std::string> value_range(const std::string& spec, const std::string& flag, bool descending);
std::vector<InputValue> read_all(const std::vector<std::string>& texts, const std::string& what);
// physical's flag `name` (no leading --): a number, a range of one of the swept inputs (v0, A, f,
// F-N, u-mean), or the text of shape and unit.
void read_physical(Flags& f, const std::string& name, const std::string& text);
extern const std::vector<std::string> kSweptPhysical;
extern const std::vector<FlagSpec> kWaveFlags;
extern const std::vector<FlagSpec> kPrecisionFlags;
extern const std::vector<FlagSpec> kPhysicalPrecisionFlags;
extern const std::vector<FlagSpec> kSolverFlags;
extern const std::vector<FlagSpec> kRigFlags;
extern const std::vector<FlagSpec> kInPlaneFlags;
extern const FlagSpec kCertifyFlag;
void decimal_beta(Flags& f, const std::string& t);
void profile_named(Flags& f, const std::string& t);
void format_of_point(Flags& f, const std::string& t);
void format_of_rows(Flags& f, const std::string& t);
void text_beta(Flags& f, const std::string& t);
void text_gamma(Flags& f, const std::string& t);

// Helpers of the commands (common.cpp): required flags, precision and batch options, CSV and JSON
// output, the wave, --certify.
const std::string& need(const Flags& f, const std::optional<std::string>& value, const std::string& name);
const InputValue& need(const Flags& f, const InputValue& value, const std::string& name);
Precision precision_of(const Flags& f);
BatchOptions batch_options(const Flags& f);
// The in-plane drive of --longitudinal, --transverse, --phase, --in-plane-wave and --wave constant (none: the
// paper's model).
std::optional<InPlaneSpec> inplane_options(const Flags& f);
// The normal wave of --wave: read_wave's, or for --wave constant (with the in-plane drive) a
// WaveSpec named "constant" that the in-plane solver does not read.
WaveSpec normal_wave(const Flags& f, const std::optional<InPlaneSpec>& inplane);
void write_csv_row(const std::vector<std::string>& fields);
nlohmann::ordered_json json_record(const std::vector<std::string>& names, const std::vector<std::string>& values);
extern std::string pending_diagnostics;
WaveSpec read_wave(const Flags& f);
std::optional<Certifier> certifier_of(const Flags& f, const WaveSpec& wave, const BatchOptions& opt);
Certificate certified(const Certifier& certifier, Quantity q, const Point& p, const Precision& precision,
                      const std::string& printed);
std::vector<std::pair<std::string, std::string>> certificate_fields(const Certificate& c, bool enclosure);

}  // namespace vibrofric::tool
