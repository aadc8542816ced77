#include "properties.hpp"

namespace vt {
VIBROFRIC_PROPERTIES(double, vt::Fixed<double>);
}  // namespace vt
