#include "properties.hpp"

namespace vt {
VIBROFRIC_PROPERTIES(mpfr300, vt::Mpfr<300>);
}  // namespace vt
