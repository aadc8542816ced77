#include "properties.hpp"

namespace vt {
VIBROFRIC_PROPERTIES(bin50, vt::Fixed<vibrofric::bin50>);
}  // namespace vt
