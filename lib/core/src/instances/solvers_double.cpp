// The flat-punch and curved solvers in double, compiled once (solver.hpp, curved.hpp).
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric {
VIBROFRIC_SOLVER_INSTANCES(, double)
VIBROFRIC_CURVED_INSTANCES(, double)
}  // namespace vibrofric
