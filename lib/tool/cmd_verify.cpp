// version (of vibrofric, the compiler, Boost, MPFR and GMP) and verify (every claim of the paper
// and of model.md, as text or JSON).
#include <boost/version.hpp>

#include <cstdio>
#include <iostream>
#include <vector>

#include "cli.hpp"
#include "vibrofric/verification/claims.hpp"

namespace vibrofric::tool {

int run_version(const Flags&) {
  std::printf("vibrofric %s\n", VIBROFRIC_VERSION);
#if defined(__clang__)
  std::printf("compiler clang %s\n", __clang_version__);
#elif defined(__GNUC__)
  std::printf("compiler gcc %s\n", __VERSION__);
#else
  std::printf("compiler unknown\n");
#endif
  std::printf("boost %d.%d.%d\n", BOOST_VERSION / 100000, BOOST_VERSION / 100 % 1000, BOOST_VERSION % 100);
  std::printf("mpfr %s\n", mpfr_get_version());
  std::printf("gmp %s\n", gmp_version);
  return 0;
}

int run_verify(const Flags& f) {
  const int digits = f.digits.value_or(50);
  std::vector<ClaimCheck> checks;
  if (f.claim)
    checks.push_back(check_claim(*f.claim, digits));
  else
    checks = verify_claims(digits);
  if (f.format == Format::json) {
    std::cout << claims_json(checks, digits) << '\n';
    return 0;
  }
  std::printf("%-28s %-8s %-20s %-9s %s\n", "claim", "cases", "verdict", "deviation", "statement");
  for (const auto& c : checks) {
    std::printf("%-28s %-8zu %-20s %-9s %s\n", c.id.c_str(), c.cases, verdict_text(c).c_str(),
                c.deviation_text.c_str(), c.statement.c_str());
  }
  std::printf("\nrequested precision: %d digits\n", digits);
  for (const auto& c : checks) {
    std::printf("\n%s (%s, %s) — %s\n", c.id.c_str(), c.key.c_str(), c.source.c_str(), verdict_text(c).c_str());
    std::printf("  method:    %s%s\n", c.method.c_str(), c.proof.empty() ? "" : (" (" + c.proof + ")").c_str());
    std::printf("  checked:   %s\n", c.how.c_str());
    std::printf("  criterion: %s\n", c.criterion.c_str());
    std::printf("  %-10s %s\n", (c.certification + ":").c_str(), c.certification_note.c_str());
    std::printf("  deviation: %s (%s)\n", c.deviation_text.c_str(), c.deviation_unit.c_str());
    std::printf("  worst:     %s\n", c.worst.c_str());
    if (!c.scope.empty()) std::printf("  scope:     %s\n", c.scope.c_str());
    if (!c.fails_where.empty()) std::printf("  fails:     %s\n", c.fails_where.c_str());
    if (!c.corrected.empty()) {
      std::printf("  corrected: %s\n", c.corrected.c_str());
      if (c.corrected_deviation) std::printf("             largest deviation %s\n", c.corrected_deviation_text.c_str());
    }
    for (const auto& m : c.measured) std::printf("  measured:  %s: %s\n", m.name.c_str(), m.value.c_str());
  }
  return 0;
}

}  // namespace vibrofric::tool
