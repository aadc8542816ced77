// Speed of the solver in long double (x87 80-bit, 64-bit significand), as computed.
#include "speed.hpp"

namespace vibrofric::bench {
void register_speed_long_double() { register_solver<long double>("solver_long_double", 0); }
}  // namespace vibrofric::bench
