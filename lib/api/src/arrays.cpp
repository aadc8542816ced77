#include "vibrofric/api/arrays.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace vibrofric {

namespace {

// A file in the temporary directory holding `text`, removed when this goes out of scope: the
// readers of catalogue.hpp and profile.hpp take a path, and reading through them is what makes an
// array behave exactly as a file.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& text) {
    std::error_code ec;
    std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
    if (ec) dir = "/tmp";
    std::string pattern = (dir / "vibrofric-array-XXXXXX").string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw InputError("cannot create a temporary file in " + dir.string() + " for an array wave");
    path_ = pattern;
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        ::close(fd);
        std::remove(path_.c_str());
        throw InputError("cannot write the temporary file " + path_ + " for an array wave");
      }
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
  }
  ~ScratchFile() { std::remove(path_.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The reader's message with the scratch file's name replaced by `label`, and "PATH:LINE" by
// "label[j]" (j = LINE − 1 − header lines: the array index).
std::string relabel(std::string message, const std::string& path, const std::string& label, int header_lines) {
  for (std::size_t at = message.find(path); at != std::string::npos; at = message.find(path, at)) {
    std::size_t end = at + path.size();
    std::string replacement = label;
    if (end < message.size() && message[end] == ':') {
      std::size_t digits = end + 1;
      while (digits < message.size() && message[digits] >= '0' && message[digits] <= '9') ++digits;
      if (digits > end + 1) {
        const long line = std::strtol(message.c_str() + end + 1, nullptr, 10);
        replacement += "[" + std::to_string(line - 1 - header_lines) + "]";
        end = digits;
      }
    }
    // The readers quote a path as 'PATH' and a wave as 'samples:PATH': keep the quotes, drop the prefix.
    std::size_t begin = at;
    for (const char* prefix : {"samples:", "fourier:", "profile:"}) {
      const std::size_t n = std::char_traits<char>::length(prefix);
      if (begin >= n && message.compare(begin - n, n, prefix) == 0) begin -= n;
    }
    message.replace(begin, end - begin, replacement);
    at = begin + replacement.size();
  }
  return message;
}

template <class Read>
auto read_through_file(const std::string& text, const std::string& label, int header_lines, Read read) {
  const ScratchFile file(text);
  try {
    return read(file.path());
  } catch (const DomainError& e) {
    throw DomainError(relabel(e.what(), file.path(), label, header_lines));
  } catch (const InputError& e) {
    throw InputError(relabel(e.what(), file.path(), label, header_lines));
  }
}

void check_all(const std::vector<std::string>& values, const std::string& name) {
  for (std::size_t j = 0; j < values.size(); ++j) check_decimal(values[j], name + "[" + std::to_string(j) + "]");
}

}  // namespace

std::string decimal_text(double x) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, r.ptr);
}

WaveSpec samples_wave(const std::vector<std::string>& y, const std::vector<std::string>& t, const std::string& label) {
  if (!t.empty() && t.size() != y.size())
    throw InputError(label + ": t has " + std::to_string(t.size()) + " values and y " + std::to_string(y.size()) +
                     ": expected one time stamp per value (one period with its end point)");
  check_all(y, label + " y");
  check_all(t, label + " t");
  std::string text = t.empty() ? "" : "time,value\n";
  for (std::size_t j = 0; j < y.size(); ++j) text += (t.empty() ? "" : t[j] + ",") + y[j] + "\n";
  WaveSpec spec = read_through_file(text, label, t.empty() ? 0 : 1,
                                    [](const std::string& path) { return parse_wave("samples:" + path); });
  spec.name = label;
  return spec;
}

WaveSpec fourier_wave(const std::vector<std::string>& a, const std::vector<std::string>& b, const std::string& a0,
                      const std::string& label) {
  if (a.size() != b.size())
    throw InputError(label + ": a has " + std::to_string(a.size()) + " coefficients and b " + std::to_string(b.size()) +
                     ": expected a_k and b_k for the same k = 1 … K");
  if (!a0.empty()) check_decimal(a0, label + " a0");
  check_all(a, label + " a");  // a[j] is a_{j+1}
  check_all(b, label + " b");
  std::string text = a0.empty() ? "" : "0 " + a0 + " 0\n";
  for (std::size_t j = 0; j < a.size(); ++j) text += std::to_string(j + 1) + " " + a[j] + " " + b[j] + "\n";
  WaveSpec spec = read_through_file(text, label, a0.empty() ? 0 : 1,
                                    [](const std::string& path) { return parse_wave("fourier:" + path); });
  spec.name = label;
  return spec;
}

WaveSpec fitted_wave(const FourierFit& fit, const std::string& label) {
  const std::string text = fourier_file_text(fit, label);
  int header_lines = 0;  // the comment lines and the 'k a_k b_k' header: label[k] is harmonic k
  for (std::size_t at = 0; at < text.size() && (text[at] == '#' || text[at] == 'k'); ++header_lines) {
    at = text.find('\n', at);
    if (at == std::string::npos) break;
    ++at;
  }
  WaveSpec spec = read_through_file(text, label, header_lines,
                                    [](const std::string& path) { return parse_wave("fourier:" + path); });
  spec.name = label;
  return spec;
}

ProfileSpec profile_arrays(const std::vector<std::string>& r, const std::vector<std::string>& f, const std::string& label) {
  if (r.size() != f.size())
    throw InputError(label + ": r has " + std::to_string(r.size()) + " values and f " + std::to_string(f.size()) +
                     ": expected one height per radius");
  check_all(r, label + " r");
  check_all(f, label + " f");
  std::string text;
  for (std::size_t j = 0; j < r.size(); ++j) text += r[j] + " " + f[j] + "\n";
  ProfileSpec spec = read_through_file(text, label, 0, [&](const std::string& path) { return parse_profile("profile:" + path); });
  spec.name = label;
  return spec;
}

}  // namespace vibrofric
