// The longitudinal in-plane solver in long double, compiled once (core/inplane/inplane.hpp).
#include "inplane_solver.hpp"

namespace vibrofric {
namespace detail {
template class InPlaneEngine<long double>;
}  // namespace detail
template class InPlaneSolver<long double>;
}  // namespace vibrofric
