#include "properties.hpp"

namespace vt {
VIBROFRIC_PROPERTIES(mpfr30, vt::Mpfr<30>);
}  // namespace vt
