// The rig dynamics solver in mpfr, compiled once (core/dynamics/dynamics.hpp).
#include "rig_solver.hpp"

namespace vibrofric {
namespace detail {
template class RigEngine<mpfr>;
}  // namespace detail
template class RigSolver<mpfr>;
}  // namespace vibrofric
