// Counters behind floor.hpp: the bench links with --wrap for each counted MPFR function
// (bench/CMakeLists.txt), so every call from the library and Boost.Multiprecision lands here
// first. Calls MPFR makes inside itself are not counted.
#include "floor.hpp"

#include <mpfr.h>
#include <time.h>

#include <boost/math/constants/constants.hpp>
#include <vector>

extern "C" int __real_mpfr_sin_cos(mpfr_ptr, mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);

namespace vibrofric::bench {
namespace {
struct Counter {
  long bits = 0;
  CallCount count;
};
thread_local Counter counter;
void seen(mpfr_srcptr result) {
  if (mpfr_get_prec(result) >= counter.bits)
    ++counter.count.full;
  else
    ++counter.count.reduced;
}
}  // namespace

void count_reset(long bits) { counter = Counter{bits, {}}; }
CallCount count_read() { return counter.count; }

double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}

std::vector<mpfr> sin_cos_phases() {
  std::vector<mpfr> x;
  for (int k = 1; k <= 16; ++k) x.push_back(2 * boost::math::constants::pi<mpfr>() * k / 17);
  return x;
}

double time_sin_cos(std::size_t calls) {
  const std::vector<mpfr> x = sin_cos_phases();
  mpfr s, c;
  const double t0 = thread_cpu_ns();
  for (std::size_t i = 0; i < calls; ++i) {
    __real_mpfr_sin_cos(s.backend().data(), c.backend().data(), x[i % x.size()].backend().data(), MPFR_RNDN);
    benchmark::DoNotOptimize(s.backend().data());
  }
  return (thread_cpu_ns() - t0) / static_cast<double>(calls);
}

}  // namespace vibrofric::bench

using vibrofric::bench::seen;

#define VIBROFRIC_WRAP_1(f)                                                      \
  int __real_##f(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);                            \
  int __wrap_##f(mpfr_ptr y, mpfr_srcptr x, mpfr_rnd_t r) {                     \
    seen(y);                                                                     \
    return __real_##f(y, x, r);                                                  \
  }
#define VIBROFRIC_WRAP_2(f)                                                      \
  int __real_##f(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);               \
  int __wrap_##f(mpfr_ptr y, mpfr_srcptr a, mpfr_srcptr b, mpfr_rnd_t r) {      \
    seen(y);                                                                     \
    return __real_##f(y, a, b, r);                                               \
  }

extern "C" {
VIBROFRIC_WRAP_1(mpfr_sin)
VIBROFRIC_WRAP_1(mpfr_cos)
VIBROFRIC_WRAP_1(mpfr_tan)
VIBROFRIC_WRAP_1(mpfr_exp)
VIBROFRIC_WRAP_1(mpfr_log)
VIBROFRIC_WRAP_1(mpfr_log10)
VIBROFRIC_WRAP_1(mpfr_sinh)
VIBROFRIC_WRAP_1(mpfr_cosh)
VIBROFRIC_WRAP_1(mpfr_tanh)
VIBROFRIC_WRAP_1(mpfr_cbrt)
VIBROFRIC_WRAP_2(mpfr_atan2)
VIBROFRIC_WRAP_2(mpfr_pow)

int __real_mpfr_sin_cos(mpfr_ptr, mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
int __wrap_mpfr_sin_cos(mpfr_ptr s, mpfr_ptr c, mpfr_srcptr x, mpfr_rnd_t r) {
  seen(s);
  return __real_mpfr_sin_cos(s, c, x, r);
}
int __real_mpfr_pow_si(mpfr_ptr, mpfr_srcptr, long, mpfr_rnd_t);
int __wrap_mpfr_pow_si(mpfr_ptr y, mpfr_srcptr x, long n, mpfr_rnd_t r) {
  seen(y);
  return __real_mpfr_pow_si(y, x, n, r);
}
}
