// Shared helpers of the robustness tests (issue #7): scratch files for user waveforms, exact
// decimal strings of dyadic rationals, and the sanitizer switch that shrinks the sizes.
#pragma once
#include <unistd.h>

#include <boost/multiprecision/cpp_int.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

namespace robustness {

// Under AddressSanitizer everything runs several times slower: the tests then use smaller sizes.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

// A file in $TMPDIR (or /tmp) with the given contents, removed on destruction.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& contents) {
    const char* dir = std::getenv("TMPDIR");
    std::string pattern = std::string(dir && *dir ? dir : "/tmp") + "/vibrofric-robustness-XXXXXX";
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("mkstemp failed for " + pattern);
    ::close(fd);
    path_ = pattern;
    std::ofstream out(path_, std::ios::binary);
    out << contents;
    if (!out) throw std::runtime_error("cannot write " + path_);
  }
  ~ScratchFile() { std::remove(path_.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// n / 2^k as an exact decimal string ("-0.375"): dyadic rationals are exact in double, long
// double and mpfr, so every number type and the rational second algorithm see the same input.
inline std::string dyadic(long long n, int k) {
  using boost::multiprecision::cpp_int;
  const bool negative = n < 0;
  cpp_int m = negative ? cpp_int(-n) : cpp_int(n);
  for (int i = 0; i < k; ++i) m *= 5;  // n / 2^k = n·5^k / 10^k
  std::string digits = m.str();
  if (k > 0) {
    if (digits.size() <= static_cast<std::size_t>(k)) digits.insert(0, static_cast<std::size_t>(k) + 1 - digits.size(), '0');
    digits.insert(digits.size() - static_cast<std::size_t>(k), ".");
    while (digits.back() == '0') digits.pop_back();
    if (digits.back() == '.') digits.pop_back();
  }
  return (negative && digits != "0" ? "-" : "") + digits;
}

// Environment variable as a count, or the fallback.
inline long env_count(const char* name, long fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  return end && *end == '\0' && n >= 0 ? n : fallback;
}

}  // namespace robustness
