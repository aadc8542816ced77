// The claims catalogue: one entry per row of model.md's claims table — the paper's equations
// (Eqs. 6, 13, 17, 18, 19, 20–21, 22, 23, 24), its statements (Eqs. 7–13 "after expanding and
// rearranging", Eq. 6 as printed in the jumping range, Sec. 3's static coefficient and
// entanglement, Sec. 3.1's continuity and uniqueness, Sec. 3.2's convexity and the range of Eq. 23,
// Figs. 2, 3 and 4, the abstract's scope for curved contacts) — and, apart from them (source
// "model.md (correction)" or "model.md (extension)"), the statements of model.md itself that the
// suite found to need correction (β_c table), Eq. 6, Sec. 3 and the flat-punch limit carried
// over to curved contacts by the MDR, and the rig dynamics' limits; and (source "Part II
// (abstract)") the two claims of the abstract of the series' Part II. Each entry says how the claim is checked; its check runs the
// high-precision solver and returns the measured deviation and the verdict. A claim is never
// adjusted to fit: the verdict is what is measured, and it is the same at every precision of the
// documented range.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace vibrofric {

enum class Verdict {
  holds,                // deviation within the requested precision
  holds_approximately,  // the statement is approximate (or asymptotic); its measured size is reported
  fails,                // a counterexample is given, with the statement the solver and a proof support
};
std::string verdict_name(Verdict v);

// A measured value that the verdict rests on, beyond the largest deviation: as printed, and its
// parts as named fields, which is what the tests and the report read (never the printed text).
struct Measurement {
  std::string name;   // e.g. "order of D in 1/N (N = 64 -> 256)"
  std::string value;  // as printed, e.g. "0.998 to 1.002"
  std::vector<std::pair<std::string, std::string>> fields;  // e.g. {"lo", "0.998"}, {"hi", "1.002"}; one
                                                            // number or word alone: {"value", ...}
  // The field named `key`; InputError if there is none.
  const std::string& field(const std::string& key) const;
};

struct ClaimCheck {
  std::string key;        // short name for tests and the command line, e.g. "eq24"
  std::string id;         // the paper's label, e.g. "Eq. 24"
  std::string source;     // "paper", "model.md (correction)" or "model.md (extension)"
  std::string statement;  // as the paper (or model.md) makes it
  std::string method;     // symbolic proof / high-precision comparison / independent method
  std::string how;        // what the check computes, with its grid
  std::string criterion;  // how the verdict follows from the numbers
  std::string proof;      // derivation in proofs/ ("" if none)
  int digits = 0;         // requested precision; the solver runs with guard digits beyond
  std::size_t cases = 0;
  double deviation = 0;   // largest deviation of the statement as made, rounded to double (it
                          // underflows to 0 beyond ~300 digits: deviation_text keeps the exponent)
  std::string deviation_text;  // the same at the working precision, 3 significant digits ("1.23e-402")
  std::string deviation_unit;  // what it measures: "relative", "absolute, in mu0", "|gamma_min - 0.6|", ...
  std::string worst;      // the case with the largest deviation (the counterexample if it fails)
  Verdict verdict = Verdict::holds;
  // "certified" where the verdict is proven by a certified computation on the claim's grid (exact
  // rationals or interval enclosures, README "Certified values"): the closed form equal to the
  // exact value, or inside the enclosure (for a counterexample: outside it); else "numerical": it
  // rests on the high-precision solver and its error estimate. The note says how, or what keeps
  // the claim numerical.
  std::string certification = "numerical";
  std::string certification_note;
  std::string scope;      // where the verdict holds, when that is part of it (e.g. a β range)
  std::string fails_where;  // for an approximate statement: where it does not hold ("" if nowhere checked)
  std::string corrected;  // the statement the solver and a proof support, when it differs
  std::optional<double> corrected_deviation;  // its largest measured deviation (none: no corrected statement)
  std::string corrected_deviation_text;       // the same at the working precision ("" if none)
  std::vector<Measurement> measured;
};

// The verdict as verify prints it: "holds (certified)", "fails (numerical)", …; an approximate
// statement's verdict is a measured size, printed alone.
std::string verdict_text(const ClaimCheck& c);

struct ClaimEntry {
  std::string key, id, source, statement, method, proof;
  ClaimCheck (*check)(int digits);
};

// The catalogue, in the order of model.md.
const std::vector<ClaimEntry>& claims_catalogue();

// One claim by key ("eq6", …, "fig4-scaling", "eqs7-13", "eq6-jumping", "entanglement",
// "continuity", "uniqueness", "convexity", "eq23-range", "fig2", "beta-c", "scope-wearflat",
// "scope-numerics", "curved-eq6-sec3", "curved-power-flat", "rig-limits", "part2-limits",
// "part2-resonance", "inplane-rigid", "inplane-ratchet", "inplane-combined", "inplane-transverse"); throws InputError for
// an unknown key.
ClaimCheck check_claim(const std::string& key, int digits);

// Every claim at `digits` significant digits (10 to 300, the range over which the verdicts are tested
// to be the same; more digits work but the curved-contact claims then take hours).
std::vector<ClaimCheck> verify_claims(int digits);
inline constexpr int min_verify_digits = 10;  // the front ends' range for verify
inline constexpr int max_verify_digits = 300;

// The fields of a check as the JSON document below and the Python module's dicts show them, in
// that order: f(name, value) with value a std::string, a std::size_t (cases), a
// std::optional<std::string> (corrected_deviation: none without a corrected statement) or the
// measurements.
template <class F>
void for_each_field(const ClaimCheck& c, F&& f) {
  f("key", c.key);
  f("id", c.id);
  f("source", c.source);
  f("statement", c.statement);
  f("method", c.method);
  f("how", c.how);
  f("criterion", c.criterion);
  f("proof", c.proof);
  f("worst", c.worst);
  f("verdict", verdict_name(c.verdict));
  f("certification", c.certification);
  f("certification_note", c.certification_note);
  f("scope", c.scope);
  f("fails_where", c.fails_where);
  f("corrected", c.corrected);
  f("cases", c.cases);
  f("deviation", c.deviation_text);
  f("deviation_unit", c.deviation_unit);
  f("corrected_deviation", c.corrected_deviation ? std::optional<std::string>(c.corrected_deviation_text) : std::nullopt);
  f("measured", c.measured);
}

// The checks as one JSON document (`verify --format json`, the report generator): {"digits": D,
// "claims": [{key, id, source, statement, method, how, criterion, proof,
// worst, verdict, certification, certification_note, scope, fails_where, corrected, cases,
// deviation, deviation_unit,
// corrected_deviation, measured: [{name, value, fields: {key: value, ...}}, ...]}, ...]}. Deviations are decimal strings at
// the working precision (a JSON number would pass through a double and underflow beyond 300
// digits); corrected_deviation is null where a claim has no corrected statement.
std::string claims_json(const std::vector<ClaimCheck>& checks, int digits);

}  // namespace vibrofric
