// The longitudinal in-plane solver in mpfr, compiled once (core/inplane/inplane.hpp).
#include "inplane_solver.hpp"

namespace vibrofric {
namespace detail {
template class InPlaneEngine<mpfr>;
}  // namespace detail
template class InPlaneSolver<mpfr>;
}  // namespace vibrofric
