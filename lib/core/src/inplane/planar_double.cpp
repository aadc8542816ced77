// The two-dimensional in-plane solver in double, compiled once (core/inplane/planar.hpp).
#include "planar_solver.hpp"

namespace vibrofric {
namespace detail {
template class PlanarEngine<double>;
}  // namespace detail
template class PlanarSolver<double>;
}  // namespace vibrofric
