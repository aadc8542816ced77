#include "vibrofric/api/evaluate.hpp"

#include <iterator>
#include <limits>
#include <type_traits>

namespace vibrofric {

namespace {
constexpr NumberType kTypes[] = {NumberType::float64, NumberType::float80, NumberType::bin50, NumberType::bin100,
                                 NumberType::mpfr};
constexpr const char* kTypeNames[] = {"double", "long-double", "cpp_bin_float_50", "cpp_bin_float_100", "mpfr"};
}  // namespace

std::optional<NumberType> number_type_named(const std::string& text) {
  for (const NumberType t : kTypes)
    if (text == kTypeNames[static_cast<int>(t)]) return t;
  return std::nullopt;
}

std::vector<std::string> number_type_names() {
  std::vector<std::string> names;
  for (NumberType t : kTypes) names.push_back(number_type_name(t));
  return names;
}

std::string number_type_name(NumberType t) {
  const auto i = static_cast<std::size_t>(t);
  return i < std::size(kTypeNames) ? kTypeNames[i] : "?";
}

int output_digits(const Precision& p) {
  return visit_number_type(p.type, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    if constexpr (is_runtime_precision_v<Real>) {
      return p.digits;
    } else if constexpr (std::is_floating_point_v<Real>) {
      return std::numeric_limits<Real>::max_digits10;
    } else {
      return std::numeric_limits<Real>::digits10;  // cpp_bin_float_50 and _100: 50 and 100
    }
  });
}

namespace {
// The digits printed, after the request's are checked.
int checked_output_digits(const Precision& precision) {
  if (precision.type == NumberType::mpfr &&
      (precision.digits < min_digits || precision.digits > max_digits))
    throw InputError("digits = " + std::to_string(precision.digits) + ": expected " +
                     std::to_string(min_digits) + " to " + std::to_string(max_digits));
  return output_digits(precision);
}
}  // namespace

Evaluated evaluate_one(const WaveSpec& wave, Quantity q, const Point& point, const Precision& precision,
                       const BatchOptions& options) {
  const int digits = checked_output_digits(precision);
  return visit_number_type(precision.type, [&](auto tag) {
    return detail::evaluate_one_typed<typename decltype(tag)::type>(wave, q, point, digits, options);
  });
}

void evaluate_stream(const WaveSpec& wave, Quantity q, std::size_t count,
                     const std::function<Point(std::size_t)>& point, const Precision& precision,
                     const BatchOptions& options, const std::function<void(std::size_t, const StreamValue&)>& sink) {
  const int digits = checked_output_digits(precision);
  visit_number_type(precision.type, [&](auto tag) {
    detail::evaluate_stream_typed<typename decltype(tag)::type>(wave, q, count, point, digits, options, sink);
  });
}

std::vector<std::string> evaluate(const WaveSpec& wave, Quantity q, const std::vector<Point>& points,
                                  const Precision& precision, const BatchOptions& options) {
  std::vector<std::string> out(points.size());
  evaluate_stream(
      wave, q, points.size(), [&](std::size_t i) { return points[i]; }, precision, options,
      [&](std::size_t i, const StreamValue& value) { out[i] = value.text; });
  return out;
}

}  // namespace vibrofric
