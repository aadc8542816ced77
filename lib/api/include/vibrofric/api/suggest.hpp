// "Did you mean": the known name nearest to a misspelt one (a wave, profile, number type, command
// or flag), for the one-line refusals of every front end (issue 30).
#pragma once
#include <string>
#include <vector>

namespace vibrofric {

// "did you mean 'X'?" (or "'X' or 'Y'?" for a tie) for the names in `known` nearest to `typed`,
// or "" if none is near enough to be a typo. Near: the optimal-string-alignment distance (one
// edit inserts, deletes or replaces a character, or swaps two neighbours; case is ignored) is
// at most 1 where the longer of the two words has up to 4 characters, 2 up to 8 and 3 beyond,
// and below the name's own length; or `typed` (3 characters or more) begins the name. A known name written as `head:ARG`
// (power:P) is compared by its head, and the suggestion keeps what was typed after the colon.
// First, a word of the field for a known name (freq, frequency → f; velocity → v0; amplitude → A;
// load → F_N; …; leading dashes, case and '_' against '-' aside) suggests that name.
std::string did_you_mean(const std::string& typed, const std::vector<std::string>& known);

}  // namespace vibrofric
