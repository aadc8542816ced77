// The flat-punch and curved solvers in long double, compiled once (solver.hpp, curved.hpp).
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric {
VIBROFRIC_SOLVER_INSTANCES(, long double)
VIBROFRIC_CURVED_INSTANCES(, long double)
}  // namespace vibrofric
