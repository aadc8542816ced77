// The two-dimensional in-plane solver in mpfr, compiled once (core/inplane/planar.hpp).
#include "planar_solver.hpp"

namespace vibrofric {
namespace detail {
template class PlanarEngine<mpfr>;
}  // namespace detail
template class PlanarSolver<mpfr>;
}  // namespace vibrofric
