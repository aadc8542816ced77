#include "properties.hpp"

namespace vt {
VIBROFRIC_PROPERTIES(long_double, vt::Fixed<long double>);
}  // namespace vt
