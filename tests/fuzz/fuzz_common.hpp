// Shared parts of the fuzz targets (issue #7). Each target defines LLVMFuzzerTestOneInput; it is
// linked either with libFuzzer (clang, -fsanitize=fuzzer: the `fuzz` preset) or with replay.cpp,
// a plain main() that runs the files and directories given on the command line once each (any
// compiler: the seed corpus is replayed by ctest in every build, under ASan in the `asan` preset).
//
// The contract checked: every input ends in a value or in a clean vibrofric error — InputError
// (DomainError) for bad input, SolverError for a solver that cannot meet its budget. Any other
// exception, a NaN or out-of-range value, or a disagreement between number types is a finding:
// the target prints it and aborts (libFuzzer then saves the input as a crash).
#pragma once
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include "vibrofric/core/errors.hpp"

namespace fuzz {

[[noreturn]] inline void finding(const std::string& what, const std::string& input) {
  std::fprintf(stderr, "\n==== vibrofric fuzz finding: %s\n---- input (%zu bytes):\n%s\n----\n", what.c_str(), input.size(),
               input.c_str());
  std::fflush(stderr);
  std::abort();
}

// Which clean error ended an input (for the statistics; nothing else depends on it).
enum class Outcome { value, input_error, solver_error };

// Runs f(); a vibrofric error is a clean outcome, anything else a finding.
template <class F>
Outcome clean(const std::string& input, const char* stage, F f) {
  try {
    f();
    return Outcome::value;
  } catch (const vibrofric::InputError&) {
    return Outcome::input_error;
  } catch (const vibrofric::SolverError&) {
    return Outcome::solver_error;
  } catch (const std::exception& e) {
    finding(std::string(stage) + ": unexpected exception " + typeid(e).name() + ": " + e.what(), input);
  } catch (...) {
    finding(std::string(stage) + ": unexpected non-standard exception", input);
  }
}

// The input as a file the readers can open by name: an anonymous in-memory file
// (memfd_create), named /proc/self/fd/N, closed on destruction.
class MemFile {
 public:
  MemFile(const std::uint8_t* data, std::size_t size) {
    fd_ = memfd_create("vibrofric-fuzz", 0);
    if (fd_ < 0) throw std::runtime_error("memfd_create failed");
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n = ::write(fd_, data + done, size - done);
      if (n <= 0) throw std::runtime_error("write to memfd failed");
      done += static_cast<std::size_t>(n);
    }
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  ~MemFile() { ::close(fd_); }
  MemFile(const MemFile&) = delete;
  MemFile& operator=(const MemFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  int fd_ = -1;
  std::string path_;
};

}  // namespace fuzz
