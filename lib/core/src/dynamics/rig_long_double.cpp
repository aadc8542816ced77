// The rig dynamics solver in long double, compiled once (core/dynamics/dynamics.hpp).
#include "rig_solver.hpp"

namespace vibrofric {
namespace detail {
template class RigEngine<long double>;
}  // namespace detail
template class RigSolver<long double>;
}  // namespace vibrofric
