// The flat-punch and curved solvers in bin100, compiled once (solver.hpp, curved.hpp).
#include "vibrofric/core/curved.hpp"
#include "vibrofric/core/solver.hpp"

namespace vibrofric {
VIBROFRIC_SOLVER_INSTANCES(, bin100)
VIBROFRIC_CURVED_INSTANCES(, bin100)
}  // namespace vibrofric
