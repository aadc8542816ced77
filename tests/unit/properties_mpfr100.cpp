#include "properties.hpp"

namespace vt {
VIBROFRIC_PROPERTIES(mpfr100, vt::Mpfr<100>);
}  // namespace vt
