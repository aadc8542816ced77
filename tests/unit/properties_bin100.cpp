#include "properties.hpp"

namespace vt {
VIBROFRIC_PROPERTIES(bin100, vt::Fixed<vibrofric::bin100>);
}  // namespace vt
