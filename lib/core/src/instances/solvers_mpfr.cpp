// The flat-punch and curved solvers in mpfr, compiled once (solver.hpp, curved.hpp).
#include "vibrofric/core/curved/curved.hpp"
#include "vibrofric/core/flat/solver.hpp"

namespace vibrofric {
VIBROFRIC_SOLVER_INSTANCES(, mpfr)
VIBROFRIC_CURVED_INSTANCES(, mpfr)
}  // namespace vibrofric
