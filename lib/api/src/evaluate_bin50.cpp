#include "evaluate_impl.hpp"

namespace vibrofric {
VIBROFRIC_INSTANTIATE_EVALUATE(vibrofric::bin50)
}  // namespace vibrofric
