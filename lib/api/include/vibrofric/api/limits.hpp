// What a caller may ask for, in one place (model.md, "Domain and edge behaviour": absurd
// precisions and inputs are refused): the API checks these, and the tool and the Python module
// quote them in their messages and help texts.
#pragma once
#include <cstddef>

namespace vibrofric {

inline constexpr int min_digits = 1;      // significant digits of an mpfr request
inline constexpr int max_digits = 10000;
inline constexpr int root_iterations_limit = 100000;  // the largest Options::max_root_iterations a caller may set
inline constexpr int quadrature_levels_limit = 30;    // the largest Options::max_quadrature_levels (2^30 nodes a level)
inline constexpr int min_trace_points = 2;          // trace: N + 1 phases
inline constexpr int max_trace_points = 1000000;
inline constexpr int max_range_points = 1000000;    // sweep ranges FROM:TO:N
inline constexpr int max_fit_harmonics = 10000;     // fit: K
inline constexpr unsigned max_harmonic_index = 100000;  // fourier files: k
inline constexpr unsigned max_threads = 1024;       // worker threads of a batch (0: every core)
// A file holds at most this many lines (the table reader stops there: an endless input is an
// error, not a memory exhaustion), a profile at most this many samples (refused past it); arrays
// are held to the same numbers.
inline constexpr std::size_t max_table_lines = 10'000'000;
inline constexpr std::size_t max_profile_samples = 100'000;

}  // namespace vibrofric
