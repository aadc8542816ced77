// Speed of the solver in cpp_bin_float_50 (Boost.Multiprecision, fixed 50 decimal digits).
#include "speed.hpp"

namespace vibrofric::bench {
void register_speed_bin50() { register_solver<bin50>("solver_cpp_bin_float_50", 0); }
}  // namespace vibrofric::bench
