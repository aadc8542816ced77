// The paper's claims (model.md, "The paper's claims that the suite verifies"), each decided by
// the high-precision solver: Eq. 6, 13, 17, 18, 19, 21, 22.
#pragma once
#include <string>
#include <vector>

namespace vibrofric {

enum class Verdict {
  holds,                // deviation within the requested precision
  holds_approximately,  // deviation small but above the requested precision (size reported)
  fails,                // counterexample given
};
std::string verdict_name(Verdict v);

struct ClaimCheck {
  std::string id;         // the paper's equation, e.g. "Eq. 17"
  std::string statement;  // as the paper makes it
  std::string method;     // how it is checked, with the number of cases
  int digits = 0;         // requested precision; the solver runs with guard digits beyond
  double deviation = 0;   // largest relative deviation over the cases (0: exact)
  std::string worst;      // the case with the largest deviation
  Verdict verdict = Verdict::holds;
  std::size_t cases = 0;
};

// Deviation at or below 10^-digits: holds; at or below 1e-3: holds approximately; else fails.
std::vector<ClaimCheck> verify_claims(int digits);

}  // namespace vibrofric
