// did_you_mean (api/suggest.hpp): the known names a misspelling is one to three edits from.
// Expected values are the edit distances counted by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "vibrofric/api/suggest.hpp"

namespace {

using vibrofric::did_you_mean;

const std::vector<std::string> kWaves{"sine", "triangle", "sawtooth-right", "sawtooth-left", "square", "power:P",
                                      "fourier:FILE", "samples:FILE"};

TEST(Suggest, OneEditFromAWave) {
  EXPECT_EQ(did_you_mean("sin", kWaves), "did you mean 'sine'?");        // insertion (and a prefix)
  EXPECT_EQ(did_you_mean("tirangle", kWaves), "did you mean 'triangle'?");  // two neighbours swapped
  EXPECT_EQ(did_you_mean("squre", kWaves), "did you mean 'square'?");    // deletion
  EXPECT_EQ(did_you_mean("Sine", kWaves), "did you mean 'sine'?");       // case only
}

TEST(Suggest, TwoEditsOnlyForLongerWords) {
  EXPECT_EQ(did_you_mean("sinus", kWaves), "did you mean 'sine'?");     // 2 edits, 5 letters typed
  EXPECT_EQ(did_you_mean("cosine", kWaves), "did you mean 'sine'?");    // 2 deletions, 6 letters
  EXPECT_EQ(did_you_mean("trinagel", kWaves), "did you mean 'triangle'?");  // 2 swaps, 8 letters
  EXPECT_EQ(did_you_mean("sxnx", kWaves), "");                          // 2 edits, 4 letters on both sides
}

TEST(Suggest, ParametricNamesKeepTheArgument) {
  EXPECT_EQ(did_you_mean("powr:2", kWaves), "did you mean 'power:2'?");
  EXPECT_EQ(did_you_mean("sample:rig.csv", kWaves), "did you mean 'samples:rig.csv'?");
  EXPECT_EQ(did_you_mean("power", kWaves), "");  // power:P needs its exponent; "power" is no typo of it
}

TEST(Suggest, APrefixOfTwoNamesSuggestsBoth) {
  EXPECT_EQ(did_you_mean("sawtooth", kWaves), "did you mean 'sawtooth-right' or 'sawtooth-left'?");
}

TEST(Suggest, FlagsCommandsAndNothingNear) {
  EXPECT_EQ(did_you_mean("--gama", {"--beta", "--gamma", "--wave"}), "did you mean '--gamma'?");
  EXPECT_EQ(did_you_mean("mue", {"mu", "psi", "sweep"}), "did you mean 'mu'?");
  EXPECT_EQ(did_you_mean("xyz", kWaves), "");
  EXPECT_EQ(did_you_mean("", kWaves), "");
  EXPECT_EQ(did_you_mean("sine", kWaves), "");  // a known name is not misspelt
  EXPECT_EQ(did_you_mean(std::string(100, 's'), kWaves), "");
}

// The field's words for a quantity, which no spelling distance finds (--freq is 3 edits from --f
// and 2 from --area), in the tool's flags and in Python's keywords alike; only names the caller knows.
TEST(Suggest, SynonymsOfTheFieldsQuantities) {
  const std::vector<std::string> flags{"--f", "--v0", "--A", "--F-N", "--mu0", "--R", "--area", "--skip-rows"};
  EXPECT_EQ(did_you_mean("--freq", flags), "did you mean '--f'?");
  EXPECT_EQ(did_you_mean("--Frequency", flags), "did you mean '--f'?");
  EXPECT_EQ(did_you_mean("--velocity", flags), "did you mean '--v0'?");
  EXPECT_EQ(did_you_mean("--amplitude", flags), "did you mean '--A'?");
  EXPECT_EQ(did_you_mean("--normal_load", flags), "did you mean '--F-N'?");
  EXPECT_EQ(did_you_mean("--skiprows", flags), "did you mean '--skip-rows'?");
  const std::vector<std::string> keywords{"f", "v0", "A", "F_N", "mu0"};
  EXPECT_EQ(did_you_mean("frequency", keywords), "did you mean 'f'?");
  EXPECT_EQ(did_you_mean("load", keywords), "did you mean 'F_N'?");
  EXPECT_EQ(did_you_mean("--frequency", {"--beta", "--gamma"}), "");  // mu has no frequency
}

}  // namespace
