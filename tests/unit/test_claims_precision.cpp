// verify --digits D gives the same verdicts over its whole documented range (10 to 300): the
// largest D here (about five minutes on one core, hence its own binary and time limit); the
// smallest, and the verdicts at 50 digits with their evidence, in test_claims.cpp.
#include <gtest/gtest.h>

#include "established_verdicts.hpp"
#include "vibrofric/verification/claims.hpp"

namespace {

TEST(ClaimCatalogue, VerdictsAtTheLargestPrecisionAreTheEstablishedOnes) {
  const auto checks = vibrofric::verify_claims(300);
  EXPECT_EQ(checks.size(), vibrofric::testing::established().size());
  for (const auto& c : checks) {
    const auto it = vibrofric::testing::established().find(c.key);
    ASSERT_NE(it, vibrofric::testing::established().end()) << c.key;
    EXPECT_EQ(vibrofric::verdict_name(c.verdict), vibrofric::verdict_name(it->second.verdict))
        << c.id << " at 300 digits: deviation " << c.deviation_text << " at " << c.worst;
    EXPECT_EQ(c.certification, vibrofric::testing::certified_claims().count(c.key) ? "certified" : "numerical") << c.id;
    // The deviation keeps the working precision's exponent (a double would underflow below 1e-308).
    if (c.verdict == vibrofric::Verdict::holds && c.deviation_text != "0") {
      EXPECT_LT(std::stoi(c.deviation_text.substr(c.deviation_text.find('e') + 1)), -300) << c.id;
    }
  }
}

}  // namespace
