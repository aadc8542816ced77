// The longitudinal in-plane solver in double, compiled once (core/inplane/inplane.hpp).
#include "inplane_solver.hpp"

namespace vibrofric {
namespace detail {
template class InPlaneEngine<double>;
}  // namespace detail
template class InPlaneSolver<double>;
}  // namespace vibrofric
