#include "evaluate_impl.hpp"

namespace vibrofric {
VIBROFRIC_INSTANTIATE_EVALUATE(vibrofric::bin100)
}  // namespace vibrofric
