#include "evaluate_impl.hpp"

namespace vibrofric {
VIBROFRIC_INSTANTIATE_EVALUATE(long double)
}  // namespace vibrofric
