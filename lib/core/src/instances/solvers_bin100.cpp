// The flat-punch and curved solvers in bin100, compiled once (solver.hpp, curved.hpp).
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric {
VIBROFRIC_SOLVER_INSTANCES(, bin100)
VIBROFRIC_CURVED_INSTANCES(, bin100)
}  // namespace vibrofric
