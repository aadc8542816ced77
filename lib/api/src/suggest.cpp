#include "vibrofric/api/suggest.hpp"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <utility>

namespace vibrofric {
namespace {

std::string lower(const std::string& s) {
  std::string out = s;
  for (char& ch : out) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return out;
}

// Optimal string alignment distance (Damerau–Levenshtein without edits of a swapped pair).
std::size_t distance(const std::string& a, const std::string& b) {
  const std::size_t m = a.size(), n = b.size();
  std::vector<std::vector<std::size_t>> d(m + 1, std::vector<std::size_t>(n + 1));
  for (std::size_t i = 0; i <= m; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= n; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= m; ++i)
    for (std::size_t j = 1; j <= n; ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[m][n];
}

std::size_t allowed(std::size_t length) { return length <= 4 ? 1 : length <= 8 ? 2 : 3; }

// A name as a key: lower case, no leading dashes, '_' as '-' (the tool's --F-N is Python's F_N).
std::string key(const std::string& name) {
  std::string k = lower(name.substr(std::min(name.find_first_not_of('-'), name.size())));
  std::replace(k.begin(), k.end(), '_', '-');
  return k;
}

// Words a user of the field writes for a quantity, by the key of its name: what no spelling
// distance finds (--freq is not a typo of --f).
const char* synonym(const std::string& k) {
  static const std::pair<const char*, const char*> table[] = {
      {"freq", "f"},          {"frequency", "f"},        {"hz", "f"},
      {"velocity", "v0"},     {"speed", "v0"},           {"v", "v0"},             {"sliding-velocity", "v0"},
      {"sliding-speed", "v0"}, {"v-0", "v0"},             {"amplitude", "a"},      {"amp", "a"},
      {"load", "f-n"},        {"normal-load", "f-n"},    {"force", "f-n"},        {"normal-force", "f-n"},
      {"fn", "f-n"},          {"cof", "mu0"},            {"friction", "mu0"},     {"mu-0", "mu0"},
      {"sphere-radius", "r"}, {"ball-radius", "r"},      {"radius-of-curvature", "r"},
      {"precision", "digits"}, {"dps", "digits"},         {"skiprows", "skip-rows"}, {"skip", "skip-rows"},
      {"skip-lines", "skip-rows"}, {"stiffness", "k-system"}, {"system-stiffness", "k-system"}, {"weight", "mass"},
      {"waveform", "wave"},   {"signal", "wave"}};
  for (const auto& [word, name] : table)
    if (k == word) return name;
  return nullptr;
}

}  // namespace

std::string did_you_mean(const std::string& typed, const std::vector<std::string>& known) {
  // Names far longer than any known one are not typos (and would make the table large).
  if (typed.empty() || typed.size() > 64) return "";
  if (const char* meant = synonym(key(typed)))
    for (const std::string& name : known)
      if (key(name) == meant) return "did you mean '" + name + "'?";
  std::vector<std::string> best;
  std::size_t best_d = static_cast<std::size_t>(-1);
  for (const std::string& name : known) {
    const auto colon = name.find(':');
    const std::string head = lower(name.substr(0, colon));
    const auto typed_colon = typed.find(':');
    std::string word = lower(typed.substr(0, colon == std::string::npos ? std::string::npos : typed_colon));
    if (colon != std::string::npos && typed_colon == std::string::npos) continue;  // power:P needs its argument
    std::size_t d = distance(word, head);
    if (word.size() >= 3 && word.size() < head.size() && head.compare(0, word.size(), word) == 0) d = std::min<std::size_t>(d, 1);
    if (d == 0 && colon == std::string::npos && typed == name) continue;  // the name itself is known
    if (d > allowed(std::max(word.size(), head.size())) || d >= head.size()) continue;
    const std::string suggestion = colon == std::string::npos ? name : name.substr(0, colon) + typed.substr(typed_colon);
    if (d < best_d) {
      best_d = d;
      best.clear();
    }
    if (d == best_d && std::find(best.begin(), best.end(), suggestion) == best.end()) best.push_back(suggestion);
  }
  if (best.empty() || best.size() > 2) return "";
  return "did you mean '" + best[0] + "'" + (best.size() == 2 ? " or '" + best[1] + "'" : "") + "?";
}

}  // namespace vibrofric
