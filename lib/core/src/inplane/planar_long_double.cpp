// The two-dimensional in-plane solver in long double, compiled once (core/inplane/planar.hpp).
#include "planar_solver.hpp"

namespace vibrofric {
namespace detail {
template class PlanarEngine<long double>;
}  // namespace detail
template class PlanarSolver<long double>;
}  // namespace vibrofric
