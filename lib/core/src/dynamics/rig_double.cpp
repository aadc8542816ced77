// The rig dynamics solver in double, compiled once (core/dynamics/dynamics.hpp).
#include "rig_solver.hpp"

namespace vibrofric {
namespace detail {
template class RigEngine<double>;
}  // namespace detail
template class RigSolver<double>;
}  // namespace vibrofric
